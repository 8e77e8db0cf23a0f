//! The reef's *Minds* section of the side panel: each kind of fish's hunger,
//! libido and fear constants and its character, over the demo's own values;
//! each row is drawn from its entry in [`MindTraits::NUMBERS`]
//! (`settings/minds.rs`), the rows a kind shows from [`MindTraits::shown_for`].

use eframe::egui;

use super::WidgetRects;
use super::setting_slider::setting_row;
use crate::i18n::ts;
use crate::settings::reef::ReefSettings;
use crate::sim::reef::mind::habits::{KindTraits, MindTraits};
use crate::sim::reef::mind::{FishKind, Habits};

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
    let header = egui::CollapsingHeader::new(egui::RichText::new(ts("reef-minds")).strong())
        .id_salt("reef_minds")
        .default_open(false)
        .show(ui, |ui| {
            ui.label(egui::RichText::new(ts("reef-minds.help")).small());
            if !demo_habits.iter().any(|h| h.kind == *kind)
                && let Some(first) = demo_habits.first()
            {
                *kind = first.kind;
            }
            ui.horizontal(|ui| {
                for (k, label) in [
                    (FishKind::Predator, ts("reef-minds-sharks")),
                    (FishKind::Prey, ts("reef-minds-prey")),
                    (FishKind::Pacifist, ts("reef-minds-pacifists")),
                ] {
                    let present = demo_habits.iter().any(|h| h.kind == k);
                    let r = ui
                        .add_enabled(present, egui::Button::selectable(*kind == k, label))
                        .on_hover_text(match k {
                            FishKind::Predator => ts("reef-minds-sharks.help"),
                            FishKind::Prey => ts("reef-minds-prey.help"),
                            FishKind::Pacifist => ts("reef-minds-pacifists.help"),
                        })
                        .on_disabled_hover_text(ts("reef-minds-none-here"));
                    rects.insert(&format!("reef_minds_{}", k.label()), r.rect);
                    if r.clicked() {
                        *kind = k;
                    }
                }
            });
            let Some(demo) = demo_habits.iter().find(|h| h.kind == *kind).copied() else {
                ui.label(ts("reef-minds-no-fish"));
                return;
            };
            let t = traits.of_mut(*kind);
            // Each row shows what the kind's fish have (the demo's own, with
            // the teacher's changes) and puts a change into the teacher's.
            let mut now = MindTraits::of_fish(&t.applied_to(demo));
            let prefix = MindTraits::prefix(ReefSettings::PREFIX, *kind);
            egui::Grid::new("reef_minds_grid")
                .num_columns(2)
                .spacing([8.0, 6.0])
                .show(ui, |ui| {
                    for setting in MindTraits::shown_for(*kind) {
                        if setting_row(ui, rects, &prefix, setting, &mut now) {
                            setting.set(t, setting.value(&now));
                        }
                    }
                });
            let changed = *t != MindTraits::default();
            let r = ui
                .add_enabled(changed, egui::Button::new(ts("reef-minds-reset")))
                .on_hover_text(ts("reef-minds-reset.help"));
            rects.insert("reef_minds_reset", r.rect);
            if r.clicked() {
                *t = MindTraits::default();
            }
        });
    rects.insert("reef_minds", header.header_response.rect);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::studio::Studio;
    use crate::sim::reef::mind::Sex;
    use crate::ui::studio_panel::draw_controls_for_test;

    /// The section opened on `kind`, over a demo with every kind: the names of
    /// the widgets it draws.
    fn drawn(kind: FishKind) -> Vec<String> {
        let demo: Vec<Habits> = FishKind::ALL
            .iter()
            .map(|&k| Habits::new(k, Sex::Female, 0))
            .collect();
        let mut traits = KindTraits::default();
        let mut kind = kind;
        let (rects, _) = draw_controls_for_test(&Studio::default(), false, |ui, rects| {
            // Every collapsed section open.
            ui.ctx().memory_mut(|m| m.set_everything_is_visible(true));
            minds_ui(ui, &mut traits, &mut kind, &demo, rects);
        });
        assert_eq!(traits, KindTraits::default(), "drawing changes nothing");
        rects.iter().map(|(name, _)| name.clone()).collect()
    }

    /// Every widget the section drew before its rows came from the settings
    /// table is still drawn under its name (the browser tests click them).
    #[test]
    fn each_kind_draws_its_rows_under_the_names_they_always_had() {
        let hunger = ["hunger", "hunger_calm", "hunger_nominal", "hunger_ravenous"];
        let libido = [
            "libido",
            "libido_calm",
            "libido_nominal",
            "libido_sexual_mania",
        ];
        let fear = ["fear_distance", "alarm"];
        let character = [
            "urge",
            "box_timid",
            "box_ordinary",
            "box_courageous",
            "persistence_fickle",
            "persistence_ordinary",
            "persistence_devoted",
        ];
        let section = ["predator", "prey", "pacifist", "reset"];
        let predator: Vec<&str> = [&hunger[..], &["appetite"], &character, &section].concat();
        let prey: Vec<&str> = [
            &hunger[..],
            &["appetite"],
            &fear,
            &["panic"],
            &character,
            &section,
        ]
        .concat();
        let pacifist: Vec<&str> = [
            &hunger[..],
            &libido,
            &["appetite"],
            &fear,
            &character,
            &section,
        ]
        .concat();
        for (kind, rows) in [
            (FishKind::Predator, predator),
            (FishKind::Prey, prey),
            (FishKind::Pacifist, pacifist),
        ] {
            let mut wanted: Vec<String> = rows.iter().map(|r| format!("reef_minds_{r}")).collect();
            wanted.push("reef_minds".to_owned());
            wanted.sort();
            let mut got = drawn(kind);
            got.sort();
            assert_eq!(got, wanted, "{kind:?}");
        }
    }
}
