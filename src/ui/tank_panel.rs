//! The controls of one boid tank: preset, control mode, the five force sliders on the
//! papers' 0–100 scale, perception, and the animals in it. Every control has hover
//! help a 12-year-old understands.

use eframe::egui;

use super::WidgetRects;
use super::studio_panel::{control, control_block, control_row, is_hidden};
use crate::settings::Side;
use crate::settings::range::Range;
use crate::settings::tank::{Preset, TankSettings};
use crate::sim::boids::control_mode::ControlMode;

/// The name on a mode's radio button.
pub fn mode_label(mode: ControlMode) -> &'static str {
    match mode {
        ControlMode::Blended => "Blended (direct)",
        ControlMode::Classic => "Classic",
        ControlMode::DirectAlternate => "Direct alternate",
        ControlMode::MonteCarlo => "Monte Carlo",
    }
}

/// The automation name of a mode (`monte_carlo`), for widget names.
fn mode_name(mode: ControlMode) -> String {
    serde_json::to_value(mode)
        .ok()
        .and_then(|v| v.as_str().map(str::to_owned))
        .unwrap_or_default()
}

fn preset_name(preset: Preset) -> String {
    serde_json::to_value(preset)
        .ok()
        .and_then(|v| v.as_str().map(str::to_owned))
        .unwrap_or_default()
}

/// The label and hover help of each force slider, in `weights_mut` order.
const FORCE_HELP: [(&str, &str); 5] = [
    (
        "Containment",
        "How strongly a fish stays in the pond: it turns back towards open water before its \
         path comes near the glass, the sand or the surface.",
    ),
    (
        "Alignment",
        "How much a fish copies the direction its neighbours are swimming \
         (close neighbours count more: their heading is easier to see).",
    ),
    (
        "Cohesion",
        "How much a fish swims towards the middle of the neighbours it can see \
         (and of the distant school it sees), easing off as it arrives.",
    ),
    (
        "Separation",
        "How much a fish keeps its own space: it moves away from fish inside its personal \
         space, harder the closer they are.",
    ),
    (
        "Avoidance",
        "How strongly a fish swerves around obstacles: the glass, sand and surface, rocks, \
         pillars, stingrays, and fish coming straight at it (three or more close together \
         count as one obstacle).",
    ),
];

