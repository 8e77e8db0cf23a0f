//! The motor half of every behaviour routine (Tu & Terzopoulos 1994 §6.4): a
//! routine says where it wants to go and how (its [`Wish`]), and here it picks the
//! motor controllers of the muscle body (§3.3–3.4) that do it:
//!
//! | the routine wants                      | motor controllers |
//! |----------------------------------------|-------------------|
//! | to swim on (heading error under [`MotorChoiceParams::turn_mc_min_deg`]) | swim-MC at the wished speed; course kept by a bend of the turning segments proportional to the error ([`MotorChoiceParams::course_gain_per_rad`], `body::turn_mc::add_steering`) |
//! | to swim somewhere [`MotorChoiceParams::turn_mc_min_deg`] or more off its heading | turn-MC(angle), at most 90° at a time; the routine asks again when the turn is done (not while pursuing a moving target, [`Gait::Pursue`]: it keeps re-aiming with the held bend) |
//! | to climb or dive                       | both pectoral fins pitched (twice the elevation error, at most ±0.5 rad; chasing food, [`Gait::Forage`], the wished elevation itself, at most ±[`MotorChoiceParams::forage_max_fin_pitch_rad`]), trimming the body: it pitches with them and swims up or down its own axis (`BodyParams::fin_trim_gain`) |
//! | to go much slower than it swims, towards a goal less than [`MotorChoiceParams::turn_mc_min_deg`] off its heading | fins across the flow (brake), no tail beat (a goal further round is turned to first: the turn needs the tail's thrust) |
//! | to hover ([`Gait::Hover`])             | no tail beat, fins across the flow: the fish stops within a body length and stays |
//! | to hover and bob ([`Gait::Bob`])       | a slow tail beat ([`MotorChoiceParams::bob_swim_fraction`]) against fins that brake and tilt up and down together at [`MotorChoiceParams::bob_hz`]: the fish holds its place and rises and sinks |
//!
//! A turn-MC turn, once started, runs to its end (the paper's turns are
//! ballistic: a quick bend and a slow release); while it runs the routine's wish
//! sets only the fins, and [`crate::sim::body::physical_fish::PhysicalFish::step`]
//! beats the tail at the setting the turn-MC's key turns were measured at, so
//! that a 90° key turns the fish 90° at any speed the routine asked for.
//!
//! Why the held bend for small corrections: a turn-MC turn of any angle lasts
//! as long as its restoring stroke (3.9 s for the smallest key,
//! `body/turn_mc.rs`), so a chase steered only by turn-MC turns zigzags: the
//! target moves while the fish cannot re-aim. The held bend is the turn-MC's
//! own bend (the same anterior and middle segments, contracted on the turning
//! side) kept as long as the error lasts and proportional to it: the
//! continuous limit of the steering map for small angles. Measured in
//! `docs/fish-mind.md`.
//!
//! The point-mass body has no motor controllers: it follows the wish's velocity
//! through the boid layer.

use crate::sim::common::fmath;
use std::f32::consts::TAU;

use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::body::PectoralFins;
use crate::sim::body::motor_bridge::{MotorIntent, level_turn_deg};
use crate::sim::reef::params::MotorChoiceParams;

/// How a routine wants its body to move.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Gait {
    /// Swim at the wished velocity; turns of [`MotorChoiceParams::turn_mc_min_deg`] or more are
    /// turn-MC turns (avoiding, escaping, schooling, leaving, wandering).
    #[default]
    Swim,
    /// Swim after a moving target (chasing-target: eating, mating, courting),
    /// re-aiming every step with the held bend: a turn-MC turn cannot be re-aimed
    /// once started and overshoots a target a few body lengths away.
    Pursue,
    /// Swim after food (eating-food's chase): as [`Gait::Pursue`], with the
    /// fins pitched to the wished climb, up to
    /// [`MotorChoiceParams::forage_max_fin_pitch_rad`] (steeper climbs and
    /// dives; plankton barely moves). Not twice the error from the body's own
    /// pitch: the trimmed body's pitch follows its fins, so that loop rang
    /// from full climb to full dive step to step at steep fins.
    Forage,
    /// Swim with the school (schooling, and foraging with the school): the
    /// muscle body is steered like the physics scene's schooling fish, by the
    /// boid layer's intended velocity through the desired-velocity bridge
    /// (`body/motor_bridge.rs`), whose smoothing keeps a school together (driven
    /// step by step by the school routine's wish, the fish thrashed at full
    /// bend among their neighbours and the school of *School meets obstacle*
    /// slowed to 0.05 m/s in four to six groups, measured). Here, like
    /// [`Gait::Pursue`].
    School,
    /// Stop and stay: eating at the food, the courted female while she is nuzzled.
    Hover,
    /// Stay and bob up and down with the fins: the courted female while the male
    /// loops (§7.3).
    Bob,
}

