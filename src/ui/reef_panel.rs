//! The "Reef" scene's controls (which demo, which body, the water, overlays) and
//! its inspector: the selected fish's habits, its hunger, libido and fear (bars
//! and their history), its intention, memory and focus, its motor command, its
//! fish-eye view; and the reef's event log.

use eframe::egui;
use egui_plot::{Legend, Line, Plot, PlotPoints};

use super::WidgetRects;
use super::bottom_panel::plot_height_under_caption;
use super::control_panel::PanelAction;
use crate::lab::Run;
use crate::settings::reef::{ReefOverlay, ReefSettings};
use crate::sim::reef::demos::ReefScene;
use crate::sim::reef::mind::habits::{
    COURAGEOUS_BOX_BODY_LENGTHS, DEFAULT_BOX_BODY_LENGTHS, DEFAULT_PERSISTENCE_BODY_LENGTHS,
    DEVOTED_BODY_LENGTHS, FICKLE_BODY_LENGTHS, KindTraits, MindTraits, TIMID_BOX_BODY_LENGTHS,
};
use crate::sim::reef::mind::mental_state::{
    CALM_DIGESTION_RATE, CALM_LIBIDO_RATE, MANIC_LIBIDO_RATE, NOMINAL_DIGESTION_RATE,
    NOMINAL_LIBIDO_RATE, RAVENOUS_DIGESTION_RATE,
};
use crate::sim::reef::mind::{FishKind, Habits, Intention, Liking, Sex, Target};
use crate::sim::reef::world::{ReefAnimal, ReefBody, ReefBodyKind, ReefWorld};

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
                .add(egui::Slider::new(
                    &mut prey,
                    ReefSettings::PREY_COUNT.bounds(),
                ))
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
                .add(egui::Slider::new(
                    &mut food,
                    ReefSettings::FOOD_COUNT.bounds(),
                ))
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
                    egui::Slider::new(&mut reef.visibility_m, ReefSettings::VISIBILITY_M.bounds())
                        .suffix(" m"),
                )
                .on_hover_text(help);
            rects.insert("reef_visibility", r.rect);
            ui.end_row();

            let help = "How fast the water flows; it carries plankton and sways the seaweed";
            ui.label("Current").on_hover_text(help);
            let r = ui
                .add(
                    egui::Slider::new(
                        &mut reef.current_m_per_s,
                        ReefSettings::CURRENT_M_PER_S.bounds(),
                    )
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

/// The height the reef inspector under the tank would like, points, with a fish
/// selected and without (see [`super::bottom_panel::bottom_panel_height`] for what it gets).
pub fn reef_inspector_height(selected: bool) -> f32 {
    if selected { 230.0 } else { 120.0 }
}

/// The bottom panel of the reef scene: the inspector of the selected fish, or a
/// hint; and the event log; in `content_height` points (a column that needs more
/// scrolls).
pub fn reef_inspector_ui(
    ui: &mut egui::Ui,
    run: &Run,
    selected: Option<u32>,
    fish_eye: Option<FishEyeView>,
    content_height: f32,
    rects: &mut WidgetRects,
) {
    let Some(reef) = run.reef() else {
        return;
    };
    let animal = selected.and_then(|i| reef.animals().get(i as usize).map(|a| (i as usize, a)));
    // Every column fits `content_height`: the text columns scroll, the plot and the
    // event log take what their caption (one line) leaves.
    let line = ui.text_style_height(&egui::TextStyle::Body);
    let spacing = ui.spacing().item_spacing.y;
    let under_caption = plot_height_under_caption(content_height, line, spacing);
    ui.horizontal_top(|ui| {
        match animal {
            Some((i, a)) => {
                ui.vertical(|ui| {
                    ui.set_width(300.0);
                    egui::ScrollArea::vertical()
                        .id_salt("reef_mind_summary")
                        .max_height(content_height)
                        .show(ui, |ui| mind_summary_ui(ui, reef, i, a, rects));
                });
                ui.separator();
                ui.vertical(|ui| {
                    ui.set_width((ui.available_width() - 560.0).max(220.0));
                    history_plot_ui(ui, a, under_caption, rects);
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
                        // The eye and the two lines under it fit under the caption.
                        let side = (under_caption - 2.0 * (line + spacing)).clamp(0.0, 150.0);
                        let r = ui.add(
                            egui::Image::new(view.texture)
                                .fit_to_exact_size(egui::vec2(side, side)),
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
                    egui::ScrollArea::vertical()
                        .id_salt("reef_summary")
                        .max_height(content_height)
                        .show(ui, |ui| {
                            let counts = reef.counts();
                            ui.label(egui::RichText::new("Reef").strong());
                            ui.label(format!(
                                "{} animals alive · {} plankton · {} prey eaten · {} spawnings",
                                reef.alive_count(),
                                reef.food().len(),
                                counts.prey_eaten,
                                counts.spawnings
                            ));
                            ui.label(
                                "Click a fish to see its hunger, fear and plans, and what it sees.",
                            );
                        });
                });
            }
        }
        ui.separator();
        ui.vertical(|ui| {
            event_log_ui(ui, reef, under_caption, rects);
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

fn history_plot_ui(ui: &mut egui::Ui, a: &ReefAnimal, height: f32, rects: &mut WidgetRects) {
    ui.add(
        egui::Label::new(egui::RichText::new("Its mind over the last two minutes").strong())
            .truncate(),
    );
    let series = |f: fn(&crate::sim::reef::world::MindSample) -> f32| -> PlotPoints {
        a.history
            .iter()
            .map(|s| [f64::from(s.time_secs), f64::from(f(s))])
            .collect()
    };
    let r = Plot::new("reef_mind_history")
        .height(height)
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

fn event_log_ui(ui: &mut egui::Ui, reef: &ReefWorld, height: f32, rects: &mut WidgetRects) {
    ui.label(egui::RichText::new("What happened").strong())
        .on_hover_text("Newest first: meals, chases, courtship");
    let r = egui::ScrollArea::vertical()
        .id_salt("reef_events")
        .max_height(height)
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

/// A row of the *Minds* section: one of [`MindTraits::ALL`] (by name), how it
/// reads to a student, and its named values.
struct MindRow {
    /// The trait's settings name, in [`MindTraits::ALL`].
    name: &'static str,
    /// Short name for the widget rectangles (`reef_minds_<key>`).
    key: &'static str,
    label: &'static str,
    help: &'static str,
    suffix: &'static str,
    /// A slider (logarithmic or not), or only the named values.
    slider: Option<bool>,
    /// Named values: (label, value, what it means).
    presets: &'static [(&'static str, f32, &'static str)],
    /// The kinds the row matters for.
    kinds: &'static [FishKind],
}

const ALL_KINDS: &[FishKind] = &FishKind::ALL;
const NOT_PREDATORS: &[FishKind] = &[FishKind::Prey, FishKind::Pacifist];

const MIND_ROWS: [MindRow; 9] = [
    MindRow {
        name: "digestion_rate_per_unit",
        key: "hunger",
        label: "Hunger grows (p0)",
        help: "p0: how fast a meal is digested, so how soon the fish is hungry again, \
               per time unit of 1/40 s. Calm (Shoal's default) 0.0003: hungry again \
               21 s after a full meal. The paper's nominal 0.00067: after 9 s; \
               ravenous 0.005: after 1 s",
        suffix: "",
        slider: Some(true),
        presets: &[
            ("Calm", CALM_DIGESTION_RATE, "p0 = 0.0003 (Shoal's default)"),
            (
                "Nominal",
                NOMINAL_DIGESTION_RATE,
                "p0 = 0.00067 (the paper's)",
            ),
            (
                "Ravenous",
                RAVENOUS_DIGESTION_RATE,
                "p0 = 0.005 (the paper's)",
            ),
        ],
        kinds: ALL_KINDS,
    },
    MindRow {
        name: "libido_rate_per_unit",
        key: "libido",
        label: "Libido grows (p1)",
        help: "p1: how fast the wish to mate grows after mating, per time unit of \
               1/40 s. Calm (Shoal's default) 0.0011: a fed fish wants to mate again \
               6 s after mating. The paper's nominal 0.0025: after 2.5 s; sexual \
               mania 0.01: after 0.6 s",
        suffix: "",
        slider: Some(true),
        presets: &[
            ("Calm", CALM_LIBIDO_RATE, "p1 = 0.0011 (Shoal's default)"),
            ("Nominal", NOMINAL_LIBIDO_RATE, "p1 = 0.0025 (the paper's)"),
            ("Sexual mania", MANIC_LIBIDO_RATE, "p1 = 0.01 (the paper's)"),
        ],
        kinds: &[FishKind::Pacifist],
    },
    MindRow {
        name: "appetite_food_units",
        key: "appetite",
        label: "Appetite (α)",
        help: "α: how much food fills the fish (a plankton particle is 1, a prey fish 4)",
        suffix: " food",
        slider: Some(false),
        presets: &[],
        kinds: ALL_KINDS,
    },
    MindRow {
        name: "fear_distance_body_lengths",
        key: "fear_distance",
        label: "Fear distance (D0)",
        help: "D0: a shark nearer than this many body lengths frightens the fish as much \
               as it can be (paper: 3.85)",
        suffix: " BL",
        slider: Some(false),
        presets: &[],
        kinds: NOT_PREDATORS,
    },
    MindRow {
        name: "fear_threshold",
        key: "alarm",
        label: "Alarm at fear (f0)",
        help: "f0: fear above this makes the fish take evasive action (paper: between 0.1 \
               and 0.5)",
        suffix: "",
        slider: Some(false),
        presets: &[],
        kinds: NOT_PREDATORS,
    },
    MindRow {
        name: "panic_threshold",
        key: "panic",
        label: "Panic at fear (f1)",
        help: "f1: when the nearest shark frightens it more than this, a schooling fish \
               stops schooling and flees alone",
        suffix: "",
        slider: Some(false),
        presets: &[],
        kinds: &[FishKind::Prey],
    },
    MindRow {
        name: "urge_threshold",
        key: "urge",
        label: "Acts on urges at (r)",
        help: "r: hunger (or the wish to mate) above this sends the fish looking for food \
               (or a partner) (paper: below 0.5)",
        suffix: "",
        slider: Some(false),
        presets: &[],
        kinds: ALL_KINDS,
    },
    MindRow {
        name: "collision_box_ahead_body_lengths",
        key: "box",
        label: "Collision box",
        help: "How far ahead the fish watches for things in its way",
        suffix: "",
        slider: None,
        presets: &[
            (
                "Timid",
                TIMID_BOX_BODY_LENGTHS,
                "swerves from anything far ahead (1.5 body lengths)",
            ),
            (
                "Ordinary",
                DEFAULT_BOX_BODY_LENGTHS,
                "swerves from what is 0.8 body lengths ahead",
            ),
            (
                "Courageous",
                COURAGEOUS_BOX_BODY_LENGTHS,
                "swerves only at the last moment (0.3 body lengths)",
            ),
        ],
        kinds: ALL_KINDS,
    },
    MindRow {
        name: "persistence_body_lengths",
        key: "persistence",
        label: "Persistence",
        help: "Does the fish stick to the food, prey or partner it chose?",
        suffix: "",
        slider: None,
        presets: &[
            (
                "Fickle",
                FICKLE_BODY_LENGTHS,
                "switches to any target that is a little nearer",
            ),
            (
                "Ordinary",
                DEFAULT_PERSISTENCE_BODY_LENGTHS,
                "switches when another is 2 body lengths nearer",
            ),
            (
                "Devoted",
                DEVOTED_BODY_LENGTHS,
                "sticks to its target unless another is 20 body lengths nearer",
            ),
        ],
        kinds: ALL_KINDS,
    },
];

/// One row of the *Minds* grid: the label, a slider over the trait's range
/// and its named values as buttons; what the teacher picks goes into `traits`.
fn mind_row_ui(
    ui: &mut egui::Ui,
    row: &MindRow,
    traits: &mut MindTraits,
    now: &Habits,
    rects: &mut WidgetRects,
) {
    let Some(spec) = MindTraits::ALL.iter().find(|t| t.name == row.name) else {
        return;
    };
    ui.label(row.label).on_hover_text(row.help);
    ui.vertical(|ui| {
        let value = (spec.current)(now);
        if let Some(logarithmic) = row.slider {
            let mut v = value;
            let r = ui
                .add(
                    egui::Slider::new(&mut v, spec.min..=spec.max)
                        .logarithmic(logarithmic)
                        .suffix(row.suffix),
                )
                .on_hover_text(row.help);
            rects.insert(&format!("reef_minds_{}", row.key), r.rect);
            if r.changed() {
                (spec.set)(traits, Some(v));
            }
        }
        if !row.presets.is_empty() {
            ui.horizontal_wrapped(|ui| {
                for &(label, v, what) in row.presets {
                    let r = ui
                        .selectable_label(value == v, label)
                        .on_hover_text(format!("{label}: {what}"));
                    let name = label.to_lowercase().replace(' ', "_");
                    rects.insert(&format!("reef_minds_{}_{name}", row.key), r.rect);
                    if r.clicked() {
                        (spec.set)(traits, Some(v));
                    }
                }
            });
        }
    });
    ui.end_row();
}

/// The reef's *Minds* section: the constants of hunger, libido and fear and
/// the personality of one kind of fish at a time (Tu & Terzopoulos §6), over
/// the values the demo chose (`demo_habits`: the first fish of each kind in
/// the reef). Every change applies to every fish of the kind at once.
pub fn minds_ui(
    ui: &mut egui::Ui,
    traits: &mut KindTraits,
    kind: &mut FishKind,
    demo_habits: &[Habits],
    rects: &mut WidgetRects,
) {
    ui.separator();
    let header = egui::CollapsingHeader::new(egui::RichText::new("Minds").strong())
        .id_salt("reef_minds")
        .default_open(false)
        .show(ui, |ui| {
            ui.label(
                egui::RichText::new(
                    "How fast each kind of fish gets hungry or wants to mate, how far away a \
                     shark frightens it, and its character. Changes apply at once.",
                )
                .small(),
            );
            if !demo_habits.iter().any(|h| h.kind == *kind)
                && let Some(first) = demo_habits.first()
            {
                *kind = first.kind;
            }
            ui.horizontal(|ui| {
                for (k, label) in [
                    (FishKind::Predator, "Sharks"),
                    (FishKind::Prey, "Prey fish"),
                    (FishKind::Pacifist, "Pacifists"),
                ] {
                    let present = demo_habits.iter().any(|h| h.kind == k);
                    let r = ui
                        .add_enabled(present, egui::Button::selectable(*kind == k, label))
                        .on_hover_text(match k {
                            FishKind::Predator => "The hunters: they eat prey fish",
                            FishKind::Prey => "Small fish that school and flee the shark",
                            FishKind::Pacifist => "Fish that graze on plankton and court",
                        })
                        .on_disabled_hover_text("None of these in this demo");
                    rects.insert(&format!("reef_minds_{}", k.label()), r.rect);
                    if r.clicked() {
                        *kind = k;
                    }
                }
            });
            let Some(demo) = demo_habits.iter().find(|h| h.kind == *kind).copied() else {
                ui.label("No fish in this reef.");
                return;
            };
            let t = traits.of_mut(*kind);
            let now = t.applied_to(demo);
            egui::Grid::new("reef_minds_grid")
                .num_columns(2)
                .spacing([8.0, 6.0])
                .show(ui, |ui| {
                    for row in MIND_ROWS.iter().filter(|r| r.kinds.contains(kind)) {
                        mind_row_ui(ui, row, t, &now, rects);
                    }
                });
            let changed = *t != MindTraits::default();
            let r = ui
                .add_enabled(changed, egui::Button::new("The demo's own values"))
                .on_hover_text("Undo every change to this kind of fish");
            rects.insert("reef_minds_reset", r.rect);
            if r.clicked() {
                *t = MindTraits::default();
            }
        });
    rects.insert("reef_minds", header.header_response.rect);
}
