//! Feeding and predation on the reef (Tu & Terzopoulos §6.4 eating and §7.1):
//! open mouths suck in food and prey, a strike at prey in a crowd can be
//! confused and miss (the confusion effect), and plankton drifts, sinks and is
//! replenished.

use glam::Vec3;
use rand::Rng;

use super::events::ReefEventKind;
use super::params::ReefParams;
use super::world::*;
use crate::sim::reef::mind::{FishKind, Intention, Target};

/// Is food at `food_m` within reach of the vacuum of a mouth at `mouth_m` of a
/// fish `length_m` long heading along `heading`: within
/// [`ReefParams::suck_range_body_lengths`] and ahead of the mouth
/// ([`ReefParams::suck_cone_cos`]), or right at it?
pub(super) fn in_suck_reach(
    params: &ReefParams,
    mouth_m: Vec3,
    heading: Vec3,
    length_m: f32,
    food_m: Vec3,
) -> bool {
    let d = food_m.distance(mouth_m);
    let ahead = (food_m - mouth_m).normalize_or_zero().dot(heading);
    d < params.suck_range_body_lengths * length_m
        && (ahead > params.suck_cone_cos || d < 0.2 * length_m)
}

impl ReefWorld {
    /// Living prey other than `j` within the confusion radius of `j` (its
    /// body lengths) of `at`: the crowd that can confuse a strike at `j`.
    pub(crate) fn prey_crowding(&self, j: usize, at: Vec3) -> usize {
        let reach_m =
            self.params.confusion_radius_body_lengths * self.animals[j].body.body_length_m();
        self.animals
            .iter()
            .enumerate()
            .filter(|&(k, o)| {
                k != j
                    && o.alive
                    && o.habits.kind == FishKind::Prey
                    && o.body.position_m().distance(at) < reach_m
            })
            .count()
    }

    /// The confusion effect at predator `i`'s strike on prey `j`: with `n`
    /// other prey within [`ReefParams::confusion_radius_body_lengths`] of the
    /// target, the strike succeeds with probability 1 / (1 +
    /// [`ReefParams::confusion_per_neighbour`] · n). On a miss (returns true) the
    /// prey darts away at its top speed, the predator needs
    /// [`ReefParams::missed_strike_recovery_secs`] before it can strike
    /// again, and the event is logged. A lone prey is never missed.
    pub(super) fn strike_confused(&mut self, i: usize, j: usize) -> bool {
        let target_m = self.animals[j].body.position_m();
        let crowd = self.prey_crowding(j, target_m);
        let success = 1.0 / (1.0 + self.params.confusion_per_neighbour * crowd as f32);
        if crowd == 0 || self.rng.random::<f32>() < success {
            return false;
        }
        let mouth = self.animals[i].body.head_m();
        let prey = &mut self.animals[j];
        let away = (target_m - mouth).normalize_or(prey.body.heading());
        let dart = away * prey.body.top_speed_m_per_s() - prey.body.velocity_m_per_s();
        prey.body.nudge(dart);
        prey.intended_m_per_s = away * prey.body.top_speed_m_per_s();
        self.animals[i].strike_recovery_secs = self.params.missed_strike_recovery_secs;
        self.counts.missed_strikes += 1;
        let text = format!(
            "{} missed {}: {} other prey around it confused it",
            self.animals[i].name(i),
            self.animals[j].name(j),
            crowd
        );
        self.log(
            ReefEventKind::Missed {
                predator: i as u32,
                prey: j as u32,
                crowd: crowd as u32,
            },
            text,
        );
        true
    }

