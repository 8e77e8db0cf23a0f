//! The boid scenes' panels: the aquarium (fish and rocks, one slider) and the
//! schooling lab (compare two tanks, each tank's urges, the rock tools, the
//! metrics plots under the tank, and *Show vision* over it).

use eframe::egui;
use glam::{Vec2, Vec3};

use super::WidgetRects;
use super::body_overlay;
use super::boids_attention::{attention_section_ui, draw_attention, selected_attention};
use super::metrics_panel::{METRICS_PANEL_HEIGHT, metrics_panel_ui, side_color};
use super::scene_panel::{Notice, ScenePanel, ViewContext, ViewInput};
use super::setting_slider::setting_row;
use super::show_bottom_panel;
use super::studio_panel::{control, control_block, is_hidden, is_mystery};
use super::tank_panel::{mode_label, tank_ui};
use crate::i18n::{num, tr, ts};
use crate::lab::Lab;
use crate::render::OrbitCamera;
use crate::settings::tank::TankSettings;
use crate::settings::{Settings, Side};
use crate::sim::Obstacle;
use crate::sim::boids::attention::Attention;
use crate::sim::boids::forces::Perception;
use crate::tr;

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

/// The aquarium: fish wander among the rocks; one slider, how many.
pub struct AquariumPanel;

impl ScenePanel for AquariumPanel {
    fn controls_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings, rects: &mut WidgetRects) {
        egui::Grid::new("aquarium_grid")
            .num_columns(2)
            .spacing([8.0, 6.0])
            .show(ui, |ui| {
                setting_row(
                    ui,
                    rects,
                    &Side::Left.prefix(),
                    &TankSettings::AQUARIUM_FISH_COUNT,
                    &mut settings.left,
                );
            });
    }
}

/// What a click in the schooling lab's tank does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum EditTool {
    /// Clicks and drags turn the camera.
    #[default]
    Look,
    /// A click on the sand puts a rock there.
    AddRock,
    /// Drag a rock to move it.
    MoveRock,
    /// A click on a rock removes it.
    RemoveRock,
}

impl EditTool {
    pub const ALL: [Self; 4] = [Self::Look, Self::AddRock, Self::MoveRock, Self::RemoveRock];

    fn label(self) -> &'static str {
        match self {
            Self::Look => ts("boids-tool-look"),
            Self::AddRock => ts("boids-tool-add-rock"),
            Self::MoveRock => ts("boids-tool-move-rock"),
            Self::RemoveRock => ts("boids-tool-remove"),
        }
    }

    fn name(self) -> &'static str {
        match self {
            Self::Look => "tool_look",
            Self::AddRock => "tool_add_rock",
            Self::MoveRock => "tool_move_rock",
            Self::RemoveRock => "tool_remove_rock",
        }
    }

    fn help(self) -> &'static str {
        match self {
            Self::Look => ts("boids-tool-look.help"),
            Self::AddRock => ts("boids-tool-add-rock.help"),
            Self::MoveRock => ts("boids-tool-move-rock.help"),
            Self::RemoveRock => ts("boids-tool-remove.help"),
        }
    }
}

/// The schooling lab: which tank the controls edit, the rock tool, and the rock
/// being dragged.
#[derive(Clone, Debug, Default)]
pub struct BoidsPanel {
    edit_side: Side,
    /// Are the two tanks drawn one above the other (then named top and bottom)?
    stacked: std::cell::Cell<bool>,
    tool: EditTool,
    /// The obstacle being dragged with the Move tool: tank and index.
    dragging: Option<(Side, usize)>,
    /// What each tank's selected fish paid attention to in the last step.
    attention: [Option<Attention>; 2],
    /// Each tank's obstacles and tank box as the world has them (for the
    /// rock buttons, which work without a mouse).
    obstacles: [Vec<Obstacle>; 2],
    tanks: [Option<crate::sim::Tank>; 2],
    /// The obstacle the rock buttons act on, by index.
    rock: usize,
    /// Why the last rock button changed nothing, shown next frame.
    rock_notice: Option<Notice>,
}

impl ScenePanel for BoidsPanel {
    fn offers_experiment(&self) -> bool {
        true
    }

