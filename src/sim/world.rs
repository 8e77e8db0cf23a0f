//! The whole aquarium: tank, obstacles and fish, advanced in fixed time steps.
//!
//! A world is built from a seed and is deterministic: the same seed and the
//! same sequence of calls give bit-identical fish on the same machine.

use std::f32::consts::TAU;

use glam::{Vec2, Vec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use super::boid_forces::{self, Perception};
use super::control_mode::{self, ControlMode};
use super::fish::Fish;
use super::obstacle::Obstacle;
use super::spatial_grid::SpatialGrid;
use super::steering::{self, SteeringParams};
use super::tank::Tank;

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

/// Gap between an obstacle's footprint and the side walls, in metres.
/// Default 1.0 m: fish can swim behind every obstacle, and pushing a fish out
/// of an obstacle can never push it out of the tank.
const WALL_CLEARANCE_M: f32 = 1.0;

/// Smallest gap between the footprints of two obstacles, in metres.
/// Default 0.8 m: wide enough for fish (with their avoidance clearance) to
/// swim between, and obstacles never overlap.
const OBSTACLE_GAP_M: f32 = 0.8;

/// Random positions tried per obstacle or fish before giving up (obstacle)
/// or falling back to a pushed-out position (fish). Default 200: placement
/// practically always succeeds in the default tank, and the loop is bounded.
const PLACEMENT_ATTEMPTS: usize = 200;

/// Distance from walls and obstacle surfaces at which new fish appear, in
/// metres. Default 0.3 m: about one body length, so no fish starts touching
/// anything.
const SPAWN_CLEARANCE_M: f32 = 0.3;

/// What to build: the seed and the number of fish.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct WorldConfig {
    /// Seed of the random generator; the same seed gives the same aquarium.
    /// Default 1.
    pub seed: u64,
    /// Number of fish. Default 200: a lively tank that any laptop can run.
    pub fish_count: usize,
}

