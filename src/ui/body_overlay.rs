//! Drawn over the physics scene's 3D view with egui's painter: the spring–mass
//! skeleton of the physical fish (nodes, springs, muscles coloured by how much they
//! contract), force arrows (the water's push on each node, where the fish wants to
//! go, where it goes, the current), and picking a fish with the mouse.

use eframe::egui;
use glam::Vec3;

use super::WidgetRects;
use super::scene_panel::{ViewContext, ViewInput};
use crate::i18n::ts;
use crate::lab::Run;
use crate::render::OrbitCamera;
use crate::sim::body::NODE_COUNT;
use crate::sim::body::body_layout::{MUSCLES, SPRINGS, SpringKind};
use crate::sim::body::hydrodynamics::add_water_forces;
use crate::sim::body::motor_bridge::{to_body_frame, to_tank_frame};

/// Skeletons drawn at most when no fish is selected. 40, chosen: 3,600 lines stay
/// cheap and readable; with a selection only the selected fish is drawn.
pub const SKELETONS_MAX: usize = 40;

/// Screen distance within which a click picks a fish, points (plus its drawn
/// half-length). 12, chosen: easy to hit with a mouse.
const PICK_SLACK_PT: f32 = 12.0;

/// The same on a touch screen: 22 points, so a fish is at least a 44-point
/// target, the size touch guidelines ask for (a fingertip is about 10 mm).
const TOUCH_PICK_SLACK_PT: f32 = 22.0;

/// The colour of a muscle contracted by `u` in [0, 1]: relaxed pale blue, fully
/// contracted red. (The skeleton also draws a muscle thicker as it pulls,
/// [`muscle_width`], so the contraction does not rest on colour alone.)
pub fn muscle_color(u: f32) -> egui::Color32 {
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let lerp = |a: f32, b: f32| (a + (b - a) * u).round() as u8;
    egui::Color32::from_rgb(lerp(140.0, 255.0), lerp(190.0, 50.0), lerp(255.0, 40.0))
}

/// The width of a muscle contracted by `u` in [0, 1], points: 1.5 relaxed to
/// 5 fully contracted.
pub fn muscle_width(u: f32) -> f32 {
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    1.5 + 3.5 * u
}

struct Projector<'a> {
    camera: &'a OrbitCamera,
    rect: egui::Rect,
    aspect: f32,
}

impl Projector<'_> {
    fn new(camera: &OrbitCamera, rect: egui::Rect) -> Projector<'_> {
        Projector {
            camera,
            rect,
            aspect: rect.width() / rect.height().max(1.0),
        }
    }

    fn point(&self, p: Vec3) -> Option<egui::Pos2> {
        self.camera.project(p, self.aspect).map(|uv| {
            self.rect.min + egui::vec2(uv.x * self.rect.width(), uv.y * self.rect.height())
        })
    }

    fn arrow(&self, painter: &egui::Painter, from: Vec3, to: Vec3, stroke: egui::Stroke) {
        if let (Some(a), Some(b)) = (self.point(from), self.point(to)) {
            painter.arrow(a, b - a, stroke);
        }
    }
}

/// Where an animal whose middle is at `centre` is drawn: its middle on screen
/// and half its length on screen (at least 4 points); `None` behind the camera.
fn screen_disc(project: &Projector, centre: Vec3, body_length_m: f32) -> Option<(egui::Pos2, f32)> {
    let c = project.point(centre)?;
    let half = project
        .point(centre + camera_right(project.camera) * 0.5 * body_length_m)
        .map_or(4.0, |e| c.distance(e).max(4.0));
    Some((c, half))
}

/// Which animals to draw: the selected one, or the first [`SKELETONS_MAX`].
fn shown(run: &Run, selected: Option<u32>) -> Vec<usize> {
    let count = run.scene().physics().map_or(0, |p| p.animals().len());
    match selected {
        Some(i) if (i as usize) < count => vec![i as usize],
        _ => (0..count.min(SKELETONS_MAX)).collect(),
    }
}

