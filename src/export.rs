//! *Download data (CSV)* and `shoal.export_csv()`: each scene's own numbers as
//! one tidy CSV file a spreadsheet opens.
//!
//! Every file starts with comment lines (`# `): the scene, the simulated time,
//! the seed and the share link fragment that reopens the exact settings (paste
//! it after Shoal's address). Then one header line and one row per
//! observation:
//!
//! - aquarium and schooling lab: the school's metrics, one row per sample (every
//!   0.25 s) per tank, over the last five minutes (the same table as
//!   `shoal.metrics_csv()`, [`crate::metrics_history::CSV_HEADER`]);
//! - physics fish: the selected fish's twelve muscles and its speed at every step
//!   of the last [`crate::lab::BODY_TRACE_SECS`] seconds; with no fish selected, a
//!   comment saying to click one and the school's metrics over the last minutes;
//! - reef: one table whose first column, `table`, says what a row is: `counts`
//!   (living animals by kind, plankton, prey eaten, missed strikes, food eaten,
//!   spawnings, collisions, every 0.275 s), `event` (the event log) and `mind`
//!   (the selected fish's hunger, libido, fear and intention, every 0.5 s over
//!   its last two minutes); a row leaves the other tables' columns empty;
//! - learning lab: the same layout, `training` rows (the current drill's
//!   objective after every annealing step: current and best E, temperature) and
//!   `finished` rows (each learned drill's objective, annealing steps and the
//!   energy its two main rhythms keep).
//!
//! Files are named after the scene and the simulated time
//! (`shoal-reef-t0125s.csv`), never the wall clock: the run is deterministic and
//! so is its file. Pure: no egui, no files; tested natively.

use std::fmt::Write as _;

use serde::Serialize;

use crate::i18n::{Lang, with_lang};
use crate::lab::{Lab, Run};
use crate::settings::{Scene, Settings};
use crate::sim::body::MUSCLE_COUNT;
use crate::sim::body::body_layout::{MUSCLES, MuscleSegment, Side};

/// A CSV file to save: its name and its text (`shoal.export_csv()` returns it
/// as `{name, text}`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct CsvExport {
    pub name: String,
    pub text: String,
}

/// The left (or only) tank's scene as a CSV file: the header every file has,
/// then the scene's own tables ([`crate::scenes::SceneClass::write_csv`]).
///
/// The file is in English whatever language the screen shows: spreadsheets,
/// scripts and the tests read its comment lines by their prefixes
/// (`# settings link: `) and its numbers with a decimal point, and one file
/// reads the same on every computer.
pub fn scene_csv(lab: &Lab) -> CsvExport {
    with_lang(Lang::En, || english_scene_csv(lab))
}

fn english_scene_csv(lab: &Lab) -> CsvExport {
    let settings = lab.settings();
    let run = &lab.runs()[0];
    let mut text = header(settings, run);
    settings.scene.class().write_csv(lab, &mut text);
    CsvExport {
        name: file_name(settings.scene, run.time_secs()),
        text,
    }
}

/// `shoal-<scene>-t<seconds>s.csv`, the whole simulated seconds on at least
/// four digits, so the files of one lesson sort by time.
pub fn file_name(scene: Scene, time_secs: f64) -> String {
    let secs = if time_secs.is_finite() {
        time_secs.max(0.0).floor() as u64
    } else {
        0
    };
    format!("shoal-{}-t{secs:04}s.csv", scene.name())
}

/// The last comment line of the files that hold several tables.
pub(crate) const FILTER_NOTE: &str =
    "# filter on the first column: a row leaves the other tables' columns empty\n"; // words: a CSV comment line, English like the whole file (see scene_csv)

/// How often the lab samples `run`'s metrics and for how long it keeps them.
pub(crate) fn sampling(run: &Run) -> String {
    let every = run.sample_every_steps() as f64 * run.scene().dt_secs();
    format!(
        "every {every:.3} s over the last {:.0} s", // words: part of a CSV comment line, English like the whole file
        crate::metrics_history::HISTORY_SECS
    )
}