/// Draws the controls of `tank`, the tank of `side`. Widget names get no
/// prefix: only one tank's controls are on screen at a time; the studio's
/// rules are keyed by the full setting (`left.alignment`).
pub fn tank_ui(ui: &mut egui::Ui, tank: &mut TankSettings, side: Side, rects: &mut WidgetRects) {
    let key = |name: &str| format!("{}.{name}", side.name());
    ui.label(egui::RichText::new("Preset").strong())
        .on_hover_text("Ready-made mixes of the five urges, from the paper's Table 1");
    control(ui, rects, &key("preset"), |ui, rects| {
        ui.horizontal_wrapped(|ui| {
            for preset in Preset::ALL {
                let response = ui
                    .selectable_value(&mut tank.preset, preset, preset.label())
                    .on_hover_text(preset.help());
                rects.insert(&format!("preset_{}", preset_name(preset)), response.rect);
            }
        });
    });

    ui.add_space(4.0);
    if !is_hidden(ui, &key("mode")) {
        ui.label(egui::RichText::new("How the urges combine").strong())
            .on_hover_text("The control mode: how a fish turns five urges into one move");
    }
    control_block(ui, rects, &key("mode"), "control mode", |ui, rects| {
        for mode in ControlMode::ALL {
            let response = ui
                .radio_value(&mut tank.mode, mode, mode_label(mode))
                .on_hover_text(mode.explanation());
            rects.insert(&format!("mode_{}", mode_name(mode)), response.rect);
        }
        ui.label(egui::RichText::new(tank.mode.explanation()).small().weak());
    });
    ui.label(
        egui::RichText::new(
            "Wander and fleeing from sharks are not urges of the mode: \
             they act on top of it, in every mode.",
        )
        .small()
        .weak(),
    );

    ui.add_space(4.0);
    ui.label(egui::RichText::new("Urges (0–100)").strong())
        .on_hover_text("How much each urge counts, on the paper's 0 to 100 scale");
    egui::Grid::new("force_sliders")
        .num_columns(2)
        .spacing([8.0, 4.0])
        .show(ui, |ui| {
            for ((range, weight), (label, help)) in tank.weights_mut().into_iter().zip(FORCE_HELP) {
                control_row(
                    ui,
                    rects,
                    &key(range.key),
                    |ui| {
                        ui.label(label).on_hover_text(help);
                    },
                    |ui, rects| {
                        let response = ui
                            .add(egui::Slider::new(weight, range.bounds()).max_decimals(0))
                            .on_hover_text(help);
                        rects.insert(&format!("weight_{}", range.key), response.rect);
                    },
                );
            }
        });

    ui.add_space(4.0);
    ui.label(egui::RichText::new("Senses, body and wander").strong())
        .on_hover_text(
            "Not part of the presets: Individual and Group change only the five urges, \
             so these stay the same when you pick a preset.",
        );
    egui::Grid::new("perception_sliders")
        .num_columns(2)
        .spacing([8.0, 4.0])
        .show(ui, |ui| {
            let mut slider = |ui: &mut egui::Ui,
                              label: &str,
                              value: &mut f32,
                              range: Range<f32>,
                              suffix: &str,
                              help: &str| {
                control_row(
                    ui,
                    rects,
                    &key(range.key),
                    |ui| {
                        ui.label(label).on_hover_text(help);
                    },
                    |ui, rects| {
                        let response = ui
                            .add(
                                egui::Slider::new(value, range.bounds())
                                    .suffix(suffix)
                                    .max_decimals(1),
                            )
                            .on_hover_text(help);
                        rects.insert(range.key, response.rect);
                    },
                );
            };
            slider(
                ui,
                "Vision distance",
                &mut tank.vision_distance_m,
                TankSettings::VISION_DISTANCE_M,
                " m",
                "How far a fish can see its neighbours, in metres.",
            );
            slider(
                ui,
                "Vision angle",
                &mut tank.vision_angle_deg,
                TankSettings::VISION_ANGLE_DEG,
                "°",
                "How wide a fish sees around itself. At 360° it sees behind too; \
                 at 300° there is a blind spot behind its tail.",
            );
            slider(
                ui,
                "Top speed",
                &mut tank.max_speed_m_per_s,
                TankSettings::MAX_SPEED_M_PER_S,
                " m/s",
                "The fastest a fish can swim, in metres per second.",
            );
            slider(
                ui,
                "Turning power",
                &mut tank.max_force_m_per_s2,
                TankSettings::MAX_FORCE_M_PER_S2,
                " m/s²",
                "How hard a fish can turn or speed up at once (the maximum force). \
                 Small values make slow, lazy turns.",
            );
            slider(
                ui,
                "Personal space",
                &mut tank.personal_space_m,
                TankSettings::PERSONAL_SPACE_M,
                " m",
                "How close another fish may come before separation pushes this one away. \
                 A school settles at about one body length (0.3–0.5 m here).",
            );
            slider(
                ui,
                "Wander",
                &mut tank.wander,
                TankSettings::WANDER,
                "",
                "How much a fish roams about on its own, 0 to 100 (on the urges' scale). \
                 The same for loners and schools: a school's alignment and cohesion \
                 overcome it, loners' do not.",
            );
        });

    ui.add_space(4.0);
    ui.label(egui::RichText::new("Animals").strong());
    egui::Grid::new("animal_counts")
        .num_columns(2)
        .spacing([8.0, 4.0])
        .show(ui, |ui| {
            count_row(
                ui,
                rects,
                side,
                "Fish",
                "fish",
                &mut tank.fish_count,
                TankSettings::FISH_COUNT,
                10,
                "How many fish (the prey) are in the tank.",
            );
            count_row(
                ui,
                rects,
                side,
                "Sharks",
                "sharks",
                &mut tank.sharks,
                TankSettings::SHARKS,
                1,
                "Hunters. A shark chases a fish; fish that see it flee and bunch together.",
            );
            count_row(
                ui,
                rects,
                side,
                "Stingrays",
                "stingrays",
                &mut tank.stingrays,
                TankSettings::STINGRAYS,
                1,
                "Flat fish that glide over the sand. Other fish swim around them like rocks.",
            );
        });
}

/// A label, − and + buttons and a number for an animal count.
#[expect(clippy::too_many_arguments)]
fn count_row(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    side: Side,
    label: &str,
    name: &str,
    count: &mut u32,
    range: Range<u32>,
    step: u32,
    help: &str,
) {
    let key = format!("{}.{}", side.name(), range.key);
    control_row(
        ui,
        rects,
        &key,
        |ui| {
            ui.label(label).on_hover_text(help);
        },
        |ui, rects| {
            ui.horizontal(|ui| {
                let minus = ui
                    .add_enabled(*count > range.min, egui::Button::new(" − "))
                    .on_hover_text(format!("Take {step} away"));
                rects.insert(&format!("{name}_minus"), minus.rect);
                if minus.clicked() {
                    *count = range.clamp(count.saturating_sub(step));
                }
                let value = ui
                    .add(
                        egui::DragValue::new(count)
                            .range(range.bounds())
                            .speed(f64::from(step).max(1.0) * 0.2),
                    )
                    .on_hover_text(help);
                rects.insert(&format!("{name}_count"), value.rect);
                let plus = ui
                    .add_enabled(*count < range.max, egui::Button::new(" + "))
                    .on_hover_text(format!("Add {step}"));
                rects.insert(&format!("{name}_plus"), plus.rect);
                if plus.clicked() {
                    *count = range.clamp(*count + step);
                }
            });
        },
    );
}
