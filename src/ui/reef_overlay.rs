//! Drawn over the reef's 3D view with egui's painter: the selected fish's view
//! volume (300° out to the water's visibility, the blind cone behind) and a line to
//! what its mind is focused on; each female's choice of partner; name tags; and
//! the light or temperature of the water as coloured dots.

use eframe::egui;
use glam::Vec3;

use super::reef_panel::{intention_color, intention_word};
use crate::i18n::ts;
use crate::lab::Run;
use crate::render::OrbitCamera;
use crate::settings::reef::ReefOverlay;
use crate::sim::reef::mind::{Intention, Sex, Target};
use crate::sim::reef::perception::FIELD_OF_VIEW_RAD;

fn project(camera: &OrbitCamera, rect: egui::Rect, p: Vec3) -> Option<egui::Pos2> {
    let aspect = rect.width() / rect.height().max(1.0);
    camera
        .project(p, aspect)
        .map(|uv| rect.min + egui::vec2(uv.x * rect.width(), uv.y * rect.height()))
}

/// The selected fish's field of view (a horizontal fan of 300° out to the
/// visibility, the 60° blind sector left open) and its focus line.
pub fn draw_vision(
    painter: &egui::Painter,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
    selected: u32,
) {
    let Some(reef) = run.scene().reef() else {
        return;
    };
    let Some(a) = reef.animals().get(selected as usize).filter(|a| a.alive) else {
        return;
    };
    let Some((_, centre, _)) = run
        .selectable_animals(alpha)
        .into_iter()
        .find(|s| s.0 == selected as usize)
    else {
        return;
    };
    let heading = a.body.heading();
    let eye = centre + heading * 0.5 * a.body.body_length_m();
    let visibility = reef.config().visibility_m;
    let tank = *reef.tank();
    // As far as the water is clear, and no farther than the glass.
    let reach = |direction: Vec3| visibility.min(tank.distance_to_glass(eye, direction));
    let flat = (heading * Vec3::new(1.0, 0.0, 1.0)).normalize_or(Vec3::X);
    let yaw = flat.z.atan2(flat.x);
    let half = 0.5 * FIELD_OF_VIEW_RAD;
    let fan = egui::Color32::from_rgba_unmultiplied(255, 255, 200, 70);
    // The rim of the field of view, and spokes every 30°.
    let steps = 60;
    let rim: Vec<egui::Pos2> = (0..=steps)
        .filter_map(|k| {
            let angle = yaw - half + FIELD_OF_VIEW_RAD * k as f32 / steps as f32;
            let direction = Vec3::new(angle.cos(), 0.0, angle.sin());
            project(camera, rect, eye + direction * reach(direction))
        })
        .collect();
    painter.add(egui::Shape::line(rim, egui::Stroke::new(1.5, fan)));
    if let Some(e) = project(camera, rect, eye) {
        for k in 0..=10 {
            let angle = yaw - half + FIELD_OF_VIEW_RAD * k as f32 / 10.0;
            let direction = Vec3::new(angle.cos(), 0.0, angle.sin());
            if let Some(p) = project(camera, rect, eye + direction * reach(direction)) {
                let edge = k == 0 || k == 10;
                let stroke = egui::Stroke::new(
                    if edge { 1.5 } else { 0.7 },
                    if edge {
                        egui::Color32::from_rgba_unmultiplied(255, 120, 120, 140)
                    } else {
                        fan
                    },
                );
                painter.line_segment([e, p], stroke);
            }
        }
        // The focus line.
        let focus = a.focus;
        let target_m = match focus.target {
            Some(Target::Animal(j)) => run
                .selectable_animals(alpha)
                .into_iter()
                .find(|s| s.0 == j as usize)
                .map(|s| s.1),
            Some(Target::Food(id)) => reef
                .food()
                .iter()
                .find(|f| f.id == id)
                .map(|f| f.position_m),
            Some(Target::Obstacle(k)) => reef
                .obstacles()
                .get(k as usize)
                .map(|o| o.core_point_m(eye)),
            Some(Target::Glass) => Some(reef.tank().clamp_inside(eye + heading * 2.0, 0.0)),
            None => None,
        };
        if let Some(t) = target_m.and_then(|t| project(camera, rect, t)) {
            let color = intention_color(focus.intention);
            painter.line_segment([e, t], egui::Stroke::new(2.5, color));
            painter.circle_stroke(t, 7.0, egui::Stroke::new(2.0, color));
            painter.text(
                t + egui::vec2(9.0, -9.0),
                egui::Align2::LEFT_BOTTOM,
                intention_word(focus.intention),
                egui::FontId::proportional(14.0),
                color,
            );
        }
    }
}

