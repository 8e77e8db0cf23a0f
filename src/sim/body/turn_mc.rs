//! The turn motor controllers, Tu & Terzopoulos 1994 §3.3: turn-MC(angle) →
//! {r0, s0, r1, s1}, the contraction amplitude r and rate s of the anterior (0) and
//! posterior (1) turning segments (here the anterior and middle muscle segments, see
//! `body_layout.rs`). "A left turn is achieved by quickly contracting the left side
//! springs of the segments and relaxing those on the right side. … Then the
//! contracted springs are restored to their rest lengths at a slower rate, so that
//! the fish regains its original shape with minimal further change in
//! orientation."
//!
//! Contraction profile of one segment on the turning side (the other side relaxed):
//! u(t) = s·t up to the amplitude r (reached at t = r/s), then down at the slower rate
//! q·s to 0, q = [`TurnMc::restore_rate_ratio`]. A right turn is the mirror image.
//!
//! # Steering map (paper: "4 sets of parameters … interpolated … any angle up to 90°")
//! Four key sets for 30°, 45°, 60° and 90° were found by [`find_steering_map`]
//! (reproduce: `cargo run --release --bin shoal-census -- turn-table`) and are
//! stored in [`SteeringMap::DEFAULT`]. Angles in between are linear interpolation of
//! the parameters between neighbouring keys (and from zero below 30°); larger turns are
//! sequences of turns of at most 90° each ([`TurnMc::start_turn`]).
//! The measurement ([`measure_turn_deg`], [`measure_heading_change_deg`]): a default
//! 26-unit fish swims straight at top speed for [`TURN_LEAD_IN_SECS`], executes the
//! turn while the swim-MC keeps beating ([`combine_swim_and_turn`]), then swims
//! straight for [`TURN_SETTLE_SECS`]; the turn angle is the change of the fore
//! body's horizontal heading, averaged over one second (three tail beats) before
//! the turn and at the end.
//!
//! Why the turn is measured while swimming and the turn adds to the swim wave
//! ([`combine_swim_and_turn`]): at the body's time scale (k = 40, see `fish_body.rs`)
//! a gliding fish loses most of its speed within a fraction of a second, so there
//! is almost no momentum to deflect, and with linear drag a bend that is undone
//! turns a gliding fish very little however fast it is made. The turn comes from
//! the tail's thrust acting on a bent body, so the angle grows with r and with the
//! time spent bent. With the slow restoring stroke (1/20 of the contraction rate)
//! that time is r/s·(1 + 20).
//!
//! Measured on the default (converged) body with the braced tail fin,
//! census `turn-table`, each turn's quick stroke timed to the beat
//! ([`KEY_BEAT_PHASE_RAD`]):
//!
//! | key angle | r0 = r1 | s0 = s1 (1/s) | duration (s) | measured (left) |
//! |-----------|---------|---------------|--------------|-----------------|
//! | 30°       | 0.3529  | 2.0           | 3.7          | 30.0°           |
//! | 45°       | 0.4698  | 2.0           | 4.9          | 46.1°           |
//! | 60°       | 0.5561  | 2.0           | 5.8          | 59.9°           |
//! | 90°       | 0.7160  | 2.0           | 7.5          | 89.5°           |
//!
//! [`SteeringMap::DEFAULT`] keeps the 45°, 60° and 90° keys (0.5559 for 60°,
//! from an earlier run of the same search: 60.0°) and takes a larger 30° key,
//! r = 0.3701, bisected on the turn averaged over 0.3, 0.6 and 1.0 of the top
//! speed (see there). Interpolated (measured left/right): 10° → 13.0/−13.0,
//! 20° → 22.7/−22.5, 35° → 37.6/−37.2, 50° → 48.0/−48.1, 75° → 73.2/−73.5.
//! Sequences: 135° requested → 133.5°, 180° → 181.2°. Doubling the body's time
//! resolution changes the key turns by under 3 % (`fish_body.rs`,
//! "Convergence"). On the earlier, unconverged body (backward Euler, controllers
//! sampled once per step) the same keys turn about 28 % less.

