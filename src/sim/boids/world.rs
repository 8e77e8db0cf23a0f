//! The whole aquarium: tank, obstacles, fish, sharks and stingrays, advanced in
//! fixed time steps.
//!
//! A world is built from a seed and is deterministic: the same seed and the
//! same sequence of calls give bit-identical animals on the same machine.
//!
//! The world holds the stages of its step, each a struct that owns its state
//! and takes everything else as explicit inputs (as rapier's pipeline does);
//! this file only says in which order they run ([`World::step`]):
//!
//! 1. predators: the stingrays' obstacles are rebuilt (one disc per stingray,
//!    one polygon per cluster of three or more, see
//!    [`super::stingray::cluster_obstacles`]; [`Predators`]);
//! 2. neighbours: the snapshot of the school every fish perceives
//!    ([`Snapshot`]);
//! 3. every fish steers and moves: without the boid layer it wanders; with it,
//!    fish by fish, whom it heeds ([`Heeding`]), its urges ([`UrgeInputs`]),
//!    its fear of sharks ([`Fear`]), the control mode's choice
//!    ([`ControlStage`]), its wander, the record for the attention inspector
//!    ([`StepLog`]) and the move under the hard rules
//!    ([`super::hard_rules::move_fish`]);
//! 4. predators: the stingrays glide, the sharks hunt and may catch a fish;
//! 5. metrics: the school's [`WorldMetrics`] are measured ([`WorldMeter`]).
//!
//! The fixed obstacles are the placement stage's ([`Scenery`]), which also
//! checks a teacher's edits; spawning is in [`super::placement`].

use glam::{Vec2, Vec3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use super::attention::{Attention, StepLog};
use super::control_mode::{self, ControlMode, ControlStage};
use super::forces::Perception;
use super::hard_rules::{enforce_hard_constraints, move_fish};
use super::metrics::{WorldMeter, WorldMetrics};
use super::neighbours::{Heeding, Snapshot};
use super::params::BoidWorldParams;
use super::placement::{self, ObstacleEditError, Scenery};
use super::predators::{self, Fear, Predators};
use super::shark::Shark;
use super::stingray::Stingray;
use super::urges::{self, UrgeInputs};
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::steering::{self, SteeringParams};
use crate::sim::common::tank::Tank;

pub use super::metrics::SPATIAL_METRICS_EVERY_STEPS;
pub use super::neighbours::NEIGHBOUR_SEARCH_EVERY_STEPS;
pub use super::params::DT_SECS;

/// Most fish a world will hold. Default 50,000: the scale the performance
/// goal (issue 36) and the benchmark measure; the app's own limit is the
/// settings' `FISH_COUNT_MAX`. Stops a typo from freezing the computer.
pub const MAX_FISH_COUNT: usize = 50_000;

/// What to build: the seed, the animals and (optionally) the obstacles.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct WorldConfig {
    /// Seed of the random generator; the same seed gives the same aquarium.
    /// Default 1.
    pub seed: u64,
    /// Number of fish. Default 200: a lively tank that any laptop can run.
    pub fish_count: usize,
    /// Number of sharks (at most [`MAX_SHARKS`](super::shark::MAX_SHARKS)). Default 0.
    pub sharks: usize,
    /// Number of stingrays (at most
    /// [`MAX_STINGRAYS`](super::stingray::MAX_STINGRAYS)). Default 0.
    pub stingrays: usize,
    /// `None`: the layout generated from the seed; `Some`: exactly these
    /// obstacles (e.g. edited by a teacher; invalid ones are left out, see
    /// [`World::set_obstacles`]). Default `None`.
    pub obstacles: Option<Vec<Obstacle>>,
}

impl Default for WorldConfig {
    fn default() -> Self {
        Self {
            seed: 1,
            fish_count: 200,
            sharks: 0,
            stingrays: 0,
            obstacles: None,
        }
    }
}

