//! Solid things in the tank that fish must swim around: rocks, pillars and
//! polygonal prisms (Lim & Tan's SIMBA paper implements "polygon, wall and rock"
//! obstacles; docs/boids.md).
//!
//! Each obstacle is described by a signed distance function (SDF): the
//! distance from a point to the obstacle's surface, negative inside. Steering
//! and the hard "no fish inside a rock" rule are both built on it.
//!
//! Obstacles are plain data (serde, internally tagged by `kind`) so that a
//! teacher's edited layout can be saved and loaded; [`Obstacle::validate`]
//! checks one against the tank before the world accepts it.

use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};

use crate::i18n::{num, tr};
use crate::sim::common::tank::Tank;
use crate::tr;

/// Smallest radius of a rock or pillar, in metres. Default 0.1 m: about a
/// third of a fish; anything smaller would not be seen as an obstacle.
pub const MIN_RADIUS_M: f32 = 0.1;

/// Largest radius of a rock or pillar, in metres. Default 1.5 m: a boulder
/// 3 m across still leaves the 8 m deep tank room to swim around it.
pub const MAX_RADIUS_M: f32 = 1.5;

/// Fewest and most corners of a polygon footprint. Default 3–12: a triangle is
/// the simplest closed shape; 12 corners draw any reef ledge a teacher needs and
/// keep the distance computation cheap.
pub const POLYGON_VERTICES: std::ops::RangeInclusive<usize> = 3..=12;

/// Smallest footprint area of a polygon, in m². Default 0.01 m² (10 cm × 10 cm):
/// rejects degenerate polygons (all corners on a line) that would have no inside.
pub const MIN_POLYGON_AREA_M2: f32 = 0.01;

/// Shortest polygon edge, in metres. Default 0.05 m: rejects repeated corners,
/// whose edge would have no direction.
pub const MIN_POLYGON_EDGE_M: f32 = 0.05;

/// Gap between an obstacle's footprint and the side walls, in metres.
/// Default 1.0 m: fish can swim behind every obstacle, and pushing a fish out
/// of an obstacle can never push it out of the tank.
pub const WALL_CLEARANCE_M: f32 = 1.0;

/// Smallest gap between an obstacle's top and the water surface, in metres.
/// Default 0.5 m: fish can always swim over an obstacle.
pub const SURFACE_CLEARANCE_M: f32 = 0.5;

/// Why an obstacle cannot be put in the tank, in words a teacher understands.
#[derive(Clone, Debug, PartialEq)]
pub enum ObstacleError {
    Radius(f32),
    NearTheGlass { x_m: f32, z_m: f32 },
    HeightNotANumber,
    OffTheSand { floor_y_m: f32, base_y_m: f32 },
    Height(f32),
    RockNotANumber,
    RockBuried,
    RockFloats,
    RockTooHigh,
    PillarNotANumber,
    Corners(usize),
    CornerNotANumber,
    CornersTooClose(usize, usize),
    Flat,
    NotConvex(usize),
}

impl std::fmt::Display for ObstacleError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let text = match *self {
            Self::Radius(radius) => tr!(
                "boids-obstacle-radius",
                min = MIN_RADIUS_M,
                max = MAX_RADIUS_M,
                radius = radius
            ),
            Self::NearTheGlass { x_m, z_m } => tr!(
                "boids-obstacle-near-the-glass",
                gap = WALL_CLEARANCE_M,
                x = num(f64::from(x_m), 2),
                z = num(f64::from(z_m), 2)
            ),
            Self::HeightNotANumber => tr("boids-obstacle-height-not-a-number"),
            Self::OffTheSand {
                floor_y_m,
                base_y_m,
            } => tr!(
                "boids-obstacle-off-the-sand",
                floor = floor_y_m,
                base = base_y_m
            ),
            Self::Height(height) => tr!(
                "boids-obstacle-height",
                gap = SURFACE_CLEARANCE_M,
                height = height
            ),
            Self::RockNotANumber => tr("boids-obstacle-rock-not-a-number"),
            Self::RockBuried => tr("boids-obstacle-rock-buried"),
            Self::RockFloats => tr("boids-obstacle-rock-floats"),
            Self::RockTooHigh => tr!("boids-obstacle-rock-too-high", gap = SURFACE_CLEARANCE_M),
            Self::PillarNotANumber => tr("boids-obstacle-pillar-not-a-number"),
            Self::Corners(count) => tr!(
                "boids-obstacle-corners",
                min = *POLYGON_VERTICES.start(),
                max = *POLYGON_VERTICES.end(),
                count = count
            ),
            Self::CornerNotANumber => tr("boids-obstacle-corner-not-a-number"),
            Self::CornersTooClose(first, second) => tr!(
                "boids-obstacle-corners-too-close",
                first = first,
                second = second,
                min = MIN_POLYGON_EDGE_M
            ),
            Self::Flat => tr!("boids-obstacle-flat", min = MIN_POLYGON_AREA_M2),
            Self::NotConvex(corner) => tr!("boids-obstacle-not-convex", corner = corner),
        };
        f.write_str(&text)
    }
}

