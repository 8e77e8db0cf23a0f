//! The status line under the aquarium: frame rate, simulation rate, GPU tier, time.

use eframe::egui;

use crate::automation::StateReport;
use crate::render::RenderCaps;

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
        ui.label(format!("{:.0} FPS", state.fps))
            .on_hover_text("Pictures drawn per second");
        ui.separator();
        ui.label(format!("{:.0} steps/s", state.steps_per_sec))
            .on_hover_text("Simulation steps computed per second of real time");
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
                format!(", tank at {:.0} % of the pixels", d.scale * d.scale * 100.0)
            });
        ui.label(format!("{}{aa}{detail}", caps.tier.label()))
            .on_hover_text(
                "The graphics system your browser gave Shoal: WebGPU is the newest, \
             WebGL2 works everywhere else. \"tank at N % of the pixels\": the graphics cannot keep \
             up, so the tank is drawn with fewer pixels to stay smooth (View › Tank \
             detail)",
            );
        ui.separator();
        ui.label(format!("t = {:.1} s", state.time_secs))
            .on_hover_text("Simulated time since the start");
        ui.separator();
        if count_is_mystery {
            ui.label("? fish").on_hover_text(
                "Your teacher hid the number of fish: count them, or work it out from what \
                 they do",
            );
        } else {
            ui.label(format!("{} fish", state.fish_count));
        }
        if state.paused {
            ui.separator();
            ui.label(egui::RichText::new("paused").strong());
        }
        if state.slowed_down {
            ui.separator();
            ui.label(egui::RichText::new("slowed down").color(ui.visuals().warn_fg_color))
                .on_hover_text(
                    "This computer cannot keep up with the chosen speed, so the simulation \
                     runs slower than asked (nothing is skipped: the fish just move in slow \
                     motion). Try fewer fish or a lower speed.",
                );
        }
    });
}
