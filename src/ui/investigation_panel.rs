//! Guided investigations in the app (issue 15): the side panel's
//! *Investigations* button, the list of the five, and a small movable window
//! that takes a student through one, a question at a time: the intro, the
//! prediction (committed and then locked; *Run* stays disabled until then), the
//! run beside the prediction, prompts to explain, and what scientists found.
//! The tank stays visible and every control stays usable; after the reveal the
//! sandbox is open. *Download my record* saves the session's investigations as
//! one HTML file (and the numbers as CSV).
//!
//! The state machine, the measurements and the record are
//! [`crate::investigation`]; this file only draws them and reports what the app
//! must do.

use eframe::egui;

use super::WidgetRects;
use super::investigation_plot::{outcome_ui, sketch_ui, timelines_ui};
use super::scene_panel::Notice;
use crate::i18n::{num, tr, ts};
use crate::investigation::{
    INVESTIGATIONS, Investigation, InvestigationReport, Measurement, PredictionKind, Progress,
    Step, record,
};
use crate::lab::Lab;
use crate::settings::Settings;
use crate::tr;

/// Widest the window gets, points. Default 380: beside the tank on a laptop,
/// and on a phone it is the screen's width less a margin.
const WINDOW_WIDTH: f32 = 380.0;

fn list_id() -> egui::Id {
    egui::Id::unique("investigations_list_open")
}

/// The side panel's *Investigations* button (at its top, on the first
/// screen), and beside it *Experiment…* where the scene offers one.
pub fn investigations_button(ui: &mut egui::Ui, experiment: bool, rects: &mut WidgetRects) {
    ui.horizontal(|ui| {
        let r = ui
            .add(
                egui::Button::new(egui::RichText::new(ts("inv-button")).strong())
                    .min_size(egui::vec2(0.0, 30.0)),
            )
            .on_hover_text(ts("inv-button.help"));
        rects.insert("investigations", r.rect);
        if r.clicked() {
            let open = ui.data(|d| d.get_temp::<bool>(list_id()).unwrap_or(false));
            ui.data_mut(|d| d.insert_temp(list_id(), !open));
        }
        if experiment {
            super::experiment_panel::experiment_button(ui, rects);
        }
    });
}

/// What the window asks of the app.
pub enum InvestigationAction {
    /// Set the lab to these settings (an investigation's setup, or a control
    /// the window offers).
    Settings(Box<Settings>),
    /// Start the run (the lab is set up).
    Run,
    Notice(Notice),
}

/// The investigation under way, its run and those done before this session.
#[derive(Default)]
pub struct InvestigationPanel {
    current: Option<Progress>,
    measurement: Option<Measurement>,
    window_open: bool,
    /// Earlier investigations of this session (for the record).
    done: Vec<Progress>,
}

impl InvestigationPanel {
    /// Opens `investigation` from its start: returns the settings that set up
    /// its scene. The one under way goes to the record if it was predicted.
    pub fn open(
        &mut self,
        ctx: &egui::Context,
        investigation: &'static Investigation,
    ) -> Result<Settings, String> {
        let settings =
            crate::investigation::setup_settings(investigation).map_err(|e| e.to_string())?;
        self.close();
        self.current = Some(Progress::new(investigation));
        self.window_open = true;
        ctx.data_mut(|d| d.insert_temp(list_id(), false));
        ctx.request_repaint();
        Ok(settings)
    }

    /// Closes the investigation under way (kept for the record if predicted).
    pub fn close(&mut self) {
        self.measurement = None;
        if let Some(p) = self.current.take()
            && p.prediction.is_some()
        {
            self.done
                .retain(|d| d.investigation.id != p.investigation.id);
            self.done.push(p);
        }
        self.window_open = false;
    }

