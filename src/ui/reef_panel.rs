//! The "Reef" scene's panel: its controls (which demo, which body, the water,
//! overlays; the *Minds* section is in `reef_minds.rs`), the inspector under the
//! tank (`reef_inspector.rs`), what the selected fish sees drawn over the tank,
//! and picking and following a fish.

use eframe::egui;

use super::WidgetRects;
use super::bottom_panel::show_bottom_panel;
use super::reef_inspector::{FishEyeView, reef_inspector_height, reef_inspector_ui};
use super::reef_minds::minds_ui;
use super::reef_skip::SkipUi;
use super::scene_panel::{Notice, ScenePanel, ViewContext, ViewInput};
use super::setting_slider::setting_row;
use super::studio_panel::{control, control_row};
use super::{body_overlay, reef_overlay};
use crate::i18n::ts;
use crate::lab::{Lab, Run};
use crate::render::Framing;
use crate::render::orbit_camera::{DEFAULT_PITCH_RAD, DEFAULT_YAW_RAD};
use crate::settings::Settings;
use crate::settings::reef::{ReefOverlay, ReefSettings};
use crate::sim::reef::demos::ReefScene;
use crate::sim::reef::mind::{FishKind, Habits, Intention};
use crate::sim::reef::world::{ReefBodyKind, ReefWorld};
use crate::tr;

/// Colours of the three urges, used by the bars, the plot and the focus line
/// (Okabe–Ito orange, reddish purple and sky blue; the plot also draws them
/// solid, dashed and dotted, and names each).
pub const HUNGER_COLOR: egui::Color32 = super::palette::ORANGE;
pub const LIBIDO_COLOR: egui::Color32 = super::palette::REDDISH_PURPLE;
pub const FEAR_COLOR: egui::Color32 = super::palette::SKY_BLUE;

/// One sentence per intention, for the inspector.
pub fn intention_sentence(intention: Intention) -> &'static str {
    match intention {
        Intention::Avoid => ts("reef-intention-avoid"),
        Intention::Escape => ts("reef-intention-escape"),
        Intention::School => ts("reef-intention-school"),
        Intention::Eat => ts("reef-intention-eat"),
        Intention::Mate => ts("reef-intention-mate"),
        Intention::Leave => ts("reef-intention-leave"),
        Intention::Wander => ts("reef-intention-wander"),
    }
}

/// An intention in one word ("escape"), in the language in force.
pub fn intention_word(intention: Intention) -> &'static str {
    match intention {
        Intention::Avoid => ts("reef-intention-avoid.word"),
        Intention::Escape => ts("reef-intention-escape.word"),
        Intention::School => ts("reef-intention-school.word"),
        Intention::Eat => ts("reef-intention-eat.word"),
        Intention::Mate => ts("reef-intention-mate.word"),
        Intention::Leave => ts("reef-intention-leave.word"),
        Intention::Wander => ts("reef-intention-wander.word"),
    }
}

/// The colour of an intention (focus line, labels).
pub fn intention_color(intention: Intention) -> egui::Color32 {
    match intention {
        Intention::Avoid => egui::Color32::from_rgb(230, 230, 230),
        Intention::Escape | Intention::School => FEAR_COLOR,
        Intention::Eat => HUNGER_COLOR,
        Intention::Mate => LIBIDO_COLOR,
        Intention::Leave | Intention::Wander => egui::Color32::from_rgb(150, 220, 150),
    }
}

/// The reef scene's section of the control panel.
/// The demo buttons and what the demo shows.
fn demo_ui(ui: &mut egui::Ui, reef: &mut ReefSettings, rects: &mut WidgetRects) {
    ui.separator();
    ui.label(egui::RichText::new(ts("reef-heading")).strong());
    control(ui, rects, "reef.demo", |ui, rects| {
        ui.horizontal_wrapped(|ui| {
            for demo in ReefScene::ALL {
                let button = ui
                    .selectable_label(reef.demo == demo, demo.label())
                    .on_hover_text(demo.explanation());
                rects.insert(&format!("reef_demo_{}", demo_name(demo)), button.rect);
                if button.clicked() {
                    reef.choose_demo(demo);
                }
            }
        })
    });
    ui.label(egui::RichText::new(reef.demo.explanation()).italics());
}

