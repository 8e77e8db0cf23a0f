//! The *Experiment…* window (issue 16): a student chooses a setting to vary
//! (and optionally a second), its levels, the seeds, the warm-up and measuring
//! times and the measures; sees how many runs that is and about how long; and
//! starts it. The runs go on a slice per frame (see
//! [`crate::experiment::session`]) while the tank keeps swimming; a progress
//! bar, *Pause* and *Cancel*; then the dose–response plots and table
//! (`experiment_plot.rs`), *Download CSV* and *Save design* (the file
//! `shoal-lab` runs headless).
//!
//! Nothing here knows a scene: the settings a factor may vary come from the
//! engine ([`factor_keys`]), the measures from [`Measure::available_in`], and
//! the base settings are the current ones. The schooling lab's side panel has
//! the button ([`experiment_button`]).

use eframe::egui;
use serde_json::{Value, json};

use super::WidgetRects;
use super::experiment_plot::{WatchRequest, factor_text, level_text, results_ui, shows_side};
use super::scene_panel::Notice;
use crate::experiment::design::{
    Factor, MeasureChoice, Replicates, default_levels, factor_keys, is_switch, settings_value,
};
use crate::experiment::session::{FRAME_BUDGET_SECS, frame_budget_secs};
use crate::experiment::{
    Design, DesignError, ExperimentReport, ExperimentSession, Measure, Plan, RunSpec, Summary,
};
use crate::i18n::{num, tr, ts};
use crate::settings::{Scene, Settings};
use crate::tr;

/// A browser is slower than the native core the engine's estimate is for:
/// about 2.5× (docs/benchmarks.md), used until the lab's own cost is measured.
const BROWSER_SLOWDOWN: f64 = if cfg!(target_arch = "wasm32") {
    2.5
} else {
    1.0
};

/// Frames a second assumed for the estimate's wall time (the experiment gets
/// [`frame_budget_secs`] of each). Default 40: between the 60 of an idle page
/// and the 30 the budget aims to keep.
const ASSUMED_FPS: f64 = 40.0;

fn open_id() -> egui::Id {
    egui::Id::unique("experiment_open")
}

fn set_open(ctx: &egui::Context, open: bool) {
    ctx.data_mut(|d| d.insert_temp(open_id(), open));
}

/// The side panel's *Experiment…* button: opens (or closes) the window. Not
/// in a student view with mystery values: the experiment's table prints every
/// setting.
pub fn experiment_button(ui: &mut egui::Ui, rects: &mut WidgetRects) {
    if super::studio_panel::has_mystery(ui) {
        return;
    }
    let r = ui
        .add(egui::Button::new(ts("experiment-open")).min_size(egui::vec2(0.0, 30.0)))
        .on_hover_text(ts("experiment-open.help"));
    rects.insert("experiment", r.rect);
    if r.clicked() {
        let open = ui.data(|d| d.get_temp::<bool>(open_id()).unwrap_or(false));
        set_open(ui.ctx(), !open);
    }
}

/// One factor as the form holds it: a setting and a range of levels (an on/off
/// setting's levels are off and on).
#[derive(Clone, Debug, PartialEq)]
pub struct FactorForm {
    pub key: String,
    pub from: f64,
    pub to: f64,
    pub steps: u32,
}

impl FactorForm {
    /// `key` over its slider's range, or a round part of it, in about `steps`
    /// levels ([`default_levels`]).
    fn new(base: &Settings, key: &str, steps: u32) -> Self {
        let (from, to, steps) = default_levels(base, key, steps).unwrap_or((0.0, 1.0, steps));
        Self {
            key: key.to_owned(),
            from,
            to,
            steps,
        }
    }

    fn factor(&self, base: &Settings) -> Factor {
        Factor {
            key: self.key.clone(),
            levels: if is_switch(base, &self.key) {
                json!([false, true])
            } else {
                json!({"from": self.from, "to": self.to, "steps": self.steps})
            },
        }
    }
}

/// One measure's row of the form.
#[derive(Clone, Debug, PartialEq)]
pub struct MeasureForm {
    pub measure: Measure,
    pub on: bool,
    /// The last sample instead of the mean over the window.
    pub last: bool,
}

/// The window's form: everything a [`Design`] needs but the base settings
/// (the current ones, given when the design is made).
#[derive(Clone, Debug, PartialEq)]
pub struct DesignForm {
    pub name: String,
    pub factor: FactorForm,
    pub second: Option<FactorForm>,
    pub seeds: u32,
    pub first_seed: u64,
    pub warmup_secs: f64,
    pub measure_secs: f64,
    pub measures: Vec<MeasureForm>,
}

impl DesignForm {
    /// A first sweep for `base`'s scene: its first settable factor (alignment
    /// in the schooling lab), 3 seeds, 10 s warm-up, 20 s measured, the first
    /// measure on.
    pub fn new(base: &Settings, keys: &[String]) -> Self {
        let key = keys
            .iter()
            .find(|k| k.ends_with(".alignment"))
            .or_else(|| keys.first())
            .cloned()
            .unwrap_or_default();
        let measures: Vec<MeasureForm> = Measure::ALL
            .into_iter()
            .filter(|m| m.available_in(base.scene))
            .enumerate()
            .map(|(k, measure)| MeasureForm {
                measure,
                on: k == 0,
                last: measure.is_counter(),
            })
            .collect();
        Self {
            name: format!("{}-sweep", key.rsplit('.').next().unwrap_or("my")),
            factor: FactorForm::new(base, &key, 3),
            second: None,
            seeds: 3,
            first_seed: 1,
            warmup_secs: 10.0,
            measure_secs: 20.0,
            measures,
        }
    }

