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

/// The words of the side panel of every scene, as a screen reader reads them
/// (names and hover help), in `lang`.
fn side_panel_words(lang: crate::i18n::Lang) -> Vec<(Scene, String)> {
    crate::i18n::with_lang(lang, || {
        let mut words = Vec::new();
        for scene in Scene::ALL {
            let mirror = side_panel_mirror(scene);
            for item in &mirror.items {
                words.push((scene, item.name.trim().to_owned()));
                if let Some(description) = &item.description {
                    words.push((scene, description.trim().to_owned()));
                }
            }
        }
        words
    })
}

#[test]
fn every_word_of_every_side_panel_changes_with_the_language() {
    use crate::i18n::Lang;
    use std::collections::BTreeSet;
    let english: BTreeSet<String> = side_panel_words(Lang::En)
        .into_iter()
        .map(|(_, w)| w)
        .collect();
    // Words both languages write alike (a name, an abbreviation, a number).
    let en = crate::i18n::tests::texts(Lang::En);
    let es = crate::i18n::tests::texts(Lang::Es);
    let alike: BTreeSet<&String> = en
        .iter()
        .filter(|(id, text)| es.get(*id) == Some(text))
        .map(|(_, text)| text)
        .collect();
    let words = |w: &str| {
        w.split(|c: char| !c.is_alphabetic())
            .filter(|w| w.chars().count() >= 2)
            .count()
    };
    // While some files' words are not yet in the catalogue (`NOT_YET`, whose
    // words the lint does not read yet), only the catalogue's words are held
    // to this; once it is empty, every word on the panels is.
    let catalogued: BTreeSet<&String> = en.values().collect();
    let whole = crate::i18n::tests::NOT_YET.is_empty();
    // A language's name in itself, the same whichever language is shown.
    let own_names: Vec<&str> = Lang::ALL.iter().map(|l| l.native_name()).collect();
    // A scene whose own panel is still in `NOT_YET` waits for it.
    let waiting = |scene: &Scene| {
        crate::i18n::tests::NOT_YET.contains(&format!("ui/{}_panel.rs", scene.name()).as_str())
    };
    let untranslated: BTreeSet<String> = side_panel_words(Lang::Es)
        .into_iter()
        .filter(|(scene, _)| !waiting(scene))
        .filter(|(_, w)| {
            english.contains(w)
                && (whole || catalogued.contains(w))
                && words(w) > 0
                && !alike.contains(w)
                && !own_names.contains(&w.as_str())
        })
        .map(|(scene, w)| format!("{scene:?}: {w}"))
        .collect();
    assert!(
        untranslated.is_empty(),
        "{} words of the side panels stay English in Spanish:\n{}",
        untranslated.len(),
        untranslated.into_iter().collect::<Vec<_>>().join("\n")
    );
}

#[test]
fn the_language_picker_changes_every_word_without_a_mouse() {
    use crate::i18n::Lang;
    crate::i18n::with_lang(Lang::En, || {
        let mut harness = Harness::new(Scene::Boids);
        let mirror = harness.frame();
        assert!(mirror.control("Reset").is_some());
        assert!(mirror.control("English").is_some());
        harness.click(&mirror, "Español");
        harness.frame();
        assert_eq!(crate::i18n::lang(), Lang::Es);
        let mirror = harness.frame();
        assert!(
            mirror.control("Reiniciar").is_some() && mirror.control("Reset").is_none(),
            "the panel speaks Spanish: {:?}",
            mirror.controls().map(|i| &i.name).collect::<Vec<_>>()
        );
        assert_eq!(
            mirror.control("Español").map(|i| &i.kind),
            Some(&Kind::Button {
                pressed: Some(true)
            })
        );
    });
}

#[test]
fn a_drop_down_opens_and_chooses_from_a_screen_reader() {
    let ctx = egui::Context::default();
    ctx.enable_accesskit();
    let mut pending = Vec::new();
    let mut choice = 0;
    let mut mirror = Mirror::default();
    let press = |mirror: &Mirror, pending: &mut Vec<egui::Event>, name: &str| {
        let item = mirror
            .items
            .iter()
            .find(|i| i.name == name)
            .unwrap_or_else(|| panic!("no {name} in {:?}", mirror.items));
        pending.push(egui::Event::AccessKitActionRequest(
            egui::accesskit::ActionRequest {
                action: egui::accesskit::Action::Click,
                target_tree: egui::accesskit::TreeId::ROOT,
                target_node: egui::accesskit::NodeId(item.id),
                data: None,
            },
        ));
    };
    for frame in 0..8 {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(800.0, 600.0),
            )),
            time: Some(f64::from(frame) / 60.0),
            events: std::mem::take(&mut pending),
            ..Default::default()
        };
        let mut output = ctx.run_ui(input, |ui| {
            egui::ComboBox::from_id_salt("levels")
                .selected_text(format!("level {choice}"))
                .show_ui(ui, |ui| {
                    for i in 0..3 {
                        ui.selectable_value(&mut choice, i, format!("level {i}"));
                    }
                })
                .response
                .accessible_name("Levels");
        });
        output.textures_delta.clear();
        if let Some(update) = output.platform_output.accesskit_update {
            mirror = Mirror::from_update(&update);
        }
        match frame {
            1 => press(&mirror, &mut pending, "Levels"),
            4 => {
                assert!(matches!(
                    mirror.control("Levels").map(|i| &i.kind),
                    Some(Kind::ComboBox { expanded: true, .. })
                ));
                press(&mirror, &mut pending, "level 2");
            }
            _ => {}
        }
    }
    assert_eq!(choice, 2, "the option chosen through the mirror");
}