    fn before_frame(
        &mut self,
        lab: &mut Lab,
        _now_secs: f64,
        _ctx: &egui::Context,
    ) -> Option<Notice> {
        self.attention = [None, None];
        for run in lab.runs() {
            if let Some(world) = run.scene().boids() {
                self.attention[run.side().index()] =
                    selected_attention(world, lab.settings(), run.side());
            }
            let i = run.side().index();
            self.obstacles[i] = run.scene().obstacles().to_vec();
            self.tanks[i] = Some(*run.scene().tank());
        }
        self.rock_notice.take()
    }

    fn controls_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings, rects: &mut WidgetRects) {
        ui.separator();
        ui.horizontal_wrapped(|ui| {
            control(ui, rects, "compare", |ui, rects| {
                let compare = ui
                    .checkbox(&mut settings.compare, ts("boids-compare"))
                    .on_hover_text(ts("boids-compare.help"));
                rects.insert("compare", compare.rect);
            });
            control(ui, rects, "show_vision", |ui, rects| {
                let vision = ui
                    .checkbox(&mut settings.show_vision, ts("boids-show-vision"))
                    .on_hover_text(ts("boids-show-vision.help"));
                rects.insert("show_vision", vision.rect);
            });
        });
        let sides: &[Side] = if settings.compare {
            &Side::BOTH
        } else {
            &[Side::Left]
        };
        for &side in sides {
            let name = settings
                .compare
                .then(|| tank_name(side, self.stacked.get()));
            attention_section_ui(
                ui,
                settings,
                side,
                name,
                self.attention[side.index()].as_ref(),
                rects,
            );
        }
        if !settings.compare {
            self.edit_side = Side::Left;
        } else {
            ui.horizontal(|ui| {
                ui.label(ts("boids-edit"));
                for side in Side::BOTH {
                    let label = tank_name(side, self.stacked.get());
                    let response = ui
                        .selectable_value(&mut self.edit_side, side, label)
                        .on_hover_text(ts("boids-edit.help"));
                    rects.insert(&format!("edit_{}", side.name()), response.rect);
                    if self.edit_side == side {
                        // Which tank the controls change, for the browser tests.
                        rects.insert(&format!("editing_{}", side.name()), response.rect);
                    }
                }
            });
        }
        ui.add_space(4.0);
        tank_ui(ui, settings.tank_mut(self.edit_side), self.edit_side, rects);

        ui.add_space(4.0);
        let rocks = format!("{}.obstacles", self.edit_side.name());
        if !is_hidden(ui, &rocks) {
            ui.label(egui::RichText::new(ts("boids-rocks")).strong())
                .on_hover_text(ts("boids-rocks.help"));
        }
        let edit_side = self.edit_side;
        let tool = &mut self.tool;
        let drawn = control_block(ui, rects, &rocks, ts("boids-rock-tools"), |ui, rects| {
            ui.horizontal_wrapped(|ui| {
                for t in EditTool::ALL {
                    let response = ui
                        .selectable_value(tool, t, t.label())
                        .on_hover_text(t.help());
                    rects.insert(t.name(), response.rect);
                }
            });
            ui.label(egui::RichText::new(tool.help()).small().weak());
            let keyboard = RockKeys {
                tool: *tool,
                side: edit_side,
                obstacles: &self.obstacles[edit_side.index()],
                tank: self.tanks[edit_side.index()],
                rock: &mut self.rock,
            };
            if let Some(notice) = keyboard.ui(ui, settings, rects) {
                self.rock_notice = Some(notice);
            }
            let restore = ui
                .add_enabled(
                    settings.tank(edit_side).obstacles.is_some(),
                    egui::Button::new(ts("boids-restore-rocks")),
                )
                .on_hover_text(ts("boids-restore-rocks.help"));
            rects.insert("restore_rocks", restore.rect);
            if restore.clicked() {
                settings.tank_mut(edit_side).obstacles = None;
            }
        });
        if drawn.is_none() {
            // Locked or hidden rocks: the mouse only looks.
            self.tool = EditTool::Look;
        }
        ui.add_space(4.0);
        super::predation_panel::predation_ui(ui, &mut settings.predation, rects);
    }

    fn bottom_ui(
        &mut self,
        ui: &mut egui::Ui,
        lab: &Lab,
        _settings: &mut Settings,
        rects: &mut WidgetRects,
    ) {
        let labels: Vec<String> = lab
            .runs()
            .iter()
            .map(|run| {
                let tank = lab.settings().tank(run.side());
                // A mystery mix keeps its preset's name to itself.
                let preset = if is_mystery(ui, &format!("{}.preset", run.side().name())) {
                    ts("boids-preset-mystery")
                } else {
                    tank.preset.label()
                };
                if lab.comparing() {
                    format!("{} ({preset})", tank_name(run.side(), self.stacked.get()),)
                } else {
                    preset.to_owned()
                }
            })
            .collect();
        show_bottom_panel(
            ui,
            "metrics",
            METRICS_PANEL_HEIGHT,
            rects,
            |ui, height, rects| metrics_panel_ui(ui, lab.runs(), &labels, height, rects),
        );
    }

    fn draw_overlays(&self, view: &ViewContext, settings: &Settings, rects: &mut WidgetRects) {
        self.stacked.set(view.stacked);
        if settings.show_vision {
            draw_vision(view);
        }
        if let (Some(selected), Some(attention), Some(world)) = (
            settings.selected_in(view.side),
            self.attention[view.side.index()].as_ref(),
            view.run.scene().boids(),
        ) {
            draw_attention(view, world, selected, attention);
        } else if let Some(selected) = settings.selected_in(view.side) {
            body_overlay::draw_selection(
                view.painter,
                view.rect,
                view.camera,
                view.run,
                view.alpha,
                selected,
            );
        }
        body_overlay::record_animal_rects(view, rects);
        if view.comparing {
            draw_tank_label(view, settings);
        }
    }

    fn view_input(&mut self, input: &ViewInput, settings: &mut Settings) -> Option<Notice> {
        if self.tool == EditTool::Look {
            // A click on a fish selects it; on open water, lets it go.
            if let Some(picked) = body_overlay::clicked_animal(input) {
                settings.tank_mut(input.side).selected = picked;
            }
            return None;
        }
        self.rock_tool_input(input, settings)
    }

    fn holds_drag(&self) -> bool {
        self.dragging.is_some()
    }
}

