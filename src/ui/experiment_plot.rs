//! An experiment's results in the window: a dose–response plot per measure
//! (the mean over seeds with its 95 % interval against the factor's level; with
//! two factors one line per level of the second) and a table whose buttons set
//! the tank to one run, to watch it. A click near a point of a plot does the
//! same for that level's first seed.

use eframe::egui;
use egui_plot::{Legend, Line, Plot, PlotPoints, Points};
use serde_json::Value;

use super::WidgetRects;
use crate::experiment::summary::significant;
use crate::experiment::{Plan, SummaryRow};
use crate::i18n::{localize_decimal, tr, ts};
use crate::settings::names::setting_name;
use crate::settings::{Scene, Settings};
use crate::tr;

/// Height of one dose–response plot, points. Default 150: two plots and the
/// table fit a laptop's window; a phone scrolls.
const PLOT_HEIGHT: f32 = 150.0;

/// The run a student asked to watch: its levels and seed.
#[derive(Clone, Debug, PartialEq)]
pub struct WatchRequest {
    pub levels: Vec<Value>,
    pub seed: u64,
}

/// A level on a plot's x axis: a number as it is, off and on as 0 and 1.
fn level_x(level: &Value) -> f64 {
    match level {
        Value::Bool(b) => f64::from(u8::from(*b)),
        other => other.as_f64().unwrap_or(f64::NAN),
    }
}

/// Does `scene` ever show two tanks (the schooling lab's comparison)? Its
/// factors then name their tank ("Alignment (left tank)"): an experiment
/// runs the left one.
pub fn shows_side(scene: Scene) -> bool {
    let comparing = Settings {
        scene,
        compare: true,
        ..Settings::default()
    };
    scene.class().tanks(&comparing) > 1
}

/// A factor's setting as the side panel names it, with its tank when
/// `with_side` ([`shows_side`]): "Alignment (left tank)". The key stays the
/// design's and the CSV's.
pub fn factor_text(key: &str, with_side: bool) -> String {
    crate::settings::names::setting_text(key, with_side)
}

/// [`factor_text`] with the setting's unit, for an axis or a column:
/// "Vision distance (m)".
fn factor_text_with_unit(key: &str, with_side: bool) -> String {
    setting_name(key).map_or_else(|| key.to_owned(), |n| n.text_with_unit(with_side))
}

/// A level as a person reads it (`80`, not `80.0`; `on`, `off`), in the
/// language in force (`0,5` in Spanish).
pub fn level_text(level: &Value) -> String {
    match level {
        Value::Bool(true) => tr("experiment-level-on"),
        Value::Bool(false) => tr("experiment-level-off"),
        Value::Number(n) => localize_decimal(
            &n.as_f64()
                .map_or_else(|| n.to_string(), |x| format!("{}", (x * 1e6).round() / 1e6)),
        ),
        other => other.to_string(),
    }
}

/// The plots and the table of `rows` (the summary of `plan`'s completed runs).
/// Returns the run to watch, if one was asked for.
pub fn results_ui(
    ui: &mut egui::Ui,
    plan: &Plan,
    rows: &[SummaryRow],
    rects: &mut WidgetRects,
) -> Option<WatchRequest> {
    let mut watch = None;
    let side = shows_side(plan.base.scene);
    if rows.is_empty() {
        ui.label(ts("experiment-no-run-yet"));
        return None;
    }
    for (m, &(measure, summary)) in plan.measures.iter().enumerate() {
        let summary_name = if summary == crate::experiment::Summary::Final {
            ts("experiment-final")
        } else {
            ts("experiment-mean")
        };
        ui.label(
            egui::RichText::new(tr!(
                "experiment-plot-title",
                measure = measure.label(),
                summary = summary_name
            ))
            .strong(),
        );
        let mine: Vec<&SummaryRow> = rows.iter().filter(|r| r.measure == measure).collect();
        if let Some(w) = dose_response_plot(ui, plan, m, &mine, rects) {
            watch = Some(w);
        }
    }
    ui.add_space(4.0);
    ui.label(egui::RichText::new(ts("experiment-interval-about")).small());
    let fewest = rows.iter().map(|r| r.n).min().unwrap_or(0);
    if fewest < crate::experiment::summary::FEW_SEEDS {
        let warning = tr!("experiment-few-seeds", count = fewest);
        ui.label(egui::RichText::new(warning).color(ui.visuals().warn_fg_color));
    }
    ui.add_space(4.0);
    ui.label(egui::RichText::new(ts("experiment-table-title")).strong());
    // A solid scroll bar, under the table: a floating one would lie over the
    // last row's watch buttons and take their clicks.
    let floating = ui.spacing().scroll;
    ui.spacing_mut().scroll = egui::style::ScrollStyle::solid();
    egui::ScrollArea::horizontal()
        .id_salt("experiment_table_scroll")
        .show(ui, |ui| {
            let grid = egui::Grid::new("experiment_table")
                .striped(true)
                .show(ui, |ui| {
                    // The watch buttons next to their level, before the
                    // numbers: long measure names must not push them out of
                    // the window.
                    for factor in &plan.factors {
                        ui.strong(factor_text_with_unit(&factor.key, side));
                    }
                    ui.strong(ts("experiment-table-watch"));
                    ui.strong("n");
                    for &(measure, _) in &plan.measures {
                        ui.strong(measure.label()).on_hover_text(measure.help());
                    }
                    ui.end_row();
                    for (r, chunk) in rows.chunks(plan.measures.len().max(1)).enumerate() {
                        let Some(first) = chunk.first() else {
                            continue;
                        };
                        for level in &first.levels {
                            ui.label(level_text(level));
                        }
                        ui.horizontal(|ui| {
                            for (k, &seed) in plan.seeds.iter().take(first.n).enumerate() {
                                // An id of its own: a press and its release
                                // must meet the same button, whatever else the
                                // window drew this frame.
                                let b = ui
                                    .push_id(("experiment_watch", r, k), |ui| {
                                        ui.small_button(tr!(
                                            "experiment-seed-button",
                                            seed = seed.to_string()
                                        ))
                                    })
                                    .inner
                                    .on_hover_text(ts("experiment-seed-button.help"));
                                rects.insert(&format!("experiment_watch_{r}_{k}"), b.rect);
                                if b.clicked() {
                                    watch = Some(WatchRequest {
                                        levels: first.levels.clone(),
                                        seed,
                                    });
                                }
                            }
                        });
                        ui.label(first.n.to_string());
                        for row in chunk {
                            ui.label(if row.ci95_low.is_finite() {
                                tr!(
                                    "experiment-interval",
                                    mean = localize_decimal(&significant(row.mean)),
                                    low = localize_decimal(&significant(row.ci95_low)),
                                    high = localize_decimal(&significant(row.ci95_high))
                                )
                            } else {
                                localize_decimal(&significant(row.mean))
                            });
                        }
                        ui.end_row();
                    }
                });
            rects.insert("experiment_table", grid.response.rect);
        });
    ui.spacing_mut().scroll = floating;
    watch
}

