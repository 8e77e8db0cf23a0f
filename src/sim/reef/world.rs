//! The living reef of Tu & Terzopoulos 1994 (Plate 1): fish with minds. The
//! reef's step is a pipeline of stages, each a struct that owns its state and
//! takes what it reads and writes as explicit inputs (as rapier's
//! `PhysicsPipeline::step` does); this file holds them and lists the order.
//! Each step every living animal, in index order,
//! 1. **perceives** ([`Perception`], `reef/perception.rs`): what it sees with
//!    its 300° occluded vision out to the water's visibility V_r, the
//!    temperature at its centre and the brightness of its retinal image;
//! 2. updates its **mental state** and lets the **intention generator** choose an
//!    intention and a focus ([`ReefAnimal::think`], `reef/animal.rs`, `reef/mind/`);
//! 3. runs the **behaviour routine** for it ([`behaviour::behave`],
//!    `reef/behaviour.rs`, with the pair's wishes of `reef/courtship.rs`),
//!    which gives the velocity it wants and how (swim, hover, or hover and bob);
//! 4. moves its **body** ([`bodies::move_body`], `reef/bodies.rs`): the
//!    muscle-driven spring–mass fish by default, whose motor controllers
//!    (swim-MC, turn-MC, pectoral fins) the routine's motor choice picks
//!    (`reef/motor_choice.rs`), or the light point-mass fish of the boid layer
//!    for big scenes, steered to the wished velocity — the same mind drives
//!    either; keeping off the glass, sand, surface and rocks bends the
//!    direction of a swimming wish (motor preferences).
//!
//! Then mouths suck in food and prey ([`Feeding`], `reef/feeding.rs`), pairs
//! court ([`Courtship`]), plankton drifts and is replenished ([`Plankton`]),
//! seaweed sways in the current (`reef/seaweed.rs`), collisions are counted
//! ([`Contacts`], `reef/contacts.rs`) and the prey school is watched
//! ([`SchoolWatch`], `reef/school_watch.rs`); readable events go to the
//! [`EventLog`] ("shark 12 ate fish 3", `reef/events.rs`). Deterministic for a
//! seed: one ChaCha8 generator, drawn from in the same order every run,
//! animals in index order.

use glam::Vec3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use super::behaviour::{self, BehaviourInputs};
use super::bodies::{self, BodyInputs};
use super::contacts::Contacts;
use super::courtship::{Courtship, CourtshipInputs, Pair};
use super::demos::{self, ReefScene, StockInputs};
use super::events::{EventLog, ReefEvent};
use super::feeding::{Feeding, FeedingInputs, Plankton};
use super::perception::{self, Eye, Perception, PerceptionInputs, Retina};
use super::school_watch::{SchoolWatch, WatchInputs};
use super::seaweed;
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::tank::Tank;
use crate::sim::common::water_current::WaterCurrent;
use crate::sim::reef::animal::MindInputs;
use crate::sim::reef::environment::Environment;
use crate::sim::reef::mind::FishKind;
use crate::sim::reef::mind::habits::KindTraits;
use crate::sim::reef::params::ReefParams;

pub use super::animal::{
    HISTORY_EVERY_SECS, HISTORY_LEN, MAX_REEF_ANIMALS, MindSample, ReefAnimal,
};
pub use super::bodies::{POINT_BODY_DT_SECS, ReefBody, ReefBodyKind};
pub use super::contacts::COLLISION_BODY_LENGTHS;
pub use super::events::{ESCAPE_LOG_EVERY_SECS, EVENT_LOG_LEN, ReefCounts};
pub use super::feeding::{FoodParticle, MAX_FOOD};
pub use super::seaweed::{SEAWEED_NODES, Seaweed};

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

