//! Solid things in the tank that fish must swim around: rocks and pillars.
//!
//! Each obstacle is described by a signed distance function (SDF): the
//! distance from a point to the obstacle's surface, negative inside. Steering
//! and the hard "no fish inside a rock" rule are both built on it.

use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};

/// A solid obstacle. Sizes in metres.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Obstacle {
    /// A round rock (a sphere), often half-buried in the sand.
    Rock {
        /// Centre of the sphere in metres; may be below the floor.
        center_m: Vec3,
        /// Radius in metres.
        radius_m: f32,
    },
    /// A vertical pillar (e.g. coral) standing on the floor.
    ///
    /// It is rooted in the sand: the solid is treated as continuing below
    /// its base, so its bottom face is never offered as a way out. (Pushing
    /// a fish out through the bottom would push it into the sand.)
    Cylinder {
        /// Centre of the bottom face in metres (on the floor).
        base_center_m: Vec3,
        /// Radius in metres.
        radius_m: f32,
        /// Height above the base in metres.
        height_m: f32,
    },
}

impl Obstacle {
    /// Signed distance from `p_m` to the surface in metres: positive outside,
    /// zero on the surface, negative inside.
    pub fn signed_distance_m(&self, p_m: Vec3) -> f32 {
        match *self {
            Obstacle::Rock { center_m, radius_m } => (p_m - center_m).length() - radius_m,
            Obstacle::Cylinder { .. } => {
                let d = self.cylinder_face_distances_m(p_m);
                // Inside: the nearest face (both parts ≤ 0). Outside: the
                // Euclidean distance to the side, the top or the rim.
                d.max_element().min(0.0) + d.max(Vec2::ZERO).length()
            }
        }
    }

    /// Unit vector pointing out of the obstacle at `p_m`: the direction in
    /// which the signed distance grows fastest. Never NaN; at a rock's exact
    /// centre it is up (+y), on a pillar's axis it is +x or up.
    pub fn outward_normal(&self, p_m: Vec3) -> Vec3 {
        match *self {
            Obstacle::Rock { center_m, .. } => (p_m - center_m).normalize_or(Vec3::Y),
            Obstacle::Cylinder { base_center_m, .. } => {
                let d = self.cylinder_face_distances_m(p_m);
                let radial = (p_m - base_center_m) * Vec3::new(1.0, 0.0, 1.0);
                let side = radial.normalize_or(Vec3::X);
                if d.x <= 0.0 && d.y <= 0.0 {
                    // Inside: out through the nearest face.
                    if d.x > d.y { side } else { Vec3::Y }
                } else {
                    // Outside: away from the nearest surface point
                    // (side, top, or both near the rim).
                    (side * d.x.max(0.0) + Vec3::Y * d.y.max(0.0)).normalize_or(Vec3::Y)
                }
            }
        }
    }

    /// If `p_m` is closer than `margin_m` to the surface (or inside), move it
    /// along the outward normal so that it is exactly `margin_m` outside;
    /// otherwise return it unchanged.
    pub fn push_outside(&self, p_m: Vec3, margin_m: f32) -> Vec3 {
        let distance_m = self.signed_distance_m(p_m);
        if distance_m < margin_m {
            p_m + self.outward_normal(p_m) * (margin_m - distance_m)
        } else {
            p_m
        }
    }

    /// The point of the obstacle's core nearest to `p_m`: a rock's centre, or
    /// the point of a pillar's axis at the height of `p_m` (clamped to the
    /// pillar). Obstacle avoidance steers away from this point.
    pub fn core_point_m(&self, p_m: Vec3) -> Vec3 {
        match *self {
            Obstacle::Rock { center_m, .. } => center_m,
            Obstacle::Cylinder {
                base_center_m,
                height_m,
                ..
            } => {
                let top_y_m = base_center_m.y + height_m.max(0.0);
                Vec3::new(
                    base_center_m.x,
                    p_m.y.max(base_center_m.y).min(top_y_m),
                    base_center_m.z,
                )
            }
        }
    }

    /// The obstacle's radius in metres (rock or pillar).
    pub fn radius_m(&self) -> f32 {
        match *self {
            Obstacle::Rock { radius_m, .. } | Obstacle::Cylinder { radius_m, .. } => radius_m,
        }
    }