    /// The design: the scene and its own settings as they are now, then the form.
    pub fn design(&self, base: &Settings) -> Design {
        let section = base.scene.class().facts().settings_section;
        let all = settings_value(base);
        let mut settings = serde_json::Map::new();
        settings.insert("scene".into(), Value::from(base.scene.name()));
        if let Some(v) = all.get(section) {
            settings.insert(section.into(), v.clone());
        }
        Design {
            name: self.name.clone(),
            description: String::new(),
            link: None,
            settings: Some(Value::Object(settings)),
            factors: std::iter::once(&self.factor)
                .chain(&self.second)
                .map(|f| f.factor(base))
                .collect(),
            replicates: Replicates {
                count: Some(self.seeds),
                first_seed: Some(self.first_seed),
                seeds: None,
            },
            warmup_secs: self.warmup_secs,
            measure_secs: self.measure_secs,
            measures: self
                .measures
                .iter()
                .filter(|m| m.on)
                .map(|m| MeasureChoice {
                    measure: m.measure.name().to_owned(),
                    summary: if m.last {
                        Summary::Final
                    } else {
                        Summary::Mean
                    }
                    .name()
                    .to_owned(),
                })
                .collect(),
        }
    }
}

/// What the lab measured of its own steps: wall seconds per step of all its
/// animals (0: not yet), to scale the engine's estimate to this machine.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LabCost {
    pub secs_per_step: f64,
    pub animals: usize,
    /// Frames drawn per second lately (0: not known).
    pub fps: f64,
}

/// A design checked: its plan's size and how long it should take here.
#[derive(Clone, Debug)]
struct Checked {
    design: Design,
    result: Result<Sizing, DesignError>,
    /// The language its error was written in (checked again on a change).
    lang: crate::i18n::Lang,
}

#[derive(Clone, Copy, Debug)]
struct Sizing {
    runs: usize,
    warmup_steps: u64,
    measure_steps: u64,
    /// Wall seconds of computing per step of a run, on this machine.
    secs_per_step: f64,
    fps: f64,
}

impl Sizing {
    fn of(plan: &Plan, cost: LabCost) -> Self {
        let e = plan.estimate();
        let engine = e.secs_one_core * BROWSER_SLOWDOWN;
        let here = if cost.secs_per_step > 0.0 && cost.animals > 0 {
            e.animal_steps * cost.secs_per_step / cost.animals as f64
        } else {
            engine
        };
        Self {
            runs: e.runs,
            warmup_steps: plan.warmup_steps,
            measure_steps: plan.measure_steps,
            secs_per_step: here / e.total_steps.max(1) as f64,
            fps: cost.fps,
        }
    }

    fn compute_secs(&self) -> f64 {
        self.secs_per_step * (self.runs as u64 * (self.warmup_steps + self.measure_steps)) as f64
    }

    /// Wall seconds with the slice a frame at `fps` gets (the frames drawn
    /// per second now, or [`ASSUMED_FPS`] when not known; see
    /// [`frame_budget_secs`]).
    fn wall_secs(&self) -> f64 {
        let fps = if self.fps > 0.0 {
            self.fps
        } else {
            ASSUMED_FPS
        };
        self.compute_secs() / (frame_budget_secs(1.0 / fps) * fps).min(1.0)
    }
}

/// What the window asks of the app.
#[derive(Clone, Debug, PartialEq)]
pub enum ExperimentOutcome {
    /// Set the tank to these settings and restart it (watch one run).
    Watch(Box<Settings>),
    Notice(Notice),
    /// Copy the link that reopens this design (*Copy link*).
    CopyLink(Box<Design>),
}

/// The window, the form and the experiment under way (or finished).
#[derive(Default)]
pub struct ExperimentPanel {
    form: Option<(Scene, DesignForm)>,
    keys: Option<(Scene, Vec<String>)>,
    checked: Option<Checked>,
    session: Option<ExperimentSession>,
}

/// "about 3 min", "about 40 s".
pub fn duration_text(secs: f64) -> String {
    if !secs.is_finite() {
        "–".into()
    } else if secs < 1.0 {
        tr("experiment-duration-under-second")
    } else if secs < 90.0 {
        tr!("experiment-duration-secs", value = num(secs, 0))
    } else if secs < 90.0 * 60.0 {
        tr!("experiment-duration-min", value = num(secs / 60.0, 0))
    } else {
        tr!("experiment-duration-hours", value = num(secs / 3600.0, 1))
    }
}

impl ExperimentPanel {
    /// Runs this frame's slice, about `budget_secs` of wall time
    /// ([`crate::experiment::session::frame_budget_secs`]). True while runs
    /// remain (keep repainting).
    pub fn frame(&mut self, now_secs: f64, budget_secs: f64) -> bool {
        let Some(session) = &mut self.session else {
            return false;
        };
        session.slice(budget_secs, now_secs);
        session.running()
    }