/// The reef's sliders: body, counts, water, and what is drawn over the tank.
fn reef_sliders_ui(ui: &mut egui::Ui, reef: &mut ReefSettings, rects: &mut WidgetRects) {
    egui::Grid::new("reef_grid")
        .num_columns(2)
        .spacing([8.0, 6.0])
        .show(ui, |ui| {
            let help = ts("reef-body.help");
            control_row(
                ui,
                rects,
                "reef.body",
                |ui| {
                    ui.label(ts("reef-body")).on_hover_text(help);
                },
                |ui, rects| {
                    ui.horizontal(|ui| {
                        for (kind, label, name) in [
                            (
                                ReefBodyKind::Physical,
                                ts("reef-body-muscles"),
                                "reef_body_physical",
                            ),
                            (
                                ReefBodyKind::PointMass,
                                ts("reef-body-points"),
                                "reef_body_point",
                            ),
                        ] {
                            let r = ui
                                .radio_value(&mut reef.body, kind, label)
                                .on_hover_text(help);
                            rects.insert(name, r.rect);
                        }
                    });
                },
            );

            if setting_row(
                ui,
                rects,
                ReefSettings::PREFIX,
                &ReefSettings::PREY_COUNT,
                reef,
            ) {
                // The fish numbers change with the new reef.
                reef.selected = None;
            }
            setting_row(
                ui,
                rects,
                ReefSettings::PREFIX,
                &ReefSettings::FOOD_COUNT,
                reef,
            );
            for water in [ReefSettings::VISIBILITY_M, ReefSettings::CURRENT_M_PER_S] {
                setting_row(ui, rects, ReefSettings::PREFIX, &water, reef);
            }

            let help = ts("reef-show-water.help");
            control_row(
                ui,
                rects,
                "reef.overlay",
                |ui| {
                    ui.label(ts("reef-show-water")).on_hover_text(help);
                },
                |ui, rects| {
                    ui.horizontal(|ui| {
                        for overlay in ReefOverlay::ALL {
                            let r = ui
                                .radio_value(&mut reef.overlay, overlay, overlay.label())
                                .on_hover_text(help);
                            rects.insert(&format!("reef_overlay_{}", overlay.name()), r.rect);
                        }
                    });
                },
            );
        });
    control(ui, rects, "reef.show_vision", |ui, rects| {
        let r = ui
            .checkbox(&mut reef.show_vision, ts("reef-show-vision"))
            .on_hover_text(ts("reef-show-vision.help"));
        rects.insert("reef_show_vision", r.rect);
    });
}

/// Name tags, and the selected fish: follow it, let it go.
fn selection_ui(
    ui: &mut egui::Ui,
    reef: &mut ReefSettings,
    selected_name: Option<&str>,
    rects: &mut WidgetRects,
) {
    let r = ui
        .checkbox(&mut reef.name_tags, ts("reef-name-tags"))
        .on_hover_text(ts("reef-name-tags.help"));
    rects.insert("reef_name_tags", r.rect);
    match reef.selected {
        Some(i) => {
            ui.horizontal(|ui| {
                control(ui, rects, "reef.follow", |ui, rects| {
                    let r = ui
                        .checkbox(&mut reef.follow, ts("reef-follow"))
                        .on_hover_text(ts("reef-follow.help"));
                    rects.insert("reef_follow", r.rect);
                });
                let r = ui
                    .button(ts("reef-deselect"))
                    .on_hover_text(ts("reef-deselect.help"));
                rects.insert("reef_deselect", r.rect);
                if r.clicked() {
                    reef.selected = None;
                    reef.follow = false;
                }
            });
            let name =
                selected_name.map_or_else(|| tr!("reef-animal-number", index = i), str::to_owned);
            ui.label(tr!("reef-selected", name = name));
        }
        None => {
            ui.label(ts("reef-select-hint"));
        }
    }
}

