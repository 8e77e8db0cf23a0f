//! The "Learning lab" scene's controls (who learns, how long, start/pause/reset,
//! which controllers drive the demo fish, the race, saving and loading) and its
//! plots: training progress, the objective over the annealing steps, and Fig. 8's
//! three rows (learned controls, primary Fourier modes, abstracted controls).

use eframe::egui;
use egui_plot::{Legend, Line, Plot, PlotPoints};

use super::WidgetRects;
use super::bottom_panel::{plot_height_under_caption, show_bottom_panel};
use super::files::{FileError, PendingFile, open_text_file, save_text_file};
use super::scene_panel::{Notice, ScenePanel};
use super::setting_slider::setting_row;
use super::studio_panel::{control, control_row};
use crate::lab::{Lab, LabError, Run};
use crate::render::Framing;
use crate::settings::Settings;
use crate::settings::learning::LearningSettings;
use crate::sim::BodySpecies;
use crate::sim::body::body_layout::muscle_index;
use crate::sim::body::{MuscleSegment, Side};
use crate::sim::learning::learned_set::LearnedSetError;
use crate::sim::learning::learning_lab::{ControllerChoice, LearningLab, SetSource};
use crate::sim::learning::{Abstraction, Task};

/// The learning lab's one-off actions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LearningAction {
    /// Forget the training.
    ResetTraining,
    /// Start the race.
    StartRace,
    /// Download the learned controllers.
    SaveControllers,
    /// Open a controllers file.
    LoadControllers,
}

/// The learning lab's section of the control panel.
fn learning_controls_ui(
    ui: &mut egui::Ui,
    learning: &mut LearningSettings,
    rects: &mut WidgetRects,
) -> Vec<LearningAction> {
    let mut actions = Vec::new();
    ui.separator();
    ui.label(egui::RichText::new("Learning to swim").strong());
    egui::Grid::new("learning_grid")
        .num_columns(2)
        .spacing([8.0, 6.0])
        .show(ui, |ui| {
            let help = "Who learns. A shark is the same body, twice as long";
            control_row(
                ui,
                rects,
                "learning.species",
                |ui| {
                    ui.label("Learner").on_hover_text(help);
                },
                |ui, rects| {
                    ui.horizontal(|ui| {
                        for (species, label, name) in [
                            (BodySpecies::Fish, "Fish", "learning_fish"),
                            (BodySpecies::Shark, "Shark", "learning_shark"),
                        ] {
                            let r = ui
                                .radio_value(&mut learning.species, species, label)
                                .on_hover_text(help);
                            rects.insert(name, r.rect);
                        }
                    });
                },
            );

            setting_row(
                ui,
                rects,
                LearningSettings::PREFIX,
                &LearningSettings::ANNEALING_STEPS,
                learning,
            );
        });
    ui.horizontal(|ui| {
        let label = if learning.training {
            "Pause training"
        } else {
            "Start training"
        };
        control(ui, rects, "learning.training", |ui, rects| {
            let r = ui.button(label).on_hover_text(
                "The fish practises a little every frame: it changes its muscle timing at \
                 random, keeps changes that take it farther, and sometimes keeps a worse one \
                 to explore",
            );
            rects.insert("learning_train", r.rect);
            if r.clicked() {
                learning.training = !learning.training;
            }
        });
        let r = ui
            .button("Reset training")
            .on_hover_text("Forget everything: the fish is brain-dead again");
        rects.insert("learning_reset", r.rect);
        if r.clicked() {
            actions.push(LearningAction::ResetTraining);
            learning.training = false;
        }
    });
    let help = "Which controllers swim the fish between the two orange buoys: the hand-tuned \
                ones its designers wrote, or the ones it learned by itself";
    ui.label("The swimmer between the buoys uses")
        .on_hover_text(help);
    control(ui, rects, "learning.controller", |ui, rects| {
        ui.horizontal(|ui| {
            for (choice, label, name) in [
                (ControllerChoice::Learned, "Learned", "learning_learned"),
                (
                    ControllerChoice::HandTuned,
                    "Hand-tuned",
                    "learning_hand_tuned",
                ),
            ] {
                let r = ui
                    .radio_value(&mut learning.controller, choice, label)
                    .on_hover_text(help);
                rects.insert(name, r.rect);
            }
        })
    });
    ui.horizontal(|ui| {
        let r = ui.button("Run the race").on_hover_text(
            "Copies of the fish, saved after more and more tries of the first drill, race \
             from the same start line (the paper's Fig. 7). Practice helps a lot at first \
             and then hardly at all: the last two copies finish almost together",
        );
        rects.insert("learning_race", r.rect);
        if r.clicked() {
            actions.push(LearningAction::StartRace);
        }
    });
    ui.horizontal(|ui| {
        let r = ui
            .button("Save controllers")
            .on_hover_text("Download what the fish learned as a file");
        rects.insert("learning_save", r.rect);
        if r.clicked() {
            actions.push(LearningAction::SaveControllers);
        }
        let r = ui
            .button("Load controllers")
            .on_hover_text("Open a file saved before; the swimmer then uses it");
        rects.insert("learning_load", r.rect);
        if r.clicked() {
            actions.push(LearningAction::LoadControllers);
        }
    });
    actions
}

