//! The dynamic fish: 23 point masses joined by 91 springs, 12 of them muscles,
//! pushed by the water. Tu & Terzopoulos 1994 §3.1 eq. (1)
//! m_i ẍ_i + γ_i ẋ_i − w_i = f^w_i, with w_i = Σ_j c_ij e_ij r_ij/‖r_ij‖, muscles
//! (§3.2) and the water force of `hydrodynamics.rs`, integrated by implicit Euler.
//!
//! # Scale
//! The paper's constants are for a fish 26 units long with Δt = 0.055. A fish of
//! `body_length_m` uses the length scale s = body_length_m / 26 and
//!
//! | quantity          | scaled as | why |
//! |-------------------|-----------|-----|
//! | positions         | × s       | geometry |
//! | time, Δt          | × 1       | keep the paper's Δt = 0.055 s and its stability |
//! | masses            | × s²      | so that the water force A·v (∝ s³) and m·a (∝ s²·s) scale alike |
//! | stiffness, damping| × s²      | c·e ∝ s³ like m·a |
//! | other forces      | × s³      | |
//!
//! With these factors every term of eq. (1) scales by s³, so any fish moves exactly
//! like the paper's fish measured in body lengths per second: speeds in m/s are
//! s × the paper-unit speeds, angles and frequencies are unchanged. Masses are
//! therefore "paper mass units × s²", not kilograms; the water density is folded
//! into them (the paper's force has no density either).
//!
//! # Time scale: a paper time unit is not a second
//! The paper gives Δt = 0.055 but no time unit. Read as seconds, its constants make
//! a sluggish fish (diagnosis, 26-unit fish, k = 1 below, measured with a diagnostic run while tuning):
//! contracting one side of the middle and posterior segments fully from rest bends
//! the tail 7.1 units sideways with t63 = 1.76 s, t90 = 2.6 s in water, and even
//! with the water switched off (air, node and spring damping only) t63 = 1.0 s,
//! t90 = 1.2 s, first peak at about 2 s: the lowest bending mode of masses 1.1–11
//! on springs of 28–38 has a natural frequency of about 0.25 Hz, so no drag or
//! scaling bug can be the cause. The integrator and the water were checked too:
//! Δt = 0.055 and Δt = 0.0055 give the same step response (t63 1.76 s vs 1.71 s),
//! and a rigid sideways launch decays like the summed face areas predict (0.50 vs
//! analytic 0.43 of the speed after 1 s, the difference being the body's yaw), so
//! the water force is counted once. Swimming with k = 1 saturates at 0.15 Hz and
//! 0.023 body lengths/s; at 3 Hz it gives 0.000.
//!
//! So one second here is k = [`BodyParams::paper_time_units_per_sec`] paper time
//! units (default 40): stiffness × k², damping, water and fin forces × k, the
//! righting couple × k², masses unchanged. This keeps every ratio of the paper's
//! constants (the fish in paper time is the paper's fish) and is the least invasive
//! change that lets the tail beat at 1–3 Hz: with k = 40 the same step response has
//! t63 = 0.05 s, t90 = 0.07 s (with Δt = 0.0055; with the default Δt = 0.055 both
//! are 0.11 s, two steps, because the command ramps over the first step). The paper's own step, 0.055 paper units, would need
//! k steps per 0.055 s; [`BodyParams::substeps`] = 8 substeps of 0.0069 s
//! (0.275 paper units) are enough: one 0.055 s step (2.2 paper units) damps the tail
//! beat numerically and gives 0.155 body lengths/s at 3 Hz instead of 0.600.
//!
//! # Integration
//! Linearised implicit Euler (Baraff & Witkin 1998), one linear solve per substep:
//! (M + Δt D + Δt² K) Δv = Δt (f₀ − Δt K v₀), v₁ = v₀ + Δv, x₁ = x₀ + Δt v₁,
//! with K = −∂f/∂x of the springs and D = −∂f/∂v of node damping, spring damping and
//! the water (see `hydrodynamics.rs`). The spring block is
//! K_s = c [r̂r̂ᵀ + max(0, 1 − l/‖r‖)(I − r̂r̂ᵀ)]; clamping the transverse term of a
//! compressed spring at zero keeps K positive semi-definite, so the matrix is
//! symmetric positive definite and a banded Cholesky solves it
//! (`banded_cholesky.rs`). Fin forces and the righting couple are explicit (small
//! and smooth).
//!
//! # Cost
//! Measured with `tests::step_cost` (`cargo test --release --lib step_cost --
//! --ignored --nocapture`): native release build, a fish swimming at top speed,
//! minimum of seven batches of 2000 steps, on the development machine (2 cores
//! shared with other builds; the old code measured 187 µs there when quiet and
//! 255–280 µs under load, the earlier note said 26–34 µs per substep).
//!
//! | version | µs per step (8 substeps) | µs per substep |
//! |---------|-------------------------:|---------------:|
//! | before: row-by-row Cholesky over the full band, 3×3 f64 block loops | 187 | 23.4 |
//! | now, exact matrix every substep (default) | 55.5 | 6.9 |
//! | now, [`BodyParams::jacobian_interval`] = 2 | 38.5 | 4.8 |
//! | now, [`BodyParams::jacobian_interval`] = 4 | 29.7 | 3.7 |
//!
//! The default is 3.4× faster with the same scheme. A substep now spends about
//! 45 % factorising, 12 % solving, 12 % on the water and the rest on springs, fins,
//! the righting couple and assembly (perf). What did it: the factorisation follows
//! the envelope of the matrix instead of the full band (9 300 instead of 14 700
//! multiply-adds) and works column-major, a node (three columns) at a time, in
//! contiguous loops the compiler vectorises (`banded_cholesky.rs`); the spring and
//! water arithmetic runs over arrays (four springs or faces at a time), the blocks
//! are added straight into the band with no 3×3 loops, and the solve multiplies by
//! stored reciprocal pivots. Tried and dropped: f32 for the matrix (the tables
//! printed the same, but a factorisation was only 0.2–0.3 µs faster natively and
//! would gain nothing on wasm without SIMD, not worth the lost precision);
//! fixed-length sweeps over zero-padded columns (slower: the compiler no longer
//! vectorised them); tracking the envelope during assembly instead of scanning each
//! column, and a branch-free scan (both measured slower).
//!
//! The arithmetic is reordered (reciprocal pivots, three products summed before the
//! subtraction), so results differ from the old code in the last bits, but the speed
//! table (`tests::speed_table`, all 11 rows to 3 decimals) and the turn table
//! (`tests::turn_table`: key amplitudes to 4 decimals, all measured turns to 0.1°)
//! print exactly as before. Still deterministic: no threads, no clocks, no
//! allocation.
//!
//! # Lagged Jacobian (optional, off by default)
//! [`BodyParams::jacobian_interval`] = n reuses one assembled and factorised matrix
//! for n substeps (a "frozen Jacobian" semi-implicit scheme): every substep still
//! evaluates the forces and the K v₀ term of the right-hand side at its own state,
//! only the matrix (spring directions and lengths, the water's active faces and
//! normals) is up to n − 1 substeps old. Each step starts with a fresh matrix, so
//! steps stay independent. Measured with the tables' own routines:
//!
//! | n | µs per step | top speed at 1 / 3 / 5 Hz (BL/s) | r of the 30/45/60/90° keys | 50° / 75° turn | 135° / 180° sequence |
//! |---|------------:|------------------------------|----------------------------|----------------|----------------------|
//! | 1 | 55.5 | 0.175 / 0.600 / 0.662 | 0.348 / 0.449 / 0.542 / 0.700 | 49.6° / 74.1° | 132.6° / 183.5° |
//! | 2 | 38.5 | 0.175 / 0.592 / 0.642 | 0.353 / 0.460 / 0.560 / 0.717 | 47.7° / 70.8° | 129.0° / 177.2° |
//! | 4 | 29.7 | 0.174 / 0.563 / 0.584 | 0.363 / 0.478 / 0.576 / 0.736 | 45.3° / 67.8° | 123.0° / 168.0° |
//! | 8 | — | diverges | | | |
//!
//! (Measured with the first tail-fin layout, before the fin was braced to ring 4:
//! see `body_layout.rs`.)
//!
//! Stability: with n = 2 and n = 4 every test of `tests.rs` passes, including the
//! ten-minute random run (random speeds, fins and currents every 5 s: finite,
//! spine within ±10 %, no inverted volume, no clamped pivot), and
//! `tests::a_lagged_jacobian_swims_nearly_like_the_exact_one` checks n = 2 (speed
//! within 5 %). With n = 8 (one matrix per step) the solve turns non-finite from
//! 1.5 Hz up, the fish stalls (0.000 BL/s in the speed table) and the random run
//! and four other tests fail. Chosen: n = 1. The exact scheme already meets the
//! budget of about 80 µs per fish-step natively, and the lag slows swimming
//! (n = 2: −1 to −3 % above 2 Hz) and turning (up to −5 %) enough to leave the
//! tuned speed table (`motor_controller.rs`) and steering map (`turn_mc.rs`)
//! slightly off; n = 2 stays available per fish where a third of the cost matters
//! more than that (re-tune both tables if it becomes the default).