/// The SIMBA boid layer's settings: five weights on the papers' 0–100 scale (in
/// [`control_mode::Force::ALL`] order), how they combine, and what fish perceive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoidParams {
    pub weights: [f32; 5],
    pub mode: ControlMode,
    pub perception: Perception,
    /// Wander on the urges' 0–100 scale: a full slider gives
    /// [`control_mode::WANDER_SHARE_AT_FULL_WEIGHT`] of the maximum force. It is
    /// added on top of the control mode (as fleeing is). Default
    /// [`DEFAULT_WANDER`] in every preset.
    pub wander_weight: f32,
}

/// The boid layer's default wander (0–100), the same in every preset.
/// Default 10 (tuned): enough that loners roam apart, too little to break a
/// school.
pub const DEFAULT_WANDER: f32 = 10.0;

impl BoidParams {
    /// Table 1's "group" weights, blended, with the boid layer's default senses
    /// and body (the same for every preset: only the five weights differ
    /// between *Individual* and *Group*).
    ///
    /// Senses and body (tuned on seeds 1–12, 200 fish; `docs/boids.md`):
    /// - vision 5 m and 300° (Tu & Terzopoulos §5): about a school's width in
    ///   this 12 m tank, so a straggler still sees the school;
    /// - the 7 nearest seen neighbours (Ballerini et al. 2008);
    /// - personal space 0.8 m: neighbours closer than this push (more strongly
    ///   the closer they are), so a school's nearest neighbours settle about
    ///   one body length apart (Pitcher & Partridge 1979);
    /// - top speed 0.8 m/s, maximum force 8 m/s² and response time 0.1 s: an
    ///   urge asks for its velocity change within a tenth of a second (limited
    ///   to the maximum force), and its weight's share of that (25 % at 100,
    ///   avoidance 100 %) is what the fish feels. With 0.25 s the group school
    ///   milled more (polarization 0.58 against 0.86, seeds 1–12);
    /// - wander 10 (on the urges' 0–100 scale): a little roaming of their own,
    ///   which a school's alignment and cohesion overcome and loners' do not.
    pub fn group() -> Self {
        Self {
            weights: control_mode::GROUP_WEIGHTS,
            mode: ControlMode::Blended,
            perception: Perception {
                vision_distance_m: 5.0,
                vision_angle_rad: 300f32.to_radians(),
                max_speed_m_per_s: 0.8,
                max_force_m_per_s2: 8.0,
                separation_distance_m: 0.8,
                response_time_s: 0.1,
                clear_sight_m: 0.3,
                far_pull: 0.5,
                min_speed_m_per_s: 0.15,
            },
            wander_weight: DEFAULT_WANDER,
        }
    }

    /// Table 1's "individual" weights with exactly the group's senses, body,
    /// wander and mode: the weights alone make the difference.
    pub fn individual() -> Self {
        Self {
            weights: control_mode::INDIVIDUAL_WEIGHTS,
            ..Self::group()
        }
    }
}

/// The aquarium and everything in it: what the world is (tank, fish, settings,
/// the random generator, the clock) and the stages of its step, each owning
/// its own state.
#[derive(Clone, Debug)]
pub struct World {
    config: WorldConfig,
    tank: Tank,
    fish: Vec<Fish>,
    params: SteeringParams,
    /// The world's tuning (walls, the pond's edge, fear).
    world_params: BoidWorldParams,
    /// The one generator every random draw comes from, in a fixed order.
    rng: ChaCha8Rng,
    time_secs: f64,
    steps: u64,
    non_finite_repairs: u64,
    /// `Some`: fish steer with the SIMBA boid layer; `None`: they wander alone.
    boids: Option<BoidParams>,
    /// Placement: the fixed obstacles.
    scenery: Scenery,
    /// Predators: sharks, stingrays and the stingrays as obstacles.
    predators: Predators,
    /// Neighbours: what every fish perceives of the school this step.
    snapshot: Snapshot,
    /// Neighbours: whom each fish heeds.
    heeding: Heeding,
    /// Fear: how frightened each fish is (the alarm).
    fear: Fear,
    /// Control mode: its choices and their counts.
    control: ControlStage,
    /// What each fish did in the last boid step that cannot be worked out
    /// again afterwards (the dice, wander, fleeing), for [`World::attention`].
    step_log: StepLog,
    /// Metrics: the school measured after every step.
    meter: WorldMeter,
    /// The fish in the snapshot's slot order during a boid step (a buffer
    /// kept between steps): the step reads and writes them front to back,
    /// then puts them back in their places.
    slot_fish: Vec<Fish>,
}

