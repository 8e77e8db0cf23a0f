//! The schooling lab: Lim & Tan's SIMBA boid layer on the boid tank, with
//! sharks, stingrays, a teacher's rocks and two tanks to compare.

use std::fmt::Write as _;

use super::{BOID_CLOCK, BoidTank, SCHOOL_MEASURES, SceneClass, SceneFacts};
use crate::experiment::Measure;
use crate::lab::Lab;
use crate::settings::{Scene, Settings, Side};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::{SceneWorld, WorldConfig};
use crate::ui::about_text;
use crate::ui::scene_panel::ScenePanel;

pub struct SchoolingLab;

/// The measures of the schooling lab: the school's, and the sharks' catches.
const MEASURES: [Measure; 7] = [
    SCHOOL_MEASURES[0],
    SCHOOL_MEASURES[1],
    SCHOOL_MEASURES[2],
    SCHOOL_MEASURES[3],
    SCHOOL_MEASURES[4],
    SCHOOL_MEASURES[5],
    Measure::Catches,
];

/// Everything the tank of `side` has: the boid layer with its weights, mode
/// and senses, sharks, stingrays and the teacher's rocks.
fn tank(settings: &Settings, side: Side) -> BoidTank {
    let tank = settings.tank(side);
    BoidTank {
        config: WorldConfig {
            seed: settings.seed,
            fish_count: tank.fish_count as usize,
            sharks: tank.sharks as usize,
            stingrays: tank.stingrays as usize,
            obstacles: tank.obstacles.clone(),
        },
        boids: Some(tank.boid_params()),
        predation: settings.predation,
    }
}

/// What the schooling lab is, in data.
const FACTS: SceneFacts = SceneFacts {
    id: "scene-schooling",
    about: &about_text::SCHOOLING_LAB,
    settings_section: "left",
    count_keys: &["left.fish_count", "right.fish_count"],
    clock: BOID_CLOCK,
    secs_per_animal_step: 0.9e-6,
    // Lim & Tan's 500, and the scale a classroom projector shows.
    bench_counts: &[500, 5_000, 20_000],
    measures: &MEASURES,
};

impl SceneClass for SchoolingLab {
    fn facts(&self) -> &'static SceneFacts {
        &FACTS
    }

    fn scene(&self) -> Scene {
        Scene::Boids
    }

    /// Each tank's own selected fish; the right tank's only while comparing.
    fn selected(&self, settings: &Settings, side: Side) -> Option<u32> {
        match side {
            Side::Left => settings.left.selected,
            Side::Right => settings
                .compare
                .then_some(settings.right.selected)
                .flatten(),
        }
    }

    fn select(&self, settings: &mut Settings, side: Side, animal: Option<u32>) {
        match side {
            Side::Left => settings.left.selected = animal,
            Side::Right => settings.right.selected = animal,
        }
    }

    fn tanks(&self, settings: &Settings) -> usize {
        if settings.compare { 2 } else { 1 }
    }

    fn set_animal_count(&self, settings: &mut Settings, count: u32) {
        settings.left.fish_count = count;
        settings.left.sharks = 0;
        settings.left.stingrays = 0;
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
        metrics_tables(lab, out);
    }

    fn panel(&self) -> Box<dyn ScenePanel> {
        Box::new(crate::ui::boids_panel::BoidsPanel::default())
    }
}

/// The boid tanks' CSV: the metrics table of every tank shown.
pub(super) fn metrics_tables(lab: &Lab, out: &mut String) {
    let _ = writeln!(
        out,
        "# the school's metrics {}, one row per tank",
        crate::export::sampling(&lab.runs()[0])
    );
    out.push_str(&lab.metrics_csv());
}
