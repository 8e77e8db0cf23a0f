//! The eframe application: one `Lab` (one tank, or two side by side), the 3D views
//! and the panels around them.
//!
//! Each frame: advance the lab by the fixed steps real time asks for, lay out the
//! panels (which may change settings), handle camera and rock-editing input on each
//! 3D view, and hand the renderer a freshly built frame per view.

use eframe::egui;

use crate::automation::{AutomationError, CameraReport, Command, SceneDetailReport, StateReport};
use crate::bench::Benchmark;
use crate::clock::RateMeter;
use crate::lab::Lab;
use crate::render::{FrameBuilder, OrbitCamera, RenderCaps, SceneDetail, SceneRenderer};
use crate::settings::{Scene, Settings, Side};
use crate::ui::{
    CurrentPanel, Notice, PanelAction, ViewContext, ViewInput, WidgetRects, control_panel_ui,
    status_line_ui,
};

/// Time constant of the follow camera gliding to the selected fish, seconds (0.4,
/// chosen: smooth, and a fish at top speed never leaves the view, at any frame rate).
const FOLLOW_TIME_CONSTANT_SECS: f32 = 0.4;

/// Why Shoal could not start.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum StartError {
    #[error("Shoal needs a GPU renderer (WebGPU or WebGL2), and none could be started.")]
    NoGpuRenderer,
}

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
            "render tier: {} ({:?}), MSAA ×{}",
            caps.tier.label(),
            render_state.adapter.get_info().backend,
            caps.msaa_samples
        );
        cc.egui_ctx.set_theme(egui::Theme::Dark);
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
            ctx: cc.egui_ctx.clone(),
        })
    }

    /// Tells the app its page address (for share links). An
    /// `?investigation=<id>` in it opens that investigation, an
    /// `?experiment=…` reopens that experiment (its scene set up, its runs
    /// started); a link that cannot be opened is explained in a notice, and
    /// the rest of the link stays as it was opened.
    pub fn set_page_url(&mut self, url: String) {
        use crate::experiment::link as experiment_link;
        use crate::investigation::link as investigation_link;
        let investigation = investigation_link::from_url(&url);
        let experiment = experiment_link::from_url(&url);
        self.page_url = Some(experiment_link::without_experiment(
            &investigation_link::without_investigation(&url),
        ));
        match investigation {
            Some(Ok(investigation)) => {
                if let Err(err) = self.open_investigation(investigation, None) {
                    self.notice = Some(Notice::error(err.to_string()));
                }
            }
            Some(Err(err)) => {
                self.notice = Some(Notice::error(format!(
                    "This link could not open its investigation: {err}. The rest of the link \
                     was opened."
                )));
            }
            None => {}
        }
        match experiment {
            Some(Ok(plan)) => self.reopen_experiment(plan),
            Some(Err(err)) => {
                self.notice = Some(Notice::error(format!(
                    "This link could not open its experiment: {err}. The rest of the link \
                     was opened."
                )));
            }
            None => {}
        }
    }

    /// An experiment link's plan: the tank shows the experiment's scene and
    /// base settings, and its runs start.
    fn reopen_experiment(&mut self, plan: crate::experiment::Plan) {
        let mut settings = plan.base.clone();
        settings.paused = false;
        settings.speed = self.lab.settings().speed;
        self.lab.apply_settings(settings);
        let cost = self.lab_cost();
        self.experiment.start_plan(&self.ctx, plan, cost);
        self.notice = Some(Notice::info(format!(
            "This link reopened the experiment '{}': its runs start now, the same runs and \
             numbers as when the link was made.",
            self.experiment.design().map_or("", |d| d.name.as_str())
        )));
    }

    /// The link that reopens the experiment in the *Experiment* window and runs
    /// it again (`shoal.experiment_link()`); `None` if the window was never
    /// opened.
    pub fn experiment_link(&self) -> Option<String> {
        let page = self.page_url.clone().unwrap_or_default();
        self.experiment
            .design()
            .map(|design| crate::experiment::link::link(&page, design))
    }

    /// Opens `investigation` (its scene set up through the settings), then
    /// applies `patch` over its settings. All or nothing.
    fn open_investigation(
        &mut self,
        investigation: &'static crate::investigation::Investigation,
        patch: Option<&serde_json::Value>,
    ) -> Result<(), AutomationError> {
        let mut settings = crate::investigation::setup_settings(investigation)?;
        if let Some(patch) = patch {
            settings.apply_patch(patch)?;
        }
        self.investigations
            .open(&self.ctx, investigation)
            .map_err(AutomationError::BadArgument)?;
        self.lab.apply_settings(settings);
        self.ctx.request_repaint();
        Ok(())
    }

    /// `shoal.set(patch)`, where the patch may name an `investigation` to open
    /// (or `null` to close it). All or nothing: an unknown id or a bad setting
    /// changes nothing.
    pub fn set_with_investigation(
        &mut self,
        patch: serde_json::Value,
    ) -> Result<(), AutomationError> {
        use crate::investigation::link::{Request, split_patch};
        let (request, rest) =
            split_patch(&patch).map_err(|err| AutomationError::BadArgument(err.to_string()))?;
        match request {
            Request::None => self.run_command(Command::Set(rest)),
            Request::Open(investigation) => self.open_investigation(investigation, Some(&rest)),
            Request::Close => {
                self.run_command(Command::Set(rest))?;
                self.investigations.close();
                Ok(())
            }
        }
    }

    /// `shoal.state().investigation`: the one open, if any.
    pub fn investigation_report(&self) -> Option<crate::investigation::InvestigationReport> {
        self.investigations.report()
    }

    /// The student's record as `(html, csv)` (`shoal.investigation_record()`).
    pub fn investigation_record(&self) -> (String, String) {
        self.investigations.record_files()
    }

    /// Shows an explanation at the top of the view (e.g. a share link that could not
    /// be opened).
    pub fn show_error_notice(&mut self, text: String) {
        self.notice = Some(Notice::error(text));
    }

    /// What `shoal.state()` reports.
    pub fn state_report(&self) -> StateReport {
        let mut report = StateReport::new(
            &self.lab,
            self.caps.tier.name(),
            self.fps_meter.rate_per_sec(),
        );
        report.bench = self.benchmark.as_ref().map(Benchmark::report);
        report.frames = self.frames_drawn;
        report.camera = Some(CameraReport {
            yaw_deg: self.camera.yaw_rad.to_degrees(),
            pitch_deg: self.camera.pitch_rad.to_degrees(),
            distance_m: self.camera.distance_m,
            target_m: self.camera.target_m.to_array(),
        });
        report.notice = self.notice.as_ref().map(|n| n.text.clone());
        report.ui_scale = Some(self.ctx.zoom_factor());
        report.scene_detail = Some(SceneDetailReport {
            scale: self.scene_detail.scale(),
            auto: self.scene_detail.auto,
        });
        report
    }

    /// Makes the next frame panic (`shoal.crash_test()`), so tests can check that a
    /// panic is explained on the page and that reloading brings Shoal back.
    pub fn request_crash_test(&mut self) {
        self.crash_requested = true;
        self.ctx.request_repaint();
    }

    /// Starts the benchmark (the `?bench` page mode).
    pub fn start_benchmark(&mut self) {
        // Frame times at every pixel, comparable between machines and runs.
        self.scene_detail.set_auto(false);
        self.benchmark = Some(Benchmark::new());
    }

    fn benchmark_ui(&self, ui: &mut egui::Ui) {
        let Some(bench) = &self.benchmark else {
            return;
        };
        let report = bench.report();
        egui::Window::new("Benchmark")
            .anchor(egui::Align2::RIGHT_TOP, egui::vec2(-8.0, 8.0))
            .resizable(false)
            .collapsible(false)
            .show(ui.ctx(), |ui| {
                ui.label(if report.done {
                    "Done. Figures for this computer and browser:"
                } else {
                    "Measuring… (about a minute)"
                });
                egui::Grid::new("bench_rows").striped(true).show(ui, |ui| {
                    for head in [
                        "scene",
                        "fish",
                        "steps/s",
                        "fish-steps/s",
                        "frame ms",
                        "CPU ms",
                    ] {
                        ui.strong(head);
                    }
                    ui.end_row();
                    for row in &report.rows {
                        ui.label(row.scene);
                        ui.label(row.fish.to_string());
                        ui.label(format!("{:.0}", row.sim_steps_per_sec));
                        ui.label(format!("{:.0}", row.fish_steps_per_sec));
                        ui.label(format!("{:.2}", row.frame_ms));
                        ui.label(format!("{:.2}", row.cpu_frame_ms));
                        ui.end_row();
                    }
                });
                if let Some(rate) = report.annealing_evaluations_per_sec {
                    ui.label(format!("Learning lab: {rate:.1} annealing evaluations/s"));
                }
                if let Some(e) = &report.experiment {
                    ui.label(format!(
                        "Experiment {}: {:.3} runs/s ({} runs of {} steps, one thread)",
                        e.name, e.runs_per_sec, e.runs, e.steps_per_run
                    ));
                }
            });
    }

    /// The interface scale in use: CSS pixels per egui point, beyond the
    /// screen's own pixel ratio.
    pub fn interface_scale_now(&self) -> f32 {
        self.ctx.zoom_factor()
    }

    /// Where the named widgets are, for `shoal.widgets()`.
    pub fn widget_rects(&self) -> &WidgetRects {
        &self.widget_rects
    }

    /// The current settings (`shoal.settings()`), by the names `shoal.set` takes.
    pub fn state_settings(&self) -> &Settings {
        self.lab.settings()
    }

    /// `shoal.settings()`: the current settings as JSON, with the mystery
    /// values masked in the student view.
    pub fn settings_json(&self) -> serde_json::Value {
        let settings = self.lab.settings();
        let mut json = serde_json::to_value(settings).unwrap_or_default();
        settings.studio.mask_settings_json(&mut json);
        // The studio, even when empty (links leave an empty one out).
        if let (Some(object), Ok(studio)) =
            (json.as_object_mut(), serde_json::to_value(&settings.studio))
        {
            object.insert("studio".to_owned(), studio);
        }
        json
    }

    /// Masks in `state()`'s JSON what would give a mystery value away
    /// (student view only).
    pub fn mask_state_json(&self, state: &mut serde_json::Value) {
        self.lab.settings().studio.mask_state_json(state);
    }

    /// The link *Share with class* gives (`shoal.student_link()`): these
    /// settings in the student view.
    pub fn student_link(&self) -> String {
        crate::ui::studio_panel::student_link(
            self.lab.settings(),
            self.page_url.as_deref().unwrap_or_default(),
        )
    }

    /// The link that reopens the current settings (`shoal.share_link()`).
    pub fn share_link(&self) -> String {
        let page = self.page_url.clone().unwrap_or_default();
        let page = match self.investigations.open_id() {
            Some(id) => crate::investigation::link::with_investigation(&page, id),
            None => page,
        };
        format!(
            "{}#{}",
            page,
            crate::settings::share_link::encode(self.lab.settings())
        )
    }

    /// The metrics of the last minutes as CSV (`shoal.metrics_csv()`).
    pub fn metrics_csv(&self) -> String {
        self.lab.metrics_csv()
    }

    /// The scene's data file, what *Download data* saves (`shoal.export_csv()`).
    pub fn export_csv(&self) -> crate::export::CsvExport {
        crate::export::scene_csv(&self.lab)
    }

    /// Runs an automation command and asks for a repaint so the change shows.
    pub fn run_command(&mut self, command: Command) -> Result<(), AutomationError> {
        let result = command.execute(&mut self.lab);
        self.ctx.request_repaint();
        result
    }

    /// What the lab measured of its own steps, to scale an experiment's estimate.
    fn lab_cost(&self) -> crate::ui::LabCost {
        crate::ui::LabCost {
            secs_per_step: self.lab.step_cost_secs(),
            animals: self.lab.runs().iter().map(|r| r.animal_count()).sum(),
            fps: self.fps_meter.rate_per_sec(),
        }
    }

    /// Starts an experiment from a design (`shoal.experiment()`), with the
    /// current settings under any the design leaves out.
    pub fn start_experiment(
        &mut self,
        design: &serde_json::Value,
    ) -> Result<(), crate::experiment::DesignError> {
        let design = crate::experiment::Design::from_json(&design.to_string())?;
        let cost = self.lab_cost();
        self.experiment.start(&self.ctx, &design, cost)
    }

    /// Cancels the experiment under way (`shoal.cancel_experiment()`), keeping
    /// its completed runs; false if none was running.
    pub fn cancel_experiment(&mut self) -> bool {
        self.ctx.request_repaint();
        self.experiment.cancel()
    }

    /// `shoal.state().experiment`.
    pub fn experiment_report(&self) -> Option<crate::experiment::ExperimentReport> {
        self.experiment.report()
    }

    /// Frames what the scene is about (the whole tank unless its panel says
    /// otherwise), and stops following.
    fn reset_view(&mut self) {
        let tank = self.lab.scene().tank();
        let settings = self.lab.settings();
        self.camera = match self
            .scene_panel
            .for_scene(settings.scene)
            .framing(&self.lab.runs()[0], settings)
        {
            Some(framing) => OrbitCamera::framed(&framing, self.framed_aspect),
            None => OrbitCamera::framing(tank.min_m, tank.max_m, self.framed_aspect),
        };
        self.camera_is_default = true;
        self.following = false;
    }

    /// The interface scale (automatic unless chosen) and, on the first frame,
    /// the side panel closed in a narrow window (a phone sees the tank first).
    fn choose_screen_layout(&mut self) {
        use crate::ui::screen::{auto_scale, is_narrow};
        let zoom = self.ctx.zoom_factor();
        let css = self.ctx.content_rect().size() * zoom;
        let wanted = self
            .interface_scale
            .unwrap_or_else(|| auto_scale(css.x, css.y));
        if (wanted - zoom).abs() > 0.005 {
            self.ctx.set_zoom_factor(wanted);
        }
        if !self.layout_chosen && css.x > 0.0 {
            self.layout_chosen = true;
            if is_narrow(css.x / wanted) {
                self.panel_open = false;
            }
        }
    }

    /// Orbit, zoom and pan from mouse and touch input on a 3D view.
    fn camera_input(&mut self, ui: &egui::Ui, response: &egui::Response, rect: egui::Rect) {
        let camera_before = self.camera.clone();
        let (zoom, scroll, multi_touch) =
            ui.input(|i| (i.zoom_delta(), i.smooth_scroll_delta(), i.multi_touch()));
        if let Some(touch) = multi_touch {
            // Two fingers: pinch to zoom, drag to pan.
            if response.contains_pointer() || response.hovered() {
                self.camera.zoom(touch.zoom_delta);
                self.camera.pan(
                    touch.translation_delta.x,
                    touch.translation_delta.y,
                    rect.height(),
                );
            }
        } else {
            if response.dragged_by(egui::PointerButton::Primary)
                && !self.scene_panel.get().holds_drag()
            {
                let delta = response.drag_delta();
                self.camera.rotate(delta.x, delta.y);
            }
            if response.dragged_by(egui::PointerButton::Secondary)
                || response.dragged_by(egui::PointerButton::Middle)
            {
                let delta = response.drag_delta();
                self.camera.pan(delta.x, delta.y, rect.height());
            }
            if response.hovered() {
                self.camera.zoom(zoom * (scroll.y * 0.0015).exp());
            }
        }
        if self.camera != camera_before {
            self.camera_is_default = false;
        }
    }

    /// The 3D views: one tank, or two side by side (one above the other when
    /// that shows the tanks clearly bigger, see [`compare_layout`]).
    fn views_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings) {
        let full = ui.available_rect_before_wrap();
        self.widget_rects.insert("aquarium", full);
        let frame_secs = ui.input(|i| i.stable_dt).min(0.5);
        self.follow_selected(settings, frame_secs);
        let count = self.lab.runs().len();
        let rects = compare_layout(full, count);
        self.views_stacked = rects.len() > 1 && rects[0].left() == rects[1].left();
        let aspect = rects[0].width() / rects[0].height().max(1.0);
        if self.camera_is_default && (aspect - self.framed_aspect).abs() > 0.01 {
            self.framed_aspect = aspect;
            self.reset_view();
        }
        for (index, rect) in rects.into_iter().enumerate() {
            self.view_ui(ui, rect, index, settings);
        }
    }

    /// Glides the camera's target towards the animal the scene follows.
    fn follow_selected(&mut self, settings: &Settings, frame_secs: f32) {
        let Some(selected) = self.scene_panel.get().followed(settings) else {
            self.following = false;
            return;
        };
        let run = &self.lab.runs()[0];
        let Some((_, centre, length)) = run
            .selectable_animals(self.lab.draw_alpha())
            .into_iter()
            .find(|a| a.0 == selected as usize)
        else {
            return;
        };
        let share = 1.0 - (-frame_secs.max(0.0) / FOLLOW_TIME_CONSTANT_SECS).exp();
        self.camera.target_m = self.camera.target_m.lerp(centre, share);
        // On starting to follow, come close enough to see the body bend: about eight
        // body lengths away (the teacher may zoom afterwards).
        if !self.following {
            self.following = true;
            self.camera.distance_m = self.camera.distance_m.min(8.0 * length);
        }
        self.camera_is_default = false;
        self.ctx.request_repaint();
    }

    fn view_ui(
        &mut self,
        ui: &mut egui::Ui,
        rect: egui::Rect,
        index: usize,
        settings: &mut Settings,
    ) {
        let side = Side::BOTH[index];
        let response = ui.interact(
            rect,
            egui::Id::unique(("aquarium_view", index)),
            egui::Sense::click_and_drag(),
        );
        self.widget_rects
            .insert(&format!("view_{}", side.name()), rect);
        let input = ViewInput {
            response: &response,
            rect,
            camera: &self.camera,
            lab: &self.lab,
            side,
        };
        if let Some(notice) = self.scene_panel.get_mut().view_input(&input, settings) {
            self.notice = Some(notice);
        }
        self.camera_input(ui, &response, rect);

        let pixels_per_point = ui.ctx().pixels_per_point();
        let size_px = self.scene_detail.image_size([
            rect.width() * pixels_per_point,
            rect.height() * pixels_per_point,
        ]);
        let run = &self.lab.runs()[index];
        // The water animates with simulated time: pausing freezes the whole picture.
        let time_secs = run.time_secs() as f32;
        self.frame_builders[index].set_selected(self.scene_panel.get().selected(settings));
        let frame = self.frame_builders[index].build(
            run,
            self.lab.draw_alpha(),
            &self.camera,
            size_px,
            time_secs,
            index as u32,
        );
        ui.painter()
            .add(eframe::egui_wgpu::Callback::new_paint_callback(rect, frame));

        let painter = ui.painter_at(rect);
        let view = ViewContext {
            painter: &painter,
            rect,
            camera: &self.camera,
            run,
            alpha: self.lab.draw_alpha(),
            side,
            comparing: self.lab.comparing(),
            stacked: self.views_stacked,
            panel_hidden: !self.panel_open,
        };
        self.scene_panel
            .get()
            .draw_overlays(&view, settings, &mut self.widget_rects);

        // Reset view, always at hand: at the top right of the last view.
        if index + 1 == self.lab.runs().len() {
            let size = egui::vec2(112.0, 26.0);
            let at = rect.right_top() + egui::vec2(-size.x - 8.0, 8.0);
            let button = ui
                .put(
                    egui::Rect::from_min_size(at, size),
                    egui::Button::new("Reset view (V)"),
                )
                .on_hover_text("Put the camera back on what this scene is about");
            self.widget_rects.insert("reset_view", button.rect);
            if button.clicked() {
                self.reset_view();
            }
        }
    }

    fn apply(&mut self, actions: Vec<PanelAction>) {
        for action in actions {
            match action {
                PanelAction::Step => self.lab.step(1),
                PanelAction::Reset => self.lab.reset(None),
                PanelAction::ResetView => self.reset_view(),
                PanelAction::HidePanel => self.panel_open = false,
                PanelAction::CopyLink => {
                    let link = self.share_link();
                    self.ctx.copy_text(link);
                    self.notice = Some(Notice::info(
                        "Link copied. Paste it in a message or a web page: it opens \
                         Shoal with exactly these settings.",
                    ));
                }
                PanelAction::ExportCsv => {
                    let csv = self.export_csv();
                    self.notice = Some(
                        match crate::ui::save_text_file(
                            &csv.name,
                            "text/csv",
                            &csv.text,
                            Some("open it with a spreadsheet"),
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

    /// The learned controllers in use, as JSON (`shoal.save_controllers()`).
    pub fn controllers_json(&self) -> Result<String, crate::ui::SaveControllersError> {
        crate::ui::controllers_json(&self.lab)
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
                        let close = ui.button("OK").on_hover_text("Hide this message");
                        self.widget_rects.insert("notice_ok", close.rect);
                        if close.clicked() {
                            self.notice = None;
                        }
                    });
                });
            });
    }
}