use glam::Vec3;
use serde::{Deserialize, Serialize};

use super::banded_cholesky::{BandedCholesky, SYSTEM_SIZE, sym3_outer};
use super::body_layout::{
    HEAD_NODE, MASSES, MUSCLE_COUNT, MUSCLES, NODE_COUNT, PAPER_BODY_LENGTH, REST_POSITIONS,
    RING_COUNT, SPRING_COUNT, SPRINGS, TAIL_FIN_NODES, ring_nodes,
};
use super::hydrodynamics::add_water_forces;
use super::pectoral_fins::PectoralFins;
use crate::sim::paper_time::{FISH_STEP_SECS, PAPER_TIME_UNITS_PER_SEC};

/// Largest accepted [`BodyParams::substeps`].
pub const MAX_SUBSTEPS: u32 = 64;

/// Physical parameters of the body, in paper units (a 26-unit fish); [`FishBody`]
/// scales them by its size (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BodyParams {
    /// Fixed time step, seconds. Default [`FISH_STEP_SECS`] = 0.055 s = 2.2 paper
    /// time units, the length of 40 of the paper's steps (footnote 2: Δt = 0.055
    /// paper units), split into [`Self::substeps`].
    pub dt_secs: f32,
    /// Node damping γ_i, paper units (force per velocity). Default 0.05, paper
    /// footnote 2. Acts on the velocity relative to the water (chosen: a passive fish
    /// drifts with the current).
    pub node_damping: f32,
    /// Damping along each spring, paper units (force per relative velocity).
    /// Default 0.1, the value of the vanish87/UnityFishSimulation re-implementation;
    /// the paper has none. It calms the stiff tail-fin modes.
    pub spring_damping: f32,
    /// Fully contracted muscle rest length as a fraction of the relaxed one
    /// (l_min / l), dimensionless. Default 0.5, tuned (the paper gives no number;
    /// the re-implementation uses 0.7): against the stiffer cross springs a fully
    /// contracted muscle only reaches 0.67 l at 0.5 (0.87 l at 0.7); top swim speed
    /// at 3 Hz is 0.600 body lengths/s at 0.5 and 0.357 at 0.7.
    pub muscle_min_length_ratio: f32,
    /// Factor on the paper's water force f = −A (n·v) n, dimensionless. Default 1.0
    /// (the paper's formula as written).
    pub water_drag_coefficient: f32,
    /// Paper time units per second, k (dimensionless). Default
    /// [`PAPER_TIME_UNITS_PER_SEC`] = 40, the fish world's one clock, tuned here (see the
    /// module doc, "Time scale"): the paper never says its time unit is a second, and
    /// with k = 1 swimming saturates at about 0.15 Hz. Measured top speed at 3 Hz
    /// with 8 substeps: 0.56 (k = 30), 0.60 (k = 40), 0.60 (k = 50) body lengths/s;
    /// k = 20 saturates below 3 Hz (0.014 at 3 Hz, as k = 1 does above 0.15 Hz,
    /// i.e. saturation sits near 0.15·k Hz). Every rate
    /// constant is scaled so that one second here is k paper time units:
    /// stiffness × k², damping, water and fin forces × k, righting couple × k²;
    /// masses and lengths unchanged. A field so that measurements can vary the body's
    /// time scale; the minds always read [`PAPER_TIME_UNITS_PER_SEC`], so a body
    /// run at another k no longer shares their clock.
    pub paper_time_units_per_sec: f32,
    /// Implicit Euler substeps per step, count (clamped to 1..=[`MAX_SUBSTEPS`]).
    /// Default 8, tuned: each substep is 0.0069 s = 0.275 paper time units at the
    /// default k = 40. Top speed at 3 Hz: 0.155 (1 substep), 0.525 (5), 0.600 (8)
    /// body lengths/s. Cost grows linearly (about 7 µs per substep on the
    /// development machine, see the module doc, "Cost", and `tests::step_cost`).
    pub substeps: u32,
    /// Substeps that share one system matrix and its factorisation (a lagged or
    /// "frozen" Jacobian), count, clamped to 1..=`substeps`. Default 1, chosen: every
    /// substep solves with its own exact matrix, the scheme the speed table
    /// (`motor_controller.rs`) and the steering map (`turn_mc.rs`) were tuned with.
    /// Forces and the right-hand side are always evaluated at the current state;
    /// only the matrix is reused. Larger values are cheaper but change the motion
    /// (measured, see the module doc, "Lagged Jacobian"): 2 saves a third of the
    /// cost (38 instead of 56 µs per step) and slows swimming by 0–3 % and turns by
    /// up to 5 %; 4 costs 30 µs, −2 to −12 % and up to −10 %; 8 blows up.
    #[serde(default = "one")]
    pub jacobian_interval: u32,
    /// Strength of the righting couple per ring, paper force units per unit of
    /// sin(tilt). Default 20.0, chosen (not tuned): keeps the fish level and upright
    /// in every test run; without it the body pitches nose-down by about 24° while
    /// swimming. Restores both roll and pitch, so climbing comes from fin lift with
    /// the body level. Stands for the swim bladder above the centre of mass
    /// (neutral buoyancy: no net force, no gravity).
    pub righting_force: f32,
    /// Area of one pectoral fin, paper units². Default 6.0, chosen (about a quarter
    /// of the flank area of one body ring); a ±0.5 rad fin pitch changes the depth by
    /// more than 0.5 % of a body length in 30 s at top swim speed (test).
    pub pectoral_fin_area: f32,
}

