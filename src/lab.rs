//! The running experiment: the simulated world, the teacher's settings and the clock
//! that advances one in fixed steps.
//!
//! `Lab` has no GPU and no UI, so everything the UI and the automation API can do to
//! a run is tested natively. The app owns one `Lab` and draws it.

use glam::Vec3;

use crate::clock::{FixedStepClock, RateMeter};
use crate::settings::Settings;
use crate::sim::{World, WorldConfig};

/// A world, its settings and its clock.
pub struct Lab {
    settings: Settings,
    world: World,
    clock: FixedStepClock,
    /// Fish positions before the last step, for interpolated drawing.
    previous_positions_m: Vec<Vec3>,
    steps_meter: RateMeter,
    /// Counts rebuilds of the world, so the renderer knows when its meshes are stale.
    generation: u64,
}

impl Lab {
    pub fn new(settings: Settings) -> Self {
        let world = World::new(world_config(&settings));
        let previous_positions_m = world.fish().iter().map(|f| f.position_m).collect();
        Self {
            settings,
            world,
            clock: FixedStepClock::new(f64::from(World::DT_SECS)),
            previous_positions_m,
            steps_meter: RateMeter::default(),
            generation: 0,
        }
    }

    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    pub fn world(&self) -> &World {
        &self.world
    }

    /// Changes whenever the world is rebuilt (new seed, scene or reset).
    pub fn world_generation(&self) -> u64 {
        self.generation
    }

    /// Replaces the settings, doing what each change means: a new seed or scene
    /// rebuilds the world, a new fish count adds or removes fish, speed and pause take
    /// effect from the next frame. The caller has validated `new` (see
    /// [`Settings::apply_patch`]); out-of-range values are clamped here too, so no
    /// path can put the world in a state the UI could not.
    pub fn apply_settings(&mut self, new: Settings) {
        let mut new = new;
        if new.validate().is_err() {
            new.speed = new
                .speed
                .clamp(crate::settings::SPEED_MIN, crate::settings::SPEED_MAX);
            if !new.speed.is_finite() {
                new.speed = 1.0;
            }
            new.fish_count = new.fish_count.min(crate::settings::FISH_COUNT_MAX);
            new.seed = new.seed.min(crate::settings::SEED_MAX);
        }
        let rebuild = new.seed != self.settings.seed || new.scene != self.settings.scene;
        let recount = new.fish_count != self.settings.fish_count;
        let unpaused = self.settings.paused && !new.paused;
        self.settings = new;
        if rebuild {
            self.reset(None);
        } else if recount {
            self.world.set_fish_count(self.settings.fish_count as usize);
            self.snapshot_positions();
        }
        if unpaused {
            self.clock.clear();
        }
    }

    /// Rebuilds the world from `seed` (or the current seed), keeping every other
    /// setting.
    pub fn reset(&mut self, seed: Option<u64>) {
        if let Some(seed) = seed {
            self.settings.seed = seed.min(crate::settings::SEED_MAX);
        }
        self.world = World::new(world_config(&self.settings));
        self.generation += 1;
        self.clock.clear();
        self.snapshot_positions();
    }

    /// Runs the steps owed for a frame of `frame_secs` real seconds (none while
    /// paused). `now_secs` is wall-clock time, for the steps-per-second meter.
    pub fn advance_frame(&mut self, frame_secs: f64, now_secs: f64) -> u32 {
        let steps = if self.settings.paused {
            0
        } else {
            self.clock
                .steps_for_frame(frame_secs, f64::from(self.settings.speed))
        };
        self.run_steps(steps);
        self.steps_meter.record(now_secs, u64::from(steps));
        steps
    }

    /// Runs exactly `n` steps now, paused or not (single step, `shoal.step(n)`).
    pub fn step(&mut self, n: u32) {
        self.run_steps(n);
    }

    fn run_steps(&mut self, n: u32) {
        for i in 0..n {
            if i + 1 == n {
                self.snapshot_positions();
            }
            self.world.step();
        }
    }

    fn snapshot_positions(&mut self) {
        self.previous_positions_m.clear();
        self.previous_positions_m
            .extend(self.world.fish().iter().map(|f| f.position_m));
    }

    /// Where fish `index` should be drawn: between its last two simulated positions,
    /// `alpha` of the way (see [`FixedStepClock::alpha`]).
    pub fn drawn_position_m(&self, index: usize) -> Vec3 {
        let current = self.world.fish()[index].position_m;
        match self.previous_positions_m.get(index) {
            Some(previous) if !self.settings.paused => previous.lerp(current, self.clock.alpha()),
            _ => current,
        }
    }

    /// Simulation steps per second of wall-clock time over the last second.
    pub fn steps_per_sec(&self) -> f64 {
        self.steps_meter.rate_per_sec()
    }

    /// Did the last frame hit the step cap (the machine cannot keep up)?
    pub fn fell_behind(&self) -> bool {
        self.clock.fell_behind()
    }
}

fn world_config(settings: &Settings) -> WorldConfig {
    WorldConfig {
        seed: settings.seed,
        fish_count: settings.fish_count as usize,
        ..WorldConfig::default()
    }
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
        lab.apply_settings(Settings {
            fish_count: 37,
            ..lab.settings().clone()
        });
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
            let previous = lab.previous_positions_m[i];
            let total = previous.distance(fish.position_m);
            assert!(drawn.distance(previous) <= total + 1e-5);
            assert!(drawn.distance(fish.position_m) <= total + 1e-5);
        }
    }
}
