//! The experiment engine's tests: validation names the field, the run order and
//! shards, a run is the interactive run, determinism, the CSV and its merge.

use serde_json::{Value, json};

use crate::experiment::design::{Design, DesignError, MAX_RUNS, Measure, Plan, Summary};

const _: () = assert!(MAX_RUNS == 10_000, "the refusal below quotes it");
use crate::experiment::runner::{Experiment, ExperimentRun, RunResult};
use crate::experiment::{experiment_csv, merge_csv, summarise};
use crate::lab::Lab;
use crate::settings::{Scene, Settings};

/// A small schooling-lab design: 12 fish and a shark, alignment 20 and 60, two
/// seeds, 0.5 s warm-up, 1 s measured.
fn tiny() -> Value {
    json!({
        "name": "tiny",
        "settings": {"scene": "boids", "left": {"preset": "group", "fish_count": 12, "sharks": 1}},
        "factors": [{"key": "left.alignment", "levels": [20, 60]}],
        "replicates": {"count": 2, "first_seed": 5},
        "warmup_secs": 0.5,
        "measure_secs": 1.0,
        "measures": [
            {"measure": "polarization"},
            {"measure": "catches", "summary": "final"},
            {"measure": "nnd_body_lengths", "summary": "series"}
        ]
    })
}

fn plan_of(value: &Value) -> Result<Plan, DesignError> {
    Design::from_json(&value.to_string())?.validate()
}

fn refused(value: &Value) -> DesignError {
    plan_of(value).expect_err("the design is refused")
}

fn run_all(plan: &Plan) -> Vec<RunResult> {
    plan.runs()
        .iter()
        .map(|spec| ExperimentRun::new(plan, spec).run_to_end())
        .collect()
}

#[test]
fn every_refusal_names_its_field() {
    let cases: Vec<(Value, &str, &str)> = vec![
        (
            json!({"factors": [{"key": "left.alignmnt", "levels": [1]}]}),
            "factors[0].key",
            "alignmnt",
        ),
        (
            json!({"factors": [{"key": "left.alignment", "levels": [20, 150]}]}),
            "factors[0].levels[1]",
            "out of range",
        ),
        (
            json!({"factors": [{"key": "left.alignment", "levels": {"from": 0, "to": 200, "steps": 3}}]}),
            "factors[0].levels",
            "200 is out of range",
        ),
        (
            json!({"factors": [{"key": "left.fish_count", "levels": [10, 2.5]}]}),
            "factors[0].levels[1]",
            "wrong type",
        ),
        (
            json!({"factors": [{"key": "left.alignment", "levels": [true]}]}),
            "factors[0].levels[0]",
            "numbers",
        ),
        (
            json!({"factors": [{"key": "left.alignment", "levels": []}]}),
            "factors[0].levels",
            "no levels",
        ),
        (
            json!({"factors": [{"key": "left.alignment", "levels": {"from": 0, "to": 1, "steps": 0}}]}),
            "factors[0].levels.steps",
            "no levels",
        ),
        (
            json!({"factors": [{"key": "right.alignment", "levels": [1]}]}),
            "factors[0].key",
            "does not act",
        ),
        (
            json!({"factors": [{"key": "seed", "levels": [1]}]}),
            "factors[0].key",
            "replicates",
        ),
        (
            json!({"factors": [{"key": "left.selected", "levels": [1, 2]}]}),
            "factors[0].key",
            "chooses the fish shown",
        ),
        (
            json!({"factors": [{"key": "left.mode", "levels": [1]}]}),
            "factors[0].key",
            "not a number",
        ),
        (
            json!({"factors": [{"key": "left.cohesion", "levels": [1]}, {"key": "left.cohesion", "levels": [2]}]}),
            "factors[1].key",
            "already",
        ),
        (
            json!({"replicates": {"count": 0}}),
            "replicates.count",
            "no replicates",
        ),
        (
            json!({"replicates": {"seeds": [3, 4, 3]}}),
            "replicates.seeds[2]",
            "twice",
        ),
        (json!({"replicates": {}}), "replicates", "how many"),
        (
            json!({"measures": [{"measure": "polarization"}, {"measure": "spawnings"}]}),
            "measures[1].measure",
            "not measured in the Schooling lab",
        ),
        (
            json!({"measures": [{"measure": "happiness"}]}),
            "measures[0].measure",
            "unknown measure",
        ),
        (
            json!({"measures": [{"measure": "milling", "summary": "median"}]}),
            "measures[0].summary",
            "unknown summary",
        ),
        (json!({"measures": []}), "measures", "nothing to measure"),
        (
            json!({"measure_secs": 0}),
            "measure_secs",
            "measures nothing",
        ),
        (
            json!({"measure_secs": 0.1}),
            "measure_secs",
            "no metrics sample",
        ),
        (json!({"warmup_secs": -1}), "warmup_secs", "out of range"),
        (
            json!({"settings": {"left": {"cohesion": 101}}}),
            "settings.left.cohesion",
            "out of range",
        ),
        (json!({"link": "#v2.abc"}), "link", "version"),
        (
            json!({
                "factors": [{"key": "left.cohesion", "levels": {"from": 0, "to": 100, "steps": 1000}}],
                "replicates": {"count": 11}
            }),
            "factors",
            "at most 10000",
        ),
    ];
    for (change, field, words) in cases {
        let mut design = tiny();
        for (k, v) in change.as_object().unwrap() {
            design[k] = v.clone();
        }
        let err = refused(&design);
        assert_eq!(err.field, field, "{change}: {err}");
        assert!(err.to_string().contains(words), "{change}: {err}");
    }
    // The reef has spawnings; the learning lab has no school.
    let mut reef = tiny();
    reef["settings"] = json!({"scene": "reef"});
    reef["factors"] = json!([{"key": "reef.prey_count", "levels": [4, 8]}]);
    reef["measures"] = json!([{"measure": "spawnings", "summary": "final"}]);
    assert!(plan_of(&reef).is_ok());
    reef["settings"] = json!({"scene": "learning"});
    reef["factors"] = json!([]);
    reef["measures"] = json!([{"measure": "polarization"}]);
    assert_eq!(refused(&reef).field, "measures[0].measure");
    // An unknown field of the file is named by the JSON reader.
    let mut typo = tiny();
    typo["warmup_sec"] = json!(1);
    let err = refused(&typo);
    assert_eq!(err.field, "warmup_sec", "{err}");
    let mut missing = tiny();
    missing.as_object_mut().unwrap().remove("replicates");
    assert_eq!(refused(&missing).field, "replicates");
    let err = Design::from_json("{\"name\": 3}").unwrap_err();
    assert_eq!(err.field, "(file, line 1, column 10)", "{err}");
}

