//! A muscle-driven fish in the tank: the spring–mass body of `body/` with its swim
//! and turn motor controllers, the bridge from the steering layer
//! (`body/motor_bridge.rs`) and a point-mass summary (centre of mass and velocity) that
//! the steering layer and the school metrics read like any boid.
//!
//! Species differ by size, mass and colour only (chosen): the body scales its masses with the square of its length
//! (see `body/fish_body.rs`), so a shark twice as long is four times heavier
//! and swims twice as fast in metres per second.

use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::body::motor_bridge::{
    MotorBridge, MotorIntent, MotorParams, TOP_SPEED_BODY_LENGTHS_PER_SEC, to_body_frame,
    to_tank_frame,
};
use crate::sim::body::{FishBody, MUSCLE_COUNT, NODE_COUNT, PectoralFins, SwimMc, TurnMc};
use crate::sim::common::fish::Fish;

#[cfg(not(target_arch = "wasm32"))]
pub mod trials;

/// Body steps over which the fore body's direction is averaged into the heading.
/// 8, chosen: 8 steps of 0.055 s = 0.44 s, one tail beat at the swim-MC's 2.3 Hz,
/// so the average nulls the beat. The fore body yaws about ±20° with every beat; a
/// bridge reading the raw direction starts turns the wrong way, and one reading an
/// exponential average (time constant 0.5 s) still sees a ±3° wiggle at the beat
/// frequency: on the converged body that wiggle, fed back through the steering
/// bend in time with the beat, damps the swim wave until a fish correcting a small
/// heading error at 0.4 of its top speed stalls at 0.02 m/s (measured,
/// census `closed-loop-turn-times`).
pub const HEADING_WINDOW_STEPS: usize = 8;

/// What kind of animal a physical fish is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BodySpecies {
    /// A reef fish about half a metre long.
    Fish,
    /// A shark: the same body, twice as long.
    Shark,
}

impl BodySpecies {
    /// Typical body length, metres (fish 0.5 m, chosen so a fish at top speed,
    /// 0.3 m/s, crosses the 12 m tank in 40 s; shark 1.0 m, a small reef shark:
    /// larger ones turn in circles wider than the 8 m tank is deep).
    pub fn body_length_m(self) -> f32 {
        match self {
            Self::Fish => 0.5,
            Self::Shark => 1.0,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Fish => "fish",
            Self::Shark => "shark",
        }
    }
}

/// The motor command in use, for the inspector and the plots.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MotorState {
    /// swim-MC speed fraction in [0, 1].
    pub speed_fraction: f32,
    /// Pectoral fins.
    pub fins: PectoralFins,
    /// Is a turn running?
    pub turning: bool,
    /// The 12 muscle contractions sent to the body (order of `body_layout::MUSCLES`).
    pub muscles: [f32; MUSCLE_COUNT],
}

/// One physical fish.
#[derive(Clone, Debug)]
pub struct PhysicalFish {
    pub species: BodySpecies,
    /// Colour around the colour wheel, 0..1.
    pub hue: f32,
    body: FishBody,
    swim: SwimMc,
    turn: TurnMc,
    bridge: MotorBridge,
    motor: MotorState,
    /// Where the fish is heading: the fore body's direction averaged over the
    /// last [`HEADING_WINDOW_STEPS`] steps (tank frame, unit).
    heading: Vec3,
    /// The fore body's direction at the last [`HEADING_WINDOW_STEPS`] steps, a
    /// ring buffer written at `recent_next`.
    recent_forward: [Vec3; HEADING_WINDOW_STEPS],
    recent_next: usize,
    /// The fish as the steering layer sees it: centre of mass, velocity, wander
    /// state (tank frame).
    pub point: Fish,
}

