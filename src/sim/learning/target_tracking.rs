//! Target tracking with learned controllers, Tu & Terzopoulos 1994 §4.3 and Fig. 9:
//! "a shark model that has trained itself to swim between targets (spherical
//! buoys); having swum from the left to the far target, it has now turned and is
//! proceeding to the near target."
//!
//! The fish uses only the learned speed and steering map ([`LearnedMotor`]): full
//! learned speed, and a turn request proportional to the horizontal angle between
//! its heading and the buoy ([`FULL_TURN_ERROR_DEG`] or more asks for the largest
//! learned turn rate). Its heading is the fore body's direction averaged over
//! [`HEADING_SMOOTHING_SECS`] (the fore body yaws with every tail beat, as in
//! `body/physical_fish.rs`). A buoy is reached when the centre of mass comes within
//! [`REACH_RADIUS_BODY_LENGTHS`]; the fish then makes for the other one, and so on.
//! Everything is in the body frame of the start (z up); the buoys' heights are
//! ignored.

use glam::{Vec2, Vec3};

use crate::sim::body::physical_fish::BodySpecies;
use crate::sim::body::{BodyParams, FishBody, PectoralFins};
use crate::sim::learning::learned_motor::{LearnedMotor, LearnedMotorMap};

/// Heading error that asks for the largest learned turn, degrees. 30, chosen:
/// smaller errors ask for proportionally gentler turns, so the fish does not
/// zig-zag past the buoy.
pub const FULL_TURN_ERROR_DEG: f32 = 30.0;
/// A buoy is reached within this distance of the centre of mass, body lengths.
/// 1.0, chosen: the fish passes beside it, as in Fig. 9.
pub const REACH_RADIUS_BODY_LENGTHS: f32 = 1.0;
/// Time constant of the heading average, seconds (0.5, as `body/physical_fish.rs`).
pub const HEADING_SMOOTHING_SECS: f32 = 0.5;

/// A fish swimming between two buoys on learned controllers.
#[derive(Clone, Debug)]
pub struct BuoyTracker {
    body: FishBody,
    motor: LearnedMotor,
    buoys_m: [Vec3; 2],
    next_buoy: usize,
    heading: Vec2,
    steps: u64,
    reached_secs: Vec<f32>,
    path_m: Vec<Vec3>,
}

impl BuoyTracker {
    /// A fish of `species` at rest at the origin heading +x, making for `buoys_m[0]`
    /// first (body frame, metres).
    pub fn new(
        map: LearnedMotorMap,
        species: BodySpecies,
        params: BodyParams,
        buoys_m: [Vec3; 2],
    ) -> Self {
        let body = FishBody::with_params(species.body_length_m(), Vec3::ZERO, Vec3::X, params);
        let start = body.centre_of_mass_m();
        Self {
            body,
            motor: LearnedMotor::new(map),
            buoys_m,
            next_buoy: 0,
            heading: Vec2::X,
            steps: 0,
            reached_secs: Vec::new(),
            path_m: vec![start],
        }
    }

    /// One body step.
    pub fn step(&mut self) {
        let dt = self.body.dt_secs();
        let here = self.body.centre_of_mass_m();
        let to_buoy = (self.buoys_m[self.next_buoy] - here).truncate();
        let error_deg = self.heading.angle_to(to_buoy).to_degrees();
        let turn = if error_deg.is_finite() {
            (error_deg / FULL_TURN_ERROR_DEG).clamp(-1.0, 1.0)
        } else {
            0.0
        };
        let motor = &self.motor;
        self.body
            .step_with(&PectoralFins::NEUTRAL, Vec3::ZERO, |t| {
                motor.muscles_at(1.0, turn, t)
            });
        self.motor.advance(1.0, turn, dt);
        self.steps += 1;
        let forward = self.body.forward().truncate().normalize_or_zero();
        if forward != Vec2::ZERO {
            let k = (dt / HEADING_SMOOTHING_SECS).clamp(0.0, 1.0);
            self.heading = self.heading.lerp(forward, k).normalize_or(forward);
        }
        let here = self.body.centre_of_mass_m();
        self.path_m.push(here);
        let reach_m = REACH_RADIUS_BODY_LENGTHS * self.body.rest_body_length_m();
        if (self.buoys_m[self.next_buoy] - here).truncate().length() < reach_m {
            self.reached_secs.push(self.time_secs());
            self.next_buoy = 1 - self.next_buoy;
        }
    }

    /// Steps until both buoys have been reached or `max_secs` have passed; true if
    /// both were reached.
    pub fn run_until_both_reached(&mut self, max_secs: f32) -> bool {
        while self.reached_secs.len() < 2 && self.time_secs() < max_secs {
            self.step();
        }
        self.reached_secs.len() >= 2
    }

    pub fn time_secs(&self) -> f32 {
        self.steps as f32 * self.body.dt_secs()
    }

    /// When each buoy was reached, seconds since the start (in order of arrival).
    pub fn reached_secs(&self) -> &[f32] {
        &self.reached_secs
    }

    /// Index of the buoy the fish is making for.
    pub fn next_buoy(&self) -> usize {
        self.next_buoy
    }

    pub fn buoys_m(&self) -> &[Vec3; 2] {
        &self.buoys_m
    }

    pub fn body(&self) -> &FishBody {
        &self.body
    }

    /// The centre of mass after every step, metres (body frame).
    pub fn path_m(&self) -> &[Vec3] {
        &self.path_m
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::learning::learned_set::LearnedControllerSet;
    use crate::sim::learning::target_tracking::*;

    #[test]
    fn a_learned_fish_swims_to_both_buoys_in_bounded_time() {
        let map = LearnedControllerSet::pretrained()
            .and_then(|s| s.motor_map())
            .expect("the shipped set drives a fish");
        let species = BodySpecies::Fish;
        let l = species.body_length_m();
        // Fig. 9: the far buoy first, then back to the near one beside the start.
        let buoys = [
            Vec3::new(8.0 * l, 2.0 * l, 0.0),
            Vec3::new(1.0 * l, 4.0 * l, 0.0),
        ];
        let mut tracker = BuoyTracker::new(map, species, BodyParams::default(), buoys);
        let reached = tracker.run_until_both_reached(MAX_SECS);
        assert!(
            reached,
            "reached {:?} in {} s",
            tracker.reached_secs(),
            tracker.time_secs()
        );
        let times = tracker.reached_secs();
        assert!(times[0] > 5.0 && times[1] > times[0], "{times:?}");
        assert!(tracker.path_m().iter().all(|p| p.is_finite()));
    }

    /// The bound of the test, seconds.
    const MAX_SECS: f32 = 150.0;
}
