//! The stingray: a flat ray about 1 m wide that glides slowly just above the
//! sand, wandering (the SIMBA papers' third species). For the fish it is a
//! moving obstacle: they avoid it like a rock (Lim & Tan: "other agents are
//! avoided the same way"), and three or more stingrays close together are
//! avoided as one polygon (SIMBA paper §Implementation: "the centre position of
//! at least three particles that are close enough … regarded as a closed
//! polygon"), see [`cluster_obstacles`]. Its size, glide height, speeds and
//! gaps are [`StingrayParams`] (`BoidWorldParams::stingray`).

use crate::sim::common::fmath;
use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};

use crate::sim::boids::params::StingrayParams;
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::{Obstacle, convex_hull};
use crate::sim::common::steering::SteeringParams;

/// Most stingrays a world holds. Default 20: enough to pave a corner of the sand
/// and show the polygon rule; more would leave the fish no floor.
pub const MAX_STINGRAYS: usize = 20;

/// A stingray: its body (position, velocity, `body_length_m` = its width) and
/// the height it glides at.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Stingray {
    /// Position, velocity and width (as `body_length_m`), as for a fish.
    pub body: Fish,
    /// Height of its centre above the sand that it holds, metres.
    pub glide_height_m: f32,
}

impl Stingray {
    /// The stingray as the fish see it: a disc of [`StingrayParams::radius_m`]
    /// from the sand up to the top of its body, rooted in the sand like a pillar
    /// (a fish has no business between a gliding ray and the sand).
    pub fn obstacle(&self, floor_y_m: f32, ray: &StingrayParams) -> Obstacle {
        let p = self.body.position_m;
        Obstacle::Cylinder {
            base_center_m: Vec3::new(p.x, floor_y_m, p.z),
            radius_m: ray.radius_m,
            height_m: (p.y - floor_y_m + ray.thickness_m * 0.5).max(0.05),
        }
    }
}

/// Steering limits of a stingray (`ray`) for [`Fish::integrate`] and level
/// wander.
pub fn stingray_params(fish_params: &SteeringParams, ray: &StingrayParams) -> SteeringParams {
    SteeringParams {
        max_speed_m_per_s: ray.max_m_per_s,
        min_speed_m_per_s: ray.min_m_per_s,
        max_force_m_per_s2: ray.max_force_m_per_s2,
        cruise_speed_body_lengths_per_s: ray.cruise_m_per_s / (2.0 * ray.radius_m),
        wander_distance_m: 1.5,
        wander_radius_m: 0.6,
        wander_pitch_jitter_rad: 0.0,
        wander_max_pitch_rad: 0.0,
        ..*fish_params
    }
}

/// A new stingray (`ray`) at `position_m` (its glide height is its height above
/// the sand at `floor_y_m`), heading at `yaw_rad`.
pub fn new_stingray(
    position_m: Vec3,
    yaw_rad: f32,
    floor_y_m: f32,
    ray: &StingrayParams,
) -> Stingray {
    let direction = Vec3::new(fmath::cos(yaw_rad), 0.0, fmath::sin(yaw_rad));
    let mut body = Fish::new(
        position_m,
        direction * ray.cruise_m_per_s,
        2.0 * ray.radius_m,
        0.1,
    );
    body.tail_phase_rad = yaw_rad.rem_euclid(TAU);
    Stingray {
        body,
        glide_height_m: (position_m.y - floor_y_m)
            .clamp(ray.min_glide_height_m, ray.max_glide_height_m),
    }
}

