//! The predators and fear stage of the boid step: sharks hunt (with the
//! confusion effect) and may catch a fish, stingrays glide over the sand and
//! become obstacles, and fish that see or sense a shark flee (escape force)
//! and alarm the neighbours that heed them.

use crate::sim::common::fmath;
use glam::Vec3;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

use super::forces::{self, Perception};
use super::hard_rules::push_shark_clear;
use super::params::{BoidWorldParams, DT_SECS};
use super::placement::{self, stingray_fits};
use super::shark::{self, MAX_SHARKS, Shark};
use super::stingray::{self, MAX_STINGRAYS, Stingray};
use crate::sim::common::fish::{Fish, heading_of};
use crate::sim::common::obstacle::{Obstacle, ObstacleSet};
use crate::sim::common::spatial_grid::{Nearest, SpatialGrid};
use crate::sim::common::steering::{self, SteeringParams};
use crate::sim::common::tank::Tank;

/// The escape force of a fish and how urgent it is (0–1), or `None` when the
/// fish is calm. A fish that notices a shark (within
/// [`BoidWorldParams::fear_radius_m`] inside its 300° field of view, or within
/// [`BoidWorldParams::lateral_line_m`] from any direction) [`steering::evade`]s
/// the nearest one it notices, at full urgency within the lateral line's range
/// fading to a quarter at the fear radius (a distant shark makes the school veer
/// away together rather than scatter). A fish that notices none but is alarmed by
/// frightened neighbours (`alarm`, their urgency ×
/// [`BoidWorldParams::alarm_share`], see [`BoidWorldParams::alarm_threshold`])
/// evades the nearest shark with that urgency. The force is the maximum force ×
/// urgency.
pub(super) fn escape_force(
    world: &BoidWorldParams,
    position_m: Vec3,
    velocity_m_per_s: Vec3,
    sharks: &[Shark],
    params: &SteeringParams,
    alarm: f32,
) -> Option<(Vec3, f32)> {
    let heading = heading_of(velocity_m_per_s);
    let cos_half_view = fmath::cos(150f32.to_radians());
    let mut noticed: Option<(f32, &Shark)> = None;
    let mut nearest: Option<(f32, &Shark)> = None;
    for shark in sharks {
        let offset_m = shark.body.position_m - position_m;
        let distance_m = offset_m.length();
        let in_view = heading.dot(offset_m) >= cos_half_view * distance_m;
        let seen =
            distance_m < world.lateral_line_m || (distance_m < world.fear_radius_m && in_view);
        if seen && noticed.is_none_or(|(d, _)| distance_m < d) {
            noticed = Some((distance_m, shark));
        }
        if nearest.is_none_or(|(d, _)| distance_m < d) {
            nearest = Some((distance_m, shark));
        }
    }
    let (urgency, shark) = match (noticed, nearest) {
        (Some((distance_m, shark)), _) => {
            let urgency = if distance_m <= world.lateral_line_m {
                1.0
            } else {
                1.0 - 0.75 * (distance_m - world.lateral_line_m)
                    / (world.fear_radius_m - world.lateral_line_m)
            };
            (urgency.max(alarm.min(1.0)), shark)
        }
        (None, Some((_, shark))) if alarm >= world.alarm_threshold => (alarm.min(1.0), shark),
        _ => return None,
    };
    let evade = steering::evade(
        position_m,
        velocity_m_per_s,
        shark.body.position_m,
        shark.body.velocity_m_per_s,
        params.max_speed_m_per_s,
        f32::INFINITY,
        &world.steering,
    );
    Some((
        evade.normalize_or_zero() * params.max_force_m_per_s2.clamp(0.0, 1e6) * urgency,
        urgency,
    ))
}

/// How frightened each fish is, for the alarm that spreads through a school:
/// a fish is alarmed by the fright of the neighbours it heeds in the last
/// step, so the fright of this step is written aside and swapped in at its end.
#[derive(Clone, Debug, Default)]
pub(super) struct Fear {
    /// Each fish's escape urgency in the last boid step (0 = calm).
    fear: Vec<f32>,
    /// The same for this step, filled fish by fish.
    next_fear: Vec<f32>,
}