/// What a behaviour routine wants this step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wish {
    /// Where to swim and how fast (tank frame, m/s). The muscle body reads its
    /// direction and speed; the point-mass body follows it as a desired velocity.
    pub velocity_m_per_s: Vec3,
    pub gait: Gait,
}

impl Wish {
    pub fn swim(velocity_m_per_s: Vec3) -> Self {
        Self {
            velocity_m_per_s,
            gait: Gait::Swim,
        }
    }

    pub fn pursue(velocity_m_per_s: Vec3) -> Self {
        Self {
            velocity_m_per_s,
            gait: Gait::Pursue,
        }
    }

    pub fn hover() -> Self {
        Self {
            velocity_m_per_s: Vec3::ZERO,
            gait: Gait::Hover,
        }
    }

    pub fn bob() -> Self {
        Self {
            velocity_m_per_s: Vec3::ZERO,
            gait: Gait::Bob,
        }
    }
}

/// The fish as its motor choice sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Where it heads (tank frame, unit; averaged over a tail beat).
    pub heading: Vec3,
    /// Its speed, m/s.
    pub speed_m_per_s: f32,
    /// Its top swimming speed, m/s.
    pub top_speed_m_per_s: f32,
    /// Is its turn-MC busy with a turn?
    pub turning: bool,
}