    /// Starts `design` (a running experiment is dropped) and opens the window.
    pub fn start(
        &mut self,
        ctx: &egui::Context,
        design: &Design,
        cost: LabCost,
    ) -> Result<(), DesignError> {
        self.start_plan(ctx, design.validate()?, cost);
        Ok(())
    }

    /// Starts a validated `plan` (an experiment link's) and opens the window.
    pub fn start_plan(&mut self, ctx: &egui::Context, plan: Plan, cost: LabCost) {
        let sizing = Sizing::of(&plan, cost);
        self.session = Some(ExperimentSession::new(plan, sizing.secs_per_step));
        set_open(ctx, true);
        ctx.request_repaint();
    }

    /// The design in the window: the experiment under way or shown, else the
    /// form's as last checked (`None` before the window was opened).
    pub fn design(&self) -> Option<&Design> {
        match &self.session {
            Some(session) => Some(&session.plan().design),
            None => self.checked.as_ref().map(|c| &c.design),
        }
    }

    /// Cancels the experiment under way, keeping its completed runs. False if
    /// none was running.
    pub fn cancel(&mut self) -> bool {
        match &mut self.session {
            Some(s) if s.running() => {
                s.cancel();
                true
            }
            _ => false,
        }
    }

    /// `shoal.state().experiment`.
    pub fn report(&self) -> Option<ExperimentReport> {
        self.session.as_ref().map(ExperimentSession::report)
    }

    fn keys_for(&mut self, settings: &Settings) -> Vec<String> {
        match &self.keys {
            Some((scene, keys)) if *scene == settings.scene => keys.clone(),
            _ => {
                let keys = factor_keys(settings);
                self.keys = Some((settings.scene, keys.clone()));
                keys
            }
        }
    }

    /// The window, if open. `settings` are the current ones (the base).
    pub fn window_ui(
        &mut self,
        ctx: &egui::Context,
        settings: &Settings,
        cost: LabCost,
        rects: &mut WidgetRects,
    ) -> Vec<ExperimentOutcome> {
        let mut out = Vec::new();
        let mut open = ctx.data(|d| d.get_temp::<bool>(open_id()).unwrap_or(false));
        if !open {
            return out;
        }
        let keys = self.keys_for(settings);
        if self.form.as_ref().is_none_or(|(s, _)| *s != settings.scene) {
            self.form = Some((settings.scene, DesignForm::new(settings, &keys)));
        }
        let screen = ctx.content_rect();
        let width = (screen.width() - 24.0).clamp(200.0, 560.0);
        let shown = egui::Window::new(ts("experiment-window"))
            .id(egui::Id::unique("experiment_window"))
            .open(&mut open)
            .collapsible(true)
            .resizable(false)
            .default_width(width)
            .max_width(width)
            .max_height((screen.height() - 60.0).max(200.0))
            .default_pos(screen.right_top() + egui::vec2(-width - 12.0, 40.0))
            .constrain(true)
            .show(ctx, |ui| {
                // As tall as the screen allows once the results are longer.
                let tall = (screen.height() - 120.0).max(160.0);
                egui::ScrollArea::vertical()
                    .max_height(tall)
                    .min_scrolled_height(tall.min(720.0))
                    .show(ui, |ui| {
                        self.contents_ui(ui, settings, &keys, cost, rects, &mut out);
                        crate::ui::focus_view::keep_focus_in_view(ui, "experiment");
                    });
            });
        if let Some(shown) = shown {
            rects.insert("experiment_window", shown.response.rect);
        }
        set_open(ctx, open);
        out
    }

