//! The tank in words, for a student who cannot see it.
//!
//! - [`summary`]: one or two sentences on what the tank shows now, from the
//!   same numbers the plots show (the school's groups, alignment, spacing and
//!   speed; the reef's animals and the selected fish's mind; the physics
//!   fish's body; the learning lab's progress).
//! - [`full`]: the summary, each plot's latest value and its trend over the
//!   last ten seconds, and the latest events: what the *Describe the tank*
//!   key reads.
//! - [`Narrator`]: what the polite live region says, at a calm rate: a
//!   sentence when something happens (a shark catches a fish, the school
//!   splits or comes together, lines up or breaks up, a reef event), and the
//!   summary when it has changed and nothing was said for a while.
//!
//! Words come from the state report (`crate::automation::StateReport`),
//! never from the picture, so what is said is what the plots measure.

use crate::automation::{StateReport, TankReport};
use crate::i18n::{fmt, num, ts};
use crate::metrics_history::{MetricsHistory, MetricsSample};
use crate::tr;

/// At most one sentence about an event every this many seconds (real time);
/// events in between are said together.
pub const EVENT_GAP_SECS: f64 = 4.0;
/// The summary is said again at most this often, and only when its words
/// changed.
pub const SUMMARY_GAP_SECS: f64 = 30.0;

/// How aligned the fish are, in words, from the polarization (0–1).
pub fn alignment_words(polarization: f32) -> &'static str {
    if polarization >= 0.8 {
        ts("describe-aligned-tight")
    } else if polarization >= 0.5 {
        ts("describe-aligned-loose")
    } else {
        ts("describe-aligned-none")
    }
}

/// One tank of point-mass or muscle fish, as its metrics say.
fn school_words(fish: usize, sample: &MetricsSample, count_hidden: bool) -> String {
    let fish_text = if count_hidden {
        tr!("describe-the-fish")
    } else {
        tr!("describe-fish-count", count = fish)
    };
    if fish == 0 {
        return tr!("describe-empty");
    }
    let arrangement = match sample.groups {
        0 | 1 if fish > 1 => tr!("describe-one-school"),
        0 | 1 => tr!("describe-alone"),
        // Mostly fish on their own, hardly groups at all.
        g if g as usize * 4 > fish => tr!("describe-scattered", groups = g),
        g => tr!("describe-in-groups", groups = g),
    };
    let mut words = tr!(
        "describe-school",
        fish = fish_text,
        arrangement = arrangement,
        alignment = alignment_words(sample.polarization),
        polarization = num(sample.polarization.into(), 2),
        spacing = num(sample.nnd_body_lengths.into(), 1),
        speed = num(sample.mean_speed.into(), 2),
    );
    if sample.milling >= 0.5 {
        words.push_str(", ");
        words.push_str(&tr!(
            "describe-milling",
            milling = num(sample.milling.into(), 2)
        ));
    }
    words.push('.');
    if sample.catches > 0 {
        words.push(' ');
        words.push_str(&tr!("describe-caught-so-far", count = sample.catches));
    }
    words
}