/// The motor controllers that carry out `wish` for `body` at `time_secs` (the
/// bobbing clock), tuned by `params`. Non-finite input asks for nothing.
pub fn choose(params: &MotorChoiceParams, wish: &Wish, body: &Body, time_secs: f32) -> MotorIntent {
    let idle = MotorIntent {
        speed_fraction: 0.0,
        start_turn_deg: None,
        steer: 0.0,
        fins: PectoralFins::NEUTRAL,
    };
    let top = body.top_speed_m_per_s;
    let d = wish.velocity_m_per_s;
    if !(d.is_finite() && body.heading.is_finite() && top > 0.0) {
        return idle;
    }
    match wish.gait {
        Gait::Hover => {
            return MotorIntent {
                fins: PectoralFins::BRAKE,
                ..idle
            };
        }
        Gait::Bob => {
            let rising = fmath::sin(TAU * params.bob_hz * time_secs) >= 0.0;
            let pitch = if rising {
                params.bob_lift_pitch_rad
            } else {
                -std::f32::consts::FRAC_PI_4
            };
            return MotorIntent {
                speed_fraction: params.bob_swim_fraction,
                fins: PectoralFins::pitch(pitch),
                ..idle
            };
        }
        Gait::Swim | Gait::Pursue | Gait::Forage | Gait::School => {}
    }
    let speed = if body.speed_m_per_s.is_finite() {
        body.speed_m_per_s.max(0.0)
    } else {
        0.0
    };
    let wanted = d.length();
    let level = Vec3::new(d.x, 0.0, d.z).length();
    let has_level_goal =
        level > 1e-3 * top && Vec3::new(body.heading.x, 0.0, body.heading.z).length() > 1e-3;
    let error_deg = if has_level_goal {
        level_turn_deg(body.heading, d)
    } else {
        0.0
    };
    // Brake for a goal ahead only: a goal `turn_mc_min_deg` or more round is turned
    // to first, and a turn needs the tail's thrust. (Braking for any goal, a
    // nuzzling male behind the female but facing away from her braked, coasted,
    // beat again and braked, turning about 6°/s while he swam out of her sight:
    // courtship seeds 1-16 spawned 14 times within 5 minutes, now 15, and no
    // pair stalls in nuzzling; `shoal-census courtship-seeds`.)
    if wanted < 0.5 * speed
        && speed > params.brake_above_fraction * top
        && !body.turning
        && error_deg.abs() < params.turn_mc_min_deg
    {
        return MotorIntent {
            fins: PectoralFins::BRAKE,
            ..idle
        };
    }
    let mut speed_fraction = (wanted / top).clamp(0.0, 1.0);
    // Climb or dive with the fins.
    let elevation = fmath::atan2(d.y, level);
    let pitch = fmath::asin(body.heading.y.clamp(-1.0, 1.0));
    let max_fin_pitch = if wish.gait == Gait::Forage {
        params.forage_max_fin_pitch_rad
    } else {
        params.max_fin_pitch_rad
    };
    let fins = if wanted > 0.0 && wish.gait == Gait::Forage {
        PectoralFins::climb(elevation.clamp(-max_fin_pitch, max_fin_pitch))
    } else if wanted > 0.0 {
        PectoralFins::climb(
            (params.pitch_gain * (elevation - pitch)).clamp(-max_fin_pitch, max_fin_pitch),
        )
    } else {
        PectoralFins::NEUTRAL
    };
    // Yaw: a turn-MC turn for a large error, the held bend for a small one.
    let (mut start_turn_deg, mut steer) = (None, 0.0);
    if body.turning {
        // The turn runs to its end.
    } else if wish.gait == Gait::Swim && error_deg.abs() >= params.turn_mc_min_deg {
        start_turn_deg = Some(error_deg.clamp(-90.0, 90.0));
    } else {
        steer = (params.course_gain_per_rad * error_deg.to_radians()).clamp(-1.0, 1.0);
        // The bend turns the fish by the tail's thrust on it: beat at least as
        // hard as the bend (the circle stays about 0.6 body lengths).
        speed_fraction = speed_fraction.max(steer.abs());
    }
    MotorIntent {
        speed_fraction,
        start_turn_deg,
        steer,
        fins,
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::reef::motor_choice::*;

    fn body(speed: f32, turning: bool) -> Body {
        Body {
            heading: Vec3::X,
            speed_m_per_s: speed,
            top_speed_m_per_s: 0.3,
            turning,
        }
    }

    #[test]
    fn a_large_turn_is_a_turn_mc_turn_and_a_small_one_a_held_bend() {
        let level = |deg: f32| {
            // + = left; left of +x is −z with y up.
            let r = deg.to_radians();
            Vec3::new(fmath::cos(r), 0.0, -fmath::sin(r)) * 0.2
        };
        // 120° to the left: one 90° turn-MC turn now, the rest when it is done.
        let m = choose(
            &MotorChoiceParams::default(),
            &Wish::swim(level(120.0)),
            &body(0.2, false),
            0.0,
        );
        assert_eq!(m.start_turn_deg, Some(90.0));
        assert_eq!(m.steer, 0.0);
        // Straight behind to the right: 90° to the right.
        let m = choose(
            &MotorChoiceParams::default(),
            &Wish::swim(level(-179.0)),
            &body(0.2, false),
            0.0,
        );
        assert_eq!(m.start_turn_deg, Some(-90.0));
        // At the turn-MC's threshold: a turn-MC turn of that angle.
        let m = choose(
            &MotorChoiceParams::default(),
            &Wish::swim(level(MotorChoiceParams::default().turn_mc_min_deg + 1.0)),
            &body(0.2, false),
            0.0,
        );
        let angle = m.start_turn_deg.expect("a turn-MC turn");
        assert!(
            (angle - (MotorChoiceParams::default().turn_mc_min_deg + 1.0).min(90.0)).abs() < 0.1,
            "{angle}"
        );
        // While a turn runs nothing new starts.
        let m = choose(
            &MotorChoiceParams::default(),
            &Wish::swim(level(120.0)),
            &body(0.2, true),
            0.0,
        );
        assert_eq!((m.start_turn_deg, m.steer), (None, 0.0));
        // A pursuit re-aims with the held bend, however large the error.
        let m = choose(
            &MotorChoiceParams::default(),
            &Wish::pursue(level(120.0)),
            &body(0.2, false),
            0.0,
        );
        assert_eq!((m.start_turn_deg, m.steer), (None, 1.0));
        // 10° to the right: a proportional bend, no turn-MC turn.
        let m = choose(
            &MotorChoiceParams::default(),
            &Wish::swim(level(-10.0) * 0.5),
            &body(0.1, false),
            0.0,
        );
        assert_eq!(m.start_turn_deg, None);
        assert!(
            (m.steer + MotorChoiceParams::default().course_gain_per_rad * 10f32.to_radians()).abs()
                < 1e-4
        );
    }

    #[test]
    fn hovering_stops_the_tail_and_brakes_with_the_fins() {
        let m = choose(
            &MotorChoiceParams::default(),
            &Wish::hover(),
            &body(0.2, false),
            0.0,
        );
        assert_eq!(m.speed_fraction, 0.0);
        assert_eq!(m.fins, PectoralFins::BRAKE);
        // Much slower than now: brake.
        let m = choose(
            &MotorChoiceParams::default(),
            &Wish::swim(Vec3::X * 0.02),
            &body(0.25, false),
            0.0,
        );
        assert_eq!((m.speed_fraction, m.fins), (0.0, PectoralFins::BRAKE));
        // Much slower, but towards a goal behind: no brake, the tail beats and the
        // fish bends round (pursuit) or starts a turn-MC turn (swim).
        for wish in [Wish::pursue(-Vec3::X * 0.02), Wish::swim(-Vec3::X * 0.02)] {
            let m = choose(
                &MotorChoiceParams::default(),
                &wish,
                &body(0.25, false),
                0.0,
            );
            assert_ne!(m.fins, PectoralFins::BRAKE, "{wish:?}");
            assert!(
                m.speed_fraction > 0.0 || m.start_turn_deg.is_some(),
                "{wish:?}: {m:?}"
            );
        }
    }

    #[test]
    fn bobbing_beats_slowly_and_tilts_the_fins_up_then_down() {
        let up = choose(
            &MotorChoiceParams::default(),
            &Wish::bob(),
            &body(0.0, false),
            0.25 / MotorChoiceParams::default().bob_hz,
        );
        let down = choose(
            &MotorChoiceParams::default(),
            &Wish::bob(),
            &body(0.0, false),
            0.75 / MotorChoiceParams::default().bob_hz,
        );
        assert_eq!(
            up.speed_fraction,
            MotorChoiceParams::default().bob_swim_fraction
        );
        assert!(up.fins.left_angle_rad > std::f32::consts::FRAC_PI_2);
        assert!(down.fins.left_angle_rad < std::f32::consts::FRAC_PI_2);
        assert_eq!(up.start_turn_deg, None);
    }

    #[test]
    fn climbing_pitches_the_fins_and_garbage_asks_for_nothing() {
        let up = choose(
            &MotorChoiceParams::default(),
            &Wish::swim(Vec3::new(1.0, 0.5, 0.0) * 0.2),
            &body(0.2, false),
            0.0,
        );
        assert!(up.fins.left_angle_rad > std::f32::consts::FRAC_PI_2);
        assert!(up.fins.trim, "climbing fins trim the body");
        let bob = choose(
            &MotorChoiceParams::default(),
            &Wish::bob(),
            &body(0.0, false),
            0.0,
        );
        assert!(!bob.fins.trim, "bobbing leaves the body level");
        let nan = choose(
            &MotorChoiceParams::default(),
            &Wish::swim(Vec3::NAN),
            &body(0.2, false),
            0.0,
        );
        assert_eq!(nan.speed_fraction, 0.0);
    }

    #[test]
    fn a_chase_for_food_sets_its_fins_to_the_wished_climb_whatever_the_body_pitch() {
        // Food 0.4 rad above the heading's level: the fins pitch 0.4 rad
        // whether the body is level or already pitched 0.3 rad nose up (the
        // other gaits pitch them by twice the error, 0.8 and 0.2, clamped).
        let wish = Wish {
            velocity_m_per_s: Vec3::new(fmath::cos(0.4), fmath::sin(0.4), 0.0) * 0.2,
            gait: Gait::Forage,
        };
        let p = MotorChoiceParams::default();
        for pitch in [0.0f32, 0.3] {
            let b = Body {
                heading: Vec3::new(fmath::cos(pitch), fmath::sin(pitch), 0.0),
                ..body(0.2, false)
            };
            let fins = choose(&p, &wish, &b, 0.0).fins;
            assert!(fins.trim);
            let fin_pitch = fins.left_angle_rad - std::f32::consts::FRAC_PI_2;
            assert!(
                (fin_pitch - 0.4).abs() < 1e-4,
                "body {pitch}: fins {fin_pitch}"
            );
            let pursue = choose(&p, &Wish::pursue(wish.velocity_m_per_s), &b, 0.0).fins;
            let expected = (2.0 * (0.4 - pitch)).min(p.max_fin_pitch_rad);
            assert!(
                (pursue.left_angle_rad - std::f32::consts::FRAC_PI_2 - expected).abs() < 1e-4,
                "pursuit, body {pitch}"
            );
        }
        // Steeper food: at most `forage_max_fin_pitch_rad`.
        let steep = Wish {
            velocity_m_per_s: Vec3::new(0.1, 1.0, 0.0),
            gait: Gait::Forage,
        };
        let fins = choose(&p, &steep, &body(0.2, false), 0.0).fins;
        let fin_pitch = fins.left_angle_rad - std::f32::consts::FRAC_PI_2;
        assert!((fin_pitch - p.forage_max_fin_pitch_rad).abs() < 1e-4);
    }
}
