//! Sharks and stingrays in the boid tank, and the fear they cause: a shark
//! hunts (with the confusion effect), stingrays glide over the sand and become
//! obstacles, and fish that see or sense a shark flee (escape force, alarm).

use crate::sim::common::fmath;
use glam::Vec3;
use rand::Rng;

use crate::sim::boids::forces::{self, Perception};
use crate::sim::boids::shark::{self, Shark};
use crate::sim::boids::stingray::{self};
use crate::sim::common::fish::{Fish, heading_of};
use crate::sim::common::obstacle::{Obstacle, ObstacleSet};
use crate::sim::common::spatial_grid::Nearest;
use crate::sim::common::steering::{self, SteeringParams};
use crate::sim::common::tank::Tank;

use super::params::BoidWorldParams;
use super::placement::stingray_fits;
use super::world::*;

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

/// [`push_clear`] for a shark: out of the glass and the rocks by
/// [`SHARK_MARGIN_M`]; stingrays are not in a shark's way.
pub(super) fn push_shark_clear(body: &mut Fish, tank: &Tank, obstacles: &ObstacleSet) {
    push_clear(
        body,
        tank,
        obstacles,
        &ObstacleSet::EMPTY,
        SHARK_MARGIN_M,
        SHARK_MARGIN_M,
    );
}

impl World {
    /// The stingrays' discs (hard rule) and avoidance shapes, and the list of
    /// everything the fish avoid.
    pub(super) fn rebuild_stingray_obstacles(&mut self) {
        let floor_y_m = self.tank.min_m.y;
        let ray = &self.world_params.stingray;
        let discs: Vec<Obstacle> = self
            .stingrays
            .iter()
            .map(|s| s.obstacle(floor_y_m, ray))
            .collect();
        self.stingray_solids.rebuild(&discs);
        self.stingray_avoid.clear();
        stingray::cluster_obstacles(&self.stingrays, floor_y_m, ray, &mut self.stingray_avoid);
        self.avoid_all
            .rebuild(self.obstacles.iter().chain(&self.stingray_avoid));
    }

