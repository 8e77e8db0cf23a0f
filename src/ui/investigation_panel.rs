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
    Shows, Step, record,
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

fn window_id() -> egui::Id {
    egui::Id::unique("investigation_window")
}

/// Gap between the docked window and the tanks, and the screen's edge, points.
const DOCK_GAP: f32 = 6.0;

/// The narrowest the tanks get beside the docked window, points; narrower
/// aquariums (a phone) put the window under the tanks instead.
const DOCK_MIN_TANKS: f32 = 320.0;

/// The least height of tank kept above the window docked at the bottom.
const DOCK_MIN_TANK_HEIGHT: f32 = 160.0;

/// Where the investigation window sits while open, and the room left to the
/// tanks: the window never covers a tank, so what a prompt asks the student
/// to watch ("the shark near the school") stays in sight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dock {
    /// The window's outer rectangle (title bar and frame included).
    pub window: egui::Rect,
    /// The tanks' area (the aquarium less the window's strip).
    pub tanks: egui::Rect,
}

/// The dock in `aquarium` (the area the tanks are drawn in) for a window at
/// most `width` points wide: a column at the aquarium's right when the tanks
/// keep [`DOCK_MIN_TANKS`] beside it, else a strip along its bottom (a phone:
/// the tanks above it). `None` when the aquarium is too small for either (a
/// phone with the side panel open): the window then floats as before.
pub fn dock(aquarium: egui::Rect, width: f32) -> Option<Dock> {
    let (w, h) = (aquarium.width(), aquarium.height());
    if w >= width + DOCK_GAP * 2.0 + DOCK_MIN_TANKS {
        let left = aquarium.right() - width - DOCK_GAP;
        return Some(Dock {
            window: egui::Rect::from_min_max(
                egui::pos2(left, aquarium.top() + DOCK_GAP),
                egui::pos2(aquarium.right() - DOCK_GAP, aquarium.bottom() - DOCK_GAP),
            ),
            tanks: egui::Rect::from_min_max(
                aquarium.min,
                egui::pos2(left - DOCK_GAP, aquarium.bottom()),
            ),
        });
    }
    if w >= 200.0 && h >= DOCK_MIN_TANK_HEIGHT + 240.0 {
        let window_h = (h * 0.5).clamp(240.0, h - DOCK_MIN_TANK_HEIGHT);
        let top = aquarium.bottom() - window_h;
        return Some(Dock {
            window: egui::Rect::from_min_max(
                egui::pos2(aquarium.left() + DOCK_GAP, top),
                egui::pos2(aquarium.right() - DOCK_GAP, aquarium.bottom() - DOCK_GAP),
            ),
            tanks: egui::Rect::from_min_max(
                aquarium.min,
                egui::pos2(aquarium.right(), top - DOCK_GAP),
            ),
        });
    }
    None
}

/// Inner margin and stroke of a window's frame, each side, points: what
/// the outer rectangle adds to the content's width.
const FRAME_SIDES: f32 = 16.0;

/// Height of a window's title bar and frame, points.
const TITLE_AND_FRAME: f32 = 48.0;