impl BoidsPanel {
    /// Adds, moves or removes obstacles with the mouse (the panel's rock tools).
    fn rock_tool_input(&mut self, input: &ViewInput, settings: &mut Settings) -> Option<Notice> {
        let (response, rect, side) = (input.response, input.rect, input.side);
        if self.tool == EditTool::Look {
            return None;
        }
        let pointer = response.interact_pointer_pos().or(response.hover_pos())?;
        let uv = Vec2::new(
            (pointer.x - rect.min.x) / rect.width().max(1.0),
            (pointer.y - rect.min.y) / rect.height().max(1.0),
        );
        let (origin, direction) = input.camera.ray(uv, input.aspect());
        let world = input.lab.run(side)?.scene();
        let tank = *world.tank();
        let current: Vec<Obstacle> = settings
            .tank(side)
            .obstacles
            .clone()
            .unwrap_or_else(|| world.obstacles().to_vec());
        let floor_hit = floor_point(origin, direction, tank.min_m.y);
        match self.tool {
            EditTool::Look => None,
            EditTool::AddRock => {
                let p = floor_hit.filter(|_| response.clicked())?;
                let rock = Obstacle::Rock {
                    center_m: Vec3::new(p.x, tank.min_m.y - 0.2 * NEW_ROCK_RADIUS_M, p.z),
                    radius_m: NEW_ROCK_RADIUS_M,
                };
                let mut next = current;
                next.push(rock);
                propose_obstacles(settings, side, next, &tank)
            }
            EditTool::RemoveRock => {
                if !response.clicked() {
                    return None;
                }
                let i = picked_obstacle(&current, origin, direction)?;
                let mut next = current;
                next.remove(i);
                propose_obstacles(settings, side, next, &tank)
            }
            EditTool::MoveRock => {
                if response.drag_started_by(egui::PointerButton::Primary) {
                    self.dragging = picked_obstacle(&current, origin, direction).map(|i| (side, i));
                }
                let mut notice = None;
                if let (Some((drag_side, i)), Some(p)) = (self.dragging, floor_hit)
                    && drag_side == side
                    && response.dragged_by(egui::PointerButton::Primary)
                    && i < current.len()
                {
                    let mut next = current;
                    next[i] = next[i].moved_to(Vec2::new(p.x, p.z));
                    notice = propose_obstacles(settings, side, next, &tank);
                }
                if response.drag_stopped() {
                    self.dragging = None;
                }
                notice
            }
        }
    }
}

