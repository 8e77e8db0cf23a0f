//! The dynamic fish: 23 point masses joined by 91 springs, 12 of them muscles,
//! pushed by the water. Tu & Terzopoulos 1994 §3.1 eq. (1)
//! m_i ẍ_i + γ_i ẋ_i − w_i = f^w_i, with w_i = Σ_j c_ij e_ij r_ij/‖r_ij‖, muscles
//! (§3.2) and the water force of `hydrodynamics.rs`, integrated implicitly (BDF2 by
//! default, backward Euler on request; see "Integration").
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
//! t63 = 0.05 s, t90 = 0.07 s (with Δt = 0.0055). The tail-beat frequencies
//! scale with k: at k = 30 the whole speed–frequency curve (`motor_controller.rs`)
//! moves to frequencies 3/4 as high, its collapse from about 4.1 Hz to about
//! 3.1 Hz, so 3 Hz would sit at the collapse (measured while choosing the
//! default). The paper's own step, 0.055 paper units, would need k steps per
//! 0.055 s; [`BodyParams::substeps`] = 12 substeps of 4.6 ms (0.18 paper
//! units) are converged (below).
//!
//! # Integration
//! Linearised BDF2 (second-order backward differentiation), one linear solve per
//! substep of length h. With β = 2h/3, x̂ = (4x₀ − x₋₁)/3, v̂ = (4v₀ − v₋₁)/3 (the
//! state now and one substep back) the scheme is v₁ = v̂ + β M⁻¹ f(x₁, v₁),
//! x₁ = x̂ + β v₁. The forces are linearised around the extrapolated state
//! x* = 2x₀ − x₋₁, v* = 2v₀ − v₋₁, which is within O(h²) of the answer, so the
//! terms that are not implicit (the water's face normals, the spring directions of
//! the damping, the fins and the righting couple) stay second-order accurate:
//! (M + βD + β²K) Δv = M (v̂ − v*) + β (f* − K z), z = x̂ + β v* − x*,
//! v₁ = v* + Δv, x₁ = x̂ + β v₁,
//! with K = −∂f/∂x of the springs and D = −∂f/∂v of node damping, spring damping and
//! the water (see `hydrodynamics.rs`). The first substep of a new body, or after
//! the world moved the nodes from outside (a hard constraint), has no history and
//! is a backward Euler substep (β = h, x̂ = x* = x₀, v̂ = v* = v₀; the scheme of
//! Baraff & Witkin 1998), [`Integrator::BackwardEuler`] uses it throughout. The spring block is
//! K_s = c [r̂r̂ᵀ + max(0, 1 − l/‖r‖)(I − r̂r̂ᵀ)]; clamping the transverse term of a
//! compressed spring at zero keeps K positive semi-definite, so the matrix is
//! symmetric positive definite and a banded Cholesky solves it
//! (`banded_cholesky.rs`). [`BodyParams::jacobian_interval`] = 2 reuses one
//! assembled and factorised matrix for 2 substeps (9.2 ms): every substep still
//! evaluates the forces and the right-hand side at its own state; only the
//! matrix is up to one substep old.
//!
//! The motor controllers are sampled at the end of every substep
//! ([`FishBody::step_with`]): a 3 Hz beat sampled once per 0.055 s step is only six
//! points per period, and the linear ramp between them cuts the wave's corners.
//! [`FishBody::step`] (one command per step, ramped) remains for callers that have
//! only one command per step.
//!
//! # Convergence
//! `tests::convergence_table` (`cargo test --release --lib convergence_table --
//! --ignored --nocapture`): speed at full amplitude (body lengths/s) for each
//! tail-beat frequency, and the heading change of the four key turns of the
//! steering map (`turn_mc.rs`, tuned on the default body) while swimming at the top
//! setting (2.3 Hz), against the scheme, the
//! control sampling and the substeps per 0.055 s step ("matrix every": substeps per
//! factorisation).
//!
//! The whole table is in `docs/fish-body.md` ("Convergence"). In short, with the
//! spring damping of 2.0, the mirror-symmetric skin and the braced tail fin:
//! - The old default (8 backward Euler substeps, one command per step) was far from
//!   converged: the top speed 0.469 body lengths/s against 0.581 at 64 BDF2
//!   substeps, the keys about a third short (90° key: 59.9°).
//! - Backward Euler converges only to first order: at 64 substeps a doubling still
//!   adds 2 % to the speed and 5 % to the 90° turn.
//! - BDF2 with per-substep sampling has the speed converged from 8 substeps on
//!   (0.581–0.587 at 2.3 Hz). From the default, 12 substeps with a matrix every 2,
//!   a doubling (24 substeps, matrix every 4) changes the top speed by 0.5 % and the
//!   30/45/60/90° keys by 1.0 / 0.4 / 2.2 / 1.0 %. `tests::the_default_body_is_converged`
//!   fails if a doubling changes the top speed or a key turn by 3 % or more.
//! - Above 3 Hz the swimming is erratic and not converged (4 Hz: 0.55–0.79 across
//!   resolutions; at 5 Hz the passive tail fails in some runs): the top setting,
//!   2.3 Hz, stays well below.
//!
//! ## Converged is not enough: the held bend's second state
//! With the spring damping of the earlier body, 0.1, a slow fish that steered with a
//! held bend (`turn_mc::add_steering`) could fall into a second, almost motionless
//! state (0.02 m/s instead of 0.1 m/s for a 0.5 m fish at 0.4 of the top speed) and
//! stay there even when the command was then held constant; started from steady
//! swimming, the same command swam on. That state belongs to the equations, not to
//! the integrator: `physical_fish::agility::closed_loop_turn_times` (±90° and ±30°
//! turns from 1.0/0.7/0.4/0.2 of the top speed, three tail-beat phases, 15 s
//! limit) never finished some turns with BDF2 at 16, 64 and 256 substeps and with
//! backward Euler at 256 and 1024, the converged runs agreeing closely; only backward
//! Euler at 64 substeps finished them all (worst 6.3 s), through its numerical
//! damping. The lightly damped springs are the light tail fin's (0.165 mass units on
//! springs of 30: damping 0.1 is 2 % of critical). With spring damping 2.0 (45 % of
//! critical for a tail-fin spring, 5 % for the heaviest nodes) every turn finishes,
//! and the result agrees across resolutions: worst 5.9 s at BDF2 12/1, 5.8 s at
//! 16/2 and 24/4, 5.9 s at 32/4 and 64/1, 6.7 s at 12/2 (biases 0.5/0.5/0.25, the
//! earlier chiral skin; 5.9 s at 12/2 with the symmetric skin); with
//! damping 1.0 the worst was 12.4 s at 64/1, with 0.5 some turns still never
//! finished at 16/2. A matrix older than 2 substeps of
//! 4.6 ms brings the stalls back (12/3 and 16/4, 13.8 ms: never at 0.2 of the top
//! speed), so the matrix stays at most 9.2 ms old. The swimming barely changes
//! (top speed 0.611 → 0.607 body lengths/s; 0.608 with the mirror-symmetric skin).
//!
//! # Cost
//! Measured with `tests::step_cost` (`cargo test --release --lib step_cost --
//! --ignored --nocapture`, a fish swimming at top speed, minimum of seven batches
//! of 2000 steps; set `STEP_COST=bdf2:24:4,euler:8:1` to time other settings),
//! native release build on the development machine shared with another engineer's
//! builds; compare the rows (measured in one run):
//!
//! | scheme | µs per step | µs per substep |
//! |--------|------------:|---------------:|
//! | backward Euler, 8 substeps, matrix every substep (the earlier default) | 47.5 | 5.9 |
//! | BDF2, 12 substeps, matrix every substep | 72.6 | 6.1 |
//! | **BDF2, 12 substeps, matrix every 2 (default)** | **51.7** | 4.3 |
//! | BDF2, 16 substeps, matrix every 2 (the previous default) | 68.8 | 4.3 |
//!
//! The default costs 1.09 times the old body per step. Earlier figures on a busier
//! machine (same code): backward Euler 8/1 60.5 µs, BDF2 16/2 94.2, 24/4 116.1, 32/4
//! 154.9 µs. Reusing the matrix longer is cheaper but not robust (above).
//! A substep with a fresh matrix spends about half its time factorising: the
//! factorisation follows the envelope of the matrix instead of the full band
//! and works column-major, a node (three columns) at a time, in contiguous loops
//! the compiler vectorises (`banded_cholesky.rs`); the spring and water
//! arithmetic runs over arrays (four springs or faces at a time), the blocks are
//! added straight into the band, and the solve multiplies by stored reciprocal
//! pivots. Still deterministic: no threads, no clocks, no allocation.

