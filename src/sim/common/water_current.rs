//! A slowly varying water current that the physical fish feel (Tu & Terzopoulos
//! 1994 §3.2: the water force acts on the body's velocity *relative to the water*,
//! so a fish that does not swim drifts with the flow and one that holds its place
//! must swim against it).
//!
//! The flow is horizontal and built from a stream function, so it is
//! divergence-free (water neither piles up nor vanishes) and never flows through
//! the glass:
//!
//! ψ(X, Z, t) = a₁(t) sin(πX) sin(πZ) + a₂(t) sin(2πX) sin(πZ),
//! with X = (x − x_min)/W and Z = (z − z_min)/D in [0, 1] across the tank, and
//! u_x = ∂ψ/∂z, u_z = −∂ψ/∂x, u_y = 0.
//!
//! The first mode is one gyre filling the tank (the water circles round it); the
//! second splits it into two counter-rotating gyres. Their amplitudes breathe over
//! minutes: a₁ = s (0.8 + 0.2 sin 2πt/T₁), a₂ = 0.35 s sin 2πt/T₂ with T₁ = 47 s
//! and T₂ = 83 s (two unrelated periods, so the pattern does not repeat within a
//! lesson). Amplitudes are normalised so that the strongest water in the tank
//! moves at about `strength_m_per_s`.

use crate::sim::common::fmath;
use std::f32::consts::{PI, TAU};

use glam::Vec3;

use crate::sim::common::tank::Tank;

/// Period of the main gyre's breathing, seconds (47, chosen: slow next to a fish's
/// seconds-long turns, fast enough to notice in a lesson).
const MAIN_PERIOD_SECS: f32 = 47.0;
/// Period of the second mode, seconds (83, chosen: not a multiple of the first).
const SECOND_PERIOD_SECS: f32 = 83.0;
/// Share of the second mode at its peak (0.35, chosen: bends the gyre visibly
/// without reversing it).
const SECOND_MODE_SHARE: f32 = 0.35;

/// The current in a tank.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaterCurrent {
    tank: Tank,
    /// Speed of the fastest water, m/s (0 = still water).
    pub strength_m_per_s: f32,
}

impl WaterCurrent {
    pub fn new(tank: Tank, strength_m_per_s: f32) -> Self {
        let strength_m_per_s = if strength_m_per_s.is_finite() {
            strength_m_per_s.max(0.0)
        } else {
            0.0
        };
        Self {
            tank,
            strength_m_per_s,
        }
    }

    /// The water velocity at `p_m` at time `time_secs`, m/s. Zero outside the tank.
    pub fn velocity_m_per_s(&self, p_m: Vec3, time_secs: f64) -> Vec3 {
        if self.strength_m_per_s == 0.0 || !p_m.is_finite() {
            return Vec3::ZERO;
        }
        let size = self.tank.size_m();
        let x = (p_m.x - self.tank.min_m.x) / size.x;
        let z = (p_m.z - self.tank.min_m.z) / size.z;
        if !((0.0..=1.0).contains(&x) && (0.0..=1.0).contains(&z)) {
            return Vec3::ZERO;
        }
        // Time in f64 until the phase is reduced, so the flow stays smooth after hours.
        let phase = |period: f32| ((time_secs / f64::from(period)).fract() as f32) * TAU;
        let a1 = 0.8 + 0.2 * fmath::sin(phase(MAIN_PERIOD_SECS));
        let a2 = SECOND_MODE_SHARE * fmath::sin(phase(SECOND_PERIOD_SECS));
        // ψ = Σ a_k sin(k π X) sin(π Z); the peak of |∇ψ| of the first mode is
        // π·max(1/W, 1/D), which the normalisation divides out.
        let (sx1, cx1) = fmath::sin_cos(PI * x);
        let (sx2, cx2) = fmath::sin_cos(2.0 * PI * x);
        let (sz, cz) = fmath::sin_cos(PI * z);
        let dpsi_dz = (a1 * sx1 + a2 * sx2) * PI * cz / size.z;
        let dpsi_dx = (a1 * PI * cx1 + a2 * 2.0 * PI * cx2) * sz / size.x;
        let norm = PI * (1.0 / size.x).max(1.0 / size.z);
        Vec3::new(dpsi_dz, 0.0, -dpsi_dx) * (self.strength_m_per_s / norm)
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::common::water_current::*;

    fn grid(tank: &Tank, n: usize) -> impl Iterator<Item = Vec3> + '_ {
        (0..=n).flat_map(move |i| {
            (0..=n).map(move |k| {
                let t = Vec3::new(i as f32 / n as f32, 0.5, k as f32 / n as f32);
                tank.min_m + t * tank.size_m()
            })
        })
    }

    #[test]
    fn still_water_is_still_and_flow_is_horizontal_and_bounded() {
        let tank = Tank::default();
        let still = WaterCurrent::new(tank, 0.0);
        let flow = WaterCurrent::new(tank, 0.1);
        let mut fastest: f32 = 0.0;
        for p in grid(&tank, 24) {
            assert_eq!(still.velocity_m_per_s(p, 3.0), Vec3::ZERO);
            for t in [0.0, 11.7, 40.0, 3600.0] {
                let v = flow.velocity_m_per_s(p, t);
                assert!(v.is_finite() && v.y == 0.0);
                fastest = fastest.max(v.length());
            }
        }
        assert!(fastest > 0.07 && fastest < 0.16, "fastest {fastest}");
    }

    #[test]
    fn water_never_flows_through_the_glass() {
        let tank = Tank::default();
        let flow = WaterCurrent::new(tank, 0.2);
        for i in 0..=20 {
            let s = i as f32 / 20.0;
            let along_x = tank.min_m.x + s * tank.size_m().x;
            let along_z = tank.min_m.z + s * tank.size_m().z;
            for t in [0.0, 20.0, 61.0] {
                let on_x_wall = flow.velocity_m_per_s(Vec3::new(tank.min_m.x, 1.0, along_z), t);
                let on_z_wall = flow.velocity_m_per_s(Vec3::new(along_x, 1.0, tank.max_m.z), t);
                assert!(on_x_wall.x.abs() < 1e-4, "{on_x_wall}");
                assert!(on_z_wall.z.abs() < 1e-4, "{on_z_wall}");
            }
        }
    }

    #[test]
    fn flow_is_divergence_free_and_changes_slowly() {
        let tank = Tank::default();
        let flow = WaterCurrent::new(tank, 0.1);
        let h = 1e-2;
        for p in grid(&tank, 7).filter(|p| tank.contains(*p, 0.2)) {
            let dvx = flow.velocity_m_per_s(p + Vec3::X * h, 5.0).x
                - flow.velocity_m_per_s(p - Vec3::X * h, 5.0).x;
            let dvz = flow.velocity_m_per_s(p + Vec3::Z * h, 5.0).z
                - flow.velocity_m_per_s(p - Vec3::Z * h, 5.0).z;
            assert!(((dvx + dvz) / (2.0 * h)).abs() < 1e-3);
            let now = flow.velocity_m_per_s(p, 5.0);
            let later = flow.velocity_m_per_s(p, 6.0);
            assert!(now.distance(later) < 0.01, "{now} {later}");
        }
    }
}
