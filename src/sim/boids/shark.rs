//! The predator: a shark that picks a fish, pursues it and eats it (the SIMBA
//! papers' "shark" species; Lim & Tan list fish, shark and stingray).
//!
//! A hunting shark locks onto the nearest fish it sees and [`pursue`]s it
//! (Reynolds 1999: seek the target's predicted position). **Confusion effect**:
//! a predator attacking a group finds it hard to single out one prey; Landeau &
//! Terborgh 1986 (Anim. Behav. 34:1372) saw largemouth bass catch lone silvery
//! minnows at once but rarely succeed against shoals of 8 or more, because the
//! bass kept switching targets. Here, each second, the shark loses its lock with
//! rate [`SharkHuntParams::confusion_rate_per_neighbour_per_s`] × (fish within
//! [`SharkHuntParams::confusion_radius_m`] of its target), and then needs
//! [`SharkHuntParams::refocus_secs`] to pick a new one: a lone fish is never
//! lost, a fish in a tight school almost at once. **The strike**: after
//! [`SharkHuntParams::strike_lock_secs`] of lock, a shark within
//! [`SharkHuntParams::lunge_distance_m`] of its target lunges, faster and more
//! agile than the fish for a moment ([`lunge_params`]), and breaks off after
//! [`SharkHuntParams::lunge_max_secs`] if it missed. A catch (the target within
//! [`SharkHuntParams::catch_distance_m`] of the mouth) is counted, the fish
//! reappears far away, and the shark cruises satiated for
//! [`SharkHuntParams::satiated_secs`]. The hunting numbers are
//! [`SharkHuntParams`] (`BoidWorldParams::shark`), the body and species numbers
//! (length, speeds, force, vision) [`SharkParams`]
//! (`BoidWorldParams::shark_species`).
//!
//! [`pursue`]: crate::sim::common::steering::pursue

use crate::sim::common::fmath;
use std::f32::consts::TAU;

use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::boids::params::{SharkHuntParams, SharkParams};
use crate::sim::common::fish::Fish;
use crate::sim::common::steering::SteeringParams;

/// Most sharks a world holds. Default 10: a few predators already scatter a
/// school of 200; more turn the tank into a feeding frenzy.
pub const MAX_SHARKS: usize = 10;

/// Confusing neighbours counted at most. Default 15: beyond that the shark is
/// confused anyway; bounds the cost of counting in a dense school (the capacity
/// of the neighbour list counted, at most `spatial_grid::MAX_NEAREST`), so it
/// stays a const.
pub const MAX_CONFUSING_NEIGHBOURS: u32 = 15;

/// A shark: its body (position, velocity, length; the renderer reads it like a
/// fish) and its hunting state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Shark {
    /// Position, velocity and size, as for a fish.
    pub body: Fish,
    /// Index of the fish the shark is hunting, if it has one.
    pub target: Option<usize>,
    /// Seconds left of cruising after a catch (0 = hungry).
    pub satiated_secs: f32,
    /// Seconds left before it can pick a new target after losing one.
    pub refocus_secs: f32,
    /// Seconds it has kept its lock on the current target.
    pub lock_secs: f32,
    /// Fish this shark has caught.
    pub catches: u64,
}

impl Shark {
    /// The mouth: half a body length ahead of the centre, in metres.
    pub fn mouth_m(&self) -> Vec3 {
        self.body.position_m + self.body.heading() * self.body.body_length_m * 0.5
    }

    /// Is the shark looking for (or chasing) prey?
    pub fn is_hungry(&self) -> bool {
        self.satiated_secs <= 0.0
    }
}

/// Steering limits of a shark of `species`, as [`SteeringParams`] for
/// [`Fish::integrate`] and wander: attack top speed, cruising at
/// [`SharkParams::cruise_m_per_s`].
pub fn shark_params(
    fish_params: &SteeringParams,
    body_length_m: f32,
    species: &SharkParams,
) -> SteeringParams {
    SteeringParams {
        max_speed_m_per_s: species.attack_m_per_s,
        min_speed_m_per_s: species.min_m_per_s,
        max_force_m_per_s2: species.max_force_m_per_s2,
        cruise_speed_body_lengths_per_s: species.cruise_m_per_s / body_length_m.max(0.1),
        wander_distance_m: 2.0,
        wander_radius_m: 0.8,
        ..*fish_params
    }
}

/// Steering limits of a shark in its final lunge:
/// [`SharkHuntParams::lunge_m_per_s`] and
/// [`SharkHuntParams::lunge_force_m_per_s2`] instead of the attack speed and force.
pub fn lunge_params(hunt: &SharkHuntParams, params: &SteeringParams) -> SteeringParams {
    SteeringParams {
        max_speed_m_per_s: hunt.lunge_m_per_s,
        max_force_m_per_s2: hunt.lunge_force_m_per_s2,
        ..*params
    }
}

/// Probability that a shark loses its lock during one step of `dt_secs` when
/// `neighbours` fish are within [`SharkHuntParams::confusion_radius_m`] of its
/// target: `1 − exp(−rate · n · dt)`, n capped at [`MAX_CONFUSING_NEIGHBOURS`].
pub fn lose_lock_probability(hunt: &SharkHuntParams, neighbours: u32, dt_secs: f32) -> f32 {
    if !hunt.confusion {
        return 0.0;
    }
    let n = neighbours.min(MAX_CONFUSING_NEIGHBOURS) as f32;
    1.0 - fmath::exp(-hunt.confusion_rate_per_neighbour_per_s * n * dt_secs)
}

/// A new shark of `species` at `position_m`, heading at `yaw_rad` at cruising
/// speed, with length `body_length_m`.
pub fn new_shark(
    position_m: Vec3,
    yaw_rad: f32,
    body_length_m: f32,
    species: &SharkParams,
) -> Shark {
    let direction = Vec3::new(fmath::cos(yaw_rad), 0.0, fmath::sin(yaw_rad));
    let mut body = Fish::new(
        position_m,
        direction * species.cruise_m_per_s,
        body_length_m,
        0.6,
    );
    body.tail_phase_rad = yaw_rad.rem_euclid(TAU);
    Shark {
        body,
        target: None,
        satiated_secs: 0.0,
        refocus_secs: 0.0,
        lock_secs: 0.0,
        catches: 0,
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::boids::shark::*;

    #[test]
    fn a_lone_fish_never_confuses_the_shark_and_a_schooled_one_soon_does() {
        assert_eq!(
            lose_lock_probability(&SharkHuntParams::default(), 0, 1.0 / 60.0),
            0.0
        );
        // Within one second, with 7 close neighbours: practically always lost.
        let per_step = lose_lock_probability(&SharkHuntParams::default(), 7, 1.0 / 60.0);
        let kept_for_a_second = fmath::powi(1.0 - per_step, 60);
        assert!(kept_for_a_second < 0.1, "{kept_for_a_second}");
        assert!(lose_lock_probability(&SharkHuntParams::default(), 100, 1.0) <= 1.0);
    }

    #[test]
    fn the_mouth_is_half_a_body_ahead() {
        let shark = new_shark(Vec3::new(1.0, 2.0, 0.0), 0.0, 2.0, &SharkParams::default());
        assert!((shark.mouth_m() - Vec3::new(2.0, 2.0, 0.0)).length() < 1e-5);
        assert!(shark.is_hungry());
    }
}