impl World {
    /// Same as the module constant [`DT_SECS`].
    pub const DT_SECS: f32 = DT_SECS;

    /// Build the scene for `config.seed`: the obstacles (generated: 4–6 rocks
    /// half-buried in the sand, 2–3 pillars and 0–1 reef ledge, none
    /// overlapping and all away from the glass; or `config.obstacles`), then
    /// the stingrays, the sharks and `config.fish_count` fish (each count at
    /// most its maximum) at free places.
    pub fn new(config: WorldConfig) -> Self {
        let tank = Tank::default();
        let mut rng = ChaCha8Rng::seed_from_u64(config.seed);
        let obstacles = match &config.obstacles {
            None => placement::place_obstacles(&tank, &mut rng),
            Some(list) => placement::valid_obstacles(list.clone(), &tank),
        };
        let mut world = Self {
            config: WorldConfig {
                obstacles: config.obstacles.as_ref().map(|_| obstacles.clone()),
                ..config.clone()
            },
            tank,
            fish: Vec::new(),
            params: SteeringParams::default(),
            world_params: BoidWorldParams::default(),
            rng,
            time_secs: 0.0,
            steps: 0,
            non_finite_repairs: 0,
            boids: None,
            scenery: Scenery::new(obstacles),
            predators: Predators::default(),
            snapshot: Snapshot::default(),
            heeding: Heeding::default(),
            fear: Fear::default(),
            control: ControlStage::default(),
            step_log: StepLog::default(),
            meter: WorldMeter::default(),
            slot_fish: Vec::new(),
        };
        world.set_species_counts(config.sharks, config.stingrays);
        world.set_fish_count(config.fish_count);
        world.measure();
        world
    }

    /// The rocks that a world of `seed` places when no layout is given (they
    /// are placed first, so the fish counts do not change them).
    pub fn seeded_obstacles(seed: u64) -> Vec<Obstacle> {
        placement::place_obstacles(&Tank::default(), &mut ChaCha8Rng::seed_from_u64(seed))
    }

    /// The tank.
    pub fn tank(&self) -> &Tank {
        &self.tank
    }

    /// Rocks, pillars and polygons (the fixed obstacles; stingrays are not in it).
    pub fn obstacles(&self) -> &[Obstacle] {
        self.scenery.obstacles()
    }

    /// The stingrays as the fish avoid them this step: one disc per stingray,
    /// or one [`Obstacle::Polygon`] per cluster of three or more close ones.
    pub fn stingray_obstacles(&self) -> &[Obstacle] {
        self.predators.stingray_avoid()
    }

    /// All fish, in a stable order (fish i stays fish i; a caught fish is
    /// replaced in place by a new one).
    pub fn fish(&self) -> &[Fish] {
        &self.fish
    }

    /// The sharks.
    pub fn sharks(&self) -> &[Shark] {
        self.predators.sharks()
    }

    /// The stingrays.
    pub fn stingrays(&self) -> &[Stingray] {
        self.predators.stingrays()
    }

    /// Fish caught by sharks since the start or the last reset.
    pub fn catches(&self) -> u64 {
        self.predators.catches()
    }

    /// The school's metrics, force frequencies and catches after the last step.
    pub fn metrics(&self) -> &WorldMetrics {
        self.meter.metrics()
    }

    /// Simulated time since the start or the last reset, in seconds.
    pub fn time_secs(&self) -> f64 {
        self.time_secs
    }

    /// Number of steps since the start or the last reset.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The seed this world was built from.
    pub fn seed(&self) -> u64 {
        self.config.seed
    }

    /// The world's tuning (walls, the pond's edge, fear; see [`BoidWorldParams`]).
    pub fn world_params(&self) -> &BoidWorldParams {
        &self.world_params
    }

