//! The side panel: play/pause, single step, reset, speed, fish count, seed and view.
//! Every control has hover help a 12-year-old understands.

use eframe::egui;

use super::WidgetRects;
use crate::settings::{FISH_COUNT_MAX, SEED_MAX, SPEED_MAX, SPEED_MIN, Settings};

/// One-off things the teacher asked for this frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PanelAction {
    /// Advance the simulation by one step.
    Step,
    /// Start the run again from the same seed.
    Reset,
    /// Put the camera back where it started.
    ResetView,
    /// Collapse the panel so the aquarium fills the screen.
    HidePanel,
}

/// Draws the control panel, editing `settings` in place, and records where the
/// main widgets are (for the browser tests' real clicks, see `shoal.widgets()`).
pub fn control_panel_ui(
    ui: &mut egui::Ui,
    settings: &mut Settings,
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
    ui.label(egui::RichText::new(settings.scene.description()).weak());
    ui.separator();

    ui.label(egui::RichText::new("Simulation").strong());
    ui.horizontal(|ui| {
        let (icon, help) = if settings.paused {
            ("Play", "Start the fish swimming again (Space)")
        } else {
            ("Pause", "Freeze the fish so you can look closely (Space)")
        };
        let play_pause = ui
            .add(egui::Button::new(icon).min_size(egui::vec2(64.0, 0.0)))
            .on_hover_text(help);
        rects.insert("play_pause", play_pause.rect);
        if play_pause.clicked() {
            settings.paused = !settings.paused;
        }
        let step = ui
            .button("Step")
            .on_hover_text("Move time forward by one tiny step, 1/60 of a second (S)");
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
            ui.label("Speed")
                .on_hover_text("How fast time runs: 1× is real time, 2× is twice as fast");
            let speed = ui
                .add(
                    egui::Slider::new(&mut settings.speed, SPEED_MIN..=SPEED_MAX)
                        .logarithmic(true)
                        .suffix("×")
                        .max_decimals(2),
                )
                .on_hover_text("How fast time runs: 1× is real time, 2× is twice as fast");
            rects.insert("speed", speed.rect);
            ui.end_row();

            ui.label("Fish")
                .on_hover_text("How many fish are in the tank");
            let fish = ui
                .add(
                    egui::Slider::new(&mut settings.left.fish_count, 0..=FISH_COUNT_MAX)
                        .logarithmic(true)
                        .smallest_positive(1.0),
                )
                .on_hover_text("How many fish are in the tank");
            rects.insert("fish_count", fish.rect);
            ui.end_row();

            ui.label("Seed").on_hover_text(
                "The number that decides where everything starts. \
                 The same seed always gives the same run, so a class can share it",
            );
            ui.horizontal(|ui| {
                let seed = ui
                    .add(egui::DragValue::new(&mut settings.seed).range(0..=SEED_MAX))
                    .on_hover_text("Type a number to start a new run from it");
                rects.insert("seed", seed.rect);
                let dice = ui
                    .button("New")
                    .on_hover_text("Pick a new random seed: a different tank and different fish");
                rects.insert("new_seed", dice.rect);
                if dice.clicked() {
                    settings.seed = next_seed(settings.seed);
                }
            });
            ui.end_row();
        });

    ui.separator();
    ui.label(egui::RichText::new("View").strong());
    let reset_view = ui
        .button("Reset view")
        .on_hover_text("Put the camera back in front of the tank");
    rects.insert("reset_view", reset_view.rect);
    if reset_view.clicked() {
        actions.push(PanelAction::ResetView);
    }
    ui.label(
        egui::RichText::new(
            "Drag to turn the tank · scroll or pinch to zoom · right-drag or two fingers to move",
        )
        .small()
        .weak(),
    );
    actions
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