impl Fear {
    /// Gets ready for a boid step of `fish_count` fish (a new fish starts calm).
    pub(super) fn begin_step(&mut self, fish_count: usize) {
        self.fear.resize(fish_count, 0.0);
        self.next_fear.clear();
        self.next_fear.resize(fish_count, 0.0);
    }

    /// The escape force of fish `i` (at `position_m`, swimming with
    /// `velocity_m_per_s`, heeding `neighbours`, given as slots of the step's
    /// snapshot with `fish_at_slot` the fish in each slot) from `sharks`, or `None` when
    /// it is calm: what it notices itself, or the alarm of its frightened
    /// neighbours within [`BoidWorldParams::alarm_range_m`] (their last
    /// fright × [`BoidWorldParams::alarm_share`]). Records its fright for the
    /// next step.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn escape(
        &mut self,
        i: usize,
        neighbours: &Nearest,
        fish_at_slot: &[u32],
        position_m: Vec3,
        velocity_m_per_s: Vec3,
        sharks: &[Shark],
        params: &SteeringParams,
        world: &BoidWorldParams,
    ) -> Option<Vec3> {
        // Many eyes: the fright of the heeded neighbours (last step's), unless
        // joint flight is switched off.
        let alarm = if !world.joint_flight {
            0.0
        } else {
            neighbours
                .iter()
                .filter(|&(_, d2)| d2 <= world.alarm_range_m * world.alarm_range_m)
                .map(|(j, _)| self.fear[fish_at_slot[j] as usize])
                .fold(0.0, f32::max)
                * world.alarm_share
        };
        let escape = escape_force(world, position_m, velocity_m_per_s, sharks, params, alarm);
        self.next_fear[i] = escape.map_or(0.0, |(_, urgency)| urgency);
        escape.map(|(force, _)| force)
    }

    /// Ends a boid step: this step's fright becomes the last step's.
    pub(super) fn end_step(&mut self) {
        std::mem::swap(&mut self.fear, &mut self.next_fear);
    }
}

/// The sharks and stingrays, the stingrays as obstacles, and the catches.
#[derive(Clone, Debug, Default)]
pub(super) struct Predators {
    sharks: Vec<Shark>,
    stingrays: Vec<Stingray>,
    /// The stingrays as the fish avoid them (discs and cluster polygons).
    stingray_avoid: Vec<Obstacle>,
    /// The stingrays as solid discs (the hard rule).
    stingray_solids: ObstacleSet,
    /// The fixed obstacles followed by the stingrays' avoidance shapes:
    /// everything a fish steers round.
    avoid_all: ObstacleSet,
    /// Fish caught since the start or the last reset.
    catches: u64,
}

impl Predators {
    /// The sharks.
    pub(super) fn sharks(&self) -> &[Shark] {
        &self.sharks
    }

    /// The stingrays.
    pub(super) fn stingrays(&self) -> &[Stingray] {
        &self.stingrays
    }

    /// The sharks, to place by hand.
    #[cfg(test)]
    pub(super) fn sharks_mut(&mut self) -> &mut [Shark] {
        &mut self.sharks
    }

    /// The stingrays, to place by hand.
    #[cfg(test)]
    pub(super) fn stingrays_mut(&mut self) -> &mut [Stingray] {
        &mut self.stingrays
    }

    /// The stingrays as the fish avoid them (discs and cluster polygons).
    pub(super) fn stingray_avoid(&self) -> &[Obstacle] {
        &self.stingray_avoid
    }

    /// The stingrays as solid discs (the hard rule).
    pub(super) fn stingray_solids(&self) -> &ObstacleSet {
        &self.stingray_solids
    }

    /// The fixed obstacles and the stingrays' avoidance shapes together, as
    /// last rebuilt ([`Self::rebuild_stingray_obstacles`]).
    pub(super) fn avoid_all(&self) -> &ObstacleSet {
        &self.avoid_all
    }

    /// Fish caught since the start or the last reset.
    pub(super) fn catches(&self) -> u64 {
        self.catches
    }

    /// Fixed `obstacles` and stingray discs: what a new fish must not start in.
    pub(super) fn solids(&self, obstacles: &[Obstacle]) -> Vec<Obstacle> {
        let mut solids = obstacles.to_vec();
        solids.extend(self.stingray_solids.as_slice().iter().cloned());
        solids
    }