/// What the tank shows now, in one or two sentences.
pub fn summary(state: &StateReport) -> String {
    let hidden = state.student_view && state.fish_count == 0;
    let mut words = if let Some(reef) = &state.scene_report.reef {
        let mut w = tr!(
            "describe-reef",
            predators = reef.predators as u64,
            prey = reef.prey as u64,
            pacifists = reef.pacifists as u64,
            food = reef.food as u64,
        );
        if let Some(fish) = &reef.selected {
            w.push(' ');
            w.push_str(&mind_words(fish));
        }
        w
    } else if let Some(learning) = &state.scene_report.learning {
        let mut w = match learning.drill {
            Some(drill) => tr!(
                "describe-drill",
                drill = drill + 1,
                drills = learning.drills,
                percent = num(f64::from(learning.progress) * 100.0, 0),
                best = num(f64::from(learning.best_objective), 2),
            ),
            None => tr!(
                "describe-lab",
                learned = learning.finished.len(),
                drills = learning.drills,
                source = match learning.source {
                    crate::sim::learning::learning_lab::SetSource::Shipped => "shipped", // words: a Fluent selector
                    crate::sim::learning::learning_lab::SetSource::TrainedHere => "trained", // words: a Fluent selector
                    crate::sim::learning::learning_lab::SetSource::Loaded => "loaded", // words: a Fluent selector
                }
            ),
        };
        if let Some(race) = &learning.race {
            w.push(' ');
            w.push_str(&tr!(
                "describe-race",
                count = race.len().max(learning.race_entrants)
            ));
        }
        w
    } else if let Some(physics) = &state.scene_report.physics {
        let mut w = school_words(physics.fish, &state.metrics.sample, hidden);
        if physics.sharks > 0 {
            w.push(' ');
            w.push_str(&tr!(
                "describe-sharks-hunting",
                count = physics.sharks as u64
            ));
        }
        if let Some(fish) = &physics.selected {
            w.push(' ');
            w.push_str(&tr!(
                if fish.turning {
                    "describe-physics-fish-turning"
                } else {
                    "describe-physics-fish"
                },
                number = fish.index + 1,
                speed = num(f64::from(fish.speed_m_per_s), 2),
            ));
        }
        w
    } else if state.compare {
        let right = state.metrics_right.as_ref().map_or(String::new(), |r| {
            format!(
                " {}",
                tr!(
                    "describe-right-tank",
                    words = school_words(state.fish_count, &r.sample, hidden)
                )
            )
        });
        let left = tr!(
            "describe-left-tank",
            words = school_words(state.fish_count, &state.metrics.sample, hidden)
        );
        format!("{left}{right}")
    } else {
        let mut w = school_words(state.fish_count, &state.metrics.sample, hidden);
        if let Some(attention) = &state.metrics.attention {
            w.push(' ');
            w.push_str(&tr!("describe-sees", count = attention.neighbours.len()));
        }
        w
    };
    if state.paused {
        words.push(' ');
        words.push_str(ts("describe-paused"));
    }
    words
}

/// What the selected animal does, when one is selected: said when a
/// student picks it with the keyboard.
pub fn selected(state: &StateReport) -> Option<String> {
    if let Some(reef) = &state.scene_report.reef {
        return reef
            .selected
            .as_ref()
            .map(|fish| tr!("describe-selected", what = mind_words(fish)));
    }
    if let Some(physics) = &state.scene_report.physics {
        return physics.selected.as_ref().map(|fish| {
            tr!(
                if fish.turning {
                    "describe-selected-body-turning"
                } else {
                    "describe-selected-body"
                },
                number = fish.index + 1,
                species = fish.species,
                length = num(f64::from(fish.body_length_m), 2),
                speed = num(f64::from(fish.speed_m_per_s), 2),
            )
        });
    }
    state.metrics.attention.as_ref().map(|attention| {
        let mut words = tr!(
            if attention.sees_far_school {
                "describe-selected-sees-far"
            } else {
                "describe-selected-sees"
            },
            number = attention.fish + 1,
            count = attention.neighbours.len(),
        );
        if attention.fleeing {
            words.push(' ');
            words.push_str(ts("describe-fleeing"));
        }
        words
    })
}

/// The selected reef fish's state of mind.
fn mind_words(fish: &crate::sim::reef::report::SelectedMindReport) -> String {
    if !fish.alive {
        return tr!("describe-eaten", name = fish.name.as_str());
    }
    use crate::sim::reef::mind::Intention;
    // Selectors of `describe-mind`'s words, not words.
    let doing = match fish.intention {
        Intention::Avoid => "avoid",
        Intention::Escape => "escape",
        Intention::School => "school",
        Intention::Eat => "eat",
        Intention::Mate => "mate",
        Intention::Leave => "leave",
        Intention::Wander => "wander",
    };
    tr!(
        "describe-mind",
        name = fish.name.as_str(),
        doing = doing,
        hunger = num(f64::from(fish.hunger), 1),
        fear = num(f64::from(fish.fear), 1),
        libido = num(f64::from(fish.libido), 1),
    )
}