    fn contents_ui(
        &mut self,
        ui: &mut egui::Ui,
        settings: &Settings,
        keys: &[String],
        cost: LabCost,
        rects: &mut WidgetRects,
        out: &mut Vec<ExperimentOutcome>,
    ) {
        let running = self
            .session
            .as_ref()
            .is_some_and(ExperimentSession::running);
        ui.label(egui::RichText::new(ts("experiment-intro")).weak());
        if let Some(session) = &self.session {
            // The design is put away while it runs and while its results show.
            let plan = session.plan();
            let r = ui.label(
                egui::RichText::new(tr!(
                    "experiment-running-design",
                    name = plan.design.name.as_str(),
                    runs = plan.run_count(),
                    secs = num(plan.steps_per_run() as f64 * plan.dt_secs, 0)
                ))
                .strong(),
            );
            rects.insert("experiment_running_design", r.rect);
            self.session_ui(ui, rects, out);
            return;
        }
        let Some((_, form)) = self.form.as_mut() else {
            return;
        };
        ui.add_enabled_ui(!running, |ui| form_ui(ui, form, settings, keys, rects));
        let design = form.design(settings);
        let lang = crate::i18n::lang();
        if self
            .checked
            .as_ref()
            .is_none_or(|c| c.design != design || c.lang != lang)
        {
            let result = design.validate().map(|plan| Sizing::of(&plan, cost));
            self.checked = Some(Checked {
                design: design.clone(),
                result,
                lang,
            });
        }
        ui.separator();
        let valid = match self.checked.as_ref().map(|c| &c.result) {
            Some(Ok(sizing)) => {
                sizing_ui(ui, form, settings, sizing, rects);
                true
            }
            Some(Err(err)) => {
                let (field, reason) = error_in_words(err, &design, shows_side(settings.scene));
                let r = ui.colored_label(
                    ui.visuals().warn_fg_color,
                    tr!("experiment-cannot-start", field = field, reason = reason),
                );
                rects.insert("experiment_error", r.rect);
                false
            }
            None => false,
        };
        ui.horizontal_wrapped(|ui| {
            let start = ui
                .add_enabled(valid && !running, egui::Button::new(ts("experiment-start")))
                .on_hover_text(ts("experiment-start.help"));
            rects.insert("experiment_start", start.rect);
            if start.clicked()
                && let Err(err) = self.start(ui.ctx(), &design, cost)
            {
                out.push(ExperimentOutcome::Notice(Notice::error(err.to_string())));
            }
            let save = ui
                .button(ts("experiment-save-design"))
                .on_hover_text(ts("experiment-save-design.help"));
            rects.insert("experiment_save_design", save.rect);
            if save.clicked() {
                let text = serde_json::to_string_pretty(&design).unwrap_or_default();
                out.push(save_file(
                    &format!("shoal-experiment-{}.json", file_stem(&design.name)),
                    "application/json",
                    &text,
                    &tr("experiment-save-design-next"),
                ));
            }
            copy_link_button(ui, &design, rects, out);
        });
    }

    /// Progress while running; then the results.
    fn session_ui(
        &mut self,
        ui: &mut egui::Ui,
        rects: &mut WidgetRects,
        out: &mut Vec<ExperimentOutcome>,
    ) {
        let Some(session) = &mut self.session else {
            return;
        };
        ui.separator();
        let p = session.progress();
        if session.running() {
            let left = session
                .secs_left()
                .map_or_else(|| tr("experiment-measuring-pace"), duration_text);
            let text = if session.paused() {
                tr!(
                    "experiment-progress-paused",
                    done = p.runs_done,
                    total = p.runs_total
                )
            } else {
                tr!(
                    "experiment-progress",
                    done = p.runs_done,
                    total = p.runs_total,
                    left = left
                )
            };
            let bar = ui.add(
                egui::ProgressBar::new(p.steps_done as f32 / p.steps_total.max(1) as f32)
                    .text(text),
            );
            rects.insert("experiment_progress", bar.rect);
            ui.horizontal(|ui| {
                let label = if session.paused() {
                    ts("experiment-resume")
                } else {
                    ts("experiment-pause")
                };
                let pause = ui.button(label).on_hover_text(ts("experiment-pause.help"));
                rects.insert("experiment_pause", pause.rect);
                if pause.clicked() {
                    let paused = session.paused();
                    session.set_paused(!paused);
                }
                let cancel = ui
                    .button(ts("experiment-cancel"))
                    .on_hover_text(ts("experiment-cancel.help"));
                rects.insert("experiment_cancel", cancel.rect);
                if cancel.clicked() {
                    session.cancel();
                }
            });
            return;
        }
        let plan = session.plan().clone();
        let heading = if session.cancelled() {
            tr!(
                "experiment-cancelled",
                done = p.runs_done,
                total = p.runs_total
            )
        } else {
            tr!("experiment-done", count = p.runs_done)
        };
        let r = ui.label(egui::RichText::new(heading).strong());
        rects.insert("experiment_results", r.rect);
        let rows = session.experiment().summary();
        if let Some(WatchRequest { levels, seed }) = results_ui(ui, &plan, &rows, rects) {
            let spec = RunSpec {
                index: 0,
                levels: levels.clone(),
                seed,
            };
            let mut watched = plan.settings_for(&spec);
            watched.paused = false;
            out.push(ExperimentOutcome::Watch(Box::new(watched)));
            let side = shows_side(plan.base.scene);
            let what: Vec<String> = plan
                .factors
                .iter()
                .zip(&levels)
                .map(|(f, l)| format!("{} = {}", factor_text(&f.key, side), level_text(l)))
                .collect();
            out.push(ExperimentOutcome::Notice(Notice::info(tr!(
                "experiment-watching",
                levels = what.join(", "),
                seed = seed.to_string()
            ))));
        }
        let mut clear = false;
        ui.horizontal_wrapped(|ui| {
            let csv = ui
                .button(ts("experiment-download-csv"))
                .on_hover_text(ts("experiment-download-csv.help"));
            rects.insert("experiment_csv", csv.rect);
            if csv.clicked() {
                out.push(save_file(
                    &format!("shoal-experiment-{}.csv", file_stem(&plan.design.name)),
                    "text/csv",
                    &session.experiment().csv(),
                    &tr("experiment-download-csv-next"),
                ));
            }
            let clear_button = ui
                .button(ts("experiment-new"))
                .on_hover_text(ts("experiment-new.help"));
            rects.insert("experiment_clear", clear_button.rect);
            clear = clear_button.clicked();
            copy_link_button(ui, &plan.design, rects, out);
        });
        if clear {
            self.session = None;
        }
    }
}

