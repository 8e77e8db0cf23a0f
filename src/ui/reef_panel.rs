//! The "Reef" scene's controls (which demo, which body, the water, overlays) and
//! its inspector: the selected fish's habits, its hunger, libido and fear (bars
//! and their history), its intention, memory and focus, its motor command, its
//! fish-eye view; and the reef's event log.

use eframe::egui;
use egui_plot::{Legend, Line, Plot, PlotPoints};

use super::WidgetRects;
use super::control_panel::PanelAction;
use crate::lab::Run;
use crate::reef_settings::{
    REEF_CURRENT_MAX_M_PER_S, REEF_FOOD_MAX, REEF_PREY_MAX, ReefOverlay, ReefSettings,
    VISIBILITY_MAX_M, VISIBILITY_MIN_M,
};
use crate::sim::mind::{FishKind, Intention, Liking, Sex, Target};
use crate::sim::reef_world::{ReefAnimal, ReefBody, ReefBodyKind, ReefScene, ReefWorld};

/// Colours of the three urges, used by the bars, the plot and the focus line.
pub const HUNGER_COLOR: egui::Color32 = egui::Color32::from_rgb(255, 170, 60);
pub const LIBIDO_COLOR: egui::Color32 = egui::Color32::from_rgb(240, 110, 200);
pub const FEAR_COLOR: egui::Color32 = egui::Color32::from_rgb(110, 180, 255);

