//! Where things go in the boid tank: the seed's rocks, pillars and ledges, a
//! teacher's edits to them (checked for gaps), and spawning fish, sharks and
//! stingrays clear of the rocks and of each other. The placement stage of the
//! world ([`Scenery`]) owns the fixed obstacles; the spawning functions take
//! the tank, what to keep clear of and the world's generator as inputs.

use crate::sim::common::fmath;
use std::f32::consts::TAU;

use glam::{Vec2, Vec3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

use super::hard_rules::push_shark_clear;
use super::params::{SharkParams, StingrayParams};
use super::shark::{self, Shark};
use super::stingray::{self, Stingray};
use crate::i18n::tr;
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::{Obstacle, ObstacleError, ObstacleSet, WALL_CLEARANCE_M};
use crate::sim::common::steering::SteeringParams;
use crate::sim::common::tank::Tank;
use crate::tr;

/// Smallest gap between the footprints of two obstacles, in metres.
/// Default 0.8 m: wide enough for fish (with their avoidance clearance) to
/// swim between, and obstacles never overlap.
pub(super) const OBSTACLE_GAP_M: f32 = 0.8;

/// Smallest gap between a teacher's obstacle and the others, in metres.
/// Default 0.3 m: about one fish length, so a fish pushed out of one obstacle
/// never lands in another.
const EDITED_OBSTACLE_GAP_M: f32 = 0.3;

/// Random positions tried per obstacle or animal before giving up (obstacle)
/// or falling back to a pushed-out position (animal). Default 200: placement
/// practically always succeeds in the default tank, and the loop is bounded.
const PLACEMENT_ATTEMPTS: usize = 200;

/// Distance from walls and obstacle surfaces at which new fish appear, in
/// metres. Default 0.3 m: about one body length, so no fish starts touching
/// anything.
const SPAWN_CLEARANCE_M: f32 = 0.3;

/// Obstacles from a user's list that pass [`Obstacle::validate`] and keep the
/// gap to the ones before them; the others are logged and left out.
pub(super) fn valid_obstacles(obstacles: Vec<Obstacle>, tank: &Tank) -> Vec<Obstacle> {
    let mut kept: Vec<Obstacle> = Vec::with_capacity(obstacles.len());
    for (i, obstacle) in obstacles.into_iter().enumerate() {
        match obstacle
            .validate(tank)
            .map_err(ObstacleEditError::from)
            .and_then(|()| check_gap(&obstacle, &kept, None))
        {
            Ok(()) => kept.push(obstacle),
            Err(reason) => log::warn!("obstacle {i} left out: {reason}"),
        }
    }
    kept
}

/// Would a world keep every one of `obstacles` ([`valid_obstacles`] leaves
/// none out)? If not, the first it would leave out and why: the panel refuses
/// such an edit with this reason instead of letting the rock vanish.
pub fn check_obstacles(
    obstacles: &[Obstacle],
    tank: &Tank,
) -> Result<(), (usize, ObstacleEditError)> {
    for (i, obstacle) in obstacles.iter().enumerate() {
        obstacle
            .validate(tank)
            .map_err(ObstacleEditError::from)
            .and_then(|()| check_gap(obstacle, &obstacles[..i], None))
            .map_err(|reason| (i, reason))?;
    }
    Ok(())
}

/// Why a teacher's obstacle edit was refused (nothing changed).
#[derive(Clone, Debug, PartialEq)]
pub enum ObstacleEditError {
    Invalid(ObstacleError),
    NoSuchObstacle { index: usize, count: usize },
    PlaceNotANumber,
    TooClose(usize),
}

impl From<ObstacleError> for ObstacleEditError {
    fn from(e: ObstacleError) -> Self {
        Self::Invalid(e)
    }
}

impl std::fmt::Display for ObstacleEditError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let text = match self {
            Self::Invalid(e) => return std::fmt::Display::fmt(e, f),
            Self::NoSuchObstacle { index, count } => {
                tr!("boids-obstacle-no-such", index = *index, count = *count)
            }
            Self::PlaceNotANumber => tr("boids-obstacle-place-not-a-number"),
            Self::TooClose(other) => tr!(
                "boids-obstacle-too-close",
                other = *other,
                gap = EDITED_OBSTACLE_GAP_M
            ),
        };
        f.write_str(&text)
    }
}

impl std::error::Error for ObstacleEditError {}