/// How far one press of a rock's arrow button moves it, metres (0.5: a
/// rock's radius or so, a few presses cross a gap between rocks).
const ROCK_STEP_M: f32 = 0.5;

/// The rock tools without a mouse: buttons that pick a rock and move or
/// remove it, or add one in the middle of the floor (WCAG 2.1.1: every drag
/// has a key or button alternative).
struct RockKeys<'a> {
    tool: EditTool,
    side: Side,
    obstacles: &'a [Obstacle],
    tank: Option<crate::sim::Tank>,
    rock: &'a mut usize,
}

impl RockKeys<'_> {
    fn ui(
        self,
        ui: &mut egui::Ui,
        settings: &mut Settings,
        rects: &mut WidgetRects,
    ) -> Option<Notice> {
        let tank = self.tank?;
        let current: Vec<Obstacle> = settings
            .tank(self.side)
            .obstacles
            .clone()
            .unwrap_or_else(|| self.obstacles.to_vec());
        let mut proposal = None;
        match self.tool {
            EditTool::Look => return None,
            EditTool::AddRock => {
                let add = ui
                    .button(ts("boids-rock-add-middle"))
                    .on_hover_text(ts("boids-rock-add-middle.help"));
                rects.insert("rock_add_middle", add.rect);
                if add.clicked() {
                    // The free spot nearest the middle of the floor.
                    let centre = 0.5 * (tank.min_m + tank.max_m);
                    let spots = (0..12).flat_map(|ring| {
                        let count = if ring == 0 { 1 } else { 8 * ring };
                        (0..count).map(move |k| {
                            let angle = std::f32::consts::TAU * k as f32 / count as f32;
                            let r = ring as f32 * ROCK_STEP_M;
                            Vec2::new(centre.x + r * angle.cos(), centre.z + r * angle.sin())
                        })
                    });
                    let free = spots
                        .map(|p| {
                            let mut next = current.clone();
                            next.push(Obstacle::Rock {
                                center_m: Vec3::new(
                                    p.x,
                                    tank.min_m.y - 0.2 * NEW_ROCK_RADIUS_M,
                                    p.y,
                                ),
                                radius_m: NEW_ROCK_RADIUS_M,
                            });
                            next
                        })
                        .find(|next| {
                            crate::sim::boids::placement::check_obstacles(next, &tank).is_ok()
                        });
                    match free {
                        Some(next) => {
                            *self.rock = next.len() - 1;
                            proposal = Some(next);
                        }
                        None => {
                            return Some(Notice::info(ts("boids-rock-no-room")));
                        }
                    }
                }
            }
            EditTool::MoveRock | EditTool::RemoveRock => {
                if current.is_empty() {
                    ui.label(ts("boids-no-rocks"));
                    return None;
                }
                let n = current.len();
                *self.rock = (*self.rock).min(n - 1);
                let at = current[*self.rock].footprint_center_m();
                ui.horizontal_wrapped(|ui| {
                    let previous = ui.button("◀").accessible_name(ts("boids-rock-previous"));
                    rects.insert("rock_previous", previous.rect);
                    if previous.clicked() {
                        *self.rock = (*self.rock + n - 1) % n;
                    }
                    // Where it is, in words a screen reader reads.
                    ui.label(tr!(
                        "boids-rock-where",
                        number = *self.rock + 1,
                        count = n,
                        left = num(f64::from(at.x - tank.min_m.x), 1),
                        front = num(f64::from(tank.max_m.z - at.y), 1),
                    ));
                    let next = ui.button("▶").accessible_name(ts("boids-rock-next"));
                    rects.insert("rock_next", next.rect);
                    if next.clicked() {
                        *self.rock = (*self.rock + 1) % n;
                    }
                });
                if self.tool == EditTool::MoveRock {
                    ui.horizontal_wrapped(|ui| {
                        for (label, name, dx, dz) in [
                            ("boids-rock-left", "rock_left", -ROCK_STEP_M, 0.0),
                            ("boids-rock-right", "rock_right", ROCK_STEP_M, 0.0),
                            ("boids-rock-back", "rock_back", 0.0, -ROCK_STEP_M),
                            ("boids-rock-front", "rock_front", 0.0, ROCK_STEP_M),
                        ] {
                            let r = ui
                                .button(tr(label))
                                .on_hover_text(tr!(
                                    "boids-rock-move-help",
                                    step = num(f64::from(ROCK_STEP_M), 1)
                                ))
                                .accessible_name(tr(&format!("{label}.name")));
                            rects.insert(name, r.rect);
                            if r.clicked() {
                                let mut next = current.clone();
                                next[*self.rock] =
                                    next[*self.rock].moved_to(at + Vec2::new(dx, dz));
                                proposal = Some(next);
                            }
                        }
                    });
                } else {
                    let remove = ui.button(ts("boids-rock-remove-this"));
                    rects.insert("rock_remove_this", remove.rect);
                    if remove.clicked() {
                        let mut next = current;
                        next.remove(*self.rock);
                        proposal = Some(next);
                    }
                }
            }
        }
        proposal.and_then(|next| propose_obstacles(settings, self.side, next, &tank))
    }
}

