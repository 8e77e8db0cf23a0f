//! The living reef of Tu & Terzopoulos 1994 (Plate 1): fish with minds. Each
//! step every animal
//! 1. **perceives** (`reef/perception.rs`): what it sees with its 300° occluded
//!    vision out to the water's visibility V_r, the temperature at its centre
//!    and the brightness of its retinal image;
//! 2. updates its **mental state** and lets the **intention generator** choose an
//!    intention and a focus (`reef/mind/`);
//! 3. runs the **behaviour routine** for it (`reef/behaviour.rs`, `reef/courtship.rs`),
//!    which gives the velocity it wants and how (swim, hover, or hover and bob);
//!    keeping off the glass, sand, surface and rocks bends the direction of a
//!    swimming wish (motor preferences);
//! 4. moves its **body**: the muscle-driven spring–mass fish by default, whose
//!    motor controllers (swim-MC, turn-MC, pectoral fins) the routine's motor
//!    choice picks (`reef/motor_choice.rs`), or the light point-mass fish of the boid
//!    layer for big scenes, steered to the wished velocity — the same mind
//!    drives either.
//!
//! Then mouths suck in food and prey, plankton drifts and is replenished,
//! seaweed sways in the current, and readable events are logged ("shark 12 ate
//! fish 3"). Deterministic for a seed: one ChaCha8 generator, animals in
//! index order.

use crate::sim::common::fmath;
use std::collections::VecDeque;

use glam::Vec3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use super::demos::ReefScene;
use super::events::ReefEvent;
use super::school_watch::SchoolWatch;
use crate::sim::body::body_layout::HEAD_NODE;
use crate::sim::body::drive::{drive_physical, step_and_constrain};
use crate::sim::body::motor_bridge::TOP_SPEED_BODY_LENGTHS_PER_SEC;
use crate::sim::body::physical_fish::PhysicalFish;
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::steering::{self, SteeringParams};
use crate::sim::common::tank::Tank;
use crate::sim::common::water_current::WaterCurrent;
use crate::sim::reef::courtship::Pair;
use crate::sim::reef::environment::Environment;
use crate::sim::reef::mind::habits::KindTraits;
use crate::sim::reef::mind::{FishKind, Focus, Habits, IntentionGenerator, MentalState, Sex};
use crate::sim::reef::motor_choice::{self, Gait, Wish};
use crate::sim::reef::params::ReefParams;
use crate::sim::reef::perception::{Eye, Retina, Sphere, fish_occluder, in_a_school};

/// Most animals in a reef.
pub const MAX_REEF_ANIMALS: usize = 200;
/// Most plankton particles kept in the water.
pub const MAX_FOOD: usize = 200;
/// Time step of the point-mass body, seconds: the fish world's one step
/// ([`crate::sim::common::paper_time::FISH_STEP_SECS`]), as the muscle body's, so both
/// bodies see the same world clock.
pub const POINT_BODY_DT_SECS: f32 = crate::sim::common::paper_time::FISH_STEP_SECS;
/// Seconds between mind-history samples.
pub const HISTORY_EVERY_SECS: f64 = 0.5;
/// Mind-history samples kept per animal (2 minutes).
pub const HISTORY_LEN: usize = 240;
/// Seconds between two "fled" events of one fish.
pub(super) const ESCAPE_LOG_EVERY_SECS: f64 = 15.0;
/// Events kept in the log.
pub const EVENT_LOG_LEN: usize = 200;
/// Two bodies whose centres are closer than this share of their mean length
/// count as colliding (0.5: their bodies overlap).
pub(super) const COLLISION_BODY_LENGTHS: f32 = 0.5;

/// Which body carries the minds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ReefBodyKind {
    /// The muscle-driven spring–mass fish (Tu & Terzopoulos §3).
    #[default]
    Physical,
    /// The boid layer's point-mass fish: cheap, for big scenes.
    PointMass,
}