/// The student's name this browser remembers (none natively).
fn stored_student_name() -> String {
    #[cfg(target_arch = "wasm32")]
    {
        crate::web::stored_student_name()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        String::new()
    }
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
    /// Where the window sits this frame (see [`dock`]), set when the tanks
    /// are laid out.
    dock: Option<Dock>,
    /// The student's name for the record, as typed; `None` until read from
    /// this browser's memory.
    student: Option<String>,
    /// The class step the teacher holds the class at (issue 37), if the
    /// student is in a class: the window does not go beyond it.
    class_hold: Option<String>,
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

    /// The teacher holds the class at `step` (`None`: no hold, or no class).
    pub fn set_class_hold(&mut self, step: Option<String>) {
        self.class_hold = step;
    }

    /// May the student go on to the class step `step` (look, predict, run,
    /// explain)? Shows why not under the button when held.
    fn may_go_to(&self, ui: &mut egui::Ui, step: &str) -> bool {
        let held = self.class_hold.as_deref();
        let ok = crate::class::may_go_to(step, held);
        if !ok && let Some(held) = held {
            let name = match held {
                "look" => ts("class-step-look"),
                "predict" => ts("class-step-predict"),
                "run" => ts("class-step-run"),
                _ => ts("class-step-explain"),
            };
            ui.label(egui::RichText::new(tr!("class-held", step = name)).strong());
        }
        ok
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

    /// The student's name (read once from this browser's memory).
    fn student(&mut self) -> &mut String {
        self.student.get_or_insert_with(stored_student_name)
    }

    /// Who, when and where, for the record (`page`: the page's address).
    fn record_info(&self, page: &str) -> record::RecordInfo {
        let (date, time) = record::local_now();
        record::RecordInfo {
            student: self.student.clone().unwrap_or_else(stored_student_name),
            date,
            time,
            page: page.to_owned(),
        }
    }

    /// The record as `(html, csv, the HTML file's name)`; `page` is the page's
    /// address, for the links that run each investigation again.
    pub fn record_files(&self, page: &str) -> (String, String, String) {
        let all = self.record();
        let info = self.record_info(page);
        (
            record::html(&all, &info),
            record::csv(&all, &info),
            record::file_name(&all, &info, "html"),
        )
    }

    /// The tanks' area in `aquarium` this frame: all of it, or what the docked
    /// investigation window leaves (the app lays the tanks out in it).
    pub fn tanks_area(&mut self, ctx: &egui::Context, aquarium: egui::Rect) -> egui::Rect {
        let expanded =
            egui::collapsing_header::CollapsingState::load(ctx, window_id().with("collapsing"))
                .is_none_or(|c| c.is_open());
        let width = (ctx.content_rect().width() - 24.0).clamp(200.0, WINDOW_WIDTH);
        self.dock = (self.current.is_some() && self.window_open && expanded)
            .then(|| dock(aquarium, width + FRAME_SIDES))
            .flatten();
        self.dock.map_or(aquarium, |d| d.tanks)
    }

    /// Starts the run on `lab` (the app calls it for [`InvestigationAction::Run`]).
    pub fn start_run(&mut self, lab: &mut Lab) -> Result<(), String> {
        let Some(p) = &mut self.current else {
            return Err(tr("inv-error-no-investigation"));
        };
        p.start_run().map_err(|e| e.to_string())?;
        self.measurement = Some(Measurement::start(p.investigation, lab)?);
        p.run_settings = Some(lab.settings().clone());
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
        page: &str,
        rects: &mut WidgetRects,
    ) -> Vec<InvestigationAction> {
        let mut actions = Vec::new();
        let screen = ctx.content_rect();
        let width = (screen.width() - 24.0).clamp(200.0, WINDOW_WIDTH);
        self.list_ui(ctx, width, page, rects, &mut actions);
        if self.current.is_none() || !self.window_open {
            return actions;
        }
        let mut open = self.window_open;
        let title = self
            .current
            .as_ref()
            .map_or("", |p| p.investigation.title.text());
        let window = egui::Window::new(tr!("inv-window-title", title = title))
            .id(window_id())
            .open(&mut open)
            .collapsible(true)
            .resizable(false)
            .constrain(true);
        // Docked beside (or under) the tanks, never over them; floating where
        // there is no room to dock.
        let (window, tall) = match self.dock {
            Some(dock) => {
                let inner = dock.window.width() - FRAME_SIDES;
                let tall = (dock.window.height() - TITLE_AND_FRAME).max(120.0);
                (
                    window
                        .fixed_pos(dock.window.min)
                        .movable(false)
                        .min_width(inner)
                        .max_width(inner)
                        .max_height(tall),
                    tall,
                )
            }
            None => (
                window
                    .default_width(width)
                    .max_width(width)
                    .max_height((screen.height() - 40.0).max(200.0))
                    .default_pos(screen.right_top() + egui::vec2(-width - 16.0, 44.0)),
                (screen.height() - 110.0).max(150.0),
            ),
        };
        let shown = window.show(ctx, |ui| {
            egui::ScrollArea::vertical()
                .max_height(tall)
                .min_scrolled_height(tall.min(700.0))
                .show(ui, |ui| {
                    self.contents_ui(ui, lab, settings, page, rects, &mut actions);
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
        page: &str,
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
                            self.record_buttons(ui, page, rects, actions);
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
        &mut self,
        ui: &mut egui::Ui,
        page: &str,
        rects: &mut WidgetRects,
        actions: &mut Vec<InvestigationAction>,
    ) {
        // The name, asked once: this browser remembers it (and only this one).
        let label = ui.label(ts("inv-student-name"));
        let before = self.student().clone();
        let name = ui
            .add(
                egui::TextEdit::singleline(self.student())
                    .desired_width(f32::INFINITY)
                    .char_limit(80)
                    .hint_text(ts("inv-student-name.hint")),
            )
            .labelled_by(label.id)
            .on_hover_text(ts("inv-student-name.help"));
        rects.insert("investigation_student", name.rect);
        if *self.student() != before {
            #[cfg(target_arch = "wasm32")]
            crate::web::store_student_name(self.student().trim());
        }
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .button(ts("inv-record"))
                .on_hover_text(ts("inv-record.help"));
            rects.insert("investigation_record", r.rect);
            let csv = ui
                .button(ts("inv-record-csv"))
                .on_hover_text(ts("inv-record-csv.help"));
            rects.insert("investigation_record_csv", csv.rect);
            let (html, table, file) = if r.clicked() || csv.clicked() {
                self.record_files(page)
            } else {
                return;
            };
            let saved = if r.clicked() {
                super::save_text_file(&file, "text/html", &html, Some(ts("inv-record-next")))
            } else {
                super::save_text_file(
                    &format!("{}.csv", file.trim_end_matches(".html")),
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
        page: &str,
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
                let may = self.may_go_to(ui, "predict");
                let r = ui.add_enabled(may, egui::Button::new(ts("inv-next-predict")));
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
            Step::Reveal => self.reveal_ui(ui, page, rects, actions),
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
            let may = self.may_go_to(ui, "run");
            let r = ui
                .add_enabled(p.can_run() && may, egui::Button::new(ts("inv-run")))
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
        let may = self.may_go_to(ui, "explain");
        let next = ui.add_enabled(may, egui::Button::new(ts("inv-next-explain")));
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
        // The plot the question refers to, back beside it.
        let shows = p.explain_shows();
        if let Some(outcome) = p.outcome.as_ref().map(|o| o.localized()) {
            match shows {
                Shows::Words => {}
                Shows::Result => {
                    let sketch = match (inv.prediction, p.prediction) {
                        (PredictionKind::Curve { shapes, .. }, Some(pred)) => {
                            shapes.get(pred.choice)
                        }
                        _ => None,
                    };
                    let r = ui.scope(|ui| outcome_ui(ui, outcome, sketch)).response;
                    rects.insert("investigation_explain_plot", r.rect);
                }
                Shows::Timelines => {
                    if let Some(last) = outcome.timelines.first().and_then(|t| t.points.last()) {
                        let r = ui
                            .scope(|ui| timelines_ui(ui, &outcome.timelines, last[0]))
                            .response;
                        rects.insert("investigation_explain_plot", r.rect);
                    }
                }
            }
        }
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
        page: &str,
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
        self.record_buttons(ui, page, rects, actions);
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The aquarium (the area right of the side panel, between the status
    /// line and the panel under the tank) at three screen sizes.
    fn aquarium(w: f32, h: f32, side_panel: f32) -> egui::Rect {
        egui::Rect::from_min_max(egui::pos2(side_panel, 0.0), egui::pos2(w, h - 60.0))
    }

    #[test]
    fn the_docked_window_never_covers_a_tank() {
        for (w, h, panel) in [
            (1920.0, 1080.0, 270.0),
            (1280.0, 800.0, 270.0),
            (1024.0, 700.0, 270.0),
            (390.0, 844.0, 0.0),
        ] {
            let a = aquarium(w, h, panel);
            let width = (w - 24.0).clamp(200.0, WINDOW_WIDTH) + FRAME_SIDES;
            let d = dock(a, width).expect("room to dock");
            assert!(
                !d.window.intersects(d.tanks),
                "{w}×{h}: {:?} {:?}",
                d.window,
                d.tanks
            );
            assert!(
                a.contains_rect(d.window) && a.contains_rect(d.tanks),
                "{w}×{h}"
            );
            // Two tanks laid out in the room left, side by side or stacked,
            // each lies in it.
            assert!(
                d.tanks.width() >= 200.0 && d.tanks.height() >= 150.0,
                "{w}×{h}: {:?}",
                d.tanks
            );
            if w >= 700.0 {
                assert!(
                    d.window.left() > d.tanks.right(),
                    "beside the tanks at {w}×{h}"
                );
                assert!(d.window.width() >= width, "the full width at {w}×{h}");
            } else {
                assert!(
                    d.window.top() > d.tanks.bottom(),
                    "under the tanks on a phone"
                );
            }
        }
        // A phone with its side panel open leaves no room: the window floats.
        assert_eq!(dock(aquarium(390.0, 844.0, 334.0), 380.0), None);
    }
}
