//! The app's time-slicing gives the same runs as the engine run in one go, and
//! the browser test's experiment gives the committed CSV.

use crate::experiment::session::{ExperimentSession, steps_for_budget};
use crate::experiment::{Design, Experiment, Plan, design::factor_keys};
use crate::settings::{Scene, Settings};

const TINY_PATH: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/web/tests/fixtures/experiment-tiny.json"
);

fn tiny_plan() -> Plan {
    let text = std::fs::read_to_string(TINY_PATH).expect("the fixture design");
    Design::from_json(&text)
        .and_then(|d| d.validate())
        .expect("the fixture design is valid")
}

fn run_in_one_go(plan: Plan) -> String {
    let mut experiment = Experiment::new(plan);
    assert!(experiment.advance(u64::MAX).done);
    experiment.csv()
}

#[test]
fn slices_of_any_size_give_the_csv_of_one_go() {
    let mut plan = tiny_plan();
    // Smaller, for a quick test: 12 fish, 1 s warm-up, 1 s measured.
    plan = Design {
        settings: Some(
            serde_json::json!({"scene": "boids", "left": {"preset": "group", "fish_count": 12}}),
        ),
        warmup_secs: 1.0,
        measure_secs: 1.0,
        ..plan.design.clone()
    }
    .validate()
    .expect("valid");
    let expected = run_in_one_go(plan.clone());
    // The app's slice, with a tiny wall budget: a few steps a frame.
    let mut session = ExperimentSession::new(plan.clone(), 1e-3);
    let mut frames = 0;
    let mut now = 0.0;
    while session.running() {
        session.slice(2e-5, now);
        now += 1.0 / 60.0;
        frames += 1;
        assert!(frames < 1_000_000, "the experiment ends");
    }
    assert!(frames > 4, "it took several slices ({frames})");
    assert_eq!(session.experiment().csv(), expected);
    // Odd fixed slices, crossing the runs' and the samples' boundaries.
    for n in [1, 7, 61, 1000] {
        let mut session = ExperimentSession::new(plan.clone(), 0.0);
        while session.running() {
            session.advance(n);
        }
        assert_eq!(session.experiment().csv(), expected, "slices of {n}");
    }
    let report = session.report();
    assert!(!report.running && !report.cancelled);
    assert_eq!(report.runs_done, 4);
    assert_eq!(report.csv.as_deref(), Some(expected.as_str()));
    assert_eq!(report.summary.expect("summary").len(), 2 * 2);
}

#[test]
fn a_cancelled_session_keeps_its_completed_runs() {
    let plan = tiny_plan();
    let mut session = ExperimentSession::new(plan.clone(), 0.0);
    session.advance(plan.steps_per_run() + 3);
    session.cancel();
    assert!(!session.running());
    let before = session.progress();
    session.slice(1.0, 0.0);
    assert_eq!(
        session.progress(),
        before,
        "a cancelled session does nothing"
    );
    let report = session.report();
    assert!(report.cancelled);
    assert_eq!(report.runs_done, 1);
    let csv = report.csv.expect("the CSV of the completed run");
    assert!(csv.contains("# completed: 1 of 4 runs"), "{csv}");
}

#[test]
fn the_budget_sets_the_steps_of_a_slice() {
    assert_eq!(steps_for_budget(0.015, 0.001), 15);
    assert_eq!(steps_for_budget(0.015, 1.0), 1);
    assert_eq!(steps_for_budget(0.015, 0.0), 1);
    assert_eq!(steps_for_budget(0.015, 1e-12), 100_000);
}

#[test]
fn the_schooling_lab_offers_its_urges_and_not_what_the_engine_refuses() {
    let settings = Settings {
        scene: Scene::Boids,
        ..Settings::default()
    };
    let keys = factor_keys(&settings);
    for key in ["left.alignment", "left.fish_count"] {
        assert!(keys.iter().any(|k| k == key), "{key} in {keys:?}");
    }
    for key in &keys {
        assert!(key.starts_with("left."), "{key}");
    }
    assert!(
        !keys
            .iter()
            .any(|k| k == "seed" || k == "speed" || k.starts_with("right."))
    );
}