/// The height the learning panel under the tank would like, points (see
/// [`super::bottom_panel::bottom_panel_height`] for what it gets).
pub const LEARNING_PANEL_HEIGHT: f32 = 240.0;

/// The bottom panel: progress, the objective curve and Fig. 8, in
/// `content_height` points (each plot under a one-line caption).
pub fn learning_plots_ui(
    ui: &mut egui::Ui,
    run: &Run,
    abstraction: Option<&Abstraction>,
    content_height: f32,
    rects: &mut WidgetRects,
) {
    let Some(lab) = run.scene().learning() else {
        return;
    };
    ui.horizontal_top(|ui| {
        ui.vertical(|ui| {
            ui.set_width(300.0);
            progress_ui(ui, lab, rects);
        });
        ui.separator();
        // Four plots and the three separators between them (a separator is 6
        // points wide plus the item spacing on each side) fill the width.
        let separator = 6.0 + 2.0 * ui.spacing().item_spacing.x;
        let width = ((ui.available_width() - 3.0 * separator - 12.0) / 4.0).max(120.0);
        let height = plot_height_under_caption(
            content_height,
            ui.text_style_height(&egui::TextStyle::Body),
            ui.spacing().item_spacing.y,
        );
        ui.vertical(|ui| {
            ui.set_width(width);
            objective_plot_ui(ui, lab, height, rects);
        });
        if let Some(a) = abstraction {
            fig8_ui(ui, a, width, height, rects);
        }
    });
}

fn progress_ui(ui: &mut egui::Ui, lab: &LearningLab, rects: &mut WidgetRects) {
    let drills = lab.drills().len();
    let title = match lab.current_drill() {
        Some(k) => format!(
            "Drill {} of {drills}: {}",
            k + 1,
            Task::label(&lab.drills()[k])
        ),
        None => format!("All {drills} drills learned"),
    };
    ui.label(egui::RichText::new(title).strong());
    let r = ui.add(
        egui::ProgressBar::new(lab.progress())
            .show_percentage()
            .desired_width(280.0),
    );
    rects.insert("learning_progress", r.rect);
    let t = lab.trainer();
    if lab.current_drill().is_some() {
        ui.label(format!(
            "{} of {} tries · best E {:.3} · temperature {:.4}",
            t.evaluations(),
            lab.annealing_steps(),
            t.best_evaluation().objective,
            t.temperature()
        ))
        .on_hover_text(
            "E is what the fish tries to make small: how far it ended from its goal, plus a \
             little for jerky muscles. The temperature is how willing it still is to try worse \
             moves; it cools down as training goes on",
        );
    }
    let (_, source) = lab.learned_set();
    ui.label(format!(
        "Learned controllers in use: {}",
        match source {
            SetSource::Shipped => "the shipped set (trained before)",
            SetSource::TrainedHere => "trained here",
            SetSource::Loaded => "loaded from a file",
        }
    ));
    let times = lab.buoy_times_secs();
    ui.label(match times.as_slice() {
        [] => "Swimmer: on its way to the first buoy".to_owned(),
        [a] => format!("Swimmer: first buoy at {a:.1} s"),
        [a, b, ..] => format!("Swimmer: buoys at {a:.1} s and {b:.1} s"),
    });
    if let Some(race) = lab.race() {
        let distances = race.distances_m();
        let leader = race.leader();
        let r = ui
            .vertical(|ui| {
                ui.label(format!(
                    "Race after {:.1} s (the paper's Fig. 7):",
                    race.time_secs()
                ));
                egui::Grid::new("race_results")
                    .num_columns(3)
                    .spacing([12.0, 2.0])
                    .striped(true)
                    .show(ui, |ui| {
                        ui.strong("racer");
                        ui.strong("practice (tries)");
                        ui.strong("distance");
                        ui.end_row();
                        for (k, (e, d)) in race.entrants().zip(&distances).enumerate() {
                            let first = Some(k) == leader;
                            let name = format!("{}{}", if first { "★ " } else { "" }, k + 1);
                            ui.label(name);
                            ui.label(e.annealing_steps.to_string());
                            ui.label(format!("{d:.2} m"));
                            ui.end_row();
                        }
                    });
            })
            .response;
        rects.insert("learning_race_result", r.rect);
    }
}

