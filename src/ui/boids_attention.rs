//! "What a fish pays attention to" (issue 15, item 2): the schooling lab's
//! selected fish drawn over its tank (its field of view, rings round the
//! neighbours it heeds, its five urges as arrows and the result) and its section
//! of the side panel (the urges' strengths, which the control mode applied and
//! why, its neighbours, and the answer to "is there a leader?").
//!
//! Everything shown comes from [`World::attention`]: the step's own numbers,
//! not a second recipe.

use eframe::egui;
use glam::Vec3;

use super::WidgetRects;
use super::boids_panel::{draw_view_fan, screen_point};
use super::metrics_panel::{URGE_COLORS, urge_name};
use super::scene_panel::ViewContext;
use crate::i18n::{fmt, ts};
use crate::settings::{Settings, Side};
use crate::sim::World;
use crate::sim::boids::attention::Attention;
use crate::sim::boids::control_mode::ControlMode;
use crate::tr;

/// Shortest urge arrow on screen, points. 22, chosen: a weak urge still shows
/// its direction clear of the fish's ring (13 points).
const MIN_ARROW_PT: f32 = 22.0;

/// How much longer an urge at the full maximum force is than the shortest
/// arrow, points. 200, chosen: avoidance at full force crosses a good part of
/// the view, and the arrows grow with the square root of the strength, so an
/// urge a twentieth as strong (a school's alignment) is still about 70 points.
const ARROW_RANGE_PT: f32 = 200.0;

/// The urges' names in sentences and the table (message ids), in
/// `Force::ALL` order.
const URGE_WORDS: [&str; 5] = [
    "boids-urge-containment.help",
    "boids-urge-alignment.help",
    "boids-urge-cohesion.help",
    "boids-urge-separation.help",
    "boids-urge-avoidance.help",
];

/// Short names for the table (message ids).
const URGE_SHORT: [&str; 5] = [
    "boids-urge-containment",
    "boids-urge-alignment",
    "boids-urge-cohesion",
    "boids-urge-separation",
    "boids-urge-avoidance",
];

/// Each urge's weight's setting name (`left.cohesion`), for the studio's
/// mystery values.
const URGE_KEYS: [&str; 5] = [
    "containment",
    "alignment",
    "cohesion",
    "separation",
    "avoidance",
];

/// The attention of the selected fish of `side`'s tank, if one is selected
/// and the last step can be replayed.
pub fn selected_attention(world: &World, settings: &Settings, side: Side) -> Option<Attention> {
    world.attention(settings.selected_in(side)? as usize)
}

/// The length of an urge arrow on screen, points, for `strength` out of
/// `max_force` (m/s²).
fn arrow_length_pt(strength: f32, max_force: f32) -> f32 {
    let share = if max_force > 0.0 && strength.is_finite() {
        (strength / max_force).clamp(0.0, 1.0)
    } else {
        0.0
    };
    MIN_ARROW_PT + ARROW_RANGE_PT * share.sqrt()
}

/// Draws the selected fish's attention over its tank: field of view, rings
/// round the heeded neighbours, the five urges (applied solid, the others
/// faint and dashed, each coloured as in the table), the result (white) and a
/// yellow ring round the fish.
pub fn draw_attention(view: &ViewContext, world: &World, selected: u32, attention: &Attention) {
    let Some(boids) = world.boids() else {
        return;
    };
    let i = selected as usize;
    let drawn = view.run.drawn_positions_m(view.alpha);
    let Some(&centre) = drawn.get(i) else {
        return;
    };
    let painter = view.painter;
    let to_screen = |p: Vec3| screen_point(view.camera, view.rect, p);
    let Some(c) = to_screen(centre) else {
        return;
    };
    let heading = world.fish()[i].heading();
    draw_view_fan(view, *world.tank(), &boids.perception, centre, heading, 150);
    // The heeded neighbours: a line and a ring each.
    let ring = egui::Stroke::new(2.0, egui::Color32::WHITE);
    let link = egui::Stroke::new(
        1.0,
        egui::Color32::from_rgba_unmultiplied(255, 255, 255, 120),
    );
    for &j in &attention.neighbours {
        if let Some(p) = drawn.get(j).and_then(|&p| to_screen(p)) {
            painter.line_segment([c, p], link);
            painter.circle_stroke(p, 9.0, ring);
        }
    }
    // The selected fish.
    painter.circle_stroke(
        c,
        13.0,
        egui::Stroke::new(2.5, egui::Color32::from_rgb(255, 230, 90)),
    );
    let max_force = boids.perception.max_force_m_per_s2;
    // Screen direction of a vector in the tank from the fish.
    let screen_dir = |v: Vec3| -> Option<egui::Vec2> {
        let tip = to_screen(centre + v.normalize_or_zero() * 0.5)?;
        let d = tip - c;
        (d.length() > 0.5).then(|| d.normalized())
    };
    let font = egui::FontId::proportional(13.0);
    for (k, &v) in attention.urges_m_per_s2.iter().enumerate() {
        let strength = v.length();
        if strength <= 0.0 {
            continue;
        }
        let Some(dir) = screen_dir(v) else {
            continue;
        };
        let tip = c + dir * arrow_length_pt(strength, max_force);
        let color = URGE_COLORS[k];
        if attention.applied[k] {
            painter.arrow(c, tip - c, egui::Stroke::new(3.0, color));
        } else {
            let faint = color.gamma_multiply(0.55);
            painter.extend(egui::Shape::dashed_line(
                &[c, tip],
                egui::Stroke::new(2.0, faint),
                6.0,
                4.0,
            ));
        }
        label(painter, tip + dir * 10.0, urge_name(k), font.clone(), color);
    }
    let result = attention.steering_m_per_s2;
    if let Some(dir) = screen_dir(result) {
        let tip = c + dir * arrow_length_pt(result.length(), max_force);
        painter.arrow(c, tip - c, egui::Stroke::new(3.5, egui::Color32::WHITE));
        label(
            painter,
            tip + dir * 12.0,
            ts("boids-result-arrow"),
            egui::FontId::proportional(13.0),
            egui::Color32::WHITE,
        );
    }
}