impl Default for BodyParams {
    fn default() -> Self {
        Self {
            dt_secs: FISH_STEP_SECS,
            node_damping: 0.05,
            spring_damping: 0.1,
            muscle_min_length_ratio: 0.5,
            water_drag_coefficient: 1.0,
            paper_time_units_per_sec: PAPER_TIME_UNITS_PER_SEC,
            substeps: 8,
            jacobian_interval: 1,
            righting_force: 20.0,
            pectoral_fin_area: 6.0,
        }
    }
}

fn one() -> u32 {
    1
}

/// What the brain sends the body each step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BodyCommand {
    /// Contraction factor u_k in [0, 1] of each muscle (order: `body_layout::MUSCLES`);
    /// 0 = relaxed rest length l, 1 = l_min. Values outside are clamped, NaN is 0.
    pub muscle_contractions: [f32; MUSCLE_COUNT],
    /// Pectoral fin angles.
    pub fins: PectoralFins,
}

/// One simulated fish body. World frame = body frame of the layout after placement
/// (z up); positions in metres, velocities in m/s.
#[derive(Clone, Debug)]
pub struct FishBody {
    positions_m: [Vec3; NODE_COUNT],
    velocities_m_per_s: [Vec3; NODE_COUNT],
    /// Relaxed spring rest lengths, metres.
    rest_lengths_m: [f32; SPRING_COUNT],
    /// Muscle contraction factors in use (after clamping).
    muscle_contractions: [f32; MUSCLE_COUNT],
    params: BodyParams,
    /// s = metres per paper unit.
    metres_per_paper_unit: f32,
    /// Implicit system, allocated once.
    system: Box<BandedCholesky>,
    steps: u64,
}

