//! The side panel: scene, play/pause, single step, reset, speed, seed, the
//! scene's own controls (from its [`super::ScenePanel`]), share and export, and the
//! view. Every control has hover help a 12-year-old understands.

use eframe::egui;

use super::WidgetRects;
use super::scene_panel::PanelAction;
use super::setting_slider::{setting_row, setting_row_with};
use super::studio_panel::control;
use crate::i18n::{Lang, num, tr, ts};
use crate::scenes::CurrentPanel;
use crate::settings::{SEED_MAX, Scene, Settings};
use crate::tr;

/// The view options the side panel edits that are not settings (they belong
/// to this screen, not to the run a link shares).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewOptions {
    /// The interface scale chosen, `None` for automatic.
    pub interface_scale: Option<f32>,
    /// The scale in use now.
    pub current_scale: f32,
    /// Whether the tank's drawing scale follows the frame rate.
    pub detail_auto: bool,
    /// The tank's drawing scale now (pixels per side, share of the view's).
    pub detail_scale: f32,
}

/// Draws the control panel, editing `settings` in place, and records where the
/// main widgets are (for the browser tests' real clicks, see `shoal.widgets()`).
/// `step_secs` is one simulation step of the scene on show.
pub fn control_panel_ui(
    ui: &mut egui::Ui,
    settings: &mut Settings,
    panel: &mut CurrentPanel,
    step_secs: f64,
    view: &mut ViewOptions,
    rects: &mut WidgetRects,
) -> Vec<PanelAction> {
    let mut actions = Vec::new();
    ui.add_space(6.0);
    ui.horizontal(|ui| {
        ui.heading(ts("app-name"));
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            let hide = ui
                .button(ts("panel-hide"))
                .on_hover_text(ts("panel-hide.help"));
            rects.insert("hide_panel", hide.rect);
            if hide.clicked() {
                actions.push(PanelAction::HidePanel);
            }
        });
    });
    super::studio_panel::question_card(ui, &settings.studio, rects);
    control(ui, rects, "scene", |ui, rects| {
        ui.horizontal_wrapped(|ui| {
            for scene in Scene::ALL {
                let response = ui
                    .selectable_value(&mut settings.scene, scene, scene.class().facts().label())
                    .on_hover_text(scene.class().facts().description());
                rects.insert(&format!("scene_{}", scene.name()), response.rect);
            }
        });
    });
    ui.label(egui::RichText::new(settings.scene.class().facts().description()).weak());
    ui.horizontal_wrapped(|ui| {
        super::about::about_button(ui, rects);
        super::studio_panel::studio_button(ui, &settings.studio, rects);
        let describe = ui
            .button(ts("panel-describe"))
            .on_hover_text(ts("panel-describe.help"));
        rects.insert("describe", describe.rect);
        if describe.clicked() {
            actions.push(PanelAction::Describe);
        }
        let keys = ui
            .button(ts("panel-keys"))
            .on_hover_text(ts("panel-keys.help"));
        rects.insert("keys", keys.rect);
        if keys.clicked() {
            actions.push(PanelAction::Keyboard);
        }
    });
    ui.separator();

    ui.label(egui::RichText::new(ts("panel-simulation")).strong());
    ui.horizontal(|ui| {
        let (icon, help) = if settings.paused {
            (ts("panel-play"), ts("panel-play.help"))
        } else {
            (ts("panel-pause"), ts("panel-pause.help"))
        };
        control(ui, rects, "paused", |ui, rects| {
            let play_pause = ui
                .add(egui::Button::new(icon).min_size(egui::vec2(64.0, 0.0)))
                .on_hover_text(help);
            rects.insert("play_pause", play_pause.rect);
            if play_pause.clicked() {
                settings.paused = !settings.paused;
            }
        });
        let step = ui
            .button(ts("panel-step"))
            .on_hover_text(step_help(step_secs));
        rects.insert("step", step.rect);
        if step.clicked() {
            actions.push(PanelAction::Step);
        }
        let reset = ui
            .button(ts("panel-reset"))
            .on_hover_text(ts("panel-reset.help"));
        rects.insert("reset", reset.rect);
        if reset.clicked() {
            actions.push(PanelAction::Reset);
        }
    });
    ui.add_space(4.0);

    egui::Grid::new("settings_grid")
        .num_columns(2)
        .spacing([8.0, 6.0])
        .show(ui, |ui| {
            setting_row(ui, rects, "", &Settings::SPEED, settings);
            setting_row_with(
                ui,
                rects,
                "",
                &Settings::SEED,
                settings,
                |ui, rects, settings| {
                    let dice = ui
                        .button(ts("panel-new-seed"))
                        .on_hover_text(ts("panel-new-seed.help"));
                    rects.insert("new_seed", dice.rect);
                    if dice.clicked() {
                        settings.seed = next_seed(settings.seed);
                    }
                },
            );
        });

    // The scene's own controls: those of the scene just chosen, if a tab was
    // clicked above.
    panel
        .for_scene(settings.scene)
        .controls_ui(ui, settings, rects);

    ui.separator();
    ui.label(egui::RichText::new(ts("panel-share")).strong());
    ui.horizontal(|ui| {
        let copy = ui
            .button(ts("panel-copy-link"))
            .on_hover_text(ts("panel-copy-link.help"));
        rects.insert("copy_link", copy.rect);
        if copy.clicked() {
            actions.push(PanelAction::CopyLink);
        }
        let csv = ui
            .button(ts("panel-download-csv"))
            .on_hover_text(ts("panel-download-csv.help"));
        rects.insert("export_csv", csv.rect);
        if csv.clicked() {
            actions.push(PanelAction::ExportCsv);
        }
    });

    ui.separator();
    ui.label(egui::RichText::new(ts("panel-view")).strong());
    language_ui(ui, rects);
    ui.horizontal_wrapped(|ui| {
        let help = ts("panel-text-size.help");
        ui.label(ts("panel-text-size")).on_hover_text(help);
        let mut auto = view.interface_scale.is_none();
        let r = ui
            .checkbox(&mut auto, ts("panel-auto"))
            .on_hover_text(help)
            .accessible_name(ts("panel-text-size.auto"));
        rects.insert("ui_scale_auto", r.rect);
        if r.changed() {
            view.interface_scale = (!auto).then_some(view.current_scale);
        }
        // Buttons, not a slider: the scale changes the panel under the pointer.
        let range = super::screen::SCALE_RANGE;
        let current = view.interface_scale.unwrap_or(view.current_scale);
        let r = ui
            .add_enabled(current > *range.start() + 0.01, egui::Button::new("A−"))
            .on_hover_text(ts("panel-text-smaller"))
            .accessible_name(ts("panel-text-smaller"));
        rects.insert("ui_scale_smaller", r.rect);
        if r.clicked() {
            view.interface_scale = Some((current - 0.1).max(*range.start()));
        }
        ui.label(tr!("panel-text-scale", scale = num(f64::from(current), 2)));
        let r = ui
            .add_enabled(current < *range.end() - 0.01, egui::Button::new("A+"))
            .on_hover_text(ts("panel-text-bigger"))
            .accessible_name(ts("panel-text-bigger"));
        rects.insert("ui_scale_bigger", r.rect);
        if r.clicked() {
            view.interface_scale = Some((current + 0.1).min(*range.end()));
        }
    });
    ui.horizontal_wrapped(|ui| {
        let help = ts("panel-tank-detail.help");
        ui.label(ts("panel-tank-detail")).on_hover_text(help);
        let r = ui
            .checkbox(&mut view.detail_auto, ts("panel-auto"))
            .on_hover_text(help)
            .accessible_name(ts("panel-tank-detail.auto"));
        rects.insert("scene_detail_auto", r.rect);
        let pixels = view.detail_scale * view.detail_scale;
        ui.label(if view.detail_scale < 1.0 {
            tr!(
                "panel-pixels-share",
                percent = num(f64::from(pixels) * 100.0, 0)
            )
        } else {
            tr("panel-pixels-all")
        })
        .on_hover_text(ts("panel-pixels.help"));
    });
    super::seeing::seeing_ui(ui, rects);
    ui.label(egui::RichText::new(ts("panel-camera-hint")).small().weak());
    actions
}

