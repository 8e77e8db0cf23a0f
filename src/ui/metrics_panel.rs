//! Live numbers and plots of the school's metrics (egui_plot), one line per tank
//! (the left tank solid orange, the right dashed sky blue: never told apart by
//! colour alone), so students see in the curves why a school and a crowd of
//! loners differ.

use eframe::egui;
use egui_plot::{Line, Plot, PlotPoints};

use super::WidgetRects;
use super::bottom_panel::{plot_height_under_caption, readable_marks, time_plot};
use crate::i18n::{fmt, ts};
use crate::lab::Run;
use crate::metrics_history::MetricsSample;
use crate::settings::Side;
use crate::tr;

/// Line colour of each tank (Okabe–Ito orange and sky blue), also used for its
/// label over the 3D view; its line style is [`super::palette::side_series`]'s.
pub fn side_color(side: Side) -> egui::Color32 {
    super::palette::side_series(side).color
}

/// How a tank's values are marked in a caption when two tanks are compared:
/// a sample of its line ("—— 0.83", "– – 0.45"), so the numbers match the
/// lines without the colour.
fn caption_value(text: &str, side: Side, comparing: bool) -> String {
    if comparing {
        format!(
            "{} {text}",
            super::palette::line_glyph(super::palette::side_series(side).line)
        )
    } else {
        text.to_owned()
    }
}

/// One plotted metric: title, hover help (their message ids), how to read it
/// from a sample, fixed y range.
struct Metric {
    title: &'static str,
    /// The title's short form, if it has one (`.short`: without its unit).
    short: Option<&'static str>,
    help: &'static str,
    value: fn(&MetricsSample) -> f64,
    y_range: Option<(f64, f64)>,
}

const METRICS: [Metric; 5] = [
    Metric {
        title: "metrics-polarization",
        short: None,
        help: "metrics-polarization.help",
        value: |s| f64::from(s.polarization),
        y_range: Some((0.0, 1.0)),
    },
    Metric {
        title: "metrics-milling",
        short: None,
        help: "metrics-milling.help",
        value: |s| f64::from(s.milling),
        y_range: Some((0.0, 1.0)),
    },
    Metric {
        title: "metrics-nearest",
        short: Some("metrics-nearest.short"),
        help: "metrics-nearest.help",
        value: |s| f64::from(s.nnd_body_lengths),
        y_range: None,
    },
    Metric {
        title: "metrics-groups",
        short: None,
        help: "metrics-groups.help",
        value: |s| f64::from(s.groups),
        y_range: None,
    },
    Metric {
        title: "metrics-speed",
        short: Some("metrics-speed.short"),
        help: "metrics-speed.help",
        value: |s| f64::from(s.mean_speed),
        y_range: None,
    },
];

/// A tank's line in words, for hover help: "solid" or "dashed".
fn line_name(side: Side) -> &'static str {
    match super::palette::side_series(side).line {
        egui_plot::LineStyle::Solid => ts("metrics-line-solid"),
        egui_plot::LineStyle::Dashed { .. } => ts("metrics-line-dashed"),
        egui_plot::LineStyle::Dotted { .. } => ts("metrics-line-dotted"),
    }
}

/// The height the metrics panel under the tank would like, points (see
/// [`super::bottom_panel::bottom_panel_height`] for what it gets: at most 30 % of
/// the window). 260: plots a class reads from the back of the room.
pub const METRICS_PANEL_HEIGHT: f32 = 260.0;

/// The urges' short names' message ids, in `Force::ALL` order (the bar
/// chart's axis); [`urge_name`] gives the words.
pub const URGE_NAMES: [&str; 5] = [
    "metrics-urge-contain",
    "metrics-urge-align",
    "metrics-urge-cohere",
    "metrics-urge-separate",
    "metrics-urge-avoid",
];

/// The short name of urge `k` (in `Force::ALL` order) in the language in force.
pub fn urge_name(k: usize) -> &'static str {
    ts(URGE_NAMES[k])
}