use std::f32::consts::FRAC_PI_2;

use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::body::banded_cholesky::{BandedCholesky, SYSTEM_SIZE, sym3_outer};
use crate::sim::body::body_layout::{
    HEAD_NODE, MASSES, MUSCLE_COUNT, MUSCLES, NODE_COUNT, PAPER_BODY_LENGTH, REST_POSITIONS,
    RING_COUNT, SPRING_COUNT, SPRINGS, TAIL_FIN_NODES, ring_nodes,
};
use crate::sim::body::hydrodynamics::add_water_forces;
use crate::sim::body::pectoral_fins::PectoralFins;
use crate::sim::common::fmath;
use crate::sim::common::paper_time::{FISH_STEP_SECS, PAPER_TIME_UNITS_PER_SEC};

/// Largest accepted [`BodyParams::substeps`] (1024: enough for convergence checks
/// far beyond the default; it was 64, which silently capped such checks).
pub const MAX_SUBSTEPS: u32 = 1024;

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
    /// Default 2.0, measured (module doc, "Converged is not enough"); the paper has
    /// none, and the vanish87/UnityFishSimulation re-implementation's 0.1 (the
    /// earlier default) leaves the light tail fin's springs at 2 % of critical
    /// damping: a slow fish steering with a held bend could then stall for good.
    /// 2.0 is 45 % of critical on a tail-fin spring and 5 % on the heaviest nodes;
    /// it changes the top speed from 0.611 to 0.607 body lengths/s.
    pub spring_damping: f32,
    /// Fully contracted muscle rest length as a fraction of the relaxed one
    /// (l_min / l), dimensionless. Default 0.5, tuned (the paper gives no number;
    /// the re-implementation uses 0.7): against the stiffer cross springs a fully
    /// contracted muscle only reaches 0.67 l at 0.5 (0.87 l at 0.7); on the earlier,
    /// unconverged body (backward Euler, 8 substeps) the top swim speed at 3 Hz was
    /// 0.600 body lengths/s at 0.5 and 0.357 at 0.7.
    pub muscle_min_length_ratio: f32,
    /// Factor on the paper's water force f = −A (n·v) n, dimensionless. Default 1.0
    /// (the paper's formula as written).
    pub water_drag_coefficient: f32,
    /// Paper time units per second, k (dimensionless). Default
    /// [`PAPER_TIME_UNITS_PER_SEC`] = 40, the fish world's one clock, tuned here (see the
    /// module doc, "Time scale"): the paper never says its time unit is a second, and
    /// with k = 1 swimming saturates at about 0.15 Hz. Measured top speed at 3 Hz
    /// on the earlier body (backward Euler, 8 substeps): 0.56 (k = 30), 0.60
    /// (k = 40), 0.60 (k = 50) body lengths/s;
    /// k = 20 saturates below 3 Hz (0.014 at 3 Hz, as k = 1 does above 0.15 Hz,
    /// i.e. saturation sits near 0.15·k Hz). Every rate
    /// constant is scaled so that one second here is k paper time units:
    /// stiffness × k², damping, water and fin forces × k, righting couple × k²;
    /// masses and lengths unchanged. A field so that measurements can vary the body's
    /// time scale; the minds always read [`PAPER_TIME_UNITS_PER_SEC`], so a body
    /// run at another k no longer shares their clock.
    pub paper_time_units_per_sec: f32,
    /// Implicit substeps per step, count (clamped to 1..=[`MAX_SUBSTEPS`]).
    /// Default 12, measured: each substep is 4.6 ms = 0.18 paper time units at
    /// the default k = 40, and doubling them (with the matrix as fresh in time)
    /// changes the top speed by less than 0.1 % and the key turns by at most 1.7 %
    /// (module doc, "Convergence"). Cost grows about linearly (module doc, "Cost").
    pub substeps: u32,
    /// Substeps that share one system matrix and its factorisation (a lagged or
    /// "frozen" Jacobian), count, clamped to 1..=`substeps`. Default 2, measured:
    /// one factorisation per 9.2 ms; forces and the right-hand side are always
    /// evaluated at the current state, only the matrix is reused, and the speed and
    /// key turns stay within 1 % of a fresh matrix every substep (module doc,
    /// "Convergence"). Keep the matrix younger than about 10 ms when changing
    /// `substeps`: at 13.8 ms (12 substeps with 3 per matrix, 16 with 4) slow fish
    /// steering with a held bend stall again (module doc, "Converged is not enough").
    #[serde(default = "one")]
    pub jacobian_interval: u32,
    /// The implicit scheme of each substep. Default [`Integrator::Bdf2`], chosen:
    /// second order, converged at 12 substeps where backward Euler is not at 64
    /// (module doc, "Convergence").
    #[serde(default)]
    pub integrator: Integrator,
    /// Strength of the righting couple per ring, paper force units per unit of
    /// sin(tilt). Default 20.0, chosen (not tuned): keeps the fish level and upright
    /// in every test run; without it the body pitches nose-down by about 24° while
    /// swimming. Restores roll, and pitch towards the fin trim (`fin_trim_gain`):
    /// level for flat fins. Stands for the swim bladder above the centre of mass
    /// (neutral buoyancy: no net force, no gravity).
    pub righting_force: f32,
    /// Area of one pectoral fin, paper units². Default 6.0, chosen (about a quarter
    /// of the flank area of one body ring); a ±0.5 rad fin pitch changes the depth by
    /// more than 0.5 % of a body length in 30 s at top swim speed (test).
    pub pectoral_fin_area: f32,
    /// Fin trim: body pitch per radian of the two fins' mean pitch, dimensionless,
    /// for fins that trim ([`PectoralFins::climb`], the reef's minds climbing or
    /// diving). Default 1.0, chosen. The righting couple holds the body at this
    /// pitch (nose up for fins pitched up) instead of level. Stands for the fins'
    /// own pitching moment, which in a real fish tilts the body: in this body the
    /// fins act too close to the centre of mass to tilt it against the righting
    /// couple (under 1° at 0.5 rad; `docs/fish-body.md`), and lift alone climbs
    /// about 1 cm/s, so a muscle fish circled food half a metre above or below
    /// it. 0 restores the level body.
    #[serde(default = "default_fin_trim_gain")]
    pub fin_trim_gain: f32,
    /// Largest trim, radians. Default 0.7 (40°), chosen: the steepest fins of
    /// the reef, a food chase's (`MotorChoiceParams::forage_max_fin_pitch_rad`;
    /// the other chases pitch them at most 0.5). Trims beyond
    /// `instant_trim_rad` change at most `max_trim_rate_rad_per_s`: without
    /// that limit, muscle fish of the default reef folded their tail fins at
    /// 0.7 (28 fold samples, seeds 1–40 × 132 s) and blew up at 0.8 and 1.0
    /// (docs/fish-body.md, "Foraging agility").
    #[serde(default = "default_max_trim_rad")]
    pub max_trim_rad: f32,
    /// Trims up to this, radians, follow the fins at once; the part of a
    /// trim beyond it builds up and dies away at most
    /// `max_trim_rate_rad_per_s`. Default 0.5, chosen: the trims every
    /// gait but a food chase asks for, which behave as before the limit
    /// (limiting every trim at 2 rad/s changed which seed of *School meets
    /// obstacle* rejoins behind the pillar, and which prey the shark takes).
    #[serde(default = "default_instant_trim_rad")]
    pub instant_trim_rad: f32,
    /// Fastest change of the part of the trim beyond `instant_trim_rad`,
    /// radians per second; 0 = no limit. Default 2.0, chosen: a steep trim
    /// builds up in a tenth of a second, and a switch from a steep climb to a
    /// steep dive no longer swings the righting couple's target by 80° in one
    /// step. Default reef, seeds 1–40 × 132 s, trims up to 0.7: no fold (28
    /// fold samples without the limit); *Feeding*, seeds 1–16: 420 / 956
    /// plankton in 60 / 132 s (416 / 997 without, 379 / 906 at 1 rad/s).
    #[serde(default = "default_max_trim_rate_rad_per_s")]
    pub max_trim_rate_rad_per_s: f32,
}

