//! A courting pair of pacifists (Tu & Terzopoulos 1994 §7.3): the phases of
//! the courtship sequence, where each partner wants to go in each, and when
//! the pair moves on to the next phase. The sequence and its numbers are
//! described in `reef/courtship.rs`, whose stage forms the pairs and ends them.

use crate::sim::common::fmath;
use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::reef::motor_choice::Gait;
use crate::sim::reef::params::CourtshipParams;

/// The phases in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Phase {
    Looping,
    Circling,
    Ascending,
    Nuzzling,
    Spawned,
}

impl Phase {
    pub fn label(self) -> &'static str {
        match self {
            Self::Looping => "looping",
            Self::Circling => "circling",
            Self::Ascending => "spawning ascent",
            Self::Nuzzling => "nuzzling",
            Self::Spawned => "spawned",
        }
    }
}

/// Where one partner is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Partner {
    pub position_m: Vec3,
    pub head_m: Vec3,
    pub heading: Vec3,
    pub body_length_m: f32,
}

/// What a partner wants this step: a point to chase, a speed fraction, and how
/// (the female hovers while the male loops or nuzzles, `reef/motor_choice.rs`). A
/// hovering point-mass body, which has no fins, swims slowly to the point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wish {
    pub target_m: Vec3,
    pub speed_fraction: f32,
    pub gait: Gait,
}

/// A courting pair.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pair {
    pub male: u32,
    pub female: u32,
    pub phase: Phase,
    /// Seconds in this phase.
    pub phase_secs: f32,
    /// Counted passes (looping) or touches (nuzzling).
    pub count: u32,
    /// Radians the female has turned while circling.
    pub turned_rad: f32,
    /// Seconds since the last counted pass or touch.
    pub since_count_secs: f32,
    /// Seconds either partner has been out of the other's sight.
    pub lost_secs: f32,
    /// The female's heading last step (for counting turns).
    last_heading: Vec3,
}

impl Pair {
    pub fn new(params: &CourtshipParams, male: u32, female: u32, female_heading: Vec3) -> Self {
        Self {
            male,
            female,
            phase: Phase::Looping,
            phase_secs: 0.0,
            count: 0,
            turned_rad: 0.0,
            since_count_secs: params.pass_interval_secs,
            lost_secs: 0.0,
            last_heading: female_heading,
        }
    }

    /// Is the pair past the point where the female may still change males?
    pub fn bonded(&self) -> bool {
        self.phase != Phase::Looping
    }

    /// The looping point: in front of her head, swinging up and down.
    pub fn loop_point_m(&self, params: &CourtshipParams, female: &Partner, time_secs: f32) -> Vec3 {
        let swing = fmath::sin(std::f32::consts::TAU * params.loop_hz * time_secs);
        female.head_m
            + female.heading * 0.8 * female.body_length_m
            + Vec3::Y * (0.3 + 0.5 * swing) * female.body_length_m
    }

    /// Her abdomen: under the middle of her body.
    pub fn abdomen_m(female: &Partner) -> Vec3 {
        female.position_m - Vec3::Y * 0.2 * female.body_length_m
    }