fn objective_plot_ui(ui: &mut egui::Ui, lab: &LearningLab, height: f32, rects: &mut WidgetRects) {
    // One line, as `height` assumes: a narrow window cuts the caption short.
    ui.add(egui::Label::new("How well it swims (E, lower is better)").truncate());
    let history = lab.trainer().history();
    // At most ~600 points drawn.
    let every = (history.len() / 600).max(1);
    let series = |best: bool| -> PlotPoints {
        history
            .iter()
            .step_by(every)
            .map(|h| {
                let e = if best {
                    h.best_objective
                } else {
                    h.current_objective
                };
                [h.evaluation as f64, f64::from(e)]
            })
            .collect()
    };
    let r = Plot::new("learning_objective")
        .height(height)
        .allow_scroll(false)
        .allow_drag(false)
        .legend(Legend::default())
        .x_axis_label("tries")
        .show(ui, |plot| {
            // Named in the legend, and told apart by the line as well as the
            // colour: the try now dotted grey, the best so far solid green.
            plot.line(
                Line::new("now", series(false))
                    .color(super::palette::GREY)
                    .style(egui_plot::LineStyle::dotted_dense()),
            );
            plot.line(
                Line::new("best", series(true))
                    .color(super::palette::BLUISH_GREEN)
                    .width(2.0),
            );
        });
    rects.insert("learning_objective_plot", r.response.rect);
}