impl Default for WorldConfig {
    fn default() -> Self {
        Self {
            seed: 1,
            fish_count: 200,
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
    /// Weight of a wander added to the five forces. Default 0 (tuned): any wander
    /// strong enough to see drowned the 25 %-share neighbour forces and kept
    /// the group preset from polarising.
    pub wander_weight: f32,
}

impl BoidParams {
    /// Table 1's "group" preset, blended, with a 300° field of view (TT §5).
    ///
    /// Perception (tuned, seed sweep 1–7, 200 fish): vision 5 m, about a school's
    /// width in this 12 m tank; with 2 m the school broke into milling clusters
    /// (polarization ≈ 0.1), with 4–6 m it polarises (≈ 0.9–0.99 within a minute).
    /// Maximum force 3 m/s², so the 25 % slider share (0.75 m/s² at full weight)
    /// can turn a 0.8 m/s fish within about a body length's worth of time.
    pub fn group() -> Self {
        Self {
            weights: control_mode::GROUP_WEIGHTS,
            mode: ControlMode::Blended,
            perception: Perception {
                vision_distance_m: 5.0,
                vision_angle_rad: 300f32.to_radians(),
                max_speed_m_per_s: 0.8,
                max_force_m_per_s2: 3.0,
            },
            wander_weight: 0.0,
        }
    }

    /// Table 1's "individual" preset, same perception.
    pub fn individual() -> Self {
        Self {
            weights: control_mode::INDIVIDUAL_WEIGHTS,
            ..Self::group()
        }
    }
}

/// The aquarium and everything in it.
#[derive(Clone, Debug)]
pub struct World {
    seed: u64,
    tank: Tank,
    obstacles: Vec<Obstacle>,
    fish: Vec<Fish>,
    params: SteeringParams,
    rng: ChaCha8Rng,
    time_secs: f64,
    steps: u64,
    non_finite_repairs: u64,
    /// `Some`: fish steer with the SIMBA boid layer; `None`: they wander alone.
    boids: Option<BoidParams>,
    grid: SpatialGrid,
    /// How many fish-steps each of the five forces was applied on.
    force_counts: [u64; 5],
    /// Fish-steps taken with the boid layer on.
    boid_fish_steps: u64,
}

impl World {
    /// Same as the module constant [`DT_SECS`].
    pub const DT_SECS: f32 = DT_SECS;

    /// Build the scene for `config.seed`: 4–6 rocks half-buried in the sand
    /// and 2–3 pillars, none overlapping and all away from the glass, then
    /// `config.fish_count` fish (at most [`MAX_FISH_COUNT`]) at free places.
    pub fn new(config: WorldConfig) -> Self {
        let tank = Tank::default();
        let mut rng = ChaCha8Rng::seed_from_u64(config.seed);
        let obstacles = place_obstacles(&tank, &mut rng);
        let mut world = Self {
            seed: config.seed,
            tank,
            obstacles,
            fish: Vec::new(),
            params: SteeringParams::default(),
            rng,
            time_secs: 0.0,
            steps: 0,
            non_finite_repairs: 0,
            boids: None,
            grid: SpatialGrid::default(),
            force_counts: [0; 5],
            boid_fish_steps: 0,
        };
        world.set_fish_count(config.fish_count);
        world
    }

    /// The tank.
    pub fn tank(&self) -> &Tank {
        &self.tank
    }

    /// Rocks and pillars.
    pub fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }

    /// All fish, in a stable order (fish i stays fish i).
    pub fn fish(&self) -> &[Fish] {
        &self.fish
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
        self.seed
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

    /// Advance the world by one fixed step of [`DT_SECS`]. For each fish:
    ///
    /// 1. steering = wander·w₁ + containment·w₂ + obstacle avoidance·w₃
    ///    (replaced by zero if not finite),
    /// 2. integrate: limit to max force, semi-implicit Euler, speed kept in
    ///    [min, max] (see [`Fish::integrate`]),
    /// 3. hard constraints: clamp into the tank and push out of every
    ///    obstacle, reflecting the velocity component that points into the
    ///    glass or rock, so no fish ever leaves the water or enters a rock,
    /// 4. advance the tail-beat phase.
    pub fn step(&mut self) {
        if let Some(boids) = self.boids {
            self.step_boids(&boids);
            return;
        }
        let params = self.params;
        for fish in &mut self.fish {
            let before = *fish;
            let wander = steering::wander(fish, &mut self.rng, &params);
            let (containment, avoidance) =
                glass_and_rock_forces(&before, &self.tank, &self.obstacles, &params);
            let steering_m_per_s2 = wander * params.wander_weight
                + containment * params.containment_weight
                + avoidance * params.avoidance_weight;
            self.non_finite_repairs += move_fish(
                fish,
                &before,
                steering_m_per_s2,
                &params,
                &self.tank,
                &self.obstacles,
            );
        }
        self.finish_step();
    }

    fn finish_step(&mut self) {
        self.steps += 1;
        self.time_secs = self.steps as f64 * f64::from(DT_SECS);
    }

    /// Steer with the SIMBA boid layer (`Some`) or wander alone (`None`).
    pub fn set_boids(&mut self, boids: Option<BoidParams>) {
        self.boids = boids;
    }

    /// The boid-layer settings, when on.
    pub fn boids(&self) -> Option<&BoidParams> {
        self.boids.as_ref()
    }

    /// Fraction of fish-steps on which each force was applied (random modes show
    /// their lottery here), in [`control_mode::Force::ALL`] order.
    pub fn force_frequencies(&self) -> [f64; 5] {
        let fish_steps = self.boid_fish_steps.max(1) as f64;
        std::array::from_fn(|i| self.force_counts[i] as f64 / fish_steps)
    }

    /// One step of the boid layer. All fish perceive the same snapshot of the
    /// school (synchronous update), so the result does not depend on fish order.
    fn step_boids(&mut self, boids: &BoidParams) {
        let params = SteeringParams {
            max_speed_m_per_s: boids.perception.max_speed_m_per_s,
            max_force_m_per_s2: boids.perception.max_force_m_per_s2,
            ..self.params
        };
        let max_force = params.max_force_m_per_s2;
        let snapshot = self.fish.clone();
        let positions: Vec<Vec3> = snapshot.iter().map(|f| f.position_m).collect();
        self.grid.rebuild(
            self.tank.min_m,
            self.tank.max_m,
            boids.perception.vision_distance_m,
            &positions,
        );
        for i in 0..self.fish.len() {
            let me = snapshot[i];
            let neighbours =
                boid_forces::neighbour_forces(&snapshot, i, &self.grid, &boids.perception);
            let (containment, avoidance) =
                glass_and_rock_forces(&me, &self.tank, &self.obstacles, &params);
            let containment = steering::limit(containment, max_force);
            let avoidance = steering::limit(avoidance, max_force);
            let forces = [
                containment,
                neighbours.alignment_m_per_s2,
                neighbours.cohesion_m_per_s2,
                neighbours.separation_m_per_s2,
                avoidance,
            ];
            let combined = control_mode::combine(
                boids.mode,
                &forces,
                &boids.weights,
                max_force,
                &mut self.rng,
            );
            for (count, applied) in self.force_counts.iter_mut().zip(combined.applied) {
                *count += u64::from(applied);
            }
            self.boid_fish_steps += 1;
            let fish = &mut self.fish[i];
            let wander = steering::wander(fish, &mut self.rng, &params);
            let steering_m_per_s2 = combined.force_m_per_s2 + wander * boids.wander_weight;
            self.non_finite_repairs += move_fish(
                fish,
                &me,
                steering_m_per_s2,
                &params,
                &self.tank,
                &self.obstacles,
            );
        }
        self.finish_step();
    }

    /// Keep the first `fish_count` fish (at most [`MAX_FISH_COUNT`]), or add
    /// new ones drawn from the world's random generator. Existing fish are
    /// never changed.
    pub fn set_fish_count(&mut self, fish_count: usize) {
        let fish_count = fish_count.min(MAX_FISH_COUNT);
        self.fish.truncate(fish_count);
        while self.fish.len() < fish_count {
            let fish = spawn_fish(&self.tank, &self.obstacles, &self.params, &mut self.rng);
            self.fish.push(fish);
        }
    }

    /// Rebuild the world from `seed` with the same number of fish and the
    /// same steering tuning; time and step count restart at zero.
    pub fn reset(&mut self, seed: u64) {
        let params = self.params;
        let boids = self.boids;
        *self = Self::new(WorldConfig {
            seed,
            fish_count: self.fish.len(),
        });
        self.params = params;
        self.boids = boids;
    }
}

/// Containment (stay off the glass, floor and surface) and obstacle avoidance for
/// `fish`, both as used by every steering path.
fn glass_and_rock_forces(
    fish: &Fish,
    tank: &Tank,
    obstacles: &[Obstacle],
    params: &SteeringParams,
) -> (Vec3, Vec3) {
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
        obstacles,
        params.avoidance_look_ahead_m,
        params.max_speed_m_per_s,
    );
    (containment, avoidance)
}

/// Moves one fish by one step under `steering_m_per_s2`: integrate, repair any
/// non-finite value (back to `before`, at minimum speed), enforce the hard rules
/// and beat the tail. Returns how many repairs were needed (0, 1 or 2).
fn move_fish(
    fish: &mut Fish,
    before: &Fish,
    steering_m_per_s2: Vec3,
    params: &SteeringParams,
    tank: &Tank,
    obstacles: &[Obstacle],
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
        fish.position_m = before.position_m;
        fish.velocity_m_per_s = before.heading() * params.min_speed_m_per_s.max(0.0);
    }
    enforce_hard_constraints(fish, tank, obstacles);
    fish.advance_tail_phase(DT_SECS);
    repairs
}

