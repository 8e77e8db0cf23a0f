//! Driving a muscle-driven fish from a steering force, shared by every tank of
//! physical fish (the physics tank and the reef's muscle bodies): the force
//! changes the fish's intended velocity, the touch reflex and the body's reach
//! shape it, the motor bridge plans the muscles; after the body step the hard
//! rule keeps every node in the tank and out of the rocks.

use crate::sim::common::fmath;
use glam::Vec3;

use crate::sim::body::motor_bridge::MotorIntent;
use crate::sim::body::physical_fish::PhysicalFish;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::steering;
use crate::sim::common::tank::Tank;

/// The tuning of the shared "steer a muscle fish within its body's reach"
/// recipe ([`drive_physical`], [`within_reach`], [`touch_reflex`],
/// [`step_and_constrain`]) and of the containment both tanks of muscle fish put
/// before it. One recipe, two sets of numbers: the physics tank uses
/// [`DriveParams::physics_tank`] (the `Default`), the reef
/// [`DriveParams::reef`]; they differ only in the containment look-ahead and
/// margin, each tuned for its tank (the reef's with the earlier muscle body and
/// its courting, feeding and fleeing fish, which must come closer to the glass
/// than a school). Paper data (node masses, spring stiffnesses) stays in
/// `body/body_layout.rs`.
#[derive(Clone, Debug, PartialEq)]
pub struct DriveParams {
    /// Nodes are kept this far inside the glass, metres (0.01).
    pub glass_margin_m: f32,
    /// Swimming speed of a fish whose head touched something, fraction of its top
    /// speed: the turn-MC's minimum thrust (`MotorParams::min_turn_speed_fraction`,
    /// 0.5), enough to turn away, too little to crush the body.
    pub touch_speed_fraction: f32,
    /// Fastest turn of the intended velocity, radians per second (0.5): 29°/s, a little
    /// faster than the body's measured 26–28°/s under continuous steering
    /// (`body/motor_bridge.rs`, `physical_fish::trials`), so the body always has a turn
    /// to chase but the steering layer never plans a path the body cannot swim.
    pub max_intent_turn_rad_per_sec: f32,
    /// Largest angle between the intended velocity and where the body points, radians
    /// (1.05, 60°, chosen): a fish thrown off course by a collision or the current plans
    /// from where it really heads, not from where it wished to be.
    pub max_intent_lead_rad: f32,
    /// Steepest climb or dive a fish intends, radians (0.44, 25°, chosen: the fins lift the
    /// body slowly, `body/tests/trim.rs`).
    pub max_intent_pitch_rad: f32,
    /// Time in which a steering force would reach its desired velocity, seconds
    /// (0.25, chosen, in both tanks; the schooling lab's *group* preset uses 0.1
    /// for its point masses). In the reef: the time in which a behaviour's wish
    /// becomes a steering force, for the muscle and the point-mass body alike.
    pub response_time_secs: f32,
    /// How far ahead in time containment predicts the path, seconds.
    ///
    /// Physics tank: 10, chosen: at cruising speed (0.2 m/s for the default fish)
    /// the fish reacts 2 m before the margin, time for the body's held bend
    /// (26–28°/s, `body/motor_bridge.rs`) to turn it round with room to spare.
    ///
    /// Reef: how far ahead a reef fish foresees the glass, sand and surface,
    /// seconds of its present velocity. 8 (tuned with the earlier muscle body,
    /// whose turning circle was about 0.75 body lengths at cruising speed; the
    /// converged body's is about 1.2, `ReefParams::body_turn_radius_body_lengths`).
    pub containment_look_ahead_secs: f32,
    /// Room kept from the glass, floor and surface by the predicted path, body
    /// lengths.
    ///
    /// Physics tank: 2, chosen: the turn itself swings the tail out by about one.
    ///
    /// Reef: how far from the glass, sand and surface a reef fish keeps, body
    /// lengths. 1.5 (tuned: room for the muscle body to turn).
    pub containment_margin_body_lengths: f32,
}

impl DriveParams {
    /// The physics tank's numbers (containment 10 s ahead, 2 body lengths).
    pub fn physics_tank() -> Self {
        Self {
            glass_margin_m: 0.01,
            touch_speed_fraction: crate::sim::body::motor_bridge::MotorParams::default()
                .min_turn_speed_fraction,
            max_intent_turn_rad_per_sec: 0.5,
            max_intent_lead_rad: 1.05,
            max_intent_pitch_rad: 0.44,
            response_time_secs: 0.25,
            containment_look_ahead_secs: 10.0,
            containment_margin_body_lengths: 2.0,
        }
    }

