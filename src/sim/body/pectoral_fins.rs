//! Pectoral fins, Tu & Terzopoulos 1994 §3.4 and Fig. 5. The fins are not bodies;
//! each is a flat plate of area A whose force F_f = −A (n·v) n = −A ‖v‖ cos θ · n
//! (v = fish velocity relative to the water, θ the angle between n and v) is applied
//! to the midsection nodes 1..12.
//!
//! Fin angle convention (θ of the paper, per fin, radians, clamped to [π/4, π]):
//! the fin normal is n = cos θ · forward + sin θ · up, so
//! - θ = π/2: fin flat along the body, no force in straight swimming (neutral);
//! - θ > π/2: leading edge raised → lift, the fish ascends;
//! - θ < π/2: leading edge lowered → the fish descends;
//! - θ = π: fin across the flow → pure drag, the brake.
//!
//! Choices: the paper spreads the force equally over nodes 1..12. Here each fin's
//! force goes equally to the six nodes of *its own side* (left: the dorsal-left and
//! ventral-left nodes of rings 1–3), so unequal left/right angles give the yaw and
//! roll the paper describes (the whole 12-node spread would make them impossible).
//! The body is neutrally buoyant: no gravity and no buoyancy force at all, and a
//! righting couple (see `FishBody`, `BodyParams::righting_force`) keeps it upright.

use crate::sim::common::fmath;
use glam::Vec3;
use serde::{Deserialize, Serialize};
use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use crate::sim::body::body_layout::ring_nodes;

/// Angles of the two pectoral fins (θ of the paper, radians).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PectoralFins {
    /// Left fin θ in [π/4, π]; π/2 neutral.
    pub left_angle_rad: f32,
    /// Right fin θ in [π/4, π]; π/2 neutral.
    pub right_angle_rad: f32,
    /// Do the fins trim the body (hold it pitched by their mean pitch, see
    /// `BodyParams::fin_trim_gain`)? Set by the reef's minds when they climb or
    /// dive ([`PectoralFins::climb`]); the physics scene's bridge, bobbing and
    /// braking leave the body level.
    #[serde(default)]
    pub trim: bool,
}

impl Default for PectoralFins {
    fn default() -> Self {
        Self::NEUTRAL
    }
}

impl PectoralFins {
    /// Both fins flat: no force in straight swimming.
    pub const NEUTRAL: Self = Self {
        left_angle_rad: FRAC_PI_2,
        right_angle_rad: FRAC_PI_2,
        trim: false,
    };

    /// Both fins across the flow (θ = π): brake.
    pub const BRAKE: Self = Self {
        left_angle_rad: PI,
        right_angle_rad: PI,
        trim: false,
    };

    /// Both fins tilted by `pitch_rad` from flat: positive raises the leading edge and
    /// makes the fish ascend, negative descend. Clamped to [−π/4, π/2].
    pub fn pitch(pitch_rad: f32) -> Self {
        let theta = FRAC_PI_2 + pitch_rad;
        Self {
            left_angle_rad: theta,
            right_angle_rad: theta,
            trim: false,
        }
    }

    /// Both fins tilted by `pitch_rad` as in [`PectoralFins::pitch`], trimming
    /// the body: it pitches nose up (or down) with them and swims up (or down)
    /// its own axis.
    pub fn climb(pitch_rad: f32) -> Self {
        Self {
            trim: true,
            ..Self::pitch(pitch_rad)
        }
    }

    /// The nodes that receive the force of fin `side` (0 = left, 1 = right): the six
    /// nodes of that side in rings 1–3 (nodes 1..12).
    pub fn nodes(side: usize) -> [usize; 6] {
        let corners = if side == 0 { [0, 3] } else { [1, 2] };
        let mut out = [0; 6];
        for k in 0..3 {
            let r = ring_nodes(k);
            out[2 * k] = r[corners[0]];
            out[2 * k + 1] = r[corners[1]];
        }
        out
    }

    fn clamped(theta: f32) -> f32 {
        if theta.is_finite() {
            theta.clamp(FRAC_PI_4, PI)
        } else {
            FRAC_PI_2
        }
    }

    /// Forces of the [left, right] fin for a fish with unit `forward` and `up`
    /// directions moving at `velocity_rel_water`; `fin_area` is the area of one fin in
    /// the same length units squared. F_f = −A (n·v) n.
    pub fn forces(
        &self,
        forward: Vec3,
        up: Vec3,
        velocity_rel_water: Vec3,
        fin_area: f32,
    ) -> [Vec3; 2] {
        [self.left_angle_rad, self.right_angle_rad].map(|theta| {
            let theta = Self::clamped(theta);
            let n = (fmath::cos(theta) * forward + fmath::sin(theta) * up).normalize_or_zero();
            -fin_area * n.dot(velocity_rel_water) * n
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::body::pectoral_fins::*;

    #[test]
    fn fin_force_lifts_dives_and_brakes() {
        let v = Vec3::X * 2.0;
        let lift = PectoralFins::pitch(0.4).forces(Vec3::X, Vec3::Z, v, 1.0);
        assert!(lift[0].z > 0.0 && lift[1].z > 0.0);
        let dive = PectoralFins::pitch(-0.4).forces(Vec3::X, Vec3::Z, v, 1.0);
        assert!(dive[0].z < 0.0);
        let brake = PectoralFins::BRAKE.forces(Vec3::X, Vec3::Z, v, 1.0);
        assert!((brake[0] - Vec3::new(-2.0, 0.0, 0.0)).length() < 1e-5);
        let neutral = PectoralFins::NEUTRAL.forces(Vec3::X, Vec3::Z, v, 1.0);
        assert!(neutral[0].length() < 1e-5);
        assert_eq!(PectoralFins::nodes(0), [1, 4, 5, 8, 9, 12]);
        assert_eq!(PectoralFins::nodes(1), [2, 3, 6, 7, 10, 11]);
    }
}