impl FishBody {
    /// A fish at rest, its centre of mass at `position_m`, its head pointing along
    /// `heading` (any vector; zero means +x), dorsal side as close to +z as possible.
    pub fn new(body_length_m: f32, position_m: Vec3, heading: Vec3) -> Self {
        Self::with_params(body_length_m, position_m, heading, BodyParams::default())
    }

    /// As [`Self::new`] with explicit parameters.
    pub fn with_params(
        body_length_m: f32,
        position_m: Vec3,
        heading: Vec3,
        params: BodyParams,
    ) -> Self {
        let length = if body_length_m.is_finite() && body_length_m > 0.0 {
            body_length_m
        } else {
            1.0
        };
        let s = length / PAPER_BODY_LENGTH;
        let forward = heading.normalize_or_zero();
        let forward = if forward == Vec3::ZERO {
            Vec3::X
        } else {
            forward
        };
        let mut left = Vec3::Z.cross(forward).normalize_or_zero();
        if left == Vec3::ZERO {
            left = Vec3::Y;
        }
        let up = forward.cross(left);
        let total_mass: f32 = MASSES.iter().sum();
        let com_rest: Vec3 = REST_POSITIONS
            .iter()
            .zip(MASSES)
            .map(|(p, m)| *p * m)
            .sum::<Vec3>()
            / total_mass;
        let position_m = if position_m.is_finite() {
            position_m
        } else {
            Vec3::ZERO
        };
        let positions_m = REST_POSITIONS.map(|p| {
            let q = (p - com_rest) * s;
            position_m + forward * q.x + left * q.y + up * q.z
        });
        let rest_lengths_m =
            SPRINGS.map(|sp| REST_POSITIONS[sp.a].distance(REST_POSITIONS[sp.b]) * s);
        Self {
            positions_m,
            velocities_m_per_s: [Vec3::ZERO; NODE_COUNT],
            rest_lengths_m,
            muscle_contractions: [0.0; MUSCLE_COUNT],
            params,
            metres_per_paper_unit: s,
            system: Box::default(),
            steps: 0,
        }
    }

