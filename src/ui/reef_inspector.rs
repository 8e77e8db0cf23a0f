//! The reef's inspector under the tank: the selected fish's habits, its hunger,
//! libido and fear (bars and their history), its intention, memory and focus,
//! its motor command, its fish-eye view; and the reef's event log.

use eframe::egui;
use egui_plot::{Legend, Line, PlotPoints};

use super::WidgetRects;
use super::bottom_panel::plot_height_under_caption;
use super::bottom_panel::time_plot;
use super::reef_panel::{
    FEAR_COLOR, HUNGER_COLOR, LIBIDO_COLOR, intention_color, intention_sentence, intention_word,
};
use crate::i18n::{fmt, localize_decimal, num, ts};
use crate::lab::Run;
use crate::sim::reef::events::phase_key;
use crate::sim::reef::mind::{FishKind, Intention, Liking, Sex, Target};
use crate::sim::reef::world::{ReefAnimal, ReefBody, ReefWorld};
use crate::tr;

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
    let fish_eye = fish_eye.as_ref();
    let reef = run.scene().reef()?;
    let animal = selected.and_then(|i| reef.animals().get(i as usize).map(|a| (i as usize, a)));
    // Every column fits `content_height`: the text columns scroll, the plot and the
    // event log take what their caption (one line) leaves.
    let line = ui.text_style_height(&egui::TextStyle::Body);
    let spacing = ui.spacing().item_spacing.y;
    let under_caption = plot_height_under_caption(content_height, line, spacing);
    let mut clicked = None;
    let columns = Columns {
        reef,
        animal,
        fish_eye,
        content_height,
        under_caption,
        line,
        spacing,
    };
    if ui.available_width() < NARROW_INSPECTOR_PT {
        // A phone: one column at a time, at the full width, chosen by tabs.
        let id = egui::Id::unique("reef_inspector_tab");
        let mut tab = ui.data_mut(|d| *d.get_temp_mut_or_default::<InspectorTab>(id));
        ui.horizontal(|ui| {
            for t in InspectorTab::ALL {
                if t.needs_fish() && animal.is_none() {
                    continue;
                }
                let r = ui.selectable_label(tab == t, t.label());
                rects.insert(&format!("reef_tab_{}", t.name()), r.rect);
                if r.clicked() {
                    tab = t;
                }
            }
        });
        if tab.needs_fish() && animal.is_none() {
            tab = InspectorTab::Mind;
        }
        ui.data_mut(|d| d.insert_temp(id, tab));
        let tabs_height = line + 2.0 * spacing + ui.spacing().button_padding.y * 2.0;
        let columns = Columns {
            content_height: (content_height - tabs_height).max(0.0),
            under_caption: (under_caption - tabs_height).max(0.0),
            ..columns
        };
        let width = ui.available_width();
        ui.vertical(|ui| {
            ui.set_width(width);
            match tab {
                InspectorTab::Mind => columns.mind(ui, rects),
                InspectorTab::History => columns.history(ui, rects),
                InspectorTab::Sees => columns.sees(ui, rects),
                InspectorTab::Log => clicked = columns.log(ui, rects),
            }
        });
        return clicked;
    }
    // Wider screens: the columns side by side; just too narrow, they keep
    // their widths and scroll sideways.
    egui::ScrollArea::horizontal()
        .id_salt("reef_inspector_scroll")
        .show(ui, |ui| {
            ui.horizontal_top(|ui| {
                ui.vertical(|ui| {
                    ui.set_width(300.0);
                    columns.mind(ui, rects);
                });
                if animal.is_some() {
                    ui.separator();
                    ui.vertical(|ui| {
                        ui.set_width((ui.available_width() - 560.0).max(220.0));
                        // (In the sideways scroll the available width is the screen's.)
                        columns.history(ui, rects);
                    });
                    ui.separator();
                    ui.vertical(|ui| {
                        ui.set_width(180.0);
                        columns.sees(ui, rects);
                    });
                }
                ui.separator();
                ui.vertical(|ui| {
                    clicked = columns.log(ui, rects);
                });
            });
        });
    clicked
}

