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
//! The pair's state machine and where each partner wants to go are in
//! `reef/pair.rs`; this module holds the reef's courtship stage
//! ([`Courtship`]), which forms pairs, advances them and ends them; the
//! bodies stage (`reef/bodies.rs`) moves the partners.

use crate::sim::reef::animal::ReefAnimal;
use crate::sim::reef::events::{EventLog, Line, ReefCounts, ReefEventKind, phase_key};
use crate::sim::reef::mind::{FishKind, Focus, Intention, IntentionGenerator, Sex, Target};
use crate::sim::reef::params::CourtshipParams;

pub use crate::sim::reef::pair::{Pair, Partner, Phase, Wish};

/// How long a male left for a larger one leaves that female alone, seconds.
const REJECTED_SECS: f32 = 30.0;

/// The courtship stage's state: the courting pairs, and by animal what the
/// stage remembers of it as a suitor.
#[derive(Clone, Debug, Default)]
pub struct Courtship {
    pairs: Vec<Pair>,
    /// By animal index.
    suitors: Vec<Suitor>,
}

/// What the courtship stage remembers of one animal.
#[derive(Clone, Debug, Default)]
struct Suitor {
    /// A female that left this male for another, and for how many more
    /// seconds he leaves her alone.
    rejected_by: Option<(u32, f32)>,
    /// The partners it saw at its last decision, best first (a female's
    /// choice, for the log).
    mates_seen: Vec<u32>,
}

/// What the courtship stage reads besides the animals: the tuning, the
/// water's surface and visibility, and the clock.
pub(super) struct CourtshipInputs<'a> {
    pub params: &'a CourtshipParams,
    pub surface_y_m: f32,
    pub visibility_m: f32,
    pub time_secs: f64,
    pub dt_secs: f32,
}

impl Courtship {
    /// The courting pairs.
    pub fn pairs(&self) -> &[Pair] {
        &self.pairs
    }

    /// The pair animal `i` belongs to.
    pub fn pair_of(&self, i: usize) -> Option<&Pair> {
        let i = i as u32;
        self.pairs.iter().find(|p| p.male == i || p.female == i)
    }

    /// Animal `i`'s partner in a bonded pair (past looping), if it is in one.
    pub(super) fn bonded_partner(&self, i: usize) -> Option<u32> {
        let me = i as u32;
        self.pairs
            .iter()
            .find(|p| p.bonded() && (p.male == me || p.female == me))
            .map(|p| if p.male == me { p.female } else { p.male })
    }

    /// The female that left male `i` for another, if he still leaves her
    /// alone.
    pub(super) fn rejected_by(&self, i: usize) -> Option<u32> {
        self.suitors.get(i)?.rejected_by.map(|r| r.0)
    }

    /// Male `i` leaves the female that left him alone for `dt_secs` less.
    pub(super) fn forget_rejection(&mut self, i: usize, dt_secs: f32) {
        if let Some(suitor) = self.suitors.get_mut(i)
            && let Some((f, left)) = suitor.rejected_by
        {
            suitor.rejected_by = (left > dt_secs).then_some((f, left - dt_secs));
        }
    }

    /// Animal `i` saw these partners at its decision (best first).
    pub(super) fn saw_mates(&mut self, i: usize, mates: impl Iterator<Item = u32>) {
        let seen = &mut self.suitor_mut(i).mates_seen;
        seen.clear();
        seen.extend(mates);
    }

    /// What the stage remembers of animal `i` (a fresh memory if nothing yet).
    fn suitor_mut(&mut self, i: usize) -> &mut Suitor {
        if self.suitors.len() <= i {
            self.suitors.resize(i + 1, Suitor::default());
        }
        &mut self.suitors[i]
    }

    /// Logs female `female`'s choice of `male` when she saw other males too:
    /// "pacifist 0 chose pacifist 2 (0.61 m long) over pacifist 1 (0.46 m)".
    /// She ranks bigger males first (`reef/perception.rs`), nearer ones next.
    fn log_choice(
        &self,
        animals: &[ReefAnimal],
        log: &mut EventLog,
        time_secs: f64,
        female: u32,
        male: u32,
    ) {
        let length = |i: u32| animals[i as usize].body.body_length_m();
        let Some(over) = self
            .suitors
            .get(female as usize)
            .into_iter()
            .flat_map(|s| s.mates_seen.iter())
            .copied()
            .filter(|&m| m != male)
            .max_by(|&a, &b| length(a).total_cmp(&length(b)).then(b.cmp(&a)))
        else {
            return;
        };
        let why = if length(male) >= length(over) {
            "bigger"
        } else {
            "nearer"
        };
        let text = Line::new("reef-event-chose")
            .animal("female", animals, female as usize)
            .animal("male", animals, male as usize)
            .number("male_length", f64::from(length(male)), 2)
            .animal("over", animals, over as usize)
            .number("over_length", f64::from(length(over)), 2)
            .key("why", why);
        log.push(time_secs, ReefEventKind::Chose { female, male, over }, text);
    }

