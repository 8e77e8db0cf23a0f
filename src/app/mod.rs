//! The eframe application: one `Lab` (one tank, or two side by side), the 3D views
//! and the panels around them.
//!
//! Each frame: advance the lab by the fixed steps real time asks for, lay out the
//! panels (which may change settings), handle camera and rock-editing input on each
//! 3D view, and hand the renderer a freshly built frame per view.

mod facade;
mod recover;
pub use recover::Session;
pub mod keys;
mod views;

use eframe::egui;

use crate::bench::Benchmark;
use crate::clock::RateMeter;
use crate::i18n::{fmt, num, ts};
use crate::lab::Lab;
use crate::render::{FrameBuilder, OrbitCamera, RenderCaps, SceneDetail, SceneRenderer};
use crate::scenes::CurrentPanel;
use crate::settings::{Scene, Settings};
use crate::tr;
use crate::ui::{Notice, PanelAction, WidgetRects, control_panel_ui, status_line_ui};

/// Why Shoal could not start.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StartError {
    NoGpuRenderer,
}

impl std::fmt::Display for StartError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NoGpuRenderer => f.write_str(ts("app-no-gpu")),
        }
    }
}

impl std::error::Error for StartError {}

/// The Shoal app.
pub struct ShoalApp {
    lab: Lab,
    camera: OrbitCamera,
    /// True until the user moves the camera: the default view then re-frames the
    /// tank whenever the view's shape changes (window resize, panel hidden).
    camera_is_default: bool,
    /// Aspect ratio the camera was last framed for.
    framed_aspect: f32,
    /// One per 3D view (left, right).
    frame_builders: [FrameBuilder; 2],
    caps: RenderCaps,
    /// How many pixels the tank is drawn with (fewer on slow graphics, see
    /// [`crate::render::detail`]).
    scene_detail: SceneDetail,
    panel_open: bool,
    /// The interface scale the teacher chose (`None`: automatic from the screen,
    /// see [`crate::ui::screen::auto_scale`]).
    interface_scale: Option<f32>,
    /// Has the first frame chosen the layout (a narrow window starts with the
    /// side panel closed)?
    layout_chosen: bool,
    fps_meter: RateMeter,
    last_frame_time_secs: Option<f64>,
    /// Wall seconds the last frame spent on background runs (an experiment, an
    /// investigation's measurement), to tell the page's own frame time.
    background_secs: f64,
    /// Frames drawn since start (`state().frames`).
    frames_drawn: u64,
    /// Are the two compared tanks one above the other (a tall window)?
    views_stacked: bool,
    widget_rects: WidgetRects,
    /// The in-app benchmark, when started (`?bench`).
    benchmark: Option<Benchmark>,
    /// Set by `shoal.crash_test()`: the next frame panics, to test the error page.
    crash_requested: bool,
    notice: Option<Notice>,
    /// The page's address without its fragment, for share links (`None` natively).
    page_url: Option<String>,
    /// Is the camera following the selected fish?
    following: bool,
    /// The scene and subject (a demo) the camera was last framed for (none
    /// before the first frame).
    viewed: Option<(Scene, &'static str)>,
    /// The scene's own controls, panel under the tank, overlays and picking.
    scene_panel: CurrentPanel,
    /// The *Experiment…* window and the experiment under way, if any.
    experiment: crate::ui::ExperimentPanel,
    /// The teacher's studio's windows (*Share with class* and its QR code).
    studio: crate::ui::StudioPanel,
    /// The guided investigation under way and the session's record.
    investigations: crate::ui::InvestigationPanel,
    /// A class together (issue 37): shown only when a class server serves
    /// the page.
    class: crate::ui::class_panel::ClassPanel,
    /// What the screen reader's live region says about the tank, and when.
    narrator: crate::a11y::describe::Narrator,
    /// Say what the selected animal does on the next frame (it was just
    /// picked with N or B).
    describe_selection: bool,
    /// Is the *Keyboard* window (`?`) open?
    keys_open: bool,
    /// The live region's last words (`shoal.state().said`).
    last_said: Option<String>,
    /// The notice last read out (each new notice is said once).
    notice_said: Option<String>,
    ctx: egui::Context,
}
impl ShoalApp {
    /// Creates the app on eframe's wgpu renderer. Fails with a readable message when
    /// no GPU renderer is available.
    pub fn new(cc: &eframe::CreationContext<'_>, settings: Settings) -> Result<Self, StartError> {
        let render_state = cc
            .wgpu_render_state
            .as_ref()
            .ok_or(StartError::NoGpuRenderer)?;
        let caps = SceneRenderer::install(render_state);
        log::info!(
            "render tier: {} ({:?}), MSAA ×{}", // words: a log line
            caps.tier.label(),
            render_state.adapter.get_info().backend,
            caps.msaa_samples
        );
        crate::ui::fonts::install(&cc.egui_ctx);
        crate::ui::seeing::install(&cc.egui_ctx);
        let mut lab = Lab::new(settings);
        lab.set_frame_budget(Some(crate::lab::INTERACTIVE_FRAME_BUDGET_SECS));
        let tank = lab.scene().tank();
        let lab_scene = lab.settings().scene;
        Ok(Self {
            camera: OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0),
            camera_is_default: true,
            framed_aspect: 16.0 / 9.0,
            lab,
            frame_builders: Default::default(),
            caps,
            scene_detail: SceneDetail::default(),
            panel_open: true,
            interface_scale: None,
            layout_chosen: false,
            fps_meter: RateMeter::default(),
            last_frame_time_secs: None,
            background_secs: 0.0,
            frames_drawn: 0,
            views_stacked: false,
            widget_rects: WidgetRects::new(),
            benchmark: None,
            crash_requested: false,
            notice: None,
            page_url: None,
            following: false,
            viewed: None,
            scene_panel: CurrentPanel::new(lab_scene),
            experiment: crate::ui::ExperimentPanel::default(),
            studio: crate::ui::StudioPanel::default(),
            investigations: crate::ui::InvestigationPanel::default(),
            class: crate::ui::class_panel::ClassPanel::default(),
            narrator: Default::default(),
            describe_selection: false,
            keys_open: false,
            last_said: None,
            notice_said: None,
            ctx: cc.egui_ctx.clone(),
        })
    }