    /// The reef's numbers: the physics tank's, with containment 8 s ahead and
    /// 1.5 body lengths (see the fields).
    pub fn reef() -> Self {
        Self {
            containment_look_ahead_secs: 8.0,
            containment_margin_body_lengths: 1.5,
            ..Self::physics_tank()
        }
    }

    /// The containment margin of a fish `body_length_m` long, metres.
    pub fn containment_margin_m(&self, body_length_m: f32) -> f32 {
        self.containment_margin_body_lengths * body_length_m
    }
}

impl Default for DriveParams {
    /// The physics tank's numbers ([`DriveParams::physics_tank`]).
    fn default() -> Self {
        Self::physics_tank()
    }
}

/// Rotates `wanted` (keeping its length) so that it is at most
/// [`DriveParams::max_intent_turn_rad_per_sec`]·`dt` from `previous` and at most
/// [`DriveParams::max_intent_lead_rad`] from `forward`, and
/// at most [`DriveParams::max_intent_pitch_rad`] from level.
pub(crate) fn within_reach(
    params: &DriveParams,
    previous: Vec3,
    wanted: Vec3,
    forward: Vec3,
    dt: f32,
) -> Vec3 {
    let speed = wanted.length();
    let towards = |from: Vec3, to: Vec3, max: f32| -> Vec3 {
        let (from, to) = (from.normalize_or_zero(), to.normalize_or_zero());
        if from == Vec3::ZERO || to == Vec3::ZERO {
            return to;
        }
        let angle = fmath::acos(from.dot(to).clamp(-1.0, 1.0));
        if angle <= max {
            return to;
        }
        let axis = from.cross(to).normalize_or(Vec3::Y);
        glam::Quat::from_axis_angle(axis, max) * from
    };
    let direction = towards(previous, wanted, params.max_intent_turn_rad_per_sec * dt);
    let direction = towards(forward, direction, params.max_intent_lead_rad);
    // Level it to at most max_intent_pitch_rad up or down.
    let level = (direction * Vec3::new(1.0, 0.0, 1.0)).normalize_or(forward);
    let direction = towards(level, direction, params.max_intent_pitch_rad);
    direction * speed
}

/// Touch reflex: a fish whose head touched the glass or a rock (pushed out along
/// `away`, unit) wants to swim away from it, slowly: `wanted_m_per_s` mirrored
/// off the touched surface, at [`DriveParams::touch_speed_fraction`] of `top_m_per_s`
/// (pushing on at full speed crushed the body to 0.78 of its length, measured).
pub(crate) fn touch_reflex(
    params: &DriveParams,
    wanted_m_per_s: Vec3,
    away: Vec3,
    top_m_per_s: f32,
) -> Vec3 {
    let away = (away * Vec3::new(1.0, 0.0, 1.0)).normalize_or(away);
    let into = wanted_m_per_s.dot(away).min(0.0);
    (wanted_m_per_s - 2.0 * into * away).normalize_or(away)
        * params.touch_speed_fraction
        * top_m_per_s
}

/// Turns a steering force on a physical animal into its motor intent: the
/// force changes the animal's intended velocity (`intended`, a point-mass
/// velocity like a boid's), the touch reflex and the body's reach
/// ([`within_reach`]) shape it, and the bridge plans the muscles. Shared by
/// every tank of physical fish.
pub(crate) fn drive_physical(
    params: &DriveParams,
    animal: &mut PhysicalFish,
    intended: &mut Vec3,
    steering_m_per_s2: Vec3,
    touch: Option<Vec3>,
    dt: f32,
) -> MotorIntent {
    let top = animal.top_speed_m_per_s();
    let mut v = steering::limit(*intended + steering_m_per_s2 * dt, top);
    if let Some(away) = touch {
        v = touch_reflex(params, v, away, top);
    }
    let v = if v.length() < 0.3 * top {
        v.normalize_or(animal.heading()) * 0.3 * top
    } else {
        v
    };
    let v = within_reach(params, *intended, v, animal.heading(), dt);
    *intended = v;
    let mut intent = animal.plan(v);
    if touch.is_some() {
        intent.speed_fraction = intent.speed_fraction.min(params.touch_speed_fraction);
    }
    intent
}

/// One body step of a physical animal, then the hard rule: no node leaves the
/// tank or enters a rock. Returns the hard rule's node moves and the direction
/// the head was pushed, if it touched something.
pub(crate) fn step_and_constrain(
    params: &DriveParams,
    animal: &mut PhysicalFish,
    intent: &MotorIntent,
    water_m_per_s: Vec3,
    tank: &Tank,
    obstacles: &[Obstacle],
) -> (usize, Option<Vec3>) {
    animal.step(intent, water_m_per_s);
    let (lo, hi) = (
        tank.min_m + Vec3::splat(params.glass_margin_m),
        tank.max_m - Vec3::splat(params.glass_margin_m),
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