use crate::sim::common::fmath;
use serde::{Deserialize, Serialize};
use std::f32::consts::{FRAC_PI_2, PI, TAU};

use crate::sim::body::body_layout::{MUSCLE_COUNT, MuscleSegment, Side, muscle_index};
use crate::sim::body::motor_bridge::MotorParams;
use crate::sim::body::motor_controller::ControlSampling;

/// Straight swimming before a measured turn, seconds. 3.0, chosen: the fish is at
/// its top speed after about 1 s.
pub const TURN_LEAD_IN_SECS: f32 = 3.0;
/// Straight swimming after the contraction profile ends before the heading is read,
/// seconds. 2.0, chosen: the body is straight again and swims on a steady heading.
pub const TURN_SETTLE_SECS: f32 = 2.0;
/// Window over which the heading is averaged, seconds. 1.0 = 2.3 tail beats at
/// the top swim frequency of 2.3 Hz.
pub const HEADING_AVERAGE_SECS: f32 = 1.0;
/// Largest angle of a single turn, degrees (paper §3.3); larger requests become
/// sequences.
pub const MAX_SINGLE_TURN_DEG: f32 = 90.0;

/// Which way to turn (seen from above, the fish's own left or right).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum TurnDirection {
    /// Head swings towards +y of the body frame (counter-clockwise from above).
    Left,
    /// The mirror image.
    Right,
}

/// Amplitudes (contraction factor, [0, 1]) and quick contraction rates (contraction
/// factor per second) of the two turning segments.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TurnParams {
    /// r0: anterior turning segment amplitude, [0, 1].
    pub anterior_amplitude: f32,
    /// s0: anterior turning segment contraction rate, 1/s.
    pub anterior_rate_per_sec: f32,
    /// r1: posterior turning (= middle muscle) segment amplitude, [0, 1].
    pub posterior_amplitude: f32,
    /// s1: posterior turning segment contraction rate, 1/s.
    pub posterior_rate_per_sec: f32,
}

impl TurnParams {
    /// No turn.
    pub const ZERO: Self = Self {
        anterior_amplitude: 0.0,
        anterior_rate_per_sec: 0.0,
        posterior_amplitude: 0.0,
        posterior_rate_per_sec: 0.0,
    };

    /// Componentwise linear interpolation, `t` in [0, 1].
    pub fn lerp(&self, other: &Self, t: f32) -> Self {
        let l = |a: f32, b: f32| a + (b - a) * t;
        Self {
            anterior_amplitude: l(self.anterior_amplitude, other.anterior_amplitude),
            anterior_rate_per_sec: l(self.anterior_rate_per_sec, other.anterior_rate_per_sec),
            posterior_amplitude: l(self.posterior_amplitude, other.posterior_amplitude),
            posterior_rate_per_sec: l(self.posterior_rate_per_sec, other.posterior_rate_per_sec),
        }
    }

    /// Contraction of one segment `t_secs` after the start of the turn.
    fn contraction(amplitude: f32, rate_per_sec: f32, restore_ratio: f32, t_secs: f32) -> f32 {
        let r = sanitize(amplitude).clamp(0.0, 1.0);
        let s = sanitize(rate_per_sec).max(0.0);
        if r <= 0.0 || s <= 0.0 {
            return 0.0;
        }
        let rise_secs = r / s;
        if t_secs <= rise_secs {
            return (s * t_secs).clamp(0.0, r);
        }
        let q = sanitize(restore_ratio).clamp(1e-3, 1.0);
        (r - q * s * (t_secs - rise_secs)).max(0.0)
    }

    /// Time until both segments are relaxed again, seconds.
    pub fn duration_secs(&self, restore_ratio: f32) -> f32 {
        let q = sanitize(restore_ratio).clamp(1e-3, 1.0);
        let one = |r: f32, s: f32| {
            let (r, s) = (sanitize(r).clamp(0.0, 1.0), sanitize(s).max(0.0));
            if r <= 0.0 || s <= 0.0 {
                0.0
            } else {
                r / s + r / (q * s)
            }
        };
        one(self.anterior_amplitude, self.anterior_rate_per_sec)
            .max(one(self.posterior_amplitude, self.posterior_rate_per_sec))
    }
}

