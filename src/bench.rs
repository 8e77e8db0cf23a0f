//! The in-app benchmark (`?bench` in the browser): for several fish counts it
//! measures simulation throughput and the frame time with rendering, then reports a
//! table (console, on screen, and `shoal.state().bench`). Figures, not assertions.

use serde::Serialize;
use web_time::Instant;

use crate::lab::Lab;
use crate::settings::physics::PhysicsSettings;
use crate::settings::reef::ReefSettings;
use crate::settings::tank::{Preset, TankSettings};
use crate::settings::{Scene, Settings};

/// Scenes and fish counts the benchmark visits, in order: each scene's
/// [`crate::scenes::SceneFacts::bench_counts`].
pub fn phases() -> Vec<(Scene, u32)> {
    Scene::ALL
        .into_iter()
        .flat_map(|scene| {
            let counts = scene.class().facts().bench_counts;
            counts.iter().map(move |&n| (scene, n))
        })
        .collect()
}
/// Real seconds of rendered frames measured per fish count.
const FRAMES_PHASE_SECS: f64 = 3.0;
/// Real seconds of pure simulation stepping measured per fish count.
const SIM_PHASE_SECS: f64 = 0.5;

/// One row of results.
#[derive(Clone, Debug, Serialize)]
pub struct BenchRow {
    pub scene: &'static str,
    pub fish: u32,
    /// Simulation steps per second, stepping only (no drawing).
    pub sim_steps_per_sec: f64,
    /// `sim_steps_per_sec × fish`.
    pub fish_steps_per_sec: f64,
    /// Mean time between frames with rendering at 1× speed, milliseconds.
    pub frame_ms: f64,
    /// Mean CPU time of a frame (simulation, UI, frame building), milliseconds.
    pub cpu_frame_ms: f64,
}

/// Progress and results, as `shoal.state().bench` reports them.
#[derive(Clone, Debug, Serialize)]
pub struct BenchReport {
    pub done: bool,
    pub rows: Vec<BenchRow>,
    /// Learning lab: annealing evaluations (forward simulations of a 2.5 s
    /// swim, 45 body steps) per second, measured once all rows are done.
    pub annealing_evaluations_per_sec: Option<f64>,
    /// Experiments: the first runs of `experiments/alignment-sweep.json`, one
    /// after another on this thread, as fast as they go (no frame budget),
    /// measured once all rows are done.
    pub experiment: Option<ExperimentBench>,
}

/// Runs per second of an experiment on one thread, as `shoal-lab bench`
/// measures them natively.
#[derive(Clone, Debug, Serialize)]
pub struct ExperimentBench {
    pub name: String,
    pub runs: usize,
    pub steps_per_run: u64,
    pub runs_per_sec: f64,
    pub steps_per_sec: f64,
}

/// The experiment the benchmark times, and how many of its runs. Default: the
/// alignment sweep's first 3 runs (200 fish, 3,600 steps each; about half a
/// second each natively), enough to average over the start-up of a run.
const EXPERIMENT_DESIGN: &str = include_str!("../experiments/alignment-sweep.json");
const EXPERIMENT_RUNS: usize = 3;

/// Drives the benchmark one frame at a time.
pub struct Benchmark {
    /// The scenes and counts to visit ([`phases`]).
    phases: Vec<(Scene, u32)>,
    next: usize,
    phase_start_secs: Option<f64>,
    frames: u32,
    cpu_secs: f64,
    sim_steps_per_sec: f64,
    rows: Vec<BenchRow>,
    annealing_evaluations_per_sec: Option<f64>,
    experiment: Option<ExperimentBench>,
    /// Runs of the experiment to time ([`EXPERIMENT_RUNS`]; fewer in tests).
    experiment_runs: usize,
}

impl Default for Benchmark {
    fn default() -> Self {
        Self::new()
    }
}

impl Benchmark {
    pub fn new() -> Self {
        Self {
            phases: phases(),
            next: 0,
            phase_start_secs: None,
            frames: 0,
            cpu_secs: 0.0,
            sim_steps_per_sec: 0.0,
            rows: Vec::new(),
            annealing_evaluations_per_sec: None,
            experiment: None,
            experiment_runs: EXPERIMENT_RUNS,
        }
    }

    pub fn is_done(&self) -> bool {
        self.next >= self.phases.len()
    }

    pub fn report(&self) -> BenchReport {
        BenchReport {
            done: self.is_done(),
            rows: self.rows.clone(),
            annealing_evaluations_per_sec: self.annealing_evaluations_per_sec,
            experiment: self.experiment.clone(),
        }
    }

