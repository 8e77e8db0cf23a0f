//! The eframe application: one `Lab` (one tank, or two side by side), the 3D views
//! and the panels around them.
//!
//! Each frame: advance the lab by the fixed steps real time asks for, lay out the
//! panels (which may change settings), handle camera and rock-editing input on each
//! 3D view, and hand the renderer a freshly built frame per view.

use eframe::egui;
use glam::{Vec2, Vec3};

use crate::automation::{AutomationError, CameraReport, Command, StateReport};
use crate::bench::Benchmark;
use crate::clock::RateMeter;
use crate::lab::{Lab, LabError, Run};
use crate::render::{FrameBuilder, OrbitCamera, RenderCaps, SceneRenderer};
use crate::settings::{Scene, Settings, Side};
use crate::sim::Obstacle;
use crate::ui::{
    BODY_PLOTS_PANEL_HEIGHT, EditTool, METRICS_PANEL_HEIGHT, PanelAction, PanelState, WidgetRects,
    body_overlay, body_plots_ui, control_panel_ui, metrics_panel_ui, mode_label, reef_overlay,
    reef_panel, show_bottom_panel, side_color, status_line_ui,
};

/// Physical animals whose screen rectangles `shoal.widgets()` reports (`animal_0`,
/// …), for tests that click a fish. 20: the default tank's ten fish and shark.
const ANIMAL_RECTS_MAX: usize = 20;

/// Time constant of the follow camera gliding to the selected fish, seconds (0.4,
/// chosen: smooth, and a fish at top speed never leaves the view, at any frame rate).
const FOLLOW_TIME_CONSTANT_SECS: f32 = 0.4;

/// Radius of a rock a teacher adds by clicking, metres. Default 0.6 m: clearly
/// visible, two fish lengths across, small enough to place between others.
const NEW_ROCK_RADIUS_M: f32 = 0.6;

/// Fish whose vision is drawn at most ("Show vision"). Default 300: every fish of a
/// classroom-sized school; beyond that the lines would hide the fish.
const VISION_OBSERVERS_MAX: usize = 300;

/// Neighbour links drawn per fish at most. Default 7: the number of neighbours a
/// schooling animal attends to (Ballerini et al. 2008), and a readable picture.
const VISION_LINKS_PER_FISH: usize = 7;

/// Fish whose field of view is drawn as a fan. Default 3: a few examples; fans for
/// every fish would cover the tank.
const VISION_FANS: usize = 3;

/// A message shown at the top of the 3D view until dismissed.
#[derive(Clone, Debug, PartialEq)]
struct Notice {
    text: String,
    is_error: bool,
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
    panel_open: bool,
    panel: PanelState,
    fps_meter: RateMeter,
    last_frame_time_secs: Option<f64>,
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
    /// The obstacle being dragged with the Move tool: tank and index.
    dragging: Option<(Side, usize)>,
    /// Is the camera following the selected fish (physics scene)?
    following: bool,
    /// The reef's selected fish's retinal image: which fish, the texture, its mean
    /// brightness and when (app time, seconds) it was rendered.
    fish_eye: Option<(u32, egui::TextureHandle, f32, f64)>,
    /// The learning lab's current drill abstracted (for Fig. 8), and when (app
    /// time, seconds).
    learning_abstraction: Option<(f64, crate::sim::learning::Abstraction)>,
    /// The scene the camera was last framed for.
    viewed_scene: Scene,
    /// A controllers file the user picked, read asynchronously in the browser.
    pending_load: std::rc::Rc<std::cell::RefCell<Option<Result<String, String>>>>,
    ctx: egui::Context,
}

/// How far the default camera stands from the learning lab's buoys, metres (7.5:
/// the buoys, the swimmer and the race lanes fill the view).
const LEARNING_VIEW_DISTANCE_M: f32 = 7.5;

/// Seconds between two renders of the fish-eye view (0.2, chosen: smooth enough
/// to follow, cheap: one 96 × 96 ray cast).
const FISH_EYE_EVERY_SECS: f64 = 0.2;
/// Pixels across the fish-eye view.
const FISH_EYE_SIZE_PX: usize = 96;