fn sanitize(x: f32) -> f32 {
    if x.is_finite() { x } else { 0.0 }
}

/// The four key turns and their parameters: turn-MC(angle) by interpolation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SteeringMap {
    /// (turn angle in degrees, parameters), in increasing angle.
    pub keys: [(f32, TurnParams); 4],
}

impl SteeringMap {
    /// The key sets found by [`find_steering_map`] (see the module doc), except
    /// the 30° key: found at full thrust (r = 0.3543) it turned 26.6° from 0.3 of
    /// the top speed, so it is bisected instead on its turn averaged over 0.3, 0.6
    /// and 1.0 of the top speed (census `keys-over-swim-speeds`:
    /// 29.6° / 30.0° / 30.4°). The other keys already hold within 2 % that way.
    pub const DEFAULT: Self = Self {
        keys: [
            (30.0, key(0.3701)),
            (45.0, key(0.4698)),
            (60.0, key(0.5559)),
            (90.0, key(0.7160)),
        ],
    };

    /// turn-MC(angle): parameters for a turn of `angle_deg` (absolute value, clamped to
    /// [0, 90]; NaN is 0), interpolated linearly between neighbouring keys and from
    /// [`TurnParams::ZERO`] at 0°. Below the first key amplitude and rate shrink
    /// together, so a small turn keeps the 30° turn's duration with a shallower bend
    /// (measured 10° → 10.9°, 20° → 20.9°).
    pub fn params_for_angle(&self, angle_deg: f32) -> TurnParams {
        let a = sanitize(angle_deg).abs().min(MAX_SINGLE_TURN_DEG);
        let mut lo = (0.0, TurnParams::ZERO);
        for (deg, p) in self.keys {
            if a <= deg {
                let span = deg - lo.0;
                let t = if span > 0.0 { (a - lo.0) / span } else { 1.0 };
                return lo.1.lerp(&p, t);
            }
            lo = (deg, p);
        }
        lo.1
    }
}

impl Default for SteeringMap {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// The key-set family searched by [`find_steering_map`]: both turning segments with
/// amplitude `r` and the common quick rate [`KEY_RATE_PER_SEC`].
pub(crate) const fn key(r: f32) -> TurnParams {
    TurnParams {
        anterior_amplitude: r,
        anterior_rate_per_sec: KEY_RATE_PER_SEC,
        posterior_amplitude: r,
        posterior_rate_per_sec: KEY_RATE_PER_SEC,
    }
}

/// Quick contraction rate of the key turns, 1/s. 2.0, chosen: the full contraction
/// of a 90° turn takes 0.33 s, twenty times quicker than its restoring stroke.
pub const KEY_RATE_PER_SEC: f32 = 2.0;

/// A turn in progress.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
struct ActiveTurn {
    params: TurnParams,
    direction: TurnDirection,
    /// Seconds since the quick stroke began; negative while the turn waits for
    /// its beat phase ([`TurnMc::wait_for_beat`]).
    elapsed_secs: f32,
    /// Has the start been timed to the beat (or did the caller not ask)?
    #[serde(default)]
    timed: bool,
}

/// Phase of the swim-MC's beat (its anterior oscillator, radians; the left side
/// contracts while its sine is positive) at which the quick stroke of a left turn
/// begins: π/2, where the left side's swim contraction peaks (a right turn: 3π/2,
/// the mirror image). Chosen by measurement: how far a turn turns depends on
/// where in the beat its stroke begins. On the physical fish
/// (`physical_fish::trials::turn_at_speed_deg`: a turn requested after 3 s at 0.3,
/// 0.6 or 1.0 of the top speed), untimed, the 60° key turned 50.7–62.6° at 0.3 of
/// the top speed depending on the step at which it was requested; with the stroke
/// timed to the beat, keys ±30/60/90° at the three speeds and two request times
/// stayed within 8.2 % of the key at π/2 (11.1–15.7 % at 345°, 0°, 15°, 30°, 45°,
/// 60°; 23.4 % at 120°; measured with the earlier keys and skin). With the current
/// ones the 60° key turns 54.8–56.1° at 0.3 of the top speed whatever the request
/// step (census `key-turns-against-request-time`). [`TurnMc::wait_for_beat`] does the timing; the key
/// measurement ([`measure_turn_deg`]) times its turns the same way.
pub const KEY_BEAT_PHASE_RAD: f32 = FRAC_PI_2;

/// The left- and right-turn motor controllers (one object; the sign of the angle
/// picks the side).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TurnMc {
    /// Angle → parameters.
    pub map: SteeringMap,
    /// Restoring rate as a fraction of the quick contraction rate, dimensionless.
    /// Default 0.05, tuned: "restored … at a slower rate" (paper §3.3). The turn
    /// grows with the time spent bent (on the earlier, unconverged body the largest
    /// turn, r = 1 and s = 2/s, was 38° at 0.25 and about 160° at 0.05); with 0.05
    /// the 90° key needs r = 0.65.
    pub restore_rate_ratio: f32,
    active: Option<ActiveTurn>,
    /// Turns still queued after the active one: count and angle of each, degrees
    /// (signed, + = left).
    queued_turns: u32,
    queued_angle_deg: f32,
}

