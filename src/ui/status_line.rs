//! The status line under the aquarium: frame rate, simulation rate, GPU tier, time.

use eframe::egui;

use crate::automation::StateReport;
use crate::i18n::{num, ts};
use crate::render::RenderCaps;
use crate::tr;

/// Draws the status line, wrapped onto more lines in a narrow window (a phone,
/// or a zoomed page) so that time, count and "paused" stay in sight.
/// `count_is_mystery`: a student must not read the number of fish (the
/// teacher made it a mystery value).
pub fn status_line_ui(
    ui: &mut egui::Ui,
    state: &StateReport,
    caps: RenderCaps,
    count_is_mystery: bool,
) {
    ui.horizontal_wrapped(|ui| {
        item(ui, tr!("status-fps", fps = num(state.fps, 0))).on_hover_text(ts("status-fps.help"));
        ui.separator();
        item(ui, tr!("status-steps", steps = num(state.steps_per_sec, 0)))
            .on_hover_text(ts("status-steps.help"));
        ui.separator();
        let aa = if caps.msaa_samples > 1 {
            format!(", {}× MSAA", caps.msaa_samples)
        } else {
            String::new()
        };
        let detail = state
            .scene_detail
            .filter(|d| d.scale < 1.0)
            .map_or(String::new(), |d| {
                // The same measure as View › Tank detail: the share of the pixels.
                tr!(
                    "status-tank-pixels",
                    percent = num(f64::from(d.scale * d.scale * 100.0), 0)
                )
            });
        item(ui, format!("{}{aa}{detail}", caps.tier.label()))
            .on_hover_text(ts("status-graphics.help"));
        ui.separator();
        item(ui, tr!("status-time", seconds = num(state.time_secs, 1)))
            .on_hover_text(ts("status-time.help"));
        ui.separator();
        if count_is_mystery {
            item(ui, ts("status-fish-mystery")).on_hover_text(ts("status-fish-mystery.help"));
        } else {
            item(ui, tr!("fish-count", count = state.fish_count));
        }
        if state.paused {
            ui.separator();
            item(ui, egui::RichText::new(ts("status-paused")).strong());
        }
        if state.slowed_down {
            ui.separator();
            item(
                ui,
                egui::RichText::new(ts("status-slowed")).color(ui.visuals().warn_fg_color),
            )
            .on_hover_text(ts("status-slowed.help"));
        }
    });
}

/// One item of the status line, kept whole: a narrow window moves it to the
/// next line rather than breaking it in two ("tank at 25 % of the / pixels").
fn item(ui: &mut egui::Ui, text: impl Into<egui::WidgetText>) -> egui::Response {
    ui.add(egui::Label::new(text).wrap_mode(egui::TextWrapMode::Extend))
}