/// The hard rules: whatever the steering did, the fish ends up inside the
/// tank (by [`TANK_MARGIN_M`]) and outside every obstacle (by
/// [`OBSTACLE_MARGIN_M`]), and no longer swims into what it touched.
///
/// Obstacles are placed at least [`WALL_CLEARANCE_M`] from the side walls,
/// lower than the surface, and pushing out of a half-buried rock or a rooted
/// pillar never points into the sand, so the obstacle push cannot undo the
/// tank clamp.
fn enforce_hard_constraints(fish: &mut Fish, tank: &Tank, obstacles: &[Obstacle]) {
    let clamped_m = tank.clamp_inside(fish.position_m, TANK_MARGIN_M);
    let pushed_m = clamped_m - fish.position_m;
    for axis in 0..3 {
        // Pushed back on this axis while still swimming outwards: bounce.
        if pushed_m[axis] * fish.velocity_m_per_s[axis] < 0.0 {
            fish.velocity_m_per_s[axis] = -fish.velocity_m_per_s[axis];
        }
    }
    fish.position_m = clamped_m;

    for obstacle in obstacles {
        if obstacle.signed_distance_m(fish.position_m) < OBSTACLE_MARGIN_M {
            fish.position_m = obstacle.push_outside(fish.position_m, OBSTACLE_MARGIN_M);
            let normal = obstacle.outward_normal(fish.position_m);
            let into_m_per_s = fish.velocity_m_per_s.dot(normal);
            if into_m_per_s < 0.0 {
                fish.velocity_m_per_s -= 2.0 * into_m_per_s * normal;
            }
        }
    }
}