/// The browser test's fixture `name` (`web/tests/fixtures/experiment-{name}.json`)
/// run in one go gives the committed `experiment-{name}.csv`; the browser test
/// compares its own CSV with the same file, byte for byte.
/// `SHOAL_WRITE_FIXTURES=1` rewrites it (after a deliberate change of the runs).
fn check_fixture(name: &str) {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/web/tests/fixtures");
    let design = std::fs::read_to_string(format!("{dir}/experiment-{name}.json"))
        .expect("the fixture design");
    let plan = Design::from_json(&design)
        .and_then(|d| d.validate())
        .expect("the fixture design is valid");
    let csv = run_in_one_go(plan);
    let csv_path = format!("{dir}/experiment-{name}.csv");
    if std::env::var("SHOAL_WRITE_FIXTURES").is_ok_and(|v| v == "1") {
        std::fs::write(&csv_path, &csv).expect("write the fixture");
        return;
    }
    let committed = std::fs::read_to_string(&csv_path)
        .expect("the committed CSV (SHOAL_WRITE_FIXTURES=1 writes it)");
    assert_eq!(
        csv, committed,
        "the runs changed: if on purpose, rewrite with SHOAL_WRITE_FIXTURES=1"
    );
}

/// The schooling lab's tiny design (`experiment-tiny`).
#[test]
fn the_browser_tests_experiment_gives_the_committed_csv() {
    check_fixture("tiny");
}

/// The window speaks Spanish, the CSV does not: the tiny design run with the
/// interface in Spanish gives the committed file, byte for byte, its columns
/// and measures the codes programs read (`left.alignment`,
/// `nnd_body_lengths`), never the words on screen.
#[test]
fn the_csv_keeps_the_codes_whatever_the_window_speaks() {
    use crate::i18n::{Lang, with_lang};
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/web/tests/fixtures");
    let committed =
        std::fs::read_to_string(format!("{dir}/experiment-tiny.csv")).expect("the committed CSV");
    let csv = with_lang(Lang::Es, || run_in_one_go(tiny_plan()));
    assert_eq!(csv, committed, "the same bytes in Spanish");
    let plan = tiny_plan();
    let header = csv
        .lines()
        .find(|l| !l.starts_with('#'))
        .expect("a header line");
    for factor in &plan.factors {
        assert!(header.contains(&factor.key), "{header}");
    }
    for (measure, _) in &plan.measures {
        assert!(
            csv.contains(&format!(",{},", measure.name())),
            "{}",
            measure.name()
        );
        with_lang(Lang::Es, || assert!(!csv.contains(measure.label())));
    }
}

/// The physics tank's design (`experiment-physics`): muscle bodies, the
/// current, glam's rotations, the distance swum, the same bytes in the browser.
#[test]
fn the_browser_tests_physics_experiment_gives_the_committed_csv() {
    check_fixture("physics");
}

#[test]
fn a_slow_page_gives_the_runs_half_its_own_frame_time_and_a_fast_one_15_ms() {
    use crate::experiment::session::{FRAME_BUDGET_SECS, MAX_FRAME_BUDGET_SECS, frame_budget_secs};
    // A laptop with a GPU (60 and 30 frames a second): the 15 ms slice.
    assert_eq!(frame_budget_secs(1.0 / 60.0), FRAME_BUDGET_SECS);
    assert_eq!(frame_budget_secs(0.0), FRAME_BUDGET_SECS);
    assert!((frame_budget_secs(1.0 / 30.0) - 1.0 / 60.0).abs() < 1e-12);
    // A software renderer at 4 frames a second: half its 250 ms.
    assert!((frame_budget_secs(0.25) - 0.125).abs() < 1e-12);
    // Never more than a quarter of a second, and nothing odd from a clock.
    assert_eq!(frame_budget_secs(5.0), MAX_FRAME_BUDGET_SECS);
    assert_eq!(frame_budget_secs(f64::NAN), FRAME_BUDGET_SECS);
    assert_eq!(frame_budget_secs(-1.0), FRAME_BUDGET_SECS);
}
