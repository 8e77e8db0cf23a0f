//! The reef's demo scenes and how each is populated: the default reef (Plate 1),
//! *Predator and school*, *Courtship*, *Feeding* and *School meets obstacle*;
//! their animals, habits, rocks, food and seaweed.

use glam::Vec3;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::i18n::{Lang, ts, with_lang};
use crate::sim::body::motor_bridge::TOP_SPEED_BODY_LENGTHS_PER_SEC;
use crate::sim::body::physical_fish::{BodySpecies, PhysicalFish};
use crate::sim::common::fish::Fish;
use crate::sim::common::moment::Moment;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::tank::Tank;
use crate::sim::reef::animal::{MAX_REEF_ANIMALS, ReefAnimal};
use crate::sim::reef::bodies::{ReefBody, ReefBodyKind};
use crate::sim::reef::courtship::Phase;
use crate::sim::reef::environment::Environment;
use crate::sim::reef::events::ReefEventKind;
use crate::sim::reef::mind::{FishKind, Habits, Liking, MentalState, Sex};
use crate::sim::reef::params::ReefParams;
use crate::sim::reef::seaweed::Seaweed;

/// The demo scenes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ReefScene {
    /// Plate 1: fishes feeding on plankton, a predator hunting a prey school,
    /// pacifists courting, seaweed swaying.
    #[default]
    Reef,
    PredatorAndSchool,
    Courtship,
    Feeding,
    SchoolMeetsObstacle,
}

impl ReefScene {
    pub const ALL: [Self; 5] = [
        Self::Reef,
        Self::PredatorAndSchool,
        Self::Courtship,
        Self::Feeding,
        Self::SchoolMeetsObstacle,
    ];

    pub fn label(self) -> &'static str {
        match self {
            Self::Reef => ts("reef-demo-reef"),
            Self::PredatorAndSchool => ts("reef-demo-predator-and-school"),
            Self::Courtship => ts("reef-demo-courtship"),
            Self::Feeding => ts("reef-demo-feeding"),
            Self::SchoolMeetsObstacle => ts("reef-demo-school-meets-obstacle"),
        }
    }

    /// Prey fish in this scene unless the teacher chose a number.
    pub fn default_prey_count(self) -> usize {
        match self {
            Self::Reef => 10,
            Self::PredatorAndSchool => 14,
            Self::SchoolMeetsObstacle => 16,
            Self::Courtship | Self::Feeding => 0,
        }
    }

    /// Animals in this scene with `prey` prey fish (capped at
    /// [`MAX_REEF_ANIMALS`]).
    pub fn animal_count(self, prey: usize) -> usize {
        let others = match self {
            // A shark, two courting pairs and three grazers.
            Self::Reef => 1 + 4 + 3,
            Self::PredatorAndSchool => 1,
            Self::Courtship => 3,
            Self::Feeding => 6,
            Self::SchoolMeetsObstacle => 0,
        };
        let prey = if self.default_prey_count() > 0 {
            prey
        } else {
            0
        };
        (prey + others).min(MAX_REEF_ANIMALS)
    }

    /// Plankton kept in the water unless the teacher chose a number.
    pub fn default_food_count(self) -> usize {
        match self {
            Self::Reef => 25,
            Self::Courtship => 6,
            Self::Feeding => 30,
            Self::PredatorAndSchool | Self::SchoolMeetsObstacle => 0,
        }
    }

    /// One sentence for the UI.
    pub fn explanation(self) -> &'static str {
        match self {
            Self::Reef => ts("reef-demo-reef.help"),
            Self::PredatorAndSchool => ts("reef-demo-predator-and-school.help"),
            Self::Courtship => ts("reef-demo-courtship.help"),
            Self::Feeding => ts("reef-demo-feeding.help"),
            Self::SchoolMeetsObstacle => ts("reef-demo-school-meets-obstacle.help"),
        }
    }
}

impl ReefScene {
    /// The moment the scene is about, which *Skip to the moment* looks ahead
    /// for.
    pub fn moment(self) -> Moment {
        let (what_id, lead_secs) = match self {
            Self::Reef => ("reef-demo-reef.moment", 6.0),
            Self::PredatorAndSchool => ("reef-demo-predator-and-school.moment", 8.0),
            Self::Courtship => ("reef-demo-courtship.moment", 12.0),
            Self::Feeding => ("reef-demo-feeding.moment", 4.0),
            Self::SchoolMeetsObstacle => ("reef-demo-school-meets-obstacle.moment", 4.0),
        };
        Moment {
            // English for `shoal.state()`; the button asks for `words()`.
            what: with_lang(Lang::En, || ts(what_id)),
            what_id,
            lead_secs,
            // The school is the subject at the pillar: the demo's view from
            // above shows it whole, a camera on one fish would not.
            follow: self != Self::SchoolMeetsObstacle,
        }
    }