/// The Step button's help: one step of the scene on show, in words.
fn step_help(step_secs: f64) -> String {
    let per_second = 1.0 / step_secs.max(1e-9);
    if (per_second - per_second.round()).abs() < 0.01 {
        tr!("panel-step.help-fraction", per_second = per_second.round())
    } else {
        tr!("panel-step.help-seconds", seconds = num(step_secs, 3))
    }
}

/// The language picker: every language of the catalogue as a button named
/// in itself (a student who cannot read the current language still finds
/// their own), the one in force pressed.
fn language_ui(ui: &mut egui::Ui, rects: &mut WidgetRects) {
    ui.horizontal_wrapped(|ui| {
        let help = ts("language.help");
        ui.label(ts("language")).on_hover_text(help);
        let current = crate::i18n::lang();
        for lang in Lang::ALL {
            let r = ui
                .selectable_label(lang == current, lang.native_name())
                .on_hover_text(help);
            rects.insert(&format!("lang_{}", lang.code()), r.rect);
            if r.clicked() && lang != current {
                super::language::choose(ui.ctx(), lang);
            }
        }
    });
}

/// A new seed that looks random but is reproducible from the old one (SplitMix64).
fn next_seed(seed: u64) -> u64 {
    let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    (z ^ (z >> 31)) % (SEED_MAX + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_step_help_says_how_long_a_step_is() {
        assert!(step_help(1.0 / 60.0).contains("1/60 of a second"));
        assert!(step_help(0.055).contains("0.055 seconds"));
    }

    #[test]
    fn new_seeds_differ_and_stay_in_range() {
        let mut seed = 1;
        for _ in 0..100 {
            let next = next_seed(seed);
            assert_ne!(next, seed);
            assert!(next <= SEED_MAX);
            seed = next;
        }
    }
}
