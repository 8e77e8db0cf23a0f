//! The investigation window's pictures: a sketch of the chosen curve before the
//! run, and after it the measured result (bars, or the measured curve with its
//! 95 % intervals and the student's sketch dashed over it).

use eframe::egui;
use egui_plot::{Bar, BarChart, Legend, Line, LineStyle, Plot, PlotPoints, Points};

use crate::i18n::ts;
use crate::investigation::outcome::{Timeline, whole_step, x_span};
use crate::investigation::{Chart, Outcome, Shape};
use crate::settings::Side;

/// Height of the window's plot, points. Default 150: the window still fits a
/// phone's screen with the text around it.
const PLOT_HEIGHT: f32 = 150.0;

/// The measured result: solid orange with round markers; the student's
/// prediction: dashed sky blue (Okabe–Ito), each named in the legend.
const MEASURED: egui::Color32 = super::palette::ORANGE;
const PREDICTED: egui::Color32 = super::palette::SKY_BLUE;

fn sketch_points(shape: &Shape, x0: f64, x1: f64, y_max: f64) -> PlotPoints<'static> {
    (0..=40)
        .map(|k| {
            let u = f64::from(k) / 40.0;
            [x0 + u * (x1 - x0), shape.at(u) * y_max]
        })
        .collect()
}

/// Marks of a count's axis (fish caught) at whole numbers only: steps of 1,
/// 2, 5, 10 … with at most five over the visible range, never 3.16.
pub fn whole_marks(input: egui_plot::GridInput) -> Vec<egui_plot::GridMark> {
    let (low, high) = input.bounds;
    if !(low.is_finite() && high.is_finite()) || high <= low {
        return Vec::new();
    }
    let step = whole_step(high - low.max(0.0), 5).max(input.base_step_size.ceil());
    let first = (low / step).ceil() as i64;
    let last = (high / step).floor() as i64;
    (first..=last)
        .map(|k| egui_plot::GridMark {
            value: k as f64 * step,
            step_size: step,
        })
        .collect()
}

/// The chosen sketch alone, before the run: its shape over the axes' names.
pub fn sketch_ui(ui: &mut egui::Ui, shape: &Shape, x_label: &str, y_label: &str) {
    Plot::new("investigation_sketch")
        .height(PLOT_HEIGHT * 0.7)
        .x_axis_label(x_label)
        .y_axis_label(y_label)
        .x_axis_formatter(|_, _| String::new())
        .y_axis_formatter(|_, _| String::new())
        .include_y(0.0)
        .include_y(1.0)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .show(ui, |plot| {
            plot.line(
                Line::new(
                    ts("inv-plot-your-sketch"),
                    sketch_points(shape, 0.0, 1.0, 1.0),
                )
                .color(PREDICTED)
                .width(2.5),
            );
        });
}

