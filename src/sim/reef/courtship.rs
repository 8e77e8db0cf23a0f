//! The courtship routine of pacifists (Tu & Terzopoulos 1994 §7.3, Plate 1b):
//! **looping** (the male swims up and down through a point in front of the
//! female's head; she hovers and bobs) until his mouth has passed it
//! [`CourtshipParams::loops_to_circle`] times → **circling** (each chases the
//! other's tail) until the female has turned [`CourtshipParams::circling_turns`]
//! full turns → **spawning ascent** (she swims fast towards the surface, he
//! follows her abdomen) → **nuzzling** (he touches her abdomen from below, backs
//! off, and again, [`CourtshipParams::nuzzles`] times) → spawned.
//!
//! A female may leave her male for a larger one who joins the looping display
//! (until circling starts); the first male then turns away. A pair whose
//! partner is lost from view for [`CourtshipParams::lost_secs`], or that spends
//! more than [`CourtshipParams::phase_timeout_secs`] in one phase, breaks up.
//! The numbers live in [`CourtshipParams`] (`ReefParams::courtship`).
//!
//! This module holds the pair's state machine and where each partner wants to
//! go; the reef world (`reef/world.rs`) forms pairs and moves the bodies.

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

// The reef's courtship step: pairs form, the sequence advances, pairs end.

use super::events::ReefEventKind;
use super::world::*;
use crate::sim::reef::mind::{FishKind, Focus, Intention, IntentionGenerator, Sex, Target};

impl ReefWorld {
    /// Logs female `female`'s choice of `male` when she saw other males too:
    /// "pacifist 0 chose pacifist 2 (0.61 m long) over pacifist 1 (0.46 m)".
    /// She ranks bigger males first (`reef/perception.rs`), nearer ones next.
    fn log_choice(&mut self, female: u32, male: u32) {
        let length = |i: u32| self.animals[i as usize].body.body_length_m();
        let name = |i: u32| self.animals[i as usize].name(i as usize);
        let Some(over) = self.animals[female as usize]
            .mates_seen
            .iter()
            .copied()
            .filter(|&m| m != male)
            .max_by(|&a, &b| length(a).total_cmp(&length(b)).then(b.cmp(&a)))
        else {
            return;
        };
        let why = if length(male) >= length(over) {
            "she prefers bigger males"
        } else {
            "she weighs size against distance, and the bigger one was farther away"
        };
        let text = format!(
            "{} chose {} ({:.2} m long) over {} ({:.2} m): {why}",
            name(female),
            name(male),
            length(male),
            name(over),
            length(over)
        );
        self.log(ReefEventKind::Chose { female, male, over }, text);
    }