    /// Node positions, metres.
    pub fn positions_m(&self) -> &[Vec3; NODE_COUNT] {
        &self.positions_m
    }

    /// Node velocities, m/s.
    pub fn velocities_m_per_s(&self) -> &[Vec3; NODE_COUNT] {
        &self.velocities_m_per_s
    }

    /// Node positions and velocities for hard constraints applied between steps
    /// (the world keeps every node in the tank and out of rocks). Positions in
    /// metres, velocities in m/s.
    pub fn nodes_mut(&mut self) -> (&mut [Vec3; NODE_COUNT], &mut [Vec3; NODE_COUNT]) {
        (&mut self.positions_m, &mut self.velocities_m_per_s)
    }

    /// Gives every node the same velocity (a rigid launch), m/s; non-finite is ignored.
    pub fn set_uniform_velocity_m_per_s(&mut self, velocity: Vec3) {
        if velocity.is_finite() {
            self.velocities_m_per_s = [velocity; NODE_COUNT];
        }
    }

    /// Parameters (paper units).
    pub fn params(&self) -> &BodyParams {
        &self.params
    }

    /// Rest length of the body (head tip to tail-fin tips), metres.
    pub fn rest_body_length_m(&self) -> f32 {
        PAPER_BODY_LENGTH * self.metres_per_paper_unit
    }

    /// Fixed time step, seconds.
    pub fn dt_secs(&self) -> f32 {
        self.params.dt_secs
    }

    /// Number of steps taken.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Muscle contractions in use, each in [0, 1].
    pub fn muscle_contractions(&self) -> &[f32; MUSCLE_COUNT] {
        &self.muscle_contractions
    }

    /// Node mass in scaled mass units (paper mass × s²).
    pub fn node_mass(&self, node: usize) -> f32 {
        MASSES.get(node).copied().unwrap_or(0.0) * self.mass_scale()
    }

    fn mass_scale(&self) -> f32 {
        self.metres_per_paper_unit * self.metres_per_paper_unit
    }

    /// k = paper time units per second, guarded (non-finite or non-positive → 1).
    fn time_scale(&self) -> f32 {
        let k = self.params.paper_time_units_per_sec;
        if k.is_finite() && k > 0.0 { k } else { 1.0 }
    }

    fn force_scale(&self) -> f32 {
        self.mass_scale() * self.metres_per_paper_unit
    }

    /// Mass-weighted mean position, metres.
    pub fn centre_of_mass_m(&self) -> Vec3 {
        let total: f32 = MASSES.iter().sum();
        self.positions_m
            .iter()
            .zip(MASSES)
            .map(|(p, m)| *p * m)
            .sum::<Vec3>()
            / total
    }

    /// Mass-weighted mean velocity, m/s.
    pub fn velocity_m_per_s(&self) -> Vec3 {
        let total: f32 = MASSES.iter().sum();
        self.velocities_m_per_s
            .iter()
            .zip(MASSES)
            .map(|(v, m)| *v * m)
            .sum::<Vec3>()
            / total
    }

    fn ring_centroid(&self, k: usize) -> Vec3 {
        ring_nodes(k)
            .iter()
            .map(|&i| self.positions_m[i])
            .sum::<Vec3>()
            / 4.0
    }

    /// Unit forward direction of the fore body (ring 3 towards ring 1); zero only if
    /// the body has collapsed.
    pub fn forward(&self) -> Vec3 {
        (self.ring_centroid(0) - self.ring_centroid(2)).normalize_or_zero()
    }

