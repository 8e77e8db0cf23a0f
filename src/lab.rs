//! The running experiment: the simulated world, the teacher's settings and the clock
//! that advances one in fixed steps.
//!
//! `Lab` has no GPU and no UI, so everything the UI and the automation API can do to
//! a run is tested natively. The app owns one `Lab` and draws it.

use glam::Vec3;

use crate::clock::{FixedStepClock, RateMeter};
use crate::metrics_history::{MetricsHistory, MetricsSample, SAMPLE_EVERY_STEPS};
use crate::settings::{Scene, Settings, Side};
use crate::sim::{World, WorldConfig};

/// One tank's run: its world, what is needed to draw it smoothly, and its metrics.
pub struct Run {
    side: Side,
    world: World,
    /// Fish positions before the last step, for interpolated drawing.
    previous_positions_m: Vec<Vec3>,
    history: MetricsHistory,
    /// Which rebuild of the lab made this world.
    generation: u64,
    /// The obstacles the settings asked for when last applied.
    obstacles_from_settings: Option<Vec<crate::sim::Obstacle>>,
    /// Obstacle changes since the world was built.
    obstacle_edits: u64,
}

impl Run {
    fn new(side: Side, settings: &Settings, generation: u64) -> Self {
        let mut world = World::new(world_config(settings, side));
        world.set_boids(boid_params(settings, side));
        let mut run = Self {
            side,
            world,
            previous_positions_m: Vec::new(),
            history: MetricsHistory::default(),
            generation,
            obstacles_from_settings: settings.tank(side).obstacles.clone(),
            obstacle_edits: 0,
        };
        run.snapshot_positions();
        run.sample_metrics();
        run
    }

    pub fn side(&self) -> Side {
        self.side
    }

    pub fn world(&self) -> &World {
        &self.world
    }

    /// Changes whenever the world is rebuilt (new seed, scene or reset) or its
    /// obstacles change, so the renderer knows when its static meshes are stale.
    pub fn generation(&self) -> u64 {
        (self.generation << 32) | (self.obstacle_edits & 0xFFFF_FFFF)
    }

    /// The metrics of the last minutes.
    pub fn history(&self) -> &MetricsHistory {
        &self.history
    }

    /// The latest metrics.
    pub fn metrics(&self) -> MetricsSample {
        self.history.latest().copied().unwrap_or_default()
    }

    fn step(&mut self, snapshot: bool) {
        if snapshot {
            self.snapshot_positions();
        }
        self.world.step();
        if self.world.steps().is_multiple_of(SAMPLE_EVERY_STEPS) {
            self.sample_metrics();
        }
    }

    /// Records the world's latest metrics (computed by the simulation every step).
    /// Force shares are over the last second, so a mode switch shows at once.
    fn sample_metrics(&mut self) {
        let metrics = self.world.metrics();
        let force_frequencies = if self.world.boids().is_some() {
            metrics.force_frequencies_recent
        } else {
            [0.0; 5]
        };
        self.history.push(MetricsSample::new(
            self.world.time_secs(),
            &metrics.school,
            force_frequencies,
            metrics.catches,
        ));
    }

    /// Remembers where every animal is (fish, then sharks, then stingrays).
    fn snapshot_positions(&mut self) {
        self.previous_positions_m.clear();
        let world = &self.world;
        self.previous_positions_m.extend(
            world
                .fish()
                .iter()
                .chain(world.sharks().iter().map(|s| &s.body))
                .chain(world.stingrays().iter().map(|r| &r.body))
                .map(|f| f.position_m),
        );
    }

    fn interpolated(&self, slot: usize, current: Vec3, alpha: f32) -> Vec3 {
        match self.previous_positions_m.get(slot) {
            Some(previous) => previous.lerp(current, alpha),
            None => current,
        }
    }

    /// Where fish `index` should be drawn: `alpha` of the way from its previous to
    /// its current simulated position.
    pub fn drawn_position_m(&self, index: usize, alpha: f32) -> Vec3 {
        self.interpolated(index, self.world.fish()[index].position_m, alpha)
    }