    fn benchmark_ui(&self, ui: &mut egui::Ui) {
        let Some(bench) = &self.benchmark else {
            return;
        };
        let report = bench.report();
        egui::Window::new(ts("app-bench-title"))
            // The same window whatever the language.
            .id(egui::Id::unique("Benchmark")) // words: the window's id, never shown
            .anchor(egui::Align2::RIGHT_TOP, egui::vec2(-8.0, 8.0))
            .resizable(false)
            .collapsible(false)
            .show(ui.ctx(), |ui| {
                ui.label(if report.done {
                    ts("app-bench-done")
                } else {
                    ts("app-bench-measuring")
                });
                egui::Grid::new("bench_rows").striped(true).show(ui, |ui| {
                    for head in [
                        ts("app-bench-scene"),
                        ts("app-bench-fish"),
                        ts("app-bench-steps"),
                        ts("app-bench-fish-steps"),
                        ts("app-bench-frame"),
                        ts("app-bench-cpu"),
                    ] {
                        ui.strong(head);
                    }
                    ui.end_row();
                    for row in &report.rows {
                        ui.label(row.scene);
                        ui.label(row.fish.to_string());
                        ui.label(fmt(row.sim_steps_per_sec, 0));
                        ui.label(fmt(row.fish_steps_per_sec, 0));
                        ui.label(fmt(row.frame_ms, 2));
                        ui.label(fmt(row.cpu_frame_ms, 2));
                        ui.end_row();
                    }
                });
                if let Some(rate) = report.annealing_evaluations_per_sec {
                    ui.label(tr!("app-bench-annealing", rate = num(rate, 1)));
                }
                if let Some(e) = &report.experiment {
                    ui.label(tr!(
                        "app-bench-experiment",
                        name = e.name.to_string(),
                        rate = num(e.runs_per_sec, 3),
                        runs = e.runs,
                        steps = e.steps_per_run,
                    ));
                }
            });
    }

    fn apply(&mut self, actions: Vec<PanelAction>) {
        for action in actions {
            match action {
                PanelAction::Step => self.lab.step(1),
                PanelAction::Reset => self.lab.reset(None),
                PanelAction::ResetView => self.reset_view(),
                PanelAction::HidePanel => self.panel_open = false,
                PanelAction::Describe => self.describe_tank(),
                PanelAction::Keyboard => self.keys_open = !self.keys_open,
                PanelAction::CopyLink => {
                    let link = self.share_link();
                    self.ctx.copy_text(link);
                    self.notice = Some(Notice::info(ts("notice-link-copied")));
                }
                PanelAction::ExportCsv => {
                    let csv = self.export_csv();
                    self.notice = Some(
                        match crate::ui::save_text_file(
                            &csv.name,
                            "text/csv",
                            &csv.text,
                            Some(ts("notice-csv-next")),
                        ) {
                            Ok(message) => Notice::info(message),
                            Err(err) => Notice::error(err.to_string()),
                        },
                    );
                }
            }
        }
        let scene = self.lab.settings().scene;
        if let Some(notice) = self
            .scene_panel
            .for_scene(scene)
            .apply(&mut self.lab, &self.ctx)
        {
            self.notice = Some(notice);
        }
    }