/// `text` centred at `at` on a dark box, readable over water and fish.
fn label(
    painter: &egui::Painter,
    at: egui::Pos2,
    text: &str,
    font: egui::FontId,
    color: egui::Color32,
) {
    let galley = painter.layout_no_wrap(text.to_owned(), font, color);
    let rect = egui::Rect::from_center_size(at, galley.size());
    painter.rect_filled(rect.expand(2.0), 3.0, egui::Color32::from_black_alpha(160));
    painter.galley(rect.min, galley, color);
}

/// The control mode's rule in one sentence, with what it chose this step.
/// What a fright does to the weights: a fleeing fish's cohesion and
/// separation weights (the world's fear factors), shown beside the urges so
/// that no change of weight is hidden. Without the numbers when `hidden` (a
/// mystery weight would be given away).
pub fn fear_sentence(attention: &Attention, hidden: bool) -> String {
    let fear = crate::sim::boids::params::BoidWorldParams::default();
    if hidden {
        return tr!(
            "boids-fear-weights-hidden",
            cohesion_factor = fmt(f64::from(fear.fear_cohesion_factor), 1),
            separation_factor = fmt(f64::from(fear.fear_separation_factor), 1)
        );
    }
    tr!(
        "boids-fear-weights",
        cohesion = fmt(f64::from(attention.weights[2]), 0),
        separation = fmt(f64::from(attention.weights[3]), 0),
        cohesion_factor = fmt(f64::from(fear.fear_cohesion_factor), 1),
        separation_factor = fmt(f64::from(fear.fear_separation_factor), 1)
    )
}

pub fn rule_sentence(attention: &Attention) -> String {
    let chosen: Vec<&str> = (0..5)
        .filter(|&k| attention.applied[k])
        .map(urge_name)
        .collect();
    let chosen = if chosen.is_empty() {
        ts("boids-rule-none").to_owned()
    } else {
        chosen.join(", ")
    };
    match attention.mode {
        ControlMode::Blended => ts("boids-rule-blended").to_owned(),
        ControlMode::Classic => tr!("boids-rule-classic", chosen = chosen),
        ControlMode::DirectAlternate => tr!("boids-rule-direct-alternate", chosen = chosen),
        ControlMode::MonteCarlo => tr!("boids-rule-monte-carlo", chosen = chosen),
    }
}

/// The answer to "is there a leader?" for this fish.
pub fn leader_sentence(attention: &Attention) -> String {
    match attention.neighbours.len() {
        0 => tr!("boids-leader-alone", fish = attention.fish),
        n => tr!("boids-leader-neighbours", fish = attention.fish, count = n),
    }
}