    /// Change the world's tuning: the ablations of `docs/boids.md`
    /// (`examples/boid_contrast.rs`) switch its constants off one at a time, and the confusion and
    /// joint-flight switches set it.
    /// Any values are safe, as with [`World::params_mut`].
    pub fn world_params_mut(&mut self) -> &mut BoidWorldParams {
        &mut self.world_params
    }

    /// The steering tuning in use.
    pub fn params(&self) -> &SteeringParams {
        &self.params
    }

    /// Change the steering tuning (e.g. from sliders). Any values are safe:
    /// the fish still never leave the tank, enter a rock or become NaN.
    pub fn params_mut(&mut self) -> &mut SteeringParams {
        &mut self.params
    }

    /// How often a non-finite (NaN or infinite) steering force or state had
    /// to be replaced. Always 0 with sane parameters; a teaching aid for
    /// spotting broken tuning.
    pub fn non_finite_repairs(&self) -> u64 {
        self.non_finite_repairs
    }

    /// Steer with the SIMBA boid layer (`Some`) or wander alone (`None`).
    pub fn set_boids(&mut self, boids: Option<BoidParams>) {
        self.boids = boids;
        self.heeding.forget();
        self.step_log.withdraw();
    }

    /// Puts into `out` the neighbours fish `i` heeded in the last step: up to
    /// [`SteeringTuning::topological_neighbours`](crate::sim::common::steering_tuning::SteeringTuning::topological_neighbours)
    /// neighbours that it saw, nearest first, as the boid layer found them
    /// (the "show vision" links; the nearest seen when last searched, see
    /// [`NEIGHBOUR_SEARCH_EVERY_STEPS`]). Empty without the boid layer, for a
    /// fish that does not exist, and until the first step after the boid
    /// settings or the number of fish changed.
    pub fn interaction_neighbours(&self, i: usize, out: &mut Vec<usize>) {
        out.clear();
        if self.boids.is_none() || !self.heeding.is_current() {
            return;
        }
        if let Some(heeded) = self.heeding.get(i) {
            out.extend(heeded.neighbours().iter().map(|(j, _)| j));
        }
    }

    /// The boid-layer settings, when on.
    pub fn boids(&self) -> Option<&BoidParams> {
        self.boids.as_ref()
    }

    /// Fraction of fish-steps on which each force was applied since the start
    /// (random modes show their lottery here), in [`control_mode::Force::ALL`]
    /// order. The last second alone is in [`WorldMetrics::force_frequencies_recent`].
    pub fn force_frequencies(&self) -> [f64; 5] {
        self.control.window().total()
    }

    /// What fish `i` paid attention to in the last step: the neighbours it
    /// heeded, its five urges as the step computed and weighed them, which the
    /// control mode applied, wander and fleeing, the steering and its velocity
    /// before and after. A pure query: the step is not run again and nothing
    /// changes.
    ///
    /// `None` without the boid layer, for a fish that does not exist, and until
    /// the first step after anything the urges read changed (the boid settings,
    /// the number of fish, the obstacles or stingrays).
    pub fn attention(&self, i: usize) -> Option<Attention> {
        let boids = self.boids.as_ref()?;
        let record = self.step_log.get(i)?;
        let (slot, heeded) = self.heeding.get_in_slots(i)?;
        let fish = self.fish.get(i)?;
        if i >= self.snapshot.len() {
            return None;
        }
        let params = urges::boid_steering_params(&self.params, &boids.perception);
        let inputs = UrgeInputs::new(
            &self.snapshot,
            &self.tank,
            self.predators.avoid_all(),
            &boids.perception,
            &params,
            &self.world_params,
        );
        let weights = urges::urge_weights(boids.weights, record.fleeing(), &self.world_params);
        Some(Attention::replay(
            i,
            slot,
            boids.mode,
            &inputs,
            heeded,
            weights,
            record,
            fish.velocity_m_per_s,
        ))
    }

