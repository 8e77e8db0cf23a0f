//! The bodies stage of the reef's step: what carries a mind and how it moves.
//! The muscle body's motor controllers are picked by the routine's motor
//! choice (`reef/motor_choice.rs`); the point-mass body of the boid layer is
//! steered to the wished velocity. Under both, keeping off the glass, sand,
//! surface and rocks bends the direction of a swimming wish (the motor
//! preferences).
//!
//! [`Drive`] is the state each body keeps between steps for moving (the
//! velocity it chases, the last touch of glass or rock, the wander state);
//! [`move_body`] takes it with the body and everything it reads as explicit
//! inputs.

use glam::Vec3;
use rand::Rng;
use serde::{Deserialize, Serialize};

use crate::sim::body::body_layout::HEAD_NODE;
use crate::sim::body::drive::{drive_physical, step_and_constrain, touch_reflex};
use crate::sim::body::motor_bridge::TOP_SPEED_BODY_LENGTHS_PER_SEC;
use crate::sim::body::physical_fish::PhysicalFish;
use crate::sim::common::fish::Fish;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::steering::{self, SteeringParams};
use crate::sim::common::steering_tuning::SteeringTuning;
use crate::sim::common::tank::Tank;
use crate::sim::reef::motor_choice::{self, Gait, Wish};
use crate::sim::reef::params::ReefParams;

/// Time step of the point-mass body, seconds: the fish world's one step
/// ([`crate::sim::common::paper_time::FISH_STEP_SECS`]), as the muscle body's, so both
/// bodies see the same world clock.
pub const POINT_BODY_DT_SECS: f32 = crate::sim::common::paper_time::FISH_STEP_SECS;

/// Which body carries the minds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ReefBodyKind {
    /// The muscle-driven spring–mass fish (Tu & Terzopoulos §3).
    #[default]
    Physical,
    /// The boid layer's point-mass fish: cheap, for big scenes.
    PointMass,
}

/// The body of one reef animal.
#[derive(Clone, Debug)]
pub enum ReefBody {
    Physical(Box<PhysicalFish>),
    Point(Fish),
}

impl ReefBody {
    pub fn position_m(&self) -> Vec3 {
        match self {
            Self::Physical(p) => p.point.position_m,
            Self::Point(f) => f.position_m,
        }
    }

    pub fn velocity_m_per_s(&self) -> Vec3 {
        match self {
            Self::Physical(p) => p.point.velocity_m_per_s,
            Self::Point(f) => f.velocity_m_per_s,
        }
    }

    /// Where the fish points (unit).
    pub fn heading(&self) -> Vec3 {
        match self {
            Self::Physical(p) => p.heading(),
            Self::Point(f) => f.heading(),
        }
    }

    pub fn body_length_m(&self) -> f32 {
        match self {
            Self::Physical(p) => p.body_length_m(),
            Self::Point(f) => f.body_length_m,
        }
    }

    /// Top speed, m/s (the same for both bodies of a given length).
    pub fn top_speed_m_per_s(&self) -> f32 {
        TOP_SPEED_BODY_LENGTHS_PER_SEC * self.body_length_m()
    }

    /// The mouth (the head node of the muscle body).
    pub fn head_m(&self) -> Vec3 {
        match self {
            Self::Physical(p) => p.nodes_m()[HEAD_NODE],
            Self::Point(f) => f.position_m + f.heading() * 0.5 * f.body_length_m,
        }
    }

    /// Adds `dv_m_per_s` to the whole body's velocity (the vacuum's pull).
    pub(super) fn nudge(&mut self, dv_m_per_s: Vec3) {
        match self {
            Self::Physical(p) => p.add_velocity(dv_m_per_s),
            Self::Point(f) => f.velocity_m_per_s += dv_m_per_s,
        }
    }

    /// The same kind of body, `length_m` long, at rest at `position_m`
    /// heading along `heading` (a teacher's drag or a test's placing).
    pub(super) fn placed(&self, position_m: Vec3, heading: Vec3, length_m: f32) -> Self {
        match self {
            Self::Physical(old) => Self::Physical(Box::new(PhysicalFish::new(
                old.species,
                length_m,
                position_m,
                heading,
                old.hue,
            ))),
            Self::Point(f) => Self::Point(Fish::new(
                position_m,
                heading.normalize_or(Vec3::X) * 0.3 * TOP_SPEED_BODY_LENGTHS_PER_SEC * length_m,
                length_m,
                f.hue,
            )),
        }
    }
}