/// The trend of one measure over the history, in words: "rising from 0.62
/// ten seconds ago".
fn trend(history: &MetricsHistory, value: impl Fn(&MetricsSample) -> f32, digits: usize) -> String {
    let Some(latest) = history.latest() else {
        return String::new();
    };
    let now = value(latest);
    let Some(before) = history
        .samples()
        .filter(|s| s.time_secs <= latest.time_secs - 10.0)
        .last()
    else {
        return fmt(now.into(), digits);
    };
    let then = value(before);
    let scale = now.abs().max(then.abs()).max(1e-6);
    // Selectors of `describe-trend`, not words.
    let direction = if (now - then).abs() / scale < 0.05 {
        "steady" // words: a Fluent selector
    } else if now > then {
        "rising" // words: a Fluent selector
    } else {
        "falling" // words: a Fluent selector
    };
    tr!(
        "describe-trend",
        now = fmt(now.into(), digits),
        direction = direction,
        then = fmt(then.into(), digits),
    )
}

/// The plots' latest values and trends, for one tank's history.
fn plot_words(history: &MetricsHistory) -> String {
    if history.is_empty() {
        return String::new();
    }
    tr!(
        "describe-plots",
        polarization = trend(history, |s| s.polarization, 2),
        neighbour = trend(history, |s| s.nnd_body_lengths, 1),
        groups = trend(history, |s| s.groups as f32, 0),
        milling = trend(history, |s| s.milling, 2),
        speed = trend(history, |s| s.mean_speed, 2),
    )
}

/// Everything the *Describe the tank* key reads: the summary, the plots'
/// latest values with their trends, the latest reef events and the time.
pub fn full(state: &StateReport, histories: &[(&str, &MetricsHistory)]) -> String {
    let mut words = vec![summary(state)];
    for (name, history) in histories {
        let plots = plot_words(history);
        if !plots.is_empty() {
            words.push(if histories.len() > 1 {
                format!("{name}: {plots}")
            } else {
                plots
            });
        }
    }
    if let Some(reef) = &state.scene_report.reef
        && !reef.events.is_empty()
    {
        // Each line in the language in force (`text` is English, for programs).
        let latest: Vec<String> = reef
            .events
            .iter()
            .rev()
            .take(3)
            .map(|e| e.words())
            .collect();
        words.push(tr!("describe-latest", events = latest.join("; ")));
    }
    words.push(tr!(
        "describe-time",
        seconds = num(state.time_secs, 0),
        speed = f64::from(state.speed),
        seed = state.seed.to_string(),
    ));
    words.join(" ")
}

/// The few numbers events are read from, kept between frames.
#[derive(Clone, Debug, Default, PartialEq)]
struct Glance {
    scene: &'static str,
    steps: u64,
    groups: u32,
    aligned: bool,
    catches: u64,
    /// The latest reef event: its time (ms) and English line (which tell it
    /// apart whatever the language), and its line in the language in force.
    last_reef_event: Option<(u64, String, String)>,
}

impl Glance {
    fn of(state: &StateReport) -> Self {
        let sample = &state.metrics.sample;
        Self {
            scene: state.scene,
            steps: state.steps,
            groups: sample.groups,
            aligned: sample.polarization >= 0.8,
            catches: sample.catches + state.metrics_right.as_ref().map_or(0, tank_catches),
            last_reef_event: state.scene_report.reef.as_ref().and_then(|r| {
                r.events
                    .last()
                    .map(|e| ((e.time_secs * 1000.0) as u64, e.text.clone(), e.words()))
            }),
        }
    }
}

fn tank_catches(tank: &TankReport) -> u64 {
    tank.sample.catches
}