    /// Advance the world by one fixed step of [`DT_SECS`]. For each fish:
    ///
    /// 1. steering: without the boid layer wander·w₁ + containment·w₂ +
    ///    obstacle avoidance·w₃ (rocks, pillars, polygons and stingrays); with
    ///    it the SIMBA forces combined by the control mode;
    /// 2. plus, when it notices a shark, an escape ([`steering::evade`]) at the
    ///    full maximum force, on top of the control mode: a fish does not roll
    ///    dice about fleeing (Tu & Terzopoulos §6: fear overrides the other
    ///    intentions);
    /// 3. integrate: limit to max force, semi-implicit Euler, speed kept in
    ///    [min, max] (see [`Fish::integrate`]), non-finite results repaired;
    /// 4. hard constraints: clamp into the tank and push out of every
    ///    obstacle and stingray, reflecting the velocity component that points
    ///    into it, so no fish ever leaves the water or enters a rock;
    /// 5. advance the tail-beat phase.
    ///
    /// Then the stingrays and sharks move, and the metrics are measured.
    pub fn step(&mut self) {
        self.predators.rebuild_stingray_obstacles(
            &self.tank,
            self.scenery.obstacles(),
            &self.world_params,
        );
        let vision_m = self.boids.map_or(self.world_params.fear_radius_m, |b| {
            b.perception.vision_distance_m
        });
        self.snapshot.take(&self.fish, &self.tank, vision_m);
        match self.boids {
            Some(boids) => self.step_boid_fish(&boids),
            None => self.step_wandering_fish(),
        }
        self.heeding.end_step(self.boids.is_some());
        self.step_log.end_step(self.boids.is_some());
        self.predators.step_stingrays(
            &self.tank,
            self.scenery.obstacles(),
            &self.params,
            &self.world_params,
            &mut self.rng,
        );
        self.non_finite_repairs += self.predators.step_sharks(
            &mut self.fish,
            self.snapshot.grid(),
            &self.tank,
            self.scenery.obstacles(),
            self.scenery.solids(),
            &self.params,
            &self.world_params,
            &mut self.rng,
        );
        self.steps += 1;
        self.time_secs = self.steps as f64 * f64::from(DT_SECS);
        self.measure();
    }

    /// Wandering fish: wander, glass and rock forces, escape.
    fn step_wandering_fish(&mut self) {
        let params = self.params;
        let tuning = self.world_params.steering;
        for i in 0..self.fish.len() {
            let before = self.fish[i];
            let fish = &mut self.fish[i];
            let wander = steering::wander(fish, &mut self.rng, &params, &tuning);
            let (containment, avoidance) = urges::glass_and_rock_forces(
                &before,
                &self.tank,
                self.predators.avoid_all(),
                &params,
                &tuning,
            );
            let escape = predators::escape_force(
                &self.world_params,
                before.position_m,
                before.velocity_m_per_s,
                self.predators.sharks(),
                &params,
                0.0,
            )
            .map(|(force, _)| force);
            let steering_m_per_s2 = wander * params.wander_weight
                + containment * params.containment_weight
                + avoidance * params.avoidance_weight
                + escape.unwrap_or(Vec3::ZERO);
            self.non_finite_repairs += move_fish(
                fish,
                before.position_m,
                before.heading(),
                steering_m_per_s2,
                &params,
                &self.tank,
                self.scenery.solids(),
                self.predators.stingray_solids(),
            );
        }
    }

