//! What a run measured ([`Outcome`]): the numbers, a chart (bars or a curve with
//! its confidence intervals), a sentence for the headline and one holding the
//! prediction against the measurement. Built only from measurements
//! (`measure.rs`), never from the prediction's answer key.

use serde::Serialize;

use super::catalogue::Shape;
use crate::i18n::{Lang, lang, num};
use crate::tr;

/// One measured number.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Row {
    pub label: String,
    pub value: f64,
    pub unit: &'static str,
}

/// One point of a measured curve: the mean over seeds and its 95 % interval
/// (equal to the mean with one measurement).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CurvePoint {
    pub x: f64,
    pub mean: f64,
    pub low: f64,
    pub high: f64,
}

/// The picture of a result.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Chart {
    /// One bar per measured number (the rows); `whole` when they count
    /// something (fish caught), so the axis is marked in whole numbers.
    Bars { unit: &'static str, whole: bool },
    /// A measured curve, with the student's sketch over it: the sketch's height
    /// 1 is `y_max`.
    Curve {
        x_label: &'static str,
        y_label: &'static str,
        points: Vec<CurvePoint>,
        y_max: f64,
    },
}

/// A measured count or value over simulated time (the catches of a tank).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Timeline {
    pub label: String,
    /// (simulated seconds since the run began, value)
    pub points: Vec<[f64; 2]>,
}

/// The measured result of a run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Outcome {
    /// What was measured, in a sentence with the numbers.
    pub summary: String,
    /// The prediction held against the measurement.
    pub verdict: String,
    pub rows: Vec<Row>,
    pub chart: Chart,
    /// How the measured counts grew during the run (may be empty).
    pub timelines: Vec<Timeline>,
    /// The same result in the catalogue's other languages (its words made
    /// when the run ended), so a student who changes language reads it, and
    /// saves it, in the new one.
    #[serde(skip)]
    pub translations: Vec<(Lang, Outcome)>,
}

impl Outcome {
    /// The result in the language in force (this one where it has no
    /// translation).
    pub fn localized(&self) -> &Outcome {
        let here = lang();
        self.translations
            .iter()
            .find(|(l, _)| *l == here)
            .map_or(self, |(_, o)| o)
    }

    /// The rows as CSV lines `investigation,label,value,unit` (no header).
    pub fn csv_lines(&self, id: &str, out: &mut String) {
        use std::fmt::Write as _;
        for row in &self.rows {
            // Writing to a String cannot fail.
            let _ = writeln!(
                out,
                "{id},{},{},{}",
                csv_field(&row.label),
                row.value,
                row.unit
            );
        }
        if let Chart::Curve { points, .. } = &self.chart {
            for p in points {
                let low = tr!("inv-csv-curve-low", x = p.x);
                let high = tr!("inv-csv-curve-high", x = p.x);
                let _ = writeln!(out, "{id},{},{},", csv_field(&low), p.low);
                let _ = writeln!(out, "{id},{},{},", csv_field(&high), p.high);
            }
        }
    }
}

/// A CSV field, quoted when it holds a comma, quote or line break.
pub fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// How far a sketch lies from a measured curve: the root mean square of the
/// differences at the measured points, as a fraction of `y_max`.
pub fn shape_distance(shape: &Shape, points: &[CurvePoint], y_max: f64) -> f64 {
    if points.is_empty() || y_max <= 0.0 {
        return f64::NAN;
    }
    let (x0, x1) = x_span(points);
    let sum: f64 = points
        .iter()
        .map(|p| {
            let u = if x1 > x0 { (p.x - x0) / (x1 - x0) } else { 0.0 };
            let d = shape.at(u) - p.mean / y_max;
            d * d
        })
        .sum();
    (sum / points.len() as f64).sqrt()
}

/// The step of whole-number axis marks over `0..=span`: 1, 2, 5, 10, 20,
/// 50 … the smallest giving at most `most` steps.
pub fn whole_step(span: f64, most: usize) -> f64 {
    let most = most.max(1) as f64;
    let mut unit = 1.0;
    loop {
        for factor in [1.0, 2.0, 5.0] {
            let step = unit * factor;
            if !span.is_finite() || span / step <= most || step >= 1e15 {
                return step;
            }
        }
        unit *= 10.0;
    }
}

/// Whole-number marks from 0 to a mark at or above `max` (at least 1), at
/// most `most` steps apart: for 9.49 and 5, 0 2 4 6 8 10. The axis of a
/// count (fish caught) reads whole numbers only, never 3.16.
pub fn whole_ticks(max: f64, most: usize) -> Vec<f64> {
    let max = if max.is_finite() { max.max(1.0) } else { 1.0 };
    let step = whole_step(max, most);
    let steps = (max / step - 1e-9).ceil().max(1.0) as usize;
    (0..=steps).map(|k| k as f64 * step).collect()
}

/// The first and last x of a curve.
pub fn x_span(points: &[CurvePoint]) -> (f64, f64) {
    let x0 = points.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
    let x1 = points.iter().map(|p| p.x).fold(f64::NEG_INFINITY, f64::max);
    (x0, x1)
}

/// The verdict of a curve prediction: the chosen sketch's distance from the
/// measurement and the sketch that lies closest.
pub fn curve_verdict(shapes: &[Shape], chosen: usize, points: &[CurvePoint], y_max: f64) -> String {
    let distances: Vec<f64> = shapes
        .iter()
        .map(|s| shape_distance(s, points, y_max))
        .collect();
    let closest = distances
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(b.1))
        .map_or(0, |(k, _)| k);
    let mine = distances.get(chosen).copied().unwrap_or(f64::NAN);
    let name = |k: usize| shapes.get(k).map_or("?", |s| s.name.text());
    if closest == chosen {
        tr!(
            "inv-curve-verdict-closest",
            sketch = name(chosen),
            percent = num(100.0 * mine, 0)
        )
    } else {
        tr!(
            "inv-curve-verdict-other",
            sketch = name(chosen),
            percent = num(100.0 * mine, 0),
            closest = name(closest),
            closest_percent = num(100.0 * distances[closest], 0)
        )
    }
}
