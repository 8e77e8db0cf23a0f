//! The stingray: a flat ray about 1 m wide that glides slowly just above the
//! sand, wandering (the SIMBA papers' third species). For the fish it is a
//! moving obstacle: they avoid it like a rock (Lim & Tan: "other agents are
//! avoided the same way"), and three or more stingrays close together are
//! avoided as one polygon (SIMBA paper §Implementation: "the centre position of
//! at least three particles that are close enough … regarded as a closed
//! polygon"), see [`cluster_obstacles`].

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};

use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::{Obstacle, convex_hull};
use crate::sim::common::steering::SteeringParams;

/// Most stingrays a world holds. Default 20: enough to pave a corner of the sand
/// and show the polygon rule; more would leave the fish no floor.
pub const MAX_STINGRAYS: usize = 20;

/// Half the stingray's wingspan, in metres. Default 0.5 m: a ray 1 m across.
pub const STINGRAY_RADIUS_M: f32 = 0.5;

/// Thickness of the stingray's body, in metres. Default 0.15 m.
pub const STINGRAY_THICKNESS_M: f32 = 0.15;

/// Lowest and highest glide height of the stingray's centre above the sand, in
/// metres. Default 0.2–0.6 m: rays skim the bottom; each one keeps its own
/// height from this range.
pub const GLIDE_HEIGHT_M: (f32, f32) = (0.2, 0.6);

/// Cruising speed in m/s. Default 0.3 m/s: a slow glide, a third of a fish's
/// top speed.
pub const STINGRAY_CRUISE_M_PER_S: f32 = 0.3;

/// Top and lowest speed in m/s. Default 0.4 and 0.15 m/s.
pub const STINGRAY_MAX_M_PER_S: f32 = 0.4;
pub const STINGRAY_MIN_M_PER_S: f32 = 0.15;

/// Largest steering acceleration in m/s². Default 0.5 m/s²: wide, calm turns.
pub const STINGRAY_MAX_FORCE_M_PER_S2: f32 = 0.5;

/// Gap a stingray keeps between its wing tips and the glass or any fixed
/// obstacle, in metres. Default 0.6 m: a fish always fits between (so pushing a
/// fish out of a stingray can never push it into a rock or through the glass).
pub const STINGRAY_GAP_M: f32 = 0.6;

/// Stingrays whose centres are closer than this are "close together", in
/// metres. Default 2.0 m: their wing tips are less than 1 m apart (two to three
/// fish lengths), too narrow for a school to pass between; three or more such
/// stingrays are avoided as one polygon.
pub const CLUSTER_LINK_M: f32 = 2.0;

/// Fewest stingrays treated as one polygon. Default 3 (the SIMBA paper: "at
/// least three particles").
pub const CLUSTER_MIN_STINGRAYS: usize = 3;

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
    /// The stingray as the fish see it: a disc of [`STINGRAY_RADIUS_M`] from the
    /// sand up to the top of its body, rooted in the sand like a pillar (a fish
    /// has no business between a gliding ray and the sand).
    pub fn obstacle(&self, floor_y_m: f32) -> Obstacle {
        let p = self.body.position_m;
        Obstacle::Cylinder {
            base_center_m: Vec3::new(p.x, floor_y_m, p.z),
            radius_m: STINGRAY_RADIUS_M,
            height_m: (p.y - floor_y_m + STINGRAY_THICKNESS_M * 0.5).max(0.05),
        }
    }
}

/// Steering limits of a stingray for [`Fish::integrate`] and level wander.
pub fn stingray_params(fish_params: &SteeringParams) -> SteeringParams {
    SteeringParams {
        max_speed_m_per_s: STINGRAY_MAX_M_PER_S,
        min_speed_m_per_s: STINGRAY_MIN_M_PER_S,
        max_force_m_per_s2: STINGRAY_MAX_FORCE_M_PER_S2,
        cruise_speed_body_lengths_per_s: STINGRAY_CRUISE_M_PER_S / (2.0 * STINGRAY_RADIUS_M),
        wander_distance_m: 1.5,
        wander_radius_m: 0.6,
        wander_pitch_jitter_rad: 0.0,
        wander_max_pitch_rad: 0.0,
        ..*fish_params
    }
}