    /// Open mouths suck in food and prey; what reaches the mouth is eaten.
    pub(super) fn suck_in(&mut self, dt: f32) {
        for i in 0..self.animals.len() {
            // A predator recovers from a missed strike whatever it does meanwhile.
            let recovery = &mut self.animals[i].strike_recovery_secs;
            *recovery = (*recovery - dt).max(0.0);
            let a = &self.animals[i];
            if !a.alive || a.focus.intention != Intention::Eat {
                self.animals[i].mouth_open = false;
                continue;
            }
            let mouth = a.body.head_m();
            let length = a.body.body_length_m();
            let mut open = false;
            match a.focus.target {
                Some(Target::Food(id)) => {
                    if let Some(k) = self.food.iter().position(|f| f.id == id) {
                        let d = self.food[k].position_m.distance(mouth);
                        if in_suck_reach(
                            &self.params,
                            mouth,
                            a.body.heading(),
                            length,
                            self.food[k].position_m,
                        ) {
                            open = true;
                            let pull = (mouth - self.food[k].position_m).normalize_or_zero()
                                * self.params.vacuum_speed_m_per_s
                                * dt;
                            self.food[k].position_m = if pull.length() > d {
                                mouth
                            } else {
                                self.food[k].position_m + pull
                            };
                        }
                        if self.food[k].position_m.distance(mouth)
                            < self.params.eat_distance_m.max(0.1 * length)
                        {
                            self.food.swap_remove(k);
                            let a = &mut self.animals[i];
                            let before = a.mental.hunger;
                            a.mental.eat(&a.habits.mental, 1.0);
                            self.counts.food_eaten += 1;
                            let text = format!(
                                "{} ate plankton (hunger {:.2} → {:.2})",
                                a.name(i),
                                before,
                                a.mental.hunger
                            );
                            self.log(ReefEventKind::AteFood { fish: i as u32 }, text);
                        }
                    }
                }
                Some(Target::Animal(j)) if a.habits.kind == FishKind::Predator => {
                    let j = j as usize;
                    if j < self.animals.len() && self.animals[j].alive {
                        let prey_at = self.animals[j].body.position_m();
                        let d = prey_at.distance(mouth);
                        let ahead = (prey_at - mouth).normalize_or_zero().dot(a.body.heading());
                        let recovering = a.strike_recovery_secs > 0.0;
                        if !recovering
                            && d < self.params.predator_suck_range_body_lengths * length
                            && ahead > self.params.suck_cone_cos
                        {
                            open = true;
                            let pull = (mouth - prey_at).normalize_or_zero()
                                * self.params.vacuum_accel_m_per_s2
                                * dt;
                            self.animals[j].body.nudge(pull);
                        }
                        let strikes = !recovering && d < self.params.swallow_body_lengths * length;
                        if strikes && self.strike_confused(i, j) {
                            open = false;
                        } else if strikes {
                            let schooling = self.animals[j].focus.intention == Intention::School;
                            self.animals[j].alive = false;
                            self.animals[j].mouth_open = false;
                            let a = &mut self.animals[i];
                            a.mental.eat(
                                &a.habits.mental,
                                crate::sim::reef::mind::mental_state::PREY_FOOD_UNITS,
                            );
                            self.counts.prey_eaten += 1;
                            if schooling {
                                self.counts.schooling_prey_eaten += 1;
                            }
                            let text = format!(
                                "{} ate {}",
                                self.animals[i].name(i),
                                self.animals[j].name(j)
                            );
                            self.log(
                                ReefEventKind::AtePrey {
                                    predator: i as u32,
                                    prey: j as u32,
                                },
                                text,
                            );
                        }
                    }
                }
                _ => {}
            }
            self.animals[i].mouth_open = open;
        }
    }

    pub(super) fn drift_food(&mut self, dt: f32) {
        let t = self.time_secs;
        for k in 0..self.food.len() {
            let p = self.food[k].position_m;
            let water = self.current.velocity_m_per_s(p, t);
            let jiggle = Vec3::new(
                self.rng.random_range(-1.0..1.0),
                self.rng.random_range(-1.0..1.0),
                self.rng.random_range(-1.0..1.0),
            ) * 0.02;
            let mut q = p + (water + jiggle - Vec3::Y * self.params.plankton_sink_m_per_s) * dt;
            q = self.tank.clamp_inside(q, 0.05);
            for o in &self.obstacles {
                if o.signed_distance_m(q) < 0.02 {
                    q = o.push_outside(q, 0.02);
                }
            }
            self.food[k].position_m = q;
        }
        // Plankton that settled on the sand is gone; new plankton is released
        // near the surface.
        let floor = self.tank.min_m.y + 0.08;
        self.food.retain(|f| f.position_m.y > floor);
        self.food_release_secs -= dt;
        if self.food.len() < self.food_target && self.food_release_secs <= 0.0 {
            self.food_release_secs = self.params.food_release_secs;
            let mut p = self.random_free_point(0.5);
            p.y = self.rng.random_range(0.6..0.95) * self.tank.max_m.y;
            self.add_food(p);
        }
    }
}