/// A uniform random number between `lo` and `hi` (never panics).
fn uniform(rng: &mut ChaCha8Rng, lo: f32, hi: f32) -> f32 {
    lo + (hi - lo) * rng.random::<f32>()
}

/// Where an obstacle meets the floor: centre (x, z) and radius in metres.
fn footprint(obstacle: &Obstacle) -> (Vec2, f32) {
    let center_m = match *obstacle {
        Obstacle::Rock { center_m, .. } => center_m,
        Obstacle::Cylinder { base_center_m, .. } => base_center_m,
    };
    (Vec2::new(center_m.x, center_m.z), obstacle.radius_m())
}

/// 4–6 rocks (radius 0.4–1.0 m, centre at or up to 0.3 radii below the sand,
/// i.e. about half-buried) and 2–3 pillars (radius 0.25–0.5 m, height
/// 1.5–3.5 m) at random places that keep [`WALL_CLEARANCE_M`] from the glass
/// and [`OBSTACLE_GAP_M`] from each other. An obstacle that finds no place in
/// [`PLACEMENT_ATTEMPTS`] tries is left out.
fn place_obstacles(tank: &Tank, rng: &mut ChaCha8Rng) -> Vec<Obstacle> {
    let rock_count = rng.random_range(4..=6);
    let pillar_count = rng.random_range(2..=3);
    let mut obstacles: Vec<Obstacle> = Vec::new();
    for index in 0..rock_count + pillar_count {
        let is_rock = index < rock_count;
        for _ in 0..PLACEMENT_ATTEMPTS {
            let radius_m = if is_rock {
                uniform(rng, 0.4, 1.0)
            } else {
                uniform(rng, 0.25, 0.5)
            };
            let edge_m = WALL_CLEARANCE_M + radius_m;
            let x_m = uniform(rng, tank.min_m.x + edge_m, tank.max_m.x - edge_m);
            let z_m = uniform(rng, tank.min_m.z + edge_m, tank.max_m.z - edge_m);
            let fits = obstacles.iter().all(|other| {
                let (other_center, other_radius_m) = footprint(other);
                other_center.distance(Vec2::new(x_m, z_m))
                    >= radius_m + other_radius_m + OBSTACLE_GAP_M
            });
            if !fits {
                continue;
            }
            obstacles.push(if is_rock {
                let buried_m = uniform(rng, 0.0, 0.3) * radius_m;
                Obstacle::Rock {
                    center_m: Vec3::new(x_m, tank.min_m.y - buried_m, z_m),
                    radius_m,
                }
            } else {
                Obstacle::Cylinder {
                    base_center_m: Vec3::new(x_m, tank.min_m.y, z_m),
                    radius_m,
                    height_m: uniform(rng, 1.5, 3.5),
                }
            });
            break;
        }
    }
    obstacles
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
    let random_point = |rng: &mut ChaCha8Rng| {
        let u = Vec3::new(rng.random(), rng.random(), rng.random());
        tank.min_m + u * tank.size_m()
    };
    let is_free = |p: Vec3| {
        tank.contains(p, SPAWN_CLEARANCE_M)
            && obstacles
                .iter()
                .all(|o| o.signed_distance_m(p) >= SPAWN_CLEARANCE_M)
    };
    let mut position_m = random_point(rng);
    for _ in 0..PLACEMENT_ATTEMPTS {
        if is_free(position_m) {
            break;
        }
        position_m = random_point(rng);
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

#[cfg(test)]
mod tests {
    use super::*;

    fn world(seed: u64, fish_count: usize) -> World {
        World::new(WorldConfig { seed, fish_count })
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
        }
    }

    #[test]
    fn default_scene_has_4_to_6_rocks_and_2_to_3_pillars_that_do_not_overlap() {
        for seed in 0..20 {
            let w = world(seed, 0);
            let rocks = w
                .obstacles()
                .iter()
                .filter(|o| matches!(o, Obstacle::Rock { .. }));
            let pillars = w.obstacles().len() - rocks.clone().count();
            assert!((4..=6).contains(&rocks.count()), "seed {seed}");
            assert!((2..=3).contains(&pillars), "seed {seed}");
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
        });
        w.set_boids(Some(params));
        w
    }

    #[test]
    fn group_preset_packs_fish_closer_and_into_fewer_groups_than_individual() {
        let mut grid = crate::sim::SpatialGrid::default();
        let mut measure = |params: BoidParams| {
            let mut w = boid_world(params, 200);
            for _ in 0..3600 {
                w.step();
            }
            crate::sim::school_metrics::measure(w.fish(), w.tank().min_m, w.tank().max_m, &mut grid)
        };
        let group = measure(BoidParams::group());
        let individual = measure(BoidParams::individual());
        assert!(
            group.nnd_body_lengths < individual.nnd_body_lengths,
            "{group:?} vs {individual:?}"
        );
        assert!(
            group.groups < individual.groups,
            "{group:?} vs {individual:?}"
        );
    }

    #[test]
    fn group_preset_polarises_within_a_minute() {
        let mut grid = crate::sim::SpatialGrid::default();
        let mut w = boid_world(BoidParams::group(), 200);
        let mut best = 0.0_f32;
        for step in 1..=3600 {
            w.step();
            if step % 300 == 0 {
                let m = crate::sim::school_metrics::measure(
                    w.fish(),
                    w.tank().min_m,
                    w.tank().max_m,
                    &mut grid,
                );
                best = best.max(m.polarization);
            }
        }
        assert!(best > 0.8, "best polarization {best}");
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
                for _ in 0..600 {
                    w.step();
                }
                for f in w.fish() {
                    assert!(f.position_m.is_finite() && f.velocity_m_per_s.is_finite());
                    assert!(w.tank().contains(f.position_m, 0.0));
                    for o in w.obstacles() {
                        assert!(o.signed_distance_m(f.position_m) >= 0.0);
                    }
                }
                assert_eq!(w.non_finite_repairs(), 0, "{mode:?} {weights:?}");
            }
        }
    }
}
