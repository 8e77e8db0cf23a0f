//! The colours plots and overlays tell things apart with, and the second cue
//! each series carries so that colour is never the only one (WCAG 1.4.1): the
//! Okabe–Ito palette (Okabe & Ito 2008, *Color Universal Design*), chosen to stay
//! distinct for people with protanopia, deuteranopia and tritanopia, and for
//! each series a line style and a marker shape, with a legend or a label naming
//! it.
//!
//! The tests simulate the three colour-vision deficiencies (Machado, Oliveira &
//! Fernandes 2009, severity 1) and check that every pair of colours drawn
//! together stays apart, and that every colour shows against the plots' dark
//! background at 3:1 (WCAG 1.4.11).

use eframe::egui::Color32;
use egui_plot::{LineStyle, MarkerShape};

use crate::settings::Side;

/// Okabe–Ito orange (E69F00).
pub const ORANGE: Color32 = Color32::from_rgb(230, 159, 0);
/// Okabe–Ito sky blue (56B4E9).
pub const SKY_BLUE: Color32 = Color32::from_rgb(86, 180, 233);
/// Okabe–Ito bluish green (009E73).
pub const BLUISH_GREEN: Color32 = Color32::from_rgb(0, 158, 115);
/// Okabe–Ito yellow (F0E442).
pub const YELLOW: Color32 = Color32::from_rgb(240, 228, 66);
/// Okabe–Ito blue (0072B2), lightened a little (to 3A8FD0) so it keeps 3:1
/// on the plots' near-black background with room to spare.
pub const BLUE: Color32 = Color32::from_rgb(58, 143, 208);
/// Okabe–Ito vermillion (D55E00).
pub const VERMILLION: Color32 = Color32::from_rgb(213, 94, 0);
/// Okabe–Ito reddish purple (CC79A7).
pub const REDDISH_PURPLE: Color32 = Color32::from_rgb(204, 121, 167);
/// Light grey, the eighth entry (Okabe–Ito's black does not show on a dark
/// background).
pub const GREY: Color32 = Color32::from_rgb(190, 190, 190);

/// How one series is drawn: its colour and its cues that are not colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeriesStyle {
    pub color: Color32,
    pub line: LineStyle,
    pub marker: MarkerShape,
}

/// The series of a plot with several lines (an experiment's levels of its
/// second factor, …), in order: each differs from the others in colour, and
/// from its neighbours in line style and marker shape too.
pub const SERIES: [SeriesStyle; 6] = [
    SeriesStyle {
        color: ORANGE,
        line: LineStyle::Solid,
        marker: MarkerShape::Circle,
    },
    SeriesStyle {
        color: SKY_BLUE,
        line: LineStyle::Dashed { length: 10.0 },
        marker: MarkerShape::Square,
    },
    SeriesStyle {
        color: BLUISH_GREEN,
        line: LineStyle::Dotted { spacing: 6.0 },
        marker: MarkerShape::Diamond,
    },
    SeriesStyle {
        color: REDDISH_PURPLE,
        line: LineStyle::Dashed { length: 4.0 },
        marker: MarkerShape::Up,
    },
    SeriesStyle {
        color: YELLOW,
        line: LineStyle::Solid,
        marker: MarkerShape::Cross,
    },
    SeriesStyle {
        color: VERMILLION,
        line: LineStyle::Dashed { length: 10.0 },
        marker: MarkerShape::Down,
    },
];

/// Series `k`'s style (they repeat after [`SERIES`]'s six).
pub fn series(k: usize) -> SeriesStyle {
    SERIES[k % SERIES.len()]
}

/// Each tank's style, wherever a tank is drawn in a colour (plots, the
/// captions' values, its name over the view): the left tank solid orange, the
/// right dashed sky blue.
pub fn side_series(side: Side) -> SeriesStyle {
    match side {
        Side::Left => SERIES[0],
        Side::Right => SERIES[1],
    }
}

/// A short sample of a line style in text, for captions and hover help:
/// "——" solid, "– –" dashed, "···" dotted.
pub fn line_glyph(line: LineStyle) -> &'static str {
    match line {
        LineStyle::Solid => "——",
        LineStyle::Dashed { .. } => "– –",
        LineStyle::Dotted { .. } => "···",
    }
}

#[cfg(test)]
pub(crate) mod vision {
    //! Colour-vision deficiency simulation and colour distance, for the tests.

    use eframe::egui::Color32;

    fn to_linear(c: u8) -> f64 {
        let c = f64::from(c) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    }

    /// Machado, Oliveira & Fernandes (2009), *A Physiologically-based Model
    /// for Simulation of Color Vision Deficiency*, IEEE TVCG 15(6), Table 1 at
    /// severity 1.0, applied to linear RGB.
    pub const PROTAN: [[f64; 3]; 3] = [
        [0.152286, 1.052583, -0.204868],
        [0.114503, 0.786281, 0.099216],
        [-0.003882, -0.048116, 1.051998],
    ];
    pub const DEUTAN: [[f64; 3]; 3] = [
        [0.367322, 0.860646, -0.227968],
        [0.280085, 0.672501, 0.047413],
        [-0.011820, 0.042940, 0.968881],
    ];
    pub const TRITAN: [[f64; 3]; 3] = [
        [1.255528, -0.076749, -0.178779],
        [-0.078411, 0.930809, 0.147602],
        [0.004733, 0.691367, 0.303900],
    ];

    /// Linear RGB of an opaque colour.
    pub fn linear(c: Color32) -> [f64; 3] {
        [to_linear(c.r()), to_linear(c.g()), to_linear(c.b())]
    }