/// What to build.
#[derive(Clone, Debug, PartialEq)]
pub struct ReefConfig {
    pub seed: u64,
    pub scene: ReefScene,
    pub body: ReefBodyKind,
    /// V_r: how far fish see in this water, metres (6, chosen: half the tank).
    pub visibility_m: f32,
    /// Speed of the fastest water, m/s.
    pub current_m_per_s: f32,
    /// Plankton particles kept in the water (the scene's default if `None`).
    pub food_count: Option<usize>,
    /// Prey fish in the scenes that have a school (the scene's default if `None`).
    pub prey_count: Option<usize>,
    /// A teacher's changes to the minds of each kind of fish (none by default).
    pub traits: KindTraits,
}

impl Default for ReefConfig {
    fn default() -> Self {
        Self {
            seed: 1,
            scene: ReefScene::Reef,
            body: ReefBodyKind::Physical,
            visibility_m: 6.0,
            current_m_per_s: 0.03,
            food_count: None,
            prey_count: None,
            traits: KindTraits::default(),
        }
    }
}

/// The body of one reef animal.
#[derive(Clone, Debug)]
pub enum ReefBody {
    Physical(Box<PhysicalFish>),
    Point(Fish),
}

impl ReefBody {
    pub fn position_m(&self) -> Vec3 {
        match self {
            Self::Physical(p) => p.point.position_m,
            Self::Point(f) => f.position_m,
        }
    }

    pub fn velocity_m_per_s(&self) -> Vec3 {
        match self {
            Self::Physical(p) => p.point.velocity_m_per_s,
            Self::Point(f) => f.velocity_m_per_s,
        }
    }

    /// Where the fish points (unit).
    pub fn heading(&self) -> Vec3 {
        match self {
            Self::Physical(p) => p.heading(),
            Self::Point(f) => f.heading(),
        }
    }

    pub fn body_length_m(&self) -> f32 {
        match self {
            Self::Physical(p) => p.body_length_m(),
            Self::Point(f) => f.body_length_m,
        }
    }

    /// Top speed, m/s (the same for both bodies of a given length).
    pub fn top_speed_m_per_s(&self) -> f32 {
        TOP_SPEED_BODY_LENGTHS_PER_SEC * self.body_length_m()
    }

    /// The mouth (the head node of the muscle body).
    pub fn head_m(&self) -> Vec3 {
        match self {
            Self::Physical(p) => p.nodes_m()[HEAD_NODE],
            Self::Point(f) => f.position_m + f.heading() * 0.5 * f.body_length_m,
        }
    }

    /// Adds `dv_m_per_s` to the whole body's velocity (the vacuum's pull).
    pub(super) fn nudge(&mut self, dv_m_per_s: Vec3) {
        match self {
            Self::Physical(p) => p.add_velocity(dv_m_per_s),
            Self::Point(f) => f.velocity_m_per_s += dv_m_per_s,
        }
    }
}

/// One sample of an animal's mind, for the inspector's history plot and the
/// reef's CSV export.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MindSample {
    pub time_secs: f32,
    pub hunger: f32,
    pub libido: f32,
    pub fear: f32,
    /// What it meant to do at that moment.
    pub intention: crate::sim::reef::mind::Intention,
}