    /// For a pillar: (distance outside the side wall, distance above the
    /// top), each negative when inside that face.
    fn cylinder_face_distances_m(&self, p_m: Vec3) -> Vec2 {
        match *self {
            Obstacle::Cylinder {
                base_center_m,
                radius_m,
                height_m,
            } => {
                let offset = p_m - base_center_m;
                Vec2::new(
                    Vec2::new(offset.x, offset.z).length() - radius_m,
                    offset.y - height_m,
                )
            }
            Obstacle::Rock { .. } => Vec2::ZERO,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const EPS: f32 = 1e-5;

    fn rock() -> Obstacle {
        Obstacle::Rock {
            center_m: Vec3::new(1.0, 0.0, -1.0),
            radius_m: 0.5,
        }
    }

    fn pillar() -> Obstacle {
        Obstacle::Cylinder {
            base_center_m: Vec3::new(2.0, 0.0, 0.0),
            radius_m: 0.4,
            height_m: 3.0,
        }
    }

    fn close(a: f32, b: f32) -> bool {
        (a - b).abs() < EPS
    }

    #[test]
    fn rock_signed_distance_is_negative_inside_and_positive_outside() {
        let r = rock();
        assert!(close(r.signed_distance_m(Vec3::new(1.0, 0.0, -1.0)), -0.5));
        assert!(close(
            r.signed_distance_m(Vec3::new(1.0, 0.25, -1.0)),
            -0.25
        ));
        assert!(close(r.signed_distance_m(Vec3::new(1.0, 0.5, -1.0)), 0.0));
        assert!(close(r.signed_distance_m(Vec3::new(2.5, 0.0, -1.0)), 1.0));
    }

    #[test]
    fn rock_normal_points_away_from_centre_and_up_at_the_centre() {
        let r = rock();
        let n = r.outward_normal(Vec3::new(3.0, 0.0, -1.0));
        assert!((n - Vec3::X).length() < EPS);
        assert_eq!(r.outward_normal(Vec3::new(1.0, 0.0, -1.0)), Vec3::Y);
    }

    #[test]
    fn rock_push_outside_moves_points_to_the_margin_and_leaves_far_points() {
        let r = rock();
        let from_inside = r.push_outside(Vec3::new(1.2, 0.0, -1.0), 0.1);
        assert!(close(r.signed_distance_m(from_inside), 0.1));
        assert!((from_inside - Vec3::new(1.6, 0.0, -1.0)).length() < EPS);
        let from_centre = r.push_outside(Vec3::new(1.0, 0.0, -1.0), 0.1);
        assert!((from_centre - Vec3::new(1.0, 0.6, -1.0)).length() < EPS);
        let far = Vec3::new(5.0, 1.0, 0.0);
        assert_eq!(r.push_outside(far, 0.1), far);
    }

    #[test]
    fn pillar_signed_distance_to_side_top_and_rim() {
        let c = pillar();
        // Beside it, above it, diagonally off the rim, inside near the side.
        assert!(close(c.signed_distance_m(Vec3::new(3.0, 1.0, 0.0)), 0.6));
        assert!(close(c.signed_distance_m(Vec3::new(2.0, 3.5, 0.0)), 0.5));
        assert!(close(c.signed_distance_m(Vec3::new(2.7, 3.4, 0.0)), 0.5));
        assert!(close(c.signed_distance_m(Vec3::new(2.3, 1.0, 0.0)), -0.1));
        // On the axis near the top: the top is the nearest face.
        assert!(close(c.signed_distance_m(Vec3::new(2.0, 2.9, 0.0)), -0.1));
        // Near the floor the sand is not a way out: the side is nearest.
        assert!(close(c.signed_distance_m(Vec3::new(2.0, 0.05, 0.0)), -0.4));
    }

    #[test]
    fn pillar_normal_is_unit_everywhere_including_the_axis() {
        let c = pillar();
        let n_side = c.outward_normal(Vec3::new(2.0, 1.0, 1.0));
        assert!((n_side - Vec3::Z).length() < EPS);
        assert_eq!(c.outward_normal(Vec3::new(2.0, 3.2, 0.0)), Vec3::Y);
        assert_eq!(c.outward_normal(Vec3::new(2.0, 1.0, 0.0)), Vec3::X);
        let rim = c.outward_normal(Vec3::new(2.7, 3.4, 0.0));
        assert!((rim - Vec3::new(0.6, 0.8, 0.0)).length() < EPS);
    }

    #[test]
    fn pillar_push_outside_never_pushes_into_the_sand() {
        let c = pillar();
        let p = c.push_outside(Vec3::new(2.0, 0.05, 0.1), 0.05);
        assert!(close(c.signed_distance_m(p), 0.05));
        assert!(p.y > 0.0);
        let top = c.push_outside(Vec3::new(2.1, 2.95, 0.0), 0.05);
        assert!((top - Vec3::new(2.1, 3.05, 0.0)).length() < EPS);
    }

    #[test]
    fn geometry_is_finite_and_consistent_on_a_grid_of_points() {
        for obstacle in [rock(), pillar()] {
            for i in 0..=40 {
                for j in 0..=20 {
                    let p = Vec3::new(-1.0 + 0.1 * i as f32, -0.5 + 0.25 * j as f32, 0.0);
                    let n = obstacle.outward_normal(p);
                    assert!(n.is_finite() && close(n.length(), 1.0), "{p}");
                    let q = obstacle.push_outside(p, 0.05);
                    assert!(q.is_finite());
                    assert!(obstacle.signed_distance_m(q) >= 0.05 - EPS, "{p} -> {q}");
                }
            }
        }
    }
}