/// Is `obstacle` at least [`EDITED_OBSTACLE_GAP_M`] from each of `others`
/// (except number `skip`)? Judged on the floor footprints: each footprint's
/// bounding circle against the other's shape.
pub(super) fn check_gap(
    obstacle: &Obstacle,
    others: &[Obstacle],
    skip: Option<usize>,
) -> Result<(), ObstacleEditError> {
    for (j, other) in others.iter().enumerate() {
        if Some(j) == skip {
            continue;
        }
        let gap_m = footprint_gap_m(obstacle, other).min(footprint_gap_m(other, obstacle));
        if gap_m < EDITED_OBSTACLE_GAP_M {
            return Err(ObstacleEditError::TooClose(j));
        }
    }
    Ok(())
}

/// A lower bound of the horizontal gap between `a`'s footprint and `b`: `b`'s
/// signed distance, at the sand, from `a`'s footprint centre, minus `a`'s
/// bounding radius.
pub(super) fn footprint_gap_m(a: &Obstacle, b: &Obstacle) -> f32 {
    let c = a.footprint_center_m();
    let (base_y_m, _) = b.vertical_extent_m();
    let probe_m = Vec3::new(c.x, base_y_m.max(0.0) + 0.01, c.y);
    b.signed_distance_m(probe_m) - a.radius_m()
}

/// May a stingray (`ray`) have its centre at `p_m`? Its wing tips keep
/// [`StingrayParams::gap_m`] from the glass and from every obstacle
/// (measured at the sand, where a half-buried rock is widest).
pub(super) fn stingray_fits(
    p_m: Vec3,
    tank: &Tank,
    obstacles: &[Obstacle],
    ray: &StingrayParams,
) -> bool {
    let reach_m = ray.radius_m + ray.gap_m;
    let (lo, hi) = (tank.min_m, tank.max_m);
    let inside = p_m.x >= lo.x + reach_m
        && p_m.x <= hi.x - reach_m
        && p_m.z >= lo.z + reach_m
        && p_m.z <= hi.z - reach_m;
    let at_sand_m = Vec3::new(p_m.x, lo.y + 0.01, p_m.z);
    inside
        && obstacles
            .iter()
            .all(|o| o.signed_distance_m(at_sand_m) >= reach_m)
}

/// A uniform random number between `lo` and `hi` (never panics).
pub(super) fn uniform(rng: &mut ChaCha8Rng, lo: f32, hi: f32) -> f32 {
    lo + (hi - lo) * rng.random::<f32>()
}

/// Where an obstacle meets the floor: centre (x, z) and bounding radius in metres.
pub(super) fn footprint(obstacle: &Obstacle) -> (Vec2, f32) {
    (obstacle.footprint_center_m(), obstacle.radius_m())
}

/// 4–6 rocks (radius 0.4–1.0 m, centre at or up to 0.3 radii below the sand,
/// i.e. about half-buried), 2–3 pillars (radius 0.25–0.5 m, height 1.5–3.5 m)
/// and, on half of the seeds, one reef ledge (a convex polygon of 5–7 corners,
/// 1.0–1.6 m across its bounding circle and stretched to a ledge, 0.4–0.9 m
/// high) at random places that keep [`WALL_CLEARANCE_M`] from the glass and
/// [`OBSTACLE_GAP_M`] from each other. An obstacle that finds no place in
/// [`PLACEMENT_ATTEMPTS`] tries is left out.
pub(super) fn place_obstacles(tank: &Tank, rng: &mut ChaCha8Rng) -> Vec<Obstacle> {
    let rock_count = rng.random_range(4..=6);
    let pillar_count = rng.random_range(2..=3);
    let ledge_count = usize::from(rng.random::<bool>());
    let mut obstacles: Vec<Obstacle> = Vec::new();
    // The ledge first: it is the largest and hardest to fit.
    let kinds = std::iter::repeat_n(2, ledge_count)
        .chain(std::iter::repeat_n(0, rock_count))
        .chain(std::iter::repeat_n(1, pillar_count));
    for kind in kinds {
        for _ in 0..PLACEMENT_ATTEMPTS {
            let radius_m = match kind {
                0 => uniform(rng, 0.4, 1.0),
                1 => uniform(rng, 0.25, 0.5),
                _ => uniform(rng, 1.0, 1.6),
            };
            let edge_m = WALL_CLEARANCE_M + radius_m;
            let x_m = uniform(rng, tank.min_m.x + edge_m, tank.max_m.x - edge_m);
            let z_m = uniform(rng, tank.min_m.z + edge_m, tank.max_m.z - edge_m);
            let candidate = match kind {
                0 => {
                    let buried_m = uniform(rng, 0.0, 0.3) * radius_m;
                    Obstacle::Rock {
                        center_m: Vec3::new(x_m, tank.min_m.y - buried_m, z_m),
                        radius_m,
                    }
                }
                1 => Obstacle::Cylinder {
                    base_center_m: Vec3::new(x_m, tank.min_m.y, z_m),
                    radius_m,
                    height_m: uniform(rng, 1.5, 3.5),
                },
                _ => reef_ledge(Vec2::new(x_m, z_m), radius_m, tank.min_m.y, rng),
            };
            let (center, bound_m) = footprint(&candidate);
            let fits = obstacles.iter().all(|other| {
                let (other_center, other_radius_m) = footprint(other);
                other_center.distance(center) >= bound_m + other_radius_m + OBSTACLE_GAP_M
            }) && candidate.validate(tank).is_ok();
            if fits {
                obstacles.push(candidate);
                break;
            }
        }
    }
    obstacles
}

