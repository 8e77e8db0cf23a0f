//! The eframe application: one `Lab`, the 3D view and the panels around it.
//!
//! Each frame: advance the lab by the fixed steps real time asks for, lay out the
//! panels (which may change settings), handle camera input on the 3D view and hand
//! the renderer a freshly built frame.

use eframe::egui;

use crate::automation::{AutomationError, CameraReport, Command, StateReport};
use crate::bench::Benchmark;
use crate::clock::RateMeter;
use crate::lab::Lab;
use crate::render::{FrameBuilder, OrbitCamera, RenderCaps, SceneRenderer};
use crate::settings::Settings;
use crate::ui::{PanelAction, WidgetRects, control_panel_ui, status_line_ui};

/// The Shoal app.
pub struct ShoalApp {
    lab: Lab,
    camera: OrbitCamera,
    /// True until the user moves the camera: the default view then re-frames the
    /// tank whenever the view's shape changes (window resize, panel hidden).
    camera_is_default: bool,
    /// Aspect ratio the camera was last framed for.
    framed_aspect: f32,
    frame_builder: FrameBuilder,
    caps: RenderCaps,
    panel_open: bool,
    fps_meter: RateMeter,
    last_frame_time_secs: Option<f64>,
    widget_rects: WidgetRects,
    /// The in-app benchmark, when started (`?bench`).
    benchmark: Option<Benchmark>,
    /// Set by `shoal.crash_test()`: the next frame panics, to test the error page.
    crash_requested: bool,
    ctx: egui::Context,
}