/// *Copy link*: the link that reopens `design` and runs it again.
fn copy_link_button(
    ui: &mut egui::Ui,
    design: &Design,
    rects: &mut WidgetRects,
    out: &mut Vec<ExperimentOutcome>,
) {
    let r = ui
        .button(ts("experiment-copy-link"))
        .on_hover_text(ts("experiment-copy-link.help"));
    rects.insert("experiment_link", r.rect);
    if r.clicked() {
        out.push(ExperimentOutcome::CopyLink(Box::new(design.clone())));
    }
}

/// The form's widgets.
fn form_ui(
    ui: &mut egui::Ui,
    form: &mut DesignForm,
    settings: &Settings,
    keys: &[String],
    rects: &mut WidgetRects,
) {
    egui::Grid::new("experiment_form")
        .num_columns(2)
        .spacing([8.0, 6.0])
        .show(ui, |ui| {
            ui.label(ts("experiment-name"));
            let r = ui.add(egui::TextEdit::singleline(&mut form.name).desired_width(160.0));
            rects.insert("experiment_name", r.rect);
            ui.end_row();
            factor_ui(
                ui,
                ts("experiment-vary"),
                "experiment_factor",
                &mut form.factor,
                settings,
                keys,
                rects,
            );
            ui.label("");
            let mut two = form.second.is_some();
            let r = ui
                .checkbox(&mut two, ts("experiment-second"))
                .on_hover_text(ts("experiment-second.help"));
            rects.insert("experiment_second_on", r.rect);
            ui.end_row();
            if two && form.second.is_none() {
                let key = keys
                    .iter()
                    .find(|k| **k != form.factor.key)
                    .cloned()
                    .unwrap_or_default();
                form.second = Some(FactorForm::new(settings, &key, 2));
            } else if !two {
                form.second = None;
            }
            if let Some(second) = &mut form.second {
                factor_ui(
                    ui,
                    ts("experiment-then"),
                    "experiment_factor2",
                    second,
                    settings,
                    keys,
                    rects,
                );
            }
            ui.label(ts("experiment-seeds"))
                .on_hover_text(ts("experiment-seeds.help"));
            ui.horizontal(|ui| {
                let r = ui.add(egui::DragValue::new(&mut form.seeds).range(1..=1000));
                rects.insert("experiment_seeds", r.rect);
                ui.label(ts("experiment-from-seed"));
                let r = ui.add(
                    egui::DragValue::new(&mut form.first_seed).range(0..=crate::settings::SEED_MAX),
                );
                rects.insert("experiment_first_seed", r.rect);
            });
            ui.end_row();
            ui.label(ts("experiment-warmup"))
                .on_hover_text(ts("experiment-warmup.help"));
            let r = ui.add(
                egui::DragValue::new(&mut form.warmup_secs)
                    .range(0.0..=3600.0)
                    .speed(0.5)
                    .suffix(" s"),
            );
            rects.insert("experiment_warmup", r.rect);
            ui.end_row();
            ui.label(ts("experiment-measure-for"))
                .on_hover_text(ts("experiment-measure-for.help"));
            let r = ui.add(
                egui::DragValue::new(&mut form.measure_secs)
                    .range(0.0..=3600.0)
                    .speed(0.5)
                    .suffix(" s"),
            );
            rects.insert("experiment_measure", r.rect);
            ui.end_row();
        });
    ui.label(egui::RichText::new(ts("experiment-measures")).strong());
    egui::Grid::new("experiment_measures")
        .num_columns(2)
        .spacing([8.0, 2.0])
        .show(ui, |ui| {
            for m in &mut form.measures {
                let r = ui
                    .checkbox(&mut m.on, m.measure.label())
                    .on_hover_text(m.measure.help());
                rects.insert(&format!("experiment_measure_{}", m.measure.name()), r.rect);
                ui.horizontal(|ui| {
                    ui.selectable_value(&mut m.last, false, ts("experiment-mean"))
                        .on_hover_text(ts("experiment-mean.help"));
                    ui.selectable_value(&mut m.last, true, ts("experiment-final"))
                        .on_hover_text(ts("experiment-final.help"));
                });
                ui.end_row();
            }
        });
}