/// The settings name of a demo (`reef.demo`).
pub fn demo_name(demo: ReefScene) -> &'static str {
    match demo {
        ReefScene::Reef => "reef",
        ReefScene::PredatorAndSchool => "predator_and_school",
        ReefScene::Courtship => "courtship",
        ReefScene::Feeding => "feeding",
        ReefScene::SchoolMeetsObstacle => "school_meets_obstacle",
    }
}

/// Seconds between two renders of the fish-eye view (0.2, chosen: smooth enough
/// to follow, cheap: one 96 × 96 ray cast).
const FISH_EYE_EVERY_SECS: f64 = 0.2;
/// Pixels across the fish-eye view.
const FISH_EYE_SIZE_PX: usize = 96;

/// The selected fish's retinal image: which fish, the texture, its mean
/// brightness and when (app time, seconds) it was rendered.
struct FishEye {
    fish: u32,
    texture: egui::TextureHandle,
    mean_brightness: f32,
    at_secs: f64,
}

/// The reef scene's panel.
pub struct ReefPanel {
    /// Whose mind the *Minds* section edits.
    minds_kind: FishKind,
    /// The habits the demo gives each kind of fish present (the first of each
    /// kind), refreshed every frame.
    demo_habits: Vec<Habits>,
    fish_eye: Option<FishEye>,
    /// The selected animal's name as the log and the inspector give it.
    selected_name: Option<String>,
    /// *Skip to the moment*.
    skip: SkipUi,
}

impl Default for ReefPanel {
    fn default() -> Self {
        Self {
            minds_kind: FishKind::Predator,
            demo_habits: Vec::new(),
            fish_eye: None,
            selected_name: None,
            skip: SkipUi::default(),
        }
    }
}

impl ScenePanel for ReefPanel {
    fn offers_experiment(&self) -> bool {
        true
    }

    fn before_frame(
        &mut self,
        lab: &mut Lab,
        now_secs: f64,
        ctx: &egui::Context,
    ) -> Option<Notice> {
        // The Minds section shows the demo's own values under the teacher's.
        self.demo_habits.clear();
        if let Some(reef) = lab.runs()[0].scene().reef() {
            for kind in FishKind::ALL {
                if let Some(a) = reef.animals().iter().find(|a| a.demo_habits.kind == kind) {
                    self.demo_habits.push(a.demo_habits);
                }
            }
        }
        self.refresh_fish_eye(lab, now_secs, ctx);
        self.selected_name = lab.settings().reef.selected.and_then(|i| {
            let reef = lab.runs()[0].scene().reef()?;
            Some(reef.animals().get(i as usize)?.name(i as usize))
        });
        self.skip.before_frame(lab)
    }