    /// Unit dorsal direction of the fore body, orthogonal to [`Self::forward`].
    pub fn up(&self) -> Vec3 {
        let mut d = Vec3::ZERO;
        for k in 0..3 {
            let [dl, dr, vr, vl] = ring_nodes(k);
            let p = &self.positions_m;
            d += p[dl] + p[dr] - p[vr] - p[vl];
        }
        let f = self.forward();
        (d - d.dot(f) * f).normalize_or_zero()
    }

    /// Is the tail fin folded forward: is a tip of it ahead of the last ring, seen
    /// along the tail section (the fourth ring's centre towards the fifth's)?
    pub fn tail_fin_folded(&self) -> bool {
        let last = self.ring_centroid(RING_COUNT - 1);
        let back = (last - self.ring_centroid(RING_COUNT - 2)).normalize_or_zero();
        TAIL_FIN_NODES
            .iter()
            .any(|&i| (self.positions_m[i] - last).dot(back) < 0.0)
    }

    /// Length along the spine: head tip, the five ring centres, the tail-fin
    /// midpoint. Equals the rest body length at rest, whatever the bend.
    pub fn spine_length_m(&self) -> f32 {
        let mut prev = self.positions_m[HEAD_NODE];
        let mut len = 0.0;
        for k in 0..RING_COUNT {
            let c = self.ring_centroid(k);
            len += prev.distance(c);
            prev = c;
        }
        let tail =
            (self.positions_m[TAIL_FIN_NODES[0]] + self.positions_m[TAIL_FIN_NODES[1]]) / 2.0;
        len + prev.distance(tail)
    }

    /// Current length of every spring divided by its relaxed rest length.
    pub fn spring_strains(&self) -> [f32; SPRING_COUNT] {
        let mut out = [0.0; SPRING_COUNT];
        for (k, sp) in SPRINGS.iter().enumerate() {
            let len = self.positions_m[sp.a].distance(self.positions_m[sp.b]);
            out[k] = len / self.rest_lengths_m[k];
        }
        out
    }

    /// Kinetic energy in scaled units (for tests: comes to rest).
    pub fn kinetic_energy(&self) -> f32 {
        self.velocities_m_per_s
            .iter()
            .zip(MASSES)
            .map(|(v, m)| 0.5 * m * self.mass_scale() * v.length_squared())
            .sum()
    }

    /// Pivots clamped in the last solve; 0 unless the system degenerated.
    pub fn clamped_pivots(&self) -> usize {
        self.system.clamped_pivots
    }

    /// Advances the body by one fixed step Δt = `params.dt_secs`, as
    /// `params.substeps` implicit Euler substeps; the muscle contractions ramp
    /// linearly from the previous command to this one across the substeps.
    /// `water_velocity_m_per_s` is the current at the fish (uniform over the body).
    pub fn step(&mut self, command: &BodyCommand, water_velocity_m_per_s: Vec3) {
        let water = if water_velocity_m_per_s.is_finite() {
            water_velocity_m_per_s
        } else {
            Vec3::ZERO
        };
        let previous = self.muscle_contractions;
        let target = command.muscle_contractions.map(|c| {
            if c.is_finite() {
                c.clamp(0.0, 1.0)
            } else {
                0.0
            }
        });
        let substeps = self.params.substeps.clamp(1, MAX_SUBSTEPS);
        let h = self.params.dt_secs / substeps as f32;
        let interval = self.params.jacobian_interval.clamp(1, substeps);
        for j in 1..=substeps {
            let t = j as f32 / substeps as f32;
            for (u, (a, b)) in self
                .muscle_contractions
                .iter_mut()
                .zip(previous.iter().zip(target))
            {
                *u = a + (b - a) * t;
            }
            let refresh = (j - 1) % interval == 0;
            self.substep(&command.fins, water, h, refresh);
        }
        self.steps += 1;
    }

