//! Fixed simulation steps, independent of the frame rate.
//!
//! The simulation always advances in steps of the same length (`World::DT_SECS`); each
//! frame the clock says how many steps real time and the speed multiplier ask for.
//! Frame time never enters an integrator, so a run is the same on a fast desktop and
//! a slow Chromebook. When a machine cannot keep up, the clock caps the steps per
//! frame and drops the backlog: the simulation slows down gracefully instead of
//! spiralling into ever longer frames that freeze the tab.
//! (The pattern of Bevy's `physics_in_fixed_timestep` example and Glenn Fiedler's
//! "Fix your timestep".)

/// Turns frame times into a whole number of fixed simulation steps.
#[derive(Clone, Debug)]
pub struct FixedStepClock {
    /// Length of one simulation step, seconds of simulated time.
    step_secs: f64,
    /// Simulated time owed but not yet stepped, seconds.
    accumulator_secs: f64,
    /// Most steps run in one frame. Default 32: at 60 frames/s that is 8× real time
    /// at a 1/60 s step, the fastest speed offered, with no backlog.
    pub max_steps_per_frame: u32,
    /// Whether the last frame hit the cap.
    fell_behind: bool,
    /// Real seconds the clock has been behind without a break.
    behind_secs: f64,
}

/// Real seconds the clock must stay behind before the UI says "slowed down"
/// (1.5, chosen: the first frames after loading, while the GPU compiles its
/// shaders, are long but pass; a machine that cannot keep up stays behind).
pub const SLOWED_DOWN_AFTER_SECS: f64 = 1.5;

/// A frame is never counted as longer than this, seconds: after the tab was hidden
/// or the debugger paused, the simulation resumes instead of replaying the gap.
pub const MAX_FRAME_SECS: f64 = 0.25;

impl FixedStepClock {
    pub fn new(step_secs: f64) -> Self {
        Self {
            step_secs,
            accumulator_secs: 0.0,
            max_steps_per_frame: 32,
            fell_behind: false,
            behind_secs: 0.0,
        }
    }

    /// How many steps to run for a frame that lasted `frame_secs` of real time at
    /// `speed` simulated seconds per real second.
    pub fn steps_for_frame(&mut self, frame_secs: f64, speed: f64) -> u32 {
        let frame_too_long = frame_secs.is_finite() && frame_secs > MAX_FRAME_SECS;
        let frame_secs = if frame_secs.is_finite() {
            frame_secs.clamp(0.0, MAX_FRAME_SECS)
        } else {
            0.0
        };
        let speed = if speed.is_finite() {
            speed.max(0.0)
        } else {
            0.0
        };
        self.accumulator_secs += frame_secs * speed;
        let wanted = (self.accumulator_secs / self.step_secs).floor();
        let steps = wanted.min(f64::from(self.max_steps_per_frame)) as u32;
        let capped = wanted > f64::from(self.max_steps_per_frame);
        // Behind when steps were capped, or when a frame took so long (a very slow
        // machine) that part of it was not counted: either way simulated time runs
        // slower than asked.
        self.fell_behind = capped || (frame_too_long && speed > 0.0);
        self.behind_secs = if self.fell_behind {
            self.behind_secs + frame_secs
        } else {
            0.0
        };
        self.accumulator_secs -= f64::from(steps) * self.step_secs;
        if capped {
            // Drop the backlog rather than carry it into the next frame.
            self.accumulator_secs = 0.0;
        }
        steps
    }

    /// How far real time has moved into the next step, in [0, 1): the renderer
    /// interpolates between the last two states by this fraction.
    pub fn alpha(&self) -> f32 {
        (self.accumulator_secs / self.step_secs).clamp(0.0, 1.0) as f32
    }

    /// Did the last frame need more steps than the cap allows?
    pub fn fell_behind(&self) -> bool {
        self.fell_behind
    }

    /// Has the clock been behind for [`SLOWED_DOWN_AFTER_SECS`] of real time
    /// without a break (what the status line reports as "slowed down")?
    pub fn slowed_down(&self) -> bool {
        self.behind_secs >= SLOWED_DOWN_AFTER_SECS
    }

    /// Forgets owed time (after a pause or a reset).
    pub fn clear(&mut self) {
        self.accumulator_secs = 0.0;
        self.fell_behind = false;
        self.behind_secs = 0.0;
    }
}

/// Counts events per second over a sliding one-second window (frames, steps).
#[derive(Clone, Debug, Default)]
pub struct RateMeter {
    window_start_secs: f64,
    count_in_window: u64,
    rate_per_sec: f64,
}