impl std::error::Error for ObstacleError {}

/// A solid obstacle. Sizes in metres.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
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
    /// A vertical prism over a convex polygon (e.g. a reef ledge): the footprint
    /// `footprint_m` in the (x, z) plane, from `base_y_m` up to
    /// `base_y_m + height_m`. Rooted in the sand like a pillar.
    Polygon {
        /// Corners of the convex footprint as (x, z) in metres, in order around
        /// it (either direction), 3–12 of them.
        footprint_m: Vec<Vec2>,
        /// Height of the bottom face in metres (the floor).
        base_y_m: f32,
        /// Height above the base in metres.
        height_m: f32,
    },
}

impl Obstacle {
    /// Signed distance from `p_m` to the surface in metres: positive outside,
    /// zero on the surface, negative inside.
    pub fn signed_distance_m(&self, p_m: Vec3) -> f32 {
        match self {
            Obstacle::Rock { center_m, radius_m } => (p_m - *center_m).length() - radius_m,
            Obstacle::Cylinder { .. } | Obstacle::Polygon { .. } => {
                let d = self.prism_face_distances_m(p_m).0;
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
        match self {
            Obstacle::Rock { center_m, .. } => (p_m - *center_m).normalize_or(Vec3::Y),
            Obstacle::Cylinder { .. } | Obstacle::Polygon { .. } => {
                let (d, side) = self.prism_face_distances_m(p_m);
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
    /// the point of a pillar's axis (a polygon's: the vertical line through
    /// its corners' mean) at the height of `p_m`, clamped to the obstacle.
    /// Obstacle avoidance steers away from this point.
    pub fn core_point_m(&self, p_m: Vec3) -> Vec3 {
        match self {
            Obstacle::Rock { center_m, .. } => *center_m,
            Obstacle::Cylinder { .. } | Obstacle::Polygon { .. } => {
                let (base_y_m, top_y_m) = self.vertical_extent_m();
                let axis = self.footprint_center_m();
                Vec3::new(axis.x, p_m.y.max(base_y_m).min(top_y_m), axis.y)
            }
        }
    }

    /// Radius of the obstacle's bounding circle (sphere for a rock) around
    /// its core, in metres: the radius of a rock or pillar, the largest
    /// distance from a polygon's centre to a corner.
    pub fn radius_m(&self) -> f32 {
        match self {
            Obstacle::Rock { radius_m, .. } | Obstacle::Cylinder { radius_m, .. } => *radius_m,
            Obstacle::Polygon { footprint_m, .. } => {
                let c = self.footprint_center_m();
                footprint_m
                    .iter()
                    .map(|v| v.distance(c))
                    .fold(0.0, f32::max)
            }
        }
    }

    /// Centre of the footprint on the floor, (x, z) in metres: a rock's or
    /// pillar's centre, the mean of a polygon's corners.
    pub fn footprint_center_m(&self) -> Vec2 {
        match self {
            Obstacle::Rock { center_m: c, .. }
            | Obstacle::Cylinder {
                base_center_m: c, ..
            } => Vec2::new(c.x, c.z),
            Obstacle::Polygon { footprint_m, .. } => {
                footprint_m.iter().copied().sum::<Vec2>() / footprint_m.len().max(1) as f32
            }
        }
    }

    /// The same obstacle moved horizontally so that its footprint centre is at
    /// `floor_xz_m` (height unchanged).
    pub fn moved_to(&self, floor_xz_m: Vec2) -> Obstacle {
        let shift = floor_xz_m - self.footprint_center_m();
        let shift3 = Vec3::new(shift.x, 0.0, shift.y);
        match self {
            Obstacle::Rock { center_m, radius_m } => Obstacle::Rock {
                center_m: *center_m + shift3,
                radius_m: *radius_m,
            },
            Obstacle::Cylinder {
                base_center_m,
                radius_m,
                height_m,
            } => Obstacle::Cylinder {
                base_center_m: *base_center_m + shift3,
                radius_m: *radius_m,
                height_m: *height_m,
            },
            Obstacle::Polygon {
                footprint_m,
                base_y_m,
                height_m,
            } => Obstacle::Polygon {
                footprint_m: footprint_m.iter().map(|v| *v + shift).collect(),
                base_y_m: *base_y_m,
                height_m: *height_m,
            },
        }
    }

    /// Checks that the obstacle can be put in `tank`: every number finite, the
    /// footprint at least [`WALL_CLEARANCE_M`] from the glass, the top at least
    /// [`SURFACE_CLEARANCE_M`] below the surface, standing on (or, for a rock,
    /// sunk into) the sand, a radius in [`MIN_RADIUS_M`]..=[`MAX_RADIUS_M`], and a
    /// polygon with 3–12 corners that form a convex, non-degenerate footprint.
    /// The error says what is wrong in words a teacher understands.
    pub fn validate(&self, tank: &Tank) -> Result<(), ObstacleError> {
        const FLOOR_TOLERANCE_M: f32 = 0.01;
        let floor_y_m = tank.min_m.y;
        let top_limit_m = tank.max_m.y - SURFACE_CLEARANCE_M;
        let check_radius = |radius_m: f32| {
            if !radius_m.is_finite() || !(MIN_RADIUS_M..=MAX_RADIUS_M).contains(&radius_m) {
                Err(ObstacleError::Radius(radius_m))
            } else {
                Ok(())
            }
        };
        let check_inside = |p: Vec2, reach_m: f32| {
            let fits = p.x - reach_m >= tank.min_m.x + WALL_CLEARANCE_M - 1e-4
                && p.x + reach_m <= tank.max_m.x - WALL_CLEARANCE_M + 1e-4
                && p.y - reach_m >= tank.min_m.z + WALL_CLEARANCE_M - 1e-4
                && p.y + reach_m <= tank.max_m.z - WALL_CLEARANCE_M + 1e-4;
            if fits {
                Ok(())
            } else {
                Err(ObstacleError::NearTheGlass { x_m: p.x, z_m: p.y })
            }
        };
        let check_height = |base_y_m: f32, height_m: f32| {
            if !base_y_m.is_finite() || !height_m.is_finite() {
                return Err(ObstacleError::HeightNotANumber);
            }
            if (base_y_m - floor_y_m).abs() > FLOOR_TOLERANCE_M {
                return Err(ObstacleError::OffTheSand {
                    floor_y_m,
                    base_y_m,
                });
            }
            if height_m <= 0.0 || base_y_m + height_m > top_limit_m {
                return Err(ObstacleError::Height(height_m));
            }
            Ok(())
        };
        match self {
            Obstacle::Rock { center_m, radius_m } => {
                if !center_m.is_finite() {
                    return Err(ObstacleError::RockNotANumber);
                }
                check_radius(*radius_m)?;
                check_inside(Vec2::new(center_m.x, center_m.z), *radius_m)?;
                if center_m.y + radius_m <= floor_y_m + MIN_RADIUS_M {
                    return Err(ObstacleError::RockBuried);
                }
                if center_m.y - radius_m > floor_y_m + FLOOR_TOLERANCE_M {
                    return Err(ObstacleError::RockFloats);
                }
                if center_m.y + radius_m > top_limit_m {
                    return Err(ObstacleError::RockTooHigh);
                }
                Ok(())
            }
            Obstacle::Cylinder {
                base_center_m,
                radius_m,
                height_m,
            } => {
                if !base_center_m.is_finite() {
                    return Err(ObstacleError::PillarNotANumber);
                }
                check_radius(*radius_m)?;
                check_inside(Vec2::new(base_center_m.x, base_center_m.z), *radius_m)?;
                check_height(base_center_m.y, *height_m)
            }
            Obstacle::Polygon {
                footprint_m,
                base_y_m,
                height_m,
            } => {
                if !POLYGON_VERTICES.contains(&footprint_m.len()) {
                    return Err(ObstacleError::Corners(footprint_m.len()));
                }
                if footprint_m.iter().any(|v| !v.is_finite()) {
                    return Err(ObstacleError::CornerNotANumber);
                }
                for v in footprint_m {
                    check_inside(*v, 0.0)?;
                }
                let n = footprint_m.len();
                for i in 0..n {
                    if footprint_m[i].distance(footprint_m[(i + 1) % n]) < MIN_POLYGON_EDGE_M {
                        return Err(ObstacleError::CornersTooClose(i + 1, (i + 1) % n + 1));
                    }
                }
                let area_m2 = signed_area_m2(footprint_m);
                if area_m2.abs() < MIN_POLYGON_AREA_M2 {
                    return Err(ObstacleError::Flat);
                }
                // Convex: every turn goes the same way as the whole outline.
                for i in 0..n {
                    let (a, b, c) = (
                        footprint_m[i],
                        footprint_m[(i + 1) % n],
                        footprint_m[(i + 2) % n],
                    );
                    if (b - a).perp_dot(c - b) * area_m2.signum() < 0.0 {
                        return Err(ObstacleError::NotConvex((i + 1) % n + 1));
                    }
                }
                check_height(*base_y_m, *height_m)
            }
        }
    }

    /// Lowest and highest y of the obstacle, in metres.
    pub fn vertical_extent_m(&self) -> (f32, f32) {
        match self {
            Obstacle::Rock { center_m, radius_m } => (center_m.y - radius_m, center_m.y + radius_m),
            Obstacle::Cylinder {
                base_center_m: Vec3 { y, .. },
                height_m,
                ..
            }
            | Obstacle::Polygon {
                base_y_m: y,
                height_m,
                ..
            } => (*y, *y + height_m.max(0.0)),
        }
    }

    /// For a pillar or polygon prism: (distance outside the side wall, distance
    /// above the top), each negative when inside that face, and the horizontal
    /// unit direction out through the nearest side.
    fn prism_face_distances_m(&self, p_m: Vec3) -> (Vec2, Vec3) {
        match self {
            Obstacle::Cylinder {
                base_center_m,
                radius_m,
                height_m,
            } => {
                let offset = p_m - *base_center_m;
                let radial = Vec2::new(offset.x, offset.z);
                let side = Vec3::new(radial.x, 0.0, radial.y).normalize_or(Vec3::X);
                (
                    Vec2::new(radial.length() - radius_m, offset.y - height_m),
                    side,
                )
            }
            Obstacle::Polygon {
                footprint_m,
                base_y_m,
                height_m,
            } => {
                let (distance_m, side) = polygon_distance_m(footprint_m, Vec2::new(p_m.x, p_m.z));
                (
                    Vec2::new(distance_m, p_m.y - base_y_m - height_m),
                    Vec3::new(side.x, 0.0, side.y),
                )
            }
            Obstacle::Rock { .. } => (Vec2::ZERO, Vec3::Y),
        }
    }
}

/// Obstacles with their bounding cylinders, for a cheap broad phase: most fish
/// are nowhere near most obstacles, and a fish far from every one skips the
/// signed-distance work entirely.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ObstacleSet {
    obstacles: Vec<Obstacle>,
    bounds: Vec<Bounds>,
    max_radius_m: f32,
}

/// A vertical cylinder that holds an obstacle: footprint centre and radius
/// (the obstacle's bounding circle), and its lowest and highest y (a rooted
/// pillar or polygon reaches down without end).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Bounds {
    center_xz_m: Vec2,
    radius_m: f32,
    bottom_y_m: f32,
    top_y_m: f32,
}

impl ObstacleSet {
    /// A set with no obstacles.
    pub const EMPTY: Self = Self {
        obstacles: Vec::new(),
        bounds: Vec::new(),
        max_radius_m: 0.0,
    };

    /// Replaces the set's obstacles with copies of `obstacles`.
    pub fn rebuild<'a>(&mut self, obstacles: impl IntoIterator<Item = &'a Obstacle>) {
        self.obstacles.clear();
        self.obstacles.extend(obstacles.into_iter().cloned());
        self.bounds.clear();
        self.bounds.extend(self.obstacles.iter().map(|o| {
            let (bottom_y_m, top_y_m) = match o {
                Obstacle::Rock { .. } => o.vertical_extent_m(),
                _ => (f32::NEG_INFINITY, o.vertical_extent_m().1),
            };
            Bounds {
                center_xz_m: o.footprint_center_m(),
                radius_m: o.radius_m(),
                bottom_y_m,
                top_y_m,
            }
        }));
        self.max_radius_m = self.bounds.iter().map(|b| b.radius_m).fold(0.0, f32::max);
    }

    /// All obstacles of the set.
    pub fn as_slice(&self) -> &[Obstacle] {
        &self.obstacles
    }

    /// The largest bounding radius of an obstacle in the set, metres.
    pub fn max_radius_m(&self) -> f32 {
        self.max_radius_m
    }

    /// Number of obstacles in the set.
    pub fn len(&self) -> usize {
        self.obstacles.len()
    }

    /// Is the set empty?
    pub fn is_empty(&self) -> bool {
        self.obstacles.is_empty()
    }

    /// Obstacle `k` if its surface may lie within `reach_m` of `p_m` (`None`
    /// when it certainly does not, or there is no obstacle `k`).
    pub fn get_if_near(&self, k: usize, p_m: Vec3, reach_m: f32) -> Option<&Obstacle> {
        let b = self.bounds.get(k)?;
        let r = b.radius_m + reach_m;
        let near = p_m.y <= b.top_y_m + reach_m
            && p_m.y >= b.bottom_y_m - reach_m
            && Vec2::new(p_m.x, p_m.z).distance_squared(b.center_xz_m) <= r * r;
        near.then(|| &self.obstacles[k])
    }

    /// The obstacles whose surface may lie within `reach_m` of `p_m` (a
    /// superset: every obstacle closer than `reach_m` is among them).
    pub fn near(&self, p_m: Vec3, reach_m: f32) -> impl Iterator<Item = &Obstacle> + '_ {
        (0..self.len()).filter_map(move |k| self.get_if_near(k, p_m, reach_m))
    }
}

/// The signed area of a closed polygon in m² (shoelace formula),
/// positive for counter-clockwise corners in the (x, z) plane.
pub fn signed_area_m2(vertices_m: &[Vec2]) -> f32 {
    let n = vertices_m.len();
    (0..n)
        .map(|i| vertices_m[i].perp_dot(vertices_m[(i + 1) % n]))
        .sum::<f32>()
        * 0.5
}

/// Signed distance from `q` to a convex polygon's outline in the plane
/// (negative inside) and the unit direction out of the polygon there: away
/// from the nearest outline point outside, the nearest edge's outward normal
/// inside. A polygon with fewer than 3 corners has no inside.
fn polygon_distance_m(vertices_m: &[Vec2], q: Vec2) -> (f32, Vec2) {
    let n = vertices_m.len();
    if n == 0 {
        return (f32::INFINITY, Vec2::X);
    }
    let orientation = signed_area_m2(vertices_m).signum();
    let mut best_d2 = f32::INFINITY;
    let mut best_point = vertices_m[0];
    let mut best_edge_normal = Vec2::X;
    let mut inside = n >= 3 && orientation != 0.0;
    for i in 0..n {
        let (a, b) = (vertices_m[i], vertices_m[(i + 1) % n]);
        let edge = b - a;
        let t = ((q - a).dot(edge) / edge.length_squared().max(1e-12)).clamp(0.0, 1.0);
        let point = a + edge * t;
        let d2 = q.distance_squared(point);
        // Outward normal: right of the edge for a counter-clockwise outline.
        let normal = Vec2::new(edge.y, -edge.x).normalize_or_zero() * orientation;
        if d2 < best_d2 {
            best_d2 = d2;
            best_point = point;
            best_edge_normal = normal;
        }
        if (q - a).dot(normal) > 0.0 {
            inside = false;
        }
    }
    let distance_m = best_d2.sqrt();
    if inside {
        (-distance_m, best_edge_normal.normalize_or(Vec2::X))
    } else {
        (
            distance_m,
            (q - best_point).normalize_or(best_edge_normal.normalize_or(Vec2::X)),
        )
    }
}

/// The convex hull of `points` (Andrew's monotone chain), counter-clockwise in
/// the (x, z) plane, without repeated or collinear corners.
pub fn convex_hull(points: &[Vec2]) -> Vec<Vec2> {
    let mut sorted: Vec<Vec2> = points.iter().copied().filter(|p| p.is_finite()).collect();
    sorted.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    sorted.dedup();
    if sorted.len() < 3 {
        return sorted;
    }
    let mut hull: Vec<Vec2> = Vec::with_capacity(sorted.len() * 2);
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &Vec2>> = if pass == 0 {
            Box::new(sorted.iter())
        } else {
            Box::new(sorted.iter().rev())
        };
        for &p in iter {
            while hull.len() >= start + 2 {
                let (a, b) = (hull[hull.len() - 2], hull[hull.len() - 1]);
                if (b - a).perp_dot(p - b) <= 0.0 {
                    hull.pop();
                } else {
                    break;
                }
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

#[cfg(test)]
mod tests {
    use crate::sim::common::obstacle::*;

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

    /// A reef ledge: a 2 m × 1 m box footprint from x = 1..3, z = −0.5..0.5,
    /// 0.8 m high, corners counter-clockwise.
    fn ledge() -> Obstacle {
        Obstacle::Polygon {
            footprint_m: vec![
                Vec2::new(1.0, -0.5),
                Vec2::new(3.0, -0.5),
                Vec2::new(3.0, 0.5),
                Vec2::new(1.0, 0.5),
            ],
            base_y_m: 0.0,
            height_m: 0.8,
        }
    }

    #[test]
    fn polygon_signed_distance_to_sides_corner_top_and_inside() {
        let l = ledge();
        // Beside a long side, off a corner (a 3-4-5 triangle), above the top.
        assert!(close(l.signed_distance_m(Vec3::new(2.0, 0.4, 1.5)), 1.0));
        assert!(close(l.signed_distance_m(Vec3::new(3.3, 0.4, 0.9)), 0.5));
        assert!(close(l.signed_distance_m(Vec3::new(2.0, 1.3, 0.0)), 0.5));
        // Inside: the nearest face, the sand never counts.
        assert!(close(l.signed_distance_m(Vec3::new(2.0, 0.4, 0.4)), -0.1));
        assert!(close(l.signed_distance_m(Vec3::new(2.0, 0.7, 0.0)), -0.1));
        assert!(close(l.signed_distance_m(Vec3::new(2.0, 0.05, 0.0)), -0.5));
        // The same whichever way round the corners are listed.
        let Obstacle::Polygon { footprint_m, .. } = ledge() else {
            unreachable!()
        };
        let clockwise = Obstacle::Polygon {
            footprint_m: footprint_m.into_iter().rev().collect(),
            base_y_m: 0.0,
            height_m: 0.8,
        };
        for p in [Vec3::new(3.3, 0.4, 0.9), Vec3::new(2.0, 0.4, 0.4)] {
            assert!(close(
                clockwise.signed_distance_m(p),
                l.signed_distance_m(p)
            ));
        }
    }

    #[test]
    fn polygon_normals_point_out_through_the_nearest_side_corner_or_top() {
        let l = ledge();
        let side = l.outward_normal(Vec3::new(2.0, 0.4, 1.5));
        assert!((side - Vec3::Z).length() < EPS, "{side}");
        let corner = l.outward_normal(Vec3::new(3.3, 0.4, 0.9));
        assert!(
            (corner - Vec3::new(0.6, 0.0, 0.8)).length() < EPS,
            "{corner}"
        );
        assert_eq!(l.outward_normal(Vec3::new(2.0, 1.3, 0.0)), Vec3::Y);
        let inside_near_side = l.outward_normal(Vec3::new(2.8, 0.2, 0.0));
        assert!((inside_near_side - Vec3::X).length() < EPS);
        let pushed = l.push_outside(Vec3::new(2.8, 0.2, 0.0), 0.05);
        assert!(
            (pushed - Vec3::new(3.05, 0.2, 0.0)).length() < EPS,
            "{pushed}"
        );
    }

    #[test]
    fn validate_explains_what_is_wrong_in_plain_words() {
        let tank = Tank::default();
        let error = |o: Obstacle| o.validate(&tank).unwrap_err().to_string();
        assert_eq!(ledge().validate(&tank), Ok(()));
        assert!(
            error(Obstacle::Rock {
                center_m: Vec3::new(0.0, 0.0, 0.0),
                radius_m: 3.0,
            })
            .contains("radius must be between")
        );
        assert!(
            error(Obstacle::Cylinder {
                base_center_m: Vec3::new(5.5, 0.0, 0.0),
                radius_m: 0.3,
                height_m: 1.0,
            })
            .contains("away from the glass")
        );
        assert!(
            error(Obstacle::Rock {
                center_m: Vec3::new(0.0, 2.0, 0.0),
                radius_m: 0.5,
            })
            .contains("floats")
        );
        assert!(
            error(Obstacle::Rock {
                center_m: Vec3::new(0.0, -0.5, 0.0),
                radius_m: 0.5,
            })
            .contains("buried")
        );
        assert!(
            error(Obstacle::Cylinder {
                base_center_m: Vec3::new(0.0, 0.0, 0.0),
                radius_m: 0.3,
                height_m: 4.4,
            })
            .contains("below the surface")
        );
        assert!(
            error(Obstacle::Cylinder {
                base_center_m: Vec3::new(0.0, 1.0, 0.0),
                radius_m: 0.3,
                height_m: 1.0,
            })
            .contains("stand on the sand")
        );
        let polygon = |corners: &[(f32, f32)]| Obstacle::Polygon {
            footprint_m: corners.iter().map(|&(x, z)| Vec2::new(x, z)).collect(),
            base_y_m: 0.0,
            height_m: 1.0,
        };
        assert!(error(polygon(&[(0.0, 0.0), (1.0, 0.0)])).contains("3 to 12 corners"));
        assert!(
            error(polygon(&[(0.0, 0.0), (1.0, 0.0), (1.0, 0.01), (0.0, 0.0)]))
                .contains("closer than")
        );
        assert!(error(polygon(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)])).contains("flat"));
        assert!(
            error(polygon(&[
                (0.0, 0.0),
                (2.0, 0.0),
                (1.0, 0.5),
                (2.0, 2.0),
                (0.0, 2.0)
            ]))
            .contains("convex")
        );
        assert!(
            error(polygon(&[(0.0, 0.0), (f32::NAN, 0.0), (1.0, 1.0)])).contains("pair of numbers")
        );
    }

    #[test]
    fn the_set_broad_phase_never_misses_a_near_obstacle() {
        let obstacles = [rock(), pillar(), ledge()];
        let mut set = ObstacleSet::default();
        set.rebuild(&obstacles);
        assert_eq!(set.len(), 3);
        for i in 0..=60 {
            for j in 0..=24 {
                let p = Vec3::new(-1.0 + 0.1 * i as f32, -0.5 + 0.25 * j as f32, 0.3);
                for reach_m in [0.0, 0.05, 1.0] {
                    let near: Vec<&Obstacle> = set.near(p, reach_m).collect();
                    for o in &obstacles {
                        if o.signed_distance_m(p) < reach_m {
                            assert!(near.contains(&o), "{p} {reach_m} {o:?}");
                        }
                    }
                }
            }
        }
        assert_eq!(set.near(Vec3::new(-5.0, 4.0, 3.0), 0.5).count(), 0);
    }
}