    /// Is `kind` this scene's moment?
    pub fn is_moment(self, kind: &ReefEventKind) -> bool {
        let spawned = matches!(
            kind,
            ReefEventKind::Courtship {
                phase: Phase::Spawned,
                ..
            }
        );
        match self {
            Self::Reef => spawned || matches!(kind, ReefEventKind::AtePrey { .. }),
            Self::PredatorAndSchool => matches!(kind, ReefEventKind::AtePrey { .. }),
            Self::Courtship => spawned,
            Self::Feeding => matches!(kind, ReefEventKind::AteFood { .. }),
            // What its question asks: does the school split, join up
            // again, or go by whole? Reaching the pillar is only the
            // approach (a skip that stopped there answered nothing).
            Self::SchoolMeetsObstacle => matches!(
                kind,
                ReefEventKind::SchoolSplit { .. }
                    | ReefEventKind::SchoolJoined { .. }
                    | ReefEventKind::SchoolPassedWhole { .. }
            ),
        }
    }
}

pub(super) fn prey_habits(k: usize) -> Habits {
    let sex = if k.is_multiple_of(2) {
        Sex::Female
    } else {
        Sex::Male
    };
    Habits::new(FishKind::Prey, sex, 0)
}

pub(super) fn predator_habits() -> Habits {
    Habits::new(FishKind::Predator, Sex::Male, 9)
}

/// What a demo put in the reef.
pub(super) struct Stocked {
    pub obstacles: Vec<Obstacle>,
    pub animals: Vec<ReefAnimal>,
    pub seaweed: Vec<Seaweed>,
    /// Plankton particles the water is kept stocked with.
    pub food_target: usize,
}

/// What stocking a demo reads: the tank, the water's light and temperature
/// (a newborn's first brightness and temperature), the tuning, the body
/// that carries the minds and the teacher's number of prey.
pub(super) struct StockInputs<'a> {
    pub tank: Tank,
    pub env: &'a Environment,
    pub params: &'a ReefParams,
    pub body: ReefBodyKind,
    pub prey_count: Option<usize>,
}

/// Stocks the reef for `scene`, drawing from `rng`: rocks, animals (fed and
/// content, with random clocks), seaweed, and how much plankton to keep.
pub(super) fn populate(scene: ReefScene, rng: &mut ChaCha8Rng, inputs: &StockInputs) -> Stocked {
    let mut stock = Stock {
        rng,
        inputs,
        obstacles: Vec::new(),
        animals: Vec::new(),
        seaweed: Vec::new(),
    };
    let food_target = stock.populate(scene);
    Stocked {
        obstacles: stock.obstacles,
        animals: stock.animals,
        seaweed: stock.seaweed,
        food_target,
    }
}

/// A point at least `margin` inside `tank` and `margin` clear of every rock
/// of `obstacles` (the tank's centre if 100 draws from `rng` found none).
pub(super) fn random_free_point(
    rng: &mut ChaCha8Rng,
    tank: &Tank,
    obstacles: &[Obstacle],
    margin: f32,
) -> Vec3 {
    let (lo, hi) = (
        tank.min_m + Vec3::splat(margin),
        tank.max_m - Vec3::splat(margin),
    );
    let mut p = tank.center_m();
    for _ in 0..100 {
        p = Vec3::new(
            rng.random_range(lo.x..hi.x),
            rng.random_range(lo.y..hi.y),
            rng.random_range(lo.z..hi.z),
        );
        if obstacles.iter().all(|o| o.signed_distance_m(p) > margin) {
            break;
        }
    }
    p
}

/// A reef being stocked: the generator it draws from and what it holds so far.
struct Stock<'a, 'b> {
    rng: &'a mut ChaCha8Rng,
    inputs: &'a StockInputs<'b>,
    obstacles: Vec<Obstacle>,
    animals: Vec<ReefAnimal>,
    seaweed: Vec<Seaweed>,
}

