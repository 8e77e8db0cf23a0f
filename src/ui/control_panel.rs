//! The side panel: scene, play/pause, single step, reset, speed, seed, the boid
//! tanks' controls, obstacle tools, share and export, and the view. Every control has
//! hover help a 12-year-old understands.

use eframe::egui;

use super::WidgetRects;
use super::tank_panel::tank_ui;
use crate::settings::tank::TankSettings;
use crate::settings::{SEED_MAX, Scene, Settings, Side};
use crate::sim::reef::mind::{FishKind, Habits};

/// What a click in the tank does.
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
            Self::Look => "Look",
            Self::AddRock => "Add rock",
            Self::MoveRock => "Move rock",
            Self::RemoveRock => "Remove",
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
            Self::Look => "Drag to turn the tank, scroll to zoom.",
            Self::AddRock => "Click on the sand to put a rock there.",
            Self::MoveRock => "Drag a rock or pillar to a new place.",
            Self::RemoveRock => "Click a rock, pillar or ledge to take it out.",
        }
    }
}

/// Panel state that is not a setting: which tank the controls edit, and the tool.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelState {
    pub edit_side: Side,
    pub tool: EditTool,
    /// Reef scene: whose mind the *Minds* section edits.
    pub minds_kind: FishKind,
    /// Reef scene: the habits the demo gives each kind of fish present (the
    /// first of each kind), filled in by the app every frame.
    pub reef_demo_habits: Vec<Habits>,
}

impl Default for PanelState {
    fn default() -> Self {
        Self {
            edit_side: Side::Left,
            tool: EditTool::Look,
            minds_kind: FishKind::Predator,
            reef_demo_habits: Vec::new(),
        }
    }
}

/// One-off things the teacher asked for this frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PanelAction {
    /// Advance the simulation by one step.
    Step,
    /// Start the run again from the same seed.
    Reset,
    /// Put the camera back where it started.
    ResetView,
    /// Collapse the panel so the aquarium fills the screen.
    HidePanel,
    /// Put the link to this exact setting on the clipboard.
    CopyLink,
    /// Download the metrics of the last minutes as a CSV file.
    ExportCsv,
    /// Bring back the rocks the seed placed in the tank being edited.
    RestoreObstacles,
    /// Physics scene: the selected fish starts a turn of this many degrees (+ left).
    Turn(f32),
    /// Learning lab: forget the training.
    ResetTraining,
    /// Learning lab: start the race.
    StartRace,
    /// Learning lab: download the learned controllers.
    SaveControllers,
    /// Learning lab: open a controllers file.
    LoadControllers,
}

