//! The catalogue's tests: every scene's facts agree with its world, every
//! scene gets its own panel, and no code outside the scenes' own files names
//! a scene.

use eframe::egui;

use super::*;
use crate::lab::Lab;
use crate::ui::WidgetRects;

/// Draws each scene's side-panel section and panel under the tank for a few
/// frames through its class's panel, as the app does, and returns the widget
/// rectangles of the last frame.
fn draw_scene(scene: Scene) -> WidgetRects {
    let mut settings = Settings {
        scene,
        ..Settings::default()
    };
    let mut lab = Lab::new(settings.clone());
    let mut current = CurrentPanel::new(Scene::Aquarium);
    let ctx = egui::Context::default();
    let mut rects = WidgetRects::new();
    for frame in 0..3 {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1280.0, 800.0),
            )),
            time: Some(f64::from(frame) / 60.0),
            ..Default::default()
        };
        rects.clear();
        let mut output = ctx.run_ui(input, |ui| {
            let panel = current.for_scene(scene);
            panel.before_frame(&mut lab, f64::from(frame) / 60.0, ui.ctx());
            panel.bottom_ui(ui, &lab, &mut settings, &mut rects);
            egui::Panel::left("controls").show(ui, |ui| {
                panel.controls_ui(ui, &mut settings, &mut rects);
            });
        });
        output.textures_delta.clear();
        lab.step(1);
    }
    rects
}

#[test]
fn every_scene_gets_its_own_controls_and_panel_under_the_tank() {
    // (scene, a control of its own, its panel under the tank)
    let expected = [
        (Scene::Aquarium, "fish_count", None),
        (Scene::Boids, "compare", Some("panel_metrics")),
        (
            Scene::Physics,
            "physics_fish",
            Some("panel_body_plots_hint"),
        ),
        (Scene::Reef, "reef_prey", Some("panel_reef_inspector")),
        (
            Scene::Learning,
            "learning_train",
            Some("panel_learning_plots"),
        ),
    ];
    // (The schooling lab's tank controls have a fish count too.)
    let own: Vec<&str> = expected.iter().skip(1).map(|e| e.1).collect();
    for (scene, control, bottom) in expected {
        let rects = draw_scene(scene);
        assert!(rects.get(control).is_some(), "{scene:?} has no {control}");
        // No other scene's controls.
        for other in own.iter().filter(|o| **o != control) {
            assert!(rects.get(other).is_none(), "{scene:?} shows {other}");
        }
        let panels: Vec<&String> = rects
            .iter()
            .map(|(name, _)| name)
            .filter(|name| name.starts_with("panel_"))
            .collect();
        match bottom {
            Some(name) => assert_eq!(panels, [name], "{scene:?}"),
            None => assert!(panels.is_empty(), "{scene:?}: {panels:?}"),
        }
    }
}

#[test]
fn a_new_scene_gets_a_fresh_panel_and_the_same_scene_keeps_its_own() {
    let mut current = CurrentPanel::new(Scene::Boids);
    let address = |p: &mut dyn ScenePanel| (p as *mut dyn ScenePanel).cast::<()>() as usize;
    let first = address(current.for_scene(Scene::Boids));
    assert_eq!(address(current.for_scene(Scene::Boids)), first);
    current.for_scene(Scene::Reef);
    assert_eq!(current.scene, Scene::Reef);
}

#[test]
fn every_class_is_its_own_scene_and_agrees_with_the_world_it_builds() {
    for scene in Scene::ALL {
        let class = scene.class();
        assert_eq!(class.scene(), scene);
        let lab = Lab::new(Settings {
            scene,
            ..Settings::default()
        });
        let world = lab.scene();
        assert_eq!(world.dt_secs(), class.facts().clock.step_secs, "{scene:?}");
        assert_eq!(
            lab.runs()[0].sample_every_steps(),
            class.facts().clock.sample_every_steps
        );
        // A quarter of a second or so between samples in every scene.
        let every_secs =
            class.facts().clock.sample_every_steps as f64 * class.facts().clock.step_secs;
        assert!((0.2..=0.3).contains(&every_secs), "{scene:?}: {every_secs}");
        // The measures of a school where the world has one, none where not.
        let has_school = world.metrics().is_some();
        assert_eq!(has_school, !class.facts().measures.is_empty(), "{scene:?}");
        assert_eq!(
            has_school,
            world.school_mean_speed_m_per_s().is_some(),
            "{scene:?}"
        );
        if has_school {
            assert!(
                SCHOOL_MEASURES
                    .iter()
                    .all(|m| class.facts().measures.contains(m))
            );
        }
        assert!(class.facts().secs_per_animal_step > 0.0);
        // The counts a mystery hides are settings of the scene's own section
        // (or the compared right tank's).
        let section = format!("{}.", class.facts().settings_section);
        let settings_json = crate::experiment::design::settings_value(&Settings::default());
        for key in class.facts().count_keys {
            assert!(
                key.starts_with(&section) || key.starts_with("right."),
                "{scene:?}: {key}"
            );
            assert!(
                crate::experiment::design::value_at(&settings_json, key).is_some(),
                "{scene:?}: {key} is no setting"
            );
        }
        assert!(!class.acts("seedling.fish_count"));
        assert!(!class.facts().label().is_empty() && !class.facts().description().is_empty());
        assert!(!class.facts().about.what.is_empty());
    }
}