/// Dots through the water coloured by brightness (dark blue → pale yellow) or
/// temperature (blue → red), and bigger where the water is brighter or
/// warmer, so the size tells what the colour tells.
pub fn draw_water(
    painter: &egui::Painter,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    overlay: ReefOverlay,
) {
    let Some(reef) = run.scene().reef() else {
        return;
    };
    if overlay == ReefOverlay::None {
        return;
    }
    let env = reef.environment();
    let tank = reef.tank();
    let size = tank.size_m();
    let (nx, ny, nz) = (13, 6, 9);
    for ix in 0..nx {
        for iy in 0..ny {
            for iz in 0..nz {
                let t = Vec3::new(
                    (ix as f32 + 0.5) / nx as f32,
                    (iy as f32 + 0.5) / ny as f32,
                    (iz as f32 + 0.5) / nz as f32,
                );
                let p = tank.min_m + t * size;
                let Some(s) = project(camera, rect, p) else {
                    continue;
                };
                let (value, color) = match overlay {
                    ReefOverlay::Light => {
                        let b = env.brightness_at(p);
                        let lerp = |a: f32, c: f32| (a + (c - a) * b).round() as u8;
                        let color = egui::Color32::from_rgba_unmultiplied(
                            lerp(20.0, 255.0),
                            lerp(30.0, 245.0),
                            lerp(90.0, 170.0),
                            170,
                        );
                        (b, color)
                    }
                    ReefOverlay::Temperature => {
                        let w = env.temperature_01_at(p);
                        let lerp = |a: f32, c: f32| (a + (c - a) * w).round() as u8;
                        let color = egui::Color32::from_rgba_unmultiplied(
                            lerp(40.0, 255.0),
                            lerp(110.0, 80.0),
                            lerp(255.0, 40.0),
                            170,
                        );
                        (w, color)
                    }
                    ReefOverlay::None => continue,
                };
                painter.circle_filled(s, water_dot_radius(value), color);
            }
        }
    }
}

/// The radius of a water dot whose brightness or warmth is `value` in
/// [0, 1], points: 2.5 to 6.
pub fn water_dot_radius(value: f32) -> f32 {
    let v = if value.is_finite() {
        value.clamp(0.0, 1.0)
    } else {
        0.0
    };
    2.5 + 3.5 * v
}

/// Name tags drawn at most (60, chosen: a school's worth; more would hide the
/// fish).
const NAME_TAGS_MAX: usize = 60;

/// Each living animal's name ("shark 10", "fish 5") just above it, as the event
/// log and the inspector name it.
pub fn draw_name_tags(
    painter: &egui::Painter,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
) {
    let Some(reef) = run.scene().reef() else {
        return;
    };
    let drawn = run.drawn_positions_m(alpha);
    let aspect = rect.width() / rect.height().max(1.0);
    for (i, a) in reef.living().take(NAME_TAGS_MAX) {
        let Some(p) = drawn.get(i) else {
            continue;
        };
        let above = *p + Vec3::Y * (0.4 * a.body.body_length_m() + 0.1);
        let Some(uv) = camera.project(above, aspect) else {
            continue;
        };
        let at = rect.min + egui::vec2(uv.x * rect.width(), uv.y * rect.height());
        if !rect.contains(at) {
            continue;
        }
        let galley = painter.layout_no_wrap(
            a.name(i),
            egui::FontId::proportional(12.0),
            egui::Color32::WHITE,
        );
        let tag = egui::Rect::from_center_size(at, galley.size()).expand(2.0);
        painter.rect_filled(tag, 3.0, egui::Color32::from_black_alpha(140));
        painter.galley(tag.min + egui::vec2(2.0, 2.0), galley, egui::Color32::WHITE);
    }
}

/// Each female's choice of partner: a dashed line from her to the male she
/// wants (her intention *mate*), labelled "her choice" at his end, so the
/// *Courtship* demo shows whom she prefers, not only who follows whom. Not
/// for `except` (the selected fish whose focus line already shows it).
pub fn draw_choices(
    painter: &egui::Painter,
    rect: egui::Rect,
    camera: &OrbitCamera,
    run: &Run,
    alpha: f32,
    except: Option<u32>,
) {
    let Some(reef) = run.scene().reef() else {
        return;
    };
    let drawn = run.drawn_positions_m(alpha);
    let color = intention_color(Intention::Mate);
    for (i, a) in reef.living().filter(|(i, _)| Some(*i as u32) != except) {
        let (Sex::Female, Intention::Mate, Some(Target::Animal(m))) =
            (a.habits.sex, a.focus.intention, a.focus.target)
        else {
            continue;
        };
        let ends = drawn.get(i).zip(drawn.get(m as usize));
        let Some((she, he)) =
            ends.and_then(|(f, m)| project(camera, rect, *f).zip(project(camera, rect, *m)))
        else {
            continue;
        };
        painter.add(egui::Shape::dashed_line(
            &[she, he],
            egui::Stroke::new(2.0, color),
            8.0,
            5.0,
        ));
        painter.circle_stroke(he, 9.0, egui::Stroke::new(2.0, color));
        painter.text(
            he + egui::vec2(0.0, -14.0),
            egui::Align2::CENTER_BOTTOM,
            ts("reef-her-choice"),
            egui::FontId::proportional(13.0),
            color,
        );
    }
}
