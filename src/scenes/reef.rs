//! The reef (Tu & Terzopoulos §5–7): fish with minds, on muscle or point-mass
//! bodies, in five demos.

use std::fmt::Write as _;

use super::{FISH_WORLD_CLOCK, Followed, SCHOOL_MEASURES, SceneClass, SceneFacts};
use crate::experiment::Measure;
use crate::export::{FILTER_NOTE, quoted, sampling};
use crate::lab::{Lab, Run};
use crate::settings::{Scene, Settings, Side};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::reef::world::ReefWorld;
use crate::sim::{Obstacle, SceneWorld};
use crate::ui::about_text;
use crate::ui::scene_panel::ScenePanel;

pub struct Reef;

/// The reef's measures: the prey school's, and its census.
const MEASURES: [Measure; 12] = [
    SCHOOL_MEASURES[0],
    SCHOOL_MEASURES[1],
    SCHOOL_MEASURES[2],
    SCHOOL_MEASURES[3],
    SCHOOL_MEASURES[4],
    SCHOOL_MEASURES[5],
    Measure::Catches,
    Measure::FoodEaten,
    Measure::Spawnings,
    Measure::MissedStrikes,
    Measure::FishCollisions,
    Measure::PreyAlive,
];

/// What the reef is, in data.
const FACTS: SceneFacts = SceneFacts {
    id: "scene-reef",
    about: &about_text::REEF,
    settings_section: "reef",
    count_keys: &["reef.prey_count"],
    clock: FISH_WORLD_CLOCK,
    secs_per_animal_step: 75e-6,
    // Fish with minds (perception with occlusion) at 10, 50 and 200 animals.
    bench_counts: &[10, 50, 200],
    measures: &MEASURES,
};

impl SceneClass for Reef {
    fn facts(&self) -> &'static SceneFacts {
        &FACTS
    }

    fn scene(&self) -> Scene {
        Scene::Reef
    }

    fn selected(&self, settings: &Settings, _side: Side) -> Option<u32> {
        settings.reef.selected
    }

    fn select(&self, settings: &mut Settings, _side: Side, animal: Option<u32>) {
        settings.reef.selected = animal;
    }

    fn toggle_camera_follow(&self, settings: &mut Settings) -> Option<bool> {
        // Only with a fish to follow, as the panel's check box.
        settings.reef.follow = !settings.reef.follow && settings.reef.selected.is_some();
        Some(settings.reef.follow)
    }

    /// A new demo, body or count of prey or plankton builds a new reef.
    fn needs_rebuild(&self, before: &Settings, after: &Settings) -> bool {
        before.reef.rebuild_key() != after.reef.rebuild_key()
    }

    /// The demo's own predators and pacifists, and prey for the rest.
    fn set_animal_count(&self, settings: &mut Settings, count: u32) {
        let others = settings.reef.demo.animal_count(0) as u32;
        settings.reef.prey_count = Some(count.saturating_sub(others));
    }

    fn build(
        &self,
        settings: &Settings,
        _side: Side,
        _learning: &mut Option<LearningLab>,
    ) -> SceneWorld {
        let mut reef = ReefWorld::new(settings.reef.config(settings.seed));
        settings.predation.apply_to_reef(reef.params_mut());
        SceneWorld::Reef(Box::new(reef))
    }

    /// The water (visibility, current) and the minds' traits.
    fn follow(
        &self,
        world: &mut SceneWorld,
        settings: &Settings,
        _side: Side,
        _obstacles_applied: &mut Option<Vec<Obstacle>>,
    ) -> Followed {
        let SceneWorld::Reef(reef) = world else {
            return Followed::default();
        };
        let wanted = &settings.reef;
        if reef.config().visibility_m != wanted.visibility_m {
            reef.set_visibility(wanted.visibility_m);
        }
        if reef.config().current_m_per_s != wanted.current_m_per_s {
            reef.set_current(wanted.current_m_per_s);
        }
        settings.predation.apply_to_reef(reef.params_mut());
        if reef.config().traits != wanted.traits {
            reef.set_traits(wanted.traits);
        }
        Followed::default()
    }

    fn write_csv(&self, lab: &Lab, out: &mut String) {
        let run = &lab.runs()[0];
        if let SceneWorld::Reef(reef) = run.scene() {
            reef_csv(run, reef, lab.settings().reef.selected, out);
        }
    }

    fn panel(&self) -> Box<dyn ScenePanel> {
        Box::new(crate::ui::reef_panel::ReefPanel::default())
    }
}

/// The reef's one header: `table`, time, then each table's own columns.
pub const REEF_HEADER: &str = "table,time_s,\
predators_alive,prey_alive,pacifists_alive,food,prey_eaten,missed_strikes,\
schooling_prey_eaten,food_eaten,spawnings,fish_collisions,\
event_kind,event_text,\
animal,hunger,libido,fear,intention\n";

/// The reef: counts over time, the event log and the selected fish's mind, in
/// one table told apart by its first column.
pub fn reef_csv(run: &Run, reef: &ReefWorld, selected: Option<u32>, out: &mut String) {
    let _ = writeln!(
        out,
        "# demo: {}; body: {}",
        reef.config().scene.label(),
        match reef.config().body {
            crate::sim::reef::world::ReefBodyKind::Physical => "muscles",
            crate::sim::reef::world::ReefBodyKind::PointMass => "points",
        }
    );
    let _ = writeln!(
        out,
        "# table counts: living animals by kind and the counters since the start, {}",
        sampling(run)
    );
    let _ = writeln!(
        out,
        "# table event: the event log (its latest {} lines)",
        crate::sim::reef::world::EVENT_LOG_LEN
    );
    let _ = writeln!(
        out,
        "# table mind: the selected fish's hunger, libido and fear (0 to 1) and intention, \
         every {} s over its last {:.0} s",
        crate::sim::reef::world::HISTORY_EVERY_SECS,
        crate::sim::reef::world::HISTORY_EVERY_SECS * crate::sim::reef::world::HISTORY_LEN as f64
    );
    out.push_str(FILTER_NOTE);
    let mind = selected.and_then(|i| Some((i as usize, reef.animals().get(i as usize)?)));
    match mind {
        Some((i, a)) => {
            let _ = writeln!(out, "# selected: {}", a.name(i));
        }
        None => out.push_str(
            "# no fish selected: click a fish, then download again to add its mind over time\n",
        ),
    }
    out.push_str(REEF_HEADER);
    for c in run.census() {
        let n = c.counts;
        let _ = writeln!(
            out,
            "counts,{:.3},{},{},{},{},{},{},{},{},{},{},,,,,,,",
            c.time_secs,
            c.predators,
            c.prey,
            c.pacifists,
            c.food,
            n.prey_eaten,
            n.missed_strikes,
            n.schooling_prey_eaten,
            n.food_eaten,
            n.spawnings,
            n.fish_collisions,
        );
    }
    for e in reef.events() {
        let _ = writeln!(
            out,
            "event,{:.3},,,,,,,,,,,{},{},,,,,",
            e.time_secs,
            e.kind.name(),
            quoted(&e.text)
        );
    }
    if let Some((i, a)) = mind {
        let name = a.name(i);
        for s in &a.history {
            let _ = writeln!(
                out,
                "mind,{:.3},,,,,,,,,,,,,{name},{:.4},{:.4},{:.4},{}",
                s.time_secs,
                s.hunger,
                s.libido,
                s.fear,
                s.intention.label()
            );
        }
    }
}