/// Nodes and springs; muscles coloured by contraction, thicker.
pub fn draw_skeletons(
    painter: &egui::Painter,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
    selected: Option<u32>,
) {
    let Some(physics) = run.scene().physics() else {
        return;
    };
    let project = Projector::new(camera, rect);
    let spring_stroke = egui::Stroke::new(
        1.0,
        egui::Color32::from_rgba_unmultiplied(230, 230, 230, 110),
    );
    let cross_stroke = egui::Stroke::new(
        0.7,
        egui::Color32::from_rgba_unmultiplied(200, 200, 200, 55),
    );
    let drawn = run.drawn_nodes_all_m(alpha);
    for i in shown(run, selected) {
        let nodes = drawn[i];
        let screen: [Option<egui::Pos2>; NODE_COUNT] = nodes.map(|p| project.point(p));
        let muscles = physics.animals()[i].motor().muscles;
        for spring in SPRINGS.iter() {
            if let (Some(a), Some(b)) = (screen[spring.a], screen[spring.b]) {
                let stroke = if spring.kind == SpringKind::Cross {
                    cross_stroke
                } else {
                    spring_stroke
                };
                painter.line_segment([a, b], stroke);
            }
        }
        for (muscle, u) in MUSCLES.iter().zip(muscles) {
            let spring = &SPRINGS[muscle.spring];
            if let (Some(a), Some(b)) = (screen[spring.a], screen[spring.b]) {
                painter.line_segment([a, b], egui::Stroke::new(muscle_width(u), muscle_color(u)));
            }
        }
        for p in screen.into_iter().flatten() {
            painter.circle_filled(p, 2.5, egui::Color32::WHITE);
        }
    }
}

/// Force arrows: the water's push on each node (yellow, the thrust comes from the
/// tail), the velocity the fish wants (green), its velocity (white) and the
/// current where it is (cyan). With one fish drawn (a selected one) each of the
/// three big arrows is named at its tip, so none is known by its colour alone.
pub fn draw_forces(
    painter: &egui::Painter,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
    selected: Option<u32>,
) {
    let Some(physics) = run.scene().physics() else {
        return;
    };
    let project = Projector::new(camera, rect);
    let drawn = run.drawn_nodes_all_m(alpha);
    let shown = shown(run, selected);
    let named = shown.len() == 1;
    let mut labels = Vec::new();
    for i in shown {
        let animal = &physics.animals()[i];
        let length = animal.body_length_m();
        let nodes = drawn[i];
        let body = animal.body();
        let water = physics.water_at(animal.point.position_m);
        // The paper's water force on the body as it is now (drag coefficient 1:
        // only the directions and relative sizes matter for the picture).
        let mut forces = [Vec3::ZERO; NODE_COUNT];
        add_water_forces(
            body.positions_m(),
            body.velocities_m_per_s(),
            to_body_frame(water),
            1.0,
            &mut forces,
            None,
        );
        let largest = forces.iter().map(|f| f.length()).fold(0.0, f32::max);
        if largest > 0.0 {
            let scale = 0.35 * length / largest;
            let stroke = egui::Stroke::new(1.5, egui::Color32::from_rgb(255, 220, 60));
            for (p, f) in nodes.iter().zip(forces) {
                if f.length() > 0.05 * largest {
                    project.arrow(painter, *p, *p + to_tank_frame(f) * scale, stroke);
                }
            }
        }
        let centre = nodes.iter().sum::<Vec3>() / NODE_COUNT as f32;
        // Velocities as the distance covered in 3 seconds.
        let seconds = 3.0;
        let arrows = [
            (
                physics.desired_m_per_s(i),
                egui::Color32::from_rgb(90, 255, 120),
                ts("overlay-wants-to-go"),
            ),
            (
                animal.point.velocity_m_per_s,
                egui::Color32::WHITE,
                ts("overlay-goes"),
            ),
            (
                water,
                egui::Color32::from_rgb(80, 220, 255),
                ts("overlay-current"),
            ),
        ];
        for (v, color, name) in arrows {
            if v.length() > 1e-3 {
                let tip = centre + v * seconds;
                project.arrow(painter, centre, tip, egui::Stroke::new(2.0, color));
                if named && let (Some(a), Some(b)) = (project.point(centre), project.point(tip)) {
                    let away = (b - a).normalized() * 10.0;
                    tip_label(painter, b + away, name, color, &mut labels);
                }
            }
        }
    }
}

