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
use crate::i18n::{num, tr, ts};
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
use crate::tr;

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
    ui.label(egui::RichText::new(ts("learning-heading")).strong());
    egui::Grid::new("learning_grid")
        .num_columns(2)
        .spacing([8.0, 6.0])
        .show(ui, |ui| {
            let help = ts("learning-learner.help");
            control_row(
                ui,
                rects,
                "learning.species",
                |ui| {
                    ui.label(ts("learning-learner")).on_hover_text(help);
                },
                |ui, rects| {
                    ui.horizontal(|ui| {
                        for (species, label, name) in [
                            (BodySpecies::Fish, ts("learning-fish"), "learning_fish"),
                            (BodySpecies::Shark, ts("learning-shark"), "learning_shark"),
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
            ts("learning-train-pause")
        } else {
            ts("learning-train-start")
        };
        control(ui, rects, "learning.training", |ui, rects| {
            let r = ui
                .button(label)
                .on_hover_text(ts("learning-train-start.help"));
            rects.insert("learning_train", r.rect);
            if r.clicked() {
                learning.training = !learning.training;
            }
        });
        let r = ui
            .button(ts("learning-reset"))
            .on_hover_text(ts("learning-reset.help"));
        rects.insert("learning_reset", r.rect);
        if r.clicked() {
            actions.push(LearningAction::ResetTraining);
            learning.training = false;
        }
    });
    let help = ts("learning-swimmer-uses.help");
    ui.label(ts("learning-swimmer-uses")).on_hover_text(help);
    control(ui, rects, "learning.controller", |ui, rects| {
        ui.horizontal(|ui| {
            for (choice, label, name) in [
                (
                    ControllerChoice::Learned,
                    ts("learning-learned"),
                    "learning_learned",
                ),
                (
                    ControllerChoice::HandTuned,
                    ts("learning-hand-tuned"),
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
        let r = ui
            .button(ts("learning-race"))
            .on_hover_text(ts("learning-race.help"));
        rects.insert("learning_race", r.rect);
        if r.clicked() {
            actions.push(LearningAction::StartRace);
        }
    });
    ui.horizontal(|ui| {
        let r = ui
            .button(ts("learning-save"))
            .on_hover_text(ts("learning-save.help"));
        rects.insert("learning_save", r.rect);
        if r.clicked() {
            actions.push(LearningAction::SaveControllers);
        }
        let r = ui
            .button(ts("learning-load"))
            .on_hover_text(ts("learning-load.help"));
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
        Some(k) => tr!(
            "learning-drill-title",
            number = k + 1,
            count = drills,
            drill = drill_label(&lab.drills()[k])
        ),
        None => tr!("learning-all-drills", count = drills),
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
        ui.label(tr!(
            "learning-tries",
            tries = t.evaluations(),
            total = lab.annealing_steps(),
            best = num(f64::from(t.best_evaluation().objective), 3),
            temperature = num(f64::from(t.temperature()), 4)
        ))
        .on_hover_text(ts("learning-tries.help"));
    }
    let (_, source) = lab.learned_set();
    ui.label(tr!(
        "learning-in-use",
        source = ts(match source {
            SetSource::Shipped => "learning-source-shipped",
            SetSource::TrainedHere => "learning-source-here",
            SetSource::Loaded => "learning-source-loaded",
        })
    ));
    let times = lab.buoy_times_secs();
    ui.label(match times.as_slice() {
        [] => tr("learning-swimmer-on-its-way"),
        [a] => tr!("learning-swimmer-first-buoy", first = num(f64::from(*a), 1)),
        [a, b, ..] => tr!(
            "learning-swimmer-buoys",
            first = num(f64::from(*a), 1),
            second = num(f64::from(*b), 1)
        ),
    });
    if let Some(race) = lab.race() {
        let distances = race.distances_m();
        let leader = race.leader();
        let r = ui
            .vertical(|ui| {
                ui.label(tr!(
                    "learning-race-after",
                    seconds = num(f64::from(race.time_secs()), 1)
                ));
                egui::Grid::new("race_results")
                    .num_columns(3)
                    .spacing([12.0, 2.0])
                    .striped(true)
                    .show(ui, |ui| {
                        ui.strong(ts("learning-race-racer"));
                        ui.strong(ts("learning-race-practice"));
                        ui.strong(ts("learning-race-distance"));
                        ui.end_row();
                        for (k, (e, d)) in race.entrants().zip(&distances).enumerate() {
                            let first = Some(k) == leader;
                            let name = format!("{}{}", if first { "★ " } else { "" }, k + 1);
                            ui.label(name);
                            ui.label(e.annealing_steps.to_string());
                            ui.label(tr!(
                                "learning-race-metres",
                                distance = num(f64::from(*d), 2)
                            ));
                            ui.end_row();
                        }
                    });
                // What the race shows (and does not): the paper's Fig. 7 has the
                // longest-trained shark win; ours levels off after a few thousand tries.
                ui.add(egui::Label::new(ts("learning-race-what")).wrap());
            })
            .response;
        rects.insert("learning_race_result", r.rect);
    }
}

fn objective_plot_ui(ui: &mut egui::Ui, lab: &LearningLab, height: f32, rects: &mut WidgetRects) {
    // One line, as `height` assumes: a narrow window cuts the caption short.
    ui.add(egui::Label::new(ts("learning-objective-caption")).truncate())
        .on_hover_text(ts("learning-objective-caption.help"));
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
        .x_axis_label(ts("learning-axis-tries"))
        .show(ui, |plot| {
            // Named in the legend, and told apart by the line as well as the
            // colour: the try now dotted grey, the best so far solid green.
            plot.line(
                Line::new(ts("learning-line-now"), series(false))
                    .color(super::palette::GREY)
                    .style(egui_plot::LineStyle::dotted_dense()),
            );
            plot.line(
                Line::new(ts("learning-line-best"), series(true))
                    .color(super::palette::BLUISH_GREEN)
                    .width(2.0),
            );
        });
    rects.insert("learning_objective_plot", r.response.rect);
}

/// The four muscles of the left side that swim and turn (middle and tail
/// segments, dorsal), the ones Fig. 8 shows: each muscle, its name in the
/// legend, and whether it is the tail's.
fn shown_muscles() -> [(usize, &'static str, bool); 2] {
    [
        (
            muscle_index(MuscleSegment::Middle, Side::Left),
            ts("learning-muscle-middle"),
            false,
        ),
        (
            muscle_index(MuscleSegment::Posterior, Side::Left),
            ts("learning-muscle-tail"),
            true,
        ),
    ]
}

/// A drill in words ("swim as far as it can", "turn left at 15°/s").
fn drill_label(task: &Task) -> String {
    match *task {
        Task::ReachTarget { .. } => tr("learning-drill-swim-far"),
        Task::HoldSpeed {
            speed_body_lengths_per_sec,
        } => tr!(
            "learning-drill-hold-speed",
            speed = speed_body_lengths_per_sec
        ),
        Task::TurnHeading {
            turn_rate_deg_per_sec,
            ..
        } => tr!(
            if turn_rate_deg_per_sec >= 0.0 {
                "learning-drill-turn-left"
            } else {
                "learning-drill-turn-right"
            },
            rate = turn_rate_deg_per_sec.abs()
        ),
    }
}

fn fig8_ui(ui: &mut egui::Ui, a: &Abstraction, width: f32, height: f32, rects: &mut WidgetRects) {
    let rows: [(&str, &str, &str, &str); 3] = [
        (
            "learning_raw_plot",
            ts("learning-fig8-raw"),
            ts("learning-fig8-raw.help"),
            "raw",
        ),
        (
            "learning_modes_plot",
            ts("learning-fig8-modes"),
            ts("learning-fig8-modes.help"),
            "modes",
        ),
        (
            "learning_abstract_plot",
            ts("learning-fig8-abstract"),
            ts("learning-fig8-abstract.help"),
            "abstract",
        ),
    ];
    for (name, title, help, kind) in rows {
        ui.separator();
        ui.vertical(|ui| {
            ui.set_width(width);
            ui.add(egui::Label::new(title).truncate())
                .on_hover_text(help);
            let r = Plot::new(name)
                .height(height)
                .include_y(0.0)
                .include_y(1.0)
                .allow_scroll(false)
                .allow_drag(false)
                .x_axis_label(ts("learning-axis-time"))
                .legend(Legend::default())
                .show(ui, |plot| {
                    for (m, label, tail) in shown_muscles() {
                        // The tail solid vermillion, the middle dashed sky blue,
                        // each named in the legend.
                        let (color, line) = if tail {
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
                    .ok_or_else(|| tr("learning-open-first"))
                    .and_then(|l| l.start_race().map_err(|e| e.to_string()))
                    .err()
                    .map(|reason| Notice::info(tr!("learning-no-race", reason = reason))),
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
                .ok_or_else(|| tr("learning-open-first-reason"))
                .and_then(|l| l.load_json(&text).map_err(|e| e.to_string()))
        });
        Some(match result {
            Ok(()) => Notice::info(tr("learning-loaded")),
            Err(reason) => Notice::error(tr!("learning-load-refused", reason = reason)),
        })
    }
}

/// Why the learned controllers could not be saved.
#[derive(Debug)]
pub enum SaveControllersError {
    /// Not in the learning lab.
    NotHere(LabError),
    /// The controllers could not be written as JSON.
    Set(LearnedSetError),
    /// The file could not be saved.
    File(FileError),
}

impl From<LabError> for SaveControllersError {
    fn from(e: LabError) -> Self {
        Self::NotHere(e)
    }
}

impl From<LearnedSetError> for SaveControllersError {
    fn from(e: LearnedSetError) -> Self {
        Self::Set(e)
    }
}

impl From<FileError> for SaveControllersError {
    fn from(e: FileError) -> Self {
        Self::File(e)
    }
}

impl std::fmt::Display for SaveControllersError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NotHere(e) => std::fmt::Display::fmt(e, f),
            Self::Set(e) => f.write_str(&tr!("learning-save-failed", reason = e.to_string())),
            Self::File(e) => std::fmt::Display::fmt(e, f),
        }
    }
}

impl std::error::Error for SaveControllersError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Set(e) => Some(e),
            _ => None,
        }
    }
}

/// The learned controllers in use, as JSON (`shoal.save_controllers()`).
pub fn controllers_json(lab: &Lab) -> Result<String, SaveControllersError> {
    Ok(lab.runs()[0]
        .scene()
        .learning()
        .ok_or(LabError::LearningLabOnly("save_controllers"))?
        .save_json()?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{Lang, with_lang};
    use crate::sim::common::obstacle::ObstacleError;
    use crate::sim::learning::learning_lab::RaceNotReady;

    #[test]
    fn the_learning_lab_and_the_rocks_speak_spanish() {
        with_lang(Lang::Es, || {
            assert_eq!(ts("learning-train-start"), "Empezar a entrenar");
            assert_eq!(
                drill_label(&Task::TurnHeading {
                    turn_rate_deg_per_sec: -22.5,
                    speed_body_lengths_per_sec: 0.5,
                }),
                "girar a la derecha a 22,5°/s"
            );
            assert_eq!(
                drill_label(&Task::HoldSpeed {
                    speed_body_lengths_per_sec: 0.25
                }),
                "nadar en línea recta a 0,25 largos de cuerpo/s"
            );
            assert_eq!(
                tr!("learning-swimmer-first-buoy", first = num(3.34, 1)),
                "Nadador: primera boya a los 3,3 s"
            );
            let race = RaceNotReady {
                done: 12,
                needed: 6840,
            }
            .to_string();
            assert!(race.contains("recocido simulado"), "{race}");
            // The race window says plainly that the copies end about level.
            let what = ts("learning-race-what");
            assert!(
                what.contains("casi igual de rápido") && what.contains("no siempre gana"),
                "{what}"
            );
            let glass = ObstacleError::NearTheGlass {
                x_m: 1.5,
                z_m: -2.25,
            }
            .to_string();
            assert_eq!(
                glass,
                "debe quedar al menos a 1 m del vidrio (está en (1,50; −2,25) m)"
            );
            assert_eq!(
                LabError::LearningLabOnly("train").to_string(),
                "train() solo funciona en el laboratorio de aprendizaje"
            );
        });
        // English stays the default, as the automation API's scripts read it.
        let what = ts("learning-race-what");
        assert!(
            what.contains("about equally fast") && what.contains("does not always win"),
            "{what}"
        );
        assert_eq!(
            LabError::LearningLabOnly("train").to_string(),
            "train() works in the learning lab only"
        );
        assert_eq!(
            drill_label(&Task::TurnHeading {
                turn_rate_deg_per_sec: 15.0,
                speed_body_lengths_per_sec: 0.5,
            }),
            Task::TurnHeading {
                turn_rate_deg_per_sec: 15.0,
                speed_body_lengths_per_sec: 0.5,
            }
            .label()
        );
    }
}