impl Default for TurnMc {
    fn default() -> Self {
        Self {
            map: SteeringMap::DEFAULT,
            restore_rate_ratio: 0.05,
            active: None,
            queued_turns: 0,
            queued_angle_deg: 0.0,
        }
    }
}

impl TurnMc {
    /// Starts a turn of `angle_deg` degrees, positive = left, negative = right,
    /// replacing any turn in progress. Turns larger than 90° become a sequence of
    /// equal turns of at most 90° each, executed back to back. NaN or 0 cancels.
    pub fn start_turn(&mut self, angle_deg: f32) {
        let a = sanitize(angle_deg);
        self.active = None;
        self.queued_turns = 0;
        if a == 0.0 {
            return;
        }
        // At most 8 pieces (720°); more is never a sensible request.
        let pieces = (a.abs() / MAX_SINGLE_TURN_DEG).ceil().clamp(1.0, 8.0);
        let each = a.signum() * a.abs().min(8.0 * MAX_SINGLE_TURN_DEG) / pieces;
        self.queued_angle_deg = each;
        self.queued_turns = pieces as u32;
        self.next_turn();
    }

    /// Starts a single turn with explicit parameters (used by the search routine).
    pub fn start_turn_with(&mut self, params: TurnParams, direction: TurnDirection) {
        self.queued_turns = 0;
        self.active = Some(ActiveTurn {
            params,
            direction,
            elapsed_secs: 0.0,
            timed: false,
        });
    }

    fn next_turn(&mut self) {
        if self.queued_turns == 0 {
            self.active = None;
            return;
        }
        self.queued_turns -= 1;
        let direction = if self.queued_angle_deg >= 0.0 {
            TurnDirection::Left
        } else {
            TurnDirection::Right
        };
        self.active = Some(ActiveTurn {
            params: self.map.params_for_angle(self.queued_angle_deg),
            direction,
            elapsed_secs: 0.0,
            timed: false,
        });
    }

    /// Delays the quick stroke of a turn (or of the next part of a sequence) that
    /// has not begun yet until the swim beat, now at `beat_phase_rad` and running
    /// at `beat_frequency_hz`, reaches [`KEY_BEAT_PHASE_RAD`] (half a beat later
    /// for a right turn): the wait is less than one beat, and the turn counts as
    /// running (the caller keeps beating at the turn's setting). Does nothing if
    /// the turn already started, was timed before, or the beat stands still.
    pub fn wait_for_beat(&mut self, beat_phase_rad: f32, beat_frequency_hz: f32) {
        let Some(turn) = self.active.as_mut() else {
            return;
        };
        if turn.timed || turn.elapsed_secs != 0.0 {
            return;
        }
        turn.timed = true;
        if !(beat_frequency_hz.is_finite() && beat_frequency_hz > 0.0 && beat_phase_rad.is_finite())
        {
            return;
        }
        let target = match turn.direction {
            TurnDirection::Left => KEY_BEAT_PHASE_RAD,
            TurnDirection::Right => KEY_BEAT_PHASE_RAD + PI,
        };
        let wait_rad = (target - beat_phase_rad).rem_euclid(TAU);
        turn.elapsed_secs = -wait_rad / (TAU * beat_frequency_hz);
    }