/// What a body keeps between steps for moving.
#[derive(Clone, Debug)]
pub struct Drive {
    /// Point-mass velocity the muscle body chases (see `physics/world.rs`),
    /// or the point-mass body's own velocity, m/s.
    intended_m_per_s: Vec3,
    /// The way off the glass or rock the body touched last step, if it did.
    touch: Option<Vec3>,
    /// Wander state for the point body and the wander routine.
    wander: Fish,
}

impl Drive {
    /// A body at `position_m` swimming at `velocity_m_per_s`, `length_m`
    /// long, of colour `hue`.
    pub(super) fn new(position_m: Vec3, velocity_m_per_s: Vec3, length_m: f32, hue: f32) -> Self {
        Self {
            intended_m_per_s: velocity_m_per_s,
            touch: None,
            wander: Fish::new(position_m, velocity_m_per_s, length_m, hue),
        }
    }

    /// After the body was put down at `position_m`, to swim off at
    /// `intended_m_per_s`: no touch, the wander state moved with it.
    pub(super) fn placed(&mut self, position_m: Vec3, intended_m_per_s: Vec3) {
        self.intended_m_per_s = intended_m_per_s;
        self.wander.position_m = position_m;
        self.touch = None;
    }

    /// A dart at `velocity_m_per_s` (a prey fish escaping a missed strike).
    pub(super) fn dart(&mut self, velocity_m_per_s: Vec3) {
        self.intended_m_per_s = velocity_m_per_s;
    }

    /// One step of the boid layer's wander steering for a fish at
    /// `position_m`: the push it gives.
    pub(super) fn wander_push(
        &mut self,
        position_m: Vec3,
        rng: &mut impl Rng,
        params: &SteeringParams,
        tuning: &SteeringTuning,
    ) -> Vec3 {
        self.wander.position_m = position_m;
        self.wander.velocity_m_per_s = self.intended_m_per_s;
        steering::wander(&mut self.wander, rng, params, tuning)
    }
}

/// What the body stage reads besides the body: the tank, the rocks, the
/// water at the body, where the fish is closing in on (its food, prey or
/// partner, if it is), and the clock.
pub(super) struct BodyInputs<'a> {
    pub params: &'a ReefParams,
    pub tank: &'a Tank,
    pub obstacles: &'a [Obstacle],
    pub water_m_per_s: Vec3,
    pub chase_target_m: Option<Vec3>,
    pub time_secs: f32,
    pub dt_secs: f32,
}

/// What one body step did, for the world's counters.
pub(super) struct Moved {
    /// Constraint node moves of a muscle body.
    pub constraint_moves: u64,
    /// Did the body end the step inside a rock?
    pub inside_rock: bool,
}