/// What changed between two glances at the same run, in words.
fn news(before: &Glance, now: &Glance, state: &StateReport) -> Vec<String> {
    let mut said = Vec::new();
    // The reef and the learning lab have no school metrics to speak of.
    let school = state.scene_report.reef.is_none() && state.scene_report.learning.is_none();
    if school && !state.compare && state.fish_count > 1 {
        if now.groups > before.groups && before.groups <= 1 {
            said.push(tr!("describe-split", groups = now.groups));
        } else if now.groups == 1 && before.groups > 1 {
            said.push(tr!("describe-together"));
        }
        let polarization = || num(state.metrics.sample.polarization.into(), 2);
        if now.aligned && !before.aligned {
            said.push(tr!("describe-in-line", polarization = polarization()));
        } else if !now.aligned && before.aligned {
            said.push(tr!("describe-out-of-line", polarization = polarization()));
        }
    }
    if now.catches > before.catches {
        // (Events during a quiet gap are added up here.)
        let new = now.catches - before.catches;
        said.push(tr!("describe-caught", count = new, total = now.catches));
    }
    let event = |g: &Glance| {
        g.last_reef_event
            .as_ref()
            .map(|(t, text, _)| (*t, text.clone()))
    };
    if event(now) != event(before)
        && let Some((_, _, words)) = &now.last_reef_event
    {
        said.push(words.clone());
    }
    said
}

/// Decides what the live region says and when.
#[derive(Debug, Default)]
pub struct Narrator {
    /// The run as it was when it was last spoken of: news is told against it,
    /// so what happened during a gap is said once, added up.
    spoken: Option<Glance>,
    last_said_secs: Option<f64>,
    last_summary: String,
    last_summary_secs: Option<f64>,
}

