//! The mirror read from the real side panel of every scene: every control has
//! a name, a role a screen reader knows, and a slider its value and range.

use eframe::egui;

use super::mirror::{Item, Kind, Mirror};
use crate::lab::Lab;
use crate::scenes::CurrentPanel;
use crate::settings::{Scene, Settings};
use crate::ui::WidgetRects;
use crate::ui::{ViewOptions, control_panel_ui};

/// A rock button's step, as the panel moves it.
const ROCK_STEP: f32 = 0.5;

/// The side panel as a screen reader drives it: each frame draws the panel
/// as the app does (the scene's panel refreshed from the lab first) with
/// egui's accessibility tree on; actions on the mirror's items go to egui in
/// the next frame's input, as the page's elements send them.
pub(crate) struct Harness {
    ctx: egui::Context,
    pub lab: Lab,
    pub settings: Settings,
    panel: CurrentPanel,
    pending: Vec<egui::Event>,
    frame: u32,
    /// The notices the panel gave, oldest first.
    pub notices: Vec<String>,
}

impl Harness {
    pub fn new(scene: Scene) -> Self {
        let settings = Settings {
            scene,
            ..Settings::default()
        };
        let ctx = egui::Context::default();
        ctx.enable_accesskit();
        Self {
            ctx,
            lab: Lab::new(settings.clone()),
            settings,
            panel: CurrentPanel::new(scene),
            pending: Vec::new(),
            frame: 0,
            notices: Vec::new(),
        }
    }

    /// One frame; the settings the panel changed are applied to the lab.
    pub fn frame(&mut self) -> Mirror {
        self.frame += 1;
        let time = f64::from(self.frame) / 60.0;
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1280.0, 2400.0),
            )),
            time: Some(time),
            events: std::mem::take(&mut self.pending),
            ..Default::default()
        };
        let mut view = ViewOptions {
            interface_scale: None,
            current_scale: 1.0,
            detail_auto: true,
            detail_scale: 1.0,
        };
        let mut rects = WidgetRects::new();
        let scene = self.settings.scene;
        if let Some(notice) =
            self.panel
                .for_scene(scene)
                .before_frame(&mut self.lab, time, &self.ctx)
        {
            self.notices.push(notice.text);
        }
        let step_secs = self.lab.step_secs();
        let (settings, panel) = (&mut self.settings, &mut self.panel);
        let mut output = self.ctx.run_ui(input, |ui| {
            egui::Panel::left("controls").show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    control_panel_ui(ui, settings, panel, step_secs, &mut view, &mut rects);
                });
            });
        });
        output.textures_delta.clear();
        if &self.settings != self.lab.settings() {
            self.lab.apply_settings(self.settings.clone());
        }
        self.lab.step(1);
        let update = output
            .platform_output
            .accesskit_update
            .expect("egui sends its tree once asked to");
        Mirror::from_update(&update)
    }

    /// Presses the control named `name` in `mirror`, as a screen reader does.
    pub fn click(&mut self, mirror: &Mirror, name: &str) {
        let item = mirror
            .control(name)
            .unwrap_or_else(|| panic!("no control named {name}"));
        self.pending.push(egui::Event::AccessKitActionRequest(
            egui::accesskit::ActionRequest {
                action: egui::accesskit::Action::Click,
                target_tree: egui::accesskit::TreeId::ROOT,
                target_node: egui::accesskit::NodeId(item.id),
                data: None,
            },
        ));
    }
}

/// Draws the side panel of `scene` for a few frames, as the app does, with
/// egui's accessibility tree on, and returns the mirror of the last frame.
pub(crate) fn side_panel_mirror(scene: Scene) -> Mirror {
    let mut harness = Harness::new(scene);
    let mut mirror = Mirror::default();
    for _ in 0..3 {
        mirror = harness.frame();
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
            let label = other.class().facts().label();
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
fn a_rock_is_added_moved_and_removed_without_a_mouse() {
    let mut lab = Harness::new(Scene::Boids);
    lab.frame();
    let mut mirror = lab.frame();
    let rocks_at_first = lab.lab.scene().obstacles().len();
    lab.click(&mirror, "Add rock");
    mirror = lab.frame();
    lab.click(&mirror, "Add a rock in the middle");
    lab.frame();

    mirror = lab.frame();
    let rocks = lab.lab.scene().obstacles().to_vec();
    assert_eq!(
        rocks.len(),
        rocks_at_first + 1,
        "a rock added: {:?}",
        lab.notices
    );
    let added = rocks.last().unwrap().footprint_center_m();

    lab.click(&mirror, "Move rock");
    mirror = lab.frame();
    // The buttons act on the new rock (the last one picked): move it right.
    let here = mirror
        .items
        .iter()
        .find(|i| i.name.starts_with("Rock "))
        .map(|i| i.name.clone())
        .expect("the rock's place in words");
    assert!(
        here.starts_with(&format!("Rock {} of {}", rocks.len(), rocks.len())),
        "{here}"
    );
    // Each arrow moves it one step that way, or says why it cannot.
    let mut moves = 0;
    for (direction, step) in [
        ("right", glam::Vec2::new(ROCK_STEP, 0.0)),
        ("left", glam::Vec2::new(-ROCK_STEP, 0.0)),
        ("front", glam::Vec2::new(0.0, ROCK_STEP)),
        ("back", glam::Vec2::new(0.0, -ROCK_STEP)),
    ] {
        let before = lab
            .lab
            .scene()
            .obstacles()
            .last()
            .unwrap()
            .footprint_center_m();
        let notices = lab.notices.len();
        lab.click(&mirror, &format!("Move the rock {direction}"));
        lab.frame();
        mirror = lab.frame();
        let after = lab
            .lab
            .scene()
            .obstacles()
            .last()
            .unwrap()
            .footprint_center_m();
        if lab.notices.len() > notices {
            assert_eq!(after, before, "{direction}: refused, and nothing moved");
        } else {
            assert!(
                (after - before - step).length() < 1e-4,
                "{direction}: {before} -> {after}"
            );
            moves += 1;
        }
    }
    assert!(
        moves >= 2,
        "the rock moved {moves} times: {:?}",
        lab.notices
    );
    let _ = added;

    lab.click(&mirror, "Remove");
    mirror = lab.frame();
    lab.click(&mirror, "Remove this rock");
    lab.frame();
    lab.frame();
    assert_eq!(
        lab.lab.scene().obstacles().len(),
        rocks_at_first,
        "the rock removed"
    );
}