    /// One linearised implicit Euler step of `h` seconds with the current muscle
    /// contractions. With `refresh` the system matrix is assembled and factorised
    /// anew; otherwise the factorisation of an earlier substep is reused.
    fn substep(&mut self, fins: &PectoralFins, water: Vec3, h: f32, refresh: bool) {
        let h64 = f64::from(h);
        let mass_scale = self.mass_scale();
        let k_time = self.time_scale();
        let force_scale = self.force_scale() * k_time * k_time;
        let stiffness_scale = mass_scale * k_time * k_time;
        let damping_scale = mass_scale * k_time;
        let x = self.positions_m;
        let v = self.velocities_m_per_s;

        // Actuated rest lengths.
        let mut rest = self.rest_lengths_m;
        let shortening = 1.0 - self.params.muscle_min_length_ratio.clamp(0.05, 1.0);
        for (muscle, u) in MUSCLES.iter().zip(self.muscle_contractions) {
            rest[muscle.spring] = self.rest_lengths_m[muscle.spring] * (1.0 - u * shortening);
        }

        let forward = self.forward();
        let up = self.up();
        let fish_velocity = self.velocity_m_per_s();
        let fin_area = self.params.pectoral_fin_area
            * self.metres_per_paper_unit
            * self.metres_per_paper_unit
            * k_time;

        let system = &mut *self.system;
        if refresh {
            system.clear();
        }
        let mut forces = [Vec3::ZERO; NODE_COUNT];
        // K v₀ (for the right-hand side).
        let mut k_v = [Vec3::ZERO; NODE_COUNT];

        // Mass and node damping.
        let gamma = self.params.node_damping * damping_scale;
        for i in 0..NODE_COUNT {
            if refresh {
                let diag = f64::from(MASSES[i] * mass_scale) + h64 * f64::from(gamma);
                for c in 0..3 {
                    system.add_diagonal(3 * i + c, diag);
                }
            }
            forces[i] -= gamma * (v[i] - water);
        }

        // Springs: gathered into arrays, the arithmetic as one loop over the arrays
        // (which the compiler vectorises), then scattered to the nodes.
        let spring_damping = self.params.spring_damping * damping_scale;
        let mut r = [[0.0f32; SPRING_COUNT]; 3];
        let mut w = [[0.0f32; SPRING_COUNT]; 3];
        for (k, sp) in SPRINGS.iter().enumerate() {
            let (d, u) = (x[sp.b] - x[sp.a], v[sp.b] - v[sp.a]);
            [r[0][k], r[1][k], r[2][k]] = d.to_array();
            [w[0][k], w[1][k], w[2][k]] = u.to_array();
        }
        let terms = spring_terms(&r, &w, &rest, stiffness_scale, spring_damping, h);
        for (k, sp) in SPRINGS.iter().enumerate() {
            let dir = Vec3::new(terms.dir[0][k], terms.dir[1][k], terms.dir[2][k]);
            let f = terms.force[k] * dir;
            forces[sp.a] += f;
            forces[sp.b] -= f;
            let kdv = Vec3::new(terms.k_v[0][k], terms.k_v[1][k], terms.k_v[2][k]);
            k_v[sp.a] += kdv;
            k_v[sp.b] -= kdv;
            if refresh {
                let block = sym3_outer(
                    [f64::from(dir.x), f64::from(dir.y), f64::from(dir.z)],
                    f64::from(terms.along[k]),
                    f64::from(terms.across[k]),
                );
                system.add_spring_block(sp.a, sp.b, &block);
            }
        }

        // Water.
        add_water_forces(
            &x,
            &v,
            water,
            self.params.water_drag_coefficient * k_time,
            &mut forces,
            if refresh {
                Some((&mut *system, h64))
            } else {
                None
            },
        );

        // Pectoral fins (explicit), spread over the six midsection nodes of each side.
        let fin_forces = fins.forces(forward, up, fish_velocity - water, fin_area);
        for (side, f) in fin_forces.into_iter().enumerate() {
            for node in PectoralFins::nodes(side) {
                forces[node] += f / 6.0;
            }
        }

        // Righting couple (explicit): pull each ring's dorsal pair towards the world
        // vertical and its ventral pair the other way. Zero net force, zero when
        // level and upright; restores roll and pitch.
        let vertical = Vec3::Z;
        let righting = self.params.righting_force * force_scale;
        for k in 0..RING_COUNT {
            let [dl, dr, vr, vl] = ring_nodes(k);
            let dorsal = (x[dl] + x[dr] - x[vr] - x[vl]).normalize_or_zero();
            let g = righting * (vertical - vertical.dot(dorsal) * dorsal);
            forces[dl] += g;
            forces[dr] += g;
            forces[vr] -= g;
            forces[vl] -= g;
        }

        // Solve (M + hD + h²K) Δv = h (f₀ − h K v₀).
        let mut rhs = [0.0f64; SYSTEM_SIZE];
        for i in 0..NODE_COUNT {
            let b = h * (forces[i] - h * k_v[i]);
            rhs[3 * i] = f64::from(b.x);
            rhs[3 * i + 1] = f64::from(b.y);
            rhs[3 * i + 2] = f64::from(b.z);
        }
        if refresh {
            system.factorize();
        }
        system.solve(&mut rhs);
        for i in 0..NODE_COUNT {
            let dv = Vec3::new(
                rhs[3 * i] as f32,
                rhs[3 * i + 1] as f32,
                rhs[3 * i + 2] as f32,
            );
            let v1 = v[i] + dv;
            // Never let a non-finite value in: keep the old state for that node.
            if v1.is_finite() {
                self.velocities_m_per_s[i] = v1;
                self.positions_m[i] = x[i] + h * v1;
            }
        }
    }
}

