//! The confusion effect and joint flight as switches, in the schooling lab's
//! and the reef's panels alike (`Settings::predation`), with *Paper only*,
//! which turns both off.

use eframe::egui;

use crate::i18n::ts;
use crate::settings::PredationSettings;
use crate::ui::WidgetRects;
use crate::ui::studio_panel::control;

/// The two switches and the *Paper only* button.
pub fn predation_ui(ui: &mut egui::Ui, predation: &mut PredationSettings, rects: &mut WidgetRects) {
    ui.label(egui::RichText::new(ts("predation-heading")).strong())
        .on_hover_text(ts("predation-heading.help"));
    ui.horizontal_wrapped(|ui| {
        control(ui, rects, "predation.confusion", |ui, rects| {
            let r = ui
                .checkbox(&mut predation.confusion, ts("predation-confusion"))
                .on_hover_text(ts("predation-confusion.help"));
            rects.insert("predation_confusion", r.rect);
        });
        control(ui, rects, "predation.joint_flight", |ui, rects| {
            let r = ui
                .checkbox(&mut predation.joint_flight, ts("predation-joint-flight"))
                .on_hover_text(ts("predation-joint-flight.help"));
            rects.insert("predation_joint_flight", r.rect);
        });
    });
    let r = ui
        .add_enabled(
            !predation.is_paper_only(),
            egui::Button::new(ts("predation-paper-only")),
        )
        .on_hover_text(ts("predation-paper-only.help"));
    rects.insert("predation_paper_only", r.rect);
    if r.clicked() {
        *predation = PredationSettings::PAPER_ONLY;
    }
}
