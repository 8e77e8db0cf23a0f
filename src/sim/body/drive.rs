//! Driving a muscle-driven fish from a steering force, shared by every tank of
//! physical fish (the physics tank and the reef's muscle bodies): the force
//! changes the fish's intended velocity, the touch reflex and the body's reach
//! shape it, the motor bridge plans the muscles; after the body step the hard
//! rule keeps every node in the tank and out of the rocks.

use glam::Vec3;

use crate::sim::body::motor_bridge::MotorIntent;
use crate::sim::body::physical_fish::PhysicalFish;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::steering;
use crate::sim::common::tank::Tank;

/// Nodes are kept this far inside the glass, metres.
pub(crate) const GLASS_MARGIN_M: f32 = 0.01;

/// Swimming speed of a fish whose head touched something, fraction of its top
/// speed: the turn-MC's minimum thrust (`motor_bridge::MIN_TURN_SPEED_FRACTION`),
/// enough to turn away, too little to crush the body.
pub(crate) const TOUCH_SPEED_FRACTION: f32 =
    crate::sim::body::motor_bridge::MIN_TURN_SPEED_FRACTION;

/// Fastest turn of the intended velocity, radians per second: 29°/s, a little
/// faster than the body's measured 26–28°/s under continuous steering
/// (`body/motor_bridge.rs`, `physical_fish::agility`), so the body always has a turn
/// to chase but the steering layer never plans a path the body cannot swim.
const MAX_INTENT_TURN_RAD_PER_SEC: f32 = 0.5;
/// Largest angle between the intended velocity and where the body points, radians
/// (60°, chosen): a fish thrown off course by a collision or the current plans
/// from where it really heads, not from where it wished to be.
const MAX_INTENT_LEAD_RAD: f32 = 1.05;

/// Steepest climb or dive a fish intends, radians (25°, chosen: the fins lift the
/// body slowly, `body/tests.rs`).
const MAX_INTENT_PITCH_RAD: f32 = 0.44;

/// Rotates `wanted` (keeping its length) so that it is at most
/// [`MAX_INTENT_TURN_RAD_PER_SEC`]·`dt` from `previous` and at most
/// [`MAX_INTENT_LEAD_RAD`] from `forward`, and
/// at most [`MAX_INTENT_PITCH_RAD`] from level.
pub(crate) fn within_reach(previous: Vec3, wanted: Vec3, forward: Vec3, dt: f32) -> Vec3 {
    let speed = wanted.length();
    let towards = |from: Vec3, to: Vec3, max: f32| -> Vec3 {
        let (from, to) = (from.normalize_or_zero(), to.normalize_or_zero());
        if from == Vec3::ZERO || to == Vec3::ZERO {
            return to;
        }
        let angle = from.dot(to).clamp(-1.0, 1.0).acos();
        if angle <= max {
            return to;
        }
        let axis = from.cross(to).normalize_or(Vec3::Y);
        glam::Quat::from_axis_angle(axis, max) * from
    };
    let direction = towards(previous, wanted, MAX_INTENT_TURN_RAD_PER_SEC * dt);
    let direction = towards(forward, direction, MAX_INTENT_LEAD_RAD);
    // Level it to at most MAX_INTENT_PITCH_RAD up or down.
    let level = (direction * Vec3::new(1.0, 0.0, 1.0)).normalize_or(forward);
    let direction = towards(level, direction, MAX_INTENT_PITCH_RAD);
    direction * speed
}

/// Touch reflex: a fish whose head touched the glass or a rock (pushed out along
/// `away`, unit) wants to swim away from it, slowly: `wanted_m_per_s` mirrored
/// off the touched surface, at [`TOUCH_SPEED_FRACTION`] of `top_m_per_s`
/// (pushing on at full speed crushed the body to 0.78 of its length, measured).
pub(crate) fn touch_reflex(wanted_m_per_s: Vec3, away: Vec3, top_m_per_s: f32) -> Vec3 {
    let away = (away * Vec3::new(1.0, 0.0, 1.0)).normalize_or(away);
    let into = wanted_m_per_s.dot(away).min(0.0);
    (wanted_m_per_s - 2.0 * into * away).normalize_or(away) * TOUCH_SPEED_FRACTION * top_m_per_s
}

/// Turns a steering force on a physical animal into its motor intent: the
/// force changes the animal's intended velocity (`intended`, a point-mass
/// velocity like a boid's), the touch reflex and the body's reach
/// ([`within_reach`]) shape it, and the bridge plans the muscles. Shared by
/// every tank of physical fish.
pub(crate) fn drive_physical(
    animal: &mut PhysicalFish,
    intended: &mut Vec3,
    steering_m_per_s2: Vec3,
    touch: Option<Vec3>,
    dt: f32,
) -> MotorIntent {
    let top = animal.top_speed_m_per_s();
    let mut v = steering::limit(*intended + steering_m_per_s2 * dt, top);
    if let Some(away) = touch {
        v = touch_reflex(v, away, top);
    }
    let v = if v.length() < 0.3 * top {
        v.normalize_or(animal.heading()) * 0.3 * top
    } else {
        v
    };
    let v = within_reach(*intended, v, animal.heading(), dt);
    *intended = v;
    let mut intent = animal.plan(v);
    if touch.is_some() {
        intent.speed_fraction = intent.speed_fraction.min(TOUCH_SPEED_FRACTION);
    }
    intent
}

/// One body step of a physical animal, then the hard rule: no node leaves the
/// tank or enters a rock. Returns the hard rule's node moves and the direction
/// the head was pushed, if it touched something.
pub(crate) fn step_and_constrain(
    animal: &mut PhysicalFish,
    intent: &MotorIntent,
    water_m_per_s: Vec3,
    tank: &Tank,
    obstacles: &[Obstacle],
) -> (usize, Option<Vec3>) {
    animal.step(intent, water_m_per_s);
    let (lo, hi) = (
        tank.min_m + Vec3::splat(GLASS_MARGIN_M),
        tank.max_m - Vec3::splat(GLASS_MARGIN_M),
    );
    let centre = animal.point.position_m;
    let reach = animal.body_length_m();
    animal.constrain(lo, hi, |p| {
        obstacles
            .iter()
            .filter(|o| o.signed_distance_m(centre) < reach)
            .find(|o| o.signed_distance_m(p) < 0.0)
            .map(|o| o.push_outside(p, 0.005))
    })
}