    /// Seconds until the quick stroke of the current turn begins (0 once it has,
    /// or without a turn).
    pub fn wait_secs(&self) -> f32 {
        self.active.map_or(0.0, |t| (-t.elapsed_secs).max(0.0))
    }

    /// True while a turn (or a queued part of one) is in progress.
    pub fn is_turning(&self) -> bool {
        self.active.is_some()
    }

    /// Advances the turn by `dt_secs` and returns the 12 muscle contractions: the
    /// anterior and middle segments on the turning side, everything else 0. While
    /// turning, the caller adds these to the swim-MC's ([`combine_swim_and_turn`]).
    pub fn step(&mut self, dt_secs: f32) -> [f32; MUSCLE_COUNT] {
        let u = self.muscles_at(dt_secs);
        self.advance(dt_secs);
        u
    }

    /// Advances the turn by `dt_secs`; a finished turn hands over to the next queued
    /// one.
    pub fn advance(&mut self, dt_secs: f32) {
        let q = self.restore_rate_ratio;
        let Some(turn) = self.active.as_mut() else {
            return;
        };
        turn.elapsed_secs += sanitize(dt_secs).max(0.0);
        if turn.elapsed_secs >= turn.params.duration_secs(q) {
            self.next_turn();
        }
    }

    /// The 12 muscle contractions `t_secs` after the turn's current time, without
    /// advancing it (what the body samples within a step, see
    /// `FishBody::step_with`); all 0 when no turn runs.
    pub fn muscles_at(&self, t_secs: f32) -> [f32; MUSCLE_COUNT] {
        let mut u = [0.0; MUSCLE_COUNT];
        let Some(turn) = self.active.as_ref() else {
            return u;
        };
        let t = turn.elapsed_secs + sanitize(t_secs).max(0.0);
        let p = turn.params;
        let side = match turn.direction {
            TurnDirection::Left => Side::Left,
            TurnDirection::Right => Side::Right,
        };
        let q = self.restore_rate_ratio;
        for (segment, r, s) in [
            (
                MuscleSegment::Anterior,
                p.anterior_amplitude,
                p.anterior_rate_per_sec,
            ),
            (
                MuscleSegment::Middle,
                p.posterior_amplitude,
                p.posterior_rate_per_sec,
            ),
        ] {
            let c = TurnParams::contraction(r, s, q, t);
            let i = muscle_index(segment, side);
            u[i] = c;
            u[i + 1] = c;
        }
        u
    }
}

/// Heading change of a swimming fish executing one turn, degrees (+ = left). See the
/// module doc for the protocol. Deterministic.
pub fn measure_turn_deg(params: TurnParams, direction: TurnDirection) -> f32 {
    measure_turn_deg_with(
        params,
        direction,
        crate::sim::body::BodyParams::default(),
        ControlSampling::default(),
    )
}

/// [`measure_turn_deg`] on a body with `body` parameters and the controllers
/// sampled as `sampling` says.
pub fn measure_turn_deg_with(
    params: TurnParams,
    direction: TurnDirection,
    body: crate::sim::body::BodyParams,
    sampling: ControlSampling,
) -> f32 {
    let mut mc = TurnMc::default();
    mc.start_turn_with(params, direction);
    measure_heading_change_deg_with(&mut mc, direction == TurnDirection::Right, body, sampling)
}

/// How a fish uses both controllers at once: the turn-MC's contractions are added
/// to the swim-MC's and clamped to 1. Chosen: replacing the middle segment's swim
/// wave by the turn bend (the alternative) weakens the thrust during the turn and
/// halves the turn (measured r = 1, s = 2/s, restoring ratio 1/4: 18–24° replacing,
/// 38° adding), and a turn needs thrust (this body has almost no momentum to
/// deflect, see the module doc).
pub fn combine_swim_and_turn(
    swim: &[f32; MUSCLE_COUNT],
    turn: &[f32; MUSCLE_COUNT],
) -> [f32; MUSCLE_COUNT] {
    let mut u = *swim;
    for (a, b) in u.iter_mut().zip(turn) {
        *a = (*a + b).clamp(0.0, 1.0);
    }
    u
}