/// The fish selected in the current scene (physics or reef).
fn selected_of(settings: &Settings) -> Option<u32> {
    match settings.scene {
        Scene::Physics => settings.physics.selected,
        Scene::Reef => settings.reef.selected,
        Scene::Aquarium | Scene::Boids | Scene::Learning => None,
    }
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
        let mut lab = Lab::new(settings);
        lab.set_frame_budget(Some(crate::lab::INTERACTIVE_FRAME_BUDGET_SECS));
        let tank = lab.scene().tank();
        Ok(Self {
            camera: OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0),
            camera_is_default: true,
            framed_aspect: 16.0 / 9.0,
            lab,
            frame_builders: Default::default(),
            caps,
            panel_open: true,
            panel: PanelState::default(),
            fps_meter: RateMeter::default(),
            last_frame_time_secs: None,
            frames_drawn: 0,
            views_stacked: false,
            widget_rects: WidgetRects::new(),
            benchmark: None,
            crash_requested: false,
            notice: None,
            page_url: None,
            dragging: None,
            following: false,
            fish_eye: None,
            learning_abstraction: None,
            viewed_scene: Scene::Aquarium,
            pending_load: Default::default(),
            ctx: cc.egui_ctx.clone(),
        })
    }

    /// Tells the app its page address (for share links).
    pub fn set_page_url(&mut self, url: String) {
        self.page_url = Some(url);
    }

    /// Shows an explanation at the top of the view (e.g. a share link that could not
    /// be opened).
    pub fn show_error_notice(&mut self, text: String) {
        self.notice = Some(Notice {
            text,
            is_error: true,
        });
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

    /// The link that reopens the current settings (`shoal.share_link()`).
    pub fn share_link(&self) -> String {
        format!(
            "{}#{}",
            self.page_url.as_deref().unwrap_or_default(),
            crate::settings::share_link::encode(self.lab.settings())
        )
    }

    /// The metrics of the last minutes as CSV (`shoal.metrics_csv()`).
    pub fn metrics_csv(&self) -> String {
        self.lab.metrics_csv()
    }

    /// Runs an automation command and asks for a repaint so the change shows.
    pub fn run_command(&mut self, command: Command) -> Result<(), AutomationError> {
        let result = command.execute(&mut self.lab);
        self.ctx.request_repaint();
        result
    }

    fn reset_view(&mut self) {
        let tank = self.lab.scene().tank();
        self.camera = OrbitCamera::framing(tank.min_m, tank.max_m, self.framed_aspect);
        // The learning lab's swimmers are small in a big tank: look at them.
        if let Some(l) = self.lab.runs()[0].learning() {
            let buoys = l.buoys_m();
            // Between the buoys and the race's start line behind the swimmer.
            self.camera.target_m = (buoys[0] + buoys[1]) * 0.5 - Vec3::new(1.0, 0.0, 0.0);
            self.camera.distance_m = LEARNING_VIEW_DISTANCE_M;
        }
        self.camera_is_default = true;
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
            if response.dragged_by(egui::PointerButton::Primary) && self.dragging.is_none() {
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

    /// Renders the selected reef fish's retinal image every [`FISH_EYE_EVERY_SECS`].
    fn refresh_fish_eye(&mut self, now_secs: f64, selected: Option<u32>) {
        let Some(selected) = selected else {
            self.fish_eye = None;
            return;
        };
        let fresh = self
            .fish_eye
            .as_ref()
            .is_some_and(|f| f.0 == selected && now_secs - f.3 < FISH_EYE_EVERY_SECS);
        if fresh {
            return;
        }
        let Some(retina) = self.lab.runs()[0]
            .reef()
            .and_then(|r| r.retina(selected as usize, FISH_EYE_SIZE_PX))
        else {
            self.fish_eye = None;
            return;
        };
        let image = egui::ColorImage::from_rgba_unmultiplied(
            [retina.size, retina.size],
            &retina.to_rgba8(),
        );
        match &mut self.fish_eye {
            Some((id, texture, brightness, at)) => {
                texture.set(image, egui::TextureOptions::LINEAR);
                (*id, *brightness, *at) = (selected, retina.mean_brightness, now_secs);
            }
            None => {
                let texture =
                    self.ctx
                        .load_texture("fish_eye", image, egui::TextureOptions::LINEAR);
                self.fish_eye = Some((selected, texture, retina.mean_brightness, now_secs));
            }
        }
    }

    /// Physics and reef scenes: glides the camera's target towards the selected
    /// fish.
    fn follow_selected(&mut self, settings: &Settings, frame_secs: f32) {
        let follow = match settings.scene {
            Scene::Physics => settings.physics.follow,
            Scene::Reef => settings.reef.follow,
            Scene::Aquarium | Scene::Boids | Scene::Learning => false,
        };
        let Some(selected) = selected_of(settings).filter(|_| follow) else {
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

    /// Physics scene: a click on a fish selects it, a click on open water lets go.
    fn pick_input(&mut self, response: &egui::Response, rect: egui::Rect, settings: &mut Settings) {
        if !response.clicked() {
            return;
        }
        let Some(pointer) = response.interact_pointer_pos() else {
            return;
        };
        let picked = body_overlay::pick_animal(
            pointer,
            rect,
            &self.camera,
            &self.lab.runs()[0],
            self.lab.draw_alpha(),
        );
        if settings.scene == Scene::Reef {
            settings.reef.selected = picked;
            if picked.is_none() {
                settings.reef.follow = false;
            }
            return;
        }
        let physics = &mut settings.physics;
        physics.selected = picked;
        if picked.is_none() {
            physics.hand_control = false;
            physics.follow = false;
        }
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
        let aspect = rect.width() / rect.height().max(1.0);
        if settings.scene == Scene::Boids {
            self.rock_tool_input(&response, rect, aspect, side, settings);
        }
        if matches!(settings.scene, Scene::Physics | Scene::Reef) {
            self.pick_input(&response, rect, settings);
        }
        self.camera_input(ui, &response, rect);

        let pixels_per_point = ui.ctx().pixels_per_point();
        let size_px = [
            (rect.width() * pixels_per_point).round().max(1.0) as u32,
            (rect.height() * pixels_per_point).round().max(1.0) as u32,
        ];
        let run = &self.lab.runs()[index];
        // The water animates with simulated time: pausing freezes the whole picture.
        let time_secs = run.time_secs() as f32;
        self.frame_builders[index].set_selected(selected_of(settings));
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
        if settings.show_vision && settings.scene == Scene::Boids {
            draw_vision(&painter, rect, &self.camera, run, self.lab.draw_alpha());
        }
        if settings.scene == Scene::Physics {
            let (alpha, physics) = (self.lab.draw_alpha(), &settings.physics);
            if physics.show_body {
                body_overlay::draw_skeletons(
                    &painter,
                    rect,
                    &self.camera,
                    run,
                    alpha,
                    physics.selected,
                );
            }
            if physics.show_forces {
                body_overlay::draw_forces(
                    &painter,
                    rect,
                    &self.camera,
                    run,
                    alpha,
                    physics.selected,
                );
            }
            if let Some(selected) = physics.selected {
                body_overlay::draw_selection(&painter, rect, &self.camera, run, alpha, selected);
            }
            // Where the first animals are on screen, so browser tests can click one.
            for (i, r) in
                body_overlay::animal_screen_rects(rect, &self.camera, run, alpha, ANIMAL_RECTS_MAX)
                    .into_iter()
                    .enumerate()
            {
                if let Some(r) = r {
                    self.widget_rects.insert(&format!("animal_{i}"), r);
                }
            }
        }
        if settings.scene == Scene::Reef {
            let alpha = self.lab.draw_alpha();
            reef_overlay::draw_water(&painter, rect, &self.camera, run, settings.reef.overlay);
            if let Some(selected) = settings.reef.selected {
                if settings.reef.show_vision {
                    reef_overlay::draw_vision(&painter, rect, &self.camera, run, alpha, selected);
                }
                body_overlay::draw_selection(&painter, rect, &self.camera, run, alpha, selected);
            }
            for (i, r) in
                body_overlay::animal_screen_rects(rect, &self.camera, run, alpha, ANIMAL_RECTS_MAX)
                    .into_iter()
                    .enumerate()
            {
                if let Some(r) = r {
                    self.widget_rects.insert(&format!("animal_{i}"), r);
                }
            }
        }
        if self.lab.comparing() {
            let tank = settings.tank(side);
            let label = format!(
                "{} · {} · {}",
                match (side, self.views_stacked) {
                    (Side::Left, false) => "Left tank",
                    (Side::Right, false) => "Right tank",
                    (Side::Left, true) => "Left tank (top)",
                    (Side::Right, true) => "Right tank (bottom)",
                },
                tank.preset.label(),
                mode_label(tank.mode)
            );
            let at = rect.left_top()
                + egui::vec2(
                    10.0,
                    if index == 0 && !self.panel_open {
                        44.0
                    } else {
                        8.0
                    },
                );
            let galley =
                painter.layout_no_wrap(label, egui::FontId::proportional(15.0), side_color(side));
            painter.rect_filled(
                egui::Rect::from_min_size(at, galley.size()).expand(4.0),
                4.0,
                egui::Color32::from_black_alpha(150),
            );
            painter.galley(at, galley, side_color(side));
        }
    }

    /// Adds, moves or removes obstacles with the mouse (the panel's rock tools).
    fn rock_tool_input(
        &mut self,
        response: &egui::Response,
        rect: egui::Rect,
        aspect: f32,
        side: Side,
        settings: &mut Settings,
    ) {
        let tool = self.panel.tool;
        if tool == EditTool::Look {
            return;
        }
        let Some(pointer) = response.interact_pointer_pos().or(response.hover_pos()) else {
            return;
        };
        let uv = Vec2::new(
            (pointer.x - rect.min.x) / rect.width().max(1.0),
            (pointer.y - rect.min.y) / rect.height().max(1.0),
        );
        let (origin, direction) = self.camera.ray(uv, aspect);
        let Some(run) = self.lab.run(side) else {
            return;
        };
        let world = run.scene();
        let tank = *world.tank();
        let current: Vec<Obstacle> = settings
            .tank(side)
            .obstacles
            .clone()
            .unwrap_or_else(|| world.obstacles().to_vec());
        let floor_hit = floor_point(origin, direction, tank.min_m.y);
        match tool {
            EditTool::Look => {}
            EditTool::AddRock => {
                if response.clicked()
                    && let Some(p) = floor_hit
                {
                    let rock = Obstacle::Rock {
                        center_m: Vec3::new(p.x, tank.min_m.y - 0.2 * NEW_ROCK_RADIUS_M, p.z),
                        radius_m: NEW_ROCK_RADIUS_M,
                    };
                    let mut next = current;
                    next.push(rock);
                    self.propose_obstacles(settings, side, next);
                }
            }
            EditTool::RemoveRock => {
                if response.clicked()
                    && let Some(i) = picked_obstacle(&current, origin, direction)
                {
                    let mut next = current;
                    next.remove(i);
                    self.propose_obstacles(settings, side, next);
                }
            }
            EditTool::MoveRock => {
                if response.drag_started_by(egui::PointerButton::Primary) {
                    self.dragging = picked_obstacle(&current, origin, direction).map(|i| (side, i));
                }
                if let (Some((drag_side, i)), Some(p)) = (self.dragging, floor_hit)
                    && drag_side == side
                    && response.dragged_by(egui::PointerButton::Primary)
                    && i < current.len()
                {
                    let mut next = current;
                    next[i] = next[i].moved_to(Vec2::new(p.x, p.z));
                    self.propose_obstacles(settings, side, next);
                }
                if response.drag_stopped() {
                    self.dragging = None;
                }
            }
        }
    }

    /// Uses `obstacles` for the tank of `side` if every one is valid; otherwise
    /// explains why not and changes nothing.
    fn propose_obstacles(&mut self, settings: &mut Settings, side: Side, obstacles: Vec<Obstacle>) {
        let mut candidate = settings.clone();
        candidate.tank_mut(side).obstacles = Some(obstacles);
        match candidate.validate() {
            Ok(()) => *settings = candidate,
            Err(err) => {
                self.notice = Some(Notice {
                    text: format!("That rock cannot go there: {err}"),
                    is_error: false,
                });
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
                    self.notice = Some(Notice {
                        text: "Link copied. Paste it in a message or a web page: it opens \
                               Shoal with exactly these settings."
                            .to_owned(),
                        is_error: false,
                    });
                }
                PanelAction::ExportCsv => {
                    let csv = self.lab.metrics_csv();
                    let message = save_csv(&csv);
                    self.notice = Some(Notice {
                        is_error: message.is_err(),
                        text: message.unwrap_or_else(|e| e),
                    });
                }
                PanelAction::Turn(angle_deg) => {
                    if let Err(err) = self.lab.turn_selected(angle_deg) {
                        self.notice = Some(Notice {
                            text: err.to_string(),
                            is_error: true,
                        });
                    }
                }
                PanelAction::RestoreObstacles => {
                    let mut settings = self.lab.settings().clone();
                    settings.tank_mut(self.panel.edit_side).obstacles = None;
                    self.lab.apply_settings(settings);
                }
                PanelAction::ResetTraining => {
                    self.lab.reset_training();
                    self.learning_abstraction = None;
                }
                PanelAction::StartRace => {
                    let result = self
                        .lab
                        .learning_mut()
                        .ok_or_else(|| "Open the learning lab first.".to_owned())
                        .and_then(|l| l.start_race().map_err(|e| e.to_string()));
                    if let Err(reason) = result {
                        self.notice = Some(Notice {
                            text: format!("No race yet: {reason}."),
                            is_error: false,
                        });
                    }
                }
                PanelAction::SaveControllers => {
                    let message = self.controllers_json().and_then(|json| {
                        save_text_file("shoal-controllers.json", "application/json", &json)
                    });
                    self.notice = Some(Notice {
                        is_error: message.is_err(),
                        text: message.unwrap_or_else(|e| e),
                    });
                }
                PanelAction::LoadControllers => self.open_controllers_file(),
            }
        }
    }

    /// The learned controllers in use, as JSON (`shoal.save_controllers()`).
    pub fn controllers_json(&self) -> Result<String, String> {
        self.lab.runs()[0]
            .learning()
            .ok_or_else(|| LabError::LearningLabOnly("save_controllers").to_string())?
            .save_json()
            .map_err(|e| e.to_string())
    }

    /// Opens a controllers file: the browser's file dialog (the text arrives in a
    /// later frame, see [`Self::apply_loaded_controllers`]); natively
    /// `shoal-controllers.json` in the working folder.
    fn open_controllers_file(&mut self) {
        #[cfg(target_arch = "wasm32")]
        {
            let ctx = self.ctx.clone();
            if let Err(err) = crate::web::pick_text_file(
                ".json,application/json",
                self.pending_load.clone(),
                move || {
                    ctx.request_repaint();
                },
            ) {
                self.notice = Some(Notice {
                    text: format!("The file dialog did not open: {err}"),
                    is_error: true,
                });
            }
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let text = std::fs::read_to_string("shoal-controllers.json")
                .map_err(|err| format!("could not read shoal-controllers.json: {err}"));
            *self.pending_load.borrow_mut() = Some(text);
        }
    }

    /// Uses a controllers file the user picked, or says why it cannot be used.
    fn apply_loaded_controllers(&mut self) {
        let Some(text) = self.pending_load.borrow_mut().take() else {
            return;
        };
        let result = text.and_then(|text| {
            self.lab
                .learning_mut()
                .ok_or_else(|| "open the learning lab first".to_owned())
                .and_then(|l| l.load_json(&text).map_err(|e| e.to_string()))
        });
        self.notice = Some(match result {
            Ok(()) => Notice {
                text: "Controllers loaded: the swimmer now uses them.".to_owned(),
                is_error: false,
            },
            Err(reason) => Notice {
                text: format!("That file cannot be used, nothing was changed: {reason}"),
                is_error: true,
            },
        });
    }

    fn notice_ui(&mut self, ui: &mut egui::Ui) {
        let Some(notice) = self.notice.clone() else {
            return;
        };
        let rect = ui.max_rect();
        egui::Area::new(egui::Id::unique("notice"))
            .fixed_pos(rect.center_top() + egui::vec2(-260.0, 10.0))
            .order(egui::Order::Foreground)
            .show(ui.ctx(), |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    ui.set_max_width(520.0);
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

/// Where the ray meets the floor plane, if it points down at it.
fn floor_point(origin: Vec3, direction: Vec3, floor_y_m: f32) -> Option<Vec3> {
    if direction.y >= -1e-4 {
        return None;
    }
    let t = (floor_y_m - origin.y) / direction.y;
    (t > 0.0).then(|| origin + direction * t)
}

/// The obstacle the ray passes closest to (within its radius plus a little slack).
fn picked_obstacle(obstacles: &[Obstacle], origin: Vec3, direction: Vec3) -> Option<usize> {
    /// Extra reach when picking, metres: thin pillars stay easy to click.
    const SLACK_M: f32 = 0.3;
    obstacles
        .iter()
        .enumerate()
        .filter_map(|(i, obstacle)| {
            // The closest point of the ray to the obstacle's core at the ray's height.
            let mut best = f32::INFINITY;
            let mut along = 0.0;
            for _ in 0..48 {
                let p = origin + direction * along;
                let d = obstacle.signed_distance_m(p);
                best = best.min(d);
                along += d.max(0.05);
                if d < 0.0 || along > 200.0 {
                    break;
                }
            }
            (best < SLACK_M).then_some((i, along))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

/// "Show vision": each fish's links to the nearest neighbours it sees, and the field
/// of view of a few fish as a fan in their swimming plane.
fn draw_vision(
    painter: &egui::Painter,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
) {
    let Some(world) = run.scene().boids() else {
        return;
    };
    let Some(boids) = world.boids() else {
        return;
    };
    let perception = boids.perception;
    let fish = world.fish();
    let drawn = run.drawn_positions_m(alpha);
    let aspect = rect.width() / rect.height().max(1.0);
    let to_screen = |p: Vec3| {
        camera
            .project(p, aspect)
            .map(|uv| rect.min + egui::vec2(uv.x * rect.width(), uv.y * rect.height()))
    };
    let link_stroke = egui::Stroke::new(
        1.0,
        egui::Color32::from_rgba_unmultiplied(255, 255, 160, 90),
    );
    // The neighbours each fish actually heeds this step, as the simulation chose them.
    let mut heeded: Vec<usize> = Vec::new();
    for i in 0..fish.len().min(VISION_OBSERVERS_MAX) {
        world.interaction_neighbours(i, &mut heeded);
        let Some(a) = to_screen(drawn[i]) else {
            continue;
        };
        for &j in heeded.iter().take(VISION_LINKS_PER_FISH) {
            if j < fish.len()
                && let Some(b) = to_screen(drawn[j])
            {
                painter.line_segment([a, b], link_stroke);
            }
        }
    }
    // Fans: the field of view in the plane of the heading and the horizontal side.
    let half = (perception.vision_angle_rad * 0.5).clamp(0.0, std::f32::consts::PI);
    for (i, me) in fish.iter().enumerate().take(VISION_FANS) {
        let centre = drawn[i];
        let forward = me.heading();
        let side = forward.cross(Vec3::Y).normalize_or(Vec3::Z);
        let mut points = Vec::new();
        if let Some(c) = to_screen(centre) {
            points.push(c);
        }
        let segments = 32;
        for k in 0..=segments {
            let angle = -half + 2.0 * half * k as f32 / segments as f32;
            let dir = forward * angle.cos() + side * angle.sin();
            if let Some(p) = to_screen(centre + dir * perception.vision_distance_m) {
                points.push(p);
            }
        }
        if points.len() > 3 {
            painter.add(egui::Shape::line(
                points.clone(),
                egui::Stroke::new(
                    1.5,
                    egui::Color32::from_rgba_unmultiplied(120, 255, 200, 110),
                ),
            ));
            painter.add(egui::Shape::convex_polygon(
                points,
                egui::Color32::from_rgba_unmultiplied(120, 255, 200, 18),
                egui::Stroke::NONE,
            ));
        }
    }
}

/// Saves the CSV: a browser download on the web, a file in the working folder on
/// the desktop. Returns the message for the user.
fn save_text_file(name: &str, mime: &str, text: &str) -> Result<String, String> {
    #[cfg(target_arch = "wasm32")]
    {
        crate::web::download_text(name, mime, text)
            .map(|()| format!("Downloading {name}."))
            .map_err(|err| format!("The download did not start: {err}"))
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = mime;
        std::fs::write(name, text)
            .map(|()| format!("Saved {name} in the folder Shoal was started from."))
            .map_err(|err| format!("Could not save {name}: {err}"))
    }
}

fn save_csv(csv: &str) -> Result<String, String> {
    let name = "shoal-metrics.csv";
    #[cfg(target_arch = "wasm32")]
    {
        crate::web::download_text(name, "text/csv", csv)
            .map(|()| format!("Downloading {name}: open it with a spreadsheet."))
            .map_err(|err| format!("The download did not start: {err}"))
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        std::fs::write(name, csv)
            .map(|()| format!("Saved {name} in the folder Shoal was started from."))
            .map_err(|err| format!("Could not save {name}: {err}"))
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
        self.frames_drawn += 1;

        let status = self.state_report();
        egui::Panel::bottom("status").show(ui, |ui| {
            status_line_ui(ui, &status, self.caps);
        });

        if self.lab.settings().scene == Scene::Boids {
            let labels: Vec<String> = self
                .lab
                .runs()
                .iter()
                .map(|run| {
                    let tank = self.lab.settings().tank(run.side());
                    if self.lab.comparing() {
                        format!("{} ({})", run.side().name(), tank.preset.label())
                    } else {
                        tank.preset.label().to_owned()
                    }
                })
                .collect();
            let runs = self.lab.runs();
            show_bottom_panel(
                ui,
                "metrics",
                METRICS_PANEL_HEIGHT,
                &mut self.widget_rects,
                |ui, height, rects| metrics_panel_ui(ui, runs, &labels, height, rects),
            );
        }

        if self.lab.settings().scene == Scene::Physics {
            // The plots need a selected fish; until then one line says how to get them.
            match self.lab.settings().physics.selected {
                Some(selected) => {
                    let run = &self.lab.runs()[0];
                    show_bottom_panel(
                        ui,
                        "body_plots",
                        BODY_PLOTS_PANEL_HEIGHT,
                        &mut self.widget_rects,
                        |ui, height, rects| body_plots_ui(ui, run, Some(selected), height, rects),
                    );
                }
                None => {
                    // One line of text: the panel takes the line's height, which does not
                    // depend on the panel's.
                    let hint = egui::Panel::bottom("body_plots_hint")
                        .resizable(false)
                        .show(ui, |ui| {
                            let height = ui.available_height();
                            body_plots_ui(
                                ui,
                                &self.lab.runs()[0],
                                None,
                                height,
                                &mut self.widget_rects,
                            );
                        });
                    self.widget_rects
                        .insert("panel_body_plots_hint", hint.response.rect);
                }
            }
        }

        if self.lab.settings().scene == Scene::Learning {
            self.apply_loaded_controllers();
            let stale = self
                .learning_abstraction
                .as_ref()
                .is_none_or(|(at, _)| now_secs - at > 0.5);
            if stale && let Some(l) = self.lab.runs()[0].learning() {
                self.learning_abstraction = Some((now_secs, l.current_abstraction()));
            }
            let run = &self.lab.runs()[0];
            let abstraction = self.learning_abstraction.as_ref().map(|(_, a)| a);
            show_bottom_panel(
                ui,
                "learning_plots",
                crate::ui::learning_panel::LEARNING_PANEL_HEIGHT,
                &mut self.widget_rects,
                |ui, height, rects| {
                    crate::ui::learning_panel::learning_plots_ui(
                        ui,
                        run,
                        abstraction,
                        height,
                        rects,
                    );
                },
            );
        }
        if self.lab.settings().scene == Scene::Reef {
            let selected = self.lab.settings().reef.selected;
            self.refresh_fish_eye(now_secs, selected);
            let fish_eye = self
                .fish_eye
                .as_ref()
                .filter(|f| Some(f.0) == selected)
                .map(|(_, texture, brightness, _)| reef_panel::FishEyeView {
                    texture,
                    mean_brightness: *brightness,
                });
            let run = &self.lab.runs()[0];
            show_bottom_panel(
                ui,
                "reef_inspector",
                reef_panel::reef_inspector_height(selected.is_some()),
                &mut self.widget_rects,
                |ui, height, rects| {
                    reef_panel::reef_inspector_ui(ui, run, selected, fish_eye, height, rects);
                },
            );
        }

        let mut settings = self.lab.settings().clone();
        let mut actions = keyboard_shortcuts(ui, &mut settings);
        // The Minds section shows the demo's own values under the teacher's.
        self.panel.reef_demo_habits.clear();
        if let Some(reef) = self.lab.runs()[0].reef() {
            for kind in crate::sim::reef::mind::FishKind::ALL {
                if let Some(a) = reef.animals().iter().find(|a| a.demo_habits.kind == kind) {
                    self.panel.reef_demo_habits.push(a.demo_habits);
                }
            }
        }
        egui::Panel::left("controls")
            .default_size(270.0)
            .resizable(true)
            .show_collapsible(ui, &mut self.panel_open, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    actions.extend(control_panel_ui(
                        ui,
                        &mut settings,
                        &mut self.panel,
                        &mut self.widget_rects,
                    ));
                });
            });

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
        if &settings != self.lab.settings() {
            self.lab.apply_settings(settings);
        }
        self.apply(actions);
        // A new scene: an untouched camera frames what it shows.
        if self.lab.settings().scene != self.viewed_scene {
            self.viewed_scene = self.lab.settings().scene;
            if self.camera_is_default {
                self.reset_view();
            }
        }

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