    /// Keep the first `sharks` sharks and `stingrays` stingrays (at most
    /// [`MAX_SHARKS`] and [`MAX_STINGRAYS`]), or add new ones at free places
    /// from `rng`: the stingrays first, clear of the fixed `obstacles`, then
    /// the sharks, clear of `fixed_solids` (the same obstacles with bounds).
    /// Returns the counts kept.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn set_counts(
        &mut self,
        sharks: usize,
        stingrays: usize,
        tank: &Tank,
        obstacles: &[Obstacle],
        fixed_solids: &ObstacleSet,
        world: &BoidWorldParams,
        rng: &mut ChaCha8Rng,
    ) -> (usize, usize) {
        let (sharks, stingrays) = (sharks.min(MAX_SHARKS), stingrays.min(MAX_STINGRAYS));
        self.stingrays.truncate(stingrays);
        while self.stingrays.len() < stingrays {
            let ray = placement::spawn_stingray(tank, obstacles, rng, &world.stingray);
            self.stingrays.push(ray);
        }
        self.sharks.truncate(sharks);
        while self.sharks.len() < sharks {
            let shark = placement::spawn_shark(tank, fixed_solids, rng, &world.shark_species);
            self.sharks.push(shark);
        }
        (sharks, stingrays)
    }

    /// Sharks hunting fish number `fish_count` or above (removed) lose them.
    pub(super) fn forget_fish_from(&mut self, fish_count: usize) {
        for shark in &mut self.sharks {
            if shark.target.is_some_and(|t| t >= fish_count) {
                shark.target = None;
            }
        }
    }

    /// After the fixed `obstacles` changed: each stingray now too close to one
    /// moves to a free place drawn from `rng`.
    pub(super) fn replace_misplaced_stingrays(
        &mut self,
        tank: &Tank,
        obstacles: &[Obstacle],
        world: &BoidWorldParams,
        rng: &mut ChaCha8Rng,
    ) {
        for i in 0..self.stingrays.len() {
            if !stingray_fits(
                self.stingrays[i].body.position_m,
                tank,
                obstacles,
                &world.stingray,
            ) {
                self.stingrays[i] =
                    placement::spawn_stingray(tank, obstacles, rng, &world.stingray);
            }
        }
    }

    /// Pushes every shark out of the glass and the fixed obstacles at once.
    pub(super) fn settle_sharks(&mut self, tank: &Tank, fixed_solids: &ObstacleSet) {
        for shark in &mut self.sharks {
            push_shark_clear(&mut shark.body, tank, fixed_solids);
        }
    }

    /// The stingrays' discs (hard rule) and avoidance shapes, and the list of
    /// everything the fish avoid (the fixed `obstacles` first).
    pub(super) fn rebuild_stingray_obstacles(
        &mut self,
        tank: &Tank,
        obstacles: &[Obstacle],
        world: &BoidWorldParams,
    ) {
        let floor_y_m = tank.min_m.y;
        let ray = &world.stingray;
        let discs: Vec<Obstacle> = self
            .stingrays
            .iter()
            .map(|s| s.obstacle(floor_y_m, ray))
            .collect();
        self.stingray_solids.rebuild(&discs);
        self.stingray_avoid.clear();
        stingray::cluster_obstacles(&self.stingrays, floor_y_m, ray, &mut self.stingray_avoid);
        self.avoid_all
            .rebuild(obstacles.iter().chain(&self.stingray_avoid));
    }

    /// Stingrays glide: level wander, the glass, the fixed `obstacles`, and a
    /// spring that holds their glide height; they never come closer than
    /// [`StingrayParams::gap_m`](crate::sim::boids::params::StingrayParams::gap_m)
    /// to the glass or an obstacle (if a step would bring one closer, it turns
    /// round instead). `fish_params` are the world's steering limits, scaled
    /// to a stingray's ([`stingray::stingray_params`]).
    pub(super) fn step_stingrays(
        &mut self,
        tank: &Tank,
        obstacles: &[Obstacle],
        fish_params: &SteeringParams,
        world: &BoidWorldParams,
        rng: &mut ChaCha8Rng,
    ) {
        let species = world.stingray.clone();
        let params = stingray::stingray_params(fish_params, &species);
        let tuning = world.steering;
        let floor_y_m = tank.min_m.y;
        for ray in &mut self.stingrays {
            let before = *ray;
            let body = &mut ray.body;
            let wander = steering::wander(body, rng, &params, &tuning);
            let reach_m = species.radius_m + species.gap_m;
            let walls = steering::glass_walls(
                body.position_m,
                body.velocity_m_per_s,
                tank,
                reach_m + 1.0,
                params.max_force_m_per_s2,
                &tuning,
            );
            let avoidance = steering::avoid_obstacles(
                body.position_m,
                body.velocity_m_per_s,
                obstacles,
                1.5,
                reach_m,
                params.max_speed_m_per_s,
            );
            // Height spring: desired climb rate = height error per second.
            let height_error_m = floor_y_m + ray.glide_height_m - body.position_m.y;
            let hold = Vec3::Y * (height_error_m - body.velocity_m_per_s.y) * 2.0;
            let steering_m_per_s2 = (wander + walls * 2.0 + avoidance + hold) * Vec3::ONE;
            body.integrate(steering_m_per_s2, &params, DT_SECS);
            let legal = body.position_m.is_finite()
                && body.velocity_m_per_s.is_finite()
                && stingray_fits(body.position_m, tank, obstacles, &species);
            if !legal {
                *ray = before;
                ray.body.velocity_m_per_s = -ray.body.velocity_m_per_s.normalize_or(Vec3::X)
                    * params.min_speed_m_per_s.max(0.05);
            }
            let p = &mut ray.body.position_m;
            p.y =
                p.y.max(floor_y_m + species.min_glide_height_m)
                    .min(floor_y_m + species.max_glide_height_m);
            ray.body.advance_tail_phase(DT_SECS);
        }
    }

    /// Sharks hunt (see [`shark`]): keep or lose the lock (confusion effect,
    /// counted in `grid`, the fish's snapshot at the start of the step), pick
    /// the nearest fish they see, pursue it, and catch it at the mouth; a
    /// caught fish is replaced in place by a new one far from the sharks. The
    /// sharks steer round everything the fish avoid and are pushed out of
    /// `fixed_solids` (the fixed `obstacles` with bounds). Returns how many
    /// non-finite states had to be repaired.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn step_sharks(
        &mut self,
        fish: &mut [Fish],
        grid: &SpatialGrid,
        tank: &Tank,
        obstacles: &[Obstacle],
        fixed_solids: &ObstacleSet,
        fish_params: &SteeringParams,
        world: &BoidWorldParams,
        rng: &mut ChaCha8Rng,
    ) -> u64 {
        let mut repairs = 0;
        let species = world.shark_species.clone();
        let shark_perception = Perception {
            vision_distance_m: species.vision_m,
            vision_angle_rad: species.vision_angle_rad,
            max_speed_m_per_s: species.attack_m_per_s,
            max_force_m_per_s2: species.max_force_m_per_s2,
            separation_distance_m: 0.0,
            response_time_s: 1.0,
            clear_sight_m: 0.0,
            far_pull: 0.0,
            min_speed_m_per_s: species.min_m_per_s,
        };
        let hunt = world.shark.clone();
        let tuning = world.steering;
        for s in 0..self.sharks.len() {
            let mut shark = self.sharks[s];
            let params = shark::shark_params(fish_params, shark.body.body_length_m, &species);
            shark.satiated_secs = (shark.satiated_secs - DT_SECS).max(0.0);
            shark.refocus_secs = (shark.refocus_secs - DT_SECS).max(0.0);
            if !shark.is_hungry() {
                shark.target = None;
            }
            // Keep the lock, or lose it to confusion or distance.
            if let Some(t) = shark.target {
                let lost = match fish.get(t) {
                    None => true,
                    Some(prey) => {
                        // A strike that has not caught the fish by now has failed.
                        let failed = shark.lock_secs > hunt.strike_lock_secs + hunt.lunge_max_secs;
                        let far = failed
                            || prey.position_m.distance(shark.body.position_m)
                                > species.vision_m * 1.5;
                        let confusing = count_near(grid, prey.position_m, t, world);
                        let p_lose = shark::lose_lock_probability(&hunt, confusing, DT_SECS);
                        far || rng.random::<f32>() < p_lose
                    }
                };
                if lost {
                    shark.target = None;
                    shark.refocus_secs = hunt.refocus_secs;
                } else {
                    shark.lock_secs += DT_SECS;
                }
            }
            // Pick the nearest fish in view.
            if shark.target.is_none() && shark.is_hungry() && shark.refocus_secs <= 0.0 {
                let mut nearest = Nearest::new(1);
                let (p, heading) = (shark.body.position_m, shark.body.heading());
                grid.k_nearest(p, species.vision_m, &mut nearest, |_, q, _| {
                    forces::sees(p, heading, q, &shark_perception)
                });
                shark.target = nearest.iter().next().map(|(j, _)| j);
                shark.lock_secs = 0.0;
            }
            let before = shark.body;
            // The final lunge: locked on long enough and close, the shark
            // bursts (see shark::lunge_params).
            let lunging = shark.target.and_then(|t| fish.get(t)).is_some_and(|prey| {
                shark.lock_secs >= hunt.strike_lock_secs
                    && prey.position_m.distance(before.position_m) < hunt.lunge_distance_m
            });
            let params = if lunging {
                shark::lunge_params(&hunt, &params)
            } else {
                params
            };
            let chase = match shark.target.and_then(|t| fish.get(t)) {
                Some(prey) => steering::pursue(
                    before.position_m,
                    before.velocity_m_per_s,
                    prey.position_m,
                    prey.velocity_m_per_s,
                    params.max_speed_m_per_s,
                    params.max_force_m_per_s2,
                    &tuning,
                ),
                None => steering::wander(&mut shark.body, rng, &params, &tuning),
            };
            let containment = steering::contain_in_tank(
                before.position_m,
                before.velocity_m_per_s,
                tank,
                2.5,
                &params,
                params.max_force_m_per_s2,
                &tuning,
            );
            let avoidance = steering::avoid_obstacles(
                before.position_m,
                before.velocity_m_per_s,
                self.avoid_all.as_slice(),
                3.0,
                0.5,
                params.max_speed_m_per_s,
            );
            let steering_m_per_s2 = chase + containment * 2.0 + avoidance;
            shark.body.integrate(steering_m_per_s2, &params, DT_SECS);
            if !(shark.body.position_m.is_finite() && shark.body.velocity_m_per_s.is_finite()) {
                shark.body.position_m = before.position_m;
                shark.body.velocity_m_per_s = before.heading() * params.min_speed_m_per_s;
                repairs += 1;
            }
            push_shark_clear(&mut shark.body, tank, fixed_solids);
            shark.body.advance_tail_phase(DT_SECS);
            // The bite.
            if let Some(t) = shark.target
                && shark.lock_secs >= hunt.strike_lock_secs
                && let Some(prey) = fish.get(t)
                && prey.position_m.distance(shark.mouth_m()) < hunt.catch_distance_m
            {
                shark.catches += 1;
                self.catches += 1;
                shark.target = None;
                shark.satiated_secs = hunt.satiated_secs;
                self.sharks[s] = shark;
                fish[t] = placement::spawn_fish_far_from_sharks(
                    &self.sharks,
                    tank,
                    &self.solids(obstacles),
                    fish_params,
                    &world.shark_species,
                    rng,
                );
                continue;
            }
            self.sharks[s] = shark;
        }
        repairs
    }
}

/// Fish (other than `except`) within
/// [`SharkHuntParams::confusion_radius_m`](crate::sim::boids::params::SharkHuntParams::confusion_radius_m)
/// of `p`, counted up to [`shark::MAX_CONFUSING_NEIGHBOURS`] in `grid` (the
/// snapshot positions).
fn count_near(grid: &SpatialGrid, p: Vec3, except: usize, world: &BoidWorldParams) -> u32 {
    let mut nearest = Nearest::new(shark::MAX_CONFUSING_NEIGHBOURS as usize);
    grid.k_nearest(
        p,
        world.shark.confusion_radius_m,
        &mut nearest,
        |j, _, _| j != except,
    );
    nearest.len() as u32
}