/// The same contractions with left and right swapped (the mirror image y → −y).
pub fn mirror_muscles(u: &[f32; MUSCLE_COUNT]) -> [f32; MUSCLE_COUNT] {
    let mut out = [0.0; MUSCLE_COUNT];
    for segment in [
        MuscleSegment::Anterior,
        MuscleSegment::Middle,
        MuscleSegment::Posterior,
    ] {
        let (l, r) = (
            muscle_index(segment, Side::Left),
            muscle_index(segment, Side::Right),
        );
        out[l..l + 2].copy_from_slice(&u[r..r + 2]);
        out[r..r + 2].copy_from_slice(&u[l..l + 2]);
    }
    out
}

/// Runs the measurement protocol with a turn already started on `mc`: swims straight
/// at top speed for [`TURN_LEAD_IN_SECS`], then lets `mc` drive the anterior and
/// middle segments (the swim-MC keeps beating the posterior one) until it is done,
/// then swims straight for [`TURN_SETTLE_SECS`]. The heading is the fore body's
/// horizontal direction, unwrapped and averaged over the last
/// [`HEADING_AVERAGE_SECS`] before the turn and at the end (three tail beats, so
/// the beat's yaw wobble cancels). Returns the change in degrees (+ = left).
/// The turn's contractions are *added* to the swim-MC's (clamped to 1), so the
/// shared middle segment keeps beating around a bent mean. `mirror_swim` swaps the
/// swim-MC's sides for the whole run, so a right turn is measured as the exact
/// mirror image of a left one.
pub fn measure_heading_change_deg(mc: &mut TurnMc, mirror_swim: bool) -> f32 {
    measure_heading_change_deg_with(
        mc,
        mirror_swim,
        crate::sim::body::BodyParams::default(),
        ControlSampling::default(),
    )
}

/// [`measure_heading_change_deg`] on a body with `body` parameters and the
/// controllers sampled as `sampling` says.
pub fn measure_heading_change_deg_with(
    mc: &mut TurnMc,
    mirror_swim: bool,
    body: crate::sim::body::BodyParams,
    sampling: ControlSampling,
) -> f32 {
    use crate::sim::body::{BodyCommand, FishBody, PectoralFins, SwimMc, SwimParams};
    use glam::Vec3;
    let length_m = crate::sim::body::body_layout::PAPER_BODY_LENGTH;
    let mut fish = FishBody::with_params(length_m, Vec3::ZERO, Vec3::X, body);
    let mut swim = SwimMc::default();
    let dt = fish.dt_secs();
    let heading = |f: &FishBody| fmath::atan2(f.forward().y, f.forward().x);
    let mut previous = heading(&fish);
    let mut unwrapped_rad = previous;
    let average_steps = ((HEADING_AVERAGE_SECS / dt).round() as usize).max(1);
    let mut window: Vec<f32> = Vec::with_capacity(average_steps);
    let push = |w: &mut Vec<f32>, h: f32| {
        if w.len() == average_steps {
            w.remove(0);
        }
        w.push(h);
    };
    let mean = |w: &[f32]| w.iter().sum::<f32>() / w.len().max(1) as f32;
    let mut run = |fish: &mut FishBody,
                   swim: &mut SwimMc,
                   mut mc: Option<&mut TurnMc>,
                   window: &mut Vec<f32>| {
        let muscles_at = |t: f32, swim: &SwimMc, mc: Option<&TurnMc>| {
            let mut u = swim.muscles_at(&SwimParams::MAX, t);
            if mirror_swim {
                u = mirror_muscles(&u);
            }
            if let Some(mc) = mc {
                u = combine_swim_and_turn(&u, &mc.muscles_at(t));
            }
            u
        };
        match sampling {
            ControlSampling::PerStep => {
                let u = muscles_at(dt, swim, mc.as_deref());
                fish.step(
                    &BodyCommand {
                        muscle_contractions: u,
                        ..Default::default()
                    },
                    Vec3::ZERO,
                );
            }
            ControlSampling::PerSubstep => {
                fish.step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
                    muscles_at(t, swim, mc.as_deref())
                });
            }
        }
        swim.advance(&SwimParams::MAX, dt);
        if let Some(mc) = mc.as_deref_mut() {
            mc.advance(dt);
        }
        let h = heading(fish);
        unwrapped_rad += (h - previous + PI).rem_euclid(TAU) - PI;
        previous = h;
        push(window, unwrapped_rad);
    };
    for _ in 0..(TURN_LEAD_IN_SECS / dt).round() as usize {
        run(&mut fish, &mut swim, None, &mut window);
    }
    let before = mean(&window);
    // The stroke begins at the key beat phase (the swim is mirrored for a right
    // turn, so its beat is half a period on).
    let beat = swim.anterior_phase_rad() + if mirror_swim { PI } else { 0.0 };
    mc.wait_for_beat(beat, SwimParams::MAX.anterior_frequency_hz);
    // Guard: at most 60 s of turning.
    for _ in 0..(60.0 / dt) as usize {
        if !mc.is_turning() {
            break;
        }
        run(&mut fish, &mut swim, Some(mc), &mut window);
    }
    for _ in 0..(TURN_SETTLE_SECS / dt).round() as usize {
        run(&mut fish, &mut swim, None, &mut window);
    }
    (mean(&window) - before).to_degrees()
}