/// One sentence per intention, for the inspector.
pub fn intention_sentence(intention: Intention) -> &'static str {
    match intention {
        Intention::Avoid => "something is in its way: it swerves",
        Intention::Escape => "a predator is close: it flees",
        Intention::School => "it swims with the others of its kind",
        Intention::Eat => "it is hungry: it looks for food",
        Intention::Mate => "it wants to mate: it courts",
        Intention::Leave => "it does not like the water here: it leaves",
        Intention::Wander => "all is well: it wanders",
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
pub fn reef_controls_ui(
    ui: &mut egui::Ui,
    reef: &mut ReefSettings,
    rects: &mut WidgetRects,
) -> Vec<PanelAction> {
    let mut actions = Vec::new();
    ui.separator();
    ui.label(egui::RichText::new("Reef").strong());
    ui.horizontal_wrapped(|ui| {
        for demo in ReefScene::ALL {
            let button = ui
                .selectable_label(reef.demo == demo, demo.label())
                .on_hover_text(demo.explanation());
            rects.insert(&format!("reef_demo_{}", demo_name(demo)), button.rect);
            if button.clicked() && reef.demo != demo {
                reef.demo = demo;
                reef.prey_count = None;
                reef.food_count = None;
                reef.selected = None;
            }
        }
    });
    ui.label(egui::RichText::new(reef.demo.explanation()).italics());
    egui::Grid::new("reef_grid")
        .num_columns(2)
        .spacing([8.0, 6.0])
        .show(ui, |ui| {
            let help = "Muscles: each fish is a body of springs that swims by bending (slower to \
                        compute, true to the paper). Points: each fish is a dot that steers \
                        directly (fast, for big scenes). The mind is the same.";
            ui.label("Body").on_hover_text(help);
            ui.horizontal(|ui| {
                for (kind, label, name) in [
                    (ReefBodyKind::Physical, "Muscles", "reef_body_physical"),
                    (ReefBodyKind::PointMass, "Points", "reef_body_point"),
                ] {
                    let r = ui
                        .radio_value(&mut reef.body, kind, label)
                        .on_hover_text(help);
                    rects.insert(name, r.rect);
                }
            });
            ui.end_row();

            let demo_prey = reef.demo.default_prey_count() as u32;
            let help =
                "How many small prey fish live in this reef (they school and flee the shark)";
            ui.label("Prey fish").on_hover_text(help);
            let mut prey = reef.prey_count.unwrap_or(demo_prey);
            let r = ui
                .add(egui::Slider::new(&mut prey, 0..=REEF_PREY_MAX))
                .on_hover_text(help);
            rects.insert("reef_prey", r.rect);
            if r.changed() {
                reef.prey_count = Some(prey);
                reef.selected = None;
            }
            ui.end_row();

            let help = "How much plankton drifts in the water; eaten plankton is replaced";
            ui.label("Plankton").on_hover_text(help);
            let mut food = reef
                .food_count
                .unwrap_or(reef.demo.default_food_count() as u32);
            let r = ui
                .add(egui::Slider::new(&mut food, 0..=REEF_FOOD_MAX))
                .on_hover_text(help);
            rects.insert("reef_food", r.rect);
            if r.changed() {
                reef.food_count = Some(food);
            }
            ui.end_row();

            let help = "How far a fish can see in this water, metres. Murky water: fish see \
                        less, find less food and notice the shark later";
            ui.label("Visibility").on_hover_text(help);
            let r = ui
                .add(
                    egui::Slider::new(&mut reef.visibility_m, VISIBILITY_MIN_M..=VISIBILITY_MAX_M)
                        .suffix(" m"),
                )
                .on_hover_text(help);
            rects.insert("reef_visibility", r.rect);
            ui.end_row();

            let help = "How fast the water flows; it carries plankton and sways the seaweed";
            ui.label("Current").on_hover_text(help);
            let r = ui
                .add(
                    egui::Slider::new(&mut reef.current_m_per_s, 0.0..=REEF_CURRENT_MAX_M_PER_S)
                        .suffix(" m/s"),
                )
                .on_hover_text(help);
            rects.insert("reef_current", r.rect);
            ui.end_row();

            let help = "Colour the water by how bright or how warm it is. Some fish like light \
                        or warmth and leave water they do not like";
            ui.label("Show water").on_hover_text(help);
            ui.horizontal(|ui| {
                for overlay in ReefOverlay::ALL {
                    let r = ui
                        .radio_value(&mut reef.overlay, overlay, overlay.label())
                        .on_hover_text(help);
                    rects.insert(
                        &format!("reef_overlay_{}", overlay.label().to_lowercase()),
                        r.rect,
                    );
                }
            });
            ui.end_row();
        });
    let r = ui
        .checkbox(&mut reef.show_vision, "Show what the selected fish sees")
        .on_hover_text(
            "A fish sees all around except a narrow blind cone behind, as far as the water \
             is clear. The coloured line points at what it is thinking about",
        );
    rects.insert("reef_show_vision", r.rect);
    match reef.selected {
        Some(i) => {
            ui.horizontal(|ui| {
                let r = ui
                    .checkbox(&mut reef.follow, "Camera follows it")
                    .on_hover_text("Keep the selected fish in the middle of the view");
                rects.insert("reef_follow", r.rect);
                let r = ui.button("Deselect").on_hover_text("Let go of the fish");
                rects.insert("reef_deselect", r.rect);
                if r.clicked() {
                    reef.selected = None;
                    reef.follow = false;
                }
            });
            ui.label(format!("Selected: animal {i} (its mind is shown below)"));
        }
        None => {
            ui.label("Click a fish in the tank to look inside its head.");
        }
    }
    actions.shrink_to_fit();
    actions
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

/// What the fish-eye panel shows (made by the app from `ReefWorld::retina`).
pub struct FishEyeView<'a> {
    pub texture: &'a egui::TextureHandle,
    pub mean_brightness: f32,
}

/// The bottom panel of the reef scene: the inspector of the selected fish, or a
/// hint; and the event log.
pub fn reef_inspector_ui(
    ui: &mut egui::Ui,
    run: &Run,
    selected: Option<u32>,
    fish_eye: Option<FishEyeView>,
    rects: &mut WidgetRects,
) {
    let Some(reef) = run.reef() else {
        return;
    };
    let animal = selected.and_then(|i| reef.animals().get(i as usize).map(|a| (i as usize, a)));
    ui.horizontal_top(|ui| {
        match animal {
            Some((i, a)) => {
                ui.vertical(|ui| {
                    ui.set_width(300.0);
                    mind_summary_ui(ui, reef, i, a, rects);
                });
                ui.separator();
                ui.vertical(|ui| {
                    ui.set_width((ui.available_width() - 560.0).max(220.0));
                    history_plot_ui(ui, a, rects);
                });
                ui.separator();
                ui.vertical(|ui| {
                    ui.set_width(180.0);
                    ui.label(egui::RichText::new("What it sees").strong())
                        .on_hover_text(
                            "The world through this fish's eye: it sees almost all around, \
                             squeezed into a circle. Its brain only uses how bright it is",
                        );
                    if let Some(view) = fish_eye {
                        let r = ui.add(
                            egui::Image::new(view.texture)
                                .fit_to_exact_size(egui::vec2(150.0, 150.0)),
                        );
                        rects.insert("fish_eye", r.rect);
                        ui.label(format!("Brightness {:.2}", view.mean_brightness));
                    }
                    ui.label(format!("Water {:.1} °C", a.temperature_c));
                });
            }
            None => {
                ui.vertical(|ui| {
                    ui.set_width(300.0);
                    let counts = reef.counts();
                    ui.label(egui::RichText::new("Reef").strong());
                    ui.label(format!(
                        "{} animals alive · {} plankton · {} prey eaten · {} spawnings",
                        reef.alive_count(),
                        reef.food().len(),
                        counts.prey_eaten,
                        counts.spawnings
                    ));
                    ui.label("Click a fish to see its hunger, fear and plans, and what it sees.");
                });
            }
        }
        ui.separator();
        ui.vertical(|ui| {
            event_log_ui(ui, reef, rects);
        });
    });
}

fn mind_summary_ui(
    ui: &mut egui::Ui,
    reef: &ReefWorld,
    i: usize,
    a: &ReefAnimal,
    rects: &mut WidgetRects,
) {
    let h = &a.habits;
    let sex = match h.sex {
        Sex::Male => "male",
        Sex::Female => "female",
    };
    let title = if a.alive {
        format!("{} · {} {}", a.name(i), sex, h.kind.label())
    } else {
        format!("{} · eaten", a.name(i))
    };
    let r = ui.label(egui::RichText::new(title).strong());
    rects.insert("reef_inspector", r.rect);
    let liking = |l: Liking, high: &str, low: &str| match l {
        Liking::Indifferent => "any".to_owned(),
        Liking::High => high.to_owned(),
        Liking::Low => low.to_owned(),
    };
    ui.label(format!(
        "Species {} · {:.2} m · likes {} light, {} water{}",
        h.species,
        a.body.body_length_m(),
        liking(h.light, "bright", "dim"),
        liking(h.temperature, "warm", "cool"),
        if h.schools { " · schools" } else { "" }
    ))
    .on_hover_text("Habits: what this fish was born liking. They never change.");
    for (name, value, color, help) in [
        (
            "Hunger",
            a.mental.hunger,
            HUNGER_COLOR,
            "Grows as food digests; drops when it eats",
        ),
        (
            "Libido",
            a.mental.libido,
            LIBIDO_COLOR,
            "Grows with time since mating, unless it is hungry",
        ),
        (
            "Fear",
            a.mental.fear,
            FEAR_COLOR,
            "High when it sees a predator close by",
        ),
    ] {
        ui.horizontal(|ui| {
            ui.label(format!("{name:<7}")).on_hover_text(help);
            let bar = egui::ProgressBar::new(value.clamp(0.0, 1.0))
                .fill(color)
                .text(format!("{value:.2}"))
                .desired_width(180.0);
            let r = ui.add(bar).on_hover_text(help);
            rects.insert(&format!("reef_bar_{}", name.to_lowercase()), r.rect);
        });
    }
    let focus = a.focus;
    let sentence = match (focus.intention, h.kind) {
        (Intention::Eat, FishKind::Predator) => "it is hungry: it hunts",
        (intention, _) => intention_sentence(intention),
    };
    let r = ui.label(
        egui::RichText::new(format!(
            "Intends to {}: {}",
            focus.intention.label(),
            sentence
        ))
        .color(intention_color(focus.intention)),
    );
    rects.insert("reef_intention", r.rect);
    ui.label(format!("Focus: {}", target_text(reef, focus.target)));
    match a.generator.memory {
        Some(m) => ui.label(format!(
            "Remembers: {} {} (resumes it after swerving)",
            m.intention.label(),
            target_text(reef, m.target)
        )),
        None => ui.label("Remembers: nothing"),
    };
    if let Some(pair) = reef.pair_of(i) {
        ui.label(format!(
            "Courting: {} with animal {} ({})",
            pair.phase.label(),
            if pair.male as usize == i {
                pair.female
            } else {
                pair.male
            },
            pair.count
        ));
    }
    if let ReefBody::Physical(p) = &a.body {
        let m = p.motor();
        ui.label(format!(
            "Muscles: swim {:.0} %{}, fins {:+.0}°",
            100.0 * m.speed_fraction,
            if m.turning { ", turning" } else { "" },
            (m.fins.left_angle_rad - std::f32::consts::FRAC_PI_2).to_degrees()
        ))
        .on_hover_text("What the brain tells the muscles this moment");
    } else {
        ui.label(format!(
            "Speed {:.2} m/s (point body)",
            a.body.velocity_m_per_s().length()
        ));
    }
}

/// "plankton 12", "animal 3 (shark 3)", "the glass", "rock 1", "nothing".
pub fn target_text(reef: &ReefWorld, target: Option<Target>) -> String {
    match target {
        None => "nothing in particular".to_owned(),
        Some(Target::Food(id)) => format!("plankton {id}"),
        Some(Target::Animal(j)) => reef
            .animals()
            .get(j as usize)
            .map_or_else(|| format!("animal {j}"), |o| o.name(j as usize)),
        Some(Target::Obstacle(k)) => format!("rock {k}"),
        Some(Target::Glass) => "the glass".to_owned(),
    }
}

fn history_plot_ui(ui: &mut egui::Ui, a: &ReefAnimal, rects: &mut WidgetRects) {
    ui.label(egui::RichText::new("Its mind over the last two minutes").strong());
    let series = |f: fn(&crate::sim::reef_world::MindSample) -> f32| -> PlotPoints {
        a.history
            .iter()
            .map(|s| [f64::from(s.time_secs), f64::from(f(s))])
            .collect()
    };
    let r = Plot::new("reef_mind_history")
        .height((ui.available_height() - 8.0).clamp(90.0, 200.0))
        .include_y(0.0)
        .include_y(1.0)
        .allow_scroll(false)
        .allow_drag(false)
        .legend(Legend::default())
        .x_axis_label("time (s)")
        .show(ui, |plot| {
            plot.line(Line::new("hunger", series(|s| s.hunger)).color(HUNGER_COLOR));
            plot.line(Line::new("libido", series(|s| s.libido)).color(LIBIDO_COLOR));
            plot.line(Line::new("fear", series(|s| s.fear)).color(FEAR_COLOR));
        });
    rects.insert("reef_mind_plot", r.response.rect);
}

fn event_log_ui(ui: &mut egui::Ui, reef: &ReefWorld, rects: &mut WidgetRects) {
    ui.label(egui::RichText::new("What happened").strong())
        .on_hover_text("Newest first: meals, chases, courtship");
    let r = egui::ScrollArea::vertical()
        .id_salt("reef_events")
        .max_height((ui.available_height() - 4.0).max(80.0))
        .show(ui, |ui| {
            if reef.events().is_empty() {
                ui.label("Nothing yet.");
            }
            for e in reef.events().iter().rev().take(60) {
                let minutes = (e.time_secs / 60.0).floor();
                let secs = e.time_secs - 60.0 * minutes;
                ui.label(format!("{minutes:.0}:{secs:04.1}  {}", e.text));
            }
        });
    rects.insert("reef_events", r.inner_rect);
}