/// A factor's setting and levels.
fn factor_ui(
    ui: &mut egui::Ui,
    label: &str,
    id: &str,
    factor: &mut FactorForm,
    settings: &Settings,
    keys: &[String],
    rects: &mut WidgetRects,
) {
    ui.label(label).on_hover_text(ts("experiment-vary.help"));
    let before = factor.key.clone();
    let side = shows_side(settings.scene);
    let r = egui::ComboBox::from_id_salt(id)
        .selected_text(factor_text(&factor.key, side))
        .height(320.0)
        .show_ui(ui, |ui| {
            for key in keys {
                let r = ui.selectable_value(&mut factor.key, key.clone(), factor_text(key, side));
                rects.insert(&format!("{id}_{key}"), r.rect);
            }
        });
    rects.insert(id, r.response.rect);
    if factor.key != before {
        *factor = FactorForm::new(settings, &factor.key.clone(), factor.steps);
    }
    ui.end_row();
    ui.label("");
    if is_switch(settings, &factor.key) {
        ui.label(ts("experiment-off-and-on"));
    } else {
        // Within the slider's range, with its unit, whole for a count.
        let name = crate::settings::names::setting_name(&factor.key);
        let unit = name.map_or("", |n| n.unit);
        let slider = name.and_then(|n| n.slider);
        fn level<'a>(
            value: &'a mut f64,
            unit: &str,
            slider: Option<crate::settings::names::Slider>,
        ) -> egui::DragValue<'a> {
            let mut drag = egui::DragValue::new(value).speed(0.5).suffix(unit);
            if let Some(s) = slider {
                drag = drag.range(s.min..=s.max);
                if s.whole {
                    drag = drag.max_decimals(0);
                }
            }
            drag
        }
        ui.horizontal_wrapped(|ui| {
            ui.label(ts("experiment-range-from"));
            let r = ui.add(level(&mut factor.from, unit, slider));
            rects.insert(&format!("{id}_from"), r.rect);
            ui.label(ts("experiment-range-to"));
            let r = ui.add(level(&mut factor.to, unit, slider));
            rects.insert(&format!("{id}_to"), r.rect);
            ui.label(ts("experiment-range-in"));
            let r = ui.add(egui::DragValue::new(&mut factor.steps).range(1..=1000));
            rects.insert(&format!("{id}_steps"), r.rect);
            ui.label(ts("experiment-range-levels"));
        });
    }
    ui.end_row();
}

/// A refused form's field in the form's words (the factor's setting as the
/// side panel names it, *Seeds*, *Measure for*), and its reason with the
/// factors' keys named so too; the design file's field and the keys stay in
/// [`DesignError`] (the API and `shoal-lab` report them).
fn error_in_words(err: &DesignError, design: &Design, side: bool) -> (String, String) {
    let mut reason = err.reason.clone();
    for factor in &design.factors {
        reason = reason.replace(
            &format!("'{}'", factor.key),
            &format!("'{}'", factor_text(&factor.key, side)),
        );
    }
    let field = err.field.as_str();
    let factor = design
        .factors
        .iter()
        .enumerate()
        .find(|(i, _)| field.starts_with(&format!("factors[{i}]")));
    let field = match factor {
        Some((_, f)) => factor_text(&f.key, side),
        None if field.starts_with("replicates") => tr("experiment-seeds"),
        None if field.starts_with("measures") => tr("experiment-measures"),
        None if field == "warmup_secs" => tr("experiment-warmup"),
        None if field == "measure_secs" => tr("experiment-measure-for"),
        None if field == "factors" => tr("experiment-runs"),
        None => field.to_owned(),
    };
    (field, reason)
}

/// The design's size and time, before it starts.
fn sizing_ui(
    ui: &mut egui::Ui,
    form: &DesignForm,
    settings: &Settings,
    sizing: &Sizing,
    rects: &mut WidgetRects,
) {
    let dt = settings.scene.class().facts().clock.step_secs;
    let levels = sizing.runs / form.seeds.max(1) as usize;
    let grid = egui::Grid::new("experiment_sizing")
        .num_columns(2)
        .striped(true)
        .show(ui, |ui| {
            ui.label(ts("experiment-runs"));
            ui.label(tr!(
                "experiment-runs-value",
                levels = levels,
                seeds = form.seeds,
                runs = sizing.runs
            ));
            ui.end_row();
            ui.label(ts("experiment-steps-per-run"));
            ui.label(tr!(
                "experiment-steps-value",
                warmup = sizing.warmup_steps,
                measured = sizing.measure_steps,
                dt = num(dt, 3)
            ));
            ui.end_row();
            ui.label(ts("experiment-time"));
            ui.label(duration_text(sizing.wall_secs()))
                .on_hover_text(tr!(
                    "experiment-time-help",
                    compute = duration_text(sizing.compute_secs()),
                    ms = num(FRAME_BUDGET_SECS * 1000.0, 0)
                ));
            ui.end_row();
        });
    rects.insert("experiment_sizing", grid.response.rect);
}

/// A name safe in a file name.
fn file_stem(name: &str) -> String {
    let stem: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '-'
            }
        })
        .collect();
    if stem.is_empty() {
        "experiment".into()
    } else {
        stem
    }
}