/// `text` centred at `at` in `color` on a dark box, readable over the water;
/// moved down below the labels already `placed` that it would cover (short
/// arrows pointing the same way), and added to them.
fn tip_label(
    painter: &egui::Painter,
    at: egui::Pos2,
    text: &str,
    color: egui::Color32,
    placed: &mut Vec<egui::Rect>,
) {
    let galley = painter.layout_no_wrap(text.to_owned(), egui::FontId::proportional(13.0), color);
    let mut rect = egui::Rect::from_center_size(at, galley.size()).expand(2.0);
    while let Some(below) = placed
        .iter()
        .filter(|p| p.intersects(rect))
        .map(|p| p.bottom())
        .reduce(f32::max)
    {
        rect = rect.translate(egui::vec2(0.0, below + 1.0 - rect.top()));
    }
    placed.push(rect);
    painter.rect_filled(rect, 3.0, egui::Color32::from_black_alpha(160));
    painter.galley(rect.min + egui::vec2(2.0, 2.0), galley, color);
}

/// A ring around the selected fish so it stands out in a school.
pub fn draw_selection(
    painter: &egui::Painter,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
    selected: u32,
) {
    let Some((_, centre, length)) = run
        .selectable_animals(alpha)
        .into_iter()
        .find(|a| a.0 == selected as usize)
    else {
        return;
    };
    let project = Projector::new(camera, rect);
    let Some((c, half)) = screen_disc(&project, centre, 1.2 * length) else {
        return;
    };
    let radius = half.max(10.0);
    painter.circle_stroke(
        c,
        radius,
        egui::Stroke::new(2.0, egui::Color32::from_rgb(255, 230, 90)),
    );
}

fn camera_right(camera: &OrbitCamera) -> Vec3 {
    let forward = (camera.target_m - camera.eye_m()).normalize_or(Vec3::NEG_Z);
    forward.cross(Vec3::Y).normalize_or(Vec3::X)
}

/// The squares on screen of the selectable animals with index below `max`
/// (centred on each one's middle, as wide as its drawn length), by index;
/// `None` when behind the camera or gone.
pub fn animal_screen_rects(
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
    max: usize,
) -> Vec<Option<egui::Rect>> {
    let project = Projector::new(camera, rect);
    let mut rects = Vec::new();
    for (i, centre, length) in run.selectable_animals(alpha) {
        if i >= max {
            break;
        }
        rects.resize(i + 1, None);
        rects[i] = screen_disc(&project, centre, length)
            .map(|(c, half)| egui::Rect::from_center_size(c, egui::vec2(2.0 * half, 2.0 * half)));
    }
    rects
}

/// The animal drawn nearest to `pointer` (within its drawn half-length plus a
/// little slack), the nearest to the camera first when several overlap.
pub fn pick_animal(
    pointer: egui::Pos2,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
    slack_pt: f32,
) -> Option<u32> {
    let project = Projector::new(camera, rect);
    let eye = camera.eye_m();
    run.selectable_animals(alpha)
        .into_iter()
        .filter_map(|(i, centre, length)| {
            let (c, half) = screen_disc(&project, centre, length)?;
            (c.distance(pointer) <= half + slack_pt).then_some((i as u32, centre.distance(eye)))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

/// Physical animals whose screen rectangles `shoal.widgets()` reports (`animal_0`,
/// …), for tests that click a fish. 20: the default tank's ten fish and shark.
const ANIMAL_RECTS_MAX: usize = 20;

/// Records where the first pickable animals are on screen (`animal_0`, …), so
/// browser tests can click one.
pub fn record_animal_rects(view: &ViewContext, rects: &mut WidgetRects) {
    let on_screen = animal_screen_rects(
        view.rect,
        view.camera,
        view.run,
        view.alpha,
        ANIMAL_RECTS_MAX,
    );
    for (i, r) in on_screen.into_iter().enumerate() {
        if let Some(r) = r {
            rects.insert(&format!("animal_{i}"), r);
        }
    }
}

/// A click on a view: `Some(Some(i))` picked animal `i`, `Some(None)` a click on
/// open water, `None` no click.
pub fn clicked_animal(input: &ViewInput) -> Option<Option<u32>> {
    if !input.response.clicked() {
        return None;
    }
    let pointer = input.response.interact_pointer_pos()?;
    let run = input.lab.run(input.side)?;
    let touch = input.response.ctx.input(|i| i.has_touch_screen());
    Some(pick_animal(
        pointer,
        input.rect,
        input.camera,
        run,
        input.lab.draw_alpha(),
        if touch {
            TOUCH_PICK_SLACK_PT
        } else {
            PICK_SLACK_PT
        },
    ))
}
