//! The learning lab (Tu & Terzopoulos §4): a fish that learns to swim by
//! simulated annealing, the Fourier abstraction, the race and buoy tracking.

use std::fmt::Write as _;

use super::{FISH_WORLD_CLOCK, SceneClass, SceneFacts};
use crate::export::{FILTER_NOTE, quoted};
use crate::lab::Lab;
use crate::settings::{Scene, Settings, Side};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::{SceneWorld, Tank};
use crate::ui::about_text;
use crate::ui::scene_panel::ScenePanel;

pub struct LearningScene;

/// What the learning lab is, in data.
const FACTS: SceneFacts = SceneFacts {
    id: "scene-learning",
    about: &about_text::LEARNING_LAB,
    settings_section: "learning",
    // The learning lab has no school whose size a mystery could hide.
    count_keys: &[],
    clock: FISH_WORLD_CLOCK,
    secs_per_animal_step: 90e-6,
    // No school to measure: the learning lab's numbers are its training
    // history (its CSV) and the race.
    // The learning lab's benchmark figure is its annealing rate.
    bench_counts: &[],
    measures: &[],
};

impl SceneClass for LearningScene {
    fn facts(&self) -> &'static SceneFacts {
        &FACTS
    }

    fn scene(&self) -> Scene {
        Scene::Learning
    }

    /// A new species or number of annealing steps is a new training.
    fn needs_rebuild(&self, before: &Settings, after: &Settings) -> bool {
        before.learning.training_key() != after.learning.training_key()
    }

    fn build(
        &self,
        settings: &Settings,
        _side: Side,
        learning: &mut Option<LearningLab>,
    ) -> SceneWorld {
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
                &Tank::default(),
            )
        });
        if learning.controller() != wanted.controller {
            learning.set_controller(wanted.controller);
        }
        SceneWorld::Learning(Box::new(learning))
    }

    fn write_csv(&self, lab: &Lab, out: &mut String) {
        if let SceneWorld::Learning(learning) = lab.runs()[0].scene() {
            learning_csv(learning, out);
        }
    }

    fn panel(&self) -> Box<dyn ScenePanel> {
        Box::new(crate::ui::learning_panel::LearningPanel::default())
    }
}

/// The learning lab's one header: `table`, the drill, then each table's own
/// columns.
pub const LEARNING_HEADER: &str = "table,drill,task,\
annealing_step,current_objective,best_objective,temperature,\
annealing_steps,objective,energy_in_two_modes\n";

/// The learning lab: the current drill's objective after every annealing step
/// and the drills learned so far.
pub fn learning_csv(learning: &LearningLab, out: &mut String) {
    let trainer = learning.trainer();
    let drills = learning.drills();
    // Once every drill is learned the trainer holds the last one's history.
    let drill = learning
        .current_drill()
        .unwrap_or(drills.len().saturating_sub(1));
    let _ = writeln!(
        out,
        "# learner: {}; {} tries per drill; drill {} of {} in training{}",
        learning.species().name(),
        learning.annealing_steps(),
        drill + 1,
        drills.len(),
        if learning.current_drill().is_none() {
            " (all learned)" // words: in a CSV comment line, English like the whole file
        } else {
            ""
        }
    );
    out.push_str(
        "# table training: after every annealing step of the drill in training, the \
         objective E (lower is better) of the controls the annealer holds and of the best \
         so far, and the temperature\n",
    );
    out.push_str(
        "# table finished: each learned drill's objective, its annealing steps and the \
         share of its controls' energy in the two main rhythms\n",
    );
    out.push_str(FILTER_NOTE);
    out.push_str(LEARNING_HEADER);
    let task = drills
        .get(drill)
        .map(|t| quoted(&t.label()))
        .unwrap_or_default();
    for h in trainer.history() {
        let _ = writeln!(
            out,
            "training,{},{task},{},{:.6},{:.6},{:.6},,,",
            drill + 1,
            h.evaluation,
            h.current_objective,
            h.best_objective,
            h.temperature
        );
    }
    for (k, finished) in learning.finished_drills().iter().enumerate() {
        let task = drills
            .get(k)
            .map(|t| quoted(&t.label()))
            .unwrap_or_default();
        let energy = learning.abstraction(k).map_or(String::new(), |a| {
            format!("{:.4}", a.controller.energy_fraction)
        });
        let _ = writeln!(
            out,
            "finished,{},{task},,,,,{},{:.6},{energy}",
            k + 1,
            finished.annealing_steps,
            finished.objective,
        );
    }
}
