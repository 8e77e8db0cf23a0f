//! Live numbers and plots of the school's metrics (egui_plot), one coloured line per
//! tank, so students see in the curves why a school and a crowd of loners differ.

use eframe::egui;
use egui_plot::{Line, Plot, PlotPoints};

use super::WidgetRects;
use super::bottom_panel::plot_height_under_caption;
use crate::lab::Run;
use crate::metrics_history::MetricsSample;
use crate::settings::Side;

/// Line colour of each tank, also used for its label over the 3D view.
pub fn side_color(side: Side) -> egui::Color32 {
    match side {
        Side::Left => egui::Color32::from_rgb(255, 170, 60),
        Side::Right => egui::Color32::from_rgb(90, 200, 255),
    }
}

/// One plotted metric: title, hover help, how to read it from a sample, fixed y range.
struct Metric {
    title: &'static str,
    help: &'static str,
    value: fn(&MetricsSample) -> f64,
    y_range: Option<(f64, f64)>,
}

const METRICS: [Metric; 5] = [
    Metric {
        title: "Polarization",
        help: "How much the fish all swim the same way: the length of the average of their \
               headings. 1 when every fish swims the same way, near 0 when they point every \
               which way (or circle).",
        value: |s| f64::from(s.polarization),
        y_range: Some((0.0, 1.0)),
    },
    Metric {
        title: "Milling",
        help: "How much each group swims round and round its own centre like a whirlpool \
               (measured about the centre of each group, not of the tank, and averaged over \
               all fish; groups of fewer than 5 count 0). 1 for perfect whirlpools, near 0 \
               for groups swimming straight or fish milling about at random.",
        value: |s| f64::from(s.milling),
        y_range: Some((0.0, 1.0)),
    },
    Metric {
        title: "Nearest neighbour (body lengths)",
        help: "How far, on average, each fish is from its closest neighbour, measured in fish lengths. \
               Schooling fish keep about one body length.",
        value: |s| f64::from(s.nnd_body_lengths),
        y_range: None,
    },
    Metric {
        title: "Groups",
        help: "How many separate groups there are: fish closer than two body lengths belong \
               together, so a loner is a group of one.",
        value: |s| f64::from(s.groups),
        y_range: None,
    },
    Metric {
        title: "Mean speed (m/s)",
        help: "How fast the fish swim on average, in metres per second.",
        value: |s| f64::from(s.mean_speed),
        y_range: None,
    },
];

/// The height the metrics panel under the tank would like, points (see
/// [`super::bottom_panel::bottom_panel_height`] for what it gets).
pub const METRICS_PANEL_HEIGHT: f32 = 180.0;

/// Draws the numbers and plots for `runs` (one or two tanks); `labels` names each.
/// The plots fill what the numbers leave of `content_height` points.
pub fn metrics_panel_ui(
    ui: &mut egui::Ui,
    runs: &[Run],
    labels: &[String],
    content_height: f32,
    rects: &mut WidgetRects,
) {
    let numbers = egui::Grid::new("metric_numbers")
        .num_columns(METRICS.len() + 2)
        .spacing([14.0, 2.0])
        .show(ui, |ui| {
            ui.strong("Tank");
            for metric in &METRICS {
                ui.strong(metric.title).on_hover_text(metric.help);
            }
            ui.strong("Urge chosen (share of moves)").on_hover_text(
                "How often each urge was used: containment, alignment, cohesion, \
                 separation, avoidance. In the lottery modes this follows the weights.",
            );
            ui.end_row();
            for (run, label) in runs.iter().zip(labels) {
                let latest = run.metrics();
                ui.colored_label(side_color(run.side()), label);
                for metric in &METRICS {
                    let value = (metric.value)(&latest);
                    ui.monospace(if metric.title == "Groups" {
                        format!("{value:.0}")
                    } else {
                        format!("{value:.2}")
                    });
                }
                let shares = latest.force_frequencies.to_array();
                ui.monospace(
                    shares
                        .iter()
                        .map(|s| format!("{:>3.0}%", s * 100.0))
                        .collect::<Vec<_>>()
                        .join(" "),
                );
                ui.end_row();
            }
        });
    rects.insert("metric_numbers", numbers.response.rect);

    let plot_width =
        ((ui.available_width() - 8.0 * METRICS.len() as f32) / METRICS.len() as f32).max(120.0);
    let spacing = ui.spacing().item_spacing.y;
    let caption_height = ui.text_style_height(&egui::TextStyle::Small);
    let plot_height = plot_height_under_caption(
        content_height - numbers.response.rect.height() - spacing,
        caption_height,
        spacing,
    );
    let link = egui::Id::unique("metrics_time_axis");
    ui.horizontal(|ui| {
        for (index, metric) in METRICS.iter().enumerate() {
            ui.vertical(|ui| {
                ui.small(metric.title).on_hover_text(metric.help);
                let mut plot = Plot::new(("metric_plot", index))
                    .width(plot_width)
                    .height(plot_height)
                    .allow_scroll(false)
                    .allow_drag(false)
                    .allow_zoom(false)
                    .allow_boxed_zoom(false)
                    .show_axes([true, true])
                    .link_axis(link, [true, false])
                    .x_axis_formatter(|mark, _| format!("{:.0}s", mark.value));
                if let Some((lo, hi)) = metric.y_range {
                    plot = plot.include_y(lo).include_y(hi);
                } else {
                    plot = plot.include_y(0.0);
                }
                let response = plot.show(ui, |plot_ui| {
                    for (run, label) in runs.iter().zip(labels) {
                        let points: PlotPoints = run
                            .history()
                            .samples()
                            .map(|s| [s.time_secs, (metric.value)(s)])
                            .collect();
                        plot_ui.line(
                            Line::new(label.clone(), points)
                                .color(side_color(run.side()))
                                .width(1.5),
                        );
                    }
                });
                rects.insert(&format!("plot_{index}"), response.response.rect);
            });
        }
    });
}