#[test]
fn the_aquarium_and_the_schooling_lab_differ_only_in_their_boid_tank() {
    let settings = Settings::default();
    let aquarium = Scene::Aquarium
        .class()
        .boid_tank(&settings, Side::Left)
        .expect("a boid tank");
    let school = Scene::Boids
        .class()
        .boid_tank(&settings, Side::Left)
        .expect("a boid tank");
    assert_eq!(aquarium.boids, None, "the aquarium's fish wander");
    assert!(
        school.boids.is_some(),
        "the schooling lab's fish heed urges"
    );
    assert_eq!(aquarium.config.fish_count, school.config.fish_count);
    assert_eq!(aquarium.config.seed, school.config.seed);
    for scene in [Scene::Physics, Scene::Reef, Scene::Learning] {
        assert!(scene.class().boid_tank(&settings, Side::Left).is_none());
    }
}

/// The source files (outside tests) that may name a scene, and why.
const MAY_NAME_A_SCENE: &[(&str, &str)] = &[
    (
        "src/sim/",
        "the simulation: the scene interface dispatches here",
    ),
    ("src/scenes/", "the catalogue: one file per scene"),
    (
        "src/ui/boids_panel.rs",
        "the aquarium's and schooling lab's panel",
    ),
    ("src/ui/boids_attention.rs", "the schooling lab's panel"),
    ("src/ui/tank_panel.rs", "the schooling lab's panel"),
    ("src/ui/metrics_panel.rs", "the schooling lab's panel"),
    ("src/ui/physics_panel.rs", "the physics tank's panel"),
    (
        "src/ui/body_overlay.rs",
        "the physics tank's and reef's panels",
    ),
    ("src/ui/reef_panel.rs", "the reef's panel"),
    ("src/ui/reef_inspector.rs", "the reef's panel"),
    ("src/ui/reef_minds.rs", "the reef's panel"),
    ("src/ui/reef_overlay.rs", "the reef's panel"),
    ("src/ui/reef_skip.rs", "the reef's panel"),
    ("src/ui/learning_panel.rs", "the learning lab's panel"),
    (
        "src/investigation/measure.rs",
        "the Learning to swim investigation races the learning lab's fish",
    ),
];

/// What names one scene: a variant of the settings' scene or of the world,
/// or a downcast to one scene's world.
fn names_a_scene(code: &str) -> Option<String> {
    let variants = ["Aquarium", "Boids", "Physics", "Reef", "Learning"];
    for prefix in ["Scene::", "SceneWorld::"] {
        for variant in variants {
            let name = format!("{prefix}{variant}");
            let named = code.match_indices(&name).any(|(at, _)| {
                let before = code[..at].chars().next_back();
                let after = code[at + name.len()..].chars().next();
                !before.is_some_and(|c| c.is_alphanumeric() || c == '_')
                    && !after.is_some_and(|c| c.is_alphanumeric() || c == '_')
            });
            if named {
                return Some(name);
            }
        }
    }
    [".boids()", ".physics()", ".reef()", ".learning()"]
        .into_iter()
        .find(|downcast| code.contains(downcast))
        .map(str::to_owned)
}

/// Every `.rs` file under `dir`.
fn rust_files(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
    let entries = std::fs::read_dir(dir).expect("a source folder");
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn no_code_outside_the_scenes_own_files_names_a_scene() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    assert!(files.len() > 100, "found {} files", files.len());
    let mut offenders = Vec::new();
    for path in files {
        let relative = path
            .strip_prefix(root)
            .expect("under the crate")
            .to_string_lossy()
            .replace('\\', "/");
        let name = relative.rsplit('/').next().unwrap_or_default();
        // Tests and measurement scripts set up the scene they are about.
        let is_test_file = name == "tests.rs"
            || name.ends_with("_tests.rs")
            || name == "census.rs"
            || relative.contains("/tests/");
        if is_test_file
            || MAY_NAME_A_SCENE
                .iter()
                .any(|(p, _)| relative.starts_with(p))
        {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("a readable source file");
        // The code, without its test module.
        let code = text.split("#[cfg(test)]").next().unwrap_or_default();
        if let Some(name) = names_a_scene(code) {
            offenders.push(format!("{relative} names {name}"));
        }
    }
    assert!(
        offenders.is_empty(),
        "a scene's facts belong to its class in src/scenes/ (or its panel):\n{}",
        offenders.join("\n")
    );
    // The check itself sees what it should.
    assert_eq!(
        names_a_scene("x == Scene::Reef"),
        Some("Scene::Reef".into())
    );
    assert_eq!(names_a_scene("ReefScene::Reef"), None);
    assert_eq!(names_a_scene("run.reef().unwrap()"), Some(".reef()".into()));
}

#[test]
fn the_keyboard_selects_and_follows_where_the_mouse_can() {
    for scene in Scene::ALL {
        let class = scene.class();
        let mut settings = Settings {
            scene,
            ..Settings::default()
        };
        class.select(&mut settings, Side::Left, Some(3));
        let picks = class.selected(&settings, Side::Left) == Some(3);
        // The scenes whose panel lets one click a fish.
        let clickable = matches!(scene, Scene::Boids | Scene::Physics | Scene::Reef);
        assert_eq!(picks, clickable, "{scene:?}");
        match class.toggle_camera_follow(&mut settings) {
            Some(on) => {
                assert!(on, "{scene:?}: F follows the selected fish");
                assert_eq!(class.toggle_camera_follow(&mut settings), Some(false));
                class.select(&mut settings, Side::Left, None);
                assert_eq!(
                    class.toggle_camera_follow(&mut settings),
                    Some(false),
                    "{scene:?}: nothing to follow"
                );
            }
            None => assert!(!matches!(scene, Scene::Physics | Scene::Reef), "{scene:?}"),
        }
    }
}
