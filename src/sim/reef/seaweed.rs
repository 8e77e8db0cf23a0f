//! Seaweed: strands rooted in the sand that sway in the current. Scenery:
//! fish neither see nor touch it.

use glam::Vec3;

use crate::sim::common::fmath;
use crate::sim::common::tank::Tank;
use crate::sim::common::water_current::WaterCurrent;

/// Seaweed nodes per strand.
pub const SEAWEED_NODES: usize = 10;

/// A strand of seaweed: a chain of points rooted in the sand.
#[derive(Clone, Debug, PartialEq)]
pub struct Seaweed {
    /// Node 0 is the root.
    pub nodes_m: Vec<Vec3>,
    pub segment_m: f32,
    /// Where in its own sway the strand starts, so strands do not sway in step.
    phase_rad: f32,
}

impl Seaweed {
    /// A strand `height_m` tall standing straight up from `root_m`, swaying
    /// from `phase_rad`.
    pub(super) fn planted(root_m: Vec3, height_m: f32, phase_rad: f32) -> Self {
        let segment = height_m / (SEAWEED_NODES - 1) as f32;
        Self {
            nodes_m: (0..SEAWEED_NODES)
                .map(|n| root_m + Vec3::Y * segment * n as f32)
                .collect(),
            segment_m: segment,
            phase_rad,
        }
    }
}

/// Sways every strand for `dt_secs` at `time_secs` in the water of
/// `current`, keeping its segment lengths and its nodes above the sand of
/// `tank`.
pub(super) fn sway(
    strands: &mut [Seaweed],
    current: &WaterCurrent,
    tank: &Tank,
    time_secs: f32,
    dt_secs: f32,
) {
    let (t, dt) = (time_secs, dt_secs);
    for w in strands {
        let root = w.nodes_m[0];
        for n in 1..w.nodes_m.len() {
            let p = w.nodes_m[n];
            let water = current.velocity_m_per_s(p, f64::from(t));
            let along = n as f32 / (SEAWEED_NODES - 1) as f32;
            let sway = Vec3::new(
                fmath::sin(0.7 * t + w.phase_rad + 0.6 * along),
                0.0,
                fmath::cos(0.45 * t + 1.3 * w.phase_rad),
            ) * 0.06;
            let lift = Vec3::Y * 0.15;
            w.nodes_m[n] = p + (water * 3.0 + sway + lift) * dt * along;
        }
        // Keep the segment lengths, from the root out.
        w.nodes_m[0] = root;
        for n in 1..w.nodes_m.len() {
            let prev = w.nodes_m[n - 1];
            let dir = (w.nodes_m[n] - prev).normalize_or(Vec3::Y);
            let mut q = prev + dir * w.segment_m;
            q.y = q.y.max(tank.min_m.y + 0.02);
            w.nodes_m[n] = q;
        }
    }
}