/// Each urge's colour wherever an urge is drawn on its own (the selected
/// fish's arrows and table), in [`URGE_NAMES`] order: containment grey-blue,
/// alignment green, cohesion violet, separation red, avoidance teal (none is a
/// tank's orange or blue, the selection's yellow or the result's white).
pub const URGE_COLORS: [egui::Color32; 5] = [
    egui::Color32::from_rgb(170, 175, 215),
    egui::Color32::from_rgb(110, 230, 120),
    egui::Color32::from_rgb(205, 140, 255),
    egui::Color32::from_rgb(255, 100, 100),
    egui::Color32::from_rgb(60, 220, 200),
];

/// Draws the six plots for `runs` (one or two tanks; `labels` names each): the
/// five school metrics over time and the urges used, each under a caption with
/// its current value per tank in the tank's colour, in `content_height` points.
pub fn metrics_panel_ui(
    ui: &mut egui::Ui,
    runs: &[Run],
    labels: &[String],
    content_height: f32,
    rects: &mut WidgetRects,
) {
    let columns = METRICS.len() + 1;
    let spacing = ui.spacing().item_spacing;
    let plot_width =
        ((ui.available_width() - spacing.x * (columns as f32 - 1.0)) / columns as f32).max(150.0);
    let caption_height = ui.spacing().interact_size.y;
    let plot_height = plot_height_under_caption(content_height, caption_height, spacing.y);
    let link = egui::Id::unique("metrics_time_axis");
    let latest: Vec<MetricsSample> = runs.iter().map(Run::metrics).collect();
    // On a narrow screen the plots keep a readable width and scroll sideways.
    let scroll = egui::ScrollArea::horizontal()
        .id_salt("metric_plots_scroll")
        .show(ui, |ui| {
            ui.horizontal(|ui| {
                for (index, metric) in METRICS.iter().enumerate() {
                    ui.vertical(|ui| {
                        ui.set_width(plot_width);
                        caption_ui(
                            ui,
                            plot_width,
                            caption_height,
                            ts(metric.title),
                            metric.short.map(ts),
                            ts(metric.help),
                            |ui| {
                                // Right to left: the last tank first.
                                for ((run, sample), label) in
                                    runs.iter().zip(&latest).zip(labels).rev()
                                {
                                    let value = (metric.value)(sample);
                                    let text = if metric.title == "metrics-groups" {
                                        fmt(value, 0)
                                    } else {
                                        fmt(value, 2)
                                    };
                                    ui.label(
                                        egui::RichText::new(caption_value(
                                            &text,
                                            run.side(),
                                            runs.len() > 1,
                                        ))
                                        .monospace()
                                        .strong()
                                        .color(side_color(run.side())),
                                    )
                                    .on_hover_text(tr!(
                                        "metrics-tank-line",
                                        label = label,
                                        line = line_name(run.side())
                                    ));
                                }
                            },
                        );
                        let mut plot = time_plot(("metric_plot", index), plot_height)
                            .width(plot_width)
                            .link_axis(link, [true, false]);
                        if let Some((lo, hi)) = metric.y_range {
                            plot = plot.include_y(lo).include_y(hi);
                        } else {
                            plot = plot.include_y(0.0);
                        }
                        if metric.title == "metrics-groups" {
                            // A count: marks at whole groups (1, 2, 5 …), never 1.5.
                            plot = plot.y_grid_spacer(super::investigation_plot::whole_marks);
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
                                        .style(super::palette::side_series(run.side()).line)
                                        .width(2.0),
                                );
                            }
                        });
                        rects.insert(&format!("plot_{index}"), response.response.rect);
                    });
                }
                ui.vertical(|ui| {
                    ui.set_width(plot_width);
                    urges_plot_ui(
                        ui,
                        runs,
                        &latest,
                        labels,
                        caption_height,
                        plot_height,
                        rects,
                    );
                });
            });
        });
    rects.insert("metric_plots", scroll.inner_rect);
}