#[test]
fn runs_come_in_a_fixed_order_and_shards_hold_each_run_once() {
    let mut design = tiny();
    design["factors"] = json!([
        {"key": "left.alignment", "levels": {"from": 0, "to": 100, "steps": 3}},
        {"key": "left.sharks", "levels": [0, 2]}
    ]);
    design["replicates"] = json!({"seeds": [9, 4]});
    let plan = plan_of(&design).unwrap();
    let runs = plan.runs();
    assert_eq!(runs.len(), 12);
    assert_eq!(plan.run_count(), 12);
    let listed: Vec<(String, u64)> = runs
        .iter()
        .map(|r| {
            let levels: Vec<String> = r.levels.iter().map(ToString::to_string).collect();
            (levels.join("/"), r.seed)
        })
        .collect();
    let expected: Vec<(String, u64)> = [
        "0.0/0", "0.0/0", "0.0/2", "0.0/2", "50.0/0", "50.0/0", "50.0/2", "50.0/2", "100.0/0",
        "100.0/0", "100.0/2", "100.0/2",
    ]
    .iter()
    .zip([9, 4].iter().cycle())
    .map(|(l, s)| ((*l).to_owned(), *s))
    .collect();
    assert_eq!(listed, expected);
    assert!(runs.iter().enumerate().all(|(k, r)| r.index == k));
    for shards in 1..=13 {
        let mut seen = vec![0; runs.len()];
        for shard in 0..shards {
            for run in plan.runs_for_shard(shard, shards) {
                assert_eq!(run, runs[run.index]);
                seen[run.index] += 1;
            }
        }
        assert!(seen.iter().all(|&n| n == 1), "{shards} shards: {seen:?}");
    }
    // An on/off factor, and base settings from a share link under a patch.
    let mut linked = Settings {
        scene: Scene::Physics,
        ..Settings::default()
    };
    linked.physics.fish_count = 3;
    // Steering by hand acts on the selected fish (without one it is refused).
    linked.physics.selected = Some(0);
    let mut physics = tiny();
    physics["link"] = json!(format!(
        "https://example.org/shoal/#{}",
        crate::settings::share_link::encode(&linked)
    ));
    physics["settings"] = json!({"physics": {"sharks": 0}});
    physics["factors"] = json!([{"key": "physics.hand_control", "levels": [false, true]}]);
    physics["measures"] = json!([{"measure": "mean_speed_m_per_s"}]);
    let plan_b = plan_of(&physics).unwrap();
    assert_eq!(plan_b.factors[0].levels, vec![json!(false), json!(true)]);
    assert_eq!(
        (plan_b.base.scene, plan_b.base.physics.fish_count),
        (Scene::Physics, 3)
    );
    assert!(plan_b.settings_for(&plan_b.runs()[2]).physics.hand_control);
    // The run's settings: the base, the levels, the seed.
    let s = plan.settings_for(&runs[7]);
    assert_eq!((s.left.alignment, s.left.sharks, s.seed), (50.0, 2, 4));
    assert_eq!(s.left.fish_count, 12);
}