/// The obstacles the fish avoid for these stingrays, appended to `out`: one
/// [`Obstacle::Polygon`] for every cluster of at least
/// [`StingrayParams::cluster_min_stingrays`] stingrays linked by centre
/// distances below [`StingrayParams::cluster_link_m`] (the convex hull of their
/// discs, each disc taken as the octagon around it, as tall as the tallest),
/// and the single disc ([`Stingray::obstacle`]) of every other one. Stingrays
/// are few (at most [`MAX_STINGRAYS`]), so all pairs are compared.
pub fn cluster_obstacles(
    stingrays: &[Stingray],
    floor_y_m: f32,
    ray: &StingrayParams,
    out: &mut Vec<Obstacle>,
) {
    let n = stingrays.len();
    let mut cluster: Vec<usize> = (0..n).collect();
    // Single linkage: relabel until stable (n ≤ 20, so at most n passes of n²).
    let mut changed = true;
    while changed {
        changed = false;
        for i in 0..n {
            for j in 0..n {
                let (pi, pj) = (stingrays[i].body.position_m, stingrays[j].body.position_m);
                let close = Vec2::new(pi.x - pj.x, pi.z - pj.z).length() < ray.cluster_link_m;
                if close && cluster[j] < cluster[i] {
                    cluster[i] = cluster[j];
                    changed = true;
                }
            }
        }
    }
    // The octagon around a disc: corners at radius R / cos(π/8) contain the disc.
    let corner_m = ray.radius_m / fmath::cos(PI / 8.0);
    for label in 0..n {
        let members: Vec<&Stingray> = (0..n)
            .filter(|&i| cluster[i] == label)
            .map(|i| &stingrays[i])
            .collect();
        if members.len() >= ray.cluster_min_stingrays {
            let mut corners = Vec::with_capacity(members.len() * 8);
            let mut top_m = floor_y_m;
            for s in &members {
                let p = s.body.position_m;
                for k in 0..8 {
                    let a = k as f32 * TAU / 8.0;
                    corners.push(Vec2::new(
                        p.x + corner_m * fmath::cos(a),
                        p.z + corner_m * fmath::sin(a),
                    ));
                }
                top_m = top_m.max(p.y + ray.thickness_m * 0.5);
            }
            out.push(Obstacle::Polygon {
                footprint_m: convex_hull(&corners),
                base_y_m: floor_y_m,
                height_m: (top_m - floor_y_m).max(0.05),
            });
        } else {
            out.extend(members.iter().map(|s| s.obstacle(floor_y_m, ray)));
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::boids::stingray::*;

    fn ray_at(x: f32, z: f32) -> Stingray {
        new_stingray(Vec3::new(x, 0.4, z), 0.0, 0.0, &StingrayParams::default())
    }

    #[test]
    fn two_stingrays_stay_two_discs_but_three_close_ones_become_one_polygon() {
        let mut out = Vec::new();
        cluster_obstacles(
            &[ray_at(0.0, 0.0), ray_at(1.5, 0.0)],
            0.0,
            &StingrayParams::default(),
            &mut out,
        );
        assert_eq!(out.len(), 2);
        assert!(out.iter().all(|o| matches!(o, Obstacle::Cylinder { .. })));

        let rays = [
            ray_at(0.0, 0.0),
            ray_at(1.5, 0.0),
            ray_at(0.7, 1.4),
            ray_at(-4.0, 0.0),
        ];
        out.clear();
        cluster_obstacles(&rays, 0.0, &StingrayParams::default(), &mut out);
        assert_eq!(out.len(), 2, "{out:?}");
        let polygon = out
            .iter()
            .find(|o| matches!(o, Obstacle::Polygon { .. }))
            .expect("one polygon");
        // It covers every member's disc and the gaps between them.
        for r in &rays[..3] {
            let p = r.body.position_m;
            for k in 0..16 {
                let a = k as f32 * TAU / 16.0;
                let rim = p + Vec3::new(fmath::cos(a), 0.0, fmath::sin(a))
                    * StingrayParams::default().radius_m
                    * 0.99;
                assert!(polygon.signed_distance_m(rim) <= 0.0);
            }
        }
        assert!(
            polygon.signed_distance_m(Vec3::new(0.75, 0.2, 0.0)) < 0.0,
            "gap between"
        );
    }

    #[test]
    fn a_stingray_is_a_disc_from_the_sand_to_its_back() {
        let ray = ray_at(1.0, 2.0);
        let o = ray.obstacle(0.0, &StingrayParams::default());
        assert!(
            o.signed_distance_m(Vec3::new(1.0, 0.1, 2.0)) < 0.0,
            "under it"
        );
        assert!(
            o.signed_distance_m(Vec3::new(1.0, 0.6, 2.0)) > 0.0,
            "above it"
        );
        assert!(
            o.signed_distance_m(Vec3::new(1.6, 0.4, 2.0)) > 0.0,
            "beside it"
        );
    }
}
