//! Feeding and predation on the reef (Tu & Terzopoulos §6.4 eating and §7.1):
//! open mouths suck in food and prey, a strike at prey in a crowd can be
//! confused and miss (the confusion effect), and plankton drifts, sinks and is
//! replenished. Two stages: [`Plankton`] owns the particles and their
//! release, [`Feeding`] the mouths' suck-in and the predators' strikes.

use glam::Vec3;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::tank::Tank;
use crate::sim::common::water_current::WaterCurrent;
use crate::sim::reef::animal::ReefAnimal;
use crate::sim::reef::demos::random_free_point;
use crate::sim::reef::events::{EventLog, Line, ReefCounts, ReefEventKind};
use crate::sim::reef::mind::{FishKind, Intention, Target};
use crate::sim::reef::params::ReefParams;

/// Most plankton particles kept in the water.
pub const MAX_FOOD: usize = 200;

/// A plankton particle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FoodParticle {
    pub id: u32,
    pub position_m: Vec3,
}

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

/// The plankton in the water: the particles, how many the water is kept
/// stocked with, and the release of new ones near the surface.
#[derive(Clone, Debug, Default)]
pub struct Plankton {
    particles: Vec<FoodParticle>,
    /// Particles the water is kept stocked with.
    target: usize,
    next_id: u32,
    /// Seconds until the next particle may be released.
    release_secs: f32,
}

impl Plankton {
    /// The particles drifting now.
    pub fn particles(&self) -> &[FoodParticle] {
        &self.particles
    }

    /// The particle `id`, if it is still in the water.
    pub(super) fn find(&self, id: u32) -> Option<&FoodParticle> {
        self.particles.iter().find(|f| f.id == id)
    }

    /// Keeps the water stocked with `n` particles (at most [`MAX_FOOD`]).
    pub(super) fn set_target(&mut self, n: usize) {
        self.target = n.min(MAX_FOOD);
    }

    /// Particles the water is kept stocked with.
    pub(super) fn target(&self) -> usize {
        self.target
    }

    /// Takes every particle out and releases no more.
    pub(super) fn clear(&mut self) {
        self.particles.clear();
        self.target = 0;
    }

    /// Adds a particle at `p_m`, inside `tank` (if there is room).
    pub(super) fn add(&mut self, p_m: Vec3, tank: &Tank) {
        if self.particles.len() >= MAX_FOOD {
            return;
        }
        self.particles.push(FoodParticle {
            id: self.next_id,
            position_m: tank.clamp_inside(p_m, 0.05),
        });
        self.next_id = self.next_id.wrapping_add(1);
    }

    /// Plankton drifts with `current`, jiggles and sinks for `dt_secs` at
    /// `time_secs`; what settles on the sand is gone, and new plankton is
    /// released near the surface every [`ReefParams::food_release_secs`]
    /// while there is less than the target.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn drift(
        &mut self,
        params: &ReefParams,
        rng: &mut ChaCha8Rng,
        tank: &Tank,
        obstacles: &[Obstacle],
        current: &WaterCurrent,
        time_secs: f64,
        dt_secs: f32,
    ) {
        let (t, dt) = (time_secs, dt_secs);
        for k in 0..self.particles.len() {
            let p = self.particles[k].position_m;
            let water = current.velocity_m_per_s(p, t);
            let jiggle = Vec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            ) * 0.02;
            let mut q = p + (water + jiggle - Vec3::Y * params.plankton_sink_m_per_s) * dt;
            q = tank.clamp_inside(q, 0.05);
            for o in obstacles {
                if o.signed_distance_m(q) < 0.02 {
                    q = o.push_outside(q, 0.02);
                }
            }
            self.particles[k].position_m = q;
        }
        // Plankton that settled on the sand is gone; new plankton is released
        // near the surface.
        let floor = tank.min_m.y + 0.08;
        self.particles.retain(|f| f.position_m.y > floor);
        self.release_secs -= dt;
        if self.particles.len() < self.target && self.release_secs <= 0.0 {
            self.release_secs = params.food_release_secs;
            let mut p = random_free_point(rng, tank, obstacles, 0.5);
            p.y = rng.random_range(0.6..0.95) * tank.max_m.y;
            self.add(p, tank);
        }
    }
}

/// Living prey other than `j` within the confusion radius of `j` (its body
/// lengths) of `at`: the crowd that can confuse a strike at `j`.
pub(super) fn prey_crowding(
    params: &ReefParams,
    animals: &[ReefAnimal],
    j: usize,
    at: Vec3,
) -> usize {
    let reach_m = params.confusion_radius_body_lengths * animals[j].body.body_length_m();
    animals
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

/// The feeding and predation stage's state: by animal, the seconds until a
/// predator that missed a strike can strike again.
#[derive(Clone, Debug, Default)]
pub struct Feeding {
    strike_recovery_secs: Vec<f32>,
}

/// What the feeding stage reads and writes besides the animals and the
/// plankton: the tuning, the generator (a confused strike is a draw), the
/// log, the counters and the clock.
pub(super) struct FeedingInputs<'a> {
    pub params: &'a ReefParams,
    pub rng: &'a mut ChaCha8Rng,
    pub log: &'a mut EventLog,
    pub counts: &'a mut ReefCounts,
    pub time_secs: f64,
    pub dt_secs: f32,
}

