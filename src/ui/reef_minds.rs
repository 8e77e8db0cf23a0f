//! The reef's *Minds* section of the side panel: each kind of fish's hunger,
//! libido and fear constants and its character, over the demo's own values.

use eframe::egui;

use super::WidgetRects;
use crate::sim::reef::mind::habits::{
    COURAGEOUS_BOX_BODY_LENGTHS, DEFAULT_BOX_BODY_LENGTHS, DEFAULT_PERSISTENCE_BODY_LENGTHS,
    DEVOTED_BODY_LENGTHS, FICKLE_BODY_LENGTHS, KindTraits, MindTraits, TIMID_BOX_BODY_LENGTHS,
};
use crate::sim::reef::mind::mental_state::{
    CALM_DIGESTION_RATE, CALM_LIBIDO_RATE, MANIC_LIBIDO_RATE, NOMINAL_DIGESTION_RATE,
    NOMINAL_LIBIDO_RATE, RAVENOUS_DIGESTION_RATE,
};
use crate::sim::reef::mind::{FishKind, Habits};

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

/// The control of one row of the *Minds* grid (its label is the caller's): a
/// slider over the trait's range and its named values as buttons; what the
/// teacher picks goes into `traits`.
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
                    let kind_name = serde_json::to_value(*kind)
                        .ok()
                        .and_then(|v| v.as_str().map(str::to_owned))
                        .unwrap_or_default();
                    for row in MIND_ROWS.iter().filter(|r| r.kinds.contains(kind)) {
                        // The studio's rules name it `reef.traits.prey.fear_threshold`.
                        let key = format!("reef.traits.{kind_name}.{}", row.name);
                        super::studio_panel::control_row(
                            ui,
                            rects,
                            &key,
                            |ui| {
                                ui.label(row.label).on_hover_text(row.help);
                            },
                            |ui, rects| mind_row_ui(ui, row, t, &now, rects),
                        );
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
