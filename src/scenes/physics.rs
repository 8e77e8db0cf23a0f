//! The physics fish tank (Tu & Terzopoulos §3): muscle-driven spring–mass
//! fish steered by the boid layer.

use std::fmt::Write as _;

use super::{FISH_WORLD_CLOCK, Followed, SCHOOL_MEASURES, SceneClass, SceneFacts};
use crate::export::{muscle_columns, sampling};
use crate::lab::{Lab, Run};
use crate::settings::{Scene, Settings, Side};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::{HandCommand, Obstacle, PhysicsConfig, PhysicsWorld, SceneWorld, World};
use crate::ui::about_text;
use crate::ui::scene_panel::ScenePanel;

pub struct PhysicsTank;

/// What the physics fish tank is, in data.
const FACTS: SceneFacts = SceneFacts {
    id: "scene-physics",
    about: &about_text::PHYSICS_FISH,
    settings_section: "physics",
    count_keys: &["physics.fish_count", "physics.sharks"],
    clock: FISH_WORLD_CLOCK,
    secs_per_animal_step: 90e-6,
    // The paper's demo (10), and up to 200 muscle fish.
    bench_counts: &[10, 50, 200],
    measures: &SCHOOL_MEASURES,
};

impl SceneClass for PhysicsTank {
    fn facts(&self) -> &'static SceneFacts {
        &FACTS
    }

    fn scene(&self) -> Scene {
        Scene::Physics
    }

    fn selected(&self, settings: &Settings, _side: Side) -> Option<u32> {
        settings.physics.selected
    }

    fn select(&self, settings: &mut Settings, _side: Side, animal: Option<u32>) {
        settings.physics.selected = animal;
    }

    fn toggle_camera_follow(&self, settings: &mut Settings) -> Option<bool> {
        // Only with a fish to follow, as the panel's check box.
        settings.physics.follow = !settings.physics.follow && settings.physics.selected.is_some();
        Some(settings.physics.follow)
    }

    fn set_animal_count(&self, settings: &mut Settings, count: u32) {
        settings.physics.fish_count = count;
        settings.physics.sharks = 0;
    }

    fn build(
        &self,
        settings: &Settings,
        _side: Side,
        _learning: &mut Option<LearningLab>,
    ) -> SceneWorld {
        let physics = &settings.physics;
        SceneWorld::Physics(Box::new(PhysicsWorld::new(PhysicsConfig {
            seed: settings.seed,
            fish_count: physics.fish_count as usize,
            sharks: physics.sharks as usize,
            behaviour: physics.behaviour,
            current_m_per_s: physics.current_m_per_s,
            // The seed's rocks, as the schooling lab's tank has them.
            obstacles: World::seeded_obstacles(settings.seed),
        })))
    }

    /// Counts, behaviour, current and the selected fish's hand command.
    fn follow(
        &self,
        world: &mut SceneWorld,
        settings: &Settings,
        _side: Side,
        _obstacles_applied: &mut Option<Vec<Obstacle>>,
    ) -> Followed {
        let SceneWorld::Physics(physics) = world else {
            return Followed::default();
        };
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
        Followed {
            recount,
            obstacles: false,
        }
    }

    fn write_csv(&self, lab: &Lab, out: &mut String) {
        physics_csv(&lab.runs()[0], lab.settings().physics.selected, out);
    }

    fn panel(&self) -> Box<dyn ScenePanel> {
        Box::new(crate::ui::physics_panel::PhysicsPanel::default())
    }
}

/// The physics fish tank's school, when no fish is selected.
pub const PHYSICS_SCHOOL_HEADER: &str =
    "time_s,polarization,milling,nnd_body_lengths,groups,mean_speed_m_per_s\n";

/// The physics fish: the selected fish's muscles and speed at every step of the
/// trace the lab keeps; with none selected, the school's metrics.
pub fn physics_csv(run: &Run, selected: Option<u32>, out: &mut String) {
    let SceneWorld::Physics(physics) = run.scene() else {
        return;
    };
    let animal = selected.and_then(|i| Some((i, physics.animals().get(i as usize)?)));
    let Some((index, fish)) = animal else {
        out.push_str(
            "# no fish selected: click a fish, then download again for its twelve muscles \
             and its speed\n",
        );
        let _ = writeln!(out, "# the school's metrics {}", sampling(run));
        out.push_str(PHYSICS_SCHOOL_HEADER);
        for s in run.history().samples() {
            let _ = writeln!(
                out,
                "{:.3},{:.4},{:.4},{:.3},{},{:.4}",
                s.time_secs, s.polarization, s.milling, s.nnd_body_lengths, s.groups, s.mean_speed
            );
        }
        return;
    };
    let _ = writeln!(
        out,
        "# selected: {} {index} (body length {:.2} m)",
        fish.species.name(),
        fish.body_length_m()
    );
    let _ = writeln!(
        out,
        "# its muscles (0 resting, 1 fully contracted) and speed at every step of the last \
         {:.0} s since it was selected",
        crate::lab::BODY_TRACE_SECS
    );
    out.push_str("time_s,speed_m_per_s");
    for name in muscle_columns() {
        out.push(',');
        out.push_str(&name);
    }
    out.push('\n');
    for s in run.body_trace() {
        let _ = write!(out, "{:.3},{:.4}", s.time_secs, s.speed_m_per_s);
        for u in s.muscles {
            let _ = write!(out, ",{u:.4}");
        }
        out.push('\n');
    }
}
