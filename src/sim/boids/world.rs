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

use std::f32::consts::TAU;

use glam::{Vec2, Vec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::sim::boids::control_mode::{self, ControlMode};
use crate::sim::boids::forces::{self, Perception};
use crate::sim::boids::metrics::{ForceWindow, WorldMetrics};
use crate::sim::boids::shark::{self, MAX_SHARKS, Shark};
use crate::sim::boids::stingray::{self, MAX_STINGRAYS, Stingray};
use crate::sim::common::fish::{Fish, heading_of};
use crate::sim::common::obstacle::{Obstacle, ObstacleError, ObstacleSet, WALL_CLEARANCE_M};
use crate::sim::common::school_metrics::{self, SchoolMeter, SchoolMetrics};
use crate::sim::common::spatial_grid::{Nearest, SpatialGrid};
use crate::sim::common::steering::{self, AVOIDANCE_CLEARANCE_M, SteeringParams};
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
const TANK_MARGIN_M: f32 = 0.05;

/// Hard-constraint margin from obstacle surfaces in metres. Default 0.05 m:
/// as above, half a body width.
const OBSTACLE_MARGIN_M: f32 = 0.05;

/// Hard-constraint margin of a shark's centre from the glass and from
/// obstacles, in metres. Default 0.3 m: half a shark's body width.
const SHARK_MARGIN_M: f32 = 0.3;

/// Smallest gap between the footprints of two obstacles, in metres.
/// Default 0.8 m: wide enough for fish (with their avoidance clearance) to
/// swim between, and obstacles never overlap.
const OBSTACLE_GAP_M: f32 = 0.8;

/// Smallest gap between a teacher's obstacle and the others, in metres.
/// Default 0.3 m: about one fish length, so a fish pushed out of one obstacle
/// never lands in another.
const EDITED_OBSTACLE_GAP_M: f32 = 0.3;

/// Random positions tried per obstacle or animal before giving up (obstacle)
/// or falling back to a pushed-out position (animal). Default 200: placement
/// practically always succeeds in the default tank, and the loop is bounded.
const PLACEMENT_ATTEMPTS: usize = 200;

/// Distance from walls and obstacle surfaces at which new fish appear, in
/// metres. Default 0.3 m: about one body length, so no fish starts touching
/// anything.
const SPAWN_CLEARANCE_M: f32 = 0.3;

/// How far from a vertical glass wall the boid layer's wall algorithm starts
/// to act, in metres. Default 1.5 m (tuned): with containment's Table 1 share
/// (26 % of 25 % of the 8 m/s² maximum ≈ 0.5 m/s²) a fish at top speed turns
/// along the glass within about 1.3 m, so it rarely needs the hard rule.
pub const BOID_WALL_RANGE_M: f32 = 1.5;

/// How far from the glass, sand and surface the boid layer's containment
/// ("stay in the pond") keeps a fish's predicted path (1.5 s ahead), in metres.
/// Default 1.0 m (tuned on seeds 1–12, `docs/boids.md`): about three body
/// lengths, so the containment slider visibly keeps fish out of the pond's edge
/// zone (at 0.5 m the wall algorithm acted first and the slider did little).
pub const POND_COMFORT_MARGIN_M: f32 = 1.0;

/// Fish notice a shark within this distance when it is inside their field of
/// view (300°), in metres. Default 4 m (chosen): a shark 2 m long is plain to
/// see at that range in an aquarium; beyond it the fish keep schooling.
pub const FEAR_RADIUS_M: f32 = 4.0;

/// Fish notice a shark within this distance from any direction, in metres,
/// through the pressure waves on their lateral line. Default 3 m (chosen): the
/// bow wave of a 2 m shark carries a body length or two beyond it; without it a
/// fleeing fish forgot the shark as soon as it had turned its back (the shark
/// fell into the blind cone) and slowed down.
pub const LATERAL_LINE_M: f32 = 3.0;

/// Share of a frightened neighbour's urgency that a fish takes on when it sees
/// that neighbour flee (dimensionless, 0–1). Default 0.8 (chosen): the "many
/// eyes" of a school, whose fright spreads faster than the predator swims (the
/// Trafalgar effect, Treherne & Foster 1981, Anim. Behav. 29:911), so the
/// whole school turns away together instead of one fish bolting alone. Each
/// hop fades the alarm by this factor; see [`ALARM_THRESHOLD`].
pub const ALARM_SHARE: f32 = 0.8;

/// Farthest heeded neighbour whose fright a fish takes on, metres. Default
/// 1.0 m (chosen): two to three body lengths, the spacing of a school; a
/// neighbour's fast start is plain to see that close. Solitary fish keep
/// farther apart and so mostly meet a shark alone.
pub const ALARM_RANGE_M: f32 = 1.0;

/// Smallest passed-on alarm that frightens a fish (urgency, 0–1). Default
/// 0.25 (chosen): the alarm crosses about six neighbours (0.8⁶ ≈ 0.26) and then
/// dies out, so a school far from the shark keeps schooling.
pub const ALARM_THRESHOLD: f32 = 0.25;

/// Factor on the cohesion weight of a frightened fish (capped at 100).
/// Default 2: prey tighten their school under threat (Magurran & Pitcher 1987,
/// Proc. R. Soc. B 229:439: minnow shoals compact when a pike approaches).
pub const FEAR_COHESION_FACTOR: f32 = 2.0;

/// Factor on the separation weight of a frightened fish. Default 0.5: with
/// doubled cohesion, the school halves its spacing.
pub const FEAR_SEPARATION_FACTOR: f32 = 0.5;

/// Side of the far field's cells as a fraction of the vision distance.
/// Default 0.5 (2.5 m for 5 m vision: 40 cells in the default tank): coarse
/// enough to be cheap for every fish, fine enough that "the cells I see" is
/// close to "the fish I see".
const FAR_FIELD_CELL_SHARE: f32 = 0.5;

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
const FISH_PER_NEIGHBOUR_CELL: f32 = 3.0;

/// Smallest neighbour-grid cell in metres. Default 0.15 m: half the shortest
/// fish; finer cells only add empty ones.
const MIN_NEIGHBOUR_CELL_M: f32 = 0.15;

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
                max_neighbours: forces::TOPOLOGICAL_NEIGHBOURS,
                separation_distance_m: 0.8,
                response_time_s: 0.1,
                clear_sight_m: forces::ALIGNMENT_CLEAR_SIGHT_M,
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
struct Heeded {
    neighbours: Nearest,
    far_centre_m: Option<Vec3>,
}

/// The aquarium and everything in it.
#[derive(Clone, Debug)]
pub struct World {
    config: WorldConfig,
    tank: Tank,
    obstacles: Vec<Obstacle>,
    fish: Vec<Fish>,
    sharks: Vec<Shark>,
    stingrays: Vec<Stingray>,
    params: SteeringParams,
    rng: ChaCha8Rng,
    time_secs: f64,
    steps: u64,
    non_finite_repairs: u64,
    /// `Some`: fish steer with the SIMBA boid layer; `None`: they wander alone.
    boids: Option<BoidParams>,
    catches: u64,
    metrics: WorldMetrics,
    forces: ForceWindow,
    // Scratch, kept between steps so that a step allocates nothing.
    /// The fish's positions at the start of the step, bucketed for the
    /// neighbour search.
    grid: SpatialGrid,
    grid_cell_m: f32,
    /// What every fish perceives this step (all see the same snapshot):
    /// positions and velocities at the start of the step.
    positions_m: Vec<Vec3>,
    velocities_m_per_s: Vec<Vec3>,
    /// Do `grid` and the snapshot hold the last boid step's school (so that
    /// [`World::interaction_neighbours`] can replay it)?
    snapshot_is_last_boid_step: bool,
    /// The fixed obstacles with their bounds (the hard rule's broad phase).
    fixed_solids: ObstacleSet,
    /// The stingrays as the fish avoid them (discs and cluster polygons).
    stingray_avoid: Vec<Obstacle>,
    /// The stingrays as solid discs (the hard rule).
    stingray_solids: ObstacleSet,
    /// Fixed obstacles followed by the stingrays' avoidance shapes.
    avoid_all: ObstacleSet,
    meter: SchoolMeter,
    far_field: forces::FarField,
    /// What each fish heeded in the last boid step: its neighbours and the
    /// centre of the far school it saw (see [`NEIGHBOUR_SEARCH_EVERY_STEPS`]).
    heeded: Vec<Heeded>,
    /// How frightened each fish was in the last boid step (its escape
    /// urgency, 0 = calm), for the alarm that spreads through a school.
    fear: Vec<f32>,
    next_fear: Vec<f32>,
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
    }

    /// Puts into `out` the neighbours fish `i` heeded in the last step: up to
    /// [`Perception::max_neighbours`] neighbours that it saw, nearest first, as
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
        let vision_m = self
            .boids
            .map_or(FEAR_RADIUS_M, |b| b.perception.vision_distance_m);
        self.rebuild_neighbour_grid(vision_m);
        match self.boids {
            Some(boids) => self.step_boid_fish(&boids),
            None => self.step_wandering_fish(),
        }
        self.snapshot_is_last_boid_step = self.boids.is_some();
        self.step_stingrays();
        self.step_sharks();
        self.steps += 1;
        self.time_secs = self.steps as f64 * f64::from(DT_SECS);
        self.measure();
    }

    /// Wandering fish: wander, glass and rock forces, escape.
    fn step_wandering_fish(&mut self) {
        let params = self.params;
        for i in 0..self.fish.len() {
            let before = self.fish[i];
            let fish = &mut self.fish[i];
            let wander = steering::wander(fish, &mut self.rng, &params);
            let (containment, avoidance) =
                glass_and_rock_forces(&before, &self.tank, &self.avoid_all, &params);
            let escape = escape_force(
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
    fn step_boid_fish(&mut self, boids: &BoidParams) {
        let params = SteeringParams {
            max_speed_m_per_s: boids.perception.max_speed_m_per_s,
            max_force_m_per_s2: boids.perception.max_force_m_per_s2,
            ..self.params
        };
        let perception = &boids.perception;
        let max_force = params.max_force_m_per_s2;
        let n = self.fish.len();
        self.fear.resize(n, 0.0);
        self.next_fear.clear();
        self.next_fear.resize(n, 0.0);
        let mut applied_counts = [0u32; 5];
        self.far_field.rebuild(
            self.tank.min_m,
            self.tank.max_m,
            perception.vision_distance_m * FAR_FIELD_CELL_SHARE,
            &self.positions_m,
        );
        // Obstacles can only be in a fish's path within this reach.
        let avoid_reach_m =
            params.avoidance_look_ahead_m + AVOIDANCE_CLEARANCE_M + self.avoid_all.max_radius_m();
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
                Nearest::new(perception.max_neighbours)
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
            let neighbours = forces::forces_from_neighbours(
                &self.positions_m,
                &self.velocities_m_per_s,
                i,
                &heeded.neighbours,
                heeded.far_centre_m,
                perception,
            );
            // Many eyes: the fright of the heeded neighbours (last step's).
            let alarm = heeded
                .neighbours
                .iter()
                .filter(|&(_, d2)| d2 <= ALARM_RANGE_M * ALARM_RANGE_M)
                .map(|(j, _)| self.fear[j])
                .fold(0.0, f32::max)
                * ALARM_SHARE;
            // Containment: stay in the pond, away from its edges (turn back
            // towards open water when the path leaves the comfortable middle).
            let containment = forces::steer_towards(
                velocity_m_per_s
                    + steering::containment(
                        position_m,
                        velocity_m_per_s,
                        &self.tank,
                        params.containment_look_ahead_s,
                        POND_COMFORT_MARGIN_M,
                        params.max_speed_m_per_s,
                    ),
                velocity_m_per_s,
                perception,
            );
            // Avoidance: the glass, sand and surface (wall algorithm), the
            // rocks, pillars, ledges and stingrays (rock algorithm) and fish on
            // a collision course (swaying, clusters as one obstacle).
            let avoidance = steering::limit(
                (steering::avoid_walls(
                    position_m,
                    velocity_m_per_s,
                    &self.tank,
                    BOID_WALL_RANGE_M,
                ) + steering::avoid_obstacles(
                    position_m,
                    velocity_m_per_s,
                    self.avoid_all.near(position_m, avoid_reach_m),
                    params.avoidance_look_ahead_m,
                    AVOIDANCE_CLEARANCE_M,
                    params.max_speed_m_per_s,
                ) + forces::avoid_neighbours(
                    &self.positions_m,
                    &self.velocities_m_per_s,
                    i,
                    &heeded.neighbours,
                    params.max_speed_m_per_s,
                )) / perception.response_time_s.max(1e-3),
                max_force,
            );
            let forces = [
                containment,
                neighbours.alignment_m_per_s2,
                neighbours.cohesion_m_per_s2,
                neighbours.separation_m_per_s2,
                avoidance,
            ];
            let escape = escape_force(position_m, velocity_m_per_s, &self.sharks, &params, alarm);
            self.next_fear[i] = escape.map_or(0.0, |(_, urgency)| urgency);
            let escape = escape.map(|(force, _)| force);
            let mut weights = boids.weights;
            if escape.is_some() {
                weights[2] = (weights[2] * FEAR_COHESION_FACTOR).min(100.0);
                weights[3] *= FEAR_SEPARATION_FACTOR;
            }
            let mut needs = control_mode::needs_from_forces(&forces, max_force);
            // Classic ranks the neighbour urges by how much each is needed
            // (0–1), not by their forces, which saturate inside a school.
            needs[2] = neighbours.cohesion_need;
            needs[3] = neighbours.separation_need;
            let combined = control_mode::combine(
                boids.mode,
                &forces,
                &needs,
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
                    steering::wander(fish, &mut self.rng, &params)
                        / perception.response_time_s.max(1e-3),
                    max_force,
                ) * (boids.wander_weight.min(100.0) / 100.0
                    * control_mode::WANDER_SHARE_AT_FULL_WEIGHT)
            } else {
                Vec3::ZERO
            };
            let steering_m_per_s2 = combined.force_m_per_s2 + wander + escape.unwrap_or(Vec3::ZERO);
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
    fn rebuild_neighbour_grid(&mut self, vision_m: f32) {
        let n = self.positions_m.len().max(1) as f32;
        let volume_m3 = self.tank.size_m().element_product().max(1e-3);
        let uniform_cell_m = (volume_m3 * FISH_PER_NEIGHBOUR_CELL / n).cbrt();
        let crowding = self.grid.crowding();
        let cell_m = if self.grid_cell_m > 0.0 && crowding > 0.0 {
            self.grid_cell_m * (FISH_PER_NEIGHBOUR_CELL / crowding).cbrt()
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

    /// The stingrays' discs (hard rule) and avoidance shapes, and the list of
    /// everything the fish avoid.
    fn rebuild_stingray_obstacles(&mut self) {
        let floor_y_m = self.tank.min_m.y;
        let discs: Vec<Obstacle> = self
            .stingrays
            .iter()
            .map(|s| s.obstacle(floor_y_m))
            .collect();
        self.stingray_solids.rebuild(&discs);
        self.stingray_avoid.clear();
        stingray::cluster_obstacles(&self.stingrays, floor_y_m, &mut self.stingray_avoid);
        self.avoid_all
            .rebuild(self.obstacles.iter().chain(&self.stingray_avoid));
    }

    /// Stingrays glide: level wander, the glass, the fixed obstacles, and a
    /// spring that holds their glide height; they never come closer than
    /// [`stingray::STINGRAY_GAP_M`] to the glass or an obstacle (if a step would
    /// bring one closer, it turns round instead).
    fn step_stingrays(&mut self) {
        let params = stingray::stingray_params(&self.params);
        let floor_y_m = self.tank.min_m.y;
        for ray in &mut self.stingrays {
            let before = *ray;
            let body = &mut ray.body;
            let wander = steering::wander(body, &mut self.rng, &params);
            let reach_m = stingray::STINGRAY_RADIUS_M + stingray::STINGRAY_GAP_M;
            let walls = steering::glass_walls(
                body.position_m,
                body.velocity_m_per_s,
                &self.tank,
                reach_m + 1.0,
                params.max_force_m_per_s2,
            );
            let avoidance = steering::avoid_obstacles(
                body.position_m,
                body.velocity_m_per_s,
                &self.obstacles,
                1.5,
                reach_m,
                params.max_speed_m_per_s,
            );
            // Height spring: desired climb rate = height error per second.
            let height_error_m = floor_y_m + ray.glide_height_m - body.position_m.y;
            let hold = Vec3::Y * (height_error_m - body.velocity_m_per_s.y) * 2.0;
            let steering_m_per_s2 = (wander + walls * 2.0 + avoidance + hold) * Vec3::ONE;
            body.integrate(steering_m_per_s2, &params, DT_SECS);
            let legal = body.position_m.is_finite()
                && body.velocity_m_per_s.is_finite()
                && stingray_fits(body.position_m, &self.tank, &self.obstacles);
            if !legal {
                *ray = before;
                ray.body.velocity_m_per_s = -ray.body.velocity_m_per_s.normalize_or(Vec3::X)
                    * params.min_speed_m_per_s.max(0.05);
            }
            let p = &mut ray.body.position_m;
            p.y =
                p.y.max(floor_y_m + stingray::GLIDE_HEIGHT_M.0)
                    .min(floor_y_m + stingray::GLIDE_HEIGHT_M.1);
            ray.body.advance_tail_phase(DT_SECS);
        }
    }

    /// Sharks hunt (see [`shark`]): keep or lose the lock (confusion effect),
    /// pick the nearest fish they see, pursue it, and catch it at the mouth.
    fn step_sharks(&mut self) {
        let shark_perception = Perception {
            vision_distance_m: shark::SHARK_VISION_M,
            vision_angle_rad: shark::SHARK_VISION_ANGLE_RAD,
            max_speed_m_per_s: shark::SHARK_ATTACK_M_PER_S,
            max_force_m_per_s2: shark::SHARK_MAX_FORCE_M_PER_S2,
            max_neighbours: 1,
            separation_distance_m: 0.0,
            response_time_s: 1.0,
            clear_sight_m: 0.0,
        };
        for s in 0..self.sharks.len() {
            let mut shark = self.sharks[s];
            let params = shark::shark_params(&self.params, shark.body.body_length_m);
            shark.satiated_secs = (shark.satiated_secs - DT_SECS).max(0.0);
            shark.refocus_secs = (shark.refocus_secs - DT_SECS).max(0.0);
            if !shark.is_hungry() {
                shark.target = None;
            }
            // Keep the lock, or lose it to confusion or distance.
            if let Some(t) = shark.target {
                let lost = match self.fish.get(t) {
                    None => true,
                    Some(prey) => {
                        // A strike that has not caught the fish by now has failed.
                        let failed = shark.lock_secs > shark::STRIKE_LOCK_S + shark::LUNGE_MAX_S;
                        let far = failed
                            || prey.position_m.distance(shark.body.position_m)
                                > shark::SHARK_VISION_M * 1.5;
                        let confusing = self.count_near(prey.position_m, t);
                        let p_lose = shark::lose_lock_probability(confusing, DT_SECS);
                        far || self.rng.random::<f32>() < p_lose
                    }
                };
                if lost {
                    shark.target = None;
                    shark.refocus_secs = shark::REFOCUS_S;
                } else {
                    shark.lock_secs += DT_SECS;
                }
            }
            // Pick the nearest fish in view.
            if shark.target.is_none() && shark.is_hungry() && shark.refocus_secs <= 0.0 {
                let mut nearest = Nearest::new(1);
                let (p, heading) = (shark.body.position_m, shark.body.heading());
                self.grid
                    .k_nearest(p, shark::SHARK_VISION_M, &mut nearest, |_, q, _| {
                        forces::sees(p, heading, q, &shark_perception)
                    });
                shark.target = nearest.iter().next().map(|(j, _)| j);
                shark.lock_secs = 0.0;
            }
            let before = shark.body;
            // The final lunge: locked on long enough and close, the shark
            // bursts (see shark::lunge_params).
            let lunging = shark
                .target
                .and_then(|t| self.fish.get(t))
                .is_some_and(|prey| {
                    shark.lock_secs >= shark::STRIKE_LOCK_S
                        && prey.position_m.distance(before.position_m) < shark::LUNGE_DISTANCE_M
                });
            let params = if lunging {
                shark::lunge_params(&params)
            } else {
                params
            };
            let chase = match shark.target.and_then(|t| self.fish.get(t)) {
                Some(prey) => steering::pursue(
                    before.position_m,
                    before.velocity_m_per_s,
                    prey.position_m,
                    prey.velocity_m_per_s,
                    params.max_speed_m_per_s,
                    params.max_force_m_per_s2,
                ),
                None => steering::wander(&mut shark.body, &mut self.rng, &params),
            };
            let containment = steering::contain_in_tank(
                before.position_m,
                before.velocity_m_per_s,
                &self.tank,
                2.5,
                &params,
                params.max_force_m_per_s2,
            );
            let avoidance = steering::avoid_obstacles(
                before.position_m,
                before.velocity_m_per_s,
                self.avoid_all.as_slice(),
                3.0,
                0.5,
                params.max_speed_m_per_s,
            );
            let steering_m_per_s2 = chase + containment * 2.0 + avoidance;
            shark.body.integrate(steering_m_per_s2, &params, DT_SECS);
            if !(shark.body.position_m.is_finite() && shark.body.velocity_m_per_s.is_finite()) {
                shark.body.position_m = before.position_m;
                shark.body.velocity_m_per_s = before.heading() * params.min_speed_m_per_s;
                self.non_finite_repairs += 1;
            }
            push_shark_clear(&mut shark.body, &self.tank, &self.fixed_solids);
            shark.body.advance_tail_phase(DT_SECS);
            // The bite.
            if let Some(t) = shark.target
                && shark.lock_secs >= shark::STRIKE_LOCK_S
                && let Some(prey) = self.fish.get(t)
                && prey.position_m.distance(shark.mouth_m()) < shark::CATCH_DISTANCE_M
            {
                shark.catches += 1;
                self.catches += 1;
                shark.target = None;
                shark.satiated_secs = shark::SATIATED_S;
                self.sharks[s] = shark;
                let replacement = self.spawn_fish_far_from_sharks();
                self.fish[t] = replacement;
                continue;
            }
            self.sharks[s] = shark;
        }
    }

    /// Fish (other than `except`) within [`shark::CONFUSION_RADIUS_M`] of `p`,
    /// counted up to [`shark::MAX_CONFUSING_NEIGHBOURS`] (snapshot positions).
    fn count_near(&self, p: Vec3, except: usize) -> u32 {
        let mut nearest = Nearest::new(shark::MAX_CONFUSING_NEIGHBOURS as usize);
        self.grid
            .k_nearest(p, shark::CONFUSION_RADIUS_M, &mut nearest, |j, _, _| {
                j != except
            });
        nearest.len() as u32
    }

    /// Measures the school and stores it with the force frequencies and
    /// catches: polarization, milling and mean speed after every step; the
    /// nearest-neighbour distance and the groups every
    /// [`SPATIAL_METRICS_EVERY_STEPS`] steps (and at the start), kept in
    /// between.
    fn measure(&mut self) {
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

    /// Keep the first `fish_count` fish (at most [`MAX_FISH_COUNT`]), or add
    /// new ones drawn from the world's random generator. Existing fish are
    /// never changed. Sharks hunting a removed fish lose it.
    pub fn set_fish_count(&mut self, fish_count: usize) {
        let fish_count = fish_count.min(MAX_FISH_COUNT);
        self.fish.truncate(fish_count);
        self.rebuild_stingray_obstacles();
        while self.fish.len() < fish_count {
            let fish = spawn_fish(&self.tank, &self.solids(), &self.params, &mut self.rng);
            self.fish.push(fish);
        }
        for shark in &mut self.sharks {
            if shark.target.is_some_and(|t| t >= fish_count) {
                shark.target = None;
            }
        }
        self.config.fish_count = fish_count;
        self.snapshot_is_last_boid_step = false;
    }

    /// Keep the first `sharks` sharks and `stingrays` stingrays, or add new ones
    /// at free places from the world's random generator (at most
    /// [`MAX_SHARKS`] = 10 and [`MAX_STINGRAYS`] = 20). Fish under a new
    /// stingray are pushed out at once.
    pub fn set_species_counts(&mut self, sharks: usize, stingrays: usize) {
        let (sharks, stingrays) = (sharks.min(MAX_SHARKS), stingrays.min(MAX_STINGRAYS));
        self.stingrays.truncate(stingrays);
        while self.stingrays.len() < stingrays {
            let ray = spawn_stingray(&self.tank, &self.obstacles, &mut self.rng);
            self.stingrays.push(ray);
        }
        self.sharks.truncate(sharks);
        while self.sharks.len() < sharks {
            let shark = spawn_shark(&self.tank, &self.fixed_solids, &mut self.rng);
            self.sharks.push(shark);
        }
        self.config.sharks = sharks;
        self.config.stingrays = stingrays;
        self.settle();
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

    /// Add an obstacle after checking it ([`Obstacle::validate`], and at least
    /// 0.3 m from every other obstacle); returns its index. Fish inside it are
    /// pushed out at once; stingrays too close to it move to a free place.
    pub fn add_obstacle(&mut self, obstacle: Obstacle) -> Result<usize, ObstacleEditError> {
        obstacle.validate(&self.tank)?;
        check_gap(&obstacle, &self.obstacles, None)?;
        self.obstacles.push(obstacle);
        self.obstacles_changed();
        Ok(self.obstacles.len() - 1)
    }

    /// Move obstacle `index` so that its footprint centre is at `new_floor_xz`
    /// ((x, z) in metres), keeping its shape and height. Errors if there is no
    /// such obstacle or the new place is not allowed (then nothing changes).
    pub fn move_obstacle(
        &mut self,
        index: usize,
        new_floor_xz: Vec2,
    ) -> Result<(), ObstacleEditError> {
        let Some(old) = self.obstacles.get(index) else {
            return Err(ObstacleEditError::NoSuchObstacle {
                index,
                count: self.obstacles.len(),
            });
        };
        if !new_floor_xz.is_finite() {
            return Err(ObstacleEditError::PlaceNotANumber);
        }
        let moved = old.moved_to(new_floor_xz);
        moved.validate(&self.tank)?;
        check_gap(&moved, &self.obstacles, Some(index))?;
        self.obstacles[index] = moved;
        self.obstacles_changed();
        Ok(())
    }

    /// Remove obstacle `index`; `false` if there is none.
    pub fn remove_obstacle(&mut self, index: usize) -> bool {
        if index >= self.obstacles.len() {
            return false;
        }
        self.obstacles.remove(index);
        self.obstacles_changed();
        true
    }

    /// Replace all obstacles (e.g. a teacher's saved layout). Obstacles that
    /// fail [`Obstacle::validate`] are left out (and logged); overlapping ones
    /// are kept in order as long as they keep the 0.3 m gap to those before
    /// them. Everything inside the new obstacles is pushed out at once.
    pub fn set_obstacles(&mut self, obstacles: Vec<Obstacle>) {
        self.obstacles = valid_obstacles(obstacles, &self.tank);
        self.obstacles_changed();
    }

    fn obstacles_changed(&mut self) {
        self.config.obstacles = Some(self.obstacles.clone());
        self.fixed_solids.rebuild(&self.obstacles);
        for i in 0..self.stingrays.len() {
            if !stingray_fits(
                self.stingrays[i].body.position_m,
                &self.tank,
                &self.obstacles,
            ) {
                self.stingrays[i] = spawn_stingray(&self.tank, &self.obstacles, &mut self.rng);
            }
        }
        self.settle();
    }

    /// After a change of obstacles or stingrays: push every fish and shark out
    /// of everything at once, so no animal is ever inside an obstacle.
    fn settle(&mut self) {
        self.rebuild_stingray_obstacles();
        for fish in &mut self.fish {
            enforce_hard_constraints(fish, &self.tank, &self.fixed_solids, &self.stingray_solids);
        }
        for shark in &mut self.sharks {
            push_shark_clear(&mut shark.body, &self.tank, &self.fixed_solids);
        }
    }

    /// Fixed obstacles and stingray discs: what a new fish must not start in.
    fn solids(&self) -> Vec<Obstacle> {
        let mut solids = self.obstacles.clone();
        solids.extend(self.stingray_solids.as_slice().iter().cloned());
        solids
    }

    /// A new fish at a free place at least [`shark::RESPAWN_DISTANCE_M`] from
    /// every shark (or the farthest of the places tried).
    fn spawn_fish_far_from_sharks(&mut self) -> Fish {
        let solids = self.solids();
        let mut best: Option<(f32, Fish)> = None;
        for _ in 0..PLACEMENT_ATTEMPTS {
            let fish = spawn_fish(&self.tank, &solids, &self.params, &mut self.rng);
            let distance_m = self
                .sharks
                .iter()
                .map(|s| s.body.position_m.distance(fish.position_m))
                .fold(f32::INFINITY, f32::min);
            if distance_m >= shark::RESPAWN_DISTANCE_M {
                return fish;
            }
            if best.is_none_or(|(d, _)| distance_m > d) {
                best = Some((distance_m, fish));
            }
        }
        match best {
            Some((_, fish)) => fish,
            None => spawn_fish(&self.tank, &solids, &self.params, &mut self.rng),
        }
    }
}

/// Obstacles from a user's list that pass [`Obstacle::validate`] and keep the
/// gap to the ones before them; the others are logged and left out.
fn valid_obstacles(obstacles: Vec<Obstacle>, tank: &Tank) -> Vec<Obstacle> {
    let mut kept: Vec<Obstacle> = Vec::with_capacity(obstacles.len());
    for (i, obstacle) in obstacles.into_iter().enumerate() {
        match obstacle
            .validate(tank)
            .map_err(ObstacleEditError::from)
            .and_then(|()| check_gap(&obstacle, &kept, None))
        {
            Ok(()) => kept.push(obstacle),
            Err(reason) => log::warn!("obstacle {i} left out: {reason}"),
        }
    }
    kept
}

/// Why a teacher's obstacle edit was refused (nothing changed).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ObstacleEditError {
    #[error(transparent)]
    Invalid(#[from] ObstacleError),
    #[error("there is no obstacle number {index} (there are {count})")]
    NoSuchObstacle { index: usize, count: usize },
    #[error("the new place must be a pair of numbers")]
    PlaceNotANumber,
    #[error(
        "it is too close to obstacle {0}: keep at least {EDITED_OBSTACLE_GAP_M} m between them"
    )]
    TooClose(usize),
}

/// Is `obstacle` at least [`EDITED_OBSTACLE_GAP_M`] from each of `others`
/// (except number `skip`)? Judged on the floor footprints: each footprint's
/// bounding circle against the other's shape.
fn check_gap(
    obstacle: &Obstacle,
    others: &[Obstacle],
    skip: Option<usize>,
) -> Result<(), ObstacleEditError> {
    for (j, other) in others.iter().enumerate() {
        if Some(j) == skip {
            continue;
        }
        let gap_m = footprint_gap_m(obstacle, other).min(footprint_gap_m(other, obstacle));
        if gap_m < EDITED_OBSTACLE_GAP_M {
            return Err(ObstacleEditError::TooClose(j));
        }
    }
    Ok(())
}

/// A lower bound of the horizontal gap between `a`'s footprint and `b`: `b`'s
/// signed distance, at the sand, from `a`'s footprint centre, minus `a`'s
/// bounding radius.
fn footprint_gap_m(a: &Obstacle, b: &Obstacle) -> f32 {
    let c = a.footprint_center_m();
    let (base_y_m, _) = b.vertical_extent_m();
    let probe_m = Vec3::new(c.x, base_y_m.max(0.0) + 0.01, c.y);
    b.signed_distance_m(probe_m) - a.radius_m()
}

/// The escape force of a fish and how urgent it is (0–1), or `None` when the
/// fish is calm. A fish that notices a shark (within [`FEAR_RADIUS_M`] inside
/// its 300° field of view, or within [`LATERAL_LINE_M`] from any direction)
/// [`steering::evade`]s the nearest one it notices, at full urgency within
/// [`LATERAL_LINE_M`] fading to a quarter at [`FEAR_RADIUS_M`] (a distant
/// shark makes the school veer away together rather than scatter). A fish that
/// notices none but is alarmed by frightened neighbours (`alarm`, their
/// urgency × [`ALARM_SHARE`], see [`ALARM_THRESHOLD`]) evades the nearest shark
/// with that urgency. The force is the maximum force × urgency.
fn escape_force(
    position_m: Vec3,
    velocity_m_per_s: Vec3,
    sharks: &[Shark],
    params: &SteeringParams,
    alarm: f32,
) -> Option<(Vec3, f32)> {
    let heading = heading_of(velocity_m_per_s);
    let cos_half_view = (150f32.to_radians()).cos();
    let mut noticed: Option<(f32, &Shark)> = None;
    let mut nearest: Option<(f32, &Shark)> = None;
    for shark in sharks {
        let offset_m = shark.body.position_m - position_m;
        let distance_m = offset_m.length();
        let in_view = heading.dot(offset_m) >= cos_half_view * distance_m;
        let seen = distance_m < LATERAL_LINE_M || (distance_m < FEAR_RADIUS_M && in_view);
        if seen && noticed.is_none_or(|(d, _)| distance_m < d) {
            noticed = Some((distance_m, shark));
        }
        if nearest.is_none_or(|(d, _)| distance_m < d) {
            nearest = Some((distance_m, shark));
        }
    }
    let (urgency, shark) = match (noticed, nearest) {
        (Some((distance_m, shark)), _) => {
            let urgency = if distance_m <= LATERAL_LINE_M {
                1.0
            } else {
                1.0 - 0.75 * (distance_m - LATERAL_LINE_M) / (FEAR_RADIUS_M - LATERAL_LINE_M)
            };
            (urgency.max(alarm.min(1.0)), shark)
        }
        (None, Some((_, shark))) if alarm >= ALARM_THRESHOLD => (alarm.min(1.0), shark),
        _ => return None,
    };
    let evade = steering::evade(
        position_m,
        velocity_m_per_s,
        shark.body.position_m,
        shark.body.velocity_m_per_s,
        params.max_speed_m_per_s,
        f32::INFINITY,
    );
    Some((
        evade.normalize_or_zero() * params.max_force_m_per_s2.clamp(0.0, 1e6) * urgency,
        urgency,
    ))
}

/// Containment (stay off the glass, floor and surface) and obstacle avoidance for
/// `fish` on the wander path.
fn glass_and_rock_forces(
    fish: &Fish,
    tank: &Tank,
    obstacles: &ObstacleSet,
    params: &SteeringParams,
) -> (Vec3, Vec3) {
    let reach_m = params.avoidance_look_ahead_m + AVOIDANCE_CLEARANCE_M + obstacles.max_radius_m();
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
        AVOIDANCE_CLEARANCE_M,
        params.max_speed_m_per_s,
    );
    (containment, avoidance)
}

/// Moves one fish by one step under `steering_m_per_s2`: integrate, repair any
/// non-finite value (back to `before`, at minimum speed), enforce the hard rules
/// and beat the tail. Returns how many repairs were needed (0, 1 or 2).
#[allow(clippy::too_many_arguments)]
fn move_fish(
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
/// tank clamp. Stingrays keep [`stingray::STINGRAY_GAP_M`] from the glass and
/// from every obstacle, so pushing a fish out of a stingray cannot push it into
/// either; where stingrays overlap, a fish still inside after two rounds is
/// lifted over them.
fn enforce_hard_constraints(
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

/// [`push_clear`] for a shark: out of the glass and the rocks by
/// [`SHARK_MARGIN_M`]; stingrays are not in a shark's way.
fn push_shark_clear(body: &mut Fish, tank: &Tank, obstacles: &ObstacleSet) {
    push_clear(
        body,
        tank,
        obstacles,
        &ObstacleSet::EMPTY,
        SHARK_MARGIN_M,
        SHARK_MARGIN_M,
    );
}

/// The hard rules for any animal, with its margins from the glass and from
/// obstacles (see [`enforce_hard_constraints`]).
fn push_clear(
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

/// May a stingray's centre be at `p_m`? Its wing tips keep
/// [`stingray::STINGRAY_GAP_M`] from the glass and from every obstacle
/// (measured at the sand, where a half-buried rock is widest).
fn stingray_fits(p_m: Vec3, tank: &Tank, obstacles: &[Obstacle]) -> bool {
    let reach_m = stingray::STINGRAY_RADIUS_M + stingray::STINGRAY_GAP_M;
    let (lo, hi) = (tank.min_m, tank.max_m);
    let inside = p_m.x >= lo.x + reach_m
        && p_m.x <= hi.x - reach_m
        && p_m.z >= lo.z + reach_m
        && p_m.z <= hi.z - reach_m;
    let at_sand_m = Vec3::new(p_m.x, lo.y + 0.01, p_m.z);
    inside
        && obstacles
            .iter()
            .all(|o| o.signed_distance_m(at_sand_m) >= reach_m)
}

/// A uniform random number between `lo` and `hi` (never panics).
fn uniform(rng: &mut ChaCha8Rng, lo: f32, hi: f32) -> f32 {
    lo + (hi - lo) * rng.random::<f32>()
}

/// Where an obstacle meets the floor: centre (x, z) and bounding radius in metres.
fn footprint(obstacle: &Obstacle) -> (Vec2, f32) {
    (obstacle.footprint_center_m(), obstacle.radius_m())
}

/// 4–6 rocks (radius 0.4–1.0 m, centre at or up to 0.3 radii below the sand,
/// i.e. about half-buried), 2–3 pillars (radius 0.25–0.5 m, height 1.5–3.5 m)
/// and, on half of the seeds, one reef ledge (a convex polygon of 5–7 corners,
/// 1.0–1.6 m across its bounding circle and stretched to a ledge, 0.4–0.9 m
/// high) at random places that keep [`WALL_CLEARANCE_M`] from the glass and
/// [`OBSTACLE_GAP_M`] from each other. An obstacle that finds no place in
/// [`PLACEMENT_ATTEMPTS`] tries is left out.
fn place_obstacles(tank: &Tank, rng: &mut ChaCha8Rng) -> Vec<Obstacle> {
    let rock_count = rng.random_range(4..=6);
    let pillar_count = rng.random_range(2..=3);
    let ledge_count = usize::from(rng.random::<bool>());
    let mut obstacles: Vec<Obstacle> = Vec::new();
    // The ledge first: it is the largest and hardest to fit.
    let kinds = std::iter::repeat_n(2, ledge_count)
        .chain(std::iter::repeat_n(0, rock_count))
        .chain(std::iter::repeat_n(1, pillar_count));
    for kind in kinds {
        for _ in 0..PLACEMENT_ATTEMPTS {
            let radius_m = match kind {
                0 => uniform(rng, 0.4, 1.0),
                1 => uniform(rng, 0.25, 0.5),
                _ => uniform(rng, 1.0, 1.6),
            };
            let edge_m = WALL_CLEARANCE_M + radius_m;
            let x_m = uniform(rng, tank.min_m.x + edge_m, tank.max_m.x - edge_m);
            let z_m = uniform(rng, tank.min_m.z + edge_m, tank.max_m.z - edge_m);
            let candidate = match kind {
                0 => {
                    let buried_m = uniform(rng, 0.0, 0.3) * radius_m;
                    Obstacle::Rock {
                        center_m: Vec3::new(x_m, tank.min_m.y - buried_m, z_m),
                        radius_m,
                    }
                }
                1 => Obstacle::Cylinder {
                    base_center_m: Vec3::new(x_m, tank.min_m.y, z_m),
                    radius_m,
                    height_m: uniform(rng, 1.5, 3.5),
                },
                _ => reef_ledge(Vec2::new(x_m, z_m), radius_m, tank.min_m.y, rng),
            };
            let (center, bound_m) = footprint(&candidate);
            let fits = obstacles.iter().all(|other| {
                let (other_center, other_radius_m) = footprint(other);
                other_center.distance(center) >= bound_m + other_radius_m + OBSTACLE_GAP_M
            }) && candidate.validate(tank).is_ok();
            if fits {
                obstacles.push(candidate);
                break;
            }
        }
    }
    obstacles
}

/// A reef ledge: 5–7 corners on an ellipse (semi-axes `radius_m` and 0.4–0.7 of
/// it, turned at random) around `center_m`, 0.4–0.9 m high. Corners on an
/// ellipse always make a convex polygon.
fn reef_ledge(center_m: Vec2, radius_m: f32, floor_y_m: f32, rng: &mut ChaCha8Rng) -> Obstacle {
    let corners = rng.random_range(5..=7);
    let minor = uniform(rng, 0.4, 0.7);
    let turn_rad = uniform(rng, 0.0, TAU);
    let (sin_t, cos_t) = turn_rad.sin_cos();
    let footprint_m = (0..corners)
        .map(|k| {
            let a = k as f32 * TAU / corners as f32;
            let local = Vec2::new(a.cos() * radius_m, a.sin() * radius_m * minor);
            center_m
                + Vec2::new(
                    local.x * cos_t - local.y * sin_t,
                    local.x * sin_t + local.y * cos_t,
                )
        })
        .collect();
    Obstacle::Polygon {
        footprint_m,
        base_y_m: floor_y_m,
        height_m: uniform(rng, 0.4, 0.9),
    }
}

/// A new fish at a random free place (at least [`SPAWN_CLEARANCE_M`] from
/// glass and obstacles), swimming in a random, nearly level direction at a
/// relaxed speed, 0.3–0.5 m long, with a random colour and tail phase.
fn spawn_fish(
    tank: &Tank,
    obstacles: &[Obstacle],
    params: &SteeringParams,
    rng: &mut ChaCha8Rng,
) -> Fish {
    let is_free = |p: Vec3| {
        tank.contains(p, SPAWN_CLEARANCE_M)
            && obstacles
                .iter()
                .all(|o| o.signed_distance_m(p) >= SPAWN_CLEARANCE_M)
    };
    let mut position_m = random_point(tank, rng);
    for _ in 0..PLACEMENT_ATTEMPTS {
        if is_free(position_m) {
            break;
        }
        position_m = random_point(tank, rng);
    }
    // Practically never needed: make a crowded last try legal anyway.
    if !is_free(position_m) {
        position_m = tank.clamp_inside(position_m, SPAWN_CLEARANCE_M);
        for obstacle in obstacles {
            position_m = obstacle.push_outside(position_m, SPAWN_CLEARANCE_M);
        }
    }

    let yaw_rad = uniform(rng, 0.0, TAU);
    let pitch_rad = uniform(rng, -0.2, 0.2);
    let direction = Vec3::new(
        yaw_rad.cos() * pitch_rad.cos(),
        pitch_rad.sin(),
        yaw_rad.sin() * pitch_rad.cos(),
    );
    let body_length_m = uniform(rng, 0.3, 0.5);
    let cruise_m_per_s = params.cruise_speed_body_lengths_per_s * body_length_m;
    let speed_m_per_s = uniform(rng, 0.5, 1.0) * cruise_m_per_s;
    let hue = rng.random::<f32>();
    let mut fish = Fish::new(position_m, direction * speed_m_per_s, body_length_m, hue);
    fish.wander_angle_rad = uniform(rng, -1.0, 1.0);
    fish.tail_phase_rad = uniform(rng, 0.0, TAU);
    fish
}

/// A uniformly random point in the tank.
fn random_point(tank: &Tank, rng: &mut ChaCha8Rng) -> Vec3 {
    let u = Vec3::new(rng.random(), rng.random(), rng.random());
    tank.min_m + u * tank.size_m()
}

/// A new shark, 1.5–2 m long, at a random place at least 1 m from the glass,
/// the floor, the surface and every obstacle, cruising level in a random
/// direction.
fn spawn_shark(tank: &Tank, obstacles: &ObstacleSet, rng: &mut ChaCha8Rng) -> Shark {
    const CLEARANCE_M: f32 = 1.0;
    let mut position_m = tank.center_m();
    for _ in 0..PLACEMENT_ATTEMPTS {
        let p = random_point(tank, rng);
        if tank.contains(p, CLEARANCE_M)
            && obstacles
                .as_slice()
                .iter()
                .all(|o| o.signed_distance_m(p) >= CLEARANCE_M)
        {
            position_m = p;
            break;
        }
    }
    let length_m = uniform(rng, shark::SHARK_LENGTH_M.0, shark::SHARK_LENGTH_M.1);
    let mut new = shark::new_shark(position_m, uniform(rng, 0.0, TAU), length_m);
    push_clear(
        &mut new.body,
        tank,
        obstacles,
        &ObstacleSet::EMPTY,
        SHARK_MARGIN_M,
        SHARK_MARGIN_M,
    );
    new
}

/// A new stingray at a random place where it fits ([`stingray_fits`]), at a
/// random glide height, heading in a random direction. If no place is found
/// (a tank crammed with obstacles) it starts in the middle of the tank.
fn spawn_stingray(tank: &Tank, obstacles: &[Obstacle], rng: &mut ChaCha8Rng) -> Stingray {
    let floor_y_m = tank.min_m.y;
    let mut position_m = Vec3::new(
        tank.center_m().x,
        floor_y_m + stingray::GLIDE_HEIGHT_M.0,
        tank.center_m().z,
    );
    for _ in 0..PLACEMENT_ATTEMPTS {
        let p = random_point(tank, rng);
        let height_m = uniform(rng, stingray::GLIDE_HEIGHT_M.0, stingray::GLIDE_HEIGHT_M.1);
        let p = Vec3::new(p.x, floor_y_m + height_m, p.z);
        if stingray_fits(p, tank, obstacles) {
            position_m = p;
            break;
        }
    }
    stingray::new_stingray(position_m, uniform(rng, 0.0, TAU), floor_y_m)
}

#[cfg(test)]
mod tests {
    use crate::sim::boids::world::*;

    fn world(seed: u64, fish_count: usize) -> World {
        World::new(WorldConfig {
            seed,
            fish_count,
            ..WorldConfig::default()
        })
    }

    fn positions(world: &World) -> Vec<[u32; 3]> {
        let bits = |v: Vec3| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()];
        world.fish().iter().map(|f| bits(f.position_m)).collect()
    }

    /// Every fish is finite, in the tank and outside every obstacle.
    fn assert_all_fish_legal(world: &World) {
        for (i, fish) in world.fish().iter().enumerate() {
            let (p, v) = (fish.position_m, fish.velocity_m_per_s);
            assert!(
                p.is_finite() && v.is_finite(),
                "fish {i} not finite at step {}",
                world.steps()
            );
            assert!(world.tank().contains(p, 0.0), "fish {i} left the tank: {p}");
            for obstacle in world.obstacles() {
                let gap_m = obstacle.signed_distance_m(p);
                assert!(gap_m >= 0.0, "fish {i} inside {obstacle:?} at {p}");
            }
            for ray in world.stingrays() {
                let gap_m = ray.obstacle(world.tank().min_m.y).signed_distance_m(p);
                assert!(gap_m >= 0.0, "fish {i} inside a stingray at {p}");
            }
        }
        for shark in world.sharks() {
            let p = shark.body.position_m;
            assert!(p.is_finite() && shark.body.velocity_m_per_s.is_finite());
            assert!(world.tank().contains(p, 0.0), "shark left the tank: {p}");
            for obstacle in world.obstacles() {
                assert!(
                    obstacle.signed_distance_m(p) >= 0.0,
                    "shark in {obstacle:?}"
                );
            }
        }
        for ray in world.stingrays() {
            let p = ray.body.position_m;
            assert!(p.is_finite() && world.tank().contains(p, 0.0));
            let height_m = p.y - world.tank().min_m.y;
            assert!(
                (0.2 - 1e-4..=0.6 + 1e-4).contains(&height_m),
                "ray at {height_m} m"
            );
        }
    }

    #[test]
    fn default_scene_has_4_to_6_rocks_2_to_3_pillars_and_0_to_1_ledge_that_do_not_overlap() {
        let mut ledges_seen = 0;
        for seed in 0..20 {
            let w = world(seed, 0);
            let count = |f: fn(&Obstacle) -> bool| w.obstacles().iter().filter(|o| f(o)).count();
            let rocks = count(|o| matches!(o, Obstacle::Rock { .. }));
            let pillars = count(|o| matches!(o, Obstacle::Cylinder { .. }));
            let ledges = count(|o| matches!(o, Obstacle::Polygon { .. }));
            assert!((4..=6).contains(&rocks), "seed {seed}");
            assert!((2..=3).contains(&pillars), "seed {seed}");
            assert!(ledges <= 1, "seed {seed}");
            ledges_seen += ledges;
            for o in w.obstacles() {
                assert_eq!(o.validate(w.tank()), Ok(()), "seed {seed}");
            }
            for (i, a) in w.obstacles().iter().enumerate() {
                let (ca, ra) = footprint(a);
                // Far enough from the glass (checked at mid-height).
                let middle_m = Vec3::new(ca.x, w.tank().center_m().y, ca.y);
                assert!(w.tank().contains(middle_m, ra + WALL_CLEARANCE_M - 1e-4));
                for b in &w.obstacles()[i + 1..] {
                    let (cb, rb) = footprint(b);
                    assert!(ca.distance(cb) >= ra + rb + OBSTACLE_GAP_M);
                }
            }
        }
        assert!(ledges_seen > 0, "no seed placed a reef ledge");
    }

    #[test]
    fn same_seed_gives_bit_identical_fish_and_another_seed_does_not() {
        let mut a = world(42, 50);
        let mut b = world(42, 50);
        let mut c = world(43, 50);
        for _ in 0..1_000 {
            a.step();
            b.step();
            c.step();
        }
        assert_eq!(positions(&a), positions(&b));
        assert_ne!(positions(&a), positions(&c));
        assert_ne!(a.obstacles(), c.obstacles());
    }

    #[test]
    fn two_hundred_fish_stay_finite_in_the_tank_and_out_of_rocks_for_twenty_minutes() {
        // 20 simulated minutes in release; 5 in debug builds to keep
        // `cargo test` quick (the rules are checked at every step either way).
        let minutes = if cfg!(debug_assertions) { 5 } else { 20 };
        let mut w = world(1, 200);
        assert_all_fish_legal(&w);
        for _ in 0..minutes * 60 * 60 {
            w.step();
            assert_all_fish_legal(&w);
        }
        assert_eq!(w.non_finite_repairs(), 0);
        assert!((w.time_secs() - 60.0 * minutes as f64).abs() < 1e-3);
    }

    #[test]
    fn steering_alone_keeps_fish_clear_of_glass_and_rocks() {
        // The hard rules are a safety net: in a normal run the soft steering
        // keeps every fish well away from glass and rock on its own.
        let mut w = world(2, 200);
        for _ in 0..3_600 {
            w.step();
            for fish in w.fish() {
                let p = fish.position_m;
                assert!(
                    w.tank().contains(p, 2.0 * TANK_MARGIN_M),
                    "at the glass: {p}"
                );
                for obstacle in w.obstacles() {
                    assert!(
                        obstacle.signed_distance_m(p) > 2.0 * OBSTACLE_MARGIN_M,
                        "at a rock: {p}"
                    );
                }
            }
        }
    }

    #[test]
    fn fish_swim_several_body_lengths_in_ten_seconds() {
        let mut w = world(3, 200);
        let start: Vec<Vec3> = w.fish().iter().map(|f| f.position_m).collect();
        for _ in 0..600 {
            w.step();
        }
        let n = w.fish().len() as f32;
        let mean_displacement_m: f32 = w
            .fish()
            .iter()
            .zip(&start)
            .map(|(f, p)| f.position_m.distance(*p))
            .sum::<f32>()
            / n;
        let mean_body_length_m: f32 = w.fish().iter().map(|f| f.body_length_m).sum::<f32>() / n;
        assert!(
            mean_displacement_m > 5.0 * mean_body_length_m,
            "mean displacement {mean_displacement_m} m"
        );
    }

    #[test]
    fn fish_released_at_one_end_spread_through_the_tank_within_a_minute() {
        // Twenty fish let go together near the left glass, low in the water.
        let mut w = world(5, 20);
        let release_m = Vec3::new(w.tank().min_m.x + 0.6, 1.5, w.tank().center_m().z);
        for fish in &mut w.fish {
            fish.position_m = release_m;
        }
        // Coarse grid: 4 cells along x, 2 in height, 3 along z.
        let cells = [4usize, 2, 3];
        let mut visited = [[[false; 3]; 2]; 4];
        for _ in 0..3_600 {
            w.step();
            for fish in w.fish() {
                let u = (fish.position_m - w.tank().min_m) / w.tank().size_m();
                let cell =
                    |axis: usize| ((u[axis] * cells[axis] as f32) as usize).min(cells[axis] - 1);
                visited[cell(0)][cell(1)][cell(2)] = true;
            }
        }
        let count = visited.iter().flatten().flatten().filter(|v| **v).count();
        assert!(count >= 18, "visited only {count} of 24 cells");
    }

    #[test]
    fn set_fish_count_grows_and_shrinks_keeping_existing_fish() {
        let mut w = world(9, 10);
        for _ in 0..10 {
            w.step();
        }
        let first_ten = w.fish().to_vec();
        w.set_fish_count(25);
        assert_eq!(w.fish().len(), 25);
        assert_eq!(&w.fish()[..10], &first_ten[..]);
        assert_all_fish_legal(&w);
        w.set_fish_count(4);
        assert_eq!(w.fish(), &first_ten[..4]);
        w.set_fish_count(0);
        assert!(w.fish().is_empty());
        w.step();
        assert_eq!(w.steps(), 11);
    }

    #[test]
    fn reset_rebuilds_from_the_seed_and_keeps_the_fish_count() {
        let mut w = world(1, 7);
        w.step();
        w.set_fish_count(12);
        w.reset(77);
        assert_eq!((w.seed(), w.steps(), w.fish().len()), (77, 0, 12));
        let fresh = world(77, 12);
        assert_eq!(positions(&w), positions(&fresh));
        assert_eq!(w.obstacles(), fresh.obstacles());
    }

    #[test]
    fn five_thousand_fish_step_without_nan() {
        let mut w = world(11, 5_000);
        for _ in 0..60 {
            w.step();
        }
        assert_all_fish_legal(&w);
        assert_eq!(w.non_finite_repairs(), 0);
    }

    #[test]
    fn absurd_or_nan_parameters_cannot_break_the_hard_rules() {
        let mut w = world(13, 50);
        // Far too fast, unlimited force, nonsense weights.
        *w.params_mut() = SteeringParams {
            max_speed_m_per_s: 50.0,
            min_speed_m_per_s: 40.0,
            max_force_m_per_s2: f32::INFINITY,
            containment_weight: -5.0,
            avoidance_weight: 0.0,
            ..SteeringParams::default()
        };
        for _ in 0..300 {
            w.step();
            assert_all_fish_legal(&w);
        }
        // NaN everywhere: the NaN guard replaces the force and says so.
        *w.params_mut() = SteeringParams {
            wander_weight: f32::NAN,
            wander_jitter_rad: f32::NAN,
            max_speed_m_per_s: f32::NAN,
            max_force_m_per_s2: f32::NAN,
            ..SteeringParams::default()
        };
        for _ in 0..300 {
            w.step();
            assert_all_fish_legal(&w);
        }
        assert!(w.non_finite_repairs() > 0);
        assert!(w.fish().iter().all(|f| f.wander_angle_rad.is_finite()));
    }

    fn boid_world(params: BoidParams, fish_count: usize) -> World {
        let mut w = World::new(WorldConfig {
            seed: 1,
            fish_count,
            ..WorldConfig::default()
        });
        w.set_boids(Some(params));
        w
    }

    /// What a class measures of one configuration: the metrics averaged over
    /// the last 30 s of a minute (four samples a second) and over `seeds`, and
    /// the share of fish-steps within 0.1 m and within 1 m of the glass, sand
    /// or surface.
    #[derive(Debug, Default)]
    struct Measured {
        polarization: f32,
        milling: f32,
        nnd_body_lengths: f32,
        groups: f32,
        speed_m_per_s: f32,
        at_edge: f32,
        in_edge_zone: f32,
        at_rock: f32,
    }

    fn measure_minute(params: BoidParams, seeds: &[u64]) -> Measured {
        let mut m = Measured::default();
        let k = seeds.len() as f32;
        for &seed in seeds {
            let mut w = World::new(WorldConfig {
                seed,
                fish_count: 200,
                ..WorldConfig::default()
            });
            w.set_boids(Some(params));
            let (mut samples, mut fish_steps, mut edge, mut zone, mut rock) =
                (0.0, 0.0, 0.0, 0.0, 0.0);
            let mut sum = SchoolMetrics::default();
            for step in 1..=3600 {
                w.step();
                if step <= 1800 {
                    continue;
                }
                for f in w.fish() {
                    let p = f.position_m;
                    let gap_m = (p - w.tank.min_m).min(w.tank.max_m - p).min_element();
                    edge += f32::from(gap_m < 0.1);
                    zone += f32::from(gap_m < 1.0);
                    rock += f32::from(w.obstacles.iter().any(|o| o.signed_distance_m(p) < 0.1));
                    fish_steps += 1.0;
                }
                if step % 15 == 0 {
                    let s = w.metrics().school;
                    sum.polarization += s.polarization;
                    sum.milling += s.milling;
                    sum.nnd_body_lengths += s.nnd_body_lengths;
                    sum.groups += s.groups;
                    sum.mean_speed_m_per_s += s.mean_speed_m_per_s;
                    samples += 1.0;
                }
            }
            m.polarization += sum.polarization / samples / k;
            m.milling += sum.milling / samples / k;
            m.nnd_body_lengths += sum.nnd_body_lengths / samples / k;
            m.groups += sum.groups as f32 / samples / k;
            m.speed_m_per_s += sum.mean_speed_m_per_s / samples / k;
            m.at_edge += edge / fish_steps / k;
            m.in_edge_zone += zone / fish_steps / k;
            m.at_rock += rock / fish_steps / k;
        }
        m
    }

    /// The group preset with weight `force` (in `Force::ALL` order) at `level`.
    fn group_with(force: usize, level: f32) -> BoidParams {
        let mut params = BoidParams::group();
        params.weights[force] = level;
        params
    }

    #[test]
    fn the_weights_alone_make_a_school_of_the_group_and_loners_of_the_individuals() {
        let (group, individual) = (BoidParams::group(), BoidParams::individual());
        assert_eq!(
            BoidParams {
                weights: group.weights,
                ..individual
            },
            group,
            "the presets differ only in their weights"
        );
        let seeds = [1, 2, 3];
        let g = measure_minute(group, &seeds);
        let i = measure_minute(individual, &seeds);
        assert!(g.polarization > 0.8, "group {g:?}");
        assert!(g.groups <= 2.0, "group {g:?}");
        assert!((0.7..=1.5).contains(&g.nnd_body_lengths), "group {g:?}");
        assert!(i.polarization < 0.4, "individual {i:?}");
        assert!(
            i.nnd_body_lengths >= 1.5 * g.nnd_body_lengths,
            "individual {i:?} vs group {g:?}"
        );
        // Fish stay off the glass, sand and surface by steering, in both presets.
        assert!(g.at_edge < 0.005 && i.at_edge < 0.005, "{g:?} {i:?}");
    }

    #[test]
    fn the_group_weights_school_in_direct_alternate_mode_too() {
        let m = measure_minute(
            BoidParams {
                mode: ControlMode::DirectAlternate,
                ..BoidParams::group()
            },
            &[1, 2],
        );
        assert!(m.polarization > 0.7 && m.groups <= 2.0, "{m:?}");
    }

    #[test]
    fn the_group_weights_school_in_classic_mode_at_a_real_swimming_speed() {
        // One action per step (the steering paper ran Table 1 this way): the
        // group weights still make one polarized school, swimming well above the
        // minimum speed, and the individual weights still do not.
        let classic = |params: BoidParams| BoidParams {
            mode: ControlMode::Classic,
            ..params
        };
        let seeds = [1, 2];
        let g = measure_minute(classic(BoidParams::group()), &seeds);
        let i = measure_minute(classic(BoidParams::individual()), &seeds);
        let min_speed = boid_world(BoidParams::group(), 1)
            .params()
            .min_speed_m_per_s;
        assert!(g.polarization > 0.7 && g.groups <= 2.0, "group {g:?}");
        assert!(
            g.speed_m_per_s > 2.0 * min_speed,
            "group {g:?}, minimum {min_speed}"
        );
        assert!(i.polarization < 0.45, "individual {i:?}");
        assert!(
            i.nnd_body_lengths >= 1.5 * g.nnd_body_lengths,
            "individual {i:?} vs group {g:?}"
        );
    }

    #[test]
    fn the_monte_carlo_paper_preset_forms_a_group_that_keeps_off_the_rocks() {
        let params = BoidParams {
            weights: control_mode::MONTE_CARLO_PAPER_WEIGHTS.map(|w| w * 100.0 / 3.2),
            mode: ControlMode::MonteCarlo,
            ..BoidParams::group()
        };
        let seeds = [1, 2];
        let m = measure_minute(params, &seeds);
        assert!(m.groups <= 2.0 && m.polarization > 0.6, "{m:?}");
        // Fish-steps within 0.1 m of a rock: a few brushes at most.
        assert!(m.at_rock < 0.005, "{m:?}");
    }

    // Each slider's effect has the sign of its name: runs that differ in one
    // weight only (from the Group preset), seeds 1 and 2.

    #[test]
    fn more_alignment_gives_higher_polarization() {
        let (lo, hi) = (
            measure_minute(group_with(1, 0.0), &[1, 2]),
            measure_minute(group_with(1, 50.0), &[1, 2]),
        );
        assert!(hi.polarization > lo.polarization + 0.3, "{lo:?} {hi:?}");
    }

    #[test]
    fn more_cohesion_gives_a_smaller_nearest_neighbour_distance_and_fewer_groups() {
        let (lo, hi) = (
            measure_minute(group_with(2, 0.0), &[1, 2]),
            measure_minute(group_with(2, 60.0), &[1, 2]),
        );
        assert!(hi.nnd_body_lengths < lo.nnd_body_lengths, "{lo:?} {hi:?}");
        assert!(hi.groups < lo.groups, "{lo:?} {hi:?}");
    }

    #[test]
    fn more_separation_gives_a_larger_nearest_neighbour_distance() {
        let (lo, hi) = (
            measure_minute(group_with(3, 10.0), &[1, 2]),
            measure_minute(group_with(3, 80.0), &[1, 2]),
        );
        assert!(
            hi.nnd_body_lengths > lo.nnd_body_lengths + 0.1,
            "{lo:?} {hi:?}"
        );
    }

    #[test]
    fn more_containment_keeps_fish_further_from_the_edges_of_the_pond() {
        // Loners roam the whole pond, so the effect shows best with their weights.
        let with_containment = |level: f32| {
            let mut params = BoidParams::individual();
            params.weights[0] = level;
            params
        };
        let (lo, hi) = (
            measure_minute(with_containment(0.0), &[1, 2]),
            measure_minute(with_containment(100.0), &[1, 2]),
        );
        assert!(hi.in_edge_zone < 0.8 * lo.in_edge_zone, "{lo:?} {hi:?}");
    }

    #[test]
    fn more_avoidance_keeps_fish_off_the_rocks_and_the_glass() {
        let (lo, hi) = (
            measure_minute(group_with(4, 0.0), &[1, 2]),
            measure_minute(group_with(4, 98.0), &[1, 2]),
        );
        assert!(hi.at_rock < lo.at_rock, "{lo:?} {hi:?}");
        // Without containment only avoidance keeps them off the glass.
        let mut bare = group_with(0, 0.0);
        bare.weights[4] = 0.0;
        let (lo, hi) = (
            measure_minute(bare, &[1]),
            measure_minute(group_with(0, 0.0), &[1]),
        );
        assert!(hi.at_edge < lo.at_edge, "{lo:?} {hi:?}");
    }

    #[test]
    fn monte_carlo_in_the_world_applies_forces_as_often_as_their_weights_say() {
        let params = BoidParams {
            mode: ControlMode::MonteCarlo,
            weights: control_mode::MONTE_CARLO_PAPER_WEIGHTS,
            ..BoidParams::group()
        };
        let mut w = boid_world(params, 200);
        for _ in 0..600 {
            w.step();
        }
        let total: f32 = control_mode::MONTE_CARLO_PAPER_WEIGHTS.iter().sum();
        for (i, seen) in w.force_frequencies().into_iter().enumerate() {
            let expected = f64::from(control_mode::MONTE_CARLO_PAPER_WEIGHTS[i] / total);
            assert!(
                (seen - expected).abs() < 0.01,
                "force {i}: {seen} vs {expected}"
            );
        }
    }

    #[test]
    fn boids_with_every_slider_at_zero_or_maximum_stay_in_the_tank_and_finite() {
        for mode in ControlMode::ALL {
            for weights in [[0.0; 5], [100.0; 5]] {
                let params = BoidParams {
                    mode,
                    weights,
                    ..BoidParams::group()
                };
                let mut w = boid_world(params, 300);
                w.set_species_counts(2, 4);
                for _ in 0..600 {
                    w.step();
                }
                assert_all_fish_legal(&w);
                assert_eq!(w.non_finite_repairs(), 0, "{mode:?} {weights:?}");
            }
        }
    }

    #[test]
    fn five_thousand_schooling_fish_with_sharks_and_stingrays_stay_legal() {
        let mut w = World::new(WorldConfig {
            seed: 11,
            fish_count: 5_000,
            sharks: 3,
            stingrays: 6,
            obstacles: None,
        });
        w.set_boids(Some(BoidParams::group()));
        for _ in 0..60 {
            w.step();
        }
        assert_all_fish_legal(&w);
        assert_eq!(w.non_finite_repairs(), 0);
        assert_eq!(w.fish().len(), 5_000);
    }

    /// The first seed in 0..50 whose generated layout has a reef ledge.
    fn seed_with_a_ledge() -> u64 {
        (0..50)
            .find(|&seed| {
                world(seed, 0)
                    .obstacles()
                    .iter()
                    .any(|o| matches!(o, Obstacle::Polygon { .. }))
            })
            .expect("some seed places a ledge")
    }

    #[test]
    fn no_fish_ever_enters_a_rock_pillar_ledge_or_stingray_in_a_long_run() {
        let mut w = World::new(WorldConfig {
            seed: seed_with_a_ledge(),
            fish_count: 200,
            sharks: 1,
            stingrays: 8,
            obstacles: None,
        });
        w.set_boids(Some(BoidParams::group()));
        for _ in 0..2 * 60 * 60 {
            w.step();
            assert_all_fish_legal(&w);
        }
        assert_eq!(w.non_finite_repairs(), 0);
    }

    #[test]
    fn obstacles_round_trip_through_json_with_a_kind_tag() {
        let w = world(seed_with_a_ledge(), 0);
        let json = serde_json::to_string(w.obstacles()).unwrap();
        assert!(json.contains(r#""kind":"rock""#), "{json}");
        assert!(json.contains(r#""kind":"polygon""#), "{json}");
        assert!(json.contains("footprint_m") && json.contains("radius_m"));
        let back: Vec<Obstacle> = serde_json::from_str(&json).unwrap();
        assert_eq!(back, w.obstacles());
        let config: WorldConfig = serde_json::from_str(r#"{"seed": 5}"#).unwrap();
        assert_eq!(
            config,
            WorldConfig {
                seed: 5,
                ..WorldConfig::default()
            }
        );
        let default = WorldConfig::default();
        assert_eq!(
            (default.fish_count, default.sharks, default.stingrays),
            (200, 0, 0)
        );
        assert!(default.obstacles.is_none());
    }

    #[test]
    fn a_teachers_layout_is_used_exactly_and_survives_a_reset() {
        let layout = vec![
            Obstacle::Rock {
                center_m: Vec3::new(0.0, -0.2, 0.0),
                radius_m: 0.8,
            },
            Obstacle::Polygon {
                footprint_m: vec![
                    Vec2::new(2.0, 1.0),
                    Vec2::new(4.0, 1.0),
                    Vec2::new(3.0, 2.5),
                ],
                base_y_m: 0.0,
                height_m: 1.0,
            },
        ];
        let mut w = World::new(WorldConfig {
            obstacles: Some(layout.clone()),
            ..WorldConfig::default()
        });
        assert_eq!(w.obstacles(), &layout[..]);
        assert_all_fish_legal(&w);
        w.reset(9);
        assert_eq!(w.obstacles(), &layout[..]);
    }

    #[test]
    fn adding_moving_and_removing_obstacles_keeps_every_fish_outside() {
        let mut w = world(4, 1_000);
        w.set_species_counts(0, 3);
        for _ in 0..30 {
            w.step();
        }
        // A big rock dropped into the middle of the school.
        let rock = Obstacle::Rock {
            center_m: w.tank().center_m() * Vec3::new(1.0, 0.0, 1.0),
            radius_m: 1.4,
        };
        let before = w.obstacles().len();
        match w.add_obstacle(rock) {
            Ok(index) => {
                assert_eq!(index, before);
                assert_all_fish_legal(&w);
                // Moving it sweeps through more fish; they are pushed out at once.
                if w.move_obstacle(index, Vec2::new(-3.5, 1.5)).is_ok() {
                    assert_all_fish_legal(&w);
                }
                assert!(w.remove_obstacle(index));
            }
            Err(reason) => assert!(reason.to_string().contains("too close"), "{reason}"),
        }
        assert!(!w.remove_obstacle(99));
        assert!(w.move_obstacle(99, Vec2::ZERO).is_err());
        // Invalid obstacles are refused with a reason and change nothing.
        let count = w.obstacles().len();
        let outside = Obstacle::Cylinder {
            base_center_m: Vec3::new(5.8, 0.0, 0.0),
            radius_m: 0.3,
            height_m: 2.0,
        };
        assert!(
            w.add_obstacle(outside)
                .unwrap_err()
                .to_string()
                .contains("glass")
        );
        assert_eq!(w.obstacles().len(), count);
        // A whole new layout: a ledge across the middle.
        w.set_obstacles(vec![Obstacle::Polygon {
            footprint_m: vec![
                Vec2::new(-3.0, -1.0),
                Vec2::new(3.0, -1.0),
                Vec2::new(3.0, 1.0),
                Vec2::new(-3.0, 1.0),
            ],
            base_y_m: 0.0,
            height_m: 2.0,
        }]);
        assert_eq!(w.obstacles().len(), 1);
        assert_all_fish_legal(&w);
        for _ in 0..120 {
            w.step();
            assert_all_fish_legal(&w);
        }
    }

    #[test]
    fn species_counts_are_capped_and_spawned_legally() {
        let mut w = world(6, 100);
        w.set_species_counts(50, 50);
        assert_eq!((w.sharks().len(), w.stingrays().len()), (10, 20));
        assert_all_fish_legal(&w);
        w.set_species_counts(1, 2);
        assert_eq!((w.sharks().len(), w.stingrays().len()), (1, 2));
        for s in w.sharks() {
            let length_m = s.body.body_length_m;
            assert!((1.5..=2.0).contains(&length_m));
        }
    }

    #[test]
    fn a_fish_that_sees_a_shark_flees() {
        let mut w = boid_world(BoidParams::group(), 1);
        w.set_species_counts(1, 0);
        // The fish swims towards a (satiated, cruising) shark 3 m ahead.
        w.fish[0] = Fish::new(Vec3::new(1.0, 2.0, 0.0), Vec3::NEG_X * 0.5, 0.4, 0.0);
        w.sharks[0] = shark::new_shark(Vec3::new(-2.0, 2.0, 0.0), 0.0, 1.8);
        w.sharks[0].satiated_secs = 10.0;
        let start_m = w.fish()[0]
            .position_m
            .distance(w.sharks()[0].body.position_m);
        for _ in 0..180 {
            w.step();
        }
        let end_m = w.fish()[0]
            .position_m
            .distance(w.sharks()[0].body.position_m);
        assert!(end_m > start_m + 0.5, "distance {start_m} → {end_m}");
        assert!(w.fish()[0].velocity_m_per_s.x > 0.0, "it turned away");
    }

    /// Catches per simulated minute of 2 sharks among 200 fish, over seeds,
    /// once the fish have had half a minute to settle.
    fn catches_per_minute(params: BoidParams) -> f64 {
        let seeds = [1, 2, 3];
        let minutes = 2;
        let mut catches = 0;
        for seed in seeds {
            let mut w = World::new(WorldConfig {
                seed,
                fish_count: 200,
                ..WorldConfig::default()
            });
            w.set_boids(Some(params));
            // Half a minute to settle (the school forms), then the sharks come.
            for _ in 0..1800 {
                w.step();
            }
            w.set_species_counts(2, 0);
            for _ in 0..minutes * 3600 {
                w.step();
            }
            assert_eq!(w.fish().len(), 200, "caught fish are replaced");
            assert_eq!(w.metrics().catches, w.catches());
            catches += w.catches();
        }
        catches as f64 / (seeds.len() * minutes) as f64
    }

    /// Lone fish meet the shark alone: its lock holds, it lunges and bites.
    /// Schooling fish are saved by the confusion effect (no lock lasts long
    /// enough to strike) and by the many eyes of the school (a fish that sees
    /// a frightened neighbour flees too, so the school turns away together
    /// instead of single fish bolting out of it).
    #[test]
    fn sharks_catch_lone_fish_more_often_than_schooling_fish() {
        let lone = catches_per_minute(BoidParams::individual());
        let schooled = catches_per_minute(BoidParams::group());
        println!("catches per minute: lone {lone:.2}, schooled {schooled:.2}");
        assert!(lone > 0.0);
        assert!(lone > 1.5 * schooled, "lone {lone} vs schooled {schooled}");
    }

    #[test]
    fn stingrays_glide_near_the_sand_and_close_ones_are_avoided_as_one_polygon() {
        let mut w = world(3, 50);
        w.set_species_counts(0, 3);
        let floor_y_m = w.tank().min_m.y;
        // Three rays side by side in open water, in a clear spot.
        w.set_obstacles(Vec::new());
        for (k, ray) in w.stingrays.iter_mut().enumerate() {
            *ray =
                stingray::new_stingray(Vec3::new(-1.5 + 1.5 * k as f32, 0.4, 0.0), 0.0, floor_y_m);
        }
        w.step();
        assert_eq!(w.stingray_obstacles().len(), 1);
        assert!(matches!(
            w.stingray_obstacles()[0],
            Obstacle::Polygon { .. }
        ));
        for _ in 0..1200 {
            w.step();
            assert_all_fish_legal(&w);
        }
    }

    /// The seven fish nearest to fish `i` of `school` that it sees, nearest
    /// first, by brute force.
    fn seven_nearest_seen(school: &[Fish], i: usize, perception: &Perception) -> Vec<usize> {
        let me = school[i];
        let mut seen: Vec<(f32, usize)> = (0..school.len())
            .filter(|&j| {
                j != i
                    && forces::sees(
                        me.position_m,
                        me.heading(),
                        school[j].position_m,
                        perception,
                    )
            })
            .map(|j| (school[j].position_m.distance_squared(me.position_m), j))
            .collect();
        seen.sort_by(|a, b| a.0.total_cmp(&b.0));
        seen.iter().take(7).map(|&(_, j)| j).collect()
    }

    #[test]
    fn show_vision_links_are_the_seven_nearest_neighbours_the_fish_sees() {
        let mut w = boid_world(BoidParams::group(), 300);
        let mut links = Vec::new();
        w.interaction_neighbours(0, &mut links);
        assert!(links.is_empty(), "no step yet");
        let before: Vec<Fish> = w.fish().to_vec();
        w.step();
        let perception = BoidParams::group().perception;
        for i in [0, 17, 299] {
            w.interaction_neighbours(i, &mut links);
            // Brute force over the school as it was when the fish chose.
            assert_eq!(
                links,
                seven_nearest_seen(&before, i, &perception),
                "fish {i}"
            );
        }
        w.interaction_neighbours(300, &mut links);
        assert!(links.is_empty(), "no such fish");
        w.set_fish_count(100);
        w.interaction_neighbours(0, &mut links);
        assert!(links.is_empty(), "stale after a change of fish count");
    }

    #[test]
    fn heeded_neighbours_are_always_seen_and_searched_every_few_steps() {
        let mut w = boid_world(BoidParams::group(), 400);
        for _ in 0..60 {
            w.step();
        }
        let perception = BoidParams::group().perception;
        let mut links = Vec::new();
        for _ in 0..NEIGHBOUR_SEARCH_EVERY_STEPS {
            let before: Vec<Fish> = w.fish().to_vec();
            let step = w.steps();
            w.step();
            let mut searched = 0;
            for (i, me) in before.iter().enumerate() {
                w.interaction_neighbours(i, &mut links);
                for &j in &links {
                    assert!(
                        forces::sees(
                            me.position_m,
                            me.heading(),
                            before[j].position_m,
                            &perception
                        ),
                        "fish {i} heeds {j}, which it does not see"
                    );
                }
                if (i as u64 + step).is_multiple_of(NEIGHBOUR_SEARCH_EVERY_STEPS) {
                    searched += 1;
                    assert_eq!(
                        links,
                        seven_nearest_seen(&before, i, &perception),
                        "fish {i} searched at step {step}"
                    );
                } else {
                    assert!(links.len() <= 7);
                }
            }
            assert_eq!(searched, 100, "a quarter of the fish search each step");
        }
    }

    #[test]
    fn metrics_are_measured_after_every_step() {
        let mut w = boid_world(BoidParams::group(), 300);
        for _ in 0..90 {
            w.step();
        }
        // Step 90 is a multiple of SPATIAL_METRICS_EVERY_STEPS: all fresh.
        let fresh =
            crate::sim::common::school_metrics::measure(w.fish(), w.tank().min_m, w.tank().max_m);
        assert_eq!(w.metrics().school, fresh);
        // Blended mode applies every weighted force on every fish-step.
        assert_eq!(w.metrics().force_frequencies_recent, [1.0; 5]);
        assert_eq!(w.metrics().force_frequencies_total, w.force_frequencies());
        // One step later the order parameters are new, the spatial ones kept.
        w.step();
        let order = crate::sim::common::school_metrics::order_parameters(w.fish());
        let school = w.metrics().school;
        assert_eq!(school.polarization, order.polarization);
        assert_eq!(school.mean_speed_m_per_s, order.mean_speed_m_per_s);
        assert_eq!(
            (school.groups, school.nnd_body_lengths),
            (fresh.groups, fresh.nnd_body_lengths)
        );
    }
}