    /// Called once per frame, before the lab advances. `cpu_secs` is the previous
    /// frame's CPU time, when eframe knows it.
    pub fn frame(&mut self, lab: &mut Lab, now_secs: f64, cpu_secs: Option<f32>) {
        let Some(&(scene, fish)) = self.phases.get(self.next) else {
            return;
        };
        let Some(start) = self.phase_start_secs else {
            let mut settings = Settings {
                paused: false,
                speed: 1.0,
                scene,
                compare: false,
                show_vision: false,
                ..lab.settings().clone()
            };
            // The boid layer with the group preset; every other setting as a
            // teacher first finds it.
            settings.left = TankSettings::with_preset(Preset::Group);
            settings.physics = PhysicsSettings::default();
            settings.reef = ReefSettings::default();
            scene.class().set_animal_count(&mut settings, fish);
            lab.apply_settings(settings);
            self.sim_steps_per_sec = measure_steps_per_sec(lab);
            self.phase_start_secs = Some(now_secs);
            self.frames = 0;
            self.cpu_secs = 0.0;
            return;
        };
        self.frames += 1;
        self.cpu_secs += f64::from(cpu_secs.unwrap_or(0.0));
        let elapsed = now_secs - start;
        if elapsed >= FRAMES_PHASE_SECS {
            let frames = f64::from(self.frames.max(1));
            let row = BenchRow {
                scene: scene.name(),
                fish,
                sim_steps_per_sec: self.sim_steps_per_sec,
                fish_steps_per_sec: self.sim_steps_per_sec * f64::from(fish),
                frame_ms: elapsed * 1000.0 / frames,
                cpu_frame_ms: self.cpu_secs * 1000.0 / frames,
            };
            log::info!(
                "bench: {:>8} {:>6} fish | {:>9.0} steps/s | {:>12.0} fish-steps/s | frame {:>6.2} ms | cpu {:>6.2} ms",
                row.scene,
                row.fish,
                row.sim_steps_per_sec,
                row.fish_steps_per_sec,
                row.frame_ms,
                row.cpu_frame_ms
            );
            self.rows.push(row);
            self.next += 1;
            self.phase_start_secs = None;
            if self.is_done() {
                let rate = measure_annealing_per_sec();
                log::info!("bench: learning lab | {rate:>6.1} annealing evaluations/s");
                self.annealing_evaluations_per_sec = Some(rate);
                self.experiment = measure_experiment_runs_per_sec(self.experiment_runs);
                if let Some(e) = &self.experiment {
                    log::info!(
                        "bench: experiment {} | {} runs of {} steps | {:>6.3} runs/s | {:>9.0} steps/s",
                        e.name,
                        e.runs,
                        e.steps_per_run,
                        e.runs_per_sec,
                        e.steps_per_sec
                    );
                }
                lab.apply_settings(Settings::default());
            }
        }
    }
}

/// Annealing evaluations per second of the learning centre's benchmark trainer,
/// over about a second.
fn measure_annealing_per_sec() -> f64 {
    let mut trainer = crate::sim::learning::Trainer::benchmark();
    trainer.run_evaluations(2);
    let start = Instant::now();
    let mut n = 0u32;
    while start.elapsed().as_secs_f64() < 1.0 {
        trainer.run_evaluations(1);
        n += 1;
    }
    f64::from(n) / start.elapsed().as_secs_f64()
}

/// The first `runs` runs of the benchmark's experiment, one after another on
/// this thread (`None` if its design were refused: a bug the tests catch).
pub fn measure_experiment_runs_per_sec(runs: usize) -> Option<ExperimentBench> {
    use crate::experiment::{Design, ExperimentRun};
    let plan = Design::from_json(EXPERIMENT_DESIGN)
        .and_then(|d| d.validate())
        .map_err(|err| log::error!("bench experiment: {err}"))
        .ok()?;
    let mut specs = plan.runs();
    specs.truncate(runs);
    let start = Instant::now();
    for spec in &specs {
        ExperimentRun::new(&plan, spec).run_to_end();
    }
    let secs = start.elapsed().as_secs_f64().max(1e-9);
    Some(ExperimentBench {
        name: plan.design.name.clone(),
        runs: specs.len(),
        steps_per_run: plan.steps_per_run(),
        runs_per_sec: specs.len() as f64 / secs,
        steps_per_sec: (plan.steps_per_run() * specs.len() as u64) as f64 / secs,
    })
}

/// Steps the lab as fast as it goes for about `SIM_PHASE_SECS`.
fn measure_steps_per_sec(lab: &mut Lab) -> f64 {
    let start = Instant::now();
    let mut steps = 0u32;
    while start.elapsed().as_secs_f64() < SIM_PHASE_SECS {
        lab.step(1);
        steps += 1;
    }
    f64::from(steps) / start.elapsed().as_secs_f64()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn visits_every_fish_count_and_restores_the_default() {
        let mut lab = Lab::new(Settings::default());
        let mut bench = Benchmark {
            experiment_runs: 1,
            ..Benchmark::new()
        };
        let mut now = 0.0;
        while !bench.is_done() && now < 100.0 {
            bench.frame(&mut lab, now, Some(0.001));
            now += 0.5;
        }
        let report = bench.report();
        assert!(report.done);
        assert_eq!(
            report
                .rows
                .iter()
                .map(|r| (r.scene, r.fish))
                .collect::<Vec<_>>(),
            phases()
                .into_iter()
                .map(|(scene, fish)| (scene.name(), fish))
                .collect::<Vec<_>>()
        );
        assert!(
            report
                .rows
                .iter()
                .all(|r| r.sim_steps_per_sec > 0.0 && r.frame_ms > 0.0)
        );
        assert_eq!(lab.scene().boids().unwrap().fish().len(), 200);
        let e = report.experiment.expect("the experiment is timed");
        assert_eq!((e.name.as_str(), e.runs), ("alignment-sweep", 1));
        assert!(e.runs_per_sec > 0.0 && e.steps_per_sec > e.runs_per_sec);
    }
}
