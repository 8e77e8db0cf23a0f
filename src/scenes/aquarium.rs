//! The aquarium: fish wandering on their own among rocks and pillars, the boid
//! tank with the boid layer off.

use super::{BOID_CLOCK, BoidTank, SCHOOL_MEASURES, SceneClass, SceneFacts};
use crate::lab::Lab;
use crate::settings::{PredationSettings, Scene, Settings, Side};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::{SceneWorld, WorldConfig};
use crate::ui::about_text;
use crate::ui::scene_panel::ScenePanel;

pub struct Aquarium;

/// Wandering fish with the seed's rocks: no boid layer, no sharks or
/// stingrays, no teacher's rocks (those are the schooling lab's).
fn tank(settings: &Settings, side: Side) -> BoidTank {
    BoidTank {
        config: WorldConfig {
            seed: settings.seed,
            fish_count: settings.tank(side).fish_count as usize,
            sharks: 0,
            stingrays: 0,
            obstacles: None,
        },
        boids: None,
        predation: PredationSettings::default(),
    }
}

/// What the aquarium is, in data.
const FACTS: SceneFacts = SceneFacts {
    id: "scene-aquarium",
    about: &about_text::AQUARIUM,
    // The (left) tank's settings, of which only the fish count acts.
    settings_section: "left",
    count_keys: &["left.fish_count", "right.fish_count"],
    clock: BOID_CLOCK,
    secs_per_animal_step: 0.5e-6,
    bench_counts: &[200, 5_000, 20_000],
    measures: &SCHOOL_MEASURES,
};

impl SceneClass for Aquarium {
    fn facts(&self) -> &'static SceneFacts {
        &FACTS
    }

    fn scene(&self) -> Scene {
        Scene::Aquarium
    }

    fn acts(&self, key: &str) -> bool {
        key == "left.fish_count"
    }

    fn set_animal_count(&self, settings: &mut Settings, count: u32) {
        settings.left.fish_count = count;
    }

    fn build(
        &self,
        settings: &Settings,
        side: Side,
        _learning: &mut Option<LearningLab>,
    ) -> SceneWorld {
        tank(settings, side).build()
    }

    fn boid_tank(&self, settings: &Settings, side: Side) -> Option<BoidTank> {
        Some(tank(settings, side))
    }

    fn write_csv(&self, lab: &Lab, out: &mut String) {
        super::schooling::metrics_tables(lab, out);
    }

    fn panel(&self) -> Box<dyn ScenePanel> {
        Box::new(crate::ui::boids_panel::AquariumPanel)
    }
}