/// A new stingray at `position_m` (its glide height is its height above the
/// sand at `floor_y_m`), heading at `yaw_rad`.
pub fn new_stingray(position_m: Vec3, yaw_rad: f32, floor_y_m: f32) -> Stingray {
    let direction = Vec3::new(yaw_rad.cos(), 0.0, yaw_rad.sin());
    let mut body = Fish::new(
        position_m,
        direction * STINGRAY_CRUISE_M_PER_S,
        2.0 * STINGRAY_RADIUS_M,
        0.1,
    );
    body.tail_phase_rad = yaw_rad.rem_euclid(TAU);
    Stingray {
        body,
        glide_height_m: (position_m.y - floor_y_m).clamp(GLIDE_HEIGHT_M.0, GLIDE_HEIGHT_M.1),
    }
}

/// The obstacles the fish avoid for these stingrays, appended to `out`: one
/// [`Obstacle::Polygon`] for every cluster of at least [`CLUSTER_MIN_STINGRAYS`]
/// stingrays linked by centre distances below [`CLUSTER_LINK_M`] (the convex hull
/// of their discs, each disc taken as the octagon around it, as tall as the
/// tallest), and the single disc ([`Stingray::obstacle`]) of every other one.
/// Stingrays are few (at most [`MAX_STINGRAYS`]), so all pairs are compared.
pub fn cluster_obstacles(stingrays: &[Stingray], floor_y_m: f32, out: &mut Vec<Obstacle>) {
    let n = stingrays.len();
    let mut cluster: Vec<usize> = (0..n).collect();
    // Single linkage: relabel until stable (n ≤ 20, so at most n passes of n²).
    let mut changed = true;
    while changed {
        changed = false;
        for i in 0..n {
            for j in 0..n {
                let (pi, pj) = (stingrays[i].body.position_m, stingrays[j].body.position_m);
                let close = Vec2::new(pi.x - pj.x, pi.z - pj.z).length() < CLUSTER_LINK_M;
                if close && cluster[j] < cluster[i] {
                    cluster[i] = cluster[j];
                    changed = true;
                }
            }
        }
    }
    // The octagon around a disc: corners at radius R / cos(π/8) contain the disc.
    let corner_m = STINGRAY_RADIUS_M / (PI / 8.0).cos();
    for label in 0..n {
        let members: Vec<&Stingray> = (0..n)
            .filter(|&i| cluster[i] == label)
            .map(|i| &stingrays[i])
            .collect();
        if members.len() >= CLUSTER_MIN_STINGRAYS {
            let mut corners = Vec::with_capacity(members.len() * 8);
            let mut top_m = floor_y_m;
            for s in &members {
                let p = s.body.position_m;
                for k in 0..8 {
                    let a = k as f32 * TAU / 8.0;
                    corners.push(Vec2::new(
                        p.x + corner_m * a.cos(),
                        p.z + corner_m * a.sin(),
                    ));
                }
                top_m = top_m.max(p.y + STINGRAY_THICKNESS_M * 0.5);
            }
            out.push(Obstacle::Polygon {
                footprint_m: convex_hull(&corners),
                base_y_m: floor_y_m,
                height_m: (top_m - floor_y_m).max(0.05),
            });
        } else {
            out.extend(members.iter().map(|s| s.obstacle(floor_y_m)));
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::boids::stingray::*;

    fn ray_at(x: f32, z: f32) -> Stingray {
        new_stingray(Vec3::new(x, 0.4, z), 0.0, 0.0)
    }

    #[test]
    fn two_stingrays_stay_two_discs_but_three_close_ones_become_one_polygon() {
        let mut out = Vec::new();
        cluster_obstacles(&[ray_at(0.0, 0.0), ray_at(1.5, 0.0)], 0.0, &mut out);
        assert_eq!(out.len(), 2);
        assert!(out.iter().all(|o| matches!(o, Obstacle::Cylinder { .. })));

        let rays = [
            ray_at(0.0, 0.0),
            ray_at(1.5, 0.0),
            ray_at(0.7, 1.4),
            ray_at(-4.0, 0.0),
        ];
        out.clear();
        cluster_obstacles(&rays, 0.0, &mut out);
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
                let rim = p + Vec3::new(a.cos(), 0.0, a.sin()) * STINGRAY_RADIUS_M * 0.99;
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
        let o = ray.obstacle(0.0);
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