    fn controls_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings, rects: &mut WidgetRects) {
        demo_ui(ui, &mut settings.reef, rects);
        self.skip.controls_ui(ui, settings, rects);
        reef_sliders_ui(ui, &mut settings.reef, rects);
        selection_ui(ui, &mut settings.reef, self.selected_name.as_deref(), rects);
        ui.add_space(4.0);
        super::predation_panel::predation_ui(ui, &mut settings.predation, rects);
        minds_ui(
            ui,
            &mut settings.reef.traits,
            &mut self.minds_kind,
            &self.demo_habits,
            rects,
        );
    }

    fn bottom_ui(
        &mut self,
        ui: &mut egui::Ui,
        lab: &Lab,
        settings: &mut Settings,
        rects: &mut WidgetRects,
    ) {
        self.skip.take_follow(settings);
        let selected = lab.settings().reef.selected;
        let fish_eye = self
            .fish_eye
            .as_ref()
            .filter(|f| Some(f.fish) == selected)
            .map(|f| FishEyeView {
                texture: &f.texture,
                mean_brightness: f.mean_brightness,
            });
        let run = &lab.runs()[0];
        let clicked = show_bottom_panel(
            ui,
            "reef_inspector",
            reef_inspector_height(selected.is_some()),
            rects,
            |ui, height, rects| reef_inspector_ui(ui, run, selected, fish_eye, height, rects),
        );
        // A click on an event follows the fish it is about.
        if let Some(subject) = clicked {
            settings.reef.selected = Some(subject);
            settings.reef.follow = true;
        }
    }

    fn draw_overlays(&self, view: &ViewContext, settings: &Settings, rects: &mut WidgetRects) {
        let (painter, rect, camera, run, alpha) =
            (view.painter, view.rect, view.camera, view.run, view.alpha);
        reef_overlay::draw_water(painter, rect, camera, run, settings.reef.overlay);
        if settings.reef.name_tags {
            reef_overlay::draw_name_tags(painter, rect, camera, run, alpha);
        }
        // The selected fish's focus line already shows whom she wants.
        let focus_drawn = settings.reef.selected.filter(|_| settings.reef.show_vision);
        reef_overlay::draw_choices(painter, rect, camera, run, alpha, focus_drawn);
        if let Some(selected) = settings.reef.selected {
            if settings.reef.show_vision {
                reef_overlay::draw_vision(painter, rect, camera, run, alpha, selected);
            }
            body_overlay::draw_selection(painter, rect, camera, run, alpha, selected);
        }
        body_overlay::record_animal_rects(view, rects);
        self.skip.draw_banner(painter, rect);
    }

    fn apply(&mut self, lab: &mut Lab, _ctx: &egui::Context) -> Option<Notice> {
        self.skip.apply(lab)
    }

    /// A click on a fish selects it; a click on open water lets go.
    fn view_input(&mut self, input: &ViewInput, settings: &mut Settings) -> Option<Notice> {
        let picked = body_overlay::clicked_animal(input)?;
        settings.reef.selected = picked;
        if picked.is_none() {
            settings.reef.follow = false;
        }
        None
    }

    fn followed(&self, settings: &Settings) -> Option<u32> {
        settings.reef.selected.filter(|_| settings.reef.follow)
    }

    fn framing(&self, run: &Run, settings: &Settings) -> Option<Framing> {
        demo_framing(run.scene().reef()?, settings.reef.demo)
    }

    fn view_subject(&self, settings: &Settings) -> &'static str {
        demo_name(settings.reef.demo)
    }
}

/// Margin round the animals a demo frames, metres (1.2, chosen: a body length
/// or two of water round them, so a turn stays in view).
const FRAMING_MARGIN_M: f32 = 1.2;

/// How steeply the *School meets obstacle* demo looks down, radians (1.2, about
/// 70°: from the front the school splits behind the pillar, unseen).
const TOP_VIEW_PITCH_RAD: f32 = 1.2;

/// What each demo opens on: the whole reef; the shark and its prey; the
/// courting trio; the fish the feeding demo follows; the pillar from above.
pub fn demo_framing(reef: &ReefWorld, demo: ReefScene) -> Option<Framing> {
    let around = |kinds: &[FishKind]| {
        let points: Vec<glam::Vec3> = reef
            .living()
            .filter(|(_, a)| kinds.contains(&a.habits.kind))
            .map(|(_, a)| a.body.position_m())
            .collect();
        let first = *points.first()?;
        let (min, max) = points
            .iter()
            .fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        let margin = glam::Vec3::splat(FRAMING_MARGIN_M);
        let tank = reef.tank();
        Some(Framing::Box {
            min_m: (min - margin).max(tank.min_m),
            max_m: (max + margin).min(tank.max_m),
            yaw_rad: DEFAULT_YAW_RAD,
            pitch_rad: DEFAULT_PITCH_RAD,
        })
    };
    match demo {
        ReefScene::Reef => None,
        ReefScene::PredatorAndSchool => around(&[FishKind::Predator, FishKind::Prey]),
        ReefScene::Courtship | ReefScene::Feeding => around(&[FishKind::Pacifist]),
        ReefScene::SchoolMeetsObstacle => Some(Framing::Box {
            min_m: reef.tank().min_m,
            max_m: reef.tank().max_m,
            yaw_rad: 0.0,
            pitch_rad: TOP_VIEW_PITCH_RAD,
        }),
    }
}