/// Moves `body` as `wish` asks. The muscle body: the motor choice
/// (`reef/motor_choice.rs`) picks its motor controllers; the point-mass body:
/// the boid layer steers it towards the wished velocity. Under both, keeping
/// off the glass, sand, surface and rocks bends the direction of a swimming
/// wish.
pub(super) fn move_body(
    body: &mut ReefBody,
    drive: &mut Drive,
    wish: Wish,
    inputs: &BodyInputs,
) -> Moved {
    let BodyInputs {
        params,
        tank,
        obstacles,
        water_m_per_s: water,
        chase_target_m: chase_target,
        time_secs,
        dt_secs: dt,
    } = *inputs;
    let desired = wish.velocity_m_per_s;
    let top = body.top_speed_m_per_s();
    let length = body.body_length_m();
    let drive_params = &params.drive;
    let response_time_secs = drive_params.response_time_secs;
    let max_force = top / response_time_secs;
    let position = body.position_m();
    // Motor preferences: keep off the glass, sand, surface and rocks. A fish
    // closing in on its food, prey or partner heeds only the glass that lies
    // before it (see `ReefParams::chase_glass_margin_body_lengths`).
    let (look_ahead_s, margin_m) = match chase_target {
        Some(target_m) => (
            (target_m.distance(position) / top.max(1e-3))
                .min(drive_params.containment_look_ahead_secs),
            params.chase_glass_margin_body_lengths * length,
        ),
        None => (
            drive_params.containment_look_ahead_secs,
            drive_params.containment_margin_m(length),
        ),
    };
    let contain = |velocity: Vec3| {
        steering::containment(position, velocity, tank, look_ahead_s, margin_m, top)
    };
    let avoid_rocks = |velocity: Vec3| {
        steering::avoid_obstacles(
            position,
            velocity,
            obstacles.iter(),
            3.0,
            params.steering.avoidance_clearance_m + 0.5 * length,
            top,
        )
    };
    let keep_off = |velocity: Vec3| contain(velocity) + avoid_rocks(velocity);
    let mut constraint_moves = 0;
    match body {
        ReefBody::Physical(p) if wish.gait == Gait::School => {
            // The physics scene's way: the boid layer's intended velocity,
            // then the bridge.
            let velocity = drive.intended_m_per_s;
            let steer = steering::limit((desired - velocity) / response_time_secs, max_force);
            let keep = steering::limit(keep_off(velocity) / response_time_secs, max_force);
            let force = steering::limit(steer + keep, max_force);
            let intent = drive_physical(
                drive_params,
                p,
                &mut drive.intended_m_per_s,
                force,
                drive.touch,
                dt,
            );
            let (moved, touch) =
                step_and_constrain(drive_params, p, &intent, water, tank, obstacles);
            constraint_moves = moved as u64;
            drive.touch = touch;
        }
        ReefBody::Physical(p) => {
            let heading = p.heading();
            let speed = p.point.velocity_m_per_s.length();
            let mut wish = wish;
            if matches!(wish.gait, Gait::Swim | Gait::Pursue | Gait::Forage) {
                // The path the fish is on: its heading at the speed it swims
                // or means to swim.
                let wanted = desired.length();
                let path = heading * speed.max(wanted);
                let bent = desired + keep_off(path);
                let mut v = bent.normalize_or(heading) * wanted;
                if let Some(away) = drive.touch {
                    v = touch_reflex(drive_params, v, away, top);
                }
                wish.velocity_m_per_s = v;
            }
            let motor_body = motor_choice::Body {
                heading,
                speed_m_per_s: speed,
                top_speed_m_per_s: top,
                turning: p.is_turning(),
            };
            let intent = motor_choice::choose(&params.motor_choice, &wish, &motor_body, time_secs);
            let (moved, touch) =
                step_and_constrain(drive_params, p, &intent, water, tank, obstacles);
            constraint_moves = moved as u64;
            drive.touch = touch;
            drive.intended_m_per_s = wish.velocity_m_per_s;
        }
        ReefBody::Point(f) => {
            let velocity = drive.intended_m_per_s;
            let steer = steering::limit((desired - velocity) / response_time_secs, max_force);
            let containment = steering::limit(contain(velocity) / response_time_secs, max_force);
            let avoidance = steering::limit(avoid_rocks(velocity) / response_time_secs, max_force);
            let force = steering::limit(steer + containment + avoidance, max_force);
            let steering_params = SteeringParams {
                max_speed_m_per_s: top,
                min_speed_m_per_s: 0.2 * top,
                max_force_m_per_s2: max_force,
                ..SteeringParams::default()
            };
            f.velocity_m_per_s = drive.intended_m_per_s;
            f.integrate(force, &steering_params, dt);
            f.position_m += water * dt;
            f.position_m = tank.clamp_inside(f.position_m, 0.5 * length.min(0.5));
            for o in obstacles {
                if o.signed_distance_m(f.position_m) < 0.1 * length {
                    f.position_m = o.push_outside(f.position_m, 0.1 * length);
                }
            }
            f.advance_tail_phase(dt);
            drive.intended_m_per_s = f.velocity_m_per_s;
        }
    }
    let inside_rock = obstacles
        .iter()
        .any(|o| o.signed_distance_m(body.position_m()) < 0.0);
    Moved {
        constraint_moves,
        inside_rock,
    }
}