/// The side panel's section for the selected fish of `side`: heading, the
/// urges' table, the rule, the neighbours, the leader question, and *Let go*.
pub fn attention_section_ui(
    ui: &mut egui::Ui,
    settings: &mut Settings,
    side: Side,
    tank_name: Option<&str>,
    attention: Option<&Attention>,
    rects: &mut WidgetRects,
) {
    let Some(selected) = settings.selected_in(side) else {
        return;
    };
    ui.separator();
    let title = match tank_name {
        Some(tank) => tr!("boids-attention-title-tank", fish = selected, tank = tank),
        None => tr!("boids-attention-title", fish = selected),
    };
    ui.horizontal_wrapped(|ui| {
        ui.label(egui::RichText::new(title).strong());
        let let_go = ui
            .button(ts("boids-let-go"))
            .on_hover_text(ts("boids-let-go.help"));
        rects.insert(&format!("attention_let_go_{}", side.name()), let_go.rect);
        if let_go.clicked() {
            settings.tank_mut(side).selected = None;
        }
    });
    let Some(a) = attention else {
        ui.label(ts("boids-attention-not-yet"));
        return;
    };
    ui.label(
        egui::RichText::new(ts("boids-attention-key"))
            .small()
            .weak(),
    );
    let table = egui::Grid::new(("attention_table", side.name()))
        .num_columns(3)
        .spacing([10.0, 3.0])
        .striped(true)
        .show(ui, |ui| {
            ui.label(egui::RichText::new(ts("boids-urge")).small().strong());
            ui.label(egui::RichText::new(ts("boids-strength")).small().strong())
                .on_hover_text(ts("boids-strength.help"));
            ui.label(egui::RichText::new(ts("boids-used")).small().strong());
            ui.end_row();
            for k in 0..5 {
                ui.label(
                    egui::RichText::new(format!("■ {}", ts(URGE_SHORT[k]))).color(URGE_COLORS[k]),
                )
                .on_hover_text(ts(URGE_WORDS[k]));
                // A mystery weight's strength would give it away.
                let key = format!("{}.{}", side.name(), URGE_KEYS[k]);
                if super::studio_panel::is_mystery(ui, &key) {
                    ui.label("?").on_hover_text(ts("boids-mystery.help"));
                } else {
                    ui.label(acceleration(a.urges_m_per_s2[k].length()));
                }
                ui.label(if a.applied[k] {
                    ts("boids-used-yes")
                } else {
                    "–"
                });
                ui.end_row();
            }
            ui.label(ts("boids-wander"))
                .on_hover_text(ts("boids-wander.help"));
            ui.label(acceleration(a.wander_m_per_s2.length()));
            ui.label(ts("boids-used-always"));
            ui.end_row();
            if a.fleeing {
                ui.label(
                    egui::RichText::new(ts("boids-fleeing"))
                        .color(egui::Color32::from_rgb(255, 160, 60)),
                )
                .on_hover_text(ts("boids-fleeing.help"));
                ui.label(acceleration(a.escape_m_per_s2.length()));
                ui.label(ts("boids-used-always"));
                ui.end_row();
            }
            ui.label(egui::RichText::new(ts("boids-result")).strong())
                .on_hover_text(ts("boids-result.help"));
            ui.label(acceleration(a.steering_m_per_s2.length()));
            ui.label(format!(
                "{} m/s",
                fmt(f64::from(a.velocity_m_per_s.length()), 2)
            ))
            .on_hover_text(ts("boids-speed-after.help"));
            ui.end_row();
        });
    rects.insert(
        &format!("attention_table_{}", side.name()),
        table.response.rect,
    );
    if a.fleeing {
        // The weights a fright changes, unless the teacher hid one.
        let hidden = [2, 3].iter().any(|&k| {
            super::studio_panel::is_mystery(ui, &format!("{}.{}", side.name(), URGE_KEYS[k]))
        });
        ui.label(fear_sentence(a, hidden));
    }
    ui.label(rule_sentence(a));
    let neighbours = match a.neighbours.len() {
        0 => ts("boids-heeds-none").to_owned(),
        n => tr!(
            "boids-heeds",
            count = n,
            fish = a
                .neighbours
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    ui.label(neighbours);
    if a.sees_far_school {
        ui.label(ts("boids-far-school"));
    }
    ui.label(egui::RichText::new(ts("boids-leader")).strong());
    ui.label(leader_sentence(a));
}

/// An acceleration as the table shows it: "0.42 m/s²".
fn acceleration(m_per_s2: f32) -> String {
    format!("{} m/s²", fmt(f64::from(m_per_s2), 2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrows_grow_with_strength_and_never_vanish() {
        assert_eq!(arrow_length_pt(0.0, 8.0), MIN_ARROW_PT);
        assert!(arrow_length_pt(0.4, 8.0) > 60.0, "a school's urges read");
        assert!((arrow_length_pt(8.0, 8.0) - (MIN_ARROW_PT + ARROW_RANGE_PT)).abs() < 1e-4);
        assert!(arrow_length_pt(2.0, 8.0) > arrow_length_pt(0.5, 8.0));
        assert_eq!(arrow_length_pt(f32::NAN, 8.0), MIN_ARROW_PT);
        assert_eq!(arrow_length_pt(50.0, 8.0), arrow_length_pt(8.0, 8.0));
    }
}