/// The four muscles of the left side that swim and turn (middle and tail
/// segments, dorsal), the ones Fig. 8 shows.
fn shown_muscles() -> [(usize, &'static str); 2] {
    [
        (muscle_index(MuscleSegment::Middle, Side::Left), "middle"),
        (muscle_index(MuscleSegment::Posterior, Side::Left), "tail"),
    ]
}

fn fig8_ui(ui: &mut egui::Ui, a: &Abstraction, width: f32, height: f32, rects: &mut WidgetRects) {
    let rows: [(&str, &str, &str); 3] = [
        ("learning_raw_plot", "What it learned (left muscles)", "raw"),
        (
            "learning_modes_plot",
            "Main rhythms (Fourier modes)",
            "modes",
        ),
        (
            "learning_abstract_plot",
            "Simplified controller",
            "abstract",
        ),
    ];
    for (name, title, kind) in rows {
        ui.separator();
        ui.vertical(|ui| {
            ui.set_width(width);
            ui.add(egui::Label::new(title).truncate())
                .on_hover_text(match kind {
                "raw" => "How hard each muscle pulls over the practice swim, as learned",
                "modes" => "The few waves (frequencies) that carry most of the learned pattern",
                _ => {
                    "The learned pattern rebuilt from those few waves: this is what the fish keeps"
                }
            });
            let r = Plot::new(name)
                .height(height)
                .include_y(0.0)
                .include_y(1.0)
                .allow_scroll(false)
                .allow_drag(false)
                .x_axis_label("time (s)")
                .legend(Legend::default())
                .show(ui, |plot| {
                    for (m, label) in shown_muscles() {
                        // The tail solid vermillion, the middle dashed sky blue,
                        // each named in the legend.
                        let (color, line) = if label == "tail" {
                            (super::palette::VERMILLION, egui_plot::LineStyle::Solid)
                        } else {
                            (
                                super::palette::SKY_BLUE,
                                egui_plot::LineStyle::dashed_dense(),
                            )
                        };
                        let points: PlotPoints = match kind {
                            "raw" => a
                                .times_secs
                                .iter()
                                .zip(&a.learned)
                                .map(|(t, u)| [f64::from(*t), f64::from(u[m])])
                                .collect(),
                            "modes" => {
                                let Some(mode) = a.controller.modes.first() else {
                                    continue;
                                };
                                a.times_secs
                                    .iter()
                                    .map(|&t| {
                                        [
                                            f64::from(t),
                                            f64::from(a.controller.mean[m] + mode.value_at(t)[m]),
                                        ]
                                    })
                                    .collect()
                            }
                            _ => a
                                .times_secs
                                .iter()
                                .map(|&t| [f64::from(t), f64::from(a.controller.value_at(t)[m])])
                                .collect(),
                        };
                        plot.line(Line::new(label, points).color(color).style(line).width(1.8));
                    }
                });
            rects.insert(name, r.response.rect);
        });
    }
}

/// Seconds between two refreshes of the current drill's abstraction (Fig. 8):
/// 0.5, chosen (it changes slowly, and abstracting costs a few milliseconds).
const ABSTRACTION_EVERY_SECS: f64 = 0.5;

/// The learning lab's panel: its controls, the progress and plots under the
/// tank, saving and loading controllers, and the default view on the buoys.
#[derive(Default)]
pub struct LearningPanel {
    /// The current drill abstracted (for Fig. 8), and when (app time, seconds).
    abstraction: Option<(f64, Abstraction)>,
    /// A controllers file the user picked, read asynchronously in the browser.
    pending_load: PendingFile,
    asked: Vec<LearningAction>,
}

/// How far the default camera stands from the learning lab's buoys, metres (7.5:
/// the buoys, the swimmer and the race lanes fill the view).
const LEARNING_VIEW_DISTANCE_M: f32 = 7.5;

impl ScenePanel for LearningPanel {
    fn before_frame(
        &mut self,
        lab: &mut Lab,
        now_secs: f64,
        _ctx: &egui::Context,
    ) -> Option<Notice> {
        let stale = self
            .abstraction
            .as_ref()
            .is_none_or(|(at, _)| now_secs - at > ABSTRACTION_EVERY_SECS);
        if stale && let Some(l) = lab.runs()[0].scene().learning() {
            self.abstraction = Some((now_secs, l.current_abstraction()));
        }
        self.apply_loaded_controllers(lab)
    }

    fn controls_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings, rects: &mut WidgetRects) {
        self.asked = learning_controls_ui(ui, &mut settings.learning, rects);
    }

    fn bottom_ui(
        &mut self,
        ui: &mut egui::Ui,
        lab: &Lab,
        _settings: &mut Settings,
        rects: &mut WidgetRects,
    ) {
        let run = &lab.runs()[0];
        let abstraction = self.abstraction.as_ref().map(|(_, a)| a);
        show_bottom_panel(
            ui,
            "learning_plots",
            LEARNING_PANEL_HEIGHT,
            rects,
            |ui, height, rects| learning_plots_ui(ui, run, abstraction, height, rects),
        );
    }

    fn apply(&mut self, lab: &mut Lab, ctx: &egui::Context) -> Option<Notice> {
        let mut notice = None;
        for action in std::mem::take(&mut self.asked) {
            let outcome = match action {
                LearningAction::ResetTraining => {
                    lab.reset_training();
                    self.abstraction = None;
                    None
                }
                LearningAction::StartRace => lab
                    .learning_mut()
                    .ok_or_else(|| "Open the learning lab first.".to_owned())
                    .and_then(|l| l.start_race().map_err(|e| e.to_string()))
                    .err()
                    .map(|reason| Notice::info(format!("No race yet: {reason}."))),
                LearningAction::SaveControllers => Some(
                    match controllers_json(lab).and_then(|json| {
                        Ok(save_text_file(
                            "shoal-controllers.json",
                            "application/json",
                            &json,
                            None,
                        )?)
                    }) {
                        Ok(message) => Notice::info(message),
                        Err(err) => Notice::error(err.to_string()),
                    },
                ),
                LearningAction::LoadControllers => open_text_file(
                    ".json,application/json",
                    "shoal-controllers.json",
                    &self.pending_load,
                    ctx,
                )
                .err()
                .map(|err| Notice::error(err.to_string())),
            };
            notice = outcome.or(notice);
        }
        notice
    }

    /// Name tags over the racers, matching the race table's numbers.
    fn draw_overlays(
        &self,
        view: &super::ViewContext,
        _settings: &Settings,
        _rects: &mut WidgetRects,
    ) {
        let Some(lab) = view.run.scene().learning() else {
            return;
        };
        let Some(race) = lab.race() else {
            return;
        };
        let leader = race.leader();
        let drawn = view.run.drawn_positions_m(view.alpha);
        let aspect = view.rect.width() / view.rect.height().max(1.0);
        // Index 0 is the swimmer between the buoys; the racers follow in order.
        for (k, p) in drawn.iter().skip(1).enumerate() {
            let Some(uv) = view.camera.project(*p + glam::Vec3::Y * 0.35, aspect) else {
                continue;
            };
            let at =
                view.rect.min + egui::vec2(uv.x * view.rect.width(), uv.y * view.rect.height());
            if !view.rect.contains(at) {
                continue;
            }
            let text = format!("{}{}", if Some(k) == leader { "★ " } else { "" }, k + 1);
            let galley = view.painter.layout_no_wrap(
                text,
                egui::FontId::proportional(14.0),
                egui::Color32::WHITE,
            );
            let rect = egui::Rect::from_center_size(at, galley.size()).expand(3.0);
            view.painter
                .rect_filled(rect, 3.0, egui::Color32::from_black_alpha(150));
            view.painter.galley(
                rect.min + egui::vec2(3.0, 3.0),
                galley,
                egui::Color32::WHITE,
            );
        }
    }

    fn framing(&self, run: &Run, _settings: &Settings) -> Option<Framing> {
        // The swimmers are small in a big tank: look between the buoys and the
        // race's start line behind the swimmer.
        let buoys = run.scene().learning()?.buoys_m();
        Some(Framing::Target {
            target_m: (buoys[0] + buoys[1]) * 0.5 - glam::Vec3::new(1.0, 0.0, 0.0),
            distance_m: LEARNING_VIEW_DISTANCE_M,
        })
    }
}