    /// What each wants now: (male, female).
    pub fn wishes(
        &self,
        params: &CourtshipParams,
        male: &Partner,
        female: &Partner,
        time_secs: f32,
        surface_y_m: f32,
    ) -> (Wish, Wish) {
        let hover = |p: &Partner, bob: f32, gait: Gait| Wish {
            target_m: p.head_m + p.heading * p.body_length_m + Vec3::Y * bob * p.body_length_m,
            speed_fraction: 0.25,
            gait,
        };
        let swim = |target_m: Vec3, speed_fraction: f32| Wish {
            target_m,
            speed_fraction,
            gait: Gait::Pursue,
        };
        let bob = 0.3 * fmath::sin(std::f32::consts::TAU * 0.5 * time_secs);
        match self.phase {
            Phase::Looping => (
                swim(
                    self.loop_point_m(params, female, time_secs),
                    params.loop_speed_fraction,
                ),
                hover(female, bob, Gait::Bob),
            ),
            Phase::Circling => (
                swim(
                    female.position_m - female.heading * female.body_length_m,
                    0.8,
                ),
                swim(male.position_m - male.heading * male.body_length_m, 0.7),
            ),
            Phase::Ascending => {
                let top = surface_y_m - female.body_length_m;
                (
                    swim(
                        Self::abdomen_m(female) - female.heading * 0.3 * female.body_length_m,
                        1.0,
                    ),
                    swim(
                        Vec3::new(female.head_m.x, top, female.head_m.z)
                            + female.heading * female.body_length_m,
                        1.0,
                    ),
                )
            }
            Phase::Nuzzling | Phase::Spawned => {
                let backing_off = self.since_count_secs < params.back_off_secs;
                let abdomen = Self::abdomen_m(female);
                let male_wish = if backing_off {
                    swim(
                        abdomen
                            - Vec3::Y * 1.5 * male.body_length_m
                            - female.heading * male.body_length_m,
                        0.5,
                    )
                } else {
                    // From behind and below her (she hovers), along her axis.
                    // A male behind her abdomen aims at a point on her axis
                    // [`CourtshipParams::staging_body_lengths`] ahead of where he is along it (a
                    // path follower's look-ahead point), never past her abdomen:
                    // he turns onto her axis as he closes in, within his
                    // turning circle. A male beside or ahead of her swims back
                    // to a point that far behind her abdomen first. (Aiming at
                    // the abdomen from the side made the muscle male circle
                    // her a body length and a half away for minutes; lining up
                    // at a fixed point behind her left him facing the wrong
                    // way there, and his turn swung him a body length off her
                    // axis: 4 of 16 seeds spawned, measured.)
                    let level = Vec3::new(1.0, 0.0, 1.0);
                    let axis = (female.heading * level).normalize_or(female.heading);
                    let offset = male.head_m - abdomen;
                    let along = offset.dot(axis);
                    let look_ahead = params.staging_body_lengths * male.body_length_m;
                    let below = 0.3 * male.body_length_m;
                    let target = if along < 0.0 {
                        let carrot = (along + look_ahead).min(0.0);
                        abdomen + axis * carrot - Vec3::Y * below * (-carrot / look_ahead).min(1.0)
                    } else {
                        abdomen - axis * look_ahead - Vec3::Y * below
                    };
                    swim(target, 0.6)
                };
                (male_wish, hover(female, 0.0, Gait::Hover))
            }
        }
    }

    /// Advances the pair by `dt_secs`; returns the phase it entered, if any.
    pub fn advance(
        &mut self,
        params: &CourtshipParams,
        male: &Partner,
        female: &Partner,
        time_secs: f32,
        surface_y_m: f32,
        dt_secs: f32,
    ) -> Option<Phase> {
        self.phase_secs += dt_secs;
        self.since_count_secs += dt_secs;
        let turn = fmath::acos(
            self.last_heading
                .normalize_or_zero()
                .dot(female.heading)
                .clamp(-1.0, 1.0),
        );
        self.last_heading = female.heading;
        let next = match self.phase {
            Phase::Looping => {
                let point = self.loop_point_m(params, female, time_secs);
                if male.head_m.distance(point) < params.pass_body_lengths * male.body_length_m
                    && self.since_count_secs >= params.pass_interval_secs
                {
                    self.count += 1;
                    self.since_count_secs = 0.0;
                }
                (self.count >= params.loops_to_circle).then_some(Phase::Circling)
            }
            Phase::Circling => {
                if turn.is_finite() {
                    self.turned_rad += turn;
                }
                (self.turned_rad >= params.circling_turns * std::f32::consts::TAU)
                    .then_some(Phase::Ascending)
            }
            Phase::Ascending => {
                let high = female.position_m.y > surface_y_m - 1.5 * female.body_length_m;
                (high || self.phase_secs >= params.ascent_secs).then_some(Phase::Nuzzling)
            }
            Phase::Nuzzling => {
                if self.since_count_secs >= params.back_off_secs
                    && male.head_m.distance(Self::abdomen_m(female))
                        < params.touch_body_lengths * male.body_length_m
                {
                    self.count += 1;
                    self.since_count_secs = 0.0;
                }
                (self.count >= params.nuzzles).then_some(Phase::Spawned)
            }
            Phase::Spawned => None,
        };
        if let Some(phase) = next {
            self.phase = phase;
            self.phase_secs = 0.0;
            self.count = 0;
            self.turned_rad = 0.0;
            self.since_count_secs = if phase == Phase::Nuzzling {
                params.back_off_secs
            } else {
                params.pass_interval_secs
            };
        }
        next
    }

    /// Has the pair been stuck too long in one phase?
    pub fn timed_out(&self, params: &CourtshipParams) -> bool {
        self.phase_secs > params.phase_timeout_secs || self.lost_secs > params.lost_secs
    }
}
