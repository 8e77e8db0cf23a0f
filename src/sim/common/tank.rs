//! The glass tank: an axis-aligned box of water that the fish live in.

use glam::Vec3;
use serde::{Deserialize, Serialize};

/// The water volume, an axis-aligned box in metres.
///
/// y points up; the sand floor is the bottom face (y = 0 in the default tank)
/// and the water surface is the top face.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Tank {
    /// Corner with the smallest x, y and z, in metres.
    pub min_m: Vec3,
    /// Corner with the largest x, y and z, in metres.
    pub max_m: Vec3,
}

impl Default for Tank {
    /// A 12 m × 4.5 m × 8 m tank (x from −6 to 6, y from 0 to 4.5, z from −4
    /// to 4): a large public aquarium, roomy enough for a few hundred fish
    /// about 0.3 m long to form visible groups.
    fn default() -> Self {
        Self {
            min_m: Vec3::new(-6.0, 0.0, -4.0),
            max_m: Vec3::new(6.0, 4.5, 4.0),
        }
    }
}

impl Tank {
    /// Width, height and depth in metres.
    pub fn size_m(&self) -> Vec3 {
        self.max_m - self.min_m
    }

    /// The middle of the water volume, in metres.
    pub fn center_m(&self) -> Vec3 {
        (self.min_m + self.max_m) * 0.5
    }

    /// Is `p_m` inside the tank shrunk by `margin_m` on every side (borders
    /// included)? A NaN point is never inside.
    pub fn contains(&self, p_m: Vec3, margin_m: f32) -> bool {
        let (lo, hi) = self.shrunk_m(margin_m);
        p_m.cmpge(lo).all() && p_m.cmple(hi).all()
    }

    /// The point of the tank shrunk by `margin_m` that is closest to `p_m`
    /// (each coordinate clamped separately). If the margin is larger than half
    /// the tank the result is the centre on that axis. Never panics.
    /// How far from `p` (inside the tank) along the unit `direction` the glass,
    /// sand or surface is, metres: a fish sees no farther than its tank.
    pub fn distance_to_glass(&self, p: Vec3, direction: Vec3) -> f32 {
        let mut nearest = f32::INFINITY;
        for axis in 0..3 {
            let d = direction[axis];
            if d.abs() > 1e-6 {
                let wall = if d > 0.0 {
                    self.max_m[axis]
                } else {
                    self.min_m[axis]
                };
                nearest = nearest.min(((wall - p[axis]) / d).max(0.0));
            }
        }
        nearest
    }

    pub fn clamp_inside(&self, p_m: Vec3, margin_m: f32) -> Vec3 {
        let (lo, hi) = self.shrunk_m(margin_m);
        // `max` then `min` (not `clamp`) so that lo > hi or NaN cannot panic.
        p_m.max(lo).min(hi)
    }

    /// Lower and upper corners of the tank shrunk by `margin_m`, with the
    /// margin limited per axis to half the size so that lo ≤ hi always holds.
    fn shrunk_m(&self, margin_m: f32) -> (Vec3, Vec3) {
        let half_size_m = (self.size_m() * 0.5).max(Vec3::ZERO);
        let margin_m = Vec3::splat(margin_m.max(0.0)).min(half_size_m);
        (self.min_m + margin_m, self.max_m - margin_m)
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::common::tank::*;

    #[test]
    fn a_fish_sees_no_farther_than_its_glass() {
        let tank = Tank {
            min_m: Vec3::ZERO,
            max_m: Vec3::new(10.0, 4.0, 6.0),
        };
        let p = Vec3::new(8.0, 2.0, 3.0);
        assert!((tank.distance_to_glass(p, Vec3::X) - 2.0).abs() < 1e-6);
        assert!((tank.distance_to_glass(p, -Vec3::X) - 8.0).abs() < 1e-6);
        let diagonal = Vec3::new(1.0, 1.0, 0.0).normalize_or_zero();
        assert!((tank.distance_to_glass(p, diagonal) - 2.0f32.sqrt() * 2.0).abs() < 1e-5);
    }

    #[test]
    fn default_tank_is_12_by_4_5_by_8_metres_with_floor_at_zero() {
        let tank = Tank::default();
        assert_eq!(tank.size_m(), Vec3::new(12.0, 4.5, 8.0));
        assert_eq!(tank.center_m(), Vec3::new(0.0, 2.25, 0.0));
        assert_eq!(tank.min_m.y, 0.0);
    }

    #[test]
    fn contains_respects_the_margin() {
        let tank = Tank::default();
        assert!(tank.contains(Vec3::new(5.9, 1.0, 0.0), 0.0));
        assert!(!tank.contains(Vec3::new(5.9, 1.0, 0.0), 0.2));
        assert!(!tank.contains(Vec3::new(0.0, -0.01, 0.0), 0.0));
        assert!(!tank.contains(Vec3::NAN, 0.0));
    }

    #[test]
    fn clamp_inside_moves_outside_points_to_the_nearest_allowed_point() {
        let tank = Tank::default();
        let p = tank.clamp_inside(Vec3::new(10.0, -1.0, 2.0), 0.1);
        assert_eq!(p, Vec3::new(5.9, 0.1, 2.0));
        // A point already inside is unchanged.
        let q = Vec3::new(1.0, 2.0, 3.0);
        assert_eq!(tank.clamp_inside(q, 0.1), q);
        // Absurd margins give the centre instead of panicking.
        assert_eq!(tank.clamp_inside(q, 100.0), tank.center_m());
    }
}
