//! The side panel: scene, play/pause, single step, reset, speed, seed, the
//! scene's own controls (from its [`super::ScenePanel`]), share and export, and the
//! view. Every control has hover help a 12-year-old understands.

use eframe::egui;

use super::WidgetRects;
use super::scene_panel::PanelAction;
use super::setting_slider::{setting_row, setting_row_with};
use super::studio_panel::control;
use crate::scenes::CurrentPanel;
use crate::settings::{SEED_MAX, Scene, Settings};

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
        ui.heading("Shoal");
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            let hide = ui
                .button("Hide")
                .on_hover_text("Hide this panel so the aquarium fills the screen");
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
                    .selectable_value(&mut settings.scene, scene, scene.class().facts().label)
                    .on_hover_text(scene.class().facts().description);
                rects.insert(&format!("scene_{}", scene.name()), response.rect);
            }
        });
    });
    ui.label(egui::RichText::new(settings.scene.class().facts().description).weak());
    ui.horizontal_wrapped(|ui| {
        super::about::about_button(ui, rects);
        super::studio_panel::studio_button(ui, &settings.studio, rects);
        let describe = ui.button("Describe the tank").on_hover_text(
            "Say in words what the fish do and what the plots show now (key D). \
             A screen reader reads it aloud.",
        );
        rects.insert("describe", describe.rect);
        if describe.clicked() {
            actions.push(PanelAction::Describe);
        }
        let keys = ui
            .button("Keys")
            .on_hover_text("Every keyboard shortcut (key ?)");
        rects.insert("keys", keys.rect);
        if keys.clicked() {
            actions.push(PanelAction::Keyboard);
        }
    });
    ui.separator();

    ui.label(egui::RichText::new("Simulation").strong());
    ui.horizontal(|ui| {
        let (icon, help) = if settings.paused {
            ("Play", "Start the fish swimming again (Space)")
        } else {
            ("Pause", "Freeze the fish so you can look closely (Space)")
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
        let step = ui.button("Step").on_hover_text(step_help(step_secs));
        rects.insert("step", step.rect);
        if step.clicked() {
            actions.push(PanelAction::Step);
        }
        let reset = ui.button("Reset").on_hover_text(
            "Start again from the beginning, with the same fish in the same places (R)",
        );
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
                    let dice = ui.button("New").on_hover_text(
                        "Pick a new random seed: a different tank and different fish",
                    );
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
    ui.label(egui::RichText::new("Share").strong());
    ui.horizontal(|ui| {
        let copy = ui.button("Copy link").on_hover_text(
            "Copy a web link that opens Shoal with exactly these settings, \
             to send to your class",
        );
        rects.insert("copy_link", copy.rect);
        if copy.clicked() {
            actions.push(PanelAction::CopyLink);
        }
        let csv = ui.button("Download data (CSV)").on_hover_text(
            "Save this scene's numbers as a table for a spreadsheet, in a file named \
                 after the scene and the simulated time; its first lines hold the seed and \
                 the link that reopens these settings",
        );
        rects.insert("export_csv", csv.rect);
        if csv.clicked() {
            actions.push(PanelAction::ExportCsv);
        }
    });

    ui.separator();
    ui.label(egui::RichText::new("View").strong());
    ui.horizontal_wrapped(|ui| {
        let help = "How big text, buttons and plots are. Auto: bigger on a big screen, so \
                    the back of the room can read it";
        ui.label("Text size").on_hover_text(help);
        let mut auto = view.interface_scale.is_none();
        let r = ui
            .checkbox(&mut auto, "Auto")
            .on_hover_text(help)
            .accessible_name("Automatic text size");
        rects.insert("ui_scale_auto", r.rect);
        if r.changed() {
            view.interface_scale = (!auto).then_some(view.current_scale);
        }
        // Buttons, not a slider: the scale changes the panel under the pointer.
        let range = super::screen::SCALE_RANGE;
        let current = view.interface_scale.unwrap_or(view.current_scale);
        let r = ui
            .add_enabled(current > *range.start() + 0.01, egui::Button::new("A−"))
            .on_hover_text("Smaller text")
            .accessible_name("Smaller text");
        rects.insert("ui_scale_smaller", r.rect);
        if r.clicked() {
            view.interface_scale = Some((current - 0.1).max(*range.start()));
        }
        ui.label(format!("{current:.2}×"));
        let r = ui
            .add_enabled(current < *range.end() - 0.01, egui::Button::new("A+"))
            .on_hover_text("Bigger text")
            .accessible_name("Bigger text");
        rects.insert("ui_scale_bigger", r.rect);
        if r.clicked() {
            view.interface_scale = Some((current + 0.1).min(*range.end()));
        }
    });
    ui.horizontal_wrapped(|ui| {
        let help = "Auto: on a computer whose graphics cannot keep up, the tank is drawn \
                    with fewer pixels so that it keeps moving smoothly (the panels and plots \
                    stay sharp). Untick for the sharpest tank, however slow";
        ui.label("Tank detail").on_hover_text(help);
        let r = ui
            .checkbox(&mut view.detail_auto, "Auto")
            .on_hover_text(help)
            .accessible_name("Automatic tank detail");
        rects.insert("scene_detail_auto", r.rect);
        let pixels = view.detail_scale * view.detail_scale;
        ui.label(if view.detail_scale < 1.0 {
            format!("{:.0} % of the pixels", pixels * 100.0)
        } else {
            "every pixel".to_owned()
        })
        .on_hover_text("How many of the view's pixels the tank is drawn with now");
    });
    super::seeing::seeing_ui(ui, rects);
    ui.label(
        egui::RichText::new(
            "Drag to turn the tank · scroll or pinch to zoom · right-drag or two fingers to \
             move · V or the button on the tank puts the camera back",
        )
        .small()
        .weak(),
    );
    actions
}

/// The Step button's help: one step of the scene on show, in words.
fn step_help(step_secs: f64) -> String {
    let per_second = 1.0 / step_secs.max(1e-9);
    if (per_second - per_second.round()).abs() < 0.01 {
        format!(
            "Move time forward by one tiny step, 1/{} of a second (S)",
            per_second.round()
        )
    } else {
        format!("Move time forward by one step, {step_secs:.3} seconds (S)")
    }
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