impl PhysicalFish {
    /// A fish at rest with its centre of mass at `position_m` heading along
    /// `heading` (tank frame, y up).
    pub fn new(
        species: BodySpecies,
        body_length_m: f32,
        position_m: Vec3,
        heading: Vec3,
        hue: f32,
    ) -> Self {
        let body = FishBody::new(
            body_length_m,
            to_body_frame(position_m),
            to_body_frame(heading),
        );
        let mut fish = Self {
            species,
            hue,
            body,
            swim: SwimMc::default(),
            turn: TurnMc::default(),
            bridge: MotorBridge::default(),
            motor: MotorState::default(),
            heading: heading.normalize_or(Vec3::X),
            recent_forward: [heading.normalize_or(Vec3::X); HEADING_WINDOW_STEPS],
            recent_next: 0,
            point: Fish::new(position_m, Vec3::ZERO, body_length_m, hue),
        };
        fish.sync_point();
        fish
    }

    pub fn body(&self) -> &FishBody {
        &self.body
    }

    /// The body, to change its parameters in tests and measurement scripts.
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn body_mut(&mut self) -> &mut FishBody {
        &mut self.body
    }

    pub fn motor(&self) -> &MotorState {
        &self.motor
    }

    /// The tuning of the fish's motor bridge and controllers.
    pub fn motor_params(&self) -> &MotorParams {
        self.bridge.params()
    }

    pub fn body_length_m(&self) -> f32 {
        self.body.rest_body_length_m()
    }

    /// Top swimming speed, m/s.
    pub fn top_speed_m_per_s(&self) -> f32 {
        TOP_SPEED_BODY_LENGTHS_PER_SEC * self.body_length_m()
    }

    /// Node positions in the tank frame, metres.
    pub fn nodes_m(&self) -> [Vec3; NODE_COUNT] {
        self.body.positions_m().map(to_tank_frame)
    }

    /// Unit forward direction of the fore body now (tank frame); it swings with
    /// the tail beat.
    pub fn forward(&self) -> Vec3 {
        to_tank_frame(self.body.forward())
    }

    /// Where the fish is heading: [`Self::forward`] averaged over about a tail
    /// beat (tank frame, unit).
    pub fn heading(&self) -> Vec3 {
        self.heading
    }

    /// Unit dorsal direction (tank frame).
    pub fn up(&self) -> Vec3 {
        to_tank_frame(self.body.up())
    }

    /// Starts a turn of `angle_deg` (+ = left), as a hand command would.
    pub fn turn(&mut self, angle_deg: f32) {
        self.turn.start_turn(angle_deg);
    }

    /// Is a turn running?
    pub fn is_turning(&self) -> bool {
        self.turn.is_turning()
    }

    /// Adds `dv_m_per_s` (tank frame) to every node's velocity: an outside
    /// impulse, such as the pull of a predator's open mouth (§7.1).
    pub fn add_velocity(&mut self, dv_m_per_s: Vec3) {
        if !dv_m_per_s.is_finite() {
            return;
        }
        let dv = to_body_frame(dv_m_per_s);
        let (_, velocities) = self.body.nodes_mut();
        for v in velocities.iter_mut() {
            *v += dv;
        }
        self.sync_point();
    }

    /// What the bridge makes of `desired_m_per_s` (tank frame) now.
    pub fn plan(&mut self, desired_m_per_s: Vec3) -> MotorIntent {
        let top = self.top_speed_m_per_s();
        self.bridge.plan(
            desired_m_per_s,
            self.heading,
            self.point.velocity_m_per_s.length(),
            top,
            self.turn.is_turning(),
        )
    }

    /// Records the fore body's direction and averages the last
    /// [`HEADING_WINDOW_STEPS`] into the heading.
    fn update_heading(&mut self) {
        let forward = self.forward();
        if forward == Vec3::ZERO {
            return;
        }
        self.recent_forward[self.recent_next] = forward;
        self.recent_next = (self.recent_next + 1) % HEADING_WINDOW_STEPS;
        let sum: Vec3 = self.recent_forward.iter().sum();
        self.heading = sum.normalize_or(forward);
    }

