//! Where things go in the boid tank: the seed's rocks, pillars and ledges, a
//! teacher's edits to them (checked for gaps), and spawning fish, sharks and
//! stingrays clear of the rocks and of each other.

use crate::sim::common::fmath;
use std::f32::consts::TAU;

use glam::{Vec2, Vec3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

use crate::sim::boids::params::{SharkParams, StingrayParams};
use crate::sim::boids::shark::{self, MAX_SHARKS, Shark};
use crate::sim::boids::stingray::{self, MAX_STINGRAYS, Stingray};
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::{Obstacle, ObstacleError, ObstacleSet, WALL_CLEARANCE_M};
use crate::sim::common::steering::SteeringParams;
use crate::sim::common::tank::Tank;

use super::predators::push_shark_clear;
use super::world::*;

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

/// Why a teacher's obstacle edit was refused (nothing changed).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ObstacleEditError {
    #[error(transparent)]
    Invalid(#[from] ObstacleError),
    #[error("there is no obstacle number {index} (there are {count})")]
    NoSuchObstacle { index: usize, count: usize },
    #[error("the new place must be a pair of numbers")]
    PlaceNotANumber,
    #[error(
        "it is too close to obstacle {0}: keep at least {EDITED_OBSTACLE_GAP_M} m between them"
    )]
    TooClose(usize),
}

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
    push_clear(
        &mut new.body,
        tank,
        obstacles,
        &ObstacleSet::EMPTY,
        SHARK_MARGIN_M,
        SHARK_MARGIN_M,
    );
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

impl World {
    /// Keep the first `fish_count` fish (at most [`MAX_FISH_COUNT`]), or add
    /// new ones drawn from the world's random generator. Existing fish are
    /// never changed. Sharks hunting a removed fish lose it.
    pub fn set_fish_count(&mut self, fish_count: usize) {
        let fish_count = fish_count.min(MAX_FISH_COUNT);
        self.fish.truncate(fish_count);
        self.rebuild_stingray_obstacles();
        while self.fish.len() < fish_count {
            let fish = spawn_fish(&self.tank, &self.solids(), &self.params, &mut self.rng);
            self.fish.push(fish);
        }
        for shark in &mut self.sharks {
            if shark.target.is_some_and(|t| t >= fish_count) {
                shark.target = None;
            }
        }
        self.config.fish_count = fish_count;
        self.snapshot_is_last_boid_step = false;
        self.attention_ready = false;
    }

    /// Keep the first `sharks` sharks and `stingrays` stingrays, or add new ones
    /// at free places from the world's random generator (at most
    /// [`MAX_SHARKS`] = 10 and [`MAX_STINGRAYS`] = 20). Fish under a new
    /// stingray are pushed out at once.
    pub fn set_species_counts(&mut self, sharks: usize, stingrays: usize) {
        let (sharks, stingrays) = (sharks.min(MAX_SHARKS), stingrays.min(MAX_STINGRAYS));
        self.stingrays.truncate(stingrays);
        while self.stingrays.len() < stingrays {
            let ray = spawn_stingray(
                &self.tank,
                &self.obstacles,
                &mut self.rng,
                &self.world_params.stingray,
            );
            self.stingrays.push(ray);
        }
        self.sharks.truncate(sharks);
        while self.sharks.len() < sharks {
            let shark = spawn_shark(
                &self.tank,
                &self.fixed_solids,
                &mut self.rng,
                &self.world_params.shark_species,
            );
            self.sharks.push(shark);
        }
        self.config.sharks = sharks;
        self.config.stingrays = stingrays;
        self.settle();
    }

    /// Add an obstacle after checking it ([`Obstacle::validate`], and at least
    /// 0.3 m from every other obstacle); returns its index. Fish inside it are
    /// pushed out at once; stingrays too close to it move to a free place.
    pub fn add_obstacle(&mut self, obstacle: Obstacle) -> Result<usize, ObstacleEditError> {
        obstacle.validate(&self.tank)?;
        check_gap(&obstacle, &self.obstacles, None)?;
        self.obstacles.push(obstacle);
        self.obstacles_changed();
        Ok(self.obstacles.len() - 1)
    }

    /// Move obstacle `index` so that its footprint centre is at `new_floor_xz`
    /// ((x, z) in metres), keeping its shape and height. Errors if there is no
    /// such obstacle or the new place is not allowed (then nothing changes).
    pub fn move_obstacle(
        &mut self,
        index: usize,
        new_floor_xz: Vec2,
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
        moved.validate(&self.tank)?;
        check_gap(&moved, &self.obstacles, Some(index))?;
        self.obstacles[index] = moved;
        self.obstacles_changed();
        Ok(())
    }

    /// Remove obstacle `index`; `false` if there is none.
    pub fn remove_obstacle(&mut self, index: usize) -> bool {
        if index >= self.obstacles.len() {
            return false;
        }
        self.obstacles.remove(index);
        self.obstacles_changed();
        true
    }

    /// Replace all obstacles (e.g. a teacher's saved layout). Obstacles that
    /// fail [`Obstacle::validate`] are left out (and logged); overlapping ones
    /// are kept in order as long as they keep the 0.3 m gap to those before
    /// them. Everything inside the new obstacles is pushed out at once.
    pub fn set_obstacles(&mut self, obstacles: Vec<Obstacle>) {
        self.obstacles = valid_obstacles(obstacles, &self.tank);
        self.obstacles_changed();
    }

    pub(super) fn obstacles_changed(&mut self) {
        self.config.obstacles = Some(self.obstacles.clone());
        self.fixed_solids.rebuild(&self.obstacles);
        for i in 0..self.stingrays.len() {
            if !stingray_fits(
                self.stingrays[i].body.position_m,
                &self.tank,
                &self.obstacles,
                &self.world_params.stingray,
            ) {
                self.stingrays[i] = spawn_stingray(
                    &self.tank,
                    &self.obstacles,
                    &mut self.rng,
                    &self.world_params.stingray,
                );
            }
        }
        self.settle();
    }

    /// After a change of obstacles or stingrays: push every fish and shark out
    /// of everything at once, so no animal is ever inside an obstacle.
    pub(super) fn settle(&mut self) {
        self.rebuild_stingray_obstacles();
        // The urges read the obstacles and stingrays: the last step's can no
        // longer be replayed.
        self.attention_ready = false;
        for fish in &mut self.fish {
            enforce_hard_constraints(fish, &self.tank, &self.fixed_solids, &self.stingray_solids);
        }
        for shark in &mut self.sharks {
            push_shark_clear(&mut shark.body, &self.tank, &self.fixed_solids);
        }
    }

    /// A new fish at a free place at least [`SharkParams::respawn_distance_m`] from
    /// every shark (or the farthest of the places tried).
    pub(super) fn spawn_fish_far_from_sharks(&mut self) -> Fish {
        let solids = self.solids();
        let mut best: Option<(f32, Fish)> = None;
        for _ in 0..PLACEMENT_ATTEMPTS {
            let fish = spawn_fish(&self.tank, &solids, &self.params, &mut self.rng);
            let distance_m = self
                .sharks
                .iter()
                .map(|s| s.body.position_m.distance(fish.position_m))
                .fold(f32::INFINITY, f32::min);
            if distance_m >= self.world_params.shark_species.respawn_distance_m {
                return fish;
            }
            if best.is_none_or(|(d, _)| distance_m > d) {
                best = Some((distance_m, fish));
            }
        }
        match best {
            Some((_, fish)) => fish,
            None => spawn_fish(&self.tank, &solids, &self.params, &mut self.rng),
        }
    }
}