/// An animal of the reef: body and mind.
#[derive(Clone, Debug)]
pub struct ReefAnimal {
    /// The habits in use: the demo's own with the teacher's traits put in.
    pub habits: Habits,
    /// The habits the demo gave this animal.
    pub demo_habits: Habits,
    pub mental: MentalState,
    pub generator: IntentionGenerator,
    /// This step's intention and target.
    pub focus: Focus,
    pub body: ReefBody,
    /// Colour around the colour wheel, 0..1.
    pub hue: f32,
    /// Eaten animals stay in the list (indices are names) but no longer live.
    pub alive: bool,
    /// Is the mouth open (sucking in)?
    pub mouth_open: bool,
    /// The velocity the behaviour asked for last step, m/s.
    pub desired_m_per_s: Vec3,
    /// Mean brightness of the retinal image (refreshed about every 4 s, one
    /// fish in four each second).
    pub brightness: f32,
    /// Water temperature at the centre, °C.
    pub temperature_c: f32,
    /// Recent hunger, libido and fear.
    pub history: VecDeque<MindSample>,
    /// Point-mass velocity the muscle body chases (see `physics/world.rs`).
    pub(super) intended_m_per_s: Vec3,
    pub(super) touch: Option<Vec3>,
    /// The predator last seen, where, and for how many more seconds it is
    /// remembered (see [`ReefParams::threat_memory_secs`]).
    pub(super) last_threat: Option<(u32, Vec3, f32)>,
    /// When this animal's last escape was logged (the log says "fled" once per
    /// [`ESCAPE_LOG_EVERY_SECS`], not at every glance at the shark).
    pub(super) last_escape_logged_secs: Option<f64>,
    /// A female that left this male for another, and for how many more
    /// seconds he leaves her alone.
    pub(super) rejected_by: Option<(u32, f32)>,
    /// Wander state for the point body and the wander routine.
    pub(super) wander: Fish,
    /// Seconds until a predator that missed a strike can strike again.
    pub(super) strike_recovery_secs: f32,
    /// The partners it saw at its last decision, best first (a female's
    /// choice, for the log).
    pub(super) mates_seen: Vec<u32>,
}

impl ReefAnimal {
    /// "shark 3", "prey 7", "pacifist 2".
    pub fn name(&self, index: usize) -> String {
        let kind = match self.habits.kind {
            FishKind::Predator => "shark",
            FishKind::Prey => "fish",
            FishKind::Pacifist => "pacifist",
        };
        format!("{kind} {index}")
    }
}

/// A plankton particle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FoodParticle {
    pub id: u32,
    pub position_m: Vec3,
}

/// A strand of seaweed: a chain of points rooted in the sand.
#[derive(Clone, Debug, PartialEq)]
pub struct Seaweed {
    /// Node 0 is the root.
    pub nodes_m: Vec<Vec3>,
    pub segment_m: f32,
    pub(super) phase_rad: f32,
}

/// Seaweed nodes per strand.
pub const SEAWEED_NODES: usize = 10;

/// Counters over the run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ReefCounts {
    pub prey_eaten: u32,
    /// Strikes that failed because other prey near the target confused the
    /// predator (see [`ReefParams::confusion_per_neighbour`]).
    pub missed_strikes: u32,
    /// Pairs that completed the courtship sequence.
    pub spawnings: u32,
    /// Of those, prey whose intention was to school when caught (not the
    /// predator's S_k, which asks whether schoolmates were around it).
    pub schooling_prey_eaten: u32,
    pub food_eaten: u32,
    /// Starts of body overlaps between two fish, not counting a bonded
    /// courting pair's (circling, ascending and nuzzling are close by design).
    pub fish_collisions: u32,
    /// Body-steps inside a rock (should stay 0).
    pub inside_rock_steps: u32,
}

/// The reef.
#[derive(Clone, Debug)]
pub struct ReefWorld {
    /// The reef's tuning (boxed: some 170 bytes a scene's world enum need not
    /// carry inline).
    pub(super) params: Box<ReefParams>,
    pub(super) tank: Tank,
    pub(super) env: Environment,
    pub(super) obstacles: Vec<Obstacle>,
    pub(super) animals: Vec<ReefAnimal>,
    pub(super) food: Vec<FoodParticle>,
    pub(super) food_target: usize,
    pub(super) next_food_id: u32,
    pub(super) food_release_secs: f32,
    pub(super) seaweed: Vec<Seaweed>,
    pub(super) current: WaterCurrent,
    pub(super) config: ReefConfig,
    pub(super) rng: ChaCha8Rng,
    pub(super) time_secs: f64,
    pub(super) steps: u64,
    pub(super) next_history_secs: f64,
    pub(super) events: VecDeque<ReefEvent>,
    /// Events logged since the start (the log keeps the last
    /// [`EVENT_LOG_LEN`]).
    pub(super) events_logged: u64,
    /// What the prey school did last (split, joined, at the pillar).
    pub(super) school_watch: SchoolWatch,
    pub(super) counts: ReefCounts,
    /// Pairs in contact last step (for counting collision starts).
    pub(super) touching: Vec<(u32, u32)>,
    /// Constraint node moves of the muscle bodies.
    pub(super) constraint_moves: u64,
    /// Courting pairs.
    pub(super) pairs: Vec<Pair>,
}