/// A reef ledge: 5–7 corners on an ellipse (semi-axes `radius_m` and 0.4–0.7 of
/// it, turned at random) around `center_m`, 0.4–0.9 m high. Corners on an
/// ellipse always make a convex polygon.
pub(super) fn reef_ledge(
    center_m: Vec2,
    radius_m: f32,
    floor_y_m: f32,
    rng: &mut ChaCha8Rng,
) -> Obstacle {
    let corners = rng.random_range(5..=7);
    let minor = uniform(rng, 0.4, 0.7);
    let turn_rad = uniform(rng, 0.0, TAU);
    let (sin_t, cos_t) = fmath::sin_cos(turn_rad);
    let footprint_m = (0..corners)
        .map(|k| {
            let a = k as f32 * TAU / corners as f32;
            let local = Vec2::new(fmath::cos(a) * radius_m, fmath::sin(a) * radius_m * minor);
            center_m
                + Vec2::new(
                    local.x * cos_t - local.y * sin_t,
                    local.x * sin_t + local.y * cos_t,
                )
        })
        .collect();
    Obstacle::Polygon {
        footprint_m,
        base_y_m: floor_y_m,
        height_m: uniform(rng, 0.4, 0.9),
    }
}

/// A new fish at a random free place (at least [`SPAWN_CLEARANCE_M`] from
/// glass and obstacles), swimming in a random, nearly level direction at a
/// relaxed speed, 0.3–0.5 m long, with a random colour and tail phase.
pub(super) fn spawn_fish(
    tank: &Tank,
    obstacles: &[Obstacle],
    params: &SteeringParams,
    rng: &mut ChaCha8Rng,
) -> Fish {
    let is_free = |p: Vec3| {
        tank.contains(p, SPAWN_CLEARANCE_M)
            && obstacles
                .iter()
                .all(|o| o.signed_distance_m(p) >= SPAWN_CLEARANCE_M)
    };
    let mut position_m = random_point(tank, rng);
    for _ in 0..PLACEMENT_ATTEMPTS {
        if is_free(position_m) {
            break;
        }
        position_m = random_point(tank, rng);
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
        fmath::cos(yaw_rad) * fmath::cos(pitch_rad),
        fmath::sin(pitch_rad),
        fmath::sin(yaw_rad) * fmath::cos(pitch_rad),
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

/// A uniformly random point in the tank.
pub(super) fn random_point(tank: &Tank, rng: &mut ChaCha8Rng) -> Vec3 {
    let u = Vec3::new(rng.random(), rng.random(), rng.random());
    tank.min_m + u * tank.size_m()
}

/// A new shark, 1.5–2 m long, at a random place at least 1 m from the glass,
/// the floor, the surface and every obstacle, cruising level in a random
/// direction.
pub(super) fn spawn_shark(
    tank: &Tank,
    obstacles: &ObstacleSet,
    rng: &mut ChaCha8Rng,
    species: &SharkParams,
) -> Shark {
    const CLEARANCE_M: f32 = 1.0;
    let mut position_m = tank.center_m();
    for _ in 0..PLACEMENT_ATTEMPTS {
        let p = random_point(tank, rng);
        if tank.contains(p, CLEARANCE_M)
            && obstacles
                .as_slice()
                .iter()
                .all(|o| o.signed_distance_m(p) >= CLEARANCE_M)
        {
            position_m = p;
            break;
        }
    }
    let length_m = uniform(rng, species.min_length_m, species.max_length_m);
    let mut new = shark::new_shark(position_m, uniform(rng, 0.0, TAU), length_m, species);
    push_shark_clear(&mut new.body, tank, obstacles);
    new
}

/// A new stingray at a random place where it fits ([`stingray_fits`]), at a
/// random glide height, heading in a random direction. If no place is found
/// (a tank crammed with obstacles) it starts in the middle of the tank.
pub(super) fn spawn_stingray(
    tank: &Tank,
    obstacles: &[Obstacle],
    rng: &mut ChaCha8Rng,
    ray: &StingrayParams,
) -> Stingray {
    let floor_y_m = tank.min_m.y;
    let mut position_m = Vec3::new(
        tank.center_m().x,
        floor_y_m + ray.min_glide_height_m,
        tank.center_m().z,
    );
    for _ in 0..PLACEMENT_ATTEMPTS {
        let p = random_point(tank, rng);
        let height_m = uniform(rng, ray.min_glide_height_m, ray.max_glide_height_m);
        let p = Vec3::new(p.x, floor_y_m + height_m, p.z);
        if stingray_fits(p, tank, obstacles, ray) {
            position_m = p;
            break;
        }
    }
    stingray::new_stingray(position_m, uniform(rng, 0.0, TAU), floor_y_m, ray)
}

/// A new fish at a free place (clear of `solids`) at least
/// [`SharkParams::respawn_distance_m`] from every one of `sharks` (or the
/// farthest of the places tried): the replacement of a caught fish.
pub(super) fn spawn_fish_far_from_sharks(
    sharks: &[Shark],
    tank: &Tank,
    solids: &[Obstacle],
    params: &SteeringParams,
    species: &SharkParams,
    rng: &mut ChaCha8Rng,
) -> Fish {
    let mut best: Option<(f32, Fish)> = None;
    for _ in 0..PLACEMENT_ATTEMPTS {
        let fish = spawn_fish(tank, solids, params, rng);
        let distance_m = sharks
            .iter()
            .map(|s| s.body.position_m.distance(fish.position_m))
            .fold(f32::INFINITY, f32::min);
        if distance_m >= species.respawn_distance_m {
            return fish;
        }
        if best.is_none_or(|(d, _)| distance_m > d) {
            best = Some((distance_m, fish));
        }
    }
    match best {
        Some((_, fish)) => fish,
        None => spawn_fish(tank, solids, params, rng),
    }
}

/// The fixed obstacles (rocks, pillars, ledges: the seed's or a teacher's)
/// with their bounds for the hard rule's broad phase. Every edit is checked
/// ([`Obstacle::validate`] and the gap to the others) before it is made.
#[derive(Clone, Debug, Default)]
pub(super) struct Scenery {
    obstacles: Vec<Obstacle>,
    /// The same obstacles with their bounds.
    solids: ObstacleSet,
}

impl Scenery {
    /// Scenery of exactly `obstacles` (already checked).
    pub(super) fn new(obstacles: Vec<Obstacle>) -> Self {
        let mut scenery = Self {
            obstacles,
            solids: ObstacleSet::default(),
        };
        scenery.solids.rebuild(&scenery.obstacles);
        scenery
    }

    /// Rocks, pillars and polygons.
    pub(super) fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }

    /// The obstacles with their bounds (the hard rule's broad phase).
    pub(super) fn solids(&self) -> &ObstacleSet {
        &self.solids
    }

    /// Adds `obstacle` after checking it ([`Obstacle::validate`], and at least
    /// [`EDITED_OBSTACLE_GAP_M`] from every other obstacle); returns its index.
    pub(super) fn add(
        &mut self,
        obstacle: Obstacle,
        tank: &Tank,
    ) -> Result<usize, ObstacleEditError> {
        obstacle.validate(tank)?;
        check_gap(&obstacle, &self.obstacles, None)?;
        self.obstacles.push(obstacle);
        self.solids.rebuild(&self.obstacles);
        Ok(self.obstacles.len() - 1)
    }

    /// Moves obstacle `index` so that its footprint centre is at `new_floor_xz`
    /// ((x, z) in metres), keeping its shape and height, if there is such an
    /// obstacle and the new place is allowed (otherwise nothing changes).
    pub(super) fn move_to(
        &mut self,
        index: usize,
        new_floor_xz: Vec2,
        tank: &Tank,
    ) -> Result<(), ObstacleEditError> {
        let Some(old) = self.obstacles.get(index) else {
            return Err(ObstacleEditError::NoSuchObstacle {
                index,
                count: self.obstacles.len(),
            });
        };
        if !new_floor_xz.is_finite() {
            return Err(ObstacleEditError::PlaceNotANumber);
        }
        let moved = old.moved_to(new_floor_xz);
        moved.validate(tank)?;
        check_gap(&moved, &self.obstacles, Some(index))?;
        self.obstacles[index] = moved;
        self.solids.rebuild(&self.obstacles);
        Ok(())
    }

    /// Removes obstacle `index`; `false` if there is none.
    pub(super) fn remove(&mut self, index: usize) -> bool {
        if index >= self.obstacles.len() {
            return false;
        }
        self.obstacles.remove(index);
        self.solids.rebuild(&self.obstacles);
        true
    }

    /// Replaces all obstacles by those of `obstacles` that pass
    /// [`valid_obstacles`].
    pub(super) fn replace(&mut self, obstacles: Vec<Obstacle>, tank: &Tank) {
        *self = Self::new(valid_obstacles(obstacles, tank));
    }
}