/// Space: play/pause; S: one step; R: reset; V: reset the view. Ignored while
/// typing in a text field.
fn keyboard_shortcuts(ui: &egui::Ui, settings: &mut Settings) -> Vec<PanelAction> {
    let mut actions = Vec::new();
    if ui.ctx().egui_wants_keyboard_input() {
        return actions;
    }
    ui.input(|input| {
        if input.key_pressed(egui::Key::Space) {
            settings.paused = !settings.paused;
        }
        if input.key_pressed(egui::Key::S) {
            actions.push(PanelAction::Step);
        }
        if input.key_pressed(egui::Key::R) {
            actions.push(PanelAction::Reset);
        }
        if input.key_pressed(egui::Key::V) {
            actions.push(PanelAction::ResetView);
        }
    });
    actions
}

impl eframe::App for ShoalApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        assert!(
            !self.crash_requested,
            "crash test requested through shoal.crash_test()"
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

        self.choose_screen_layout();
        let status = self.state_report();
        egui::Panel::bottom("status").show(ui, |ui| {
            let settings = self.lab.settings();
            let hidden_count = settings.studio.count_is_mystery_for_student(settings.scene);
            status_line_ui(ui, &status, self.caps, hidden_count);
        });

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

        let mut actions = keyboard_shortcuts(ui, &mut settings);
        let step_secs = self.lab.scene().dt_secs();
        let width = ui.ctx().content_rect().width();
        let mut view = crate::ui::ViewOptions {
            interface_scale: self.interface_scale,
            current_scale: ui.ctx().zoom_factor(),
            detail_auto: self.scene_detail.auto,
            detail_scale: self.scene_detail.scale(),
        };
        egui::Panel::left("controls")
            .default_size(if crate::ui::screen::is_narrow(width) {
                crate::ui::screen::drawer_width(width)
            } else {
                270.0
            })
            .resizable(true)
            .show_collapsible(ui, &mut self.panel_open, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui.add_space(6.0);
                    crate::ui::investigations_button(ui, &mut self.widget_rects);
                    actions.extend(control_panel_ui(
                        ui,
                        &mut settings,
                        &mut self.scene_panel,
                        step_secs,
                        &mut view,
                        &mut self.widget_rects,
                    ));
                });
            });
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
                    let button = egui::Button::new("Controls");
                    let at = ui.max_rect().left_top() + egui::vec2(8.0, 8.0);
                    let show = ui
                        .put(
                            egui::Rect::from_min_size(at, egui::vec2(100.0, 28.0)),
                            button,
                        )
                        .on_hover_text("Show the control panel");
                    self.widget_rects.insert("show_panel", show.rect);
                    if show.clicked() {
                        self.panel_open = true;
                    }
                }
                self.notice_ui(ui);
            });
        crate::ui::about_window(ui.ctx(), settings.scene, &mut self.widget_rects);
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
                    let page = self.page_url.clone().unwrap_or_default();
                    self.ctx
                        .copy_text(crate::experiment::link::link(&page, &design));
                    self.notice = Some(Notice::info(
                        "Link copied: it opens Shoal on this experiment and runs it again, \
                         with the same numbers."
                            .to_owned(),
                    ));
                }
            }
        }
        let page_url = self.page_url.clone().unwrap_or_default();
        if let Some(notice) =
            self.studio
                .windows_ui(ui.ctx(), &mut settings, &page_url, &mut self.widget_rects)
        {
            self.notice = Some(notice);
        }
        let mut run_investigation = false;
        for action in
            self.investigations
                .windows_ui(ui.ctx(), &self.lab, &settings, &mut self.widget_rects)
        {
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

/// Width over height of the tank as the default camera frames it (about 2:1).
/// Used to judge which layout of two views shows the tanks bigger.
const FRAMED_TANK_ASPECT: f32 = 1.9;

/// Where `count` views (1 or 2) go in `full`. Two tanks sit side by side, or
/// one above the other when that draws them at least 15 % bigger (a tall
/// window, a portrait tablet): a framed tank fills the width of a view or the
/// height times [`FRAMED_TANK_ASPECT`], whichever is smaller.
fn compare_layout(full: egui::Rect, count: usize) -> Vec<egui::Rect> {
    const GAP: f32 = 4.0;
    if count < 2 {
        return vec![full];
    }
    let (w, h) = (full.width(), full.height());
    let side_by_side = ((w - GAP) / 2.0).min(h * FRAMED_TANK_ASPECT);
    let stacked = w.min((h - GAP) / 2.0 * FRAMED_TANK_ASPECT);
    if stacked > 1.15 * side_by_side {
        let height = (h - GAP) / 2.0;
        (0..count)
            .map(|i| {
                egui::Rect::from_min_size(
                    full.min + egui::vec2(0.0, i as f32 * (height + GAP)),
                    egui::vec2(w, height),
                )
            })
            .collect()
    } else {
        let width = (w - GAP) / 2.0;
        (0..count)
            .map(|i| {
                egui::Rect::from_min_size(
                    full.min + egui::vec2(i as f32 * (width + GAP), 0.0),
                    egui::vec2(width, h),
                )
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(w: f32, h: f32) -> egui::Rect {
        egui::Rect::from_min_size(egui::pos2(330.0, 0.0), egui::vec2(w, h))
    }

    #[test]
    fn two_tanks_sit_side_by_side_on_a_wide_screen_and_stack_on_a_tall_one() {
        // A projector (16:9 less the panel): side by side.
        let wide = compare_layout(rect(1590.0, 800.0), 2);
        assert_eq!(wide.len(), 2);
        assert_eq!(wide[0].top(), wide[1].top());
        assert!(wide[0].right() < wide[1].left());
        // A portrait tablet: one above the other, each the full width.
        let tall = compare_layout(rect(1036.0, 1000.0), 2);
        assert_eq!(tall[0].left(), tall[1].left());
        assert!(tall[0].bottom() < tall[1].top());
        assert_eq!(tall[0].width(), 1036.0);
        for layout in [wide, tall] {
            assert!(
                layout
                    .iter()
                    .all(|r| rect(1590.0, 1000.0).contains_rect(*r))
            );
        }
        assert_eq!(
            compare_layout(rect(800.0, 600.0), 1),
            vec![rect(800.0, 600.0)]
        );
    }
}