/// Draws the control panel, editing `settings` in place, and records where the
/// main widgets are (for the browser tests' real clicks, see `shoal.widgets()`).
pub fn control_panel_ui(
    ui: &mut egui::Ui,
    settings: &mut Settings,
    state: &mut PanelState,
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
    ui.horizontal(|ui| {
        for scene in Scene::ALL {
            let response = ui
                .selectable_value(&mut settings.scene, scene, scene.label())
                .on_hover_text(scene.description());
            rects.insert(&format!("scene_{}", scene.name()), response.rect);
        }
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
            .on_hover_text(if settings.scene == Scene::Physics {
                "Move time forward by one step of the muscle physics, 0.055 seconds (S)"
            } else {
                "Move time forward by one tiny step, 1/60 of a second (S)"
            });
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
                    egui::Slider::new(&mut settings.speed, Settings::SPEED.bounds())
                        .logarithmic(true)
                        .suffix("×")
                        .max_decimals(2),
                )
                .on_hover_text("How fast time runs: 1× is real time, 2× is twice as fast");
            rects.insert("speed", speed.rect);
            ui.end_row();

            if settings.scene == Scene::Aquarium {
                ui.label("Fish")
                    .on_hover_text("How many fish are in the tank");
                let fish = ui
                    .add(
                        egui::Slider::new(
                            &mut settings.left.fish_count,
                            TankSettings::FISH_COUNT.bounds(),
                        )
                        .logarithmic(true)
                        .smallest_positive(1.0),
                    )
                    .on_hover_text("How many fish are in the tank");
                rects.insert("fish_count", fish.rect);
                ui.end_row();
            }

            ui.label("Seed").on_hover_text(
                "The number that decides where everything starts. \
                 The same seed always gives the same run, so a class can share it",
            );
            ui.horizontal(|ui| {
                let seed = ui
                    .add(egui::DragValue::new(&mut settings.seed).range(Settings::SEED.bounds()))
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

    if settings.scene == Scene::Boids {
        boids_ui(ui, settings, state, rects, &mut actions);
    }
    if settings.scene == Scene::Physics {
        actions.extend(super::physics_panel::physics_controls_ui(
            ui,
            &mut settings.physics,
            rects,
        ));
    }
    if settings.scene == Scene::Reef {
        actions.extend(super::reef_panel::reef_controls_ui(
            ui,
            &mut settings.reef,
            rects,
        ));
        super::reef_panel::minds_ui(
            ui,
            &mut settings.reef.traits,
            &mut state.minds_kind,
            &state.reef_demo_habits,
            rects,
        );
    }
    if settings.scene == Scene::Learning {
        actions.extend(super::learning_panel::learning_controls_ui(
            ui,
            &mut settings.learning,
            rects,
        ));
    }

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
        let csv = ui
            .button("Download data (CSV)")
            .on_hover_text("Save the numbers of the last minutes as a table for a spreadsheet");
        rects.insert("export_csv", csv.rect);
        if csv.clicked() {
            actions.push(PanelAction::ExportCsv);
        }
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

/// The boid scene's controls: compare, vision, which tank, its sliders and tools.
fn boids_ui(
    ui: &mut egui::Ui,
    settings: &mut Settings,
    state: &mut PanelState,
    rects: &mut WidgetRects,
    actions: &mut Vec<PanelAction>,
) {
    ui.separator();
    ui.horizontal_wrapped(|ui| {
        let compare = ui
            .checkbox(&mut settings.compare, "Compare two tanks")
            .on_hover_text(
                "Show two tanks side by side with the same fish at the same start. \
             Give them different urges and see how differently they behave.",
            );
        rects.insert("compare", compare.rect);
        let vision = ui
            .checkbox(&mut settings.show_vision, "Show vision")
            .on_hover_text(
                "Draw what each fish can see: its field of view and lines to the \
                 neighbours it notices",
            );
        rects.insert("show_vision", vision.rect);
    });
    if !settings.compare {
        state.edit_side = Side::Left;
    } else {
        ui.horizontal(|ui| {
            ui.label("Edit:");
            for side in Side::BOTH {
                let label = match side {
                    Side::Left => "Left tank",
                    Side::Right => "Right tank",
                };
                let response = ui
                    .selectable_value(&mut state.edit_side, side, label)
                    .on_hover_text("Choose which tank the controls below change");
                rects.insert(&format!("edit_{}", side.name()), response.rect);
            }
        });
    }
    ui.add_space(4.0);
    tank_ui(ui, settings.tank_mut(state.edit_side), rects);

    ui.add_space(4.0);
    ui.label(egui::RichText::new("Rocks").strong())
        .on_hover_text("Change the rocks in the tank with the mouse");
    ui.horizontal_wrapped(|ui| {
        for tool in EditTool::ALL {
            let response = ui
                .selectable_value(&mut state.tool, tool, tool.label())
                .on_hover_text(tool.help());
            rects.insert(tool.name(), response.rect);
        }
    });
    ui.label(egui::RichText::new(state.tool.help()).small().weak());
    let restore = ui
        .add_enabled(
            settings.tank(state.edit_side).obstacles.is_some(),
            egui::Button::new("Restore the seed's rocks"),
        )
        .on_hover_text("Undo all rock changes in this tank");
    rects.insert("restore_rocks", restore.rect);
    if restore.clicked() {
        actions.push(PanelAction::RestoreObstacles);
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
