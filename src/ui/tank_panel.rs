//! The controls of one boid tank: preset, control mode, the five force sliders on the
//! papers' 0–100 scale, perception, and the animals in it. Every control has hover
//! help a 12-year-old understands.

use eframe::egui;
use egui::emath::Numeric;

use super::WidgetRects;
use super::setting_slider::setting_row;
use super::studio_panel::{control, control_block, is_hidden};
use crate::i18n::ts;
use crate::settings::Side;
use crate::settings::number::NumberSetting;
use crate::settings::range::SettingValue;
use crate::settings::tank::{Preset, TankSettings};
use crate::sim::boids::control_mode::ControlMode;

/// The name on a mode's radio button.
pub fn mode_label(mode: ControlMode) -> &'static str {
    match mode {
        ControlMode::Blended => ts("setting-mode-blended"),
        ControlMode::Classic => ts("setting-mode-classic"),
        ControlMode::DirectAlternate => ts("setting-mode-direct-alternate"),
        ControlMode::MonteCarlo => ts("setting-mode-monte-carlo"),
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

/// Draws the controls of `tank`, the tank of `side`. Widget names get no
/// prefix: only one tank's controls are on screen at a time; the studio's
/// rules are keyed by the full setting (`left.alignment`).
pub fn tank_ui(ui: &mut egui::Ui, tank: &mut TankSettings, side: Side, rects: &mut WidgetRects) {
    let prefix = side.prefix();
    let key = |name: &str| format!("{prefix}{name}");
    ui.label(egui::RichText::new(ts("setting-tank-panel-preset")).strong())
        .on_hover_text(ts("setting-tank-panel-preset.help"));
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
    if tank.preset == Preset::MonteCarloPaper {
        // Why its bodies overlap, measured (docs/boids.md).
        ui.label(
            egui::RichText::new(ts("setting-preset-monte-carlo-paper.note"))
                .small()
                .weak(),
        );
    }

    ui.add_space(4.0);
    if !is_hidden(ui, &key("mode")) {
        ui.label(egui::RichText::new(ts("setting-tank-panel-mode")).strong())
            .on_hover_text(ts("setting-tank-panel-mode.help"));
    }
    control_block(
        ui,
        rects,
        &key("mode"),
        ts("setting-tank-panel-mode.block"),
        |ui, rects| {
            for mode in ControlMode::ALL {
                let response = ui
                    .radio_value(&mut tank.mode, mode, mode_label(mode))
                    .on_hover_text(mode.explanation());
                rects.insert(&format!("mode_{}", mode_name(mode)), response.rect);
            }
            ui.label(egui::RichText::new(tank.mode.explanation()).small().weak());
        },
    );
    ui.label(
        egui::RichText::new(ts("setting-tank-panel-mode-note"))
            .small()
            .weak(),
    );

    ui.add_space(4.0);
    ui.label(egui::RichText::new(ts("setting-tank-panel-urges")).strong())
        .on_hover_text(ts("setting-tank-panel-urges.help"));
    rows_grid(
        ui,
        rects,
        "force_sliders",
        &prefix,
        &TankSettings::WEIGHTS,
        tank,
    );

    ui.add_space(4.0);
    ui.label(egui::RichText::new(ts("setting-tank-panel-senses")).strong())
        .on_hover_text(ts("setting-tank-panel-senses.help"));
    rows_grid(
        ui,
        rects,
        "perception_sliders",
        &prefix,
        &TankSettings::SENSES,
        tank,
    );

    ui.add_space(4.0);
    ui.label(egui::RichText::new(ts("setting-tank-panel-animals")).strong());
    rows_grid(
        ui,
        rects,
        "animal_counts",
        &prefix,
        &TankSettings::COUNTS,
        tank,
    );
    if let Some(note) = school_size_note(tank.fish_count) {
        ui.label(egui::RichText::new(note).small().weak());
    }
}

/// Where Table 1's weights alone do not give the schooling contrast: a word
/// beside the *Fish* slider at the school sizes where the measurements of
/// `docs/boids.md` (`examples/boid_contrast.rs`, 20 seeds no tuning used)
/// show it fading, so that a class reads what it sees for what it is.
pub fn school_size_note(fish_count: u32) -> Option<&'static str> {
    match fish_count {
        1..=SMALL_SCHOOL_MAX => Some(ts("setting-tank-fish-count.few")),
        CROWDED_MIN.. => Some(ts("setting-tank-fish-count.crowded")),
        _ => None,
    }
}

/// Up to this many fish, loners that meet line up in pairs (docs/boids.md).
const SMALL_SCHOOL_MAX: u32 = 50;
/// From this many fish on, the tank is crowded (docs/boids.md).
const CROWDED_MIN: u32 = 1000;

/// A two-column grid of `settings`' rows (label, control) of `tank`.
fn rows_grid<T>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    id: &str,
    prefix: &str,
    settings: &[NumberSetting<TankSettings, T>],
    tank: &mut TankSettings,
) where
    T: SettingValue + Numeric,
{
    egui::Grid::new(id)
        .num_columns(2)
        .spacing([8.0, 4.0])
        .show(ui, |ui| {
            for setting in settings {
                setting_row(ui, rects, prefix, setting, tank);
            }
        });
}

#[cfg(test)]
mod tests {
    use super::school_size_note;

    /// The note appears exactly at the sizes `docs/boids.md` measured the
    /// contrast fading at, and says which.
    #[test]
    fn the_fish_slider_warns_where_the_contrast_fades() {
        crate::i18n::with_lang(crate::i18n::Lang::En, || {
            assert!(school_size_note(20).is_some_and(|n| n.contains("50 fish or fewer")));
            assert!(school_size_note(50).is_some());
            assert_eq!(school_size_note(0), None, "no fish, nothing to compare");
            assert_eq!(school_size_note(51), None);
            assert_eq!(school_size_note(200), None, "the default");
            assert_eq!(school_size_note(999), None);
            assert!(school_size_note(1000).is_some_and(|n| n.contains("crowded")));
            assert!(school_size_note(20_000).is_some());
        });
    }
}