impl RateMeter {
    /// Records `count` events at wall-clock time `now_secs`.
    pub fn record(&mut self, now_secs: f64, count: u64) {
        self.count_in_window += count;
        let elapsed = now_secs - self.window_start_secs;
        if elapsed >= 1.0 {
            self.rate_per_sec = self.count_in_window as f64 / elapsed;
            self.count_in_window = 0;
            self.window_start_secs = now_secs;
        } else if elapsed < 0.0 {
            self.window_start_secs = now_secs;
            self.count_in_window = 0;
        }
    }

    /// Events per second over the last full window.
    pub fn rate_per_sec(&self) -> f64 {
        self.rate_per_sec
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEP: f64 = 1.0 / 60.0;

    #[test]
    fn real_time_at_speed_one_runs_one_step_per_sixtieth_of_a_second() {
        let mut clock = FixedStepClock::new(STEP);
        let total: u32 = (0..600).map(|_| clock.steps_for_frame(STEP, 1.0)).sum();
        assert!((599..=600).contains(&total), "{total}");
    }

    #[test]
    fn steps_do_not_depend_on_the_frame_rate() {
        // Ten seconds of real time at 30 and at 144 frames per second.
        let mut slow = FixedStepClock::new(STEP);
        let mut fast = FixedStepClock::new(STEP);
        let slow_steps: u32 = (0..300)
            .map(|_| slow.steps_for_frame(1.0 / 30.0, 2.0))
            .sum();
        let fast_steps: u32 = (0..1440)
            .map(|_| fast.steps_for_frame(1.0 / 144.0, 2.0))
            .sum();
        assert!((slow_steps as i64 - 1200).abs() <= 1, "{slow_steps}");
        assert!((fast_steps as i64 - 1200).abs() <= 1, "{fast_steps}");
    }

    #[test]
    fn a_slow_machine_is_capped_instead_of_freezing() {
        let mut clock = FixedStepClock::new(STEP);
        clock.max_steps_per_frame = 8;
        // 5 frames/s at 8×: 0.2 s × 8 = 96 steps wanted per frame.
        for _ in 0..10 {
            assert_eq!(clock.steps_for_frame(0.2, 8.0), 8);
            assert!(clock.fell_behind());
        }
        // The backlog is dropped: a fast frame afterwards does not catch up.
        assert!(clock.steps_for_frame(STEP, 1.0) <= 1);
    }

    #[test]
    fn a_few_long_frames_at_start_do_not_say_slowed_down_but_a_slow_machine_does() {
        let mut clock = FixedStepClock::new(STEP);
        // Loading: three long frames, then smooth ones.
        for _ in 0..3 {
            clock.steps_for_frame(0.4, 1.0);
        }
        assert!(!clock.slowed_down());
        clock.steps_for_frame(STEP, 1.0);
        assert!(!clock.slowed_down());
        // A machine that stays behind for two seconds.
        clock.max_steps_per_frame = 2;
        for _ in 0..20 {
            clock.steps_for_frame(0.1, 8.0);
        }
        assert!(clock.slowed_down());
        clock.max_steps_per_frame = 32;
        clock.steps_for_frame(STEP, 1.0);
        assert!(!clock.slowed_down());
    }

    #[test]
    fn very_long_frames_are_reported_as_falling_behind() {
        let mut clock = FixedStepClock::new(STEP);
        assert_eq!(clock.steps_for_frame(0.4, 1.0), 15);
        assert!(clock.fell_behind());
        clock.steps_for_frame(STEP, 1.0);
        assert!(!clock.fell_behind());
    }

    #[test]
    fn bad_frame_times_give_no_steps() {
        let mut clock = FixedStepClock::new(STEP);
        assert_eq!(clock.steps_for_frame(f64::NAN, 1.0), 0);
        assert_eq!(clock.steps_for_frame(-1.0, 1.0), 0);
        assert_eq!(clock.steps_for_frame(1.0, f64::INFINITY), 0);
        assert!(clock.alpha().is_finite());
    }

    #[test]
    fn rate_meter_counts_per_second() {
        let mut meter = RateMeter::default();
        for frame in 0..=120 {
            meter.record(f64::from(frame) / 60.0, 3);
        }
        assert!(
            (meter.rate_per_sec() - 180.0).abs() < 5.0,
            "{}",
            meter.rate_per_sec()
        );
    }
}