impl LearningPanel {
    /// Uses a controllers file the user picked, or says why it cannot be used.
    fn apply_loaded_controllers(&mut self, lab: &mut Lab) -> Option<Notice> {
        let text = self.pending_load.borrow_mut().take()?;
        let result = text.and_then(|text| {
            lab.learning_mut()
                .ok_or_else(|| "open the learning lab first".to_owned())
                .and_then(|l| l.load_json(&text).map_err(|e| e.to_string()))
        });
        Some(match result {
            Ok(()) => Notice::info("Controllers loaded: the swimmer now uses them."),
            Err(reason) => Notice::error(format!(
                "That file cannot be used, nothing was changed: {reason}"
            )),
        })
    }
}

/// Why the learned controllers could not be saved.
#[derive(Debug, thiserror::Error)]
pub enum SaveControllersError {
    /// Not in the learning lab.
    #[error(transparent)]
    NotHere(#[from] LabError),
    /// The controllers could not be written as JSON.
    #[error("the controllers could not be written: {0}")]
    Set(#[from] LearnedSetError),
    /// The file could not be saved.
    #[error(transparent)]
    File(#[from] FileError),
}

/// The learned controllers in use, as JSON (`shoal.save_controllers()`).
pub fn controllers_json(lab: &Lab) -> Result<String, SaveControllersError> {
    Ok(lab.runs()[0]
        .scene()
        .learning()
        .ok_or(LabError::LearningLabOnly("save_controllers"))?
        .save_json()?)
}
