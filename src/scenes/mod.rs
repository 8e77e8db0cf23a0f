//! The scene catalogue: one type per scene holds everything about it, as
//! rerun's `ViewClass` holds everything about a kind of view.
//!
//! [`SceneClass`] is that type's interface: the scene's words (label, one-line
//! description, *About this scene*), its part of the settings (section, the
//! keys that act in it, the counts a mystery hides, the selected animal, how
//! many tanks it shows, what rebuilds it), its clock (step length, metrics
//! sampling, the native cost of an animal-step), what an experiment can
//! measure in it, how its world is built from the settings and follows them,
//! its CSV file, and its panel. How its animals are drawn is the simulated
//! world's own ([`crate::sim::scene::SceneWorld::points_to_draw`],
//! [`crate::sim::scene::SceneWorld::bodies_to_draw`],
//! [`crate::sim::scene::SceneWorld::scenery`]).
//!
//! [`Scene::class`] is the one registration: a new [`Scene`] variant does not
//! compile until it has a class here. Outside `sim/`, this folder and each
//! scene's own panel, no code names a scene (the test at the end of this file
//! reads the sources to check).

mod aquarium;
mod boid_tank;
mod learning;
mod physics;
mod reef;
mod schooling;

use crate::experiment::Measure;
use crate::i18n::ts;
use crate::lab::Lab;
use crate::settings::{Scene, Settings, Side};
use crate::sim::common::paper_time::FISH_STEP_SECS;
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::scene::{BOID_SAMPLE_EVERY_STEPS, FISH_WORLD_SAMPLE_EVERY_STEPS};
use crate::sim::{Obstacle, SceneWorld, World};
use crate::ui::about_text::About;
use crate::ui::scene_panel::ScenePanel;

pub use boid_tank::{BoidTank, Followed};
pub use learning::{LEARNING_HEADER, learning_csv};
pub use physics::{PHYSICS_SCHOOL_HEADER, physics_csv};
pub use reef::{REEF_HEADER, reef_csv};

/// Everything about one scene that the code around the simulation needs.
/// Every method without a default is a fact each scene must state.
pub trait SceneClass: Sync {
    /// The scene this class describes.
    fn scene(&self) -> Scene;

    /// The scene's facts as data: words, settings section, clock, cost,
    /// benchmark counts, measures.
    fn facts(&self) -> &'static SceneFacts;

    /// Does the setting at the dotted `key` change what happens in a run of
    /// this scene? By default every key of its section does.
    fn acts(&self, key: &str) -> bool {
        key.strip_prefix(self.facts().settings_section)
            .is_some_and(|rest| rest.starts_with('.'))
    }

    /// The animal selected in the tank of `side`, if the scene lets one pick.
    fn selected(&self, _settings: &Settings, _side: Side) -> Option<u32> {
        None
    }

    /// Selects `animal` (or none) in the tank of `side`, as a click on it
    /// would; a scene that lets no one pick ignores it.
    fn select(&self, _settings: &mut Settings, _side: Side, _animal: Option<u32>) {}

    /// Turns the camera's following of the selected animal on or off (the F
    /// key); returns whether it follows now, or `None` for a scene whose
    /// camera does not follow.
    fn toggle_camera_follow(&self, _settings: &mut Settings) -> Option<bool> {
        None
    }

    /// How many tanks the scene shows with these settings (two while the
    /// schooling lab compares).
    fn tanks(&self, _settings: &Settings) -> usize {
        1
    }

    /// Do the settings changed from `before` to `after` need a new world (a
    /// new demo or body), beyond a new seed, scene or layout?
    fn needs_rebuild(&self, _before: &Settings, _after: &Settings) -> bool {
        false
    }

    /// Puts `count` animals in the scene's tank: `count` fish and no
    /// predators in the boid and physics tanks; the reef demo's own predators
    /// and pacifists with prey making up the rest.
    fn set_animal_count(&self, _settings: &mut Settings, _count: u32) {}

    /// The world of tank `side` for `settings`; the learning lab takes
    /// `learning` (kept while another scene was shown) if it fits.
    fn build(
        &self,
        settings: &Settings,
        side: Side,
        learning: &mut Option<LearningLab>,
    ) -> SceneWorld;

    /// What the boid tank of `side` should be, in the scenes that are one.
    fn boid_tank(&self, _settings: &Settings, _side: Side) -> Option<BoidTank> {
        None
    }

    /// Brings `world`, built by [`Self::build`] for tank `side`, to new
    /// settings that do not rebuild it (what sliders change while the fish
    /// swim). `obstacles_applied` is the rocks the settings asked for when last
    /// applied (the boid tanks'). By default a boid tank follows its
    /// [`Self::boid_tank`]; other scenes say what they follow.
    fn follow(
        &self,
        world: &mut SceneWorld,
        settings: &Settings,
        side: Side,
        obstacles_applied: &mut Option<Vec<Obstacle>>,
    ) -> Followed {
        match (world, self.boid_tank(settings, side)) {
            (SceneWorld::Boids(world), Some(tank)) => tank.follow(world, obstacles_applied),
            _ => Followed::default(),
        }
    }

