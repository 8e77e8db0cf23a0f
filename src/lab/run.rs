//! One tank's run: its scene's world, the previous state for smooth drawing,
//! the selected muscle fish's trace, the metrics history and the reef's
//! census; and how the settings build each scene's world.

use glam::Vec3;

use std::collections::VecDeque;

use crate::metrics_history::{MetricsHistory, MetricsSample};
use crate::settings::{Settings, Side};
use crate::sim::body::{MUSCLE_COUNT, NODE_COUNT};
use crate::sim::common::spare::release_spare;
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::reef::report::ReefCensus;
use crate::sim::scene::{SceneWorld, centre};

/// Seconds of the selected fish's muscles and speed kept for the plots.
pub const BODY_TRACE_SECS: f64 = 10.0;

/// One step of the selected physical fish, for the muscle and speed plots.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodySample {
    pub time_secs: f64,
    /// Speed of the centre of mass, m/s.
    pub speed_m_per_s: f32,
    /// The 12 muscle contractions in [0, 1] (order of `body_layout::MUSCLES`).
    pub muscles: [f32; MUSCLE_COUNT],
}

/// One tank's run: its scene's world, what is needed to draw it smoothly, and its
/// metrics. Cloned to go back in time (*Skip to the moment*, `lab/skip.rs`).
#[derive(Clone)]
pub struct Run {
    pub(super) side: Side,
    pub(super) scene: SceneWorld,
    /// Every animal's position before the last step (see
    /// [`SceneWorld::positions_m`]), for interpolated drawing.
    pub(super) previous_positions_m: Vec<Vec3>,
    /// Every animal's nodes before the last step (see [`SceneWorld::nodes_m`]).
    pub(super) previous_nodes_m: Vec<[Vec3; NODE_COUNT]>,
    /// The selected physical fish's last seconds, and which fish it is.
    body_trace: VecDeque<BodySample>,
    traced: Option<u32>,
    pub(super) history: MetricsHistory,
    /// Steps between two metrics samples (the scene's
    /// [`crate::scenes::SceneFacts::clock`]).
    sample_every_steps: u64,
    /// The scene's counts at each metrics sample over the last
    /// [`crate::metrics_history::HISTORY_SECS`] (the reef; see
    /// [`SceneWorld::census`]), oldest first.
    census: VecDeque<ReefCensus>,
    /// Which rebuild of the lab made this world.
    generation: u64,
    /// The obstacles the settings asked for when last applied.
    obstacles_from_settings: Option<Vec<crate::sim::Obstacle>>,
    /// Obstacle changes since the world was built.
    obstacle_edits: u64,
}

impl Run {
    /// A run of `settings`' scene for tank `side`; the learning lab takes
    /// `learning` (kept while another scene was shown) if it fits the settings.
    pub(super) fn new(
        side: Side,
        settings: &Settings,
        generation: u64,
        learning: &mut Option<LearningLab>,
    ) -> Self {
        let mut run = Self {
            side,
            scene: settings.scene.class().build(settings, side, learning),
            previous_positions_m: Vec::new(),
            previous_nodes_m: Vec::new(),
            body_trace: VecDeque::new(),
            traced: None,
            history: MetricsHistory::default(),
            census: VecDeque::new(),
            generation,
            sample_every_steps: settings.scene.class().facts().clock.sample_every_steps,
            obstacles_from_settings: settings
                .scene
                .class()
                .boid_tank(settings, side)
                .and_then(|tank| tank.config.obstacles),
            obstacle_edits: 0,
        };
        run.snapshot();
        run.follow(settings);
        run.sample_metrics();
        run
    }

    /// The simulated world of this tank.
    pub fn scene(&self) -> &SceneWorld {
        &self.scene
    }

    /// Simulated seconds since the run began.
    pub fn time_secs(&self) -> f64 {
        self.scene.time_secs()
    }

    /// Steps since the run began.
    pub fn steps(&self) -> u64 {
        self.scene.steps()
    }

    /// Animals in the tank (eaten ones not counted).
    pub fn animal_count(&self) -> usize {
        self.scene.animal_count()
    }

    /// Where every animal's nodes should be drawn, by index: `alpha` of the way
    /// from their previous to their current positions (tank frame, metres; see
    /// [`SceneWorld::nodes_m`]).
    pub fn drawn_nodes_all_m(&self, alpha: f32) -> Vec<[Vec3; NODE_COUNT]> {
        let mut now = Vec::new();
        self.scene.nodes_m(&mut now);
        for (i, current) in now.iter_mut().enumerate() {
            if let Some(previous) = self.previous_nodes_m.get(i) {
                *current = std::array::from_fn(|k| previous[k].lerp(current[k], alpha));
            }
        }
        now
    }

    /// Where animal `index`'s nodes should be drawn (see
    /// [`Self::drawn_nodes_all_m`]; for one animal, not in a loop).
    pub fn drawn_nodes_m(&self, index: usize, alpha: f32) -> [Vec3; NODE_COUNT] {
        self.drawn_nodes_all_m(alpha)
            .get(index)
            .copied()
            .unwrap_or([Vec3::ZERO; NODE_COUNT])
    }