/// Uses `obstacles` for the tank of `side` if the world would keep every
/// one (each valid, none too close to another); otherwise explains why not and
/// changes nothing.
fn propose_obstacles(
    settings: &mut Settings,
    side: Side,
    obstacles: Vec<Obstacle>,
    tank: &crate::sim::Tank,
) -> Option<Notice> {
    if let Err((_, reason)) = crate::sim::boids::placement::check_obstacles(&obstacles, tank) {
        return Some(Notice::info(tr!(
            "boids-rock-cannot-go",
            reason = reason.to_string()
        )));
    }
    let mut candidate = settings.clone();
    candidate.tank_mut(side).obstacles = Some(obstacles);
    match candidate.validate() {
        Ok(()) => {
            *settings = candidate;
            None
        }
        Err(err) => Some(Notice::info(tr!(
            "boids-rock-cannot-go",
            reason = err.to_string()
        ))),
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

/// What a tank is called on screen: left and right side by side, top and bottom
/// when a tall window stacks them (the settings keep `left` and `right`).
fn tank_name(side: Side, stacked: bool) -> &'static str {
    match (side, stacked) {
        (Side::Left, false) => ts("boids-tank-left"),
        (Side::Right, false) => ts("boids-tank-right"),
        (Side::Left, true) => ts("boids-tank-top"),
        (Side::Right, true) => ts("boids-tank-bottom"),
    }
}

/// In compare mode, each tank's name, preset and control mode at its top left.
fn draw_tank_label(view: &ViewContext, settings: &Settings) {
    let tank = settings.tank(view.side);
    // The studio's mystery values stay a mystery over the tank too.
    let hidden = |name: &str| {
        let rule = settings
            .studio
            .for_student(&format!("{}.{name}", view.side.name()));
        rule.mystery || rule.hidden
    };
    // The tank's line in the plots, so the name matches its line without colour.
    let label = format!(
        "{} {} · {} · {}",
        super::palette::line_glyph(super::palette::side_series(view.side).line),
        tank_name(view.side, view.stacked),
        if hidden("preset") {
            "?"
        } else {
            tank.preset.label()
        },
        if hidden("mode") {
            "?"
        } else {
            mode_label(tank.mode)
        }
    );
    // Below the *Controls* button when the panel is hidden.
    let top = if view.side == Side::Left && view.panel_hidden {
        44.0
    } else {
        8.0
    };
    let at = view.rect.left_top() + egui::vec2(10.0, top);
    let color = side_color(view.side);
    // Within the view, and clear of *Reset view* at the top right of the
    // right (or bottom) tank: a narrow view (a phone) wraps the label.
    let reserved = if view.side == Side::Right { 136.0 } else { 0.0 };
    let wrap_width = (view.rect.width() - 20.0 - reserved).max(80.0);
    let galley = view
        .painter
        .layout(label, egui::FontId::proportional(15.0), color, wrap_width);
    view.painter.rect_filled(
        egui::Rect::from_min_size(at, galley.size()).expand(4.0),
        4.0,
        egui::Color32::from_black_alpha(150),
    );
    view.painter.galley(at, galley, color);
}

/// "Show vision": each fish's links to the nearest neighbours it sees, and the field
/// of view of a few fish as a fan in their swimming plane.
fn draw_vision(view: &ViewContext) {
    let (painter, rect, camera, run) = (view.painter, view.rect, view.camera, view.run);
    let Some(world) = run.scene().boids() else {
        return;
    };
    let Some(boids) = world.boids() else {
        return;
    };
    let perception = boids.perception;
    let tank = *world.tank();
    let fish = world.fish();
    let drawn = run.drawn_positions_m(view.alpha);
    let to_screen = |p: Vec3| screen_point(camera, rect, p);
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
    for (i, me) in fish.iter().enumerate().take(VISION_FANS) {
        draw_view_fan(view, tank, &perception, drawn[i], me.heading(), 110);
    }
}

/// The field of view of a fish at `centre` heading along `forward`, drawn as a
/// fan in the plane of its heading and its horizontal side, out to its vision
/// distance or the glass; `alpha` is the outline's opacity (0–255).
pub(super) fn draw_view_fan(
    view: &ViewContext,
    tank: crate::sim::Tank,
    perception: &Perception,
    centre: Vec3,
    forward: Vec3,
    alpha: u8,
) {
    let to_screen = |p: Vec3| screen_point(view.camera, view.rect, p);
    let half = (perception.vision_angle_rad * 0.5).clamp(0.0, std::f32::consts::PI);
    let side = forward.cross(Vec3::Y).normalize_or(Vec3::Z);
    let mut points = Vec::new();
    if let Some(c) = to_screen(centre) {
        points.push(c);
    }
    let segments = 32;
    for k in 0..=segments {
        let angle = -half + 2.0 * half * k as f32 / segments as f32;
        let dir = forward * angle.cos() + side * angle.sin();
        let reach = perception
            .vision_distance_m
            .min(tank.distance_to_glass(centre, dir));
        if let Some(p) = to_screen(centre + dir * reach) {
            points.push(p);
        }
    }
    if points.len() > 3 {
        view.painter.add(egui::Shape::line(
            points.clone(),
            egui::Stroke::new(
                1.5,
                egui::Color32::from_rgba_unmultiplied(120, 255, 200, alpha),
            ),
        ));
        view.painter.add(egui::Shape::convex_polygon(
            points,
            egui::Color32::from_rgba_unmultiplied(120, 255, 200, alpha / 6),
            egui::Stroke::NONE,
        ));
    }
}

/// Where `p` is drawn in `rect`, if in front of the camera.
pub(super) fn screen_point(camera: &OrbitCamera, rect: egui::Rect, p: Vec3) -> Option<egui::Pos2> {
    let aspect = rect.width() / rect.height().max(1.0);
    camera
        .project(p, aspect)
        .map(|uv| rect.min + egui::vec2(uv.x * rect.width(), uv.y * rect.height()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stacked_tanks_are_named_top_and_bottom() {
        assert_eq!(tank_name(Side::Right, true), "Bottom tank");
    }

    #[test]
    fn the_schooling_lab_speaks_spanish_with_decimal_commas() {
        use crate::i18n::{Lang, with_lang};
        with_lang(Lang::Es, || {
            assert_eq!(tank_name(Side::Left, false), "Tanque izquierdo");
            assert_eq!(EditTool::AddRock.label(), "Poner roca");
            let rock = tr!(
                "boids-rock-where",
                number = 2,
                count = 5,
                left = num(1.5, 1),
                front = num(12.34, 1)
            );
            assert_eq!(
                rock,
                "Roca 2 de 5: a 1,5 m de la izquierda, a 12,3 m del frente"
            );
            assert_eq!(super::super::bottom_panel::axis_number(0.5, 0.25), "0,50");
            assert_eq!(tr!("status-time", seconds = num(3.34, 1)), "t = 3,3 s");
            assert_eq!(
                tr!("boids-heeds", count = 1, fish = "7"),
                "Se fija en 1 vecino (con anillo): el pez 7."
            );
            let err = crate::ui::FileError::Write {
                name: "a.csv".to_owned(),
                reason: "x".to_owned(),
            };
            assert_eq!(err.to_string(), "No se pudo guardar a.csv: x");
        });
        // English again afterwards, as the tests that read English expect.
        assert_eq!(tank_name(Side::Left, false), "Left tank");
        assert_eq!(EditTool::AddRock.label(), "Add rock");
    }
}