/// Inputs of one animal's decision, read before anyone moves.
#[derive(Clone, Copy)]
pub(super) struct Seen {
    pub(super) position_m: Vec3,
    pub(super) head_m: Vec3,
    pub(super) heading: Vec3,
    pub(super) velocity_m_per_s: Vec3,
    pub(super) length_m: f32,
    pub(super) alive: bool,
    pub(super) kind: FishKind,
    pub(super) sex: Sex,
    pub(super) species: u8,
    /// Swims in a school now, whatever its intention (see [`in_a_school`]).
    pub(super) schooling: bool,
}

impl ReefWorld {
    pub fn new(config: ReefConfig) -> Self {
        let tank = Tank::default();
        let mut config = config;
        config.visibility_m = if config.visibility_m.is_finite() {
            config.visibility_m.clamp(1.0, 20.0)
        } else {
            6.0
        };
        let mut world = Self {
            params: Box::default(),
            tank,
            env: Environment::new(tank),
            obstacles: Vec::new(),
            animals: Vec::new(),
            food: Vec::new(),
            food_target: 0,
            next_food_id: 0,
            food_release_secs: 0.0,
            seaweed: Vec::new(),
            current: WaterCurrent::new(tank, config.current_m_per_s),
            rng: ChaCha8Rng::seed_from_u64(config.seed ^ 0x00EE_F5EA),
            config: config.clone(),
            time_secs: 0.0,
            steps: 0,
            next_history_secs: 0.0,
            events: VecDeque::new(),
            events_logged: 0,
            school_watch: SchoolWatch::default(),
            counts: ReefCounts::default(),
            touching: Vec::new(),
            constraint_moves: 0,
            pairs: Vec::new(),
        };
        world.populate(config.scene);
        world.set_traits(config.traits);
        if let Some(n) = config.food_count {
            world.food_target = n.min(MAX_FOOD);
        }
        for _ in 0..world.food_target {
            let p = world.random_free_point(0.3);
            world.add_food(p);
        }
        world
    }

    pub fn tank(&self) -> &Tank {
        &self.tank
    }

    /// The reef's tuning.
    pub fn params(&self) -> &ReefParams {
        &self.params
    }

    /// Gives every animal its demo's habits with `traits` put in, at once
    /// (the teacher's *Minds* panel). Hunger, libido and fear carry on from
    /// where they are, under the new constants.
    pub fn set_traits(&mut self, traits: KindTraits) {
        self.config.traits = traits;
        for a in &mut self.animals {
            a.habits = traits.of(a.demo_habits.kind).applied_to(a.demo_habits);
        }
    }

