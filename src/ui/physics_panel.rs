//! The "Physics fish" controls (how many fish, how they steer, the current, the
//! overlays, the selected fish and its hand command) and the selected fish's live
//! plots: its twelve muscle contractions and its speed.

use eframe::egui;
use egui_plot::{Line, PlotPoints};

use super::WidgetRects;
use super::body_overlay;
use super::bottom_panel::time_plot;
use super::bottom_panel::{plot_height_under_caption, show_bottom_panel};
use super::scene_panel::{Notice, ScenePanel, ViewContext, ViewInput};
use super::setting_slider::{setting_row, setting_row_with};
use super::studio_panel::{control, control_block, is_hidden};
use crate::i18n::{Lang, ts, with_lang};
use crate::lab::{BODY_TRACE_SECS, Lab, Run};
use crate::settings::Settings;
use crate::settings::physics::PhysicsSettings;
use crate::sim::PhysicsBehaviour;
use crate::sim::body::body_layout::muscle_index;
use crate::sim::body::{MuscleSegment, Side};
use crate::tr;

/// The physics scene's section of the control panel. Returns the turn, degrees,
/// the teacher asked the selected fish to make.
fn physics_controls_ui(
    ui: &mut egui::Ui,
    physics: &mut PhysicsSettings,
    rects: &mut WidgetRects,
) -> Option<f32> {
    let mut turn = None;
    ui.separator();
    ui.label(egui::RichText::new(ts("physics-title")).strong());
    egui::Grid::new("physics_grid")
        .num_columns(2)
        .spacing([8.0, 6.0])
        .show(ui, |ui| {
            for count in [PhysicsSettings::FISH_COUNT, PhysicsSettings::SHARKS] {
                setting_row(ui, rects, PhysicsSettings::PREFIX, &count, physics);
            }
            setting_row(
                ui,
                rects,
                PhysicsSettings::PREFIX,
                &PhysicsSettings::CURRENT_M_PER_S,
                physics,
            );
        });

    if !is_hidden(ui, "physics.behaviour") {
        ui.label(ts("physics-behaviour"));
    }
    control_block(
        ui,
        rects,
        "physics.behaviour",
        ts("physics-behaviour.block"),
        |ui, rects| {
            for behaviour in PhysicsBehaviour::ALL {
                let radio = ui
                    .radio_value(&mut physics.behaviour, behaviour, behaviour.label())
                    .on_hover_text(behaviour.explanation());
                // The widget's name stays English whatever the screen shows.
                let name = with_lang(Lang::En, || behaviour.label().to_lowercase());
                rects.insert(&format!("physics_{name}"), radio.rect);
            }
            ui.label(egui::RichText::new(physics.behaviour.explanation()).weak());
        },
    );

    ui.add_space(4.0);
    control(ui, rects, "physics.show_body", |ui, rects| {
        let body = ui
            .checkbox(&mut physics.show_body, ts("physics-show-body"))
            .on_hover_text(ts("physics-show-body.help"));
        rects.insert("show_body", body.rect);
    });
    control(ui, rects, "physics.show_forces", |ui, rects| {
        let forces = ui
            .checkbox(&mut physics.show_forces, ts("physics-show-forces"))
            .on_hover_text(ts("physics-show-forces.help"));
        rects.insert("show_forces", forces.rect);
    });

    ui.separator();
    match physics.selected {
        None => {
            ui.label(egui::RichText::new(ts("physics-selected-fish")).strong());
            ui.label(egui::RichText::new(ts("physics-selected-fish.help")).weak());
        }
        Some(index) => {
            ui.horizontal(|ui| {
                ui.label(
                    egui::RichText::new(if index < physics.fish_count {
                        tr!("physics-selected-a-fish", index = index)
                    } else {
                        tr!("physics-selected-a-shark", index = index)
                    })
                    .strong(),
                );
                let clear = ui
                    .small_button(ts("physics-deselect"))
                    .on_hover_text(ts("physics-deselect.help"));
                rects.insert("deselect", clear.rect);
                if clear.clicked() {
                    physics.selected = None;
                    physics.hand_control = false;
                    physics.follow = false;
                }
            });
            if physics.selected.is_some() {
                selected_fish_ui(ui, physics, rects, &mut turn);
            }
        }
    }
    turn
}