    /// The id of the investigation open, for links.
    pub fn open_id(&self) -> Option<&'static str> {
        self.current.as_ref().map(|p| p.investigation.id)
    }

    /// `shoal.state().investigation`.
    pub fn report(&self) -> Option<InvestigationReport> {
        self.current.as_ref().map(Progress::report)
    }

    /// Every investigation of the session with a committed prediction.
    pub fn record(&self) -> Vec<Progress> {
        let mut all: Vec<Progress> = self
            .done
            .iter()
            .filter(|d| Some(d.investigation.id) != self.open_id())
            .cloned()
            .collect();
        all.extend(
            self.current
                .iter()
                .filter(|p| p.prediction.is_some())
                .cloned(),
        );
        all
    }

    /// The record as `(html, csv)`.
    pub fn record_files(&self) -> (String, String) {
        let all = self.record();
        (record::html(&all), record::csv(&all))
    }

    /// Starts the run on `lab` (the app calls it for [`InvestigationAction::Run`]).
    pub fn start_run(&mut self, lab: &mut Lab) -> Result<(), String> {
        let Some(p) = &mut self.current else {
            return Err(tr("inv-error-no-investigation"));
        };
        p.start_run().map_err(|e| e.to_string())?;
        self.measurement = Some(Measurement::start(p.investigation, lab)?);
        Ok(())
    }

    /// This frame's part of the run, about `budget_secs` of wall time where
    /// the run computes on its own. True while it goes on (keep repainting).
    pub fn frame(&mut self, lab: &mut Lab, now_secs: f64, budget_secs: f64) -> bool {
        let (Some(p), Some(m)) = (&mut self.current, &mut self.measurement) else {
            return false;
        };
        if let Some(outcome) = m.advance(p, lab, budget_secs, now_secs) {
            p.finish_run(outcome);
            self.measurement = None;
            return false;
        }
        true
    }

    /// The list and the investigation's window.
    pub fn windows_ui(
        &mut self,
        ctx: &egui::Context,
        lab: &Lab,
        settings: &Settings,
        rects: &mut WidgetRects,
    ) -> Vec<InvestigationAction> {
        let mut actions = Vec::new();
        let screen = ctx.content_rect();
        let width = (screen.width() - 24.0).clamp(200.0, WINDOW_WIDTH);
        self.list_ui(ctx, width, rects, &mut actions);
        if self.current.is_none() || !self.window_open {
            return actions;
        }
        let mut open = self.window_open;
        let title = self
            .current
            .as_ref()
            .map_or("", |p| p.investigation.title.text());
        let shown = egui::Window::new(tr!("inv-window-title", title = title))
            .id(egui::Id::unique("investigation_window"))
            .open(&mut open)
            .collapsible(true)
            .resizable(false)
            .default_width(width)
            .max_width(width)
            .max_height((screen.height() - 40.0).max(200.0))
            .default_pos(screen.right_top() + egui::vec2(-width - 16.0, 44.0))
            .constrain(true)
            .show(ctx, |ui| {
                let tall = (screen.height() - 110.0).max(150.0);
                egui::ScrollArea::vertical()
                    .max_height(tall)
                    .min_scrolled_height(tall.min(700.0))
                    .show(ui, |ui| {
                        self.contents_ui(ui, lab, settings, rects, &mut actions);
                        crate::ui::focus_view::keep_focus_in_view(ui, "investigation");
                    });
            });
        if let Some(shown) = shown {
            rects.insert("investigation_window", shown.response.rect);
        }
        self.window_open = open;
        actions
    }

    fn list_ui(
        &mut self,
        ctx: &egui::Context,
        width: f32,
        rects: &mut WidgetRects,
        actions: &mut Vec<InvestigationAction>,
    ) {
        let mut open = ctx.data(|d| d.get_temp::<bool>(list_id()).unwrap_or(false));
        if !open {
            return;
        }
        let screen = ctx.content_rect();
        let mut chosen = None;
        let mut resume = false;
        let paused_title = self
            .current
            .as_ref()
            .filter(|_| !self.window_open)
            .map(|p| p.investigation.title.text());
        let shown = egui::Window::new(ts("inv-list-title"))
            .id(egui::Id::unique("investigations_list"))
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .default_width(width)
            .max_width(width)
            .default_pos(screen.left_top() + egui::vec2(12.0, 44.0))
            .constrain(true)
            .show(ctx, |ui| {
                ui.label(egui::RichText::new(ts("inv-list-intro")).weak());
                if let Some(title) = paused_title {
                    let r = ui
                        .button(tr!("inv-continue", title = title))
                        .on_hover_text(ts("inv-continue.help"));
                    rects.insert("investigation_continue", r.rect);
                    resume = r.clicked();
                }
                let tall = (screen.height() - 140.0).max(150.0);
                egui::ScrollArea::vertical()
                    .max_height(tall)
                    .min_scrolled_height(tall.min(620.0))
                    .show(ui, |ui| {
                        for inv in &INVESTIGATIONS {
                            ui.separator();
                            let r = ui
                                .button(egui::RichText::new(inv.title.text()).strong())
                                .on_hover_text(inv.question.text());
                            rects.insert(&format!("investigation_{}", inv.id), r.rect);
                            if r.clicked() {
                                chosen = Some(inv);
                            }
                            ui.label(inv.teaser.text());
                            ui.label(
                                egui::RichText::new(tr!("inv-minutes", minutes = inv.minutes))
                                    .small()
                                    .weak(),
                            );
                        }
                        if !self.record().is_empty() {
                            ui.separator();
                            self.record_buttons(ui, rects, actions);
                        }
                    });
            });
        if let Some(shown) = shown {
            rects.insert("investigations_list", shown.response.rect);
        }
        if resume {
            self.window_open = true;
            open = false;
        }
        ctx.data_mut(|d| d.insert_temp(list_id(), open));
        if let Some(inv) = chosen {
            match self.open(ctx, inv) {
                Ok(settings) => actions.push(InvestigationAction::Settings(Box::new(settings))),
                Err(e) => actions.push(InvestigationAction::Notice(Notice::error(e))),
            }
        }
    }

    fn record_buttons(
        &self,
        ui: &mut egui::Ui,
        rects: &mut WidgetRects,
        actions: &mut Vec<InvestigationAction>,
    ) {
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .button(ts("inv-record"))
                .on_hover_text(ts("inv-record.help"));
            rects.insert("investigation_record", r.rect);
            let csv = ui
                .button(ts("inv-record-csv"))
                .on_hover_text(ts("inv-record-csv.help"));
            rects.insert("investigation_record_csv", csv.rect);
            let (html, table) = if r.clicked() || csv.clicked() {
                self.record_files()
            } else {
                return;
            };
            let saved = if r.clicked() {
                super::save_text_file(
                    "shoal-my-investigations.html",
                    "text/html",
                    &html,
                    Some(ts("inv-record-next")),
                )
            } else {
                super::save_text_file(
                    "shoal-my-investigations.csv",
                    "text/csv",
                    &table,
                    Some(ts("inv-record-csv-next")),
                )
            };
            actions.push(InvestigationAction::Notice(match saved {
                Ok(m) => Notice::info(m),
                Err(e) => Notice::error(e.to_string()),
            }));
        });
    }

    fn contents_ui(
        &mut self,
        ui: &mut egui::Ui,
        lab: &Lab,
        settings: &Settings,
        rects: &mut WidgetRects,
        actions: &mut Vec<InvestigationAction>,
    ) {
        let Some(p) = &self.current else {
            return;
        };
        steps_line(ui, p.step);
        ui.separator();
        match p.step {
            Step::Intro => {
                let inv = p.investigation;
                ui.label(inv.intro.text());
                let r = ui.button(ts("inv-next-predict"));
                rects.insert("investigation_next", r.rect);
                if r.clicked()
                    && let Some(p) = &mut self.current
                {
                    p.begin();
                }
            }
            Step::Predict => self.predict_ui(ui, rects),
            Step::Run => self.run_ui(ui, lab, settings, rects, actions),
            Step::Explain => self.explain_ui(ui, rects),
            Step::Reveal => self.reveal_ui(ui, rects, actions),
        }
    }

    fn predict_ui(&mut self, ui: &mut egui::Ui, rects: &mut WidgetRects) {
        let Some(p) = &mut self.current else {
            return;
        };
        let inv = p.investigation;
        ui.label(egui::RichText::new(inv.question.text()).strong());
        for k in 0..p.answer_count() {
            let r = ui.selectable_label(p.pending == Some(k), p.answer_text(k));
            rects.insert(&format!("investigation_choice_{k}"), r.rect);
            if r.clicked() {
                // Always allowed here: the prediction is not committed yet.
                let _ = p.choose(k);
            }
        }
        if let (
            PredictionKind::Curve {
                shapes,
                x_label,
                y_label,
            },
            Some(k),
        ) = (inv.prediction, p.pending)
            && let Some(shape) = shapes.get(k)
        {
            sketch_ui(ui, shape, x_label.text(), y_label.text());
        }
        ui.horizontal(|ui| {
            let commit = ui
                .add_enabled(p.pending.is_some(), egui::Button::new(ts("inv-commit")))
                .on_hover_text(ts("inv-commit.help"))
                .on_disabled_hover_text(ts("inv-commit.disabled"));
            rects.insert("investigation_commit", commit.rect);
            if commit.clicked() {
                let _ = p.commit();
            }
            let run = ui
                .add_enabled(false, egui::Button::new(ts("inv-run")))
                .on_disabled_hover_text(ts("inv-run.disabled"));
            rects.insert("investigation_run", run.rect);
        });
    }

    fn run_ui(
        &mut self,
        ui: &mut egui::Ui,
        lab: &Lab,
        settings: &Settings,
        rects: &mut WidgetRects,
        actions: &mut Vec<InvestigationAction>,
    ) {
        let Some(p) = &self.current else {
            return;
        };
        let inv = p.investigation;
        ui.label(egui::RichText::new(inv.question.text()).strong());
        if let Some(pred) = p.prediction {
            let r = ui.label(tr!(
                "inv-your-prediction",
                prediction = p.answer_text(pred.choice)
            ));
            rects.insert("investigation_prediction", r.rect);
        }
        ui.label(egui::RichText::new(inv.run_hint.text()).weak());
        if !p.run_started {
            let r = ui
                .add_enabled(p.can_run(), egui::Button::new(ts("inv-run")))
                .on_hover_text(ts("inv-run.help"));
            rects.insert("investigation_run", r.rect);
            if r.clicked() {
                actions.push(InvestigationAction::Run);
            }
            return;
        }
        if let Some(m) = &self.measurement {
            let (fraction, text) = m.status(lab);
            ui.add(egui::ProgressBar::new(fraction.clamp(0.0, 1.0)).text(text));
            if let Some(run) = m.alignment() {
                alignment_controls(ui, run, settings, rects, actions);
            }
            if let Some(secs) = m.catches_secs() {
                let live = crate::investigation::measure::catches_timelines(lab, secs);
                timelines_ui(ui, &live, secs);
            }
        }
        let sketch = match (inv.prediction, p.prediction) {
            (PredictionKind::Curve { shapes, .. }, Some(pred)) => shapes.get(pred.choice),
            _ => None,
        };
        let Some(outcome) = p.outcome.as_ref().map(|o| o.localized()) else {
            if let (
                Some(shape),
                PredictionKind::Curve {
                    x_label, y_label, ..
                },
            ) = (sketch, inv.prediction)
            {
                sketch_ui(ui, shape, x_label.text(), y_label.text());
            }
            return;
        };
        let r = ui.label(&outcome.summary);
        rects.insert("investigation_result", r.rect);
        outcome_ui(ui, outcome, sketch);
        if let Some(last) = outcome.timelines.first().and_then(|t| t.points.last()) {
            timelines_ui(ui, &outcome.timelines, last[0]);
        }
        ui.label(egui::RichText::new(&outcome.verdict).strong());
        let next = ui.button(ts("inv-next-explain"));
        rects.insert("investigation_next", next.rect);
        if next.clicked()
            && let Some(p) = &mut self.current
        {
            let _ = p.advance();
        }
    }

    fn explain_ui(&mut self, ui: &mut egui::Ui, rects: &mut WidgetRects) {
        let Some(p) = &mut self.current else {
            return;
        };
        let inv = p.investigation;
        if let Some(outcome) = &p.outcome {
            ui.label(egui::RichText::new(&outcome.localized().summary).weak());
        }
        ui.label(tr!(
            "inv-question-of",
            number = p.prompt + 1,
            count = inv.prompts.len()
        ));
        let prompt = ui.label(egui::RichText::new(inv.prompts[p.prompt].text()).strong());
        let answer = ui
            .add(
                egui::TextEdit::multiline(&mut p.explanations[p.prompt])
                    .desired_rows(3)
                    .desired_width(f32::INFINITY)
                    .hint_text(ts("inv-answer-hint")),
            )
            // A screen reader names the box by its question.
            .labelled_by(prompt.id);
        rects.insert("investigation_answer", answer.rect);
        let last = p.prompt + 1 == inv.prompts.len();
        let next = ui.button(if last {
            ts("inv-to-reveal")
        } else {
            ts("inv-next-question")
        });
        rects.insert("investigation_next", next.rect);
        if next.clicked() {
            let _ = p.advance();
        }
    }

    fn reveal_ui(
        &mut self,
        ui: &mut egui::Ui,
        rects: &mut WidgetRects,
        actions: &mut Vec<InvestigationAction>,
    ) {
        let Some(p) = &self.current else {
            return;
        };
        let inv = p.investigation;
        ui.label(egui::RichText::new(ts("inv-found")).strong());
        let r = ui.label(inv.reveal.text());
        rects.insert("investigation_reveal", r.rect);
        ui.label(egui::RichText::new(inv.reference.text()).small().weak());
        if let Some(outcome) = &p.outcome {
            ui.label(
                egui::RichText::new(tr!("inv-your-run", summary = &outcome.localized().summary))
                    .weak(),
            );
        }
        ui.separator();
        ui.label(ts("inv-sandbox"));
        self.record_buttons(ui, rects, actions);
        let other = ui.button(ts("inv-others"));
        rects.insert("investigation_others", other.rect);
        if other.clicked() {
            ui.data_mut(|d| d.insert_temp(list_id(), true));
        }
    }
}

