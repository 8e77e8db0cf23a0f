//! The reef's inspector under the tank: the selected fish's habits, its hunger,
//! libido and fear (bars and their history), its intention, memory and focus,
//! its motor command, its fish-eye view; and the reef's event log.

use eframe::egui;
use egui_plot::{Legend, Line, PlotPoints};

use super::WidgetRects;
use super::bottom_panel::plot_height_under_caption;
use super::bottom_panel::time_plot;
use super::reef_panel::{
    FEAR_COLOR, HUNGER_COLOR, LIBIDO_COLOR, intention_color, intention_sentence,
};
use crate::lab::Run;
use crate::sim::reef::mind::{FishKind, Intention, Liking, Sex, Target};
use crate::sim::reef::world::{ReefAnimal, ReefBody, ReefWorld};

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
/// scrolls). Returns the animal whose event line was clicked.
pub fn reef_inspector_ui(
    ui: &mut egui::Ui,
    run: &Run,
    selected: Option<u32>,
    fish_eye: Option<FishEyeView>,
    content_height: f32,
    rects: &mut WidgetRects,
) -> Option<u32> {
    let reef = run.reef()?;
    let animal = selected.and_then(|i| reef.animals().get(i as usize).map(|a| (i as usize, a)));
    // Every column fits `content_height`: the text columns scroll, the plot and the
    // event log take what their caption (one line) leaves.
    let line = ui.text_style_height(&egui::TextStyle::Body);
    let spacing = ui.spacing().item_spacing.y;
    let under_caption = plot_height_under_caption(content_height, line, spacing);
    let mut clicked = None;
    // On a narrow screen the columns keep their widths and scroll sideways.
    egui::ScrollArea::horizontal()
        .id_salt("reef_inspector_scroll")
        .show(ui, |ui| {
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
                            // (In the sideways scroll the available width is the screen's.)
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
                                let side =
                                    (under_caption - 2.0 * (line + spacing)).clamp(0.0, 150.0);
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
                    clicked = event_log_ui(ui, reef, under_caption, rects);
                });
            });
        });
    clicked
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
    let r = time_plot("reef_mind_history", height)
        .include_y(0.0)
        .include_y(1.0)
        .legend(Legend::default())
        .show(ui, |plot| {
            plot.line(Line::new("hunger", series(|s| s.hunger)).color(HUNGER_COLOR));
            plot.line(Line::new("libido", series(|s| s.libido)).color(LIBIDO_COLOR));
            plot.line(Line::new("fear", series(|s| s.fear)).color(FEAR_COLOR));
        });
    rects.insert("reef_mind_plot", r.response.rect);
}

/// The log, newest first; a click on a line selects and follows the animal it
/// is about (returned).
fn event_log_ui(
    ui: &mut egui::Ui,
    reef: &ReefWorld,
    height: f32,
    rects: &mut WidgetRects,
) -> Option<u32> {
    ui.label(egui::RichText::new("What happened").strong())
        .on_hover_text("Newest first: meals, chases, courtship. Click a line to follow who did it");
    let mut clicked = None;
    let r = egui::ScrollArea::vertical()
        .id_salt("reef_events")
        .max_height(height)
        .show(ui, |ui| {
            if reef.events().is_empty() {
                ui.label("Nothing yet.");
            }
            for (k, e) in reef.events().iter().rev().take(60).enumerate() {
                let minutes = (e.time_secs / 60.0).floor();
                let secs = e.time_secs - 60.0 * minutes;
                let subject = e.kind.subject();
                let who = reef
                    .animals()
                    .get(subject as usize)
                    .map_or_else(|| format!("animal {subject}"), |a| a.name(subject as usize));
                let line = ui
                    .add(
                        egui::Label::new(format!("{minutes:.0}:{secs:04.1}  {}", e.text))
                            .sense(egui::Sense::click()),
                    )
                    .on_hover_text(format!("Click to select and follow {who}"));
                if k == 0 {
                    rects.insert("reef_event_0", line.rect);
                }
                if line.clicked() {
                    clicked = Some(subject);
                }
            }
        });
    rects.insert("reef_events", r.inner_rect);
    clicked
}