impl Feeding {
    /// The confusion effect at predator `i`'s strike on prey `j`: with `n`
    /// other prey within [`ReefParams::confusion_radius_body_lengths`] of the
    /// target, the strike succeeds with probability 1 / (1 +
    /// [`ReefParams::confusion_per_neighbour`] · n). On a miss (returns true) the
    /// prey darts away at its top speed, the predator needs
    /// [`ReefParams::missed_strike_recovery_secs`] before it can strike
    /// again, and the event is logged. A lone prey is never missed.
    fn strike_confused(
        &mut self,
        animals: &mut [ReefAnimal],
        io: &mut FeedingInputs,
        i: usize,
        j: usize,
    ) -> bool {
        let params = io.params;
        let target_m = animals[j].body.position_m();
        let crowd = prey_crowding(params, animals, j, target_m);
        let success = 1.0 / (1.0 + params.confusion_per_neighbour * crowd as f32);
        if !params.confusion || crowd == 0 || io.rng.random::<f32>() < success {
            return false;
        }
        let mouth = animals[i].body.head_m();
        let prey = &mut animals[j];
        let away = (target_m - mouth).normalize_or(prey.body.heading());
        let dart = away * prey.body.top_speed_m_per_s() - prey.body.velocity_m_per_s();
        prey.body.nudge(dart);
        let top = prey.body.top_speed_m_per_s();
        prey.drive_mut().dart(away * top);
        self.strike_recovery_secs[i] = params.missed_strike_recovery_secs;
        io.counts.missed_strikes += 1;
        let text = Line::new("reef-event-missed")
            .animal("predator", animals, i)
            .animal("prey", animals, j)
            .count("crowd", crowd as u32);
        io.log.push(
            io.time_secs,
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
    pub(super) fn step(
        &mut self,
        animals: &mut [ReefAnimal],
        plankton: &mut Plankton,
        mut io: FeedingInputs,
    ) {
        let params = io.params;
        let dt = io.dt_secs;
        self.strike_recovery_secs.resize(animals.len(), 0.0);
        let food = &mut plankton.particles;
        for i in 0..animals.len() {
            // A predator recovers from a missed strike whatever it does meanwhile.
            let recovery = &mut self.strike_recovery_secs[i];
            *recovery = (*recovery - dt).max(0.0);
            let a = &animals[i];
            if !a.alive || a.focus.intention != Intention::Eat {
                animals[i].mouth_open = false;
                continue;
            }
            let mouth = a.body.head_m();
            let length = a.body.body_length_m();
            let mut open = false;
            match a.focus.target {
                Some(Target::Food(id)) => {
                    if let Some(k) = food.iter().position(|f| f.id == id) {
                        let d = food[k].position_m.distance(mouth);
                        if in_suck_reach(
                            params,
                            mouth,
                            a.body.heading(),
                            length,
                            food[k].position_m,
                        ) {
                            open = true;
                            let pull = (mouth - food[k].position_m).normalize_or_zero()
                                * params.vacuum_speed_m_per_s
                                * dt;
                            food[k].position_m = if pull.length() > d {
                                mouth
                            } else {
                                food[k].position_m + pull
                            };
                        }
                        if food[k].position_m.distance(mouth)
                            < params.eat_distance_m.max(0.1 * length)
                        {
                            food.swap_remove(k);
                            let a = &mut animals[i];
                            let before = a.mental.hunger;
                            a.mental.eat(&a.habits.mental, 1.0);
                            io.counts.food_eaten += 1;
                            let text = Line::new("reef-event-ate-plankton")
                                .animal_of("fish", a.habits.kind, i)
                                .number("before", f64::from(before), 2)
                                .number("after", f64::from(a.mental.hunger), 2);
                            io.log.push(
                                io.time_secs,
                                ReefEventKind::AteFood { fish: i as u32 },
                                text,
                            );
                        }
                    }
                }
                Some(Target::Animal(j)) if a.habits.kind == FishKind::Predator => {
                    let j = j as usize;
                    if j < animals.len() && animals[j].alive {
                        let prey_at = animals[j].body.position_m();
                        let d = prey_at.distance(mouth);
                        let ahead = (prey_at - mouth).normalize_or_zero().dot(a.body.heading());
                        let recovering = self.strike_recovery_secs[i] > 0.0;
                        if !recovering
                            && d < params.predator_suck_range_body_lengths * length
                            && ahead > params.suck_cone_cos
                        {
                            open = true;
                            let pull = (mouth - prey_at).normalize_or_zero()
                                * params.vacuum_accel_m_per_s2
                                * dt;
                            animals[j].body.nudge(pull);
                        }
                        let strikes = !recovering && d < params.swallow_body_lengths * length;
                        if strikes && self.strike_confused(animals, &mut io, i, j) {
                            open = false;
                        } else if strikes {
                            let schooling = animals[j].focus.intention == Intention::School;
                            animals[j].alive = false;
                            animals[j].mouth_open = false;
                            let a = &mut animals[i];
                            a.mental.eat(
                                &a.habits.mental,
                                crate::sim::reef::mind::mental_state::PREY_FOOD_UNITS,
                            );
                            io.counts.prey_eaten += 1;
                            if schooling {
                                io.counts.schooling_prey_eaten += 1;
                            }
                            let text = Line::new("reef-event-ate")
                                .animal("predator", animals, i)
                                .animal("prey", animals, j);
                            io.log.push(
                                io.time_secs,
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
            animals[i].mouth_open = open;
        }
    }
}