impl ShoalApp {
    /// Creates the app on eframe's wgpu renderer. Fails with a readable message when
    /// no GPU renderer is available.
    pub fn new(cc: &eframe::CreationContext<'_>, settings: Settings) -> Result<Self, String> {
        let render_state = cc.wgpu_render_state.as_ref().ok_or_else(|| {
            "Shoal needs a GPU renderer (WebGPU or WebGL2), and none could be started.".to_owned()
        })?;
        let caps = SceneRenderer::install(render_state);
        log::info!(
            "render tier: {} ({:?}), MSAA ×{}",
            caps.tier.label(),
            render_state.adapter.get_info().backend,
            caps.msaa_samples
        );
        cc.egui_ctx.set_theme(egui::Theme::Dark);
        let lab = Lab::new(settings);
        let tank = lab.world().tank();
        Ok(Self {
            camera: OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0),
            camera_is_default: true,
            framed_aspect: 16.0 / 9.0,
            lab,
            frame_builder: FrameBuilder::default(),
            caps,
            panel_open: true,
            fps_meter: RateMeter::default(),
            last_frame_time_secs: None,
            widget_rects: WidgetRects::new(),
            benchmark: None,
            crash_requested: false,
            ctx: cc.egui_ctx.clone(),
        })
    }

    /// What `shoal.state()` reports.
    pub fn state_report(&self) -> StateReport {
        let mut report = StateReport::new(
            &self.lab,
            self.caps.tier.name(),
            self.fps_meter.rate_per_sec(),
        );
        report.bench = self.benchmark.as_ref().map(Benchmark::report);
        report.camera = Some(CameraReport {
            yaw_deg: self.camera.yaw_rad.to_degrees(),
            pitch_deg: self.camera.pitch_rad.to_degrees(),
            distance_m: self.camera.distance_m,
            target_m: self.camera.target_m.to_array(),
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
                    "Measuring… (about 15 seconds)"
                });
                egui::Grid::new("bench_rows").striped(true).show(ui, |ui| {
                    for head in ["fish", "steps/s", "fish-steps/s", "frame ms", "CPU ms"] {
                        ui.strong(head);
                    }
                    ui.end_row();
                    for row in &report.rows {
                        ui.label(row.fish.to_string());
                        ui.label(format!("{:.0}", row.sim_steps_per_sec));
                        ui.label(format!("{:.0}", row.fish_steps_per_sec));
                        ui.label(format!("{:.2}", row.frame_ms));
                        ui.label(format!("{:.2}", row.cpu_frame_ms));
                        ui.end_row();
                    }
                });
            });
    }

    /// Where the named widgets are, for `shoal.widgets()`.
    pub fn widget_rects(&self) -> &WidgetRects {
        &self.widget_rects
    }

    /// The current settings (`shoal.settings()`), by the names `shoal.set` takes.
    pub fn state_settings(&self) -> &Settings {
        self.lab.settings()
    }

    /// Runs an automation command and asks for a repaint so the change shows.
    pub fn run_command(&mut self, command: Command) -> Result<(), AutomationError> {
        let result = command.execute(&mut self.lab);
        self.ctx.request_repaint();
        result
    }

    fn reset_view(&mut self) {
        let tank = self.lab.world().tank();
        self.camera = OrbitCamera::framing(tank.min_m, tank.max_m, self.framed_aspect);
        self.camera_is_default = true;
    }

    /// The 3D view: camera input, then the paint callback.
    fn aquarium_ui(&mut self, ui: &mut egui::Ui) {
        let rect = ui.available_rect_before_wrap();
        let response = ui.allocate_rect(rect, egui::Sense::click_and_drag());
        self.widget_rects.insert("aquarium", rect);
        let aspect = rect.width() / rect.height().max(1.0);
        if self.camera_is_default && (aspect - self.framed_aspect).abs() > 0.01 {
            self.framed_aspect = aspect;
            self.reset_view();
        }
        let camera_before = self.camera.clone();
        let (zoom, scroll, multi_touch) =
            ui.input(|i| (i.zoom_delta(), i.smooth_scroll_delta(), i.multi_touch()));
        if let Some(touch) = multi_touch {
            // Two fingers: pinch to zoom, drag to pan.
            self.camera.zoom(touch.zoom_delta);
            self.camera.pan(
                touch.translation_delta.x,
                touch.translation_delta.y,
                rect.height(),
            );
        } else {
            if response.dragged_by(egui::PointerButton::Primary) {
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

        let pixels_per_point = ui.ctx().pixels_per_point();
        let size_px = [
            (rect.width() * pixels_per_point).round().max(1.0) as u32,
            (rect.height() * pixels_per_point).round().max(1.0) as u32,
        ];
        // The water animates with simulated time: pausing freezes the whole picture.
        let time_secs = self.lab.world().time_secs() as f32;
        let frame = self
            .frame_builder
            .build(&self.lab, &self.camera, size_px, time_secs, 0);
        ui.painter()
            .add(eframe::egui_wgpu::Callback::new_paint_callback(rect, frame));
    }

    fn apply(&mut self, actions: Vec<PanelAction>) {
        for action in actions {
            match action {
                PanelAction::Step => self.lab.step(1),
                PanelAction::Reset => self.lab.reset(None),
                PanelAction::ResetView => self.reset_view(),
                PanelAction::HidePanel => self.panel_open = false,
            }
        }
    }
}

/// Space: play/pause; S: one step; R: reset. Ignored while typing in a text field.
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
        self.lab.advance_frame(frame_secs, now_secs);
        self.fps_meter.record(now_secs, 1);

        let status = self.state_report();
        egui::Panel::bottom("status").show(ui, |ui| {
            status_line_ui(ui, &status, self.caps);
        });

        let mut settings = self.lab.settings().clone();
        let mut actions = keyboard_shortcuts(ui, &mut settings);
        egui::Panel::left("controls")
            .default_size(250.0)
            .resizable(true)
            .show_collapsible(ui, &mut self.panel_open, |ui| {
                actions.extend(control_panel_ui(ui, &mut settings, &mut self.widget_rects));
            });
        if &settings != self.lab.settings() {
            self.lab.apply_settings(settings);
        }
        self.apply(actions);

        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| {
                self.aquarium_ui(ui);
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
            });

        self.benchmark_ui(ui);

        // Keep animating while the simulation runs. While paused the picture is
        // still, so egui repaints only on input: a paused class saves battery.
        if !self.lab.settings().paused {
            ui.ctx().request_repaint();
        }
    }

    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(&mut *self)
    }
}