    /// Where shark `index` should be drawn (see [`Self::drawn_position_m`]).
    pub fn drawn_shark_m(&self, index: usize, alpha: f32) -> Vec3 {
        let slot = self.world.fish().len() + index;
        self.interpolated(slot, self.world.sharks()[index].body.position_m, alpha)
    }

    /// Where stingray `index` should be drawn (see [`Self::drawn_position_m`]).
    pub fn drawn_stingray_m(&self, index: usize, alpha: f32) -> Vec3 {
        let slot = self.world.fish().len() + self.world.sharks().len() + index;
        self.interpolated(slot, self.world.stingrays()[index].body.position_m, alpha)
    }

    /// Follows new settings for this tank without restarting where possible.
    fn follow(&mut self, settings: &Settings) {
        let tank = settings.tank(self.side);
        let fish_count = tank.fish_count as usize;
        if fish_count != self.world.fish().len() {
            self.world.set_fish_count(fish_count);
            self.snapshot_positions();
        }
        let boids = boid_params(settings, self.side);
        if self.world.boids() != boids.as_ref() {
            self.world.set_boids(boids);
        }
        let config = world_config(settings, self.side);
        if (config.sharks, config.stingrays)
            != (self.world.sharks().len(), self.world.stingrays().len())
        {
            self.world
                .set_species_counts(config.sharks, config.stingrays);
            self.snapshot_positions();
        }
        if config.obstacles.as_ref() != self.obstacles_from_settings.as_ref() {
            match &config.obstacles {
                Some(obstacles) => self.world.set_obstacles(obstacles.clone()),
                // Back to the seed's layout: the obstacles are placed first from
                // the seed, so an empty world of the same seed has the same ones.
                None => {
                    let seeded = World::new(WorldConfig {
                        fish_count: 0,
                        sharks: 0,
                        stingrays: 0,
                        ..config.clone()
                    });
                    self.world.set_obstacles(seeded.obstacles().to_vec());
                }
            }
            self.obstacles_from_settings = config.obstacles;
            self.obstacle_edits += 1;
        }
    }
}

/// The running experiment: one tank, or two side by side, sharing one clock.
pub struct Lab {
    settings: Settings,
    clock: FixedStepClock,
    /// The left tank, then the right one while comparing.
    runs: Vec<Run>,
    steps_meter: RateMeter,
    /// Counts rebuilds, so each rebuilt world gets a new generation number.
    rebuilds: u64,
    /// Wall-clock seconds of simulation a frame may spend (`None`: no limit).
    frame_budget_secs: Option<f64>,
    /// Smoothed wall-clock cost of one step of every tank, seconds.
    step_cost_secs: f64,
}

/// The frame budget the app uses, seconds. Default 0.025 s: with drawing and the
/// UI a frame stays near 30 frames/s or better, so the camera and sliders stay
/// responsive however many fish swim; the simulation slows down instead
/// ("slowed down" in the status line).
pub const INTERACTIVE_FRAME_BUDGET_SECS: f64 = 0.025;

impl Lab {
    pub fn new(settings: Settings) -> Self {
        let mut settings = settings;
        settings.clamp();
        let mut lab = Self {
            settings,
            clock: FixedStepClock::new(f64::from(World::DT_SECS)),
            runs: Vec::new(),
            steps_meter: RateMeter::default(),
            rebuilds: 0,
            frame_budget_secs: None,
            step_cost_secs: 0.0,
        };
        lab.rebuild();
        lab
    }

    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The left (or only) tank's world.
    pub fn world(&self) -> &World {
        &self.runs[0].world
    }

    /// The tanks shown: one, or two while comparing.
    pub fn runs(&self) -> &[Run] {
        &self.runs
    }

    /// The run of `side`, if shown.
    pub fn run(&self, side: Side) -> Option<&Run> {
        self.runs.get(side.index())
    }

    /// Changes whenever the left world is rebuilt.
    pub fn world_generation(&self) -> u64 {
        self.runs[0].generation()
    }

    /// Does this scene show two tanks?
    pub fn comparing(&self) -> bool {
        self.settings.scene == Scene::Boids && self.settings.compare
    }