fn default_fin_trim_gain() -> f32 {
    1.0
}

fn default_instant_trim_rad() -> f32 {
    0.5
}

fn default_max_trim_rate_rad_per_s() -> f32 {
    2.0
}

fn default_max_trim_rad() -> f32 {
    0.7
}

impl Default for BodyParams {
    fn default() -> Self {
        Self {
            dt_secs: FISH_STEP_SECS,
            node_damping: 0.05,
            spring_damping: 2.0,
            muscle_min_length_ratio: 0.5,
            water_drag_coefficient: 1.0,
            paper_time_units_per_sec: PAPER_TIME_UNITS_PER_SEC,
            substeps: 12,
            jacobian_interval: 2,
            integrator: Integrator::Bdf2,
            righting_force: 20.0,
            pectoral_fin_area: 6.0,
            fin_trim_gain: default_fin_trim_gain(),
            max_trim_rad: default_max_trim_rad(),
            instant_trim_rad: default_instant_trim_rad(),
            max_trim_rate_rad_per_s: default_max_trim_rate_rad_per_s(),
        }
    }
}

fn one() -> u32 {
    1
}

/// The implicit scheme of a substep (see the module doc, "Integration").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Integrator {
    /// Linearised implicit (backward) Euler: first order, strongly damping.
    BackwardEuler,
    /// Linearised second-order backward differentiation (BDF2): second order, still
    /// L-stable; one linear solve per substep like backward Euler. Needs the state
    /// one substep back; the first substep after a change from outside (a new body,
    /// a hard constraint moving nodes) is a backward Euler substep.
    #[default]
    Bdf2,
}

