//! The whole aquarium: tank, obstacles, fish, sharks and stingrays, advanced in
//! fixed time steps.
//!
//! A world is built from a seed and is deterministic: the same seed and the
//! same sequence of calls give bit-identical animals on the same machine.
//!
//! Each step, in this order: the stingrays' obstacles are rebuilt (one disc per
//! stingray, one polygon per cluster of three or more, see
//! [`stingray::cluster_obstacles`]); every fish steers (wander, or the SIMBA
//! boid layer) and flees sharks it notices; the stingrays glide; the sharks hunt
//! and may catch a fish; finally the school's [`WorldMetrics`] are measured.

use crate::sim::common::fmath;
use glam::Vec3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use super::attention::StepRecord;
use super::params::BoidWorldParams;
use super::placement::{place_obstacles, valid_obstacles};
use super::predators::escape_force;
use crate::sim::boids::control_mode::{self, ControlMode};
use crate::sim::boids::forces::{self, Perception};
use crate::sim::boids::metrics::{ForceWindow, WorldMetrics};
use crate::sim::boids::shark::Shark;
use crate::sim::boids::stingray::Stingray;
use crate::sim::common::fish::{Fish, heading_of};
use crate::sim::common::obstacle::{Obstacle, ObstacleSet};
use crate::sim::common::school_metrics::{self, SchoolMeter, SchoolMetrics};
use crate::sim::common::spatial_grid::{Nearest, SpatialGrid};
use crate::sim::common::steering::{self, SteeringParams};
use crate::sim::common::steering_tuning::SteeringTuning;
use crate::sim::common::tank::Tank;

/// Length of one simulation step in seconds. Default 1/60 s: one step per
/// frame on a 60 Hz display. The step is fixed (the app runs as many steps as
/// real time requires) so that results do not depend on the frame rate and a
/// seed always replays the same way.
pub const DT_SECS: f32 = 1.0 / 60.0;

/// Most fish a world will hold. Default 20,000: far above a classroom's needs
/// (5,000 still run), but stops a typo from freezing the computer.
pub const MAX_FISH_COUNT: usize = 20_000;

/// Hard-constraint margin from the glass, floor and surface in metres.
/// Default 0.05 m: about half a fish's body width, so a fish's body stays in
/// the water even when the hard rule has to act.
pub(super) const TANK_MARGIN_M: f32 = 0.05;

/// Hard-constraint margin from obstacle surfaces in metres. Default 0.05 m:
/// as above, half a body width.
pub(super) const OBSTACLE_MARGIN_M: f32 = 0.05;

/// Hard-constraint margin of a shark's centre from the glass and from
/// obstacles, in metres. Default 0.3 m: half a shark's body width.
pub(super) const SHARK_MARGIN_M: f32 = 0.3;

/// Smallest gap between the footprints of two obstacles, in metres.
/// Default 0.8 m: wide enough for fish (with their avoidance clearance) to
/// swim between, and obstacles never overlap.
pub(super) const OBSTACLE_GAP_M: f32 = 0.8;

/// Smallest gap between a teacher's obstacle and the others, in metres.
/// Default 0.3 m: about one fish length, so a fish pushed out of one obstacle
/// never lands in another.
pub(super) const EDITED_OBSTACLE_GAP_M: f32 = 0.3;

/// Random positions tried per obstacle or animal before giving up (obstacle)
/// or falling back to a pushed-out position (animal). Default 200: placement
/// practically always succeeds in the default tank, and the loop is bounded.
pub(super) const PLACEMENT_ATTEMPTS: usize = 200;

/// Distance from walls and obstacle surfaces at which new fish appear, in
/// metres. Default 0.3 m: about one body length, so no fish starts touching
/// anything.
pub(super) const SPAWN_CLEARANCE_M: f32 = 0.3;

/// Side of the far field's cells as a fraction of the vision distance.
/// Default 0.5 (2.5 m for 5 m vision: 40 cells in the default tank): coarse
/// enough to be cheap for every fish, fine enough that "the cells I see" is
/// close to "the fish I see".
pub(super) const FAR_FIELD_CELL_SHARE: f32 = 0.5;