/// A caption row of `height` points: the title in strong text (hover: `help`),
/// then `values`.
/// The values come first (at the right) and the title takes what is left:
/// the whole title if it fits, else its short form `short` ("Nearest
/// neighbour" for "Nearest neighbour (body lengths)"), else the short form cut
/// with "…". Its hover (and its name for a screen reader) is always the
/// whole title: a caption never widens its plot's column, so the panel never
/// grows wider than the window.
fn caption_ui(
    ui: &mut egui::Ui,
    width: f32,
    height: f32,
    title: &str,
    short: Option<&str>,
    help: &str,
    values: impl FnOnce(&mut egui::Ui),
) {
    ui.allocate_ui_with_layout(
        egui::vec2(width, height),
        egui::Layout::right_to_left(egui::Align::Center),
        |ui| {
            ui.set_width(width);
            values(ui);
            let text_width = |text: &str| {
                egui::WidgetText::from(egui::RichText::new(text).strong())
                    .into_galley(
                        ui,
                        Some(egui::TextWrapMode::Extend),
                        f32::INFINITY,
                        egui::TextStyle::Body,
                    )
                    .size()
                    .x
            };
            let shown = match short {
                Some(short) if text_width(title) > ui.available_width() => short,
                _ => title,
            };
            ui.add(egui::Label::new(egui::RichText::new(shown).strong()).truncate())
                .on_hover_text(format!("{title}: {help}"))
                .accessible_name(title);
        },
    );
}

/// How often each urge was the one applied over the last second, per tank, as
/// bars named on the axis.
fn urges_plot_ui(
    ui: &mut egui::Ui,
    runs: &[Run],
    latest: &[MetricsSample],
    labels: &[String],
    caption_height: f32,
    plot_height: f32,
    rects: &mut WidgetRects,
) {
    caption_ui(
        ui,
        ui.available_width(),
        caption_height,
        ts("metrics-urges"),
        Some(ts("metrics-urges.short")),
        ts("metrics-urges.help"),
        |_| {},
    );
    let bar_width = 0.8 / runs.len().max(1) as f64;
    // Horizontal bars, the urges named down the side (names under narrow
    // vertical bars would not fit); the first urge at the top.
    let row = |i: usize| (URGE_NAMES.len() - 1 - i) as f64;
    let plot = Plot::new("urges_plot")
        .height(plot_height)
        .allow_scroll(false)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_boxed_zoom(false)
        .include_x(0.0)
        // A little room past 100 % for the axis's last number.
        .include_x(108.0)
        .include_y(-0.5)
        .include_y(URGE_NAMES.len() as f64 - 0.5)
        .y_axis_min_width(56.0)
        .x_grid_spacer(readable_marks)
        .custom_x_axes(vec![super::bottom_panel::readable_x_axis(|mark, _| {
            tr!("metrics-percent", value = fmt(mark.value, 0))
        })])
        .y_grid_spacer(|_| {
            (0..URGE_NAMES.len())
                .map(|k| egui_plot::GridMark {
                    value: k as f64,
                    step_size: 1.0,
                })
                .collect()
        })
        .y_axis_formatter(move |mark, _| {
            let k = mark.value.round();
            if (0.0..URGE_NAMES.len() as f64).contains(&k) {
                urge_name(URGE_NAMES.len() - 1 - k as usize).to_owned()
            } else {
                String::new()
            }
        })
        .show(ui, |plot_ui| {
            for (k, ((run, sample), label)) in runs.iter().zip(latest).zip(labels).enumerate() {
                let offset = ((runs.len() as f64 - 1.0) / 2.0 - k as f64) * bar_width;
                let bars = sample
                    .force_frequencies
                    .to_array()
                    .iter()
                    .enumerate()
                    .map(|(i, share)| {
                        egui_plot::Bar::new(row(i) + offset, *share * 100.0)
                            .width(bar_width * 0.9)
                            .name(urge_name(i))
                    })
                    .collect();
                plot_ui.bar_chart(
                    egui_plot::BarChart::new(label.clone(), bars)
                        .color(side_color(run.side()))
                        .horizontal(),
                );
            }
        });
    rects.insert("plot_urges", plot.response.rect);
}