/// The comment lines every file starts with.
fn header(settings: &Settings, run: &Run) -> String {
    let mut out = String::new();
    let scene = settings.scene;
    // Writing to a String cannot fail.
    let _ = writeln!(
        out,
        "# Shoal data: {} ({})", // words: a CSV comment line, English like the whole file
        crate::i18n::with_lang(crate::i18n::Lang::En, || scene.class().facts().label()),
        scene.name()
    );
    let _ = writeln!(
        out,
        "# simulated time: {:.3} s ({} steps)", // words: a CSV comment line scripts read
        run.time_secs(),
        run.steps()
    );
    let _ = writeln!(out, "# seed: {}", settings.seed);
    if settings.studio.has_mystery_for_student() {
        // The link holds the values the teacher made a mystery.
        let _ = writeln!(
            out,
            "# settings link: withheld (this page has mystery values for the class to infer)" // words: a CSV comment line scripts read
        );
    } else {
        let _ = writeln!(
            out,
            "# settings link: #{} (put it after Shoal's address to reopen these settings)", // words: a CSV comment line scripts read
            crate::settings::share_link::encode(settings)
        );
    }
    out
}

/// Column names of the twelve muscles, in the order of `body_layout::MUSCLES`:
/// `front_left_top`, … (segment, side, top = dorsal or bottom = ventral).
pub fn muscle_columns() -> [String; MUSCLE_COUNT] {
    std::array::from_fn(|m| {
        let muscle = MUSCLES[m];
        let segment = match muscle.segment {
            MuscleSegment::Anterior => "front",
            MuscleSegment::Middle => "middle",
            MuscleSegment::Posterior => "tail",
        };
        let side = match muscle.side {
            Side::Left => "left",
            Side::Right => "right",
        };
        let part = if muscle.dorsal { "top" } else { "bottom" };
        format!("{segment}_{side}_{part}")
    })
}