    /// One step of the boid layer, fish by fish in the snapshot grid's order
    /// (neighbours of consecutive fish share cells, so the searches stay in the
    /// cache; the result does not depend on the order, as every fish sees the
    /// snapshot). The random draws (the control mode's dice, then wander) come
    /// in this order, fish by fish.
    fn step_boid_fish(&mut self, boids: &BoidParams) {
        let perception = &boids.perception;
        let params = urges::boid_steering_params(&self.params, perception);
        let tuning = &self.world_params.steering;
        let n = self.fish.len();
        self.fear.begin_step(n);
        self.step_log.begin_step(n);
        self.control
            .begin_step(boids.mode, params.max_force_m_per_s2);
        self.heeding
            .begin_step(&self.snapshot, &self.tank, perception, self.steps);
        let inputs = UrgeInputs::new(
            &self.snapshot,
            &self.tank,
            self.predators.avoid_all(),
            perception,
            &params,
            &self.world_params,
        );
        // Every fish moves itself only, so it can move in a copy in slot order
        // (next to its neighbours in the snapshot) and be put back after.
        self.slot_fish.clear();
        self.slot_fish.extend(
            self.snapshot
                .fish_slots()
                .iter()
                .map(|&i| self.fish[i as usize]),
        );
        for slot in 0..n {
            let i = self.snapshot.fish_at_slot(slot);
            let position_m = self.snapshot.slot_positions_m()[slot];
            let velocity_m_per_s = self.snapshot.slot_velocities_m_per_s()[slot];
            let heeded = self
                .heeding
                .heed(i, slot, &self.snapshot, perception, tuning);
            let urges = inputs.urges_of(slot, heeded);
            let escape = self.fear.escape(
                i,
                heeded.neighbours(),
                self.snapshot.fish_slots(),
                position_m,
                velocity_m_per_s,
                self.predators.sharks(),
                &params,
                &self.world_params,
            );
            let fleeing = escape.is_some();
            let weights = urges::urge_weights(boids.weights, fleeing, &self.world_params);
            let combined =
                self.control
                    .combine(urges.forces(), urges.needs(), &weights, &mut self.rng);
            let fish = &mut self.slot_fish[slot];
            let wander = urges::boid_wander(
                fish,
                &mut self.rng,
                boids.wander_weight,
                perception,
                &params,
                tuning,
            );
            let escape = escape.unwrap_or(Vec3::ZERO);
            self.step_log
                .record(i, combined.applied, fleeing, wander, escape);
            self.non_finite_repairs += move_fish(
                fish,
                position_m,
                self.snapshot.slot_headings()[slot],
                combined.force_m_per_s2 + wander + escape,
                &params,
                &self.tank,
                self.scenery.solids(),
                self.predators.stingray_solids(),
            );
        }
        for (fish, &i) in self.slot_fish.iter().zip(self.snapshot.fish_slots()) {
            self.fish[i as usize] = *fish;
        }
        self.fear.end_step();
        self.control.end_step(n as u32);
    }

    /// Measures the school after the step (see [`WorldMeter::measure`]).
    fn measure(&mut self) {
        self.meter.measure(
            self.steps,
            &self.fish,
            &self.tank,
            self.control.window(),
            self.predators.catches(),
        );
    }

    /// Rebuild the world from `seed` with the same numbers of fish, sharks and
    /// stingrays, the same steering tuning and, if the obstacles were edited
    /// (or given in the config), the same obstacles; time, step count and
    /// catches restart at zero.
    pub fn reset(&mut self, seed: u64) {
        let params = self.params;
        let boids = self.boids;
        *self = Self::new(WorldConfig {
            seed,
            ..self.config.clone()
        });
        self.params = params;
        self.boids = boids;
    }

    /// Keep the first `fish_count` fish (at most [`MAX_FISH_COUNT`]), or add
    /// new ones drawn from the world's random generator. Existing fish are
    /// never changed. Sharks hunting a removed fish lose it.
    pub fn set_fish_count(&mut self, fish_count: usize) {
        let fish_count = fish_count.min(MAX_FISH_COUNT);
        self.fish.truncate(fish_count);
        self.predators.rebuild_stingray_obstacles(
            &self.tank,
            self.scenery.obstacles(),
            &self.world_params,
        );
        if self.fish.len() < fish_count {
            let solids = self.predators.solids(self.scenery.obstacles());
            while self.fish.len() < fish_count {
                let fish = placement::spawn_fish(&self.tank, &solids, &self.params, &mut self.rng);
                self.fish.push(fish);
            }
        }
        self.predators.forget_fish_from(fish_count);
        self.config.fish_count = fish_count;
        self.heeding.forget();
        self.step_log.withdraw();
    }