    /// Replaces the settings, doing what each change means: a new seed, scene or
    /// layout (compare on or off) rebuilds the worlds so both tanks start from the
    /// same positions; new counts add or remove fish; sliders take effect at the
    /// next step. Out-of-range values are clamped, so no path can put the world in
    /// a state the UI could not.
    pub fn apply_settings(&mut self, new: Settings) {
        let mut new = new;
        new.settle(&self.settings);
        new.clamp();
        let before = std::mem::replace(&mut self.settings, new);
        let rebuild = before.seed != self.settings.seed
            || before.scene != self.settings.scene
            || self.runs.len() != self.wanted_runs();
        let unpaused = before.paused && !self.settings.paused;
        if rebuild {
            self.rebuild();
        } else {
            for run in &mut self.runs {
                run.follow(&self.settings);
            }
        }
        if unpaused {
            self.clock.clear();
        }
    }

    fn wanted_runs(&self) -> usize {
        if self.comparing() { 2 } else { 1 }
    }

    fn rebuild(&mut self) {
        self.runs = Side::BOTH[..self.wanted_runs()]
            .iter()
            .map(|&side| {
                self.rebuilds += 1;
                Run::new(side, &self.settings, self.rebuilds)
            })
            .collect();
        self.clock.clear();
    }

    /// Rebuilds the worlds from `seed` (or the current seed), keeping every other
    /// setting.
    pub fn reset(&mut self, seed: Option<u64>) {
        if let Some(seed) = seed {
            self.settings.seed = seed.min(crate::settings::SEED_MAX);
        }
        self.rebuild();
    }

    /// Limits the simulation's wall-clock time per frame (the app sets
    /// [`INTERACTIVE_FRAME_BUDGET_SECS`]); steps per frame then adapt to the measured
    /// cost of a step. Results stay deterministic: only how many fixed steps run per
    /// frame changes, never their length.
    pub fn set_frame_budget(&mut self, budget_secs: Option<f64>) {
        self.frame_budget_secs = budget_secs;
    }

    /// Runs the steps owed for a frame of `frame_secs` real seconds (none while
    /// paused). `now_secs` is wall-clock time, for the steps-per-second meter.
    pub fn advance_frame(&mut self, frame_secs: f64, now_secs: f64) -> u32 {
        /// Steps per frame without a budget (see [`FixedStepClock`]).
        const MAX_STEPS: u32 = 32;
        self.clock.max_steps_per_frame = match self.frame_budget_secs {
            Some(budget) if self.step_cost_secs > 0.0 => {
                ((budget / self.step_cost_secs).floor() as u32).clamp(1, MAX_STEPS)
            }
            _ => MAX_STEPS,
        };
        let steps = if self.settings.paused {
            0
        } else {
            self.clock
                .steps_for_frame(frame_secs, f64::from(self.settings.speed))
        };
        let started = web_time::Instant::now();
        self.run_steps(steps);
        if steps > 0 {
            let cost = started.elapsed().as_secs_f64() / f64::from(steps);
            // Smoothed over a few frames; the first measurement is taken as is.
            self.step_cost_secs = if self.step_cost_secs > 0.0 {
                0.8 * self.step_cost_secs + 0.2 * cost
            } else {
                cost
            };
        }
        self.steps_meter.record(now_secs, u64::from(steps));
        steps
    }

    /// Runs exactly `n` steps now, paused or not (single step, `shoal.step(n)`).
    pub fn step(&mut self, n: u32) {
        self.run_steps(n);
    }

    fn run_steps(&mut self, n: u32) {
        for run in &mut self.runs {
            for i in 0..n {
                run.step(i + 1 == n);
            }
        }
    }

    /// How far between the last two simulated states to draw (0 while paused).
    pub fn draw_alpha(&self) -> f32 {
        if self.settings.paused {
            1.0
        } else {
            self.clock.alpha()
        }
    }

    /// Where fish `index` of the left tank should be drawn.
    pub fn drawn_position_m(&self, index: usize) -> Vec3 {
        self.runs[0].drawn_position_m(index, self.draw_alpha())
    }

    /// Simulation steps per second of wall-clock time over the last second.
    pub fn steps_per_sec(&self) -> f64 {
        self.steps_meter.rate_per_sec()
    }