/// "Question · Predict · Run · Explain · Found", the step on show in bold.
fn steps_line(ui: &mut egui::Ui, step: Step) {
    ui.horizontal_wrapped(|ui| {
        ui.spacing_mut().item_spacing.x = 4.0;
        let steps = [
            (Step::Intro, ts("inv-step-look")),
            (Step::Predict, ts("inv-step-predict")),
            (Step::Run, ts("inv-step-run")),
            (Step::Explain, ts("inv-step-explain")),
            (Step::Reveal, ts("inv-step-found")),
        ];
        for (k, (s, name)) in steps.iter().enumerate() {
            if k > 0 {
                ui.label(egui::RichText::new("·").weak());
            }
            if *s == step {
                ui.label(egui::RichText::new(*name).strong().underline());
            } else {
                ui.label(egui::RichText::new(*name).weak());
            }
        }
    });
}

/// *Is there a leader?*: alignment off and on (through the tank's own
/// setting, so its slider moves too) and what has been measured so far.
fn alignment_controls(
    ui: &mut egui::Ui,
    run: &crate::investigation::measure::AlignmentRun,
    settings: &Settings,
    rects: &mut WidgetRects,
    actions: &mut Vec<InvestigationAction>,
) {
    let preset_alignment = settings
        .left
        .preset
        .weights_and_mode()
        .map_or(26.0, |(w, _)| w[1]);
    ui.horizontal(|ui| {
        let on = settings.left.alignment > 0.0;
        let off_button = ui
            .add_enabled(on, egui::Button::new(ts("inv-alignment-off")))
            .on_hover_text(ts("inv-alignment-off.help"));
        rects.insert("investigation_alignment_off", off_button.rect);
        let on_button = ui
            .add_enabled(!on, egui::Button::new(ts("inv-alignment-on")))
            .on_hover_text(ts("inv-alignment-on.help"));
        rects.insert("investigation_alignment_on", on_button.rect);
        let mut changed = settings.clone();
        if off_button.clicked() {
            changed.left.alignment = 0.0;
        } else if on_button.clicked() {
            changed.left.alignment = if preset_alignment > 0.0 {
                preset_alignment
            } else {
                26.0
            };
        } else {
            return;
        }
        changed.left.preset = changed.left.matching_preset();
        actions.push(InvestigationAction::Settings(Box::new(changed)));
    });
    let (on, off) = run.means();
    let value = |v: Option<f64>| v.map_or_else(|| "–".into(), |v| num(v, 2));
    ui.label(tr!(
        "inv-alignment-so-far",
        on = value(on),
        off = value(off),
        fish = if run.inspected.is_empty() {
            tr("inv-none-clicked")
        } else {
            run.inspected
                .iter()
                .map(|(f, _)| f.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        }
    ));
}