    /// Where every animal should be drawn, by index: `alpha` of the way from
    /// its previous to its current position (see [`SceneWorld::positions_m`]).
    pub fn drawn_positions_m(&self, alpha: f32) -> Vec<Vec3> {
        let mut now = Vec::new();
        self.scene.positions_m(&mut now);
        for (i, current) in now.iter_mut().enumerate() {
            if let Some(previous) = self.previous_positions_m.get(i) {
                *current = previous.lerp(*current, alpha);
            }
        }
        now
    }

    /// Where animal `index` should be drawn (see [`Self::drawn_positions_m`];
    /// for one animal, not in a loop).
    pub fn drawn_position_m(&self, index: usize, alpha: f32) -> Vec3 {
        self.drawn_positions_m(alpha)
            .get(index)
            .copied()
            .unwrap_or(Vec3::ZERO)
    }

    /// Every animal that can be selected: index, drawn centre (`alpha` of the
    /// way from the last step) and body length.
    pub fn selectable_animals(&self, alpha: f32) -> Vec<(usize, Vec3, f32)> {
        let positions = self.drawn_positions_m(alpha);
        let nodes = self.drawn_nodes_all_m(alpha);
        self.scene
            .pickable()
            .into_iter()
            .map(|(i, length)| {
                let c = if self.scene.has_body(i) {
                    centre(&nodes[i])
                } else {
                    positions[i]
                };
                (i, c, length)
            })
            .collect()
    }

    /// The selected physical fish's muscles and speed over the last
    /// [`BODY_TRACE_SECS`], oldest first.
    pub fn body_trace(&self) -> &VecDeque<BodySample> {
        &self.body_trace
    }

    pub fn side(&self) -> Side {
        self.side
    }

    /// Changes whenever the world is rebuilt (new seed, scene or reset) or its
    /// obstacles change, so the renderer knows when its static meshes are stale.
    pub fn generation(&self) -> u64 {
        (self.generation << 32) | (self.obstacle_edits & 0xFFFF_FFFF)
    }

    /// Steps between two metrics samples.
    pub fn sample_every_steps(&self) -> u64 {
        self.sample_every_steps
    }

    /// The metrics of the last minutes.
    pub fn history(&self) -> &MetricsHistory {
        &self.history
    }

    /// The reef's counts over the last minutes, one per metrics sample, oldest
    /// first (empty in the other scenes).
    pub fn census(&self) -> &VecDeque<ReefCensus> {
        &self.census
    }

    /// The latest metrics.
    pub fn metrics(&self) -> MetricsSample {
        self.history.latest().copied().unwrap_or_default()
    }

    pub(super) fn step(&mut self, snapshot: bool) {
        if snapshot {
            self.snapshot();
        }
        self.scene.step();
        if let Some(fish) = self
            .traced
            .and_then(|i| self.scene.physical_fish(i as usize))
        {
            push_trace(
                &mut self.body_trace,
                sample_of(fish, self.scene.time_secs()),
            );
        }
        if self.scene.steps().is_multiple_of(self.sample_every_steps) {
            self.sample_metrics();
        }
    }

    /// Records the world's latest metrics (computed by the simulation every step).
    /// Force shares are over the last second, so a mode switch shows at once.
    fn sample_metrics(&mut self) {
        if let Some(census) = self.scene.census() {
            self.census.push_back(census);
            while self.census.front().is_some_and(|first| {
                census.time_secs - first.time_secs > crate::metrics_history::HISTORY_SECS
            }) {
                self.census.pop_front();
            }
        }
        let Some(m) = self.scene.metrics() else {
            return;
        };
        self.history.push(MetricsSample::new(
            m.time_secs,
            &m.school,
            m.force_frequencies,
            m.catches,
        ));
    }

    /// Remembers where every animal is, for interpolated drawing.
    fn snapshot(&mut self) {
        self.scene.positions_m(&mut self.previous_positions_m);
        self.scene.nodes_m(&mut self.previous_nodes_m);
        release_spare(&mut self.previous_positions_m, 1024);
        release_spare(&mut self.previous_nodes_m, 64);
    }

    /// Follows new settings for this tank without restarting where possible.
    pub(super) fn follow(&mut self, settings: &Settings) {
        let class = settings.scene.class();
        let followed = class.follow(
            &mut self.scene,
            settings,
            self.side,
            &mut self.obstacles_from_settings,
        );
        if followed.obstacles {
            self.obstacle_edits += 1;
        }
        let (recount, selected) = (followed.recount, class.selected(settings, self.side));
        if recount {
            self.snapshot();
        }
        if self.traced != selected {
            self.traced = selected;
            self.body_trace.clear();
        }
    }
}

/// The selected physical fish's speed and muscles now.
fn sample_of(animal: &crate::sim::PhysicalFish, time_secs: f64) -> BodySample {
    BodySample {
        time_secs,
        speed_m_per_s: animal.point.velocity_m_per_s.length(),
        muscles: animal.motor().muscles,
    }
}

/// Appends `sample`, keeping the last [`BODY_TRACE_SECS`].
fn push_trace(trace: &mut VecDeque<BodySample>, sample: BodySample) {
    trace.push_back(sample);
    while trace
        .front()
        .is_some_and(|s| s.time_secs < sample.time_secs - BODY_TRACE_SECS)
    {
        trace.pop_front();
    }
}