/// The measured result, with the sketch over a curve.
pub fn outcome_ui(ui: &mut egui::Ui, outcome: &Outcome, sketch: Option<&Shape>) {
    match &outcome.chart {
        Chart::Bars { unit, whole } => {
            let bars: Vec<Bar> = outcome
                .rows
                .iter()
                .enumerate()
                .filter(|(_, r)| r.unit == outcome.rows[0].unit)
                .map(|(k, r)| {
                    Bar::new(k as f64, r.value)
                        .name(&r.label)
                        .width(0.6)
                        .fill(MEASURED)
                })
                .collect();
            let labels: Vec<String> = outcome.rows.iter().map(|r| r.label.clone()).collect();
            // The race's bars (in metres) are named by their tries alone (see
            // `short_label`).
            let race = outcome.rows.iter().all(|r| r.unit == "m");
            let x_title = if race { ts("inv-plot-tries") } else { "" };
            let names = move |mark: egui_plot::GridMark, _: &std::ops::RangeInclusive<f64>| {
                let k = mark.value.round();
                if (mark.value - k).abs() < 1e-6 && k >= 0.0 {
                    labels
                        .get(k as usize)
                        .map(|l| short_label(l, race))
                        .unwrap_or_default()
                } else {
                    String::new()
                }
            };
            let mut plot = Plot::new("investigation_bars").height(PLOT_HEIGHT);
            if *whole {
                plot = plot.y_grid_spacer(whole_marks);
            }
            plot.y_axis_label(*unit)
                .include_y(0.0)
                .allow_drag(false)
                .allow_zoom(false)
                .allow_scroll(false)
                // A mark under every bar, so each one is named, and the names
                // shown from 24 points apart (six bars in the window's width;
                // egui_plot's default hides x labels closer than 60).
                .x_grid_spacer(|input| {
                    let (low, high) = input.bounds;
                    (low.ceil().max(0.0) as usize..=high.floor().max(0.0) as usize)
                        .map(|k| egui_plot::GridMark {
                            value: k as f64,
                            step_size: 1.0,
                        })
                        .collect()
                })
                .custom_x_axes(vec![
                    egui_plot::AxisHints::new_x()
                        .label(x_title)
                        .formatter(names)
                        .label_spacing(24.0..=32.0),
                ])
                .show(ui, |plot| {
                    plot.bar_chart(BarChart::new(ts("inv-plot-measured"), bars));
                });
        }
        Chart::Curve {
            x_label,
            y_label,
            points,
            y_max,
        } => {
            let (x0, x1) = x_span(points);
            Plot::new("investigation_curve")
                .height(PLOT_HEIGHT)
                .x_axis_label(*x_label)
                .y_axis_label(*y_label)
                .include_y(0.0)
                .legend(Legend::default())
                .allow_drag(false)
                .allow_zoom(false)
                .allow_scroll(false)
                .show(ui, |plot| {
                    for p in points {
                        plot.line(
                            Line::new(ts("inv-plot-interval"), vec![[p.x, p.low], [p.x, p.high]])
                                .color(MEASURED)
                                .width(1.5),
                        );
                    }
                    let mean: Vec<[f64; 2]> = points.iter().map(|p| [p.x, p.mean]).collect();
                    plot.line(
                        Line::new(ts("inv-plot-measured"), mean.clone())
                            .color(MEASURED)
                            .width(2.5),
                    );
                    plot.points(
                        Points::new(ts("inv-plot-measured"), mean)
                            .color(MEASURED)
                            .radius(3.5),
                    );
                    if let Some(shape) = sketch {
                        plot.line(
                            Line::new(
                                ts("inv-plot-your-prediction"),
                                sketch_points(shape, x0, x1, *y_max),
                            )
                            .color(PREDICTED)
                            .style(LineStyle::dashed_loose())
                            .width(2.0),
                        );
                    }
                });
        }
    }
}

/// The end of a long label, to sit under a bar; a race's bar by its number
/// of tries alone.
fn short_label(label: &str, race: bool) -> String {
    let tail = label.rsplit_once(", ").map_or(label, |(_, tail)| tail);
    // "distance after 6840 tries": the number of tries is what tells the bars
    // apart, and six longer names overlap (the plot then shows none).
    let tries = tail.split(' ').find(|w| {
        !w.is_empty()
            && w.chars()
                .all(|c| c.is_ascii_digit() || c == '.' || c == ',')
    });
    match tries {
        Some(tries) if race => tries.to_owned(),
        _ => tail.to_owned(),
    }
}

/// Counts over the run (each tank's catches), in the tanks' colours, over the
/// run's `secs` simulated seconds.
pub fn timelines_ui(ui: &mut egui::Ui, timelines: &[Timeline], secs: f64) {
    if timelines.is_empty() {
        return;
    }
    Plot::new("investigation_timelines")
        .height(PLOT_HEIGHT * 0.8)
        .x_axis_label(ts("inv-plot-simulated-seconds"))
        .y_axis_label(ts("inv-unit-fish-caught"))
        .include_x(0.0)
        .include_x(secs)
        .include_y(0.0)
        .include_y(4.0)
        .y_grid_spacer(whole_marks)
        .legend(Legend::default())
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .show(ui, |plot| {
            for (k, t) in timelines.iter().enumerate() {
                let side = if k == 0 { Side::Left } else { Side::Right };
                plot.line(
                    Line::new(t.label.clone(), t.points.clone())
                        .color(super::side_color(side))
                        .style(super::palette::side_series(side).line)
                        .width(2.0),
                );
            }
        });
}
