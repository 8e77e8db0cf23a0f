//! The mirror read from the real side panel of every scene: every control has
//! a name, a role a screen reader knows, and a slider its value and range.

use eframe::egui;

use super::mirror::{Item, Kind, Mirror};
use crate::lab::Lab;
use crate::scenes::CurrentPanel;
use crate::settings::{Scene, Settings};
use crate::ui::WidgetRects;
use crate::ui::{ViewOptions, control_panel_ui};

/// Draws the side panel of `scene` for a few frames, as the app does, with
/// egui's accessibility tree on, and returns the mirror of the last frame.
pub(crate) fn side_panel_mirror(scene: Scene) -> Mirror {
    let mut settings = Settings {
        scene,
        ..Settings::default()
    };
    let lab = Lab::new(settings.clone());
    let mut panel = CurrentPanel::new(scene);
    let ctx = egui::Context::default();
    ctx.enable_accesskit();
    let mut view = ViewOptions {
        interface_scale: None,
        current_scale: 1.0,
        detail_auto: true,
        detail_scale: 1.0,
    };
    let mut mirror = Mirror::default();
    for frame in 0..3 {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1280.0, 2400.0),
            )),
            time: Some(f64::from(frame) / 60.0),
            ..Default::default()
        };
        let mut rects = WidgetRects::new();
        let mut output = ctx.run_ui(input, |ui| {
            egui::Panel::left("controls").show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    control_panel_ui(
                        ui,
                        &mut settings,
                        &mut panel,
                        lab.step_secs(),
                        &mut view,
                        &mut rects,
                    );
                });
            });
        });
        output.textures_delta.clear();
        let update = output
            .platform_output
            .accesskit_update
            .expect("egui sends its tree once asked to");
        mirror = Mirror::from_update(&update);
    }
    mirror
}

fn describe(item: &Item) -> String {
    format!("{:?} {:?}", item.kind, item.name)
}

#[test]
fn every_control_of_every_scene_has_a_name_and_a_role() {
    for scene in Scene::ALL {
        let mirror = side_panel_mirror(scene);
        let controls: Vec<&Item> = mirror.controls().collect();
        assert!(
            controls.len() > 10,
            "{scene:?}: only {} controls: {:?}",
            controls.len(),
            controls.iter().map(|i| describe(i)).collect::<Vec<_>>()
        );
        for item in &controls {
            assert!(
                !item.name.trim().is_empty(),
                "{scene:?}: a control without a name: {}",
                describe(item)
            );
            assert!(
                item.bounds.is_some(),
                "{scene:?}: {} has no place",
                describe(item)
            );
            // A name is what is on screen next to it, not its hover help.
            assert!(
                item.name.chars().count() <= 48,
                "{scene:?}: a control named by its hover help: {}",
                describe(item)
            );
        }
        // Every scene tab is a button that says whether it is the one shown.
        for other in Scene::ALL {
            let label = other.class().facts().label;
            let tab = mirror
                .control(label)
                .unwrap_or_else(|| panic!("{scene:?}: no tab named {label}"));
            assert_eq!(
                tab.kind,
                Kind::Button {
                    pressed: Some(other == scene)
                },
                "{scene:?}: the {label} tab"
            );
        }
        assert!(
            mirror.control("Reset").is_some(),
            "{scene:?}: no Reset button"
        );
    }
}

#[test]
fn every_slider_says_its_value_and_range() {
    for scene in Scene::ALL {
        let mirror = side_panel_mirror(scene);
        let sliders: Vec<&Item> = mirror
            .controls()
            .filter(|i| matches!(i.kind, Kind::Slider { .. }))
            .collect();
        assert!(!sliders.is_empty(), "{scene:?} has no slider");
        for item in sliders {
            let Kind::Slider {
                value, min, max, ..
            } = item.kind
            else {
                unreachable!()
            };
            assert!(
                min < max,
                "{scene:?}: {} has an empty range",
                describe(item)
            );
            assert!(
                (min..=max).contains(&value),
                "{scene:?}: {} is outside its range",
                describe(item)
            );
        }
    }
}

#[test]
fn the_schooling_labs_force_sliders_are_named_as_on_screen() {
    let mirror = side_panel_mirror(Scene::Boids);
    for name in ["Alignment", "Cohesion", "Separation"] {
        let found = mirror
            .controls()
            .find(|i| i.name.starts_with(name))
            .unwrap_or_else(|| {
                panic!(
                    "no control named {name}: {:?}",
                    mirror.controls().map(describe).collect::<Vec<_>>()
                )
            });
        assert!(
            matches!(found.kind, Kind::Slider { .. }),
            "{name}: {}",
            describe(found)
        );
    }
}

#[test]
#[ignore = "prints the mirror for a look"]
fn print_the_mirrors() {
    for scene in Scene::ALL {
        let mirror = side_panel_mirror(scene);
        println!("== {scene:?}");
        for item in &mirror.items {
            println!(
                "  {:?} {:?} | {:?}",
                item.kind,
                item.name,
                item.description
                    .as_deref()
                    .map(|d| d.chars().take(40).collect::<String>())
            );
        }
    }
}