    /// Did the last frame hit the step cap (the machine cannot keep up)?
    pub fn fell_behind(&self) -> bool {
        self.clock.fell_behind()
    }

    /// The metrics history of every tank shown as one CSV text.
    pub fn metrics_csv(&self) -> String {
        let mut csv = crate::metrics_history::CSV_HEADER.to_owned();
        for run in &self.runs {
            run.history.to_csv(run.side.name(), &mut csv);
        }
        csv
    }
}

fn world_config(settings: &Settings, side: Side) -> WorldConfig {
    let tank = settings.tank(side);
    let boids = settings.scene == Scene::Boids;
    WorldConfig {
        seed: settings.seed,
        fish_count: tank.fish_count as usize,
        // Predators, stingrays and edited rocks belong to the schooling lab.
        sharks: if boids { tank.sharks as usize } else { 0 },
        stingrays: if boids { tank.stingrays as usize } else { 0 },
        obstacles: if boids { tank.obstacles.clone() } else { None },
    }
}

fn boid_params(settings: &Settings, side: Side) -> Option<crate::sim::BoidParams> {
    (settings.scene == Scene::Boids).then(|| settings.tank(side).boid_params())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn positions(lab: &Lab) -> Vec<Vec3> {
        lab.world().fish().iter().map(|f| f.position_m).collect()
    }

    #[test]
    fn paused_lab_does_not_advance_but_single_step_does() {
        let mut lab = Lab::new(Settings {
            paused: true,
            ..Settings::default()
        });
        assert_eq!(lab.advance_frame(0.1, 0.1), 0);
        assert_eq!(lab.world().steps(), 0);
        lab.step(3);
        assert_eq!(lab.world().steps(), 3);
    }

    #[test]
    fn changing_the_seed_rebuilds_and_the_same_seed_repeats_the_run() {
        let mut a = Lab::new(Settings::default());
        let mut b = Lab::new(Settings::default());
        a.step(120);
        b.step(120);
        assert_eq!(positions(&a), positions(&b));
        b.apply_settings(Settings {
            seed: 99,
            ..b.settings().clone()
        });
        assert_eq!(b.world().steps(), 0, "a new seed starts a new run");
        b.step(120);
        assert_ne!(positions(&a), positions(&b));
        b.reset(Some(1));
        b.step(120);
        assert_eq!(positions(&a), positions(&b));
    }

    #[test]
    fn changing_the_fish_count_keeps_the_run_going() {
        let mut lab = Lab::new(Settings::default());
        lab.step(10);
        let mut settings = lab.settings().clone();
        settings.left.fish_count = 37;
        lab.apply_settings(settings);
        assert_eq!(lab.world().fish().len(), 37);
        assert_eq!(lab.world().steps(), 10);
    }

    #[test]
    fn speed_multiplies_the_steps_per_frame() {
        let mut slow = Lab::new(Settings {
            speed: 0.25,
            ..Settings::default()
        });
        let mut fast = Lab::new(Settings {
            speed: 8.0,
            ..Settings::default()
        });
        for frame in 0..60 {
            let now = f64::from(frame) / 60.0;
            slow.advance_frame(1.0 / 60.0, now);
            fast.advance_frame(1.0 / 60.0, now);
        }
        assert!(
            (14..=15).contains(&slow.world().steps()),
            "{}",
            slow.world().steps()
        );
        assert!(
            (479..=480).contains(&fast.world().steps()),
            "{}",
            fast.world().steps()
        );
    }

    #[test]
    fn drawn_positions_lie_between_the_last_two_states() {
        let mut lab = Lab::new(Settings::default());
        lab.advance_frame(1.5 / 60.0, 0.0);
        let alpha = lab.clock.alpha();
        assert!(alpha > 0.0 && alpha < 1.0);
        for (i, fish) in lab.world().fish().iter().enumerate() {
            let drawn = lab.drawn_position_m(i);
            let previous = lab.runs[0].previous_positions_m[i];
            let total = previous.distance(fish.position_m);
            assert!(drawn.distance(previous) <= total + 1e-5);
            assert!(drawn.distance(fish.position_m) <= total + 1e-5);
        }
    }
}