/// Steps between two measurements of the nearest-neighbour distance, the
/// number of groups and milling (about each group's centre). Default 15 (four times a second): the plots and the CSV
/// take a sample every 15 steps (`metrics_history::SAMPLE_EVERY_STEPS`), so
/// each sample holds a fresh measurement; both change over seconds, and
/// measuring them costs 30 times the other metrics (8 ms with 20,000 fish).
/// Polarization and mean speed are measured after every step.
pub const SPATIAL_METRICS_EVERY_STEPS: u64 = 15;

/// How often a fish searches for the neighbours it heeds, in steps. Default 4
/// (15 times a second; chosen, not from the papers): in between, it keeps
/// heeding the same fish, rechecked every step against its field of view
/// with their positions now ([`forces::recheck_heeded`]), so it never
/// heeds a fish it cannot see; each search starts from them, so it is short.
/// Which fish are the seven nearest changes slowly: a list is at most 67 ms
/// old, in which a fish at 0.5 m/s moves 3.3 cm, under a tenth of a body
/// length. The searches are spread over the steps (fish `i` searches when
/// `i + step` is a multiple of 4), so every step costs the same. Searching
/// every step took about 60 % of a step with 20,000 fish; with this and the
/// seeded search the boid layer runs 2.2 times faster (`docs/benchmarks.md`).
pub const NEIGHBOUR_SEARCH_EVERY_STEPS: u64 = 4;

/// Target mean number of fish per grid cell around a fish for the neighbour
/// search, dimensionless. Default 3: the seven nearest then mostly lie in the
/// 27 cells around a fish, so a search visits one or two rings of cells.
pub(super) const FISH_PER_NEIGHBOUR_CELL: f32 = 3.0;

/// Smallest neighbour-grid cell in metres. Default 0.15 m: half the shortest
/// fish; finer cells only add empty ones.
pub(super) const MIN_NEIGHBOUR_CELL_M: f32 = 0.15;

/// What to build: the seed, the animals and (optionally) the obstacles.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct WorldConfig {
    /// Seed of the random generator; the same seed gives the same aquarium.
    /// Default 1.
    pub seed: u64,
    /// Number of fish. Default 200: a lively tank that any laptop can run.
    pub fish_count: usize,
    /// Number of sharks (at most [`MAX_SHARKS`]). Default 0.
    pub sharks: usize,
    /// Number of stingrays (at most [`MAX_STINGRAYS`]). Default 0.
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

/// What one fish heeds of the school: its nearest seen neighbours and the
/// centre of the distant fish it sees ([`forces::FarField`]).
#[derive(Clone, Copy, Debug)]
pub(super) struct Heeded {
    pub(super) neighbours: Nearest,
    pub(super) far_centre_m: Option<Vec3>,
}