    pub fn environment(&self) -> &Environment {
        &self.env
    }
    pub fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }
    pub fn animals(&self) -> &[ReefAnimal] {
        &self.animals
    }
    pub fn food(&self) -> &[FoodParticle] {
        &self.food
    }
    pub fn seaweed(&self) -> &[Seaweed] {
        &self.seaweed
    }
    pub fn events(&self) -> &VecDeque<ReefEvent> {
        &self.events
    }
    /// Events logged since the start, including those the log has dropped.
    pub fn events_logged(&self) -> u64 {
        self.events_logged
    }
    /// Courting pairs.
    pub fn pairs(&self) -> &[Pair] {
        &self.pairs
    }

    /// The pair animal `i` belongs to.
    pub fn pair_of(&self, i: usize) -> Option<&Pair> {
        let i = i as u32;
        self.pairs.iter().find(|p| p.male == i || p.female == i)
    }

    pub fn counts(&self) -> ReefCounts {
        self.counts
    }
    pub fn config(&self) -> &ReefConfig {
        &self.config
    }
    pub fn time_secs(&self) -> f64 {
        self.time_secs
    }
    pub fn steps(&self) -> u64 {
        self.steps
    }
    pub fn constraint_moves(&self) -> u64 {
        self.constraint_moves
    }
    pub fn dt_secs(&self) -> f32 {
        POINT_BODY_DT_SECS
    }
    /// The water velocity at `p_m` now.
    pub fn water_at(&self, p_m: Vec3) -> Vec3 {
        self.current.velocity_m_per_s(p_m, self.time_secs)
    }
    /// Living animals.
    pub fn alive_count(&self) -> usize {
        self.living().count()
    }
    /// The living animals with their indices.
    pub fn living(&self) -> impl Iterator<Item = (usize, &ReefAnimal)> {
        self.animals.iter().enumerate().filter(|(_, a)| a.alive)
    }

    /// Sets V_r, metres (clamped to 1–20).
    pub fn set_visibility(&mut self, visibility_m: f32) {
        if visibility_m.is_finite() {
            self.config.visibility_m = visibility_m.clamp(1.0, 20.0);
        }
    }

    /// Sets the current's strength, m/s.
    pub fn set_current(&mut self, strength_m_per_s: f32) {
        self.config.current_m_per_s = strength_m_per_s;
        self.current = WaterCurrent::new(self.tank, strength_m_per_s);
    }

    /// The prey school's order parameters (living prey only).
    pub fn school_metrics(&self) -> crate::sim::common::school_metrics::SchoolMetrics {
        let fish: Vec<Fish> = self
            .animals
            .iter()
            .filter(|a| a.alive && a.habits.kind == FishKind::Prey)
            .map(|a| {
                let mut f = Fish::new(
                    a.body.position_m(),
                    a.body.velocity_m_per_s(),
                    a.body.body_length_m(),
                    a.hue,
                );
                f.velocity_m_per_s =
                    a.body.heading() * a.body.velocity_m_per_s().length().max(1e-3);
                f
            })
            .collect();
        crate::sim::common::school_metrics::measure(&fish, self.tank.min_m, self.tank.max_m)
    }

    /// Mutable access for tests and teachers' edits (habits, mental state).
    pub fn animal_mut(&mut self, i: usize) -> Option<&mut ReefAnimal> {
        self.animals.get_mut(i)
    }

    /// Moves animal `i` (a test or a teacher's drag) to `position_m` heading
    /// `heading`, at rest.
    pub fn place(&mut self, i: usize, position_m: Vec3, heading: Vec3) {
        let Some(a) = self.animals.get_mut(i) else {
            return;
        };
        let p = self.tank.clamp_inside(position_m, 0.6);
        let length = a.body.body_length_m();
        a.body = match &a.body {
            ReefBody::Physical(old) => ReefBody::Physical(Box::new(PhysicalFish::new(
                old.species,
                length,
                p,
                heading,
                old.hue,
            ))),
            ReefBody::Point(f) => ReefBody::Point(Fish::new(
                p,
                heading.normalize_or(Vec3::X) * 0.3 * TOP_SPEED_BODY_LENGTHS_PER_SEC * length,
                length,
                f.hue,
            )),
        };
        a.intended_m_per_s = a.body.heading() * 0.5 * a.body.top_speed_m_per_s();
        a.wander.position_m = p;
        a.touch = None;
    }

    /// Adds a plankton particle at `p_m` (if there is room).
    pub fn add_food(&mut self, p_m: Vec3) {
        if self.food.len() >= MAX_FOOD {
            return;
        }
        self.food.push(FoodParticle {
            id: self.next_food_id,
            position_m: self.tank.clamp_inside(p_m, 0.05),
        });
        self.next_food_id = self.next_food_id.wrapping_add(1);
    }

    // ----- Building scenes -----

    // ----- Stepping -----

    /// Advances the reef by one step.
    pub fn step(&mut self) {
        let dt = self.dt_secs();
        let mut seen: Vec<Seen> = self
            .animals
            .iter()
            .map(|a| Seen {
                position_m: a.body.position_m(),
                head_m: a.body.head_m(),
                heading: a.body.heading(),
                velocity_m_per_s: a.body.velocity_m_per_s(),
                length_m: a.body.body_length_m(),
                alive: a.alive,
                kind: a.habits.kind,
                sex: a.habits.sex,
                species: a.habits.species,
                schooling: false,
            })
            .collect();
        // S_k of the predator's prey cost: does the fish swim in a school now
        // (whatever it intends)?
        let perception = &self.params.perception;
        let schooling: Vec<bool> = (0..seen.len())
            .map(|i| in_a_school(perception, &seen, i))
            .collect();
        for (s, schooling) in seen.iter_mut().zip(schooling) {
            s.schooling = schooling;
        }
        let bodies: Vec<Sphere> = seen
            .iter()
            .map(|s| {
                fish_occluder(
                    perception,
                    s.position_m,
                    if s.alive { s.length_m } else { 0.0 },
                )
            })
            .collect();
        let refresh_brightness = self.steps.is_multiple_of(18);
        let threat_memory_secs = self.params.threat_memory_secs;
        for i in 0..self.animals.len() {
            if !self.animals[i].alive {
                continue;
            }
            if refresh_brightness && (i as u64 + self.steps / 18).is_multiple_of(4) {
                let scene = self.retina_scene(i);
                let a = &self.animals[i];
                let eye = Eye::new(a.body.head_m(), a.body.heading(), self.config.visibility_m);
                let b = Retina::render(&eye, Vec3::Y, 10, &scene, &self.env).mean_brightness;
                self.animals[i].brightness = b;
            }
            let (percept, neighbours, predator_distances, sighted) =
                self.perceive(i, &seen, &bodies);
            let a = &mut self.animals[i];
            a.last_threat = match sighted {
                Some(j) => Some((j, seen[j as usize].position_m, threat_memory_secs)),
                None => a
                    .last_threat
                    .map(|(j, at, left)| (j, at, left - dt))
                    .filter(|t| t.2 > 0.0),
            };
            let a = &mut self.animals[i];
            a.temperature_c = self.env.temperature_c_at(seen[i].position_m);
            a.mental.update(&a.habits.mental, dt, predator_distances);
            // Predators feel no fear and no libido; prey do not mate (§7.1–7.2).
            match a.habits.kind {
                FishKind::Predator => (a.mental.fear, a.mental.libido) = (0.0, 0.0),
                FishKind::Prey => a.mental.libido = 0.0,
                FishKind::Pacifist => {}
            }
            if let Some((f, left)) = a.rejected_by {
                a.rejected_by = (left > dt).then_some((f, left - dt));
            }
            let me = i as u32;
            let partner = self
                .pairs
                .iter()
                .find(|p| p.bonded() && (p.male == me || p.female == me))
                .map(|p| if p.male == me { p.female } else { p.male });
            let a = &mut self.animals[i];
            let before = a.focus;
            a.focus = a.generator.decide(&a.habits, &a.mental, &percept, partner);
            a.mates_seen.clear();
            a.mates_seen.extend(percept.mates.iter().map(|m| m.0));
            let focus = a.focus;
            if focus.intention != before.intention || focus.target != before.target {
                self.log_decision(i, before, focus);
            }
            let wish = self.behave(i, &seen, &neighbours);
            self.move_body(i, wish, dt);
        }
        self.suck_in(dt);
        self.court(dt);
        self.drift_food(dt);
        self.sway_seaweed(dt);
        self.count_contacts();
        self.watch_school();
        self.time_secs += f64::from(dt);
        self.steps += 1;
        if self.time_secs >= self.next_history_secs {
            self.next_history_secs += HISTORY_EVERY_SECS;
            let t = self.time_secs as f32;
            for a in self.animals.iter_mut().filter(|a| a.alive) {
                if a.history.len() == HISTORY_LEN {
                    a.history.pop_front();
                }
                a.history.push_back(MindSample {
                    time_secs: t,
                    hunger: a.mental.hunger,
                    libido: a.mental.libido,
                    fear: a.mental.fear,
                    intention: a.focus.intention,
                });
            }
        }
    }

    /// Moves animal `i`'s body as `wish` asks. The muscle body: the motor choice
    /// (`reef/motor_choice.rs`) picks its motor controllers; the point-mass body: the
    /// boid layer steers it towards the wished velocity. Under both, keeping off
    /// the glass, sand, surface and rocks bends the direction of a swimming wish.
    pub(super) fn move_body(&mut self, i: usize, wish: Wish, dt: f32) {
        let chase_target = self.chase_target_m(i);
        let water = self.water_at(self.animals[i].body.position_m());
        let time_secs = self.time_secs as f32;
        let a = &mut self.animals[i];
        let desired = wish.velocity_m_per_s;
        a.desired_m_per_s = desired;
        let top = a.body.top_speed_m_per_s();
        let length = a.body.body_length_m();
        let drive = &self.params.drive;
        let response_time_secs = drive.response_time_secs;
        let max_force = top / response_time_secs;
        let position = a.body.position_m();
        // Motor preferences: keep off the glass, sand, surface and rocks. A fish
        // closing in on its food, prey or partner heeds only the glass that lies
        // before it (see `ReefParams::chase_glass_margin_body_lengths`).
        let (look_ahead_s, margin_m) = match chase_target {
            Some(target_m) => (
                (target_m.distance(position) / top.max(1e-3))
                    .min(drive.containment_look_ahead_secs),
                self.params.chase_glass_margin_body_lengths * length,
            ),
            None => (
                drive.containment_look_ahead_secs,
                drive.containment_margin_m(length),
            ),
        };
        let contain = |velocity: Vec3| {
            steering::containment(position, velocity, &self.tank, look_ahead_s, margin_m, top)
        };
        let avoid_rocks = |velocity: Vec3| {
            steering::avoid_obstacles(
                position,
                velocity,
                self.obstacles.iter(),
                3.0,
                self.params.steering.avoidance_clearance_m + 0.5 * length,
                top,
            )
        };
        let keep_off = |velocity: Vec3| contain(velocity) + avoid_rocks(velocity);
        match &mut a.body {
            ReefBody::Physical(p) if wish.gait == Gait::School => {
                // The physics scene's way: the boid layer's intended velocity,
                // then the bridge.
                let velocity = a.intended_m_per_s;
                let steer = steering::limit((desired - velocity) / response_time_secs, max_force);
                let keep = steering::limit(keep_off(velocity) / response_time_secs, max_force);
                let force = steering::limit(steer + keep, max_force);
                let intent = drive_physical(drive, p, &mut a.intended_m_per_s, force, a.touch, dt);
                let (moved, touch) =
                    step_and_constrain(drive, p, &intent, water, &self.tank, &self.obstacles);
                self.constraint_moves += moved as u64;
                a.touch = touch;
            }
            ReefBody::Physical(p) => {
                let heading = p.heading();
                let speed = p.point.velocity_m_per_s.length();
                let mut wish = wish;
                if matches!(wish.gait, Gait::Swim | Gait::Pursue | Gait::Forage) {
                    // The path the fish is on: its heading at the speed it swims
                    // or means to swim.
                    let wanted = desired.length();
                    let path = heading * speed.max(wanted);
                    let bent = desired + keep_off(path);
                    let mut v = bent.normalize_or(heading) * wanted;
                    if let Some(away) = a.touch {
                        v = crate::sim::body::drive::touch_reflex(drive, v, away, top);
                    }
                    wish.velocity_m_per_s = v;
                }
                let body = motor_choice::Body {
                    heading,
                    speed_m_per_s: speed,
                    top_speed_m_per_s: top,
                    turning: p.is_turning(),
                };
                let intent =
                    motor_choice::choose(&self.params.motor_choice, &wish, &body, time_secs);
                let (moved, touch) =
                    step_and_constrain(drive, p, &intent, water, &self.tank, &self.obstacles);
                self.constraint_moves += moved as u64;
                a.touch = touch;
                a.intended_m_per_s = wish.velocity_m_per_s;
            }
            ReefBody::Point(f) => {
                let velocity = a.intended_m_per_s;
                let steer = steering::limit((desired - velocity) / response_time_secs, max_force);
                let containment =
                    steering::limit(contain(velocity) / response_time_secs, max_force);
                let avoidance =
                    steering::limit(avoid_rocks(velocity) / response_time_secs, max_force);
                let force = steering::limit(steer + containment + avoidance, max_force);
                let params = SteeringParams {
                    max_speed_m_per_s: top,
                    min_speed_m_per_s: 0.2 * top,
                    max_force_m_per_s2: max_force,
                    ..SteeringParams::default()
                };
                f.velocity_m_per_s = a.intended_m_per_s;
                f.integrate(force, &params, dt);
                f.position_m += water * dt;
                f.position_m = self.tank.clamp_inside(f.position_m, 0.5 * length.min(0.5));
                for o in &self.obstacles {
                    if o.signed_distance_m(f.position_m) < 0.1 * length {
                        f.position_m = o.push_outside(f.position_m, 0.1 * length);
                    }
                }
                f.advance_tail_phase(dt);
                a.intended_m_per_s = f.velocity_m_per_s;
            }
        }
        if self
            .obstacles
            .iter()
            .any(|o| o.signed_distance_m(a.body.position_m()) < 0.0)
        {
            self.counts.inside_rock_steps += 1;
        }
    }

    pub(super) fn sway_seaweed(&mut self, dt: f32) {
        let t = self.time_secs as f32;
        for w in &mut self.seaweed {
            let root = w.nodes_m[0];
            for n in 1..w.nodes_m.len() {
                let p = w.nodes_m[n];
                let water = self.current.velocity_m_per_s(p, f64::from(t));
                let along = n as f32 / (SEAWEED_NODES - 1) as f32;
                let sway = Vec3::new(
                    fmath::sin(0.7 * t + w.phase_rad + 0.6 * along),
                    0.0,
                    fmath::cos(0.45 * t + 1.3 * w.phase_rad),
                ) * 0.06;
                let lift = Vec3::Y * 0.15;
                w.nodes_m[n] = p + (water * 3.0 + sway + lift) * dt * along;
            }
            // Keep the segment lengths, from the root out.
            w.nodes_m[0] = root;
            for n in 1..w.nodes_m.len() {
                let prev = w.nodes_m[n - 1];
                let dir = (w.nodes_m[n] - prev).normalize_or(Vec3::Y);
                let mut q = prev + dir * w.segment_m;
                q.y = q.y.max(self.tank.min_m.y + 0.02);
                w.nodes_m[n] = q;
            }
        }
    }

    pub(super) fn count_contacts(&mut self) {
        let mut now = Vec::new();
        for i in 0..self.animals.len() {
            if !self.animals[i].alive {
                continue;
            }
            for j in i + 1..self.animals.len() {
                if !self.animals[j].alive {
                    continue;
                }
                // A bonded pair chases each other's tails, rises together and
                // nuzzles: their contacts are the courtship, not collisions.
                let courting = self.pairs.iter().any(|p| {
                    p.bonded()
                        && ((p.male, p.female) == (i as u32, j as u32)
                            || (p.male, p.female) == (j as u32, i as u32))
                });
                if courting {
                    continue;
                }
                let (a, b) = (&self.animals[i].body, &self.animals[j].body);
                let mean = 0.5 * (a.body_length_m() + b.body_length_m());
                if a.position_m().distance(b.position_m()) < COLLISION_BODY_LENGTHS * mean {
                    now.push((i as u32, j as u32));
                }
            }
        }
        for pair in &now {
            if !self.touching.contains(pair) {
                self.counts.fish_collisions += 1;
            }
        }
        self.touching = now;
    }
}