    /// How `rgb` (linear) looks through `deficiency` (one of the matrices
    /// above, or `None` for typical vision), clamped to the gamut.
    pub fn simulate(rgb: [f64; 3], deficiency: Option<&[[f64; 3]; 3]>) -> [f64; 3] {
        let Some(m) = deficiency else {
            return rgb;
        };
        let row = |r: &[f64; 3]| (r[0] * rgb[0] + r[1] * rgb[1] + r[2] * rgb[2]).clamp(0.0, 1.0);
        [row(&m[0]), row(&m[1]), row(&m[2])]
    }

    /// CIE L*a*b* (D65) of a linear RGB colour.
    pub fn lab(rgb: [f64; 3]) -> [f64; 3] {
        let [r, g, b] = rgb;
        let x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
        let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        let z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
        let f = |t: f64| {
            if t > (6.0f64 / 29.0).powi(3) {
                t.cbrt()
            } else {
                t / (3.0 * (6.0f64 / 29.0).powi(2)) + 4.0 / 29.0
            }
        };
        let (fx, fy, fz) = (f(x / 0.95047), f(y), f(z / 1.08883));
        [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
    }

    /// CIE76 colour difference ΔE*ab between `a` and `b` as seen through
    /// `deficiency`.
    pub fn delta_e(a: Color32, b: Color32, deficiency: Option<&[[f64; 3]; 3]>) -> f64 {
        let la = lab(simulate(linear(a), deficiency));
        let lb = lab(simulate(linear(b), deficiency));
        ((la[0] - lb[0]).powi(2) + (la[1] - lb[1]).powi(2) + (la[2] - lb[2]).powi(2)).sqrt()
    }

    /// The deficiencies simulated, with names for messages.
    pub const DEFICIENCIES: [(&str, Option<&[[f64; 3]; 3]>); 4] = [
        ("typical vision", None),
        ("protanopia", Some(&PROTAN)),
        ("deuteranopia", Some(&DEUTAN)),
        ("tritanopia", Some(&TRITAN)),
    ];
}

#[cfg(test)]
mod tests {
    use super::vision::{DEFICIENCIES, delta_e};
    use super::*;
    use crate::ui::theme::{self, contrast_ratio};

    /// The smallest colour difference (ΔE*ab, CIE76) between two series drawn
    /// together, for every vision simulated. 15, chosen: several times what
    /// people notice side by side. The six Okabe–Ito series keep at least 16
    /// (sky blue and bluish green for a tritanope); the experiment plot's
    /// palette before them came to 14.9 (its orange and yellow for a
    /// deuteranope).
    const MIN_DELTA_E: f64 = 15.0;

    fn assert_apart(name: &str, colors: &[Color32], min: f64) {
        for (vision, deficiency) in DEFICIENCIES {
            for (i, a) in colors.iter().enumerate() {
                for b in &colors[i + 1..] {
                    let d = delta_e(*a, *b, deficiency);
                    assert!(
                        d >= min,
                        "{name}: {a:?} and {b:?} are only ΔE {d:.1} apart for {vision}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_series_colours_stay_apart_for_protan_deutan_and_tritan_eyes() {
        let colors: Vec<Color32> = SERIES.iter().map(|s| s.color).collect();
        assert_apart("series", &colors, MIN_DELTA_E);
        assert_apart(
            "tanks",
            &[
                side_series(Side::Left).color,
                side_series(Side::Right).color,
            ],
            MIN_DELTA_E,
        );
    }

    #[test]
    fn the_simulation_tells_the_colours_that_fool_each_eye() {
        // An orange and an olive green of about equal lightness: far apart
        // for typical vision, one colour for a protanope.
        let orange = Color32::from_rgb(200, 120, 0);
        let olive = Color32::from_rgb(110, 140, 0);
        assert!(delta_e(orange, olive, None) > 40.0);
        assert!(delta_e(orange, olive, Some(&vision::PROTAN)) < 5.0);
        assert!(delta_e(orange, olive, Some(&vision::DEUTAN)) < 15.0);
        // The experiment plot's colours before Okabe–Ito: its orange and
        // yellow came closer than the bar for a deuteranope.
        let old_orange = Color32::from_rgb(255, 170, 60);
        let old_yellow = Color32::from_rgb(240, 230, 110);
        assert!(delta_e(old_orange, old_yellow, Some(&vision::DEUTAN)) < MIN_DELTA_E);
    }

    #[test]
    fn neighbouring_series_differ_in_more_than_colour() {
        for (k, s) in SERIES.iter().enumerate() {
            let next = SERIES[(k + 1) % SERIES.len()];
            assert_ne!(
                s.line, next.line,
                "series {k} and the next share a line style"
            );
            assert_ne!(
                s.marker, next.marker,
                "series {k} and the next share a marker"
            );
        }
        let markers: std::collections::HashSet<String> =
            SERIES.iter().map(|s| format!("{:?}", s.marker)).collect();
        assert_eq!(
            markers.len(),
            SERIES.len(),
            "every series has its own marker"
        );
        assert_ne!(side_series(Side::Left).line, side_series(Side::Right).line);
        assert_ne!(
            line_glyph(side_series(Side::Left).line),
            line_glyph(side_series(Side::Right).line)
        );
    }

    #[test]
    fn every_plot_colour_shows_at_3_to_1_on_the_plot_background() {
        for high_contrast in [false, true] {
            let background = theme::visuals(high_contrast).extreme_bg_color;
            for color in [
                ORANGE,
                SKY_BLUE,
                BLUISH_GREEN,
                YELLOW,
                BLUE,
                VERMILLION,
                REDDISH_PURPLE,
                GREY,
            ] {
                let ratio = contrast_ratio(color, background);
                assert!(
                    ratio >= 3.0,
                    "{color:?} on {background:?}: {ratio:.2}:1 (high contrast: {high_contrast})"
                );
            }
        }
    }
}
