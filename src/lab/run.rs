//! One tank's run: its scene's world, the previous state for smooth drawing,
//! the selected muscle fish's trace, the metrics history and the reef's
//! census; and how the settings build each scene's world.

use glam::Vec3;

use std::collections::VecDeque;

use crate::metrics_history::{MetricsHistory, MetricsSample};
use crate::settings::{Scene, Settings, Side};
use crate::sim::body::{MUSCLE_COUNT, NODE_COUNT};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::reef::report::ReefCensus;
use crate::sim::reef::world::ReefWorld;
use crate::sim::scene::{SceneWorld, centre};
use crate::sim::{HandCommand, PhysicsConfig, PhysicsWorld, World, WorldConfig};

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
            scene: build_scene(settings, side, learning),
            previous_positions_m: Vec::new(),
            previous_nodes_m: Vec::new(),
            body_trace: VecDeque::new(),
            traced: None,
            history: MetricsHistory::default(),
            census: VecDeque::new(),
            generation,
            obstacles_from_settings: world_config(settings, side).obstacles,
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

    /// The boid world, in the aquarium and the schooling lab.
    pub fn boids(&self) -> Option<&World> {
        self.scene.boids()
    }

    /// The physical fish, in the physics scene.
    pub fn physics(&self) -> Option<&PhysicsWorld> {
        self.scene.physics()
    }

    /// The fish with minds, in the reef scene.
    pub fn reef(&self) -> Option<&ReefWorld> {
        self.scene.reef()
    }

    /// The learning lab, in its scene.
    pub fn learning(&self) -> Option<&LearningLab> {
        self.scene.learning()
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
        if self
            .scene
            .steps()
            .is_multiple_of(self.scene.sample_every_steps())
        {
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
    }

    /// Follows the physics scene's settings: counts, behaviour, current, the
    /// selected fish's hand command.
    fn follow_physics(physics: &mut PhysicsWorld, settings: &Settings) -> bool {
        let wanted = &settings.physics;
        let counts = (wanted.fish_count as usize, wanted.sharks as usize);
        let recount = counts != (physics.fish_count(), physics.shark_count());
        if recount {
            physics.set_counts(counts.0, counts.1);
        }
        if physics.behaviour() != wanted.behaviour {
            physics.set_behaviour(wanted.behaviour);
        }
        if physics.current().strength_m_per_s != wanted.current_m_per_s {
            physics.set_current(wanted.current_m_per_s);
        }
        let hand = wanted.selected.filter(|_| wanted.hand_control).map(|i| {
            (
                i as usize,
                HandCommand {
                    speed_fraction: wanted.hand_speed,
                    pitch_rad: wanted.hand_pitch_deg.to_radians(),
                },
            )
        });
        physics.set_hand_command(hand);
        recount
    }

    /// Starts a turn of `angle_deg` (+ left) on physical animal `index`.
    pub(super) fn turn(&mut self, index: usize, angle_deg: f32) {
        if let SceneWorld::Physics(physics) = &mut self.scene {
            physics.turn(index, angle_deg);
        }
    }

    /// Follows the reef scene's live settings (water, minds).
    fn follow_reef(reef: &mut ReefWorld, settings: &Settings) {
        let wanted = &settings.reef;
        if reef.config().visibility_m != wanted.visibility_m {
            reef.set_visibility(wanted.visibility_m);
        }
        if reef.config().current_m_per_s != wanted.current_m_per_s {
            reef.set_current(wanted.current_m_per_s);
        }
        if reef.config().traits != wanted.traits {
            reef.set_traits(wanted.traits);
        }
    }

    /// Follows the schooling lab's settings for this tank: counts, boid layer,
    /// species and obstacles. Returns whether animals came or went.
    fn follow_boids(&mut self, settings: &Settings) -> bool {
        let SceneWorld::Boids(world) = &mut self.scene else {
            return false;
        };
        let mut recount = false;
        let tank = settings.tank(self.side);
        let fish_count = tank.fish_count as usize;
        if fish_count != world.fish().len() {
            world.set_fish_count(fish_count);
            recount = true;
        }
        let boids = boid_params(settings, self.side);
        if world.boids() != boids.as_ref() {
            world.set_boids(boids);
        }
        let config = world_config(settings, self.side);
        if (config.sharks, config.stingrays) != (world.sharks().len(), world.stingrays().len()) {
            world.set_species_counts(config.sharks, config.stingrays);
            recount = true;
        }
        if config.obstacles.as_ref() != self.obstacles_from_settings.as_ref() {
            world.set_obstacles(match &config.obstacles {
                Some(obstacles) => obstacles.clone(),
                // Back to the seed's layout.
                None => World::seeded_obstacles(config.seed),
            });
            self.obstacles_from_settings = config.obstacles;
            self.obstacle_edits += 1;
        }
        recount
    }

    /// Follows new settings for this tank without restarting where possible.
    pub(super) fn follow(&mut self, settings: &Settings) {
        let (recount, selected) = match &mut self.scene {
            SceneWorld::Boids(_) => (self.follow_boids(settings), None),
            SceneWorld::Physics(physics) => (
                Self::follow_physics(physics, settings),
                settings.physics.selected,
            ),
            SceneWorld::Reef(reef) => {
                Self::follow_reef(reef, settings);
                (false, settings.reef.selected)
            }
            // The lab applies the learning settings itself.
            SceneWorld::Learning(_) => (false, None),
        };
        if recount {
            self.snapshot();
        }
        if self.traced != selected {
            self.traced = selected;
            self.body_trace.clear();
        }
    }
}