impl Narrator {
    /// Looks at the run at real time `now_secs` (each frame) and returns what
    /// to say now, if anything.
    pub fn observe(&mut self, state: &StateReport, now_secs: f64) -> Option<String> {
        let glance = Glance::of(state);
        let new_run = self
            .spoken
            .as_ref()
            .is_none_or(|s| s.scene != glance.scene || glance.steps < s.steps);
        if new_run {
            // A reset or another scene: start afresh, with the summary.
            self.spoken = Some(glance.clone());
            self.last_summary.clear();
            self.last_summary_secs = None;
        }
        let since = |at: Option<f64>| at.map_or(f64::INFINITY, |t| now_secs - t);
        if since(self.last_said_secs) < EVENT_GAP_SECS {
            return None;
        }
        if let Some(spoken) = &self.spoken {
            let news = news(spoken, &glance, state);
            self.spoken = Some(glance);
            if !news.is_empty() {
                self.last_said_secs = Some(now_secs);
                return Some(news.join(" "));
            }
        }
        if state.paused && !self.last_summary.is_empty() {
            return None;
        }
        if since(self.last_summary_secs) >= SUMMARY_GAP_SECS {
            let words = summary(state);
            // Only when it says something new (numbers rounded as spoken).
            if words != self.last_summary {
                self.last_summary = words.clone();
                self.last_summary_secs = Some(now_secs);
                self.last_said_secs = Some(now_secs);
                return Some(words);
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lab::Lab;
    use crate::settings::tank::{Preset, TankSettings};
    use crate::settings::{Scene, Settings};

    fn state_of(lab: &Lab) -> StateReport {
        StateReport::new(lab, "webgl2", 60.0)
    }

    fn lab(scene: Scene, seed: u64, adjust: impl FnOnce(&mut Settings)) -> Lab {
        let mut settings = Settings {
            scene,
            seed,
            ..Settings::default()
        };
        adjust(&mut settings);
        Lab::new(settings)
    }

    #[test]
    fn the_words_follow_the_numbers_of_the_plots() {
        let mut run = lab(Scene::Boids, 11, |_| {});
        run.step(600);
        let state = state_of(&run);
        let words = summary(&state);
        let sample = &state.metrics.sample;
        assert!(
            words.contains(&format!("polarization {:.2}", sample.polarization)),
            "{words}"
        );
        assert!(
            words.contains(alignment_words(sample.polarization)),
            "{words}"
        );
        assert!(
            words.contains(&format!("{} fish", state.fish_count)),
            "{words}"
        );
    }

    #[test]
    fn a_school_and_loners_are_told_apart_in_words() {
        // The lesson of the schooling lab, heard rather than seen: the same
        // tank with the Group preset and with the Individual preset.
        for seed in [21, 22] {
            let mut group = lab(Scene::Boids, seed, |s| {
                s.left = TankSettings::with_preset(Preset::Group)
            });
            let mut loners = lab(Scene::Boids, seed, |s| {
                s.left = TankSettings::with_preset(Preset::Individual)
            });
            group.step(1800);
            loners.step(1800);
            let group_words = summary(&state_of(&group));
            let loner_words = summary(&state_of(&loners));
            assert!(
                group_words.contains("in one school"),
                "seed {seed}: {group_words}"
            );
            assert!(
                !loner_words.contains("tightly aligned"),
                "seed {seed}: {loner_words}"
            );
            assert_ne!(group_words, loner_words);
        }
    }

    #[test]
    fn every_scene_is_described() {
        for scene in Scene::ALL {
            let mut run = lab(scene, 3, |_| {});
            run.step(30);
            let state = state_of(&run);
            let words = full(&state, &[("", run.runs()[0].history())]);
            assert!(words.len() > 40, "{scene:?}: {words}");
            assert!(words.contains("seed 3"), "{scene:?}: {words}");
        }
    }

    #[test]
    fn the_narrator_speaks_calmly_and_says_when_a_shark_catches_a_fish() {
        let mut run = lab(Scene::Boids, 5, |s| s.left.sharks = 3);
        let mut narrator = Narrator::default();
        let mut said: Vec<(f64, String)> = Vec::new();
        // Two simulated minutes, one frame of two steps at a time (60 frames a second).
        for frame in 0..3600 {
            run.step(2);
            let now = f64::from(frame) / 60.0;
            if let Some(text) = narrator.observe(&state_of(&run), now) {
                said.push((now, text));
            }
        }
        let catches = state_of(&run).metrics.sample.catches;
        assert!(catches > 0, "no shark caught a fish in two minutes");
        assert!(
            said.iter().any(|(_, t)| t.contains("caught")),
            "{catches} catches, never said: {said:?}"
        );
        // Calm: never two messages within the event gap.
        for pair in said.windows(2) {
            assert!(pair[1].0 - pair[0].0 >= EVENT_GAP_SECS - 1e-9, "{said:?}");
        }
        // The first thing said is the summary.
        assert!(said[0].1.contains("fish"), "{said:?}");
    }

    #[test]
    fn the_description_reads_in_spanish_with_decimal_commas() {
        use crate::i18n::{Lang, with_lang};
        let mut run = lab(Scene::Boids, 11, |s| s.paused = true);
        run.step(600);
        let state = state_of(&run);
        let words = with_lang(Lang::Es, || full(&state, &[("", run.runs()[0].history())]));
        let sample = &state.metrics.sample;
        let polarization = format!("{:.2}", sample.polarization).replace('.', ",");
        assert!(
            words.contains(&format!("polarización {polarization}")),
            "{words}"
        );
        assert!(
            words.contains(&format!("{} peces", state.fish_count)),
            "{words}"
        );
        assert!(words.contains("metros por segundo"), "{words}");
        assert!(words.contains("semilla 11"), "{words}");
        assert!(words.contains("En pausa."), "{words}");
        assert!(!words.contains("polarization"), "{words}");
        // Back in English afterwards.
        assert!(full(&state, &[]).contains("polarization"));
    }

    #[test]
    fn a_paused_tank_is_not_described_over_and_over() {
        let run = lab(Scene::Boids, 5, |s| s.paused = true);
        let mut narrator = Narrator::default();
        let said: Vec<String> = (0..600)
            .filter_map(|frame| narrator.observe(&state_of(&run), f64::from(frame)))
            .collect();
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(said[0].ends_with("Paused."), "{said:?}");
    }
}