/// One measure's plot: x the first factor's level, one line per level of the
/// second factor, error bars the 95 % interval.
fn dose_response_plot(
    ui: &mut egui::Ui,
    plan: &Plan,
    m: usize,
    rows: &[&SummaryRow],
    rects: &mut WidgetRects,
) -> Option<WatchRequest> {
    let (measure, _) = plan.measures[m];
    let side = shows_side(plan.base.scene);
    // The lines: one per level of the second factor (or one).
    let second_levels: Vec<Option<&Value>> = match plan.factors.get(1) {
        Some(f) => f.levels.iter().map(Some).collect(),
        None => vec![None],
    };
    let x_name = plan.factors.first().map_or_else(
        || tr("experiment-no-factor"),
        |f| factor_text_with_unit(&f.key, side),
    );
    let mut points_all: Vec<([f64; 2], Vec<Value>)> = Vec::new();
    let response = Plot::new(("experiment_plot", m))
        .height(PLOT_HEIGHT)
        .allow_scroll(false)
        .allow_drag(false)
        .allow_zoom(false)
        .legend(Legend::default())
        .x_axis_label(x_name)
        .show(ui, |plot| {
            for (k, second) in second_levels.iter().enumerate() {
                let name = match (plan.factors.get(1), second) {
                    (Some(f), Some(level)) => {
                        format!("{} = {}", factor_text(&f.key, side), level_text(level))
                    }
                    _ => measure.label().to_owned(),
                };
                // Each level of the second factor in its own colour, line
                // style and marker (Okabe–Ito; never colour alone), named in
                // the legend.
                let style = super::palette::series(k);
                let color = style.color;
                let line: Vec<&&SummaryRow> = rows
                    .iter()
                    .filter(|r| second.is_none_or(|s| r.levels.get(1) == Some(s)))
                    .collect();
                let xy: Vec<[f64; 2]> = line
                    .iter()
                    .map(|r| [r.levels.first().map_or(0.0, level_x), r.mean])
                    .collect();
                for (r, p) in line.iter().zip(&xy) {
                    points_all.push((*p, r.levels.clone()));
                    if r.ci95_low.is_finite() {
                        plot.line(
                            Line::new(
                                name.clone(),
                                PlotPoints::from(vec![[p[0], r.ci95_low], [p[0], r.ci95_high]]),
                            )
                            .color(color)
                            .width(1.5),
                        );
                    }
                }
                plot.line(
                    Line::new(name.clone(), PlotPoints::from(xy.clone()))
                        .color(color)
                        .style(style.line)
                        .width(1.8),
                );
                plot.points(
                    Points::new(name, PlotPoints::from(xy))
                        .color(color)
                        .shape(style.marker)
                        .filled(true)
                        .radius(4.0),
                );
            }
            // A click near a point: watch that level's first seed.
            if plot.response().clicked() {
                let bounds = plot.plot_bounds();
                let (w, h) = (bounds.width().max(1e-9), bounds.height().max(1e-9));
                plot.pointer_coordinate().and_then(|at| {
                    points_all
                        .iter()
                        .map(|(p, levels)| {
                            let d = ((p[0] - at.x) / w).powi(2) + ((p[1] - at.y) / h).powi(2);
                            (d, levels)
                        })
                        .filter(|(d, _)| *d < 0.05 * 0.05)
                        .min_by(|a, b| a.0.total_cmp(&b.0))
                        .map(|(_, levels)| levels.clone())
                })
            } else {
                None
            }
        });
    rects.insert(&format!("experiment_plot_{m}"), response.response.rect);
    let levels = response.inner?;
    Some(WatchRequest {
        levels,
        seed: *plan.seeds.first()?,
    })
}