impl Stock<'_, '_> {
    /// Puts in `scene`'s rocks, animals and seaweed; returns the plankton
    /// particles to keep in the water.
    fn populate(&mut self, scene: ReefScene) -> usize {
        let t = self.inputs.tank;
        let c = t.center_m();
        match scene {
            ReefScene::Reef => {
                self.obstacles = vec![
                    Obstacle::Rock {
                        center_m: Vec3::new(-3.0, 0.2, -1.5),
                        radius_m: 0.9,
                    },
                    Obstacle::Cylinder {
                        base_center_m: Vec3::new(2.5, 0.0, 1.5),
                        radius_m: 0.45,
                        height_m: 2.2,
                    },
                    Obstacle::Rock {
                        center_m: Vec3::new(1.0, 0.1, -2.2),
                        radius_m: 0.7,
                    },
                ];
                for k in 0..self.inputs.prey_count.unwrap_or(scene.default_prey_count()) {
                    let p = Vec3::new(-3.5, 2.5, 1.5) + self.jitter(1.2);
                    self.spawn(p, Vec3::X, prey_habits(k), 0.45);
                }
                self.spawn(Vec3::new(4.0, 2.0, -2.5), -Vec3::X, predator_habits(), 1.0);
                // Two courting pairs of species 1 and 2, plus a rival male.
                for (species, at) in [
                    (1u8, Vec3::new(2.0, 3.0, -1.0)),
                    (2, Vec3::new(-1.5, 1.5, 2.5)),
                ] {
                    let mut female = Habits::new(FishKind::Pacifist, Sex::Female, species);
                    female.light = Liking::High;
                    self.spawn(at, Vec3::Z, female, 0.5);
                    let male = Habits::new(FishKind::Pacifist, Sex::Male, species);
                    self.spawn(at + Vec3::new(1.0, 0.0, 0.0), -Vec3::Z, male, 0.55);
                }
                // Solitary grazers with different tastes.
                for (k, (light, temperature)) in [
                    (Liking::Low, Liking::Indifferent),
                    (Liking::Indifferent, Liking::High),
                    (Liking::High, Liking::Low),
                ]
                .into_iter()
                .enumerate()
                {
                    let mut h = Habits::new(FishKind::Pacifist, Sex::Female, 3 + k as u8);
                    h.light = light;
                    h.temperature = temperature;
                    let p = self.random_free_point(1.0);
                    self.spawn(p, Vec3::X, h, 0.4);
                }
                self.plant_seaweed(9);
            }
            ReefScene::PredatorAndSchool => {
                self.obstacles = vec![Obstacle::Rock {
                    center_m: Vec3::new(0.0, 0.1, 2.0),
                    radius_m: 0.8,
                }];
                for k in 0..self.inputs.prey_count.unwrap_or(scene.default_prey_count()) {
                    let p = Vec3::new(-2.5, 2.3, 0.0) + self.jitter(1.3);
                    self.spawn(p, Vec3::Z, prey_habits(k), 0.45);
                }
                // The paper's nominal digestion, faster than Shoal's calm
                // default: on the one clock (1/40 s a paper time unit) the shark
                // is hungry again 9 s after a meal and hunts most of the time.
                // (The paper's ravenous 0.005 makes it hungry again after 1.3 s:
                // it eats nearly every prey fish within 2 minutes, schooling or
                // not.)
                let mut shark = predator_habits();
                shark.mental.digestion_rate_per_unit =
                    crate::sim::reef::mind::mental_state::NOMINAL_DIGESTION_RATE;
                self.spawn(Vec3::new(4.0, 2.3, -2.0), -Vec3::X, shark, 1.0);
                self.plant_seaweed(4);
            }
            ReefScene::Courtship => {
                // Well-fed fish in sexual mania: the demo shows courtship, as the
                // *Feeding* demo shows feeding with no libido. Digestion is
                // slowed to a tenth of the nominal p0 (fully hungry after 6
                // minutes instead of 37 s), so hunger does not break the pairs up
                // before they spawn; the *Minds* panel sets it back.
                let digestion_fraction = self.inputs.params.courtship_digestion_fraction;
                let courting = |sex| {
                    let mut h = Habits::new(FishKind::Pacifist, sex, 1);
                    h.mental.libido_rate_per_unit =
                        crate::sim::reef::mind::mental_state::MANIC_LIBIDO_RATE;
                    h.mental.digestion_rate_per_unit = digestion_fraction
                        * crate::sim::reef::mind::mental_state::NOMINAL_DIGESTION_RATE;
                    h
                };
                let female = courting(Sex::Female);
                self.spawn(c + Vec3::new(0.0, 0.3, 0.0), Vec3::X, female, 0.5);
                for (k, length) in [0.45f32, 0.6].into_iter().enumerate() {
                    let male = courting(Sex::Male);
                    let p = c + Vec3::new(-2.5 + 5.0 * k as f32, 0.0, 1.5);
                    self.spawn(p, -Vec3::Z, male, length);
                }
                self.plant_seaweed(5);
            }
            ReefScene::Feeding => {
                for k in 0..6 {
                    let mut h = Habits::new(FishKind::Pacifist, Sex::Female, k as u8);
                    h.mental.digestion_rate_per_unit =
                        crate::sim::reef::mind::mental_state::RAVENOUS_DIGESTION_RATE;
                    h.mental.libido_rate_per_unit = 0.0;
                    let p = self.random_free_point(1.0);
                    self.spawn(p, Vec3::X, h, 0.45);
                }
                self.plant_seaweed(6);
            }
            ReefScene::SchoolMeetsObstacle => {
                self.obstacles = vec![Obstacle::Cylinder {
                    base_center_m: Vec3::new(0.0, 0.0, 0.0),
                    radius_m: 1.0,
                    height_m: t.size_m().y - crate::sim::common::obstacle::SURFACE_CLEARANCE_M,
                }];
                for k in 0..self.inputs.prey_count.unwrap_or(scene.default_prey_count()) {
                    let p = Vec3::new(-4.5, 2.2, 0.0) + self.jitter(1.0);
                    self.spawn(p, Vec3::X, prey_habits(k), 0.45);
                }
            }
        }
        // Everyone starts fed and content with a random clock, so the urges
        // do not all rise in step: 0.7 of its appetite eaten up to
        // `ReefParams::start_fed_for_max_secs` ago.
        let fed_for_max_secs = self.inputs.params.start_fed_for_max_secs;
        let fed_for: Vec<f32> = (0..self.animals.len())
            .map(|_| self.rng.random_range(0.0..fed_for_max_secs))
            .collect();
        for (a, secs) in self.animals.iter_mut().zip(fed_for) {
            let starving = matches!(scene, ReefScene::Feeding | ReefScene::PredatorAndSchool)
                && a.habits.kind != FishKind::Prey;
            let eaten = if starving {
                0.0
            } else {
                0.7 * a.habits.mental.appetite_food_units
            };
            a.mental = MentalState::new(&a.habits.mental, eaten, secs);
            a.mental.update(&a.habits.mental, secs, std::iter::empty());
            a.mental.secs_since_mating = secs;
        }
        scene.default_food_count()
    }