fn selected_fish_ui(
    ui: &mut egui::Ui,
    physics: &mut PhysicsSettings,
    rects: &mut WidgetRects,
    turn_asked: &mut Option<f32>,
) {
    control(ui, rects, "physics.follow", |ui, rects| {
        let follow = ui
            .checkbox(&mut physics.follow, ts("physics-follow"))
            .on_hover_text(ts("physics-follow.help"));
        rects.insert("follow", follow.rect);
    });
    control(ui, rects, "physics.hand_control", |ui, rects| {
        let hand = ui
            .checkbox(&mut physics.hand_control, ts("physics-hand"))
            .on_hover_text(ts("physics-hand.help"));
        rects.insert("hand_control", hand.rect);
    });
    ui.add_enabled_ui(physics.hand_control, |ui| {
        egui::Grid::new("hand_grid")
            .num_columns(2)
            .spacing([8.0, 6.0])
            .show(ui, |ui| {
                for hand in [PhysicsSettings::HAND_SPEED, PhysicsSettings::HAND_PITCH_DEG] {
                    setting_row(ui, rects, PhysicsSettings::PREFIX, &hand, physics);
                }
                setting_row_with(
                    ui,
                    rects,
                    PhysicsSettings::PREFIX,
                    &PhysicsSettings::TURN_ANGLE_DEG,
                    physics,
                    |ui, rects, physics| {
                        let left = physics.turn_angle_deg >= 0.0;
                        let turn = ui
                            .button(if left {
                                ts("physics-turn-left")
                            } else {
                                ts("physics-turn-right")
                            })
                            .on_hover_text(ts("physics-turn-help"));
                        rects.insert("turn", turn.rect);
                        if turn.clicked() {
                            *turn_asked = Some(physics.turn_angle_deg);
                        }
                    },
                );
            });
    });
}

/// How the muscles of one side of the fish are drawn in its plots: the left
/// side solid vermillion, the right dashed blue (Okabe–Ito).
fn muscle_side_style(side: Side) -> (egui::Color32, egui_plot::LineStyle) {
    match side {
        Side::Left => (super::palette::VERMILLION, egui_plot::LineStyle::Solid),
        Side::Right => (
            super::palette::SKY_BLUE,
            egui_plot::LineStyle::dashed_dense(),
        ),
    }
}

/// "left" or "right".
fn side_word(side: Side) -> &'static str {
    match side {
        Side::Left => ts("physics-side-left"),
        Side::Right => ts("physics-side-right"),
    }
}

/// The height the panel under the tank would like for the selected fish's plots,
/// points (see [`super::bottom_panel::bottom_panel_height`] for what it gets).
pub const BODY_PLOTS_PANEL_HEIGHT: f32 = 180.0;