fn save_file(name: &str, mime: &str, text: &str, next: &str) -> ExperimentOutcome {
    ExperimentOutcome::Notice(match super::save_text_file(name, mime, text, Some(next)) {
        Ok(message) => Notice::info(message),
        Err(err) => Notice::error(err.to_string()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn boids() -> Settings {
        Settings {
            scene: Scene::Boids,
            ..Settings::default()
        }
    }

    #[test]
    fn the_form_makes_the_plan_it_shows() {
        let mut base = boids();
        base.left.fish_count = 30;
        let keys = factor_keys(&base);
        let mut form = DesignForm::new(&base, &keys);
        assert_eq!(form.factor.key, "left.alignment");
        form.factor.from = 10.0;
        form.factor.to = 50.0;
        form.factor.steps = 3;
        form.seeds = 2;
        form.first_seed = 7;
        form.warmup_secs = 1.0;
        form.measure_secs = 2.0;
        let design = form.design(&base);
        let plan = design.validate().expect("valid");
        assert_eq!(plan.run_count(), 6);
        assert_eq!(plan.seeds, vec![7, 8]);
        assert_eq!(
            plan.factors[0].levels,
            vec![json!(10.0), json!(30.0), json!(50.0)]
        );
        assert_eq!(
            plan.base.left.fish_count, 30,
            "the current settings are the base"
        );
        assert_eq!(plan.warmup_steps, 60);
        assert_eq!(plan.measures, vec![(Measure::Polarization, Summary::Mean)]);
        // The saved design reads back as the same plan (the shoal-lab file).
        let text = serde_json::to_string_pretty(&design).expect("json");
        let again = Design::from_json(&text).and_then(|d| d.validate());
        assert_eq!(again.expect("valid again"), plan);
        // A second factor, a switch measured at its end.
        let switch = keys.iter().find(|k| is_switch(&base, k)).cloned();
        let mut second = FactorForm::new(&base, "left.fish_count", 2);
        second.from = 10.0;
        second.to = 20.0;
        second.steps = 2;
        form.second = Some(second);
        form.measures[1].on = true;
        form.measures[1].last = true;
        let plan = form.design(&base).validate().expect("valid");
        assert_eq!(plan.run_count(), 12);
        assert_eq!(plan.factors[1].levels, vec![json!(10), json!(20)]);
        assert_eq!(plan.measures[1].1, Summary::Final);
        if let Some(key) = switch {
            form.second = Some(FactorForm::new(&base, &key, 2));
            let plan = form.design(&base).validate().expect("valid");
            assert_eq!(plan.factors[1].levels, vec![json!(false), json!(true)]);
        }
    }

    #[test]
    fn an_invalid_form_is_refused_naming_the_field() {
        let base = boids();
        let keys = factor_keys(&base);
        let mut form = DesignForm::new(&base, &keys);
        form.factor.to = 500.0;
        let err = form.design(&base).validate().expect_err("out of range");
        assert_eq!(err.field, "factors[0].levels", "{err}");
        form.factor.to = 50.0;
        for m in &mut form.measures {
            m.on = false;
        }
        let err = form.design(&base).validate().expect_err("no measure");
        assert_eq!(err.field, "measures");
        form.measures[0].on = true;
        form.measure_secs = 0.0;
        assert_eq!(
            form.design(&base).validate().expect_err("0 s").field,
            "measure_secs"
        );
    }

    #[test]
    fn the_form_offers_the_engines_factors_and_the_scenes_measures() {
        let base = boids();
        let keys = factor_keys(&base);
        let form = DesignForm::new(&base, &keys);
        let names: Vec<&str> = form.measures.iter().map(|m| m.measure.name()).collect();
        assert_eq!(
            names,
            [
                "polarization",
                "milling",
                "nnd_body_lengths",
                "groups",
                "mean_speed_m_per_s",
                "distance_swum_m",
                "catches"
            ]
        );
        for key in &keys {
            let f = FactorForm::new(&base, key, 3);
            let design = Design {
                factors: vec![f.factor(&base)],
                ..form.design(&base)
            };
            // Every offered setting is accepted at its default levels.
            assert!(
                design.validate().is_ok(),
                "{key}: {:?}",
                design.validate().err()
            );
        }
    }

    /// Every scene that has the Experiment button, with its base settings.
    fn bases() -> Vec<Settings> {
        Scene::ALL
            .into_iter()
            .filter(|&s| s != Scene::Learning)
            .map(|scene| Settings {
                scene,
                ..Settings::default()
            })
            .collect()
    }

    /// A number with at most two significant digits (0, 5, 20, 250, 0.05).
    fn is_round(x: f64) -> bool {
        if x == 0.0 {
            return true;
        }
        use crate::sim::common::fmath::{log10_f64, powi_f64};
        let scale = powi_f64(10.0, log10_f64(x.abs()).floor() as i32 - 1);
        ((x / scale).round() * scale - x).abs() <= 1e-9 * x.abs()
    }

    #[test]
    fn a_new_factor_spans_its_slider_or_a_round_part_of_it() {
        use crate::settings::names::setting_name;
        let mut checked = 0;
        for base in bases() {
            for key in factor_keys(&base) {
                for steps in [2, 3] {
                    let f = FactorForm::new(&base, &key, steps);
                    if is_switch(&base, &key) {
                        continue;
                    }
                    let slider = setting_name(&key)
                        .and_then(|n| n.slider)
                        .unwrap_or_else(|| panic!("{key}: a number has a slider"));
                    assert!(
                        slider.min <= f.from && f.from < f.to && f.to <= slider.max,
                        "{key}: {} to {} within {} to {}",
                        f.from,
                        f.to,
                        slider.min,
                        slider.max
                    );
                    let whole_range = (f.from, f.to) == (slider.min, slider.max);
                    assert!(
                        whole_range || (is_round(f.from) && is_round(f.to)),
                        "{key}: {} to {} is the slider's range or round",
                        f.from,
                        f.to
                    );
                    assert!((2..=5).contains(&f.steps), "{key}: {} levels", f.steps);
                    if slider.whole {
                        let step = (f.to - f.from) / f64::from(f.steps - 1);
                        assert_eq!(step.fract(), 0.0, "{key}: whole levels, {f:?}");
                    }
                    let design = Design {
                        factors: vec![f.factor(&base)],
                        ..DesignForm::new(&base, std::slice::from_ref(&key)).design(&base)
                    };
                    assert!(design.validate().is_ok(), "{key}: {:?}", design.validate());
                    checked += 1;
                }
            }
        }
        assert!(checked > 40, "{checked}");
        // Never 0 to 52 (twice the Individual preset's 26): the slider's 0 to 100.
        let base = boids();
        let f = FactorForm::new(&base, "left.alignment", 3);
        assert_eq!((f.from, f.to, f.steps), (0.0, 100.0, 3));
        // The fish count: a round part around the 200 fish, not 0 to 20,000.
        let f = FactorForm::new(&base, "left.fish_count", 3);
        assert_eq!((f.from, f.to, f.steps), (100.0, 500.0, 3));
    }

    #[test]
    fn factors_and_measures_are_named_in_words_in_every_language() {
        use crate::i18n::{Lang, has, with_lang};
        for lang in Lang::ALL {
            with_lang(lang, || {
                for base in bases() {
                    let side = shows_side(base.scene);
                    for key in factor_keys(&base) {
                        let text = factor_text(&key, side);
                        assert!(
                            !text.contains(&key) && !text.contains('_') && !text.contains('['),
                            "{lang:?} {key}: {text}"
                        );
                    }
                }
                for measure in Measure::ALL {
                    for id in [
                        measure.label_id().to_owned(),
                        format!("{}.help", measure.label_id()),
                    ] {
                        assert!(has(lang, &id), "{lang:?}: {id}");
                    }
                    let label = measure.label();
                    assert!(
                        !label.contains(measure.name()) && !label.contains('_'),
                        "{lang:?}: {label}"
                    );
                }
            });
        }
        assert_eq!(
            factor_text("left.alignment", shows_side(Scene::Boids)),
            "Alignment (left tank)"
        );
        assert_eq!(
            factor_text("left.fish_count", shows_side(Scene::Aquarium)),
            "Fish"
        );
        assert_eq!(
            Measure::NndBodyLengths.label(),
            "Nearest neighbour (body lengths)"
        );
        with_lang(Lang::Es, || {
            assert_eq!(
                factor_text("left.alignment", true),
                "Alineación (tanque izquierdo)"
            );
            assert_eq!(Measure::Catches.label(), "Presas atrapadas");
            assert_eq!(
                Measure::NndBodyLengths.label(),
                "Vecino más cercano (largos de cuerpo)"
            );
        });
    }

    #[test]
    fn the_window_speaks_spanish_with_decimal_commas() {
        use crate::i18n::{Lang, with_lang};
        with_lang(Lang::Es, || {
            assert_eq!(duration_text(7200.0), "unas 2,0 h");
            assert_eq!(duration_text(0.2), "menos de un segundo");
            assert_eq!(tr!("experiment-done", count = 1), "Listo: 1 corrida.");
            assert_eq!(
                tr!("experiment-runs-value", levels = 3, seeds = 1, runs = 3),
                "3 niveles × 1 semilla = 3"
            );
            assert_eq!(level_text(&json!(0.5)), "0,5");
            assert_eq!(level_text(&json!(true)), "encendido");
            let mut design = DesignForm::new(&boids(), &factor_keys(&boids())).design(&boids());
            design.measure_secs = 0.1;
            let err = design.validate().expect_err("too short").to_string();
            assert!(
                err.starts_with("measure_secs: en 0,1 s no cabe ninguna muestra"),
                "{err}"
            );
            assert!(err.contains("mide al menos 0,"), "{err}");
            let err = crate::experiment::link::decode("").expect_err("empty");
            assert_eq!(err.to_string(), "el enlace no contiene ningún experimento");
        });
        // English stays as it was.
        assert_eq!(duration_text(7200.0), "about 2.0 h");
        assert_eq!(level_text(&json!(0.5)), "0.5");
    }

    #[test]
    fn a_refused_form_names_its_field_in_the_forms_words() {
        let base = boids();
        let keys = factor_keys(&base);
        let mut form = DesignForm::new(&base, &keys);
        form.second = Some(FactorForm::new(&base, "left.alignment", 2));
        let design = form.design(&base);
        let err = design.validate().expect_err("the same factor twice");
        assert_eq!(err.field, "factors[1].key", "the API's field stays");
        let (field, reason) = error_in_words(&err, &design, true);
        assert_eq!(field, "Alignment (left tank)");
        assert_eq!(reason, "'Alignment (left tank)' is already a factor");
        form.second = None;
        form.measure_secs = 0.0;
        let design = form.design(&base);
        let err = design.validate().expect_err("0 s");
        assert_eq!(error_in_words(&err, &design, true).0, "Measure for");
    }

    #[test]
    fn durations_read_as_a_person_says_them() {
        assert_eq!(duration_text(0.2), "under a second");
        assert_eq!(duration_text(40.0), "about 40 s");
        assert_eq!(duration_text(600.0), "about 10 min");
        assert_eq!(duration_text(7200.0), "about 2.0 h");
        assert_eq!(file_stem("my sweep/1"), "my-sweep-1");
    }
}