/// Per-spring results of [`spring_terms`], one array entry per spring of
/// [`SPRINGS`].
struct SpringTerms {
    /// Unit direction r̂ from node a to node b (zero for a collapsed spring).
    dir: [[f32; SPRING_COUNT]; 3],
    /// Scalar force along r̂ on node a (node b gets the opposite):
    /// c (‖r‖ − l) + d (v_b − v_a)·r̂.
    force: [f32; SPRING_COUNT],
    /// K_s (v_a − v_b) with K_s = c [(1 − t) r̂r̂ᵀ + t I], t = max(0, 1 − l/‖r‖).
    k_v: [[f32; SPRING_COUNT]; 3],
    /// The spring's block of the system matrix, h² K_s + h d r̂r̂ᵀ = along · r̂r̂ᵀ +
    /// across · I: along = h² c (1 − t) + h d, across = h² c t.
    along: [f32; SPRING_COUNT],
    across: [f32; SPRING_COUNT],
}

/// The arithmetic of every spring at once from its vector `r` = x_b − x_a and
/// relative velocity `w` = v_b − v_a (component arrays), `rest` lengths, the
/// stiffness scale, damping `d` and substep `h`. Straight-line code over arrays, so
/// the compiler runs it on four springs at a time.
fn spring_terms(
    r: &[[f32; SPRING_COUNT]; 3],
    w: &[[f32; SPRING_COUNT]; 3],
    rest: &[f32; SPRING_COUNT],
    stiffness_scale: f32,
    d: f32,
    h: f32,
) -> SpringTerms {
    let mut out = SpringTerms {
        dir: [[0.0; SPRING_COUNT]; 3],
        force: [0.0; SPRING_COUNT],
        k_v: [[0.0; SPRING_COUNT]; 3],
        along: [0.0; SPRING_COUNT],
        across: [0.0; SPRING_COUNT],
    };
    for k in 0..SPRING_COUNT {
        let (rx, ry, rz) = (r[0][k], r[1][k], r[2][k]);
        let (wx, wy, wz) = (w[0][k], w[1][k], w[2][k]);
        let len = (rx * rx + ry * ry + rz * rz).sqrt();
        let inverse = 1.0 / len;
        // As `normalize_or_zero`: a zero or non-finite length gives no direction.
        let valid = inverse.is_finite() && inverse > 0.0;
        let inverse = if valid { inverse } else { 0.0 };
        let (dx, dy, dz) = (rx * inverse, ry * inverse, rz * inverse);
        let c = STIFFNESS[k] * stiffness_scale;
        let rel_speed = wx * dx + wy * dy + wz * dz;
        let transverse = if valid {
            (1.0 - rest[k] * inverse).max(0.0)
        } else {
            0.0
        };
        let g = c * (1.0 - transverse) * rel_speed;
        let ct = c * transverse;
        out.dir[0][k] = dx;
        out.dir[1][k] = dy;
        out.dir[2][k] = dz;
        out.force[k] = c * (len - rest[k]) + d * rel_speed;
        out.k_v[0][k] = -(g * dx + ct * wx);
        out.k_v[1][k] = -(g * dy + ct * wy);
        out.k_v[2][k] = -(g * dz + ct * wz);
        out.along[k] = h * h * c * (1.0 - transverse) + h * d;
        out.across[k] = h * h * ct;
    }
    out
}

/// Stiffness of every spring, paper units (footnote 2).
const STIFFNESS: [f32; SPRING_COUNT] = {
    let mut c = [0.0; SPRING_COUNT];
    let mut k = 0;
    while k < SPRING_COUNT {
        c[k] = SPRINGS[k].kind.stiffness();
        k += 1;
    }
    c
};