/// The aquarium and everything in it.
#[derive(Clone, Debug)]
pub struct World {
    pub(super) config: WorldConfig,
    pub(super) tank: Tank,
    pub(super) obstacles: Vec<Obstacle>,
    pub(super) fish: Vec<Fish>,
    pub(super) sharks: Vec<Shark>,
    pub(super) stingrays: Vec<Stingray>,
    pub(super) params: SteeringParams,
    /// The world's tuning (walls, the pond's edge, fear).
    pub(super) world_params: BoidWorldParams,
    pub(super) rng: ChaCha8Rng,
    pub(super) time_secs: f64,
    pub(super) steps: u64,
    pub(super) non_finite_repairs: u64,
    /// `Some`: fish steer with the SIMBA boid layer; `None`: they wander alone.
    pub(super) boids: Option<BoidParams>,
    pub(super) catches: u64,
    pub(super) metrics: WorldMetrics,
    pub(super) forces: ForceWindow,
    // Scratch, kept between steps so that a step allocates nothing.
    /// The fish's positions at the start of the step, bucketed for the
    /// neighbour search.
    pub(super) grid: SpatialGrid,
    pub(super) grid_cell_m: f32,
    /// What every fish perceives this step (all see the same snapshot):
    /// positions and velocities at the start of the step.
    pub(super) positions_m: Vec<Vec3>,
    pub(super) velocities_m_per_s: Vec<Vec3>,
    /// Do `grid` and the snapshot hold the last boid step's school (so that
    /// [`World::interaction_neighbours`] can replay it)?
    pub(super) snapshot_is_last_boid_step: bool,
    /// The fixed obstacles with their bounds (the hard rule's broad phase).
    pub(super) fixed_solids: ObstacleSet,
    /// The stingrays as the fish avoid them (discs and cluster polygons).
    pub(super) stingray_avoid: Vec<Obstacle>,
    /// The stingrays as solid discs (the hard rule).
    pub(super) stingray_solids: ObstacleSet,
    /// Fixed obstacles followed by the stingrays' avoidance shapes.
    pub(super) avoid_all: ObstacleSet,
    pub(super) meter: SchoolMeter,
    pub(super) far_field: forces::FarField,
    /// What each fish heeded in the last boid step: its neighbours and the
    /// centre of the far school it saw (see [`NEIGHBOUR_SEARCH_EVERY_STEPS`]).
    pub(super) heeded: Vec<Heeded>,
    /// How frightened each fish was in the last boid step (its escape
    /// urgency, 0 = calm), for the alarm that spreads through a school.
    pub(super) fear: Vec<f32>,
    pub(super) next_fear: Vec<f32>,
    /// What each fish did in the last boid step that cannot be worked out
    /// again afterwards (the dice, wander, fleeing), for [`World::attention`].
    pub(super) last_steps: Vec<StepRecord>,
    /// Can [`World::attention`] replay the last boid step (nothing the urges
    /// read has changed since)?
    pub(super) attention_ready: bool,
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
            None => place_obstacles(&tank, &mut rng),
            Some(list) => valid_obstacles(list.clone(), &tank),
        };
        let mut world = Self {
            config: WorldConfig {
                obstacles: config.obstacles.as_ref().map(|_| obstacles.clone()),
                ..config.clone()
            },
            tank,
            obstacles,
            fish: Vec::new(),
            sharks: Vec::new(),
            stingrays: Vec::new(),
            params: SteeringParams::default(),
            world_params: BoidWorldParams::default(),
            rng,
            time_secs: 0.0,
            steps: 0,
            non_finite_repairs: 0,
            boids: None,
            catches: 0,
            metrics: WorldMetrics::default(),
            forces: ForceWindow::default(),
            grid: SpatialGrid::default(),
            grid_cell_m: 0.0,
            positions_m: Vec::new(),
            velocities_m_per_s: Vec::new(),
            snapshot_is_last_boid_step: false,
            fixed_solids: ObstacleSet::default(),
            stingray_avoid: Vec::new(),
            stingray_solids: ObstacleSet::default(),
            avoid_all: ObstacleSet::default(),
            meter: SchoolMeter::default(),
            far_field: forces::FarField::default(),
            heeded: Vec::new(),
            fear: Vec::new(),
            next_fear: Vec::new(),
            last_steps: Vec::new(),
            attention_ready: false,
        };
        world.fixed_solids.rebuild(&world.obstacles);
        world.set_species_counts(config.sharks, config.stingrays);
        world.set_fish_count(config.fish_count);
        world.measure();
        world
    }

    /// The rocks that a world of `seed` places when no layout is given (they
    /// are placed first, so the fish counts do not change them).
    pub fn seeded_obstacles(seed: u64) -> Vec<Obstacle> {
        place_obstacles(&Tank::default(), &mut ChaCha8Rng::seed_from_u64(seed))
    }

    /// The tank.
    pub fn tank(&self) -> &Tank {
        &self.tank
    }

    /// Rocks, pillars and polygons (the fixed obstacles; stingrays are not in it).
    pub fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }

    /// The stingrays as the fish avoid them this step: one disc per stingray,
    /// or one [`Obstacle::Polygon`] per cluster of three or more close ones.
    pub fn stingray_obstacles(&self) -> &[Obstacle] {
        &self.stingray_avoid
    }

    /// All fish, in a stable order (fish i stays fish i; a caught fish is
    /// replaced in place by a new one).
    pub fn fish(&self) -> &[Fish] {
        &self.fish
    }

    /// The sharks.
    pub fn sharks(&self) -> &[Shark] {
        &self.sharks
    }

    /// The stingrays.
    pub fn stingrays(&self) -> &[Stingray] {
        &self.stingrays
    }

    /// Fish caught by sharks since the start or the last reset.
    pub fn catches(&self) -> u64 {
        self.catches
    }

    /// The school's metrics, force frequencies and catches after the last step.
    pub fn metrics(&self) -> &WorldMetrics {
        &self.metrics
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
        self.snapshot_is_last_boid_step = false;
        self.attention_ready = false;
    }

    /// Puts into `out` the neighbours fish `i` heeded in the last step: up to
    /// [`SteeringTuning::topological_neighbours`] neighbours that it saw, nearest first, as
    /// the boid layer found them (the "show vision" links; the nearest seen
    /// when last searched, see [`NEIGHBOUR_SEARCH_EVERY_STEPS`]). Empty
    /// without the boid layer, for a fish that does not exist, and until the
    /// first step after the boid settings or the number of fish changed.
    pub fn interaction_neighbours(&self, i: usize, out: &mut Vec<usize>) {
        out.clear();
        if self.boids.is_none() || !self.snapshot_is_last_boid_step {
            return;
        }
        if let Some(heeded) = self.heeded.get(i) {
            out.extend(heeded.neighbours.iter().map(|(j, _)| j));
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
        self.forces.total()
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
        self.rebuild_stingray_obstacles();
        self.positions_m.clear();
        self.positions_m
            .extend(self.fish.iter().map(|f| f.position_m));
        self.velocities_m_per_s.clear();
        self.velocities_m_per_s
            .extend(self.fish.iter().map(|f| f.velocity_m_per_s));
        let vision_m = self.boids.map_or(self.world_params.fear_radius_m, |b| {
            b.perception.vision_distance_m
        });
        self.rebuild_neighbour_grid(vision_m);
        match self.boids {
            Some(boids) => self.step_boid_fish(&boids),
            None => self.step_wandering_fish(),
        }
        self.snapshot_is_last_boid_step = self.boids.is_some();
        self.attention_ready = self.boids.is_some();
        self.step_stingrays();
        self.step_sharks();
        self.steps += 1;
        self.time_secs = self.steps as f64 * f64::from(DT_SECS);
        self.measure();
    }

    /// Wandering fish: wander, glass and rock forces, escape.
    pub(super) fn step_wandering_fish(&mut self) {
        let params = self.params;
        let tuning = self.world_params.steering;
        for i in 0..self.fish.len() {
            let before = self.fish[i];
            let fish = &mut self.fish[i];
            let wander = steering::wander(fish, &mut self.rng, &params, &tuning);
            let (containment, avoidance) =
                glass_and_rock_forces(&before, &self.tank, &self.avoid_all, &params, &tuning);
            let escape = escape_force(
                &self.world_params,
                before.position_m,
                before.velocity_m_per_s,
                &self.sharks,
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
                &self.fixed_solids,
                &self.stingray_solids,
            );
        }
    }

    /// One step of the boid layer. All fish perceive the same snapshot of the
    /// school (synchronous update), so the result does not depend on fish order.
    pub(super) fn step_boid_fish(&mut self, boids: &BoidParams) {
        let params = self.boid_steering_params(boids);
        let perception = &boids.perception;
        let tuning = self.world_params.steering;
        let max_force = params.max_force_m_per_s2;
        let n = self.fish.len();
        self.fear.resize(n, 0.0);
        self.next_fear.clear();
        self.next_fear.resize(n, 0.0);
        self.last_steps.resize(n, StepRecord::default());
        let mut applied_counts = [0u32; 5];
        self.far_field.rebuild(
            self.tank.min_m,
            self.tank.max_m,
            perception.vision_distance_m * FAR_FIELD_CELL_SHARE,
            &self.positions_m,
        );
        let avoid_reach_m = self.avoid_reach_m(&params, &tuning);
        // Fish in grid order: neighbours of consecutive fish share cells, so
        // the searches stay in the cache. (The result does not depend on the
        // order: every fish sees the snapshot.)
        // After a change of settings or of the number of fish every fish
        // searches; otherwise a quarter of them (NEIGHBOUR_SEARCH_EVERY_STEPS).
        let cone = forces::ViewCone::new(perception);
        let everyone_searches = !self.snapshot_is_last_boid_step || self.heeded.len() != n;
        self.heeded.resize(
            n,
            Heeded {
                neighbours: Nearest::new(0),
                far_centre_m: None,
            },
        );
        for slot in 0..self.fish.len() {
            let i = self.grid.slots()[slot] as usize;
            let position_m = self.positions_m[i];
            let velocity_m_per_s = self.velocities_m_per_s[i];
            let searches = everyone_searches
                || (i as u64 + self.steps).is_multiple_of(NEIGHBOUR_SEARCH_EVERY_STEPS);
            let known = if everyone_searches {
                Nearest::new(tuning.topological_neighbours)
            } else {
                forces::recheck_heeded(
                    &self.positions_m,
                    &self.velocities_m_per_s,
                    i,
                    &self.heeded[i].neighbours,
                    &cone,
                )
            };
            let heeded = if searches {
                Heeded {
                    // The last neighbours, rechecked, bound the search.
                    neighbours: forces::search_heeded(
                        &self.positions_m,
                        &self.velocities_m_per_s,
                        i,
                        &self.grid,
                        perception,
                        &tuning,
                        &cone,
                        known,
                    ),
                    far_centre_m: self.far_field.seen_centre_m(
                        position_m,
                        heading_of(velocity_m_per_s),
                        &cone,
                    ),
                }
            } else {
                Heeded {
                    neighbours: known,
                    far_centre_m: self.heeded[i].far_centre_m,
                }
            };
            self.heeded[i] = heeded;
            let urges = self.urges_of(i, &heeded, perception, &params, &tuning, avoid_reach_m);
            // Many eyes: the fright of the heeded neighbours (last step's).
            let alarm = heeded
                .neighbours
                .iter()
                .filter(|&(_, d2)| {
                    d2 <= self.world_params.alarm_range_m * self.world_params.alarm_range_m
                })
                .map(|(j, _)| self.fear[j])
                .fold(0.0, f32::max)
                * self.world_params.alarm_share;
            let escape = escape_force(
                &self.world_params,
                position_m,
                velocity_m_per_s,
                &self.sharks,
                &params,
                alarm,
            );
            self.next_fear[i] = escape.map_or(0.0, |(_, urgency)| urgency);
            let escape = escape.map(|(force, _)| force);
            let fleeing = escape.is_some();
            let weights = self.urge_weights(boids, fleeing);
            let combined = control_mode::combine(
                boids.mode,
                &urges.forces,
                &urges.needs,
                &weights,
                max_force,
                &mut self.rng,
            );
            for (count, applied) in applied_counts.iter_mut().zip(combined.applied) {
                *count += u32::from(applied);
            }
            let fish = &mut self.fish[i];
            // Wander on the urges' scale: a full slider gives the same share of
            // the maximum force as a full alignment or cohesion slider.
            let wander = if boids.wander_weight > 0.0 {
                steering::limit(
                    steering::wander(fish, &mut self.rng, &params, &tuning)
                        / perception.response_time_s.max(1e-3),
                    max_force,
                ) * (boids.wander_weight.min(100.0) / 100.0
                    * control_mode::WANDER_SHARE_AT_FULL_WEIGHT)
            } else {
                Vec3::ZERO
            };
            let escape = escape.unwrap_or(Vec3::ZERO);
            let steering_m_per_s2 = combined.force_m_per_s2 + wander + escape;
            self.last_steps[i] = StepRecord {
                applied: combined.applied,
                fleeing,
                wander_m_per_s2: wander,
                escape_m_per_s2: escape,
            };
            self.non_finite_repairs += move_fish(
                fish,
                position_m,
                heading_of(velocity_m_per_s),
                steering_m_per_s2,
                &params,
                &self.tank,
                &self.fixed_solids,
                &self.stingray_solids,
            );
        }
        std::mem::swap(&mut self.fear, &mut self.next_fear);
        self.forces.push(applied_counts, self.fish.len() as u32);
    }

    /// Buckets the fish (the snapshot positions) for the neighbour search,
    /// with cells sized so that about [`FISH_PER_NEIGHBOUR_CELL`] fish share a
    /// cell around a typical fish (judged from the last step's crowding), but
    /// never larger than `vision_m`.
    pub(super) fn rebuild_neighbour_grid(&mut self, vision_m: f32) {
        let n = self.positions_m.len().max(1) as f32;
        let volume_m3 = self.tank.size_m().element_product().max(1e-3);
        let uniform_cell_m = fmath::cbrt(volume_m3 * FISH_PER_NEIGHBOUR_CELL / n);
        let crowding = self.grid.crowding();
        let cell_m = if self.grid_cell_m > 0.0 && crowding > 0.0 {
            self.grid_cell_m * fmath::cbrt(FISH_PER_NEIGHBOUR_CELL / crowding)
        } else {
            uniform_cell_m
        };
        let cell_m = cell_m
            .min(uniform_cell_m)
            .min(vision_m.max(MIN_NEIGHBOUR_CELL_M))
            .max(MIN_NEIGHBOUR_CELL_M);
        let cell_m = if cell_m.is_finite() { cell_m } else { 1.0 };
        self.grid
            .rebuild(self.tank.min_m, self.tank.max_m, cell_m, &self.positions_m);
        self.grid_cell_m = self.grid.cell_m();
    }

    /// Measures the school and stores it with the force frequencies and
    /// catches: polarization, milling and mean speed after every step; the
    /// nearest-neighbour distance and the groups every
    /// [`SPATIAL_METRICS_EVERY_STEPS`] steps (and at the start), kept in
    /// between.
    pub(super) fn measure(&mut self) {
        let school = if self.steps.is_multiple_of(SPATIAL_METRICS_EVERY_STEPS) {
            self.meter
                .measure(&self.fish, self.tank.min_m, self.tank.max_m)
        } else {
            SchoolMetrics {
                nnd_body_lengths: self.metrics.school.nnd_body_lengths,
                groups: self.metrics.school.groups,
                milling: self.metrics.school.milling,
                ..school_metrics::order_parameters(&self.fish)
            }
        };
        self.metrics = WorldMetrics {
            school,
            force_frequencies_recent: self.forces.recent(),
            force_frequencies_total: self.forces.total(),
            catches: self.catches,
        };
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

    /// Fixed obstacles and stingray discs: what a new fish must not start in.
    pub(super) fn solids(&self) -> Vec<Obstacle> {
        let mut solids = self.obstacles.clone();
        solids.extend(self.stingray_solids.as_slice().iter().cloned());
        solids
    }
}

/// Containment (stay off the glass, floor and surface) and obstacle avoidance for
/// `fish` on the wander path.
pub(super) fn glass_and_rock_forces(
    fish: &Fish,
    tank: &Tank,
    obstacles: &ObstacleSet,
    params: &SteeringParams,
    tuning: &SteeringTuning,
) -> (Vec3, Vec3) {
    let reach_m =
        params.avoidance_look_ahead_m + tuning.avoidance_clearance_m + obstacles.max_radius_m();
    let containment = steering::containment(
        fish.position_m,
        fish.velocity_m_per_s,
        tank,
        params.containment_look_ahead_s,
        params.containment_margin_m,
        params.max_speed_m_per_s,
    );
    let avoidance = steering::avoid_obstacles(
        fish.position_m,
        fish.velocity_m_per_s,
        obstacles.near(fish.position_m, reach_m),
        params.avoidance_look_ahead_m,
        tuning.avoidance_clearance_m,
        params.max_speed_m_per_s,
    );
    (containment, avoidance)
}

/// Moves one fish by one step under `steering_m_per_s2`: integrate, repair any
/// non-finite value (back to `before`, at minimum speed), enforce the hard rules
/// and beat the tail. Returns how many repairs were needed (0, 1 or 2).
#[allow(clippy::too_many_arguments)]
pub(super) fn move_fish(
    fish: &mut Fish,
    before_position_m: Vec3,
    before_heading: Vec3,
    steering_m_per_s2: Vec3,
    params: &SteeringParams,
    tank: &Tank,
    obstacles: &ObstacleSet,
    stingrays: &ObstacleSet,
) -> u64 {
    let mut repairs = 0;
    let steering_m_per_s2 = if steering_m_per_s2.is_finite() {
        steering_m_per_s2
    } else {
        repairs += 1;
        Vec3::ZERO
    };
    fish.integrate(steering_m_per_s2, params, DT_SECS);
    if !(fish.position_m.is_finite() && fish.velocity_m_per_s.is_finite()) {
        repairs += 1;
        fish.position_m = before_position_m;
        fish.velocity_m_per_s = before_heading * params.min_speed_m_per_s.max(0.0);
    }
    enforce_hard_constraints(fish, tank, obstacles, stingrays);
    fish.advance_tail_phase(DT_SECS);
    repairs
}

/// The hard rules: whatever the steering did, the fish ends up inside the
/// tank (by [`TANK_MARGIN_M`]) and outside every obstacle and stingray disc (by
/// [`OBSTACLE_MARGIN_M`]), and no longer swims into what it touched.
///
/// Obstacles are at least [`WALL_CLEARANCE_M`] from the side walls, lower than
/// the surface, and pushing out of a half-buried rock or a rooted pillar or
/// polygon never points into the sand, so the obstacle push cannot undo the
/// tank clamp. Stingrays keep
/// [`StingrayParams::gap_m`](super::params::StingrayParams::gap_m) from the
/// glass and from every obstacle, so pushing a fish out of a stingray cannot
/// push it into either; where stingrays overlap, a fish still inside after two rounds is
/// lifted over them.
pub(super) fn enforce_hard_constraints(
    fish: &mut Fish,
    tank: &Tank,
    obstacles: &ObstacleSet,
    stingrays: &ObstacleSet,
) {
    push_clear(
        fish,
        tank,
        obstacles,
        stingrays,
        TANK_MARGIN_M,
        OBSTACLE_MARGIN_M,
    );
}

/// The hard rules for any animal, with its margins from the glass and from
/// obstacles (see [`enforce_hard_constraints`]).
pub(super) fn push_clear(
    body: &mut Fish,
    tank: &Tank,
    obstacles: &ObstacleSet,
    stingrays: &ObstacleSet,
    tank_margin_m: f32,
    obstacle_margin_m: f32,
) {
    let clamped_m = tank.clamp_inside(body.position_m, tank_margin_m);
    let pushed_m = clamped_m - body.position_m;
    for axis in 0..3 {
        // Pushed back on this axis while still swimming outwards: bounce.
        if pushed_m[axis] * body.velocity_m_per_s[axis] < 0.0 {
            body.velocity_m_per_s[axis] = -body.velocity_m_per_s[axis];
        }
    }
    body.position_m = clamped_m;
    let push = |body: &mut Fish, obstacle: &Obstacle| {
        if obstacle.signed_distance_m(body.position_m) < obstacle_margin_m {
            body.position_m = obstacle.push_outside(body.position_m, obstacle_margin_m);
            let normal = obstacle.outward_normal(body.position_m);
            let into_m_per_s = body.velocity_m_per_s.dot(normal);
            if into_m_per_s < 0.0 {
                body.velocity_m_per_s -= 2.0 * into_m_per_s * normal;
            }
        }
    };
    // Broad phase: an obstacle pushes only when the body (where it is now,
    // after the pushes before) is within the margin of it.
    for k in 0..obstacles.len() {
        if let Some(obstacle) = obstacles.get_if_near(k, body.position_m, obstacle_margin_m) {
            push(body, obstacle);
        }
    }
    for _ in 0..2 {
        for k in 0..stingrays.len() {
            if let Some(disc) = stingrays.get_if_near(k, body.position_m, obstacle_margin_m) {
                push(body, disc);
            }
        }
    }
    // Overlapping discs: lift over every disc that still holds the fish.
    let mut lift_to_m = body.position_m.y;
    for disc in stingrays.near(body.position_m, 0.0) {
        if disc.signed_distance_m(body.position_m) < 0.0 {
            lift_to_m = lift_to_m.max(disc.vertical_extent_m().1 + obstacle_margin_m);
        }
    }
    if lift_to_m > body.position_m.y {
        body.position_m.y = lift_to_m.min(tank.max_m.y - tank_margin_m);
        body.velocity_m_per_s.y = body.velocity_m_per_s.y.abs();
    }
}