    /// Stingrays glide: level wander, the glass, the fixed obstacles, and a
    /// spring that holds their glide height; they never come closer than
    /// [`StingrayParams::gap_m`](crate::sim::boids::params::StingrayParams::gap_m)
    /// to the glass or an obstacle (if a step would bring one closer, it turns
    /// round instead).
    pub(super) fn step_stingrays(&mut self) {
        let species = self.world_params.stingray.clone();
        let params = stingray::stingray_params(&self.params, &species);
        let tuning = self.world_params.steering;
        let floor_y_m = self.tank.min_m.y;
        for ray in &mut self.stingrays {
            let before = *ray;
            let body = &mut ray.body;
            let wander = steering::wander(body, &mut self.rng, &params, &tuning);
            let reach_m = species.radius_m + species.gap_m;
            let walls = steering::glass_walls(
                body.position_m,
                body.velocity_m_per_s,
                &self.tank,
                reach_m + 1.0,
                params.max_force_m_per_s2,
                &tuning,
            );
            let avoidance = steering::avoid_obstacles(
                body.position_m,
                body.velocity_m_per_s,
                &self.obstacles,
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
                && stingray_fits(body.position_m, &self.tank, &self.obstacles, &species);
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

    /// Sharks hunt (see [`shark`]): keep or lose the lock (confusion effect),
    /// pick the nearest fish they see, pursue it, and catch it at the mouth.
    pub(super) fn step_sharks(&mut self) {
        let species = self.world_params.shark_species.clone();
        let shark_perception = Perception {
            vision_distance_m: species.vision_m,
            vision_angle_rad: species.vision_angle_rad,
            max_speed_m_per_s: species.attack_m_per_s,
            max_force_m_per_s2: species.max_force_m_per_s2,
            separation_distance_m: 0.0,
            response_time_s: 1.0,
        };
        let hunt = self.world_params.shark.clone();
        let tuning = self.world_params.steering;
        for s in 0..self.sharks.len() {
            let mut shark = self.sharks[s];
            let params = shark::shark_params(&self.params, shark.body.body_length_m, &species);
            shark.satiated_secs = (shark.satiated_secs - DT_SECS).max(0.0);
            shark.refocus_secs = (shark.refocus_secs - DT_SECS).max(0.0);
            if !shark.is_hungry() {
                shark.target = None;
            }
            // Keep the lock, or lose it to confusion or distance.
            if let Some(t) = shark.target {
                let lost = match self.fish.get(t) {
                    None => true,
                    Some(prey) => {
                        // A strike that has not caught the fish by now has failed.
                        let failed = shark.lock_secs > hunt.strike_lock_secs + hunt.lunge_max_secs;
                        let far = failed
                            || prey.position_m.distance(shark.body.position_m)
                                > species.vision_m * 1.5;
                        let confusing = self.count_near(prey.position_m, t);
                        let p_lose = shark::lose_lock_probability(&hunt, confusing, DT_SECS);
                        far || self.rng.random::<f32>() < p_lose
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
                self.grid
                    .k_nearest(p, species.vision_m, &mut nearest, |_, q, _| {
                        forces::sees(p, heading, q, &shark_perception)
                    });
                shark.target = nearest.iter().next().map(|(j, _)| j);
                shark.lock_secs = 0.0;
            }
            let before = shark.body;
            // The final lunge: locked on long enough and close, the shark
            // bursts (see shark::lunge_params).
            let lunging = shark
                .target
                .and_then(|t| self.fish.get(t))
                .is_some_and(|prey| {
                    shark.lock_secs >= hunt.strike_lock_secs
                        && prey.position_m.distance(before.position_m) < hunt.lunge_distance_m
                });
            let params = if lunging {
                shark::lunge_params(&hunt, &params)
            } else {
                params
            };
            let chase = match shark.target.and_then(|t| self.fish.get(t)) {
                Some(prey) => steering::pursue(
                    before.position_m,
                    before.velocity_m_per_s,
                    prey.position_m,
                    prey.velocity_m_per_s,
                    params.max_speed_m_per_s,
                    params.max_force_m_per_s2,
                    &tuning,
                ),
                None => steering::wander(&mut shark.body, &mut self.rng, &params, &tuning),
            };
            let containment = steering::contain_in_tank(
                before.position_m,
                before.velocity_m_per_s,
                &self.tank,
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
                self.non_finite_repairs += 1;
            }
            push_shark_clear(&mut shark.body, &self.tank, &self.fixed_solids);
            shark.body.advance_tail_phase(DT_SECS);
            // The bite.
            if let Some(t) = shark.target
                && shark.lock_secs >= hunt.strike_lock_secs
                && let Some(prey) = self.fish.get(t)
                && prey.position_m.distance(shark.mouth_m()) < hunt.catch_distance_m
            {
                shark.catches += 1;
                self.catches += 1;
                shark.target = None;
                shark.satiated_secs = hunt.satiated_secs;
                self.sharks[s] = shark;
                let replacement = self.spawn_fish_far_from_sharks();
                self.fish[t] = replacement;
                continue;
            }
            self.sharks[s] = shark;
        }
    }

    /// Fish (other than `except`) within
    /// [`SharkHuntParams::confusion_radius_m`](crate::sim::boids::params::SharkHuntParams::confusion_radius_m)
    /// of `p`,
    /// counted up to [`shark::MAX_CONFUSING_NEIGHBOURS`] (snapshot positions).
    pub(super) fn count_near(&self, p: Vec3, except: usize) -> u32 {
        let mut nearest = Nearest::new(shark::MAX_CONFUSING_NEIGHBOURS as usize);
        self.grid.k_nearest(
            p,
            self.world_params.shark.confusion_radius_m,
            &mut nearest,
            |j, _, _| j != except,
        );
        nearest.len() as u32
    }
}