/// The search routine behind [`SteeringMap::DEFAULT`]: within the family
/// r0 = r1 = r, s0 = s1 = [`KEY_RATE_PER_SEC`], bisect r in [0, 1] for each target
/// angle (30°, 45°, 60°, 90°) on left turns, assuming the turn grows with r (checked
/// by the tests). Returns the map and the measured angle of each key.
pub fn find_steering_map() -> (SteeringMap, [f32; 4]) {
    find_steering_map_with(crate::sim::body::BodyParams::default())
}

/// [`find_steering_map`] on a body with `body` parameters.
pub fn find_steering_map_with(body: crate::sim::body::BodyParams) -> (SteeringMap, [f32; 4]) {
    let measure = |p: TurnParams| {
        measure_turn_deg_with(p, TurnDirection::Left, body, ControlSampling::default())
    };
    let targets = [30.0, 45.0, 60.0, 90.0];
    let mut map = SteeringMap::DEFAULT;
    let mut measured = [0.0; 4];
    for (k, target) in targets.into_iter().enumerate() {
        let (mut lo, mut hi) = (0.0f32, 1.0f32);
        for _ in 0..14 {
            let mid = 0.5 * (lo + hi);
            if measure(key(mid)) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let r = 0.5 * (lo + hi);
        map.keys[k] = (target, key(r));
        measured[k] = measure(key(r));
    }
    (map, measured)
}

/// Continuous steering (not in the paper, whose turns are discrete): `steer` in
/// [−1, 1] (+ = left, NaN = 0) adds |steer| × the segment biases of `params`
/// ([`MotorParams::steer_anterior_bias`], …) to the contractions of the turning
/// side and clamps them to 1, like a turn-MC bend held for as long as the command
/// lasts.
pub fn add_steering(params: &MotorParams, u: &mut [f32; MUSCLE_COUNT], steer: f32) {
    add_steering_with(u, steer, params.steer_biases());
}

/// [`add_steering`] with explicit segment biases (anterior, middle, posterior).
pub fn add_steering_with(u: &mut [f32; MUSCLE_COUNT], steer: f32, biases: [f32; 3]) {
    let s = sanitize(steer).clamp(-1.0, 1.0);
    if s == 0.0 {
        return;
    }
    let side = if s > 0.0 { Side::Left } else { Side::Right };
    for (segment, bias) in [
        MuscleSegment::Anterior,
        MuscleSegment::Middle,
        MuscleSegment::Posterior,
    ]
    .into_iter()
    .zip(biases)
    {
        let i = muscle_index(segment, side);
        for m in &mut u[i..i + 2] {
            *m = (*m + s.abs() * bias).clamp(0.0, 1.0);
        }
    }
}