    /// Keep the first `sharks` sharks and `stingrays` stingrays, or add new ones
    /// at free places from the world's random generator (at most
    /// [`MAX_SHARKS`](super::shark::MAX_SHARKS) = 10 and
    /// [`MAX_STINGRAYS`](super::stingray::MAX_STINGRAYS) = 20). Fish under a
    /// new stingray are pushed out at once.
    pub fn set_species_counts(&mut self, sharks: usize, stingrays: usize) {
        let (sharks, stingrays) = self.predators.set_counts(
            sharks,
            stingrays,
            &self.tank,
            self.scenery.obstacles(),
            self.scenery.solids(),
            &self.world_params,
            &mut self.rng,
        );
        self.config.sharks = sharks;
        self.config.stingrays = stingrays;
        self.settle();
    }

    /// Add an obstacle after checking it ([`Obstacle::validate`], and at least
    /// 0.3 m from every other obstacle); returns its index. Fish inside it are
    /// pushed out at once; stingrays too close to it move to a free place.
    pub fn add_obstacle(&mut self, obstacle: Obstacle) -> Result<usize, ObstacleEditError> {
        let index = self.scenery.add(obstacle, &self.tank)?;
        self.obstacles_changed();
        Ok(index)
    }

    /// Move obstacle `index` so that its footprint centre is at `new_floor_xz`
    /// ((x, z) in metres), keeping its shape and height. Errors if there is no
    /// such obstacle or the new place is not allowed (then nothing changes).
    pub fn move_obstacle(
        &mut self,
        index: usize,
        new_floor_xz: Vec2,
    ) -> Result<(), ObstacleEditError> {
        self.scenery.move_to(index, new_floor_xz, &self.tank)?;
        self.obstacles_changed();
        Ok(())
    }

    /// Remove obstacle `index`; `false` if there is none.
    pub fn remove_obstacle(&mut self, index: usize) -> bool {
        let removed = self.scenery.remove(index);
        if removed {
            self.obstacles_changed();
        }
        removed
    }

    /// Replace all obstacles (e.g. a teacher's saved layout). Obstacles that
    /// fail [`Obstacle::validate`] are left out (and logged); overlapping ones
    /// are kept in order as long as they keep the 0.3 m gap to those before
    /// them. Everything inside the new obstacles is pushed out at once.
    pub fn set_obstacles(&mut self, obstacles: Vec<Obstacle>) {
        self.scenery.replace(obstacles, &self.tank);
        self.obstacles_changed();
    }

    /// After an edit of the obstacles: the config remembers them, stingrays now
    /// too close to one move, and everything is pushed out of them.
    fn obstacles_changed(&mut self) {
        self.config.obstacles = Some(self.scenery.obstacles().to_vec());
        self.predators.replace_misplaced_stingrays(
            &self.tank,
            self.scenery.obstacles(),
            &self.world_params,
            &mut self.rng,
        );
        self.settle();
    }

    /// After a change of obstacles or stingrays: push every fish and shark out
    /// of everything at once, so no animal is ever inside an obstacle.
    fn settle(&mut self) {
        self.predators.rebuild_stingray_obstacles(
            &self.tank,
            self.scenery.obstacles(),
            &self.world_params,
        );
        // The urges read the obstacles and stingrays: the last step's can no
        // longer be replayed.
        self.step_log.withdraw();
        for fish in &mut self.fish {
            enforce_hard_constraints(
                fish,
                &self.tank,
                self.scenery.solids(),
                self.predators.stingray_solids(),
            );
        }
        self.predators
            .settle_sharks(&self.tank, self.scenery.solids());
    }
}

/// Hands on the animals, for tests that place them.
#[cfg(test)]
impl World {
    /// The fish, to place by hand.
    pub(super) fn fish_mut(&mut self) -> &mut [Fish] {
        &mut self.fish
    }

    /// The sharks, to place by hand.
    pub(super) fn sharks_mut(&mut self) -> &mut [Shark] {
        self.predators.sharks_mut()
    }

    /// The stingrays, to place by hand.
    pub(super) fn stingrays_mut(&mut self) -> &mut [Stingray] {
        self.predators.stingrays_mut()
    }
}