/// Below this width, points, the inspector shows one column at a time under
/// tabs (760: the mind summary, the plot, the eye and the log side by side need
/// about 300 + 220 + 180 + 260 points; a phone held upright has 390).
pub const NARROW_INSPECTOR_PT: f32 = 760.0;

/// The inspector's column shown on a narrow screen.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum InspectorTab {
    #[default]
    Mind,
    History,
    Sees,
    Log,
}

impl InspectorTab {
    const ALL: [Self; 4] = [Self::Mind, Self::History, Self::Sees, Self::Log];

    fn label(self) -> &'static str {
        match self {
            Self::Mind => ts("reef-tab-mind"),
            Self::History => ts("reef-tab-history"),
            Self::Sees => ts("reef-tab-sees"),
            Self::Log => ts("reef-tab-log"),
        }
    }

    fn name(self) -> &'static str {
        match self {
            Self::Mind => "mind",
            Self::History => "history",
            Self::Sees => "sees",
            Self::Log => "log",
        }
    }

    /// Only shown with a fish selected.
    fn needs_fish(self) -> bool {
        matches!(self, Self::History | Self::Sees)
    }
}

/// The inspector's columns, drawn side by side or one at a time.
#[derive(Clone, Copy)]
struct Columns<'a> {
    reef: &'a ReefWorld,
    animal: Option<(usize, &'a ReefAnimal)>,
    fish_eye: Option<&'a FishEyeView<'a>>,
    content_height: f32,
    /// The height left for a plot under a one-line caption.
    under_caption: f32,
    line: f32,
    spacing: f32,
}

impl Columns<'_> {
    /// The selected fish's mind, or the reef's summary and a hint.
    fn mind(&self, ui: &mut egui::Ui, rects: &mut WidgetRects) {
        let reef = self.reef;
        match self.animal {
            Some((i, a)) => {
                egui::ScrollArea::vertical()
                    .id_salt("reef_mind_summary")
                    .max_height(self.content_height)
                    .show(ui, |ui| mind_summary_ui(ui, reef, i, a, rects));
            }
            None => {
                egui::ScrollArea::vertical()
                    .id_salt("reef_summary")
                    .max_height(self.content_height)
                    .show(ui, |ui| {
                        let counts = reef.counts();
                        ui.label(egui::RichText::new(ts("reef-heading")).strong());
                        ui.label(tr!(
                            "reef-summary",
                            animals = reef.alive_count(),
                            plankton = reef.food().len(),
                            eaten = counts.prey_eaten,
                            spawnings = counts.spawnings,
                        ));
                        ui.label(ts("reef-summary-hint"));
                    });
            }
        }
    }

    fn history(&self, ui: &mut egui::Ui, rects: &mut WidgetRects) {
        if let Some((_, a)) = self.animal {
            history_plot_ui(ui, a, self.under_caption, rects);
        }
    }

    fn sees(&self, ui: &mut egui::Ui, rects: &mut WidgetRects) {
        let Some((_, a)) = self.animal else {
            return;
        };
        ui.label(egui::RichText::new(ts("reef-sees")).strong())
            .on_hover_text(ts("reef-sees.help"));
        if let Some(view) = self.fish_eye {
            // The eye and the two lines under it fit under the caption.
            let side = (self.under_caption - 2.0 * (self.line + self.spacing)).clamp(0.0, 150.0);
            let r =
                ui.add(egui::Image::new(view.texture).fit_to_exact_size(egui::vec2(side, side)));
            rects.insert("fish_eye", r.rect);
            ui.label(tr!(
                "reef-brightness",
                value = num(f64::from(view.mean_brightness), 2)
            ));
        }
        ui.label(tr!(
            "reef-water",
            value = num(f64::from(a.temperature_c), 1)
        ));
    }

    fn log(&self, ui: &mut egui::Ui, rects: &mut WidgetRects) -> Option<u32> {
        event_log_ui(ui, self.reef, self.under_caption, rects)
    }
}