/// The world of `settings`' scene for tank `side`.
fn build_scene(settings: &Settings, side: Side, learning: &mut Option<LearningLab>) -> SceneWorld {
    match settings.scene {
        Scene::Aquarium | Scene::Boids => {
            let mut world = World::new(world_config(settings, side));
            world.set_boids(boid_params(settings, side));
            SceneWorld::Boids(Box::new(world))
        }
        Scene::Physics => SceneWorld::Physics(PhysicsWorld::new(physics_config(settings))),
        Scene::Reef => SceneWorld::Reef(ReefWorld::new(settings.reef.config(settings.seed))),
        Scene::Learning => {
            let wanted = &settings.learning;
            // The lab kept while another scene was shown, if it is the same
            // training.
            let kept = learning.take().filter(|l| {
                l.species() == wanted.species
                    && l.annealing_steps() == u64::from(wanted.annealing_steps)
                    && l.seed() == settings.seed
            });
            let mut learning = kept.unwrap_or_else(|| {
                // Open water for the learners: no rocks.
                LearningLab::new(
                    wanted.species,
                    u64::from(wanted.annealing_steps),
                    settings.seed,
                    wanted.controller,
                    &crate::sim::Tank::default(),
                )
            });
            if learning.controller() != wanted.controller {
                learning.set_controller(wanted.controller);
            }
            SceneWorld::Learning(Box::new(learning))
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

fn physics_config(settings: &Settings) -> PhysicsConfig {
    let physics = &settings.physics;
    PhysicsConfig {
        seed: settings.seed,
        fish_count: physics.fish_count as usize,
        sharks: physics.sharks as usize,
        behaviour: physics.behaviour,
        current_m_per_s: physics.current_m_per_s,
        // The seed's rocks, as the schooling lab's tank has them.
        obstacles: World::seeded_obstacles(settings.seed),
    }
}

fn world_config(settings: &Settings, side: Side) -> WorldConfig {
    let tank = settings.tank(side);
    let boids = settings.scene == Scene::Boids;
    WorldConfig {
        seed: settings.seed,
        // The aquarium and the schooling lab (other scenes build no boid world).
        fish_count: if matches!(settings.scene, Scene::Aquarium | Scene::Boids) {
            tank.fish_count as usize
        } else {
            0
        },
        // Predators, stingrays and edited rocks belong to the schooling lab.
        sharks: if boids { tank.sharks as usize } else { 0 },
        stingrays: if boids { tank.stingrays as usize } else { 0 },
        obstacles: if boids { tank.obstacles.clone() } else { None },
    }
}

fn boid_params(settings: &Settings, side: Side) -> Option<crate::sim::BoidParams> {
    (settings.scene == Scene::Boids).then(|| settings.tank(side).boid_params())
}