/// A text cell, quoted (commas and quotes inside stay in the cell).
pub(crate) fn quoted(text: &str) -> String {
    format!("\"{}\"", text.replace('"', "\"\""))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenes::{LEARNING_HEADER, PHYSICS_SCHOOL_HEADER, REEF_HEADER};

    /// The settings the file's link reopens.
    fn linked_settings(text: &str) -> Settings {
        let line = text
            .lines()
            .find_map(|l| l.strip_prefix("# settings link: "))
            .expect("a settings link line");
        let fragment = line.split_whitespace().next().unwrap();
        crate::settings::share_link::decode(fragment)
            .expect("the link decodes")
            .expect("the link holds settings")
    }

    /// The comment lines, then the table (header and rows) split into cells.
    fn table(text: &str) -> (Vec<&str>, Vec<Vec<&str>>) {
        let mut rows = text.lines().filter(|l| !l.starts_with('#'));
        let header: Vec<&str> = rows.next().expect("a header").split(',').collect();
        let rows = rows.map(split_cells).collect();
        (header, rows)
    }

    /// Cells of one CSV line (quoted cells may hold commas).
    fn split_cells(line: &str) -> Vec<&str> {
        let mut cells = Vec::new();
        let (mut start, mut quoted) = (0, false);
        for (k, c) in line.char_indices() {
            match c {
                '"' => quoted = !quoted,
                ',' if !quoted => {
                    cells.push(&line[start..k]);
                    start = k + 1;
                }
                _ => {}
            }
        }
        cells.push(&line[start..]);
        cells
    }

    fn column(header: &[&str], name: &str) -> usize {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
    }

    fn check_header(export: &CsvExport, lab: &Lab) {
        let text = &export.text;
        assert!(text.starts_with("# Shoal data: "), "{text}");
        let scene = lab.settings().scene;
        assert!(
            text.lines()
                .next()
                .unwrap()
                .contains(scene.class().facts().label())
        );
        let t = format!("# simulated time: {:.3} s", lab.runs()[0].time_secs());
        assert!(text.contains(&t), "{t} in {text}");
        assert!(text.contains(&format!("# seed: {}\n", lab.settings().seed)));
        assert_eq!(
            &linked_settings(text),
            lab.settings(),
            "the link reopens the run"
        );
        assert_eq!(
            export.name,
            file_name(scene, lab.runs()[0].time_secs()),
            "named after the scene and the time"
        );
        // Every row of the table has the header's number of cells.
        let (header, rows) = table(text);
        assert!(
            rows.iter().all(|r| r.len() == header.len()),
            "{header:?} {:?}",
            rows.iter().find(|r| r.len() != header.len())
        );
    }

    #[test]
    fn file_names_give_the_scene_and_the_whole_simulated_seconds() {
        assert_eq!(file_name(Scene::Reef, 125.4), "shoal-reef-t0125s.csv");
        assert_eq!(file_name(Scene::Boids, 0.0), "shoal-boids-t0000s.csv");
        assert_eq!(
            file_name(Scene::Physics, 12_345.9),
            "shoal-physics-t12345s.csv"
        );
        assert_eq!(
            file_name(Scene::Learning, f64::NAN),
            "shoal-learning-t0000s.csv"
        );
        assert_eq!(
            file_name(Scene::Aquarium, 59.99),
            "shoal-aquarium-t0059s.csv"
        );
    }

    #[test]
    fn the_schooling_lab_exports_its_metrics_table_for_both_tanks() {
        let mut settings = Settings {
            scene: Scene::Boids,
            compare: true,
            seed: 7,
            ..Settings::default()
        };
        settings.left.fish_count = 60;
        settings.right.fish_count = 60;
        let mut lab = Lab::new(settings);
        lab.step(150);
        let export = scene_csv(&lab);
        check_header(&export, &lab);
        assert_eq!(export.name, "shoal-boids-t0002s.csv");
        let (header, rows) = table(&export.text);
        assert_eq!(
            header.join(",") + "\n",
            crate::metrics_history::CSV_HEADER,
            "today's columns"
        );
        // 150 steps: samples at 0, 15, …, 150 in each tank.
        assert_eq!(rows.iter().filter(|r| r[0] == "left").count(), 11);
        assert_eq!(rows.iter().filter(|r| r[0] == "right").count(), 11);
        let polarization = column(&header, "polarization");
        let values: Vec<&str> = rows.iter().map(|r| r[polarization]).collect();
        assert!(values.windows(2).any(|w| w[0] != w[1]), "{values:?}");
        // The table is the one shoal.metrics_csv() gives.
        assert!(export.text.ends_with(&lab.metrics_csv()));
    }

    #[test]
    fn the_aquarium_exports_its_metrics_under_its_own_name() {
        let mut lab = Lab::new(Settings {
            scene: Scene::Aquarium,
            ..Settings::default()
        });
        lab.step(90);
        let export = scene_csv(&lab);
        check_header(&export, &lab);
        assert_eq!(export.name, "shoal-aquarium-t0001s.csv");
        let (_, rows) = table(&export.text);
        assert_eq!(rows.len(), 7, "samples at 0, 15, …, 90 steps");
    }

    fn physics_lab(selected: Option<u32>) -> Lab {
        let mut settings = Settings {
            scene: Scene::Physics,
            seed: 3,
            ..Settings::default()
        };
        settings.physics.fish_count = 4;
        settings.physics.selected = selected;
        Lab::new(settings)
    }

    #[test]
    fn the_physics_file_has_the_selected_fishs_twelve_muscles_and_speed() {
        let mut lab = physics_lab(Some(1));
        lab.step(100);
        let export = scene_csv(&lab);
        check_header(&export, &lab);
        assert_eq!(export.name, "shoal-physics-t0005s.csv");
        let selected_line = export.text.lines().find(|l| l.starts_with("# selected: "));
        let length = lab.runs()[0].scene().physics().unwrap().animals()[1].body_length_m();
        assert_eq!(
            selected_line,
            Some(format!("# selected: fish 1 (body length {length:.2} m)").as_str())
        );
        let (header, rows) = table(&export.text);
        assert_eq!(header.len(), 2 + MUSCLE_COUNT);
        assert_eq!(&header[..2], &["time_s", "speed_m_per_s"]);
        let names: Vec<String> = muscle_columns().into();
        assert_eq!(
            header[2..],
            names.iter().map(String::as_str).collect::<Vec<_>>()[..]
        );
        for part in ["front", "middle", "tail"] {
            for side in ["left", "right"] {
                for level in ["top", "bottom"] {
                    let name = format!("{part}_{side}_{level}");
                    assert!(names.contains(&name), "{name}");
                }
            }
        }
        // One row per step of the trace (the last 10 s: 100 steps of 0.055 s).
        assert_eq!(rows.len(), lab.runs()[0].body_trace().len());
        assert_eq!(rows.len(), 100);
        let number = |s: &str| s.parse::<f32>().unwrap();
        // While it swims its muscles pull, and the tail beats: a muscle
        // value changes from row to row.
        let most = rows
            .iter()
            .flat_map(|r| r[2..].iter().map(|&s| number(s)))
            .fold(0.0_f32, f32::max);
        assert!(most > 0.1, "the muscles rest all the time: {most}");
        let tail = column(&header, "tail_left_top");
        assert!(rows.windows(2).any(|w| w[0][tail] != w[1][tail]));
        assert!(rows.iter().all(|r| (0.0..=1.0).contains(&number(r[tail]))));
        let speed = column(&header, "speed_m_per_s");
        assert!(rows.iter().any(|r| number(r[speed]) > 0.01));
    }

    #[test]
    fn with_no_fish_selected_the_physics_file_says_so_and_gives_the_school() {
        let mut lab = physics_lab(None);
        lab.step(40);
        let export = scene_csv(&lab);
        check_header(&export, &lab);
        assert!(export.text.contains("# no fish selected: click a fish"));
        let (header, rows) = table(&export.text);
        assert_eq!(header.join(",") + "\n", PHYSICS_SCHOOL_HEADER);
        // Samples at 0, 5, …, 40 steps.
        assert_eq!(rows.len(), 9);
        let speed = column(&header, "mean_speed_m_per_s");
        assert!(rows.windows(2).any(|w| w[0][speed] != w[1][speed]));
    }

    /// The predator demo on point-mass bodies, with the shark selected.
    fn reef_lab() -> Lab {
        let mut settings = Settings {
            scene: Scene::Reef,
            seed: 2,
            ..Settings::default()
        };
        settings.reef.demo = crate::sim::reef::demos::ReefScene::PredatorAndSchool;
        settings.reef.body = crate::sim::reef::world::ReefBodyKind::PointMass;
        let mut lab = Lab::new(settings);
        let shark = lab.runs()[0]
            .scene()
            .reef()
            .unwrap()
            .animals()
            .iter()
            .position(|a| a.habits.kind == crate::sim::reef::mind::FishKind::Predator)
            .expect("a shark");
        let mut settings = lab.settings().clone();
        settings.reef.selected = Some(shark as u32);
        lab.apply_settings(settings);
        lab
    }

    #[test]
    fn the_reef_file_has_counts_over_time_events_and_the_selected_fishs_mind() {
        let mut lab = reef_lab();
        lab.step(640);
        let export = scene_csv(&lab);
        check_header(&export, &lab);
        assert_eq!(export.name, "shoal-reef-t0035s.csv");
        let text = &export.text;
        assert!(
            text.contains("# demo: Predator and school; body: points"),
            "{text}"
        );
        let (header, rows) = table(text);
        assert_eq!(header.join(",") + "\n", REEF_HEADER);
        let of =
            |table: &str| -> Vec<&Vec<&str>> { rows.iter().filter(|r| r[0] == table).collect() };
        let (counts, events, minds) = (of("counts"), of("event"), of("mind"));
        assert_eq!(counts.len() + events.len() + minds.len(), rows.len());
        // Counts: one row per sample (every 5 steps, the first at the start).
        assert_eq!(counts.len(), 129);
        let reef = lab.runs()[0].scene().reef().unwrap();
        let last = counts.last().unwrap();
        let census = reef.census();
        assert_eq!(last[column(&header, "prey_alive")], census.prey.to_string());
        assert_eq!(last[column(&header, "predators_alive")], "1");
        assert_eq!(
            last[column(&header, "prey_eaten")],
            census.counts.prey_eaten.to_string()
        );
        // The run shows in the numbers: the plankton drifts, is eaten or the
        // prey are; some column of the counts changes over the run.
        let first = counts.first().unwrap();
        assert!(first[2..12] != last[2..12], "{first:?} {last:?}");
        // Events: the log, with its kind and text (quoted: texts hold commas).
        assert_eq!(events.len(), reef.events().len());
        assert!(!events.is_empty(), "something happened in 35 s");
        let kind = column(&header, "event_kind");
        let text_col = column(&header, "event_text");
        for (row, e) in events.iter().zip(reef.events()) {
            assert_eq!(row[kind], e.kind.name());
            assert_eq!(row[text_col], format!("\"{}\"", e.text));
        }
        // Mind: the selected shark's history, hunger rising as it digests.
        let index = lab.settings().reef.selected.unwrap() as usize;
        let shark = &reef.animals()[index];
        assert!(text.contains(&format!("# selected: shark {index}\n")));
        assert_eq!(minds.len(), shark.history.len());
        assert!(minds.len() >= 60, "{}", minds.len());
        let animals: Vec<&str> = minds.iter().map(|r| r[column(&header, "animal")]).collect();
        assert!(
            animals.iter().all(|&a| a == format!("shark {index}")),
            "{animals:?}"
        );
        let intentions: Vec<&str> = minds
            .iter()
            .map(|r| r[column(&header, "intention")])
            .collect();
        assert!(
            intentions
                .iter()
                .all(|i| crate::sim::reef::mind::Intention::ALL
                    .iter()
                    .any(|k| k.label() == *i)),
            "{intentions:?}"
        );
        let hunger = column(&header, "hunger");
        assert!(minds.windows(2).any(|w| w[0][hunger] != w[1][hunger]));
    }

    #[test]
    fn with_no_fish_selected_the_reef_file_says_so_and_has_no_mind_rows() {
        let mut lab = reef_lab();
        let mut settings = lab.settings().clone();
        settings.reef.selected = None;
        lab.apply_settings(settings);
        lab.step(50);
        let export = scene_csv(&lab);
        check_header(&export, &lab);
        assert!(export.text.contains("# no fish selected: click a fish"));
        let (_, rows) = table(&export.text);
        assert!(rows.iter().all(|r| r[0] != "mind"));
        assert_eq!(rows.iter().filter(|r| r[0] == "counts").count(), 11);
    }

    #[test]
    fn the_learning_file_has_the_objective_history_and_the_finished_drills() {
        let mut settings = Settings {
            scene: Scene::Learning,
            seed: 4,
            ..Settings::default()
        };
        settings.learning.annealing_steps = 90;
        let mut lab = Lab::new(settings);
        // The first drill (90 steps) and 20 of the second.
        lab.train(110).unwrap();
        lab.step(20);
        let export = scene_csv(&lab);
        check_header(&export, &lab);
        assert_eq!(export.name, "shoal-learning-t0001s.csv");
        assert!(
            export.text.contains("drill 2 of 7 in training"),
            "{}",
            export.text
        );
        let (header, rows) = table(&export.text);
        assert_eq!(header.join(",") + "\n", LEARNING_HEADER);
        let training: Vec<&Vec<&str>> = rows.iter().filter(|r| r[0] == "training").collect();
        let finished: Vec<&Vec<&str>> = rows.iter().filter(|r| r[0] == "finished").collect();
        assert_eq!(training.len() + finished.len(), rows.len());
        // The random start and 20 steps.
        let trainer = lab.runs()[0].scene().learning().unwrap().trainer();
        assert_eq!(training.len(), trainer.history().len());
        assert_eq!(training.len(), 21);
        assert!(training.iter().all(|r| r[1] == "2"));
        let best = column(&header, "best_objective");
        let number = |s: &str| s.parse::<f64>().unwrap();
        // The best E never rises, and the current one moves.
        assert!(
            training
                .windows(2)
                .all(|w| number(w[1][best]) <= number(w[0][best]))
        );
        let current = column(&header, "current_objective");
        assert!(training.windows(2).any(|w| w[0][current] != w[1][current]));
        assert!(training.windows(2).any(|w| {
            w[0][column(&header, "temperature")] != w[1][column(&header, "temperature")]
        }));
        // The first drill, learned.
        assert_eq!(finished.len(), 1);
        let drill = finished[0];
        assert_eq!(drill[1], "1");
        assert_eq!(drill[2], "\"swim as far as it can\"");
        assert_eq!(drill[column(&header, "annealing_steps")], "90");
        let objective = number(drill[column(&header, "objective")]);
        let learned = &lab.runs()[0].scene().learning().unwrap().finished_drills()[0];
        assert!((objective - f64::from(learned.objective)).abs() < 1e-5);
        let energy = number(drill[column(&header, "energy_in_two_modes")]);
        assert!(energy > 0.0 && energy <= 1.0, "{energy}");
    }
}