/// The selected fish's muscles (three plots, one per body segment, four muscles
/// each) and speed over the last [`BODY_TRACE_SECS`], in `content_height` points:
/// a caption row and a plot under it, whatever the plots hold. (The plots once took
/// the panel's available height, the panel took the plots' height and a margin,
/// and the panel grew every frame: issue 14.)
pub fn body_plots_ui(
    ui: &mut egui::Ui,
    run: &Run,
    selected: Option<u32>,
    content_height: f32,
    rects: &mut WidgetRects,
) {
    let Some(index) = selected else {
        ui.vertical_centered(|ui| {
            ui.label(egui::RichText::new(ts("physics-plots-hint")).weak());
        });
        return;
    };
    let trace = run.body_trace();
    let now = trace.back().map_or(0.0, |s| s.time_secs);
    let start = now - BODY_TRACE_SECS;
    let segments = [
        (MuscleSegment::Anterior, ts("physics-muscles-front")),
        (MuscleSegment::Middle, ts("physics-muscles-middle")),
        (MuscleSegment::Posterior, ts("physics-muscles-tail")),
    ];
    let spacing = ui.spacing().item_spacing;
    let width = (ui.available_width() - 3.0 * spacing.x) / 4.0;
    // Each caption is a row of the standard height, so every plot gets the same.
    let caption_height = ui.spacing().interact_size.y;
    let plot_height = plot_height_under_caption(content_height, caption_height, spacing.y);
    ui.horizontal(|ui| {
        for (k, (segment, title)) in segments.into_iter().enumerate() {
            ui.vertical(|ui| {
                ui.set_width(width);
                ui.horizontal(|ui| {
                    ui.set_height(caption_height);
                    ui.label(egui::RichText::new(title).small());
                    // Each side's name with a sample of its line: solid and
                    // dashed tell them apart without the colour.
                    for side in [Side::Left, Side::Right] {
                        let (color, line) = muscle_side_style(side);
                        ui.label(
                            egui::RichText::new(format!(
                                "{} {}",
                                super::palette::line_glyph(line),
                                side_word(side)
                            ))
                            .small()
                            .color(color),
                        );
                    }
                })
                .response
                .on_hover_text(ts("physics-muscles.help"));
                let plot = time_plot(("muscles", index, k), plot_height)
                    .include_y(0.0)
                    .include_y(1.0)
                    .include_x(start)
                    .include_x(now)
                    .show(ui, |plot| {
                        for side in [Side::Left, Side::Right] {
                            for (offset, part) in
                                [(0, "physics-muscle-top"), (1, "physics-muscle-bottom")]
                            {
                                let m = muscle_index(segment, side) + offset;
                                let points: PlotPoints = trace
                                    .iter()
                                    .map(|s| [s.time_secs, f64::from(s.muscles[m])])
                                    .collect();
                                let (color, line) = muscle_side_style(side);
                                plot.line(
                                    Line::new(tr!(part, side = side_word(side)), points)
                                        .color(color)
                                        .style(line)
                                        .width(if offset == 0 { 2.0 } else { 1.2 }),
                                );
                            }
                        }
                    });
                rects.insert(&format!("muscle_plot_{k}"), plot.response.rect);
            });
        }
        ui.vertical(|ui| {
            ui.set_width(width);
            ui.horizontal(|ui| {
                ui.set_height(caption_height);
                ui.label(egui::RichText::new(ts("physics-speed")).small())
                    .on_hover_text(ts("physics-speed.help"));
            });
            let plot = time_plot(("speed", index), plot_height)
                .include_y(0.0)
                .include_x(start)
                .include_x(now)
                .show(ui, |plot| {
                    let points: PlotPoints = trace
                        .iter()
                        .map(|s| [s.time_secs, f64::from(s.speed_m_per_s)])
                        .collect();
                    plot.line(
                        Line::new(ts("physics-speed-line"), points).color(egui::Color32::WHITE),
                    );
                });
            rects.insert("speed_plot", plot.response.rect);
        });
    });
}

/// The physics scene's panel: its controls, the selected fish's plots under the
/// tank, the skeletons and forces over it, and picking a fish with a click.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PhysicsPanel {
    /// The turn the teacher asked the selected fish to make this frame, degrees.
    turn_asked: Option<f32>,
}

impl ScenePanel for PhysicsPanel {
    fn offers_experiment(&self) -> bool {
        true
    }