    /// Writes the scene's own tables of the left (or only) tank into the CSV
    /// export, after the header every file has.
    fn write_csv(&self, lab: &Lab, out: &mut String);

    /// A fresh panel: the scene's controls and what it draws around its tank.
    fn panel(&self) -> Box<dyn ScenePanel>;
}

impl Scene {
    /// Everything about this scene.
    pub fn class(self) -> &'static dyn SceneClass {
        match self {
            Self::Aquarium => &aquarium::Aquarium,
            Self::Boids => &schooling::SchoolingLab,
            Self::Physics => &physics::PhysicsTank,
            Self::Reef => &reef::Reef,
            Self::Learning => &learning::LearningScene,
        }
    }
}

/// The panel of the scene on show, swapped for a fresh one when the scene
/// changes (so a scene's panel state, such as the rock tool, starts afresh).
pub struct CurrentPanel {
    scene: Scene,
    panel: Box<dyn ScenePanel>,
}

impl CurrentPanel {
    pub fn new(scene: Scene) -> Self {
        Self {
            scene,
            panel: scene.class().panel(),
        }
    }

    /// The panel for `scene`: the same one while the scene stays.
    pub fn for_scene(&mut self, scene: Scene) -> &mut dyn ScenePanel {
        if scene != self.scene {
            *self = Self::new(scene);
        }
        self.panel.as_mut()
    }

    /// The panel as it is (the scene it was last asked for).
    pub fn get(&self) -> &dyn ScenePanel {
        self.panel.as_ref()
    }

    pub fn get_mut(&mut self) -> &mut dyn ScenePanel {
        self.panel.as_mut()
    }
}

/// What a scene is, as data: every fact about it that is a value. Its
/// behaviour (how it is built, follows the settings, writes its CSV, makes its
/// panel) is its [`SceneClass`]'s methods.
#[derive(Clone, Copy)]
pub struct SceneFacts {
    /// Its message in the catalogue (`scene-schooling`): the name on the
    /// scene picker ([`Self::label`]) with `.description`.
    pub id: &'static str,
    /// The words of *About this scene* (`ui/about_text.rs`).
    pub about: &'static About,
    /// The part of the settings that acts in the scene: its keys start with
    /// this and a dot (`left`, `physics`, `reef`, `learning`).
    pub settings_section: &'static str,
    /// The settings that give away how many fish there are (the status line's
    /// "40 fish", `state().fish_count`): a mystery on any of them hides the
    /// count.
    pub count_keys: &'static [&'static str],
    /// The step and the metrics sampling.
    pub clock: Clock,
    /// Native seconds of one animal-step on one core, measured with
    /// `shoal-lab bench` on the development machine (docs/benchmarks.md): the
    /// experiment window's time estimate.
    pub secs_per_animal_step: f64,
    /// The animal counts the benchmark (`?bench`, `./dev bench`) times the
    /// scene at (none: the learning lab's figure is its annealing rate).
    pub bench_counts: &'static [u32],
    /// What an experiment can measure in the scene.
    pub measures: &'static [Measure],
}

impl SceneFacts {
    /// The name on the scene picker ("Schooling lab").
    pub fn label(&self) -> &'static str {
        ts(self.id)
    }

    /// A sentence a student understands, under the picker.
    pub fn description(&self) -> &'static str {
        ts(crate::settings::number::static_id(format!(
            "{}.description",
            self.id
        )))
    }
}

/// A scene's clock: the length of its fixed step and how often the lab samples
/// its metrics (about four times a second in every scene).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Clock {
    pub step_secs: f64,
    pub sample_every_steps: u64,
}

/// The boid tanks' clock: 1/60 s steps (one a frame on a 60 Hz screen), a
/// sample every 15 (0.25 s).
pub const BOID_CLOCK: Clock = Clock {
    step_secs: World::DT_SECS as f64,
    sample_every_steps: BOID_SAMPLE_EVERY_STEPS,
};

/// The fish world's clock (muscle fish, minds, learning): the paper's
/// Δt = 0.055 s, a sample every 5 steps (0.275 s).
pub const FISH_WORLD_CLOCK: Clock = Clock {
    step_secs: FISH_STEP_SECS as f64,
    sample_every_steps: FISH_WORLD_SAMPLE_EVERY_STEPS,
};

/// The measures of every scene with a school: its order parameters and the
/// distance its fish swim.
const SCHOOL_MEASURES: [Measure; 6] = [
    Measure::Polarization,
    Measure::Milling,
    Measure::NndBodyLengths,
    Measure::Groups,
    Measure::MeanSpeed,
    Measure::DistanceSwum,
];

#[cfg(test)]
mod tests;