    /// Forms courting pairs from mutual choices, lets a female change to a
    /// larger male during looping, advances each pair's sequence and ends it.
    pub(super) fn court(&mut self, dt: f32) {
        let mates_with = |a: &ReefAnimal| match (a.alive, a.focus) {
            (
                true,
                Focus {
                    intention: Intention::Mate,
                    target: Some(Target::Animal(j)),
                },
            ) => Some(j),
            _ => None,
        };
        // A female in a looping pair who now chooses another male who
        // chooses her: she leaves the first (he turns away for a while).
        for k in 0..self.pairs.len() {
            let pair = self.pairs[k];
            if pair.bonded() {
                continue;
            }
            let chosen = mates_with(&self.animals[pair.female as usize]);
            if let Some(new) = chosen
                && new != pair.male
                && mates_with(&self.animals[new as usize]) == Some(pair.female)
                && self.pair_of(new as usize).is_none()
                && self.animals[new as usize].body.body_length_m()
                    > self.animals[pair.male as usize].body.body_length_m()
            {
                self.pairs[k] = Pair::new(
                    &self.params.courtship,
                    new,
                    pair.female,
                    self.animals[pair.female as usize].body.heading(),
                );
                self.animals[pair.male as usize].rejected_by = Some((pair.female, 30.0));
                let text = format!(
                    "{} left {} for the larger {}",
                    self.animals[pair.female as usize].name(pair.female as usize),
                    self.animals[pair.male as usize].name(pair.male as usize),
                    self.animals[new as usize].name(new as usize)
                );
                self.log(
                    ReefEventKind::LeftForLarger {
                        female: pair.female,
                        old: pair.male,
                        new,
                    },
                    text,
                );
            }
        }
        // New pairs: a male and a female who choose each other.
        for i in 0..self.animals.len() {
            let a = &self.animals[i];
            if a.habits.kind != FishKind::Pacifist
                || a.habits.sex != Sex::Male
                || self.pair_of(i).is_some()
            {
                continue;
            }
            let Some(j) = mates_with(a) else {
                continue;
            };
            if mates_with(&self.animals[j as usize]) == Some(i as u32)
                && self.pair_of(j as usize).is_none()
            {
                self.log_choice(j, i as u32);
                self.pairs.push(Pair::new(
                    &self.params.courtship,
                    i as u32,
                    j,
                    self.animals[j as usize].body.heading(),
                ));
                let text = format!(
                    "{} and {} began courting: looping",
                    self.animals[i].name(i),
                    self.animals[j as usize].name(j as usize)
                );
                self.log(
                    ReefEventKind::Courtship {
                        male: i as u32,
                        female: j,
                        phase: Phase::Looping,
                    },
                    text,
                );
            }
        }
        // Advance, finish or break up.
        let t = self.time_secs as f32;
        let surface = self.tank.max_m.y;
        let visibility = self.config.visibility_m;
        let mut k = 0;
        while k < self.pairs.len() {
            let pair = self.pairs[k];
            let partner = |i: u32| {
                let a = &self.animals[i as usize];
                Partner {
                    position_m: a.body.position_m(),
                    head_m: a.body.head_m(),
                    heading: a.body.heading(),
                    body_length_m: a.body.body_length_m(),
                }
            };
            let (m, f) = (partner(pair.male), partner(pair.female));
            let both_alive =
                self.animals[pair.male as usize].alive && self.animals[pair.female as usize].alive;
            let (mut pair, entered) = {
                let mut p = pair;
                let entered = p.advance(&self.params.courtship, &m, &f, t, surface, dt);
                p.lost_secs = if m.position_m.distance(f.position_m) > visibility {
                    p.lost_secs + dt
                } else {
                    0.0
                };
                (p, entered)
            };
            let names = (
                self.animals[pair.male as usize].name(pair.male as usize),
                self.animals[pair.female as usize].name(pair.female as usize),
            );
            if let Some(phase) = entered {
                let text = if phase == Phase::Spawned {
                    format!("{} and {} spawned", names.0, names.1)
                } else {
                    format!("{} and {} began {}", names.0, names.1, phase.label())
                };
                self.log(
                    ReefEventKind::Courtship {
                        male: pair.male,
                        female: pair.female,
                        phase,
                    },
                    text,
                );
            }
            if pair.phase == Phase::Spawned {
                self.counts.spawnings += 1;
                for id in [pair.male, pair.female] {
                    let a = &mut self.animals[id as usize];
                    let constants = a.habits.mental;
                    a.mental.mated(&constants);
                    a.generator = IntentionGenerator::default();
                }
                self.pairs.remove(k);
                continue;
            }
            let wanted = mates_with(&self.animals[pair.male as usize]) == Some(pair.female)
                || mates_with(&self.animals[pair.female as usize]) == Some(pair.male)
                || self.animals[pair.male as usize].focus.intention == Intention::Avoid
                || self.animals[pair.female as usize].focus.intention == Intention::Avoid;
            if !both_alive || pair.timed_out(&self.params.courtship) || (!pair.bonded() && !wanted)
            {
                pair.phase_secs = 0.0;
                self.pairs.remove(k);
                self.log(
                    ReefEventKind::BrokeUp {
                        male: pair.male,
                        female: pair.female,
                    },
                    format!("{} and {} stopped courting", names.0, names.1),
                );
                continue;
            }
            self.pairs[k] = pair;
            k += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::reef::courtship::*;

    #[test]
    fn the_log_shows_the_female_choosing_the_bigger_male() {
        // The Courtship demo on its default muscle bodies: she sees both
        // males and the log says whom she chose over whom, and why.
        let mut w = ReefWorld::new(ReefConfig {
            seed: 1,
            scene: crate::sim::reef::demos::ReefScene::Courtship,
            ..ReefConfig::default()
        });
        for _ in 0..80 {
            w.step();
        }
        let chose = w
            .events()
            .iter()
            .find(|e| e.kind.name() == "chose")
            .expect("no choice logged in 2 s");
        let ReefEventKind::Chose { female, male, over } = chose.kind else {
            unreachable!()
        };
        let length = |i: u32| w.animals()[i as usize].body.body_length_m();
        assert_eq!(w.animals()[female as usize].habits.sex, Sex::Female);
        assert!(length(male) > length(over), "{}", chose.text);
        assert!(
            chose.text.ends_with("she prefers bigger males"),
            "{}",
            chose.text
        );
    }

    fn params() -> CourtshipParams {
        CourtshipParams::default()
    }

    fn partner(at: Vec3, heading: Vec3) -> Partner {
        Partner {
            position_m: at,
            head_m: at + heading * 0.25,
            heading,
            body_length_m: 0.5,
        }
    }

    #[test]
    fn the_phases_follow_in_order_when_their_conditions_are_met() {
        let female = partner(Vec3::new(0.0, 2.0, 0.0), Vec3::X);
        let mut pair = Pair::new(&params(), 1, 2, Vec3::X);
        let dt = 0.055;
        let mut t = 0.0;
        let mut seen = vec![pair.phase];
        // Looping: the male's mouth sits on the looping point.
        while pair.phase == Phase::Looping && t < 100.0 {
            let point = pair.loop_point_m(&params(), &female, t);
            let male = partner(point - Vec3::X * 0.25, Vec3::X);
            if let Some(p) = pair.advance(&params(), &male, &female, t, 4.5, dt) {
                seen.push(p);
            }
            t += dt;
        }
        // The first pass counts at once, then one per interval.
        let expected = 5.0 * params().pass_interval_secs;
        assert!((expected - 0.5..expected + 1.0).contains(&t), "{t}");
        // Circling: she turns 20° a step.
        let mut angle: f32 = 0.0;
        let male = partner(Vec3::ZERO, Vec3::Z);
        while pair.phase == Phase::Circling {
            angle += 20f32.to_radians();
            let f = partner(
                Vec3::new(0.0, 2.0, 0.0),
                Vec3::new(fmath::cos(angle), 0.0, fmath::sin(angle)),
            );
            if let Some(p) = pair.advance(&params(), &male, &f, t, 4.5, dt) {
                seen.push(p);
            }
            t += dt;
        }
        assert!(angle.to_degrees() >= 540.0 - 1.0 && angle.to_degrees() < 560.0);
        // Ascending: she reaches the surface.
        let high = partner(Vec3::new(0.0, 4.0, 0.0), Vec3::X);
        seen.push(
            pair.advance(&params(), &male, &high, t, 4.5, dt)
                .expect("near the surface"),
        );
        // Nuzzling: touches need the back-off in between.
        let mut touches = 0;
        while pair.phase == Phase::Nuzzling && touches < 1000 {
            let m = partner(Pair::abdomen_m(&high) - Vec3::X * 0.25, Vec3::X);
            if let Some(p) = pair.advance(&params(), &m, &high, t, 4.5, dt) {
                seen.push(p);
            }
            t += dt;
            touches += 1;
        }
        assert!(
            touches as f32 * dt >= 2.0 * params().back_off_secs,
            "{touches}"
        );
        assert_eq!(
            seen,
            vec![
                Phase::Looping,
                Phase::Circling,
                Phase::Ascending,
                Phase::Nuzzling,
                Phase::Spawned
            ]
        );
    }

    #[test]
    fn the_male_aims_at_her_abdomen_from_below() {
        let female = partner(Vec3::new(0.0, 3.0, 0.0), Vec3::X);
        let mut pair = Pair::new(&params(), 1, 2, Vec3::X);
        pair.phase = Phase::Nuzzling;
        pair.since_count_secs = params().back_off_secs;
        let above = partner(Vec3::new(0.0, 3.5, 0.0), Vec3::X);
        let (wish, _) = pair.wishes(&params(), &above, &female, 0.0, 4.5);
        assert!(wish.target_m.y < Pair::abdomen_m(&female).y);
        let below = partner(Vec3::new(-0.3, 2.5, 0.0), Vec3::X);
        let (wish, _) = pair.wishes(&params(), &below, &female, 0.0, 4.5);
        assert_eq!(wish.target_m, Pair::abdomen_m(&female));
    }
}