    fn controls_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings, rects: &mut WidgetRects) {
        self.turn_asked = physics_controls_ui(ui, &mut settings.physics, rects);
    }

    fn bottom_ui(
        &mut self,
        ui: &mut egui::Ui,
        lab: &Lab,
        _settings: &mut Settings,
        rects: &mut WidgetRects,
    ) {
        let run = &lab.runs()[0];
        // The plots need a selected fish; until then one line says how to get them.
        match lab.settings().physics.selected {
            Some(selected) => {
                show_bottom_panel(
                    ui,
                    "body_plots",
                    BODY_PLOTS_PANEL_HEIGHT,
                    rects,
                    |ui, height, rects| body_plots_ui(ui, run, Some(selected), height, rects),
                );
            }
            None => {
                // One line of text: the panel takes the line's height, which does not
                // depend on the panel's.
                let hint = egui::Panel::bottom("body_plots_hint")
                    .resizable(false)
                    .show(ui, |ui| {
                        let height = ui.available_height();
                        body_plots_ui(ui, run, None, height, rects);
                    });
                rects.insert("panel_body_plots_hint", hint.response.rect);
            }
        }
    }

    fn draw_overlays(&self, view: &ViewContext, settings: &Settings, rects: &mut WidgetRects) {
        let physics = &settings.physics;
        let (painter, rect, camera, run, alpha) =
            (view.painter, view.rect, view.camera, view.run, view.alpha);
        if physics.show_body {
            body_overlay::draw_skeletons(painter, rect, camera, run, alpha, physics.selected);
        }
        if physics.show_forces {
            body_overlay::draw_forces(painter, rect, camera, run, alpha, physics.selected);
        }
        if let Some(selected) = physics.selected {
            body_overlay::draw_selection(painter, rect, camera, run, alpha, selected);
        }
        body_overlay::record_animal_rects(view, rects);
    }

    /// A click on a fish selects it; a click on open water lets go, unless the
    /// fish is being steered by hand.
    fn view_input(&mut self, input: &ViewInput, settings: &mut Settings) -> Option<Notice> {
        let picked = body_overlay::clicked_animal(input)?;
        let physics = &mut settings.physics;
        // While steering by hand a click that misses every fish (easily done on
        // a moving one) keeps the steering; *Deselect* lets go.
        if picked.is_none() && physics.hand_control {
            return None;
        }
        physics.selected = picked;
        if picked.is_none() {
            physics.hand_control = false;
            physics.follow = false;
        }
        None
    }

    fn apply(&mut self, lab: &mut Lab, _ctx: &egui::Context) -> Option<Notice> {
        let angle_deg = self.turn_asked.take()?;
        lab.turn_selected(angle_deg)
            .err()
            .map(|err| Notice::error(err.to_string()))
    }

    fn followed(&self, settings: &Settings) -> Option<u32> {
        settings
            .physics
            .selected
            .filter(|_| settings.physics.follow)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::studio::Studio;
    use serde_json::json;

    /// Draws the physics controls, fish 2 selected and steered by hand, under
    /// `studio`, and returns the widgets drawn.
    fn draw(studio: &Studio) -> WidgetRects {
        let mut physics = PhysicsSettings {
            selected: Some(2),
            hand_control: true,
            ..PhysicsSettings::default()
        };
        super::super::studio_panel::draw_controls_for_test(studio, false, |ui, rects| {
            physics_controls_ui(ui, &mut physics, rects);
        })
        .0
    }

    #[test]
    fn the_selected_fish_controls_follow_the_studio_rules() {
        let free = draw(&Studio::default());
        for name in ["follow", "hand_control", "hand_speed", "hand_pitch", "turn"] {
            assert!(free.get(name).is_some(), "{name} drawn without rules");
        }
        let mut settings = Settings::default();
        settings
            .apply_patch(&json!({"studio": {"student_view": true, "rules": {
                "physics.hand_pitch_deg": {"hidden": true},
                "physics.hand_speed": {"mystery": true},
                "physics.follow": {"locked": true},
                "physics.turn_angle_deg": {"hidden": true}
            }}}))
            .unwrap();
        let student = draw(&settings.studio);
        assert!(student.get("hand_pitch").is_none(), "hidden");
        assert!(student.get("turn").is_none(), "hidden with its row");
        assert!(
            student.get("hand_speed").is_none(),
            "a mystery shows no slider"
        );
        assert!(student.get("mystery_physics.hand_speed").is_some());
        assert!(student.get("locked_physics.follow").is_some(), "greyed");
        assert!(student.get("hand_control").is_some(), "a free control");
    }
}