impl ReefPanel {
    /// Renders the selected fish's retinal image every [`FISH_EYE_EVERY_SECS`].
    fn refresh_fish_eye(&mut self, lab: &Lab, now_secs: f64, ctx: &egui::Context) {
        let Some(selected) = lab.settings().reef.selected else {
            self.fish_eye = None;
            return;
        };
        let fresh = self
            .fish_eye
            .as_ref()
            .is_some_and(|f| f.fish == selected && now_secs - f.at_secs < FISH_EYE_EVERY_SECS);
        if fresh {
            return;
        }
        let Some(retina) = lab.runs()[0]
            .scene()
            .reef()
            .and_then(|r| r.retina(selected as usize, FISH_EYE_SIZE_PX))
        else {
            self.fish_eye = None;
            return;
        };
        let image = egui::ColorImage::from_rgba_unmultiplied(
            [retina.size, retina.size],
            &retina.to_rgba8(),
        );
        match &mut self.fish_eye {
            Some(eye) => {
                eye.texture.set(image, egui::TextureOptions::LINEAR);
                (eye.fish, eye.mean_brightness, eye.at_secs) =
                    (selected, retina.mean_brightness, now_secs);
            }
            None => {
                let texture = ctx.load_texture("fish_eye", image, egui::TextureOptions::LINEAR);
                self.fish_eye = Some(FishEye {
                    fish: selected,
                    texture,
                    mean_brightness: retina.mean_brightness,
                    at_secs: now_secs,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::OrbitCamera;
    use crate::sim::reef::world::ReefConfig;

    fn on_screen(camera: &OrbitCamera, p: glam::Vec3) -> bool {
        camera
            .project(p, 16.0 / 9.0)
            .is_some_and(|uv| (0.0..=1.0).contains(&uv.x) && (0.0..=1.0).contains(&uv.y))
    }

    #[test]
    fn each_demo_opens_on_its_subject() {
        for demo in ReefScene::ALL {
            let reef = ReefWorld::new(ReefConfig {
                seed: 3,
                scene: demo,
                ..ReefConfig::default()
            });
            let tank = *reef.tank();
            let whole = OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0);
            let Some(framing) = demo_framing(&reef, demo) else {
                assert_eq!(
                    demo,
                    ReefScene::Reef,
                    "only the whole reef shows the whole tank"
                );
                continue;
            };
            let camera = OrbitCamera::framed(&framing, 16.0 / 9.0);
            // Every animal the demo is about is in view.
            let subjects: &[FishKind] = match demo {
                ReefScene::PredatorAndSchool => &[FishKind::Predator, FishKind::Prey],
                ReefScene::Courtship | ReefScene::Feeding => &[FishKind::Pacifist],
                _ => &FishKind::ALL,
            };
            for (i, a) in reef.living() {
                if subjects.contains(&a.habits.kind) {
                    assert!(
                        on_screen(&camera, a.body.position_m()),
                        "{demo:?}: animal {i} is out of view"
                    );
                }
            }
            match demo {
                // The obstacle from above: the split is seen, not hidden behind it.
                ReefScene::SchoolMeetsObstacle => {
                    assert!(camera.pitch_rad > 1.0, "{}", camera.pitch_rad);
                }
                // The trio is closer than the whole tank would put it.
                ReefScene::Courtship => {
                    assert!(camera.distance_m < 0.8 * whole.distance_m);
                }
                _ => assert!(camera.distance_m <= whole.distance_m * 1.01),
            }
        }
    }

    /// The reef's words in Spanish: demo names, an intention, the inspector's
    /// readings with a decimal comma, and a real event-log line, which the
    /// screen writes in Spanish while `text` (for programs) stays English.
    #[test]
    fn the_reef_speaks_spanish() {
        use crate::i18n::{Lang, num, with_lang};
        use crate::sim::reef::events::ReefEventKind;
        use crate::sim::reef::mind::Target;
        use crate::sim::reef::world::ReefConfig;
        use crate::tr;
        use crate::ui::reef_inspector::target_text;

        // A reef logged in Spanish: the feeding demo's first meals.
        let mut w = ReefWorld::new(ReefConfig {
            seed: 3,
            scene: ReefScene::Feeding,
            body: ReefBodyKind::PointMass,
            ..ReefConfig::default()
        });
        with_lang(Lang::Es, || {
            while !w
                .events()
                .iter()
                .any(|e| matches!(e.kind, ReefEventKind::AteFood { .. }))
            {
                assert!(w.time_secs() < 120.0, "no meal in two minutes");
                w.step();
            }
        });
        let meal = w
            .events()
            .iter()
            .find(|e| matches!(e.kind, ReefEventKind::AteFood { .. }))
            .unwrap();
        assert!(
            meal.text.contains(" ate plankton (hunger 1.00 → 0."),
            "{}",
            meal.text
        );
        assert_eq!(meal.words(), meal.text, "in English, as logged");

        with_lang(Lang::Es, || {
            let words = meal.words();
            assert!(words.starts_with("pacífico "), "{words}");
            assert!(
                words.contains(" comió plancton (hambre 1,00 → 0,"),
                "{words}"
            );
            assert_eq!(ReefScene::Courtship.label(), "Cortejo");
            assert_eq!(ReefScene::Feeding.moment().words(), "el próximo bocado");
            // `shoal.state()` reads the moment in English.
            assert_eq!(ReefScene::Feeding.moment().what, "the next bite");
            assert_eq!(
                intention_sentence(Intention::Escape),
                "hay un depredador cerca: huye"
            );
            assert_eq!(target_text(&w, Some(Target::Glass)), "el vidrio");
            assert_eq!(target_text(&w, Some(Target::Animal(1))), "pacífico 1");
            let habits = tr!(
                "reef-inspector-habits",
                species = 2,
                length = num(0.456, 2),
                light = "bright",
                temperature = "any",
                schools = "yes",
            );
            assert_eq!(
                habits,
                "Especie 2 · 0,46 m · le gusta la luz intensa y el agua a cualquier \
                 temperatura · forma bancos"
            );
            assert_eq!(tr!("reef-water", value = num(24.31, 1)), "Agua a 24,3 °C");
            assert_eq!(
                tr!(
                    "reef-summary",
                    animals = 1,
                    plankton = 12,
                    eaten = 0,
                    spawnings = 2
                ),
                "1 animal vivo · 12 partículas de plancton · 0 presas comidas · 2 desoves"
            );
        });
    }

    /// Every event line the reef logs is in the catalogue (the log's
    /// `Line::new` ids are not `tr!` calls, which the i18n tests check).
    #[test]
    fn every_event_line_is_in_the_catalogue() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/sim/reef");
        let mut ids = Vec::new();
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                for (at, _) in text.match_indices("\"reef-event-") {
                    let id = text[at + 1..].split('"').next().unwrap().to_owned();
                    ids.push(id);
                }
            }
        }
        assert!(ids.len() >= 15, "{ids:?}");
        for lang in crate::i18n::Lang::ALL {
            for id in &ids {
                assert!(crate::i18n::has(lang, id), "{id} in {}", lang.code());
            }
        }
    }
}