#[test]
fn a_run_is_the_interactive_run_of_its_settings_and_seed() {
    let plan = plan_of(&tiny()).unwrap();
    let spec = &plan.runs()[3];
    assert_eq!((spec.levels[0].as_f64(), spec.seed), (Some(60.0), 6));
    // Sliced unevenly: the stops do not change the run.
    let mut run = ExperimentRun::new(&plan, spec);
    while !run.advance(7).done {}
    let result = run.finish();

    // By hand, as the page does it: shoal.set(...) with the same values, then
    // step; read the plots' samples.
    let mut settings = Settings::default();
    settings
        .apply_patch(&json!({
            "scene": "boids", "seed": 6,
            "left": {"preset": "group", "fish_count": 12, "sharks": 1, "alignment": 60}
        }))
        .unwrap();
    let mut lab = Lab::new(settings);
    lab.step(30); // 0.5 s warm-up
    let caught_before = lab.runs()[0].metrics().catches;
    let (mut times, mut polarization, mut nnd) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..4 {
        lab.step(15); // one sample every 15 steps
        let m = lab.runs()[0].metrics();
        times.push(m.time_secs);
        polarization.push(f64::from(m.polarization));
        nnd.push(f64::from(m.nnd_body_lengths));
    }
    let caught = (lab.runs()[0].metrics().catches - caught_before) as f64;
    assert_eq!(result.times_secs, times);
    assert_eq!(result.values[0], polarization);
    assert_eq!(result.mean(0), polarization.iter().sum::<f64>() / 4.0);
    assert_eq!(result.last(1), caught);
    assert_eq!(result.values[2], nnd);
    assert!(polarization.iter().all(|p| *p > 0.0 && *p <= 1.0));
}

#[test]
fn the_same_design_gives_the_same_bytes_and_shards_merge_to_them() {
    let plan = plan_of(&tiny()).unwrap();
    let full = experiment_csv(&plan, &run_all(&plan), None);
    let again = {
        let plan = plan_of(&tiny()).unwrap();
        let mut experiment = Experiment::new(plan);
        while !experiment.advance(50).done {}
        experiment.csv()
    };
    assert_eq!(full, again, "same design, same bytes");
    // Rows: 4 runs × (mean + final + 4 series samples).
    let rows: Vec<&str> = full.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(rows.len(), 1 + 4 * 6);
    assert!(
        rows[0].starts_with(
            "run,seed,left.alignment,measure,summary,time_s,value,scene,left.avoidance,"
        ),
        "{}",
        rows[0]
    );
    assert!(
        rows[1].starts_with("0,5,20.0,polarization,mean,,0."),
        "{}",
        rows[1]
    );
    assert!(full.contains("\n0,5,20.0,nnd_body_lengths,series,0.750,"));
    assert!(full.lines().any(|l| l.starts_with("# design: {")));
    // Every row has every column.
    let columns = rows[0].split(',').count();
    assert!(rows.iter().all(|r| r.split(',').count() == columns));

    // Two shards, merged in either order, give the full file.
    let shard = |i: usize| {
        let results: Vec<RunResult> = plan
            .runs_for_shard(i, 2)
            .iter()
            .map(|spec| ExperimentRun::new(&plan, spec).run_to_end())
            .collect();
        (
            format!("shard{i}.csv"),
            experiment_csv(&plan, &results, Some((i, 2))),
        )
    };
    let (a, b) = (shard(0), shard(1));
    assert!(a.1.contains("# shard: 0/2"));
    assert_eq!(merge_csv(&[a.clone(), b.clone()]).unwrap(), full);
    assert_eq!(merge_csv(&[b.clone(), a.clone()]).unwrap(), full);
    // A gap and a duplicate are refused, naming the runs.
    let err = merge_csv(std::slice::from_ref(&a)).unwrap_err().to_string();
    assert!(err.contains("run(s) 1, 3 are in no file"), "{err}");
    let err = merge_csv(&[a.clone(), b.clone(), a.clone()])
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("run(s) 0, 2 appear in more than one file"),
        "{err}"
    );
    // Another experiment's file is refused.
    let mut other = tiny();
    other["warmup_secs"] = json!(1.0);
    let other_plan = plan_of(&other).unwrap();
    let c = (
        "other.csv".to_owned(),
        experiment_csv(&other_plan, &[], None),
    );
    let err = merge_csv(&[a, c]).unwrap_err().to_string();
    assert!(err.contains("other.csv: a different experiment"), "{err}");
}