    /// Forms courting pairs from mutual choices, lets a female change to a
    /// larger male during looping, advances each pair's sequence and ends it.
    /// Spawned pairs are counted in `counts` and their minds reset.
    pub(super) fn step(
        &mut self,
        animals: &mut [ReefAnimal],
        log: &mut EventLog,
        counts: &mut ReefCounts,
        inputs: &CourtshipInputs,
    ) {
        let params = inputs.params;
        let dt = inputs.dt_secs;
        let now = inputs.time_secs;
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
            let chosen = mates_with(&animals[pair.female as usize]);
            if let Some(new) = chosen
                && new != pair.male
                && mates_with(&animals[new as usize]) == Some(pair.female)
                && self.pair_of(new as usize).is_none()
                && animals[new as usize].body.body_length_m()
                    > animals[pair.male as usize].body.body_length_m()
            {
                self.pairs[k] = Pair::new(
                    params,
                    new,
                    pair.female,
                    animals[pair.female as usize].body.heading(),
                );
                self.suitor_mut(pair.male as usize).rejected_by =
                    Some((pair.female, REJECTED_SECS));
                let text = Line::new("reef-event-left-for-larger")
                    .animal("female", animals, pair.female as usize)
                    .animal("old", animals, pair.male as usize)
                    .animal("new", animals, new as usize);
                log.push(
                    now,
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
        for i in 0..animals.len() {
            let a = &animals[i];
            if a.habits.kind != FishKind::Pacifist
                || a.habits.sex != Sex::Male
                || self.pair_of(i).is_some()
            {
                continue;
            }
            let Some(j) = mates_with(a) else {
                continue;
            };
            if mates_with(&animals[j as usize]) == Some(i as u32)
                && self.pair_of(j as usize).is_none()
            {
                self.log_choice(animals, log, now, j, i as u32);
                self.pairs.push(Pair::new(
                    params,
                    i as u32,
                    j,
                    animals[j as usize].body.heading(),
                ));
                let text = Line::new("reef-event-began-courting")
                    .animal("male", animals, i)
                    .animal("female", animals, j as usize);
                log.push(
                    now,
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
        let t = now as f32;
        let surface = inputs.surface_y_m;
        let visibility = inputs.visibility_m;
        let mut k = 0;
        while k < self.pairs.len() {
            let pair = self.pairs[k];
            let partner = |i: u32| {
                let a = &animals[i as usize];
                Partner {
                    position_m: a.body.position_m(),
                    head_m: a.body.head_m(),
                    heading: a.body.heading(),
                    body_length_m: a.body.body_length_m(),
                }
            };
            let (m, f) = (partner(pair.male), partner(pair.female));
            let both_alive =
                animals[pair.male as usize].alive && animals[pair.female as usize].alive;
            let (mut pair, entered) = {
                let mut p = pair;
                let entered = p.advance(params, &m, &f, t, surface, dt);
                p.lost_secs = if m.position_m.distance(f.position_m) > visibility {
                    p.lost_secs + dt
                } else {
                    0.0
                };
                (p, entered)
            };
            let names = Line::new("reef-event-stopped-courting")
                .animal("male", animals, pair.male as usize)
                .animal("female", animals, pair.female as usize);
            if let Some(phase) = entered {
                let text = if phase == Phase::Spawned {
                    Line::new("reef-event-spawned")
                } else {
                    Line::new("reef-event-courtship-phase").key("phase", phase_key(phase))
                }
                .animal("male", animals, pair.male as usize)
                .animal("female", animals, pair.female as usize);
                log.push(
                    now,
                    ReefEventKind::Courtship {
                        male: pair.male,
                        female: pair.female,
                        phase,
                    },
                    text,
                );
            }
            if pair.phase == Phase::Spawned {
                counts.spawnings += 1;
                for id in [pair.male, pair.female] {
                    let a = &mut animals[id as usize];
                    let constants = a.habits.mental;
                    a.mental.mated(&constants);
                    a.generator = IntentionGenerator::default();
                }
                self.pairs.remove(k);
                continue;
            }
            let wanted = mates_with(&animals[pair.male as usize]) == Some(pair.female)
                || mates_with(&animals[pair.female as usize]) == Some(pair.male)
                || animals[pair.male as usize].focus.intention == Intention::Avoid
                || animals[pair.female as usize].focus.intention == Intention::Avoid;
            if !both_alive || pair.timed_out(params) || (!pair.bonded() && !wanted) {
                pair.phase_secs = 0.0;
                self.pairs.remove(k);
                log.push(
                    now,
                    ReefEventKind::BrokeUp {
                        male: pair.male,
                        female: pair.female,
                    },
                    names,
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
    use crate::sim::common::fmath;
    use crate::sim::reef::courtship::*;
    use crate::sim::reef::world::{ReefConfig, ReefWorld};
    use glam::Vec3;

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
