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
use super::metrics_panel::{URGE_COLORS, URGE_NAMES};
use super::scene_panel::ViewContext;
use crate::settings::{Settings, Side};
use crate::sim::World;
use crate::sim::boids::attention::Attention;
use crate::sim::boids::control_mode::ControlMode;

/// Shortest urge arrow on screen, points. 22, chosen: a weak urge still shows
/// its direction clear of the fish's ring (13 points).
const MIN_ARROW_PT: f32 = 22.0;

/// How much longer an urge at the full maximum force is than the shortest
/// arrow, points. 200, chosen: avoidance at full force crosses a good part of
/// the view, and the arrows grow with the square root of the strength, so an
/// urge a twentieth as strong (a school's alignment) is still about 70 points.
const ARROW_RANGE_PT: f32 = 200.0;

/// The urges' names in sentences and the table.
const URGE_WORDS: [&str; 5] = [
    "containment (stay in the tank)",
    "alignment (swim like the neighbours)",
    "cohesion (move to the neighbours' centre)",
    "separation (keep space)",
    "avoidance (swerve round obstacles)",
];

/// Short names for the table.
const URGE_SHORT: [&str; 5] = [
    "Containment",
    "Alignment",
    "Cohesion",
    "Separation",
    "Avoidance",
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
    for k in 0..5 {
        let v = attention.urges_m_per_s2[k];
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
        label(
            painter,
            tip + dir * 10.0,
            URGE_NAMES[k],
            font.clone(),
            color,
        );
    }
    let result = attention.steering_m_per_s2;
    if let Some(dir) = screen_dir(result) {
        let tip = c + dir * arrow_length_pt(result.length(), max_force);
        painter.arrow(c, tip - c, egui::Stroke::new(3.5, egui::Color32::WHITE));
        label(
            painter,
            tip + dir * 12.0,
            "result",
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
pub fn rule_sentence(attention: &Attention) -> String {
    let chosen: Vec<&str> = (0..5)
        .filter(|&k| attention.applied[k])
        .map(|k| URGE_NAMES[k])
        .collect();
    let chosen = if chosen.is_empty() {
        "none".to_owned()
    } else {
        chosen.join(", ")
    };
    match attention.mode {
        ControlMode::Blended => "Blended: every urge with a weight pulls at once, each by its \
             weight's share (the arrows add up to the result)."
            .to_owned(),
        ControlMode::Classic => format!(
            "Classic: only the most pressing urge acts (its weight × how much it is needed \
             now). This step: {chosen}."
        ),
        ControlMode::DirectAlternate => format!(
            "Direct alternate: one dice roll, and every urge whose weight beats it acts at \
             full strength. This step: {chosen}."
        ),
        ControlMode::MonteCarlo => format!(
            "Monte Carlo: one urge is drawn by lottery; bigger weights hold more tickets. \
             This step: {chosen}."
        ),
    }
}

/// The answer to "is there a leader?" for this fish.
pub fn leader_sentence(attention: &Attention) -> String {
    let n = attention.neighbours.len();
    match n {
        0 => format!(
            "No fish leads: fish {} sees no other fish right now, so only the tank, \
             the rocks and its own wandering steer it.",
            attention.fish
        ),
        _ => format!(
            "No fish leads: fish {} reacts only to the {n} neighbour{} it sees, and each of \
             them to its own neighbours. The school's shape comes from all these small \
             reactions together.",
            attention.fish,
            if n == 1 { "" } else { "s" }
        ),
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
        Some(tank) => format!("What fish {selected} pays attention to ({tank})"),
        None => format!("What fish {selected} pays attention to"),
    };
    ui.horizontal_wrapped(|ui| {
        ui.label(egui::RichText::new(title).strong());
        let let_go = ui
            .button("Let go")
            .on_hover_text("Stop showing this fish (or click open water)");
        rects.insert(&format!("attention_let_go_{}", side.name()), let_go.rect);
        if let_go.clicked() {
            settings.tank_mut(side).selected = None;
        }
    });
    let Some(a) = attention else {
        ui.label(
            "Press Play or Step: the fish has not swum since the settings changed, so \
             there is nothing to show yet.",
        );
        return;
    };
    ui.label(
        egui::RichText::new(
            "Arrows from the fish (ringed yellow): each urge, longer when stronger; solid \
             when used this step, dashed when not; white is the result. White rings: the \
             neighbours it heeds.",
        )
        .small()
        .weak(),
    );
    let table = egui::Grid::new(("attention_table", side.name()))
        .num_columns(3)
        .spacing([10.0, 3.0])
        .striped(true)
        .show(ui, |ui| {
            ui.label(egui::RichText::new("Urge").small().strong());
            ui.label(egui::RichText::new("Strength").small().strong())
                .on_hover_text(
                    "How hard the urge pulls, as the control mode weighs it: the \
                     acceleration it asks for, in metres per second per second",
                );
            ui.label(egui::RichText::new("Used?").small().strong());
            ui.end_row();
            for k in 0..5 {
                ui.label(egui::RichText::new(format!("■ {}", URGE_SHORT[k])).color(URGE_COLORS[k]))
                    .on_hover_text(URGE_WORDS[k]);
                // A mystery weight's strength would give it away.
                let key = format!("{}.{}", side.name(), URGE_SHORT[k].to_lowercase());
                if super::studio_panel::is_mystery(ui, &key) {
                    ui.label("?")
                        .on_hover_text("A mystery value: your teacher hid it");
                } else {
                    ui.label(format!("{:.2} m/s²", a.urges_m_per_s2[k].length()));
                }
                ui.label(if a.applied[k] { "yes" } else { "–" });
                ui.end_row();
            }
            ui.label("Wander")
                .on_hover_text("Its own roaming: acts on top of every control mode");
            ui.label(format!("{:.2} m/s²", a.wander_m_per_s2.length()));
            ui.label("always");
            ui.end_row();
            if a.fleeing {
                ui.label(
                    egui::RichText::new("Fleeing a shark")
                        .color(egui::Color32::from_rgb(255, 160, 60)),
                );
                ui.label(format!("{:.2} m/s²", a.escape_m_per_s2.length()));
                ui.label("always");
                ui.end_row();
            }
            ui.label(egui::RichText::new("Result").strong())
                .on_hover_text("The steering the fish got this step (white arrow)");
            ui.label(format!("{:.2} m/s²", a.steering_m_per_s2.length()));
            ui.label(format!("{:.2} m/s", a.velocity_m_per_s.length()))
                .on_hover_text("Its speed after the step");
            ui.end_row();
        });
    rects.insert(
        &format!("attention_table_{}", side.name()),
        table.response.rect,
    );
    ui.label(rule_sentence(a));
    let neighbours = match a.neighbours.len() {
        0 => "It heeds no neighbour: it sees no other fish.".to_owned(),
        n => format!(
            "It heeds {n} neighbour{} (ringed): fish {}.",
            if n == 1 { "" } else { "s" },
            a.neighbours
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    ui.label(neighbours);
    if a.sees_far_school {
        ui.label("It also sees a distant group of fish and is drawn a little towards it.");
    }
    ui.label(egui::RichText::new("Is there a leader?").strong());
    ui.label(leader_sentence(a));
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