#[test]
fn a_cancelled_experiment_keeps_its_completed_runs() {
    let plan = plan_of(&tiny()).unwrap();
    let per_run = plan.steps_per_run();
    let mut experiment = Experiment::new(plan.clone());
    let progress = experiment.advance(per_run * 2 + 10);
    assert_eq!((progress.runs_done, progress.runs_total), (2, 4));
    assert_eq!(progress.steps_done, per_run * 2 + 10);
    assert!(!progress.done);
    let csv = experiment.csv();
    assert!(csv.contains("# completed: 2 of 4 runs"), "{csv}");
    let full = experiment_csv(&plan, &run_all(&plan), None);
    let rows = |text: &str| -> Vec<String> {
        text.lines()
            .filter(|l| !l.starts_with('#'))
            .map(str::to_owned)
            .collect()
    };
    let (kept, all) = (rows(&csv), rows(&full));
    assert_eq!(kept.len(), 1 + 2 * 6);
    assert_eq!(kept[..], all[..kept.len()], "the completed runs' rows");
}

#[test]
fn the_summary_gives_the_mean_and_an_interval_within_the_measured_values() {
    let plan = plan_of(&tiny()).unwrap();
    let fake = |index: usize, level: f64, polar: f64, caught: f64| RunResult {
        index,
        seed: 5 + index as u64 % 2,
        levels: vec![json!(level)],
        times_secs: vec![0.75, 1.0],
        values: vec![vec![polar, polar], vec![0.0, caught], vec![1.0, 1.0]],
    };
    let results = [
        fake(0, 20.0, 0.2, 1.0),
        fake(1, 20.0, 0.4, 3.0),
        fake(2, 60.0, 0.9, 0.0),
    ];
    let rows = summarise(&plan, &results);
    assert_eq!(rows.len(), 2 * 3);
    let polar = &rows[0];
    assert_eq!(
        (polar.measure, polar.summary, polar.n),
        (Measure::Polarization, Summary::Mean, 2)
    );
    assert!((polar.mean - 0.3).abs() < 1e-12);
    // Two seeds, 0.2 and 0.4: the bootstrap's means are 0.2, 0.3 or 0.4, so
    // the interval is [0.2, 0.4] (the t interval was [-0.97, 1.57], outside
    // what a polarization can be).
    assert_eq!((polar.ci95_low, polar.ci95_high), (0.2, 0.4), "{polar:?}");
    assert_eq!((rows[1].measure, rows[1].mean), (Measure::Catches, 2.0));
    assert_eq!(rows[3].n, 1);
    assert!(rows[3].sd.is_nan());
    // For the page: names, and null for "no interval".
    let js = serde_json::to_value(&rows[3]).unwrap();
    assert_eq!(js["measure"], "polarization");
    assert_eq!(js["summary"], "mean");
    assert_eq!(
        (js["levels"].clone(), js["sd"].clone()),
        (json!([60.0]), Value::Null)
    );
}

#[test]
fn the_estimate_counts_runs_steps_and_animals() {
    let plan = plan_of(&tiny()).unwrap();
    let e = plan.estimate();
    assert_eq!((e.runs, e.steps_per_run, e.total_steps), (4, 90, 360));
    // 12 fish and a shark in each run.
    assert_eq!(e.animal_steps, 13.0 * 360.0);
    assert!(e.secs_one_core > 0.0 && e.secs_one_core < 1.0);
    assert_eq!(plan.base.scene, Scene::Boids);
}
