//! Experiments in the physics fish tank and the reef (issue 16): a factor of the
//! scene changes what is measured, the same seed gives the same values, the
//! distance swum adds up the fish's speed, a measure the scene does not have is
//! refused by name, and the example files in `experiments/` are valid.

use serde_json::{Value, json};

use crate::experiment::design::{Design, DesignError, Measure, Plan};
use crate::experiment::runner::{ExperimentRun, RunResult};
use crate::settings::Scene;

fn plan_of(value: &Value) -> Result<Plan, DesignError> {
    Design::from_json(&value.to_string())?.validate()
}

fn run_all(plan: &Plan) -> Vec<RunResult> {
    plan.runs()
        .iter()
        .map(|spec| ExperimentRun::new(plan, spec).run_to_end())
        .collect()
}

/// The index of `measure` in the plan.
fn column(plan: &Plan, measure: Measure) -> usize {
    plan.measures
        .iter()
        .position(|&(m, _)| m == measure)
        .expect("the plan measures it")
}

/// Three physics fish, no shark, the current at 0 and at 0.3 m/s, one seed.
fn physics_design() -> Value {
    json!({
        "name": "physics-current",
        "settings": {"scene": "physics", "physics": {"fish_count": 3, "sharks": 0}},
        "factors": [{"key": "physics.current_m_per_s", "levels": [0.0, 0.3]}],
        "replicates": {"seeds": [4]},
        "warmup_secs": 1.0,
        "measure_secs": 3.0,
        "measures": [
            {"measure": "mean_speed_m_per_s", "summary": "mean"},
            {"measure": "distance_swum_m", "summary": "final"},
            {"measure": "distance_swum_m", "summary": "series"}
        ]
    })
}

/// A small reef of point-mass fish: 3 or 8 prey, one seed.
fn reef_design() -> Value {
    json!({
        "name": "reef-prey",
        "settings": {"scene": "reef", "reef": {"body": "point_mass", "prey_count": 3, "food_count": 10}},
        "factors": [{"key": "reef.prey_count", "levels": [3, 8]}],
        "replicates": {"seeds": [2]},
        "warmup_secs": 1.0,
        "measure_secs": 4.0,
        "measures": [
            {"measure": "distance_swum_m", "summary": "final"},
            {"measure": "mean_speed_m_per_s", "summary": "mean"},
            {"measure": "prey_alive", "summary": "final"},
            {"measure": "food_eaten", "summary": "final"}
        ]
    })
}

/// The distance swum, summed step by step, is about the mean of the speed
/// samples times the window (the samples are 0.275 s apart, so not exactly).
fn assert_distance_follows_speed(plan: &Plan, run: &RunResult) {
    let window_secs = plan.measure_steps as f64 * plan.base.scene.class().facts().clock.step_secs;
    let distance = run.last(column(plan, Measure::DistanceSwum));
    let from_speed = run.mean(column(plan, Measure::MeanSpeed)) * window_secs;
    assert!(
        distance > 0.0,
        "run {}: the fish swam ({distance} m)",
        run.index
    );
    assert!(
        (distance - from_speed).abs() <= 0.25 * from_speed,
        "run {}: {distance} m swum, {from_speed} m from the sampled speed",
        run.index
    );
    // A distance only grows.
    let series = &run.values[column(plan, Measure::DistanceSwum)];
    assert!(series.windows(2).all(|w| w[1] >= w[0]), "{series:?}");
}

#[test]
fn a_physics_factor_changes_the_measures_and_the_seed_repeats_them() {
    let plan = plan_of(&physics_design()).expect("a valid physics design");
    assert_eq!(plan.base.scene, Scene::Physics);
    let first = run_all(&plan);
    assert_eq!(first.len(), 2);
    let speed = column(&plan, Measure::MeanSpeed);
    let distance = column(&plan, Measure::DistanceSwum);
    assert_ne!(
        first[0].mean(speed),
        first[1].mean(speed),
        "the current changes the speed"
    );
    assert_ne!(first[0].last(distance), first[1].last(distance));
    for run in &first {
        assert_distance_follows_speed(&plan, run);
    }
    assert_eq!(run_all(&plan), first, "the same seed, the same values");
}

#[test]
fn a_reef_factor_changes_the_measures_and_the_seed_repeats_them() {
    let plan = plan_of(&reef_design()).expect("a valid reef design");
    assert_eq!(plan.base.scene, Scene::Reef);
    let first = run_all(&plan);
    let alive = column(&plan, Measure::PreyAlive);
    let distance = column(&plan, Measure::DistanceSwum);
    assert!(
        first[0].last(alive) <= 3.0 && first[1].last(alive) > 3.0,
        "3 or 8 prey"
    );
    assert_ne!(first[0].last(distance), first[1].last(distance));
    for run in &first {
        assert_distance_follows_speed(&plan, run);
    }
    assert_eq!(run_all(&plan), first, "the same seed, the same values");
}

#[test]
fn a_measure_the_scene_does_not_have_is_refused_by_name() {
    let mut design = physics_design();
    design["measures"] = json!([
        {"measure": "distance_swum_m"},
        {"measure": "spawnings", "summary": "final"}
    ]);
    let err = plan_of(&design).expect_err("the physics tank has no spawnings");
    assert_eq!(err.field, "measures[1].measure");
    assert!(err.to_string().contains("spawnings"), "{err}");
    assert!(
        err.to_string().contains("distance_swum_m"),
        "the scene's measures are listed: {err}"
    );

    let mut learning = physics_design();
    learning["settings"] = json!({"scene": "learning"});
    learning["factors"] = json!([]);
    learning["measures"] = json!([{"measure": "distance_swum_m"}]);
    assert_eq!(
        plan_of(&learning).expect_err("no school").field,
        "measures[0].measure"
    );
}

#[test]
fn the_example_experiments_are_valid() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/experiments");
    let mut scenes = Vec::new();
    for entry in std::fs::read_dir(dir).expect("experiments/") {
        let path = entry.expect("a file").path();
        if path.extension().is_some_and(|e| e == "json") {
            let text = std::fs::read_to_string(&path).expect("readable");
            let plan = Design::from_json(&text)
                .and_then(|d| d.validate())
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            scenes.push(plan.base.scene);
        }
    }
    assert!(
        scenes.contains(&Scene::Boids) && scenes.contains(&Scene::Physics),
        "{scenes:?}"
    );
}

#[test]
fn the_physics_tank_and_the_reef_offer_their_own_settings_as_factors() {
    use crate::experiment::design::factor_keys;
    use crate::settings::Settings;
    for (scene, wanted) in [
        (
            Scene::Physics,
            ["physics.fish_count", "physics.current_m_per_s"],
        ),
        (Scene::Reef, ["reef.prey_count", "reef.visibility_m"]),
    ] {
        let base = Settings {
            scene,
            ..Settings::default()
        };
        let keys = factor_keys(&base);
        eprintln!("{scene:?}: {keys:?}");
        for key in wanted {
            assert!(
                keys.iter().any(|k| k == key),
                "{scene:?} offers {key}: {keys:?}"
            );
        }
        let prefix = format!("{}.", scene.class().facts().settings_section);
        assert!(keys.iter().all(|k| k.starts_with(&prefix)), "{keys:?}");
    }
}