/// The state one substep before the current one, for BDF2, and the current state
/// it belongs to (if the nodes were moved from outside since, it is stale).
#[derive(Clone, Debug)]
struct History {
    previous_positions_m: [Vec3; NODE_COUNT],
    previous_velocities_m_per_s: [Vec3; NODE_COUNT],
    positions_m: [Vec3; NODE_COUNT],
    velocities_m_per_s: [Vec3; NODE_COUNT],
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
    /// β of the factorised matrix M + βD + β²K (0: none yet).
    system_beta: f32,
    /// For BDF2 (see [`History`]).
    history: Option<Box<History>>,
    steps: u64,
    /// The part of the trim beyond `params.instant_trim_rad`, radians (nose
    /// up positive), which follows the fins at most
    /// `params.max_trim_rate_rad_per_s`.
    trim_excess_rad: f32,
    /// How many times the body was torn and rebuilt ([`Self::is_torn`]).
    mends: u32,
}

/// The longest spine of a whole body, as a share of its rest length; a body
/// stretched further is torn ([`FishBody::is_torn`]). Chosen: swimming, turning,
/// braking and climbing bodies stay at 0.8–1.0 of their length (`docs/fish-body.md`);
/// the bodies that blew up in the steep-trim trials stretched to 1.2–1.5 for
/// seconds first.
pub const TORN_SPINE_RATIO: f32 = 1.3;

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
            system_beta: 0.0,
            history: None,
            steps: 0,
            trim_excess_rad: 0.0,
            mends: 0,
        }
    }

    /// Is the body torn: its spine longer than [`TORN_SPINE_RATIO`] of its rest
    /// length (or not a number)? A torn body does not heal: its springs hold it
    /// in a wrong shape, and it goes on stretching until it blows up.
    pub fn is_torn(&self) -> bool {
        let spine = self.spine_length_m();
        spine.is_nan() || spine > TORN_SPINE_RATIO * self.rest_body_length_m()
    }

    /// How many times the body was torn and rebuilt.
    pub fn mends(&self) -> u32 {
        self.mends
    }

    /// Rebuilds a body torn in the last step at rest, upright, where its
    /// centre of mass would be had it moved on at `before`'s velocity (the
    /// whole body's state at the start of the step: centre of mass, heading,
    /// mean velocity), heading as it did then and moving as a whole at that
    /// velocity if it was under two body lengths a second (else at rest). A
    /// safety net: no shipped setting tears a body (`docs/fish-body.md`).
    fn mend(&mut self, before: (Vec3, Vec3, Vec3)) {
        let (at, heading, v) = before;
        let length = self.rest_body_length_m();
        let v = if v.is_finite() && v.length() < 2.0 * length {
            v
        } else {
            Vec3::ZERO
        };
        let mut fresh =
            Self::with_params(length, at + v * self.params.dt_secs, heading, self.params);
        fresh.set_uniform_velocity_m_per_s(v);
        fresh.muscle_contractions = self.muscle_contractions;
        fresh.steps = self.steps;
        fresh.mends = self.mends + 1;
        *self = fresh;
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

    /// Parameters, to change in tests and measurement scripts.
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn params_mut(&mut self) -> &mut BodyParams {
        &mut self.params
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
    /// `params.substeps` implicit substeps; the muscle contractions ramp
    /// linearly from the previous command to this one across the substeps (for a
    /// caller that knows one command per step; [`Self::step_with`] samples the
    /// controller at every substep).
    /// `water_velocity_m_per_s` is the current at the fish (uniform over the body).
    pub fn step(&mut self, command: &BodyCommand, water_velocity_m_per_s: Vec3) {
        let previous = self.muscle_contractions;
        let target = command.muscle_contractions.map(sanitize_contraction);
        let dt = self.params.dt_secs;
        self.step_with(&command.fins, water_velocity_m_per_s, |t| {
            let a = if dt > 0.0 {
                (t / dt).clamp(0.0, 1.0)
            } else {
                1.0
            };
            let mut u = previous;
            for (u, b) in u.iter_mut().zip(target) {
                *u += (b - *u) * a;
            }
            u
        });
    }

    /// Advances the body by one fixed step Δt = `params.dt_secs`, as
    /// `params.substeps` implicit substeps, asking `muscles_at(t)` for the muscle
    /// contractions at the end of each substep, t seconds after the start of the
    /// step (0 < t ≤ Δt). Values are clamped to [0, 1], NaN is 0.
    pub fn step_with(
        &mut self,
        fins: &PectoralFins,
        water_velocity_m_per_s: Vec3,
        mut muscles_at: impl FnMut(f32) -> [f32; MUSCLE_COUNT],
    ) {
        let water = if water_velocity_m_per_s.is_finite() {
            water_velocity_m_per_s
        } else {
            Vec3::ZERO
        };
        let substeps = self.params.substeps.clamp(1, MAX_SUBSTEPS);
        let h = self.params.dt_secs / substeps as f32;
        let interval = self.params.jacobian_interval.clamp(1, substeps);
        let bdf2 = self.params.integrator == Integrator::Bdf2;
        // BDF2 continues from the last substep only if nobody moved the nodes since.
        let mut previous = match self.history.take() {
            Some(hist)
                if bdf2
                    && hist.positions_m == self.positions_m
                    && hist.velocities_m_per_s == self.velocities_m_per_s =>
            {
                Some((hist.previous_positions_m, hist.previous_velocities_m_per_s))
            }
            _ => None,
        };
        let trim_rad = self.trim(fins);
        let before = (
            self.centre_of_mass_m(),
            self.forward(),
            self.velocity_m_per_s(),
        );
        for j in 1..=substeps {
            self.muscle_contractions = muscles_at(j as f32 * h).map(sanitize_contraction);
            let now = (self.positions_m, self.velocities_m_per_s);
            let beta = if previous.is_some() { 2.0 * h / 3.0 } else { h };
            let refresh = (j - 1) % interval == 0 || beta != self.system_beta;
            self.substep(fins, trim_rad, water, h, refresh, previous.as_ref());
            if bdf2 {
                previous = Some(now);
            }
        }
        if let Some((x, v)) = previous {
            self.history = Some(Box::new(History {
                previous_positions_m: x,
                previous_velocities_m_per_s: v,
                positions_m: self.positions_m,
                velocities_m_per_s: self.velocities_m_per_s,
            }));
        }
        self.steps += 1;
        if self.is_torn() {
            self.mend(before);
        }
    }

    /// The trim for this step with `fins`, radians: the part up to
    /// `params.instant_trim_rad` at once, the rest moved at most
    /// `params.max_trim_rate_rad_per_s` × Δt towards what the fins ask
    /// ([`fin_trim_target`]). A steep climb's trim switched from nose up to nose
    /// down from one step to the next (a fish flickering between eating and
    /// avoiding, or a chase braking) rocked the body until its tail fin folded
    /// (`docs/fish-body.md`, "Foraging agility").
    fn trim(&mut self, fins: &PectoralFins) -> f32 {
        let p = &self.params;
        let target = fin_trim_target(fins, p.fin_trim_gain, p.max_trim_rad);
        let instant = p.instant_trim_rad.abs();
        let prompt = target.clamp(-instant, instant);
        let wanted = target - prompt;
        let rate = p.max_trim_rate_rad_per_s;
        let excess = if rate.is_finite() && rate > 0.0 && p.dt_secs > 0.0 {
            let most = rate * p.dt_secs;
            self.trim_excess_rad + (wanted - self.trim_excess_rad).clamp(-most, most)
        } else {
            wanted
        };
        self.trim_excess_rad = if excess.is_finite() { excess } else { 0.0 };
        prompt + self.trim_excess_rad
    }

    /// One linearised implicit substep of `h` seconds with the current muscle
    /// contractions: backward Euler, or BDF2 when `previous` (the state one substep
    /// back) is given. With `refresh` the system matrix is assembled and factorised
    /// anew; otherwise the factorisation of an earlier substep is reused.
    fn substep(
        &mut self,
        fins: &PectoralFins,
        trim_rad: f32,
        water: Vec3,
        h: f32,
        refresh: bool,
        previous: Option<&([Vec3; NODE_COUNT], [Vec3; NODE_COUNT])>,
    ) {
        // β multiplies the forces in both schemes: h for backward Euler, 2h/3 for
        // BDF2 (see the module doc).
        let beta = if previous.is_some() { 2.0 * h / 3.0 } else { h };
        let h64 = f64::from(beta);
        let mass_scale = self.mass_scale();
        let k_time = self.time_scale();
        let force_scale = self.force_scale() * k_time * k_time;
        let stiffness_scale = mass_scale * k_time * k_time;
        let damping_scale = mass_scale * k_time;
        // The state now (x₀, v₀), and the point (x*, v*) the forces are evaluated
        // and linearised at: the state now for backward Euler, the extrapolation
        // 2 y₀ − y₋₁ for BDF2 (see the module doc, "Integration").
        let (x0, v0) = (self.positions_m, self.velocities_m_per_s);
        let (x, v) = match previous {
            Some((xp, vp)) => (
                std::array::from_fn(|i| 2.0 * x0[i] - xp[i]),
                std::array::from_fn(|i| 2.0 * v0[i] - vp[i]),
            ),
            None => (x0, v0),
        };
        // Read by `forward`, `up` and `velocity_m_per_s` below.
        self.positions_m = x;
        self.velocities_m_per_s = v;
        // Where the new position starts from (x̂), the vector K is applied to on the
        // right-hand side (z) and the momentum term (m): backward Euler x̂ = x₀,
        // z = h v₀, m = 0; BDF2 x̂ = (4x₀ − x₋₁)/3, z = x̂ + β v* − x*,
        // m = (4v₀ − v₋₁)/3 − v*.
        let (x_hat, z, momentum): ([Vec3; NODE_COUNT], [Vec3; NODE_COUNT], [Vec3; NODE_COUNT]) =
            match previous {
                Some((xp, vp)) => {
                    let x_hat: [Vec3; NODE_COUNT] =
                        std::array::from_fn(|i| (4.0 * x0[i] - xp[i]) / 3.0);
                    (
                        x_hat,
                        std::array::from_fn(|i| x_hat[i] + beta * v[i] - x[i]),
                        std::array::from_fn(|i| (4.0 * v0[i] - vp[i]) / 3.0 - v[i]),
                    )
                }
                None => (x0, v0.map(|v| h * v), [Vec3::ZERO; NODE_COUNT]),
            };

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
        // K z (for the right-hand side).
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
        let mut y = [[0.0f32; SPRING_COUNT]; 3];
        for (k, sp) in SPRINGS.iter().enumerate() {
            let (d, u) = (x[sp.b] - x[sp.a], v[sp.b] - v[sp.a]);
            [r[0][k], r[1][k], r[2][k]] = d.to_array();
            [w[0][k], w[1][k], w[2][k]] = u.to_array();
            [y[0][k], y[1][k], y[2][k]] = (z[sp.b] - z[sp.a]).to_array();
        }
        let terms = spring_terms(&r, &w, &y, &rest, stiffness_scale, spring_damping, beta);
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

        // Righting couple (explicit): pull each ring's dorsal pair towards the
        // trimmed vertical (the world vertical tilted back by the fin trim, so
        // the body pitches nose up for fins pitched up) and its ventral pair the
        // other way. Zero net force, zero when upright at the trim; restores roll
        // and pitch.
        let vertical = trimmed_vertical(forward, trim_rad);
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

        // Solve (M + βD + β²K) Δv = M (v₀ − v₋₁)/3 + β (f₀ − K z) (the first term
        // only for BDF2).
        let mut rhs = [0.0f64; SYSTEM_SIZE];
        for i in 0..NODE_COUNT {
            let b = beta * (forces[i] - k_v[i]) + MASSES[i] * mass_scale * momentum[i];
            rhs[3 * i] = f64::from(b.x);
            rhs[3 * i + 1] = f64::from(b.y);
            rhs[3 * i + 2] = f64::from(b.z);
        }
        if refresh {
            system.factorize();
            self.system_beta = beta;
        }
        system.solve(&mut rhs);
        for i in 0..NODE_COUNT {
            let dv = Vec3::new(
                rhs[3 * i] as f32,
                rhs[3 * i + 1] as f32,
                rhs[3 * i + 2] as f32,
            );
            let v1 = v[i] + dv;
            let x1 = x_hat[i] + beta * v1;
            // Never let a non-finite value in: keep the old state for that node.
            if v1.is_finite() && x1.is_finite() {
                self.velocities_m_per_s[i] = v1;
                self.positions_m[i] = x1;
            } else {
                self.velocities_m_per_s[i] = v0[i];
                self.positions_m[i] = x0[i];
            }
        }
    }
}

/// The direction the righting couple pulls the back towards, body frame (z up):
/// the world vertical, tilted back by `trim_rad` in the vertical plane of the
/// heading, so that a body at rest in it pitches nose up by the trim. Level for
/// no trim, a vertical heading or non-finite input.
fn trimmed_vertical(forward: Vec3, trim_rad: f32) -> Vec3 {
    let level = Vec3::new(forward.x, forward.y, 0.0).normalize_or_zero();
    if trim_rad == 0.0 || !trim_rad.is_finite() || level == Vec3::ZERO {
        return Vec3::Z;
    }
    fmath::cos(trim_rad) * Vec3::Z - fmath::sin(trim_rad) * level
}

/// The trim `fins` ask for, radians: their mean pitch × `gain`, within
/// ±`max_rad`; 0 for fins that do not trim or non-finite input.
fn fin_trim_target(fins: &PectoralFins, gain: f32, max_rad: f32) -> f32 {
    let fin_pitch = 0.5 * (fins.left_angle_rad + fins.right_angle_rad) - FRAC_PI_2;
    let trim = (gain * fin_pitch).clamp(-max_rad.abs(), max_rad.abs());
    if !fins.trim || !trim.is_finite() {
        return 0.0;
    }
    trim
}

/// Per-spring results of [`spring_terms`], one array entry per spring of
/// [`SPRINGS`].
struct SpringTerms {
    /// Unit direction r̂ from node a to node b (zero for a collapsed spring).
    dir: [[f32; SPRING_COUNT]; 3],
    /// Scalar force along r̂ on node a (node b gets the opposite):
    /// c (‖r‖ − l) + d (v_b − v_a)·r̂.
    force: [f32; SPRING_COUNT],
    /// K_s (z_a − z_b) with K_s = c [(1 − t) r̂r̂ᵀ + t I], t = max(0, 1 − l/‖r‖).
    k_v: [[f32; SPRING_COUNT]; 3],
    /// The spring's block of the system matrix, β² K_s + β d r̂r̂ᵀ = along · r̂r̂ᵀ +
    /// across · I: along = β² c (1 − t) + β d, across = β² c t.
    along: [f32; SPRING_COUNT],
    across: [f32; SPRING_COUNT],
}

/// The arithmetic of every spring at once from its vector `r` = x_b − x_a,
/// relative velocity `w` = v_b − v_a and `y` = z_b − z_a of the vector K is
/// applied to (component arrays), `rest` lengths, the stiffness scale, damping `d`
/// and the scheme's β (h for backward Euler). Straight-line code over arrays, so
/// the compiler runs it on four springs at a time.
fn spring_terms(
    r: &[[f32; SPRING_COUNT]; 3],
    w: &[[f32; SPRING_COUNT]; 3],
    y: &[[f32; SPRING_COUNT]; 3],
    rest: &[f32; SPRING_COUNT],
    stiffness_scale: f32,
    d: f32,
    beta: f32,
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
        let (yx, yy, yz) = (y[0][k], y[1][k], y[2][k]);
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
        let g = c * (1.0 - transverse) * (yx * dx + yy * dy + yz * dz);
        let ct = c * transverse;
        out.dir[0][k] = dx;
        out.dir[1][k] = dy;
        out.dir[2][k] = dz;
        out.force[k] = c * (len - rest[k]) + d * rel_speed;
        out.k_v[0][k] = -(g * dx + ct * yx);
        out.k_v[1][k] = -(g * dy + ct * yy);
        out.k_v[2][k] = -(g * dz + ct * yz);
        out.along[k] = beta * beta * c * (1.0 - transverse) + beta * d;
        out.across[k] = beta * beta * ct;
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

/// A muscle contraction clamped to [0, 1]; NaN is 0.
fn sanitize_contraction(c: f32) -> f32 {
    if c.is_finite() {
        c.clamp(0.0, 1.0)
    } else {
        0.0
    }
}
