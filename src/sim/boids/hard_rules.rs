//! The hard rules of the boid tank, and moving one fish by one step: whatever
//! the steering did, an animal ends up in the water and outside every rock,
//! pillar, ledge and stingray. The fish step, the shark step and placement all
//! use them, so they live apart from each.

use glam::Vec3;

use super::params::DT_SECS;
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::{Obstacle, ObstacleSet};
use crate::sim::common::steering::SteeringParams;
use crate::sim::common::tank::Tank;

/// Hard-constraint margin from the glass, floor and surface in metres.
/// Default 0.05 m: about half a fish's body width, so a fish's body stays in
/// the water even when the hard rule has to act.
pub(super) const TANK_MARGIN_M: f32 = 0.05;

/// Hard-constraint margin from obstacle surfaces in metres. Default 0.05 m:
/// as above, half a body width.
pub(super) const OBSTACLE_MARGIN_M: f32 = 0.05;

/// Hard-constraint margin of a shark's centre from the glass and from
/// obstacles, in metres. Default 0.3 m: half a shark's body width.
const SHARK_MARGIN_M: f32 = 0.3;

/// Moves one fish by one step under `steering_m_per_s2`: integrate, repair any
/// non-finite value (back to `before`, at minimum speed), enforce the hard rules
/// and beat the tail. Returns how many repairs were needed (0, 1 or 2).
#[allow(clippy::too_many_arguments)]
pub(super) fn move_fish(
    fish: &mut Fish,
    before_position_m: Vec3,
    before_heading: Vec3,
    steering_m_per_s2: Vec3,
    params: &SteeringParams,
    tank: &Tank,
    obstacles: &ObstacleSet,
    stingrays: &ObstacleSet,
) -> u64 {
    let mut repairs = 0;
    let steering_m_per_s2 = if steering_m_per_s2.is_finite() {
        steering_m_per_s2
    } else {
        repairs += 1;
        Vec3::ZERO
    };
    fish.integrate(steering_m_per_s2, params, DT_SECS);
    if !(fish.position_m.is_finite() && fish.velocity_m_per_s.is_finite()) {
        repairs += 1;
        fish.position_m = before_position_m;
        fish.velocity_m_per_s = before_heading * params.min_speed_m_per_s.max(0.0);
    }
    enforce_hard_constraints(fish, tank, obstacles, stingrays);
    fish.advance_tail_phase(DT_SECS);
    repairs
}

/// The hard rules: whatever the steering did, the fish ends up inside the
/// tank (by [`TANK_MARGIN_M`]) and outside every obstacle and stingray disc (by
/// [`OBSTACLE_MARGIN_M`]), and no longer swims into what it touched.
///
/// Obstacles are at least
/// [`WALL_CLEARANCE_M`](crate::sim::common::obstacle::WALL_CLEARANCE_M) from the side walls, lower than
/// the surface, and pushing out of a half-buried rock or a rooted pillar or
/// polygon never points into the sand, so the obstacle push cannot undo the
/// tank clamp. Stingrays keep
/// [`StingrayParams::gap_m`](super::params::StingrayParams::gap_m) from the
/// glass and from every obstacle, so pushing a fish out of a stingray cannot
/// push it into either; where stingrays overlap, a fish still inside after two rounds is
/// lifted over them.
pub(super) fn enforce_hard_constraints(
    fish: &mut Fish,
    tank: &Tank,
    obstacles: &ObstacleSet,
    stingrays: &ObstacleSet,
) {
    push_clear(
        fish,
        tank,
        obstacles,
        stingrays,
        TANK_MARGIN_M,
        OBSTACLE_MARGIN_M,
    );
}

/// The hard rules for any animal (a fish or a shark), with its margins from the glass and from
/// obstacles (see [`enforce_hard_constraints`]).
fn push_clear(
    body: &mut Fish,
    tank: &Tank,
    obstacles: &ObstacleSet,
    stingrays: &ObstacleSet,
    tank_margin_m: f32,
    obstacle_margin_m: f32,
) {
    let clamped_m = tank.clamp_inside(body.position_m, tank_margin_m);
    let pushed_m = clamped_m - body.position_m;
    for axis in 0..3 {
        // Pushed back on this axis while still swimming outwards: bounce.
        if pushed_m[axis] * body.velocity_m_per_s[axis] < 0.0 {
            body.velocity_m_per_s[axis] = -body.velocity_m_per_s[axis];
        }
    }
    body.position_m = clamped_m;
    let push = |body: &mut Fish, obstacle: &Obstacle| {
        if obstacle.signed_distance_m(body.position_m) < obstacle_margin_m {
            body.position_m = obstacle.push_outside(body.position_m, obstacle_margin_m);
            let normal = obstacle.outward_normal(body.position_m);
            let into_m_per_s = body.velocity_m_per_s.dot(normal);
            if into_m_per_s < 0.0 {
                body.velocity_m_per_s -= 2.0 * into_m_per_s * normal;
            }
        }
    };
    // Broad phase: an obstacle pushes only when the body (where it is now,
    // after the pushes before) is within the margin of it.
    for k in 0..obstacles.len() {
        if let Some(obstacle) = obstacles.get_if_near(k, body.position_m, obstacle_margin_m) {
            push(body, obstacle);
        }
    }
    for _ in 0..2 {
        for k in 0..stingrays.len() {
            if let Some(disc) = stingrays.get_if_near(k, body.position_m, obstacle_margin_m) {
                push(body, disc);
            }
        }
    }
    // Overlapping discs: lift over every disc that still holds the fish.
    let mut lift_to_m = body.position_m.y;
    for disc in stingrays.near(body.position_m, 0.0) {
        if disc.signed_distance_m(body.position_m) < 0.0 {
            lift_to_m = lift_to_m.max(disc.vertical_extent_m().1 + obstacle_margin_m);
        }
    }
    if lift_to_m > body.position_m.y {
        body.position_m.y = lift_to_m.min(tank.max_m.y - tank_margin_m);
        body.velocity_m_per_s.y = body.velocity_m_per_s.y.abs();
    }
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