    fn notice_ui(&mut self, ui: &mut egui::Ui) {
        let Some(notice) = self.notice.clone() else {
            return;
        };
        let rect = ui.max_rect();
        // Centred, at most 520 points wide, and within a phone's screen.
        let width = (rect.width() - 40.0).clamp(120.0, 520.0);
        let left = (rect.center().x - 0.5 * width - 10.0).max(rect.left() + 8.0);
        egui::Area::new(egui::Id::unique("notice"))
            .fixed_pos(egui::pos2(left, rect.top() + 10.0))
            .order(egui::Order::Foreground)
            .show(ui.ctx(), |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    ui.set_max_width(width);
                    ui.horizontal(|ui| {
                        let color = if notice.is_error {
                            ui.visuals().warn_fg_color
                        } else {
                            ui.visuals().text_color()
                        };
                        ui.add(
                            egui::Label::new(egui::RichText::new(&notice.text).color(color)).wrap(),
                        );
                        let close = ui
                            .button(ts("notice-ok"))
                            .on_hover_text(ts("notice-ok.help"));
                        self.widget_rects.insert("notice_ok", close.rect);
                        if close.clicked() {
                            self.notice = None;
                        }
                    });
                });
            });
    }
}

impl eframe::App for ShoalApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        assert!(
            !self.crash_requested,
            "crash test requested through shoal.crash_test()" // words: a test's panic
        );
        let now_secs = ui.input(|i| i.time);
        self.widget_rects.clear();
        if let Some(bench) = &mut self.benchmark {
            bench.frame(&mut self.lab, now_secs, frame.info().cpu_usage);
        }
        let frame_secs = self
            .last_frame_time_secs
            .map_or(0.0, |last| now_secs - last);
        self.last_frame_time_secs = Some(now_secs);
        crate::ui::clicks::allow_slow_frames(ui.ctx(), frame_secs);
        self.scene_detail.observe(
            frame_secs,
            frame.info().cpu_usage.map(f64::from),
            !self.lab.settings().paused,
        );
        self.lab.advance_frame(frame_secs, now_secs);
        // The runs in the background get their share of this frame: 15 ms, or
        // half of the page's own work when that is slow anyway.
        let budget =
            crate::experiment::session::frame_budget_secs(frame_secs - self.background_secs);
        let started = web_time::Instant::now();
        let experimenting = self.experiment.frame(now_secs, budget);
        let investigating = self.investigations.frame(&mut self.lab, now_secs, budget);
        self.background_secs = started.elapsed().as_secs_f64();
        self.fps_meter.record(now_secs, 1);
        self.frames_drawn += 1;
        #[cfg(target_arch = "wasm32")]
        if self.frames_drawn == 1 {
            crate::web::page::mark_first_frame();
        }

        let class_actions = self.class.frame(&self.ctx, now_secs);
        self.class_actions(class_actions);
        self.investigations.set_class_hold(self.class.held_step());

        self.choose_screen_layout();
        let status = self.state_report();
        self.narrate(&status, now_secs);
        let status_panel = egui::Panel::bottom("status").show(ui, |ui| {
            let settings = self.lab.settings();
            let hidden_count = settings.studio.count_is_mystery_for_student(settings.scene);
            status_line_ui(ui, &status, self.caps, hidden_count);
        });
        self.widget_rects
            .insert("status_line", status_panel.response.rect);
        let _ = status_panel.response.accessible_name(ts("app-status"));

        // The scene's panel: refreshed from the simulation, then the panel under
        // the tank (drawn before the side panel and the tank, which take the rest).
        let scene = self.lab.settings().scene;
        let scene_panel = self.scene_panel.for_scene(scene);
        if let Some(notice) = scene_panel.before_frame(&mut self.lab, now_secs, &self.ctx) {
            self.notice = Some(notice);
        }
        if self
            .notice
            .as_ref()
            .and_then(|n| n.about_world)
            .is_some_and(|g| g != self.lab.world_generation())
        {
            self.notice = None;
        }
        let mut settings = self.lab.settings().clone();
        crate::ui::studio_panel::begin_frame(&self.ctx, &settings.studio);
        scene_panel.bottom_ui(ui, &self.lab, &mut settings, &mut self.widget_rects);

        let mut actions = self.keys(&mut settings);
        let step_secs = self.lab.scene().dt_secs();
        let width = ui.ctx().content_rect().width();
        let mut view = crate::ui::ViewOptions {
            interface_scale: self.interface_scale,
            current_scale: ui.ctx().zoom_factor(),
            detail_auto: self.scene_detail.auto,
            detail_scale: self.scene_detail.scale(),
        };
        let controls = egui::Panel::left("controls")
            .default_size(if crate::ui::screen::is_narrow(width) {
                crate::ui::screen::drawer_width(width)
            } else {
                270.0
            })
            .resizable(true)
            .show_collapsible(ui, &mut self.panel_open, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui.add_space(6.0);
                    // The two ways into a lesson, on the first screen.
                    let experiment = self
                        .scene_panel
                        .for_scene(settings.scene)
                        .offers_experiment();
                    crate::ui::investigations_button(ui, experiment, &mut self.widget_rects);
                    self.class.side_ui(ui, &mut self.widget_rects);
                    actions.extend(control_panel_ui(
                        ui,
                        &mut settings,
                        &mut self.scene_panel,
                        step_secs,
                        &mut view,
                        &mut self.widget_rects,
                    ));
                    crate::ui::focus_view::keep_focus_in_view(ui, "controls");
                });
            });
        if let Some(controls) = controls {
            // The panel's name for a screen reader (a region of the page).
            let _ = controls.response.accessible_name(ts("app-controls"));
        }
        self.interface_scale = view.interface_scale;
        if view.detail_auto != self.scene_detail.auto {
            self.scene_detail.set_auto(view.detail_auto);
        }
        if let Some(studio) = crate::ui::studio_panel::end_frame(&self.ctx) {
            settings.studio = studio;
        }

        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| {
                self.views_ui(ui, &mut settings);
                if !self.panel_open {
                    let button = egui::Button::new(ts("app-controls"));
                    let at = ui.max_rect().left_top() + egui::vec2(8.0, 8.0);
                    let show = ui
                        .put(
                            egui::Rect::from_min_size(at, egui::vec2(100.0, 28.0)),
                            button,
                        )
                        .on_hover_text(ts("app-controls.help"));
                    self.widget_rects.insert("show_panel", show.rect);
                    if show.clicked() {
                        self.panel_open = true;
                    }
                }
                self.notice_ui(ui);
            });
        crate::ui::about_window(ui.ctx(), settings.scene, &mut self.widget_rects);
        keys::help_window(ui.ctx(), &mut self.keys_open, &mut self.widget_rects);
        let cost = self.lab_cost();
        let mut watch = false;
        for outcome in self
            .experiment
            .window_ui(ui.ctx(), &settings, cost, &mut self.widget_rects)
        {
            match outcome {
                crate::ui::ExperimentOutcome::Watch(run) => {
                    settings = *run;
                    watch = true;
                }
                crate::ui::ExperimentOutcome::Notice(notice) => self.notice = Some(notice),
                crate::ui::ExperimentOutcome::CopyLink(design) => {
                    let page = self.page();
                    self.ctx
                        .copy_text(crate::experiment::link::link(&page, &design));
                    self.notice = Some(Notice::info(tr!("notice-experiment-link-copied")));
                }
            }
        }
        let page_url = self.page();
        if let Some(notice) =
            self.studio
                .windows_ui(ui.ctx(), &mut settings, &page_url, &mut self.widget_rects)
        {
            self.notice = Some(notice);
        }
        let class_actions =
            self.class
                .windows_ui(ui.ctx(), &settings, &page_url, &mut self.widget_rects);
        self.class_actions(class_actions);
        let mut run_investigation = false;
        for action in self.investigations.windows_ui(
            ui.ctx(),
            &self.lab,
            &settings,
            &page_url,
            &mut self.widget_rects,
        ) {
            match action {
                crate::ui::InvestigationAction::Settings(s) => settings = *s,
                crate::ui::InvestigationAction::Run => run_investigation = true,
                crate::ui::InvestigationAction::Notice(n) => self.notice = Some(n),
            }
        }
        // The student view keeps what the teacher's rules keep.
        let current = self.lab.settings();
        if &settings != current {
            current.studio.enforce(current, &mut settings);
        }
        if &settings != self.lab.settings() {
            self.lab.apply_settings(settings);
        }
        if run_investigation && let Err(err) = self.investigations.start_run(&mut self.lab) {
            self.notice = Some(Notice::error(err));
        }
        self.class
            .report_investigation(self.investigations.report().as_ref());
        if watch {
            // The run from its start, as the experiment ran it.
            self.lab.reset(None);
        }
        self.apply(actions);
        // A new scene or demo opens framed on what it is about, wherever the
        // camera was (a close-up of the last scene's fish would show a corner).
        let scene = self.lab.settings().scene;
        let viewing = (
            scene,
            self.scene_panel
                .for_scene(scene)
                .view_subject(self.lab.settings()),
        );
        if self.viewed != Some(viewing) {
            self.viewed = Some(viewing);
            self.reset_view();
        }

        self.benchmark_ui(ui);

        // Keep animating while the simulation runs. While paused the picture is
        // still, so egui repaints only on input: a paused class saves battery.
        if !self.lab.settings().paused || experimenting || investigating {
            ui.ctx().request_repaint();
        }
    }

    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(&mut *self)
    }
}