    fn jitter(&mut self, r: f32) -> Vec3 {
        Vec3::new(
            self.rng.random_range(-r..r),
            self.rng.random_range(-0.5 * r..0.5 * r),
            self.rng.random_range(-r..r),
        )
    }

    fn random_free_point(&mut self, margin: f32) -> Vec3 {
        random_free_point(self.rng, &self.inputs.tank, &self.obstacles, margin)
    }

    fn spawn(&mut self, position_m: Vec3, heading: Vec3, habits: Habits, length_m: f32) {
        if self.animals.len() >= MAX_REEF_ANIMALS {
            return;
        }
        let length = length_m * self.rng.random_range(0.95..1.05);
        let mut p = self.inputs.tank.clamp_inside(position_m, length.max(0.6));
        for o in &self.obstacles {
            if o.signed_distance_m(p) < length {
                p = o.push_outside(p, length);
            }
        }
        let hue = match habits.kind {
            FishKind::Predator => 0.58,
            FishKind::Prey => 0.08 + 0.04 * self.rng.random_range(-1.0..1.0f32),
            FishKind::Pacifist => (0.3 + 0.17 * f32::from(habits.species)).fract(),
        };
        let heading = heading.normalize_or(Vec3::X);
        let body = match self.inputs.body {
            ReefBodyKind::Physical => {
                let species = if habits.kind == FishKind::Predator {
                    BodySpecies::Shark
                } else {
                    BodySpecies::Fish
                };
                ReefBody::Physical(Box::new(PhysicalFish::new(
                    species, length, p, heading, hue,
                )))
            }
            ReefBodyKind::PointMass => ReefBody::Point(Fish::new(
                p,
                heading * 0.5 * TOP_SPEED_BODY_LENGTHS_PER_SEC * length,
                length,
                hue,
            )),
        };
        let top = TOP_SPEED_BODY_LENGTHS_PER_SEC * length;
        let env = self.inputs.env;
        self.animals.push(ReefAnimal::new(
            habits,
            body,
            hue,
            p,
            length,
            heading * 0.5 * top,
            env.brightness_at(p),
            env.temperature_c_at(p),
        ));
    }

    fn plant_seaweed(&mut self, strands: usize) {
        for k in 0..strands {
            let mut root = self.random_free_point(0.5);
            root.y = self.inputs.tank.min_m.y;
            let height = self.rng.random_range(1.2..2.6f32);
            self.seaweed
                .push(Seaweed::planted(root, height, k as f32 * 1.7));
        }
    }
}