    /// Advances one body step under `intent` in water moving at
    /// `water_m_per_s` (tank frame).
    pub fn step(&mut self, intent: &MotorIntent, water_m_per_s: Vec3) {
        if let Some(angle) = intent.start_turn_deg {
            self.turn.start_turn(angle);
        }
        let dt = self.body.dt_secs();
        let turning = self.turn.is_turning();
        // A turn's quick stroke begins at the beat phase its key was measured at
        // (less than one beat later; the frequency is the same at every speed).
        let beat_hz = self.swim.max.anterior_frequency_hz;
        self.turn
            .wait_for_beat(self.swim.anterior_phase_rad(), beat_hz);
        // From the step in which the stroke begins, a turn-MC turn beats the tail
        // at the setting its keys were measured at.
        let speed_fraction = if turning && self.turn.wait_secs() < dt {
            self.bridge.params().turn_swim_speed_fraction
        } else {
            intent.speed_fraction
        };
        let params = self.swim.params_for_speed(speed_fraction);
        // The motor controllers are sampled at every substep of the body.
        let (swim, turn, motor_params) = (&self.swim, &self.turn, self.bridge.params());
        self.body
            .step_with(&intent.fins, to_body_frame(water_m_per_s), |t| {
                let mut muscles = crate::sim::body::turn_mc::combine_swim_and_turn(
                    &swim.muscles_at(&params, t),
                    &turn.muscles_at(t),
                );
                crate::sim::body::turn_mc::add_steering(motor_params, &mut muscles, intent.steer);
                muscles
            });
        self.swim.advance(&params, dt);
        self.turn.advance(dt);
        self.update_heading();
        self.motor = MotorState {
            speed_fraction: speed_fraction.clamp(0.0, 1.0),
            fins: intent.fins,
            turning,
            muscles: *self.body.muscle_contractions(),
        };
        self.sync_point();
    }

    /// Keeps every node inside the box `[min_m, max_m]` (tank frame) and outside
    /// the solids (`push_out` moves a point inside a solid to its surface). The
    /// body is moved as a whole: it is translated by the deepest node's push, up
    /// to four times (a corner, a wall and a rock), and loses the velocity that
    /// carried it in. Moving nodes one by one flattened bodies against rocks
    /// (measured: 0.78 of their length). Returns how many pushes were needed and,
    /// if the head or the fore body touched something, the direction it was
    /// pushed (tank frame, unit).
    pub fn constrain(
        &mut self,
        min_m: Vec3,
        max_m: Vec3,
        push_out: impl Fn(Vec3) -> Option<Vec3>,
    ) -> (usize, Option<Vec3>) {
        /// The head tip and rings 1–2.
        const FORE_NODES: usize = 9;
        const MAX_PUSHES: usize = 4;
        let (positions, velocities) = self.body.nodes_mut();
        let mut pushes = 0;
        let mut touch = None;
        for _ in 0..MAX_PUSHES {
            let mut deepest: Option<(usize, Vec3)> = None;
            for (node, p) in positions.iter().enumerate() {
                let tank_p = to_tank_frame(*p);
                let mut q = tank_p.clamp(min_m, max_m);
                if let Some(out) = push_out(q) {
                    q = out;
                }
                let push = q - tank_p;
                if push != Vec3::ZERO
                    && deepest.is_none_or(|(_, d)| push.length_squared() > d.length_squared())
                {
                    deepest = Some((node, push));
                }
            }
            let Some((node, push)) = deepest else { break };
            pushes += 1;
            let normal = push.normalize_or_zero();
            if node < FORE_NODES && touch.is_none() {
                touch = Some(normal);
            }
            let (push_b, normal_b) = (to_body_frame(push), to_body_frame(normal));
            for (p, v) in positions.iter_mut().zip(velocities.iter_mut()) {
                *p += push_b;
                *v -= v.dot(normal_b).min(0.0) * normal_b;
            }
        }
        if pushes > 0 {
            self.sync_point();
        }
        (pushes, touch)
    }

    fn sync_point(&mut self) {
        self.point.position_m = to_tank_frame(self.body.centre_of_mass_m());
        self.point.velocity_m_per_s = to_tank_frame(self.body.velocity_m_per_s());
    }
}