fn mind_summary_ui(
    ui: &mut egui::Ui,
    reef: &ReefWorld,
    i: usize,
    a: &ReefAnimal,
    rects: &mut WidgetRects,
) {
    let h = &a.habits;
    // Selectors of the catalogue's messages, not words.
    let sex = match h.sex {
        Sex::Male => "male",
        Sex::Female => "female",
    };
    let title = if a.alive {
        // (`FishKind::label` is an id: "predator", "prey", "pacifist".)
        tr!(
            "reef-inspector-title",
            name = a.name(i),
            sex = sex,
            kind = h.kind.label()
        )
    } else {
        tr!("reef-inspector-eaten", name = a.name(i))
    };
    let r = ui.label(egui::RichText::new(title).strong());
    rects.insert("reef_inspector", r.rect);
    let liking = |l: Liking, high: &'static str, low: &'static str| match l {
        Liking::Indifferent => "any",
        Liking::High => high,
        Liking::Low => low,
    };
    ui.label(tr!(
        "reef-inspector-habits",
        species = h.species,
        length = num(f64::from(a.body.body_length_m()), 2),
        light = liking(h.light, "bright", "dim"),
        temperature = liking(h.temperature, "warm", "cool"),
        schools = if h.schools { "yes" } else { "no" },
    ))
    .on_hover_text(ts("reef-inspector-habits.help"));
    for (name, key, value, color, help) in [
        (
            ts("reef-inspector-hunger"),
            "hunger",
            a.mental.hunger,
            HUNGER_COLOR,
            ts("reef-inspector-hunger.help"),
        ),
        (
            ts("reef-inspector-libido"),
            "libido",
            a.mental.libido,
            LIBIDO_COLOR,
            ts("reef-inspector-libido.help"),
        ),
        (
            ts("reef-inspector-fear"),
            "fear",
            a.mental.fear,
            FEAR_COLOR,
            ts("reef-inspector-fear.help"),
        ),
    ] {
        ui.horizontal(|ui| {
            ui.label(format!("{name:<7}")).on_hover_text(help);
            // The value beside the bar, not on it: text over the coloured
            // fill and the dark track could not keep 4.5:1 on both.
            let bar = egui::ProgressBar::new(value.clamp(0.0, 1.0))
                .fill(color)
                .desired_width(180.0);
            let r = ui.add(bar).on_hover_text(help);
            ui.label(egui::RichText::new(fmt(f64::from(value), 2)).monospace());
            rects.insert(&format!("reef_bar_{key}"), r.rect);
        });
    }
    let focus = a.focus;
    let sentence = match (focus.intention, h.kind) {
        (Intention::Eat, FishKind::Predator) => ts("reef-intention-hunt"),
        (intention, _) => intention_sentence(intention),
    };
    let r = ui.label(
        egui::RichText::new(tr!(
            "reef-inspector-intends",
            intention = intention_word(focus.intention),
            sentence = sentence
        ))
        .color(intention_color(focus.intention)),
    );
    rects.insert("reef_intention", r.rect);
    ui.label(tr!(
        "reef-inspector-focus",
        target = target_text(reef, focus.target)
    ));
    match a.generator.memory {
        Some(m) => ui.label(tr!(
            "reef-inspector-remembers",
            intention = intention_word(m.intention),
            target = target_text(reef, m.target)
        )),
        None => ui.label(ts("reef-inspector-remembers-nothing")),
    };
    if let Some(pair) = reef.pair_of(i) {
        let partner = if pair.male as usize == i {
            pair.female
        } else {
            pair.male
        };
        ui.label(tr!(
            "reef-inspector-courting",
            phase = phase_key(pair.phase),
            partner = target_text(reef, Some(Target::Animal(partner))),
            count = pair.count
        ));
    }
    if let ReefBody::Physical(p) = &a.body {
        let m = p.motor();
        ui.label(tr!(
            "reef-inspector-muscles",
            speed = num(f64::from(100.0 * m.speed_fraction), 0),
            turning = if m.turning { "yes" } else { "no" },
            // A whole number with its sign: the same in every language.
            fins = format!(
                "{:+.0}",
                (m.fins.left_angle_rad - std::f32::consts::FRAC_PI_2).to_degrees()
            )
        ))
        .on_hover_text(ts("reef-inspector-muscles.help"));
    } else {
        ui.label(tr!(
            "reef-inspector-speed",
            speed = num(f64::from(a.body.velocity_m_per_s().length()), 2)
        ));
    }
}