/// The reef: the stages of its step and the state they share.
#[derive(Clone, Debug)]
pub struct ReefWorld {
    /// The reef's tuning (boxed: some 170 bytes a scene's world enum need not
    /// carry inline).
    params: Box<ReefParams>,
    config: ReefConfig,
    tank: Tank,
    env: Environment,
    obstacles: Vec<Obstacle>,
    current: WaterCurrent,
    seaweed: Vec<Seaweed>,
    /// The animals, bodies and minds: the data the stages read and write.
    animals: Vec<ReefAnimal>,
    plankton: Plankton,
    feeding: Feeding,
    courtship: Courtship,
    contacts: Contacts,
    school_watch: SchoolWatch,
    log: EventLog,
    counts: ReefCounts,
    /// Constraint node moves of the muscle bodies.
    constraint_moves: u64,
    rng: ChaCha8Rng,
    time_secs: f64,
    steps: u64,
    next_history_secs: f64,
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
        let params: Box<ReefParams> = Box::default();
        let env = Environment::new(tank);
        let mut rng = ChaCha8Rng::seed_from_u64(config.seed ^ 0x00EE_F5EA);
        let stocked = demos::populate(
            config.scene,
            &mut rng,
            &StockInputs {
                tank,
                env: &env,
                params: &params,
                body: config.body,
                prey_count: config.prey_count,
            },
        );
        let mut world = Self {
            params,
            tank,
            env,
            obstacles: stocked.obstacles,
            current: WaterCurrent::new(tank, config.current_m_per_s),
            seaweed: stocked.seaweed,
            animals: stocked.animals,
            plankton: Plankton::default(),
            feeding: Feeding::default(),
            courtship: Courtship::default(),
            contacts: Contacts::default(),
            school_watch: SchoolWatch::default(),
            log: EventLog::default(),
            counts: ReefCounts::default(),
            constraint_moves: 0,
            rng,
            config: config.clone(),
            time_secs: 0.0,
            steps: 0,
            next_history_secs: 0.0,
        };
        world.plankton.set_target(stocked.food_target);
        world.set_traits(config.traits);
        if let Some(n) = config.food_count {
            world.plankton.set_target(n);
        }
        for _ in 0..world.plankton.target() {
            let p = demos::random_free_point(&mut world.rng, &world.tank, &world.obstacles, 0.3);
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

    /// The reef's tuning, to change (a test's or a census script's probe of
    /// a setting; the lab never changes it).
    pub fn params_mut(&mut self) -> &mut ReefParams {
        &mut self.params
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
        self.plankton.particles()
    }
    pub fn seaweed(&self) -> &[Seaweed] {
        &self.seaweed
    }
    pub fn events(&self) -> &std::collections::VecDeque<ReefEvent> {
        self.log.lines()
    }
    /// Events logged since the start, including those the log has dropped.
    pub fn events_logged(&self) -> u64 {
        self.log.logged()
    }
    /// Courting pairs.
    pub fn pairs(&self) -> &[Pair] {
        self.courtship.pairs()
    }

    /// The pair animal `i` belongs to.
    pub fn pair_of(&self, i: usize) -> Option<&Pair> {
        self.courtship.pair_of(i)
    }

    /// The first event of the demo's moment among those logged after the
    /// first `logged_before` (see [`ReefWorld::events_logged`]).
    pub fn moment_since(&self, logged_before: u64) -> Option<&ReefEvent> {
        let new = self.events_logged().saturating_sub(logged_before) as usize;
        let scene = self.config.scene;
        let events = self.events();
        events
            .iter()
            .skip(events.len().saturating_sub(new))
            .find(|e| scene.is_moment(&e.kind))
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

    /// Renders animal `i`'s retinal image (`size` × `size`).
    pub fn retina(&self, i: usize, size: usize) -> Option<Retina> {
        let a = self.animals.get(i)?;
        let eye = Eye::new(a.body.head_m(), a.body.heading(), self.config.visibility_m);
        let scene =
            perception::retina_scene(&self.animals, self.plankton.particles(), &self.obstacles, i);
        Some(Retina::render(&eye, Vec3::Y, size, &scene, &self.env))
    }

    /// Mutable access for tests and teachers' edits (habits, mental state).
    pub fn animal_mut(&mut self, i: usize) -> Option<&mut ReefAnimal> {
        self.animals.get_mut(i)
    }

    /// Moves animal `i` (a test or a teacher's drag) to `position_m` heading
    /// `heading`, at rest.
    pub fn place(&mut self, i: usize, position_m: Vec3, heading: Vec3) {
        let p = self.tank.clamp_inside(position_m, 0.6);
        if let Some(a) = self.animals.get_mut(i) {
            a.place(p, heading);
        }
    }

    /// Adds a plankton particle at `p_m` (if there is room).
    pub fn add_food(&mut self, p_m: Vec3) {
        self.plankton.add(p_m, &self.tank);
    }

    /// Takes every plankton particle out of the water and releases no more
    /// (a test's tank with only the food it puts in).
    pub fn clear_food(&mut self) {
        self.plankton.clear();
    }

    /// Advances the reef by one step: the stages in order.
    pub fn step(&mut self) {
        let dt = self.dt_secs();
        let time_secs = self.time_secs;
        let view = Perception::look(&self.params.perception, &self.animals);
        let refresh_brightness = self.steps.is_multiple_of(18);
        for i in 0..self.animals.len() {
            if !self.animals[i].alive {
                continue;
            }
            // Perception: the retina's brightness now and then, then what
            // the animal sees.
            if refresh_brightness && (i as u64 + self.steps / 18).is_multiple_of(4) {
                let scene = perception::retina_scene(
                    &self.animals,
                    self.plankton.particles(),
                    &self.obstacles,
                    i,
                );
                let a = &self.animals[i];
                let eye = Eye::new(a.body.head_m(), a.body.heading(), self.config.visibility_m);
                let b = Retina::render(&eye, Vec3::Y, 10, &scene, &self.env).mean_brightness;
                self.animals[i].brightness = b;
            }
            let sight = view.perceive(
                i,
                &self.animals[i],
                &PerceptionInputs {
                    params: &self.params,
                    visibility_m: self.config.visibility_m,
                    env: &self.env,
                    tank: &self.tank,
                    obstacles: &self.obstacles,
                    food: self.plankton.particles(),
                    courtship: &self.courtship,
                },
            );
            // Mind: mental state and intention.
            let partner = self.courtship.bonded_partner(i);
            let before = self.animals[i].think(MindInputs {
                percept: &sight.percept,
                predator_distances: sight.predator_distances,
                sighted: sight.sighted,
                mate_sighted: sight.mate_sighted,
                partner,
                env: &self.env,
                threat_memory_secs: self.params.threat_memory_secs,
                dt_secs: dt,
            });
            self.courtship.forget_rejection(i, dt);
            self.courtship
                .saw_mates(i, sight.percept.mates.iter().map(|m| m.0));
            let focus = self.animals[i].focus;
            if focus.intention != before.intention || focus.target != before.target {
                self.log
                    .log_decision(&self.animals, i, before, focus, time_secs);
            }
            // Behaviour and motor choice: the wish.
            let wish = behaviour::behave(
                i,
                &mut self.animals[i],
                view.seen(),
                &sight.neighbours,
                &mut self.rng,
                &BehaviourInputs {
                    params: &self.params,
                    tank: &self.tank,
                    env: &self.env,
                    obstacles: &self.obstacles,
                    plankton: &self.plankton,
                    courtship: &self.courtship,
                    time_secs: time_secs as f32,
                },
            );
            // Body.
            let chase_target_m =
                behaviour::chase_target_m(&self.animals, self.plankton.particles(), i);
            let water_m_per_s = self.water_at(self.animals[i].body.position_m());
            let a = &mut self.animals[i];
            a.desired_m_per_s = wish.velocity_m_per_s;
            let (body, drive) = a.body_and_drive_mut();
            let moved = bodies::move_body(
                body,
                drive,
                wish,
                &BodyInputs {
                    params: &self.params,
                    tank: &self.tank,
                    obstacles: &self.obstacles,
                    water_m_per_s,
                    chase_target_m,
                    time_secs: time_secs as f32,
                    dt_secs: dt,
                },
            );
            self.constraint_moves += moved.constraint_moves;
            if moved.inside_rock {
                self.counts.inside_rock_steps += 1;
            }
        }
        self.feeding.step(
            &mut self.animals,
            &mut self.plankton,
            FeedingInputs {
                params: &self.params,
                rng: &mut self.rng,
                log: &mut self.log,
                counts: &mut self.counts,
                time_secs,
                dt_secs: dt,
            },
        );
        self.courtship.step(
            &mut self.animals,
            &mut self.log,
            &mut self.counts,
            &CourtshipInputs {
                params: &self.params.courtship,
                surface_y_m: self.tank.max_m.y,
                visibility_m: self.config.visibility_m,
                time_secs,
                dt_secs: dt,
            },
        );
        self.plankton.drift(
            &self.params,
            &mut self.rng,
            &self.tank,
            &self.obstacles,
            &self.current,
            time_secs,
            dt,
        );
        seaweed::sway(
            &mut self.seaweed,
            &self.current,
            &self.tank,
            time_secs as f32,
            dt,
        );
        self.contacts
            .step(&self.animals, &self.courtship, &mut self.counts);
        self.school_watch.step(
            &self.animals,
            &mut self.log,
            &WatchInputs {
                time_secs,
                scene: self.config.scene,
                obstacles: &self.obstacles,
                tank: &self.tank,
            },
        );
        self.time_secs += f64::from(dt);
        self.steps += 1;
        if self.time_secs >= self.next_history_secs {
            self.next_history_secs += HISTORY_EVERY_SECS;
            let t = self.time_secs as f32;
            for a in self.animals.iter_mut().filter(|a| a.alive) {
                a.record_history(t);
            }
        }
    }
}