/// "plankton 12", "shark 3", "the glass", "rock 1", "nothing in
/// particular", in the language in force.
pub fn target_text(reef: &ReefWorld, target: Option<Target>) -> String {
    match target {
        None => tr!("reef-target-nothing"),
        // Ids as written, not as numbers (no thousands separator).
        Some(Target::Food(id)) => tr!("reef-target-plankton", id = id.to_string()),
        Some(Target::Animal(j)) => reef.animals().get(j as usize).map_or_else(
            || tr!("reef-animal-number", index = j),
            |o| o.name(j as usize),
        ),
        Some(Target::Obstacle(k)) => tr!("reef-target-rock", id = k.to_string()),
        Some(Target::Glass) => tr!("reef-target-glass"),
    }
}

fn history_plot_ui(ui: &mut egui::Ui, a: &ReefAnimal, height: f32, rects: &mut WidgetRects) {
    ui.add(egui::Label::new(egui::RichText::new(ts("reef-inspector-history")).strong()).truncate());
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
            // Named in the legend and told apart by the line as well as the
            // colour: hunger solid, libido dashed, fear dotted.
            plot.line(
                Line::new(ts("reef-inspector-hunger.plot"), series(|s| s.hunger))
                    .color(HUNGER_COLOR)
                    .width(2.0),
            );
            plot.line(
                Line::new(ts("reef-inspector-libido.plot"), series(|s| s.libido))
                    .color(LIBIDO_COLOR)
                    .style(egui_plot::LineStyle::dashed_dense())
                    .width(2.0),
            );
            plot.line(
                Line::new(ts("reef-inspector-fear.plot"), series(|s| s.fear))
                    .color(FEAR_COLOR)
                    .style(egui_plot::LineStyle::dotted_dense())
                    .width(2.0),
            );
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
    ui.label(egui::RichText::new(ts("reef-log")).strong())
        .on_hover_text(ts("reef-log.help"));
    let mut clicked = None;
    let r = egui::ScrollArea::vertical()
        .id_salt("reef_events")
        .max_height(height)
        .show(ui, |ui| {
            if reef.events().is_empty() {
                ui.label(ts("reef-log-empty"));
            }
            for (k, e) in reef.events().iter().rev().take(60).enumerate() {
                let minutes = (e.time_secs / 60.0).floor();
                let secs = e.time_secs - 60.0 * minutes;
                let subject = e.kind.subject();
                let who = reef.animals().get(subject as usize).map_or_else(
                    || tr!("reef-animal-number", index = subject),
                    |a| a.name(subject as usize),
                );
                // The time with the language's decimal mark, the line in
                // the language in force.
                let time = localize_decimal(&format!("{minutes:.0}:{secs:04.1}"));
                let line = ui
                    .add(
                        egui::Label::new(format!("{time}  {}", e.words()))
                            .sense(egui::Sense::click()),
                    )
                    .on_hover_text(tr!("reef-log-follow", who = who));
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
