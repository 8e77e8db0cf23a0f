//! The interface's look in one place: the egui `Visuals` and text sizes the
//! app installs, in its usual dark theme and in a high-contrast one, and the
//! WCAG contrast ratio its tests hold every colour to (text 4.5:1, 1.4.3;
//! widget boundaries, the focus ring and plot lines 3:1, 1.4.11; text 7:1 in
//! the high-contrast theme, 1.4.6).
//!
//! The app installs exactly what [`style`] returns ([`install`]), so the tests
//! read the colours a class sees.

use eframe::egui::{self, Color32, Stroke};

/// The size of small text (`RichText::small`, hints under controls), points.
/// 12, chosen: egui's own 9 is hard to read on a projector or for weak eyes;
/// body text stays 13.
pub const SMALL_TEXT_PT: f32 = 12.0;

/// The width of the focus ring (the stroke round the widget that has the
/// keyboard's focus, or is being pressed), points: 2 in the usual theme, 3 in
/// the high-contrast one.
pub const FOCUS_RING_PT: [f32; 2] = [2.0, 3.0];

/// A colour's relative luminance (WCAG 2.1, the sRGB transfer function), of
/// the colour as shown: premultiplied alpha is taken as drawn over black
/// (composite with [`over`] first to put it on a background).
pub fn relative_luminance(c: Color32) -> f64 {
    let channel = |v: u8| {
        let v = f64::from(v) / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * channel(c.r()) + 0.7152 * channel(c.g()) + 0.0722 * channel(c.b())
}

/// The WCAG contrast ratio of two colours, 1 to 21, whichever is lighter.
pub fn contrast_ratio(a: Color32, b: Color32) -> f64 {
    let (la, lb) = (relative_luminance(a), relative_luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

/// `fg` (premultiplied, maybe translucent) drawn over the opaque `bg`, as
/// egui blends it (in gamma space).
pub fn over(fg: Color32, bg: Color32) -> Color32 {
    let keep = 1.0 - f32::from(fg.a()) / 255.0;
    let mix = |f: u8, b: u8| (f32::from(f) + keep * f32::from(b)).round().min(255.0) as u8;
    Color32::from_rgb(
        mix(fg.r(), bg.r()),
        mix(fg.g(), bg.g()),
        mix(fg.b(), bg.b()),
    )
}

/// The usual dark theme: egui's dark visuals with the colours that missed
/// WCAG AA brought up to it (see the README's *Seeing*): lighter normal and
/// weak text, a lighter error red, a visible border round buttons, checkboxes
/// and text fields, lighter slider rails and checkbox boxes, a 2-point focus
/// ring.
fn standard_visuals() -> egui::Visuals {
    let mut v = egui::Visuals::dark();
    // Text: egui's grey 140 passes, its weak text (60 % of it, about grey 95)
    // does not (2.7:1); normal text moves up to make room for a weak text
    // that passes and still looks weaker.
    v.widgets.noninteractive.fg_stroke.color = Color32::from_gray(185);
    v.weak_text_color = Some(Color32::from_gray(145));
    // Pure red on grey 27 is 4.3:1.
    v.error_fg_color = Color32::from_rgb(255, 95, 95);
    // Widget boundaries at 3:1 on the panel: a border round every control,
    // and slider rails and checkbox boxes light enough to see.
    v.widgets.inactive.bg_stroke = Stroke::new(1.0, Color32::from_gray(125));
    v.widgets.inactive.bg_fill = Color32::from_gray(105);
    v.widgets.hovered.bg_fill = Color32::from_gray(120);
    v.widgets.hovered.bg_stroke = Stroke::new(1.0, Color32::from_gray(190));
    v.widgets.active.bg_fill = Color32::from_gray(110);
    v.widgets.active.bg_stroke = Stroke::new(FOCUS_RING_PT[0], Color32::WHITE);
    v.widgets.open.bg_stroke = Stroke::new(1.0, Color32::from_gray(125));
    // Separators and plot frames.
    v.widgets.noninteractive.bg_stroke = Stroke::new(1.0, Color32::from_gray(80));
    // The selected tab or button: egui's dark blue is 2.3:1 on the panel; a
    // lighter blue with white text shows at 3.6:1 and keeps the text at 4.8:1.
    v.selection.bg_fill = Color32::from_rgb(0, 120, 180);
    v.selection.stroke = Stroke::new(1.0, Color32::WHITE);
    v
}

/// The high-contrast theme: white text on black (21:1), weak text at 12:1,
/// two-point light borders round every control, a three-point yellow focus
/// ring, strong selection.
fn high_contrast_visuals() -> egui::Visuals {
    let mut v = egui::Visuals::dark();
    let black = Color32::BLACK;
    let focus = Color32::from_rgb(255, 221, 0);
    v.panel_fill = black;
    v.window_fill = Color32::from_gray(8);
    v.extreme_bg_color = black;
    v.faint_bg_color = Color32::from_gray(24);
    v.code_bg_color = Color32::from_gray(40);
    v.window_stroke = Stroke::new(2.0, Color32::WHITE);
    v.window_shadow = egui::Shadow::NONE;
    v.popup_shadow = egui::Shadow::NONE;
    v.weak_text_color = Some(Color32::from_gray(205));
    v.hyperlink_color = Color32::from_rgb(130, 205, 255);
    v.warn_fg_color = Color32::from_rgb(255, 200, 60);
    v.error_fg_color = Color32::from_rgb(255, 140, 140);
    // A selected tab's fill must show on black (3:1) and its white text on
    // the fill: no fill gives both 3:1 and 7:1 (that needs a luminance of
    // exactly 0.1), so the text gets 5:1 and the fill 4.2:1.
    v.selection.bg_fill = Color32::from_rgb(0, 115, 190);
    v.selection.stroke = Stroke::new(2.0, Color32::WHITE);
    v.text_cursor.stroke = Stroke::new(3.0, focus);
    let w = &mut v.widgets;
    w.noninteractive.bg_fill = black;
    w.noninteractive.weak_bg_fill = black;
    w.noninteractive.bg_stroke = Stroke::new(1.0, Color32::from_gray(170));
    w.noninteractive.fg_stroke = Stroke::new(1.0, Color32::WHITE);
    w.inactive.weak_bg_fill = Color32::from_gray(30);
    w.inactive.bg_fill = Color32::from_gray(100);
    w.inactive.bg_stroke = Stroke::new(2.0, Color32::from_gray(230));
    w.inactive.fg_stroke = Stroke::new(1.5, Color32::WHITE);
    w.hovered.weak_bg_fill = Color32::from_gray(55);
    w.hovered.bg_fill = Color32::from_gray(120);
    w.hovered.bg_stroke = Stroke::new(2.0, Color32::WHITE);
    w.hovered.fg_stroke = Stroke::new(2.0, Color32::WHITE);
    w.active.weak_bg_fill = Color32::from_gray(45);
    w.active.bg_fill = Color32::from_gray(110);
    w.active.bg_stroke = Stroke::new(FOCUS_RING_PT[1], focus);
    w.active.fg_stroke = Stroke::new(2.0, Color32::WHITE);
    w.open.weak_bg_fill = Color32::from_gray(30);
    w.open.bg_fill = black;
    w.open.bg_stroke = Stroke::new(2.0, Color32::from_gray(230));
    w.open.fg_stroke = Stroke::new(1.5, Color32::WHITE);
    v
}

/// The visuals of the usual theme, or of the high-contrast one.
pub fn visuals(high_contrast: bool) -> egui::Visuals {
    if high_contrast {
        high_contrast_visuals()
    } else {
        standard_visuals()
    }
}

/// The whole style the app installs: [`visuals`], small text at
/// [`SMALL_TEXT_PT`], and with `reduce_motion` no animations (panels and
/// windows open at once, scrolling jumps).
pub fn style(high_contrast: bool, reduce_motion: bool) -> egui::Style {
    let mut style = egui::Style {
        visuals: visuals(high_contrast),
        ..Default::default()
    };
    if let Some(small) = style.text_styles.get_mut(&egui::TextStyle::Small) {
        small.size = SMALL_TEXT_PT;
    }
    if reduce_motion {
        style.animation_time = 0.0;
        style.scroll_animation = egui::style::ScrollAnimation::none();
        style.visuals.text_cursor.blink = false;
    }
    style
}

/// Installs [`style`] as the app's (dark) theme.
pub fn install(ctx: &egui::Context, high_contrast: bool, reduce_motion: bool) {
    ctx.set_theme(egui::Theme::Dark);
    ctx.set_style_of(egui::Theme::Dark, style(high_contrast, reduce_motion));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_contrast_ratio_is_wcags() {
        assert!((contrast_ratio(Color32::BLACK, Color32::WHITE) - 21.0).abs() < 1e-9);
        assert!((contrast_ratio(Color32::WHITE, Color32::WHITE) - 1.0).abs() < 1e-9);
        // WCAG's own example figures: #777 on white is 4.48:1, #767676 4.54:1.
        let ratio = contrast_ratio(Color32::from_gray(0x77), Color32::WHITE);
        assert!((ratio - 4.48).abs() < 0.01, "{ratio}");
        let ratio = contrast_ratio(Color32::from_gray(0x76), Color32::WHITE);
        assert!((ratio - 4.54).abs() < 0.01, "{ratio}");
        assert_eq!(
            over(Color32::from_black_alpha(0), Color32::from_gray(27)),
            Color32::from_gray(27)
        );
        assert_eq!(
            over(
                Color32::from_gray(140).gamma_multiply(0.5),
                Color32::from_gray(20)
            ),
            Color32::from_gray(80)
        );
    }

    /// The text colours a theme shows, by name, each on every background it
    /// is drawn on.
    fn text_cases(v: &egui::Visuals) -> Vec<(String, Color32, Color32)> {
        let backgrounds = [
            ("panel", v.panel_fill),
            ("window", v.window_fill),
            ("text field or plot", v.extreme_bg_color),
            ("striped row", over(v.faint_bg_color, v.panel_fill)),
        ];
        let texts = [
            ("text", v.text_color()),
            ("weak text", v.weak_text_color()),
            ("hint text", v.weak_text_color()),
            ("strong text", v.strong_text_color()),
            ("hyperlink", v.hyperlink_color),
            ("warning", v.warn_fg_color),
            ("error", v.error_fg_color),
        ];
        let mut cases = Vec::new();
        for (text, color) in texts {
            for (background, fill) in backgrounds {
                cases.push((
                    format!("{text} on the {background}"),
                    over(color, fill),
                    fill,
                ));
            }
        }
        // The text on a control, on the control's own fill, in each state.
        let w = &v.widgets;
        for (state, wv) in [
            ("button", w.inactive),
            ("hovered button", w.hovered),
            ("pressed or focused button", w.active),
            ("open menu button", w.open),
        ] {
            let fill = over(wv.weak_bg_fill, v.panel_fill);
            cases.push((format!("{state}'s text"), wv.text_color(), fill));
        }
        cases
    }

    /// A selected tab's or button's text on its fill.
    fn selected_text(v: &egui::Visuals) -> f64 {
        contrast_ratio(v.selection.stroke.color, v.selection.bg_fill)
    }

    /// The boundaries and marks a person must see to use a control (1.4.11),
    /// each on what is around it.
    fn stroke_cases(v: &egui::Visuals) -> Vec<(&'static str, Color32, Color32)> {
        let w = &v.widgets;
        vec![
            (
                "button, checkbox and field border",
                w.inactive.bg_stroke.color,
                v.panel_fill,
            ),
            ("hovered border", w.hovered.bg_stroke.color, v.panel_fill),
            ("focus ring", w.active.bg_stroke.color, v.panel_fill),
            (
                "focus ring on a field",
                w.active.bg_stroke.color,
                v.extreme_bg_color,
            ),
            (
                "focused text field's frame",
                v.selection.stroke.color,
                v.extreme_bg_color,
            ),
            (
                "slider rail and checkbox box",
                w.inactive.bg_fill,
                v.panel_fill,
            ),
            (
                "check mark and slider handle",
                w.inactive.fg_stroke.color,
                w.inactive.bg_fill,
            ),
            ("selected tab", v.selection.bg_fill, v.panel_fill),
            (
                "text cursor",
                v.text_cursor.stroke.color,
                v.extreme_bg_color,
            ),
        ]
    }

    fn check_theme(high_contrast: bool, text_min: f64, stroke_min: f64) -> Vec<String> {
        let v = style(high_contrast, false).visuals;
        let mut failures = Vec::new();
        for (name, fg, bg) in text_cases(&v) {
            let ratio = contrast_ratio(fg, bg);
            if ratio < text_min {
                failures.push(format!("{name}: {ratio:.2}:1 < {text_min}:1"));
            }
        }
        for (name, fg, bg) in stroke_cases(&v) {
            let ratio = contrast_ratio(fg, bg);
            if ratio < stroke_min {
                failures.push(format!("{name}: {ratio:.2}:1 < {stroke_min}:1"));
            }
        }
        failures
    }

    #[test]
    fn the_usual_theme_meets_wcag_aa_text_4_5_and_controls_3() {
        let failures = check_theme(false, 4.5, 3.0);
        assert!(failures.is_empty(), "{failures:#?}");
        let selected = selected_text(&visuals(false));
        assert!(selected >= 4.5, "selected text {selected:.2}");
    }

    #[test]
    fn the_high_contrast_theme_meets_7_to_1_text_and_strong_controls() {
        let failures = check_theme(true, 7.0, 3.0);
        assert!(failures.is_empty(), "{failures:#?}");
        let v = visuals(true);
        // The one text under 7:1 (see `high_contrast_visuals`), still AA.
        let selected = selected_text(&v);
        assert!(selected >= 4.5, "selected text {selected:.2}");
        for (name, stroke) in [
            ("border", v.widgets.inactive.bg_stroke.color),
            ("focus ring", v.widgets.active.bg_stroke.color),
            ("focused field", v.selection.stroke.color),
        ] {
            let ratio = contrast_ratio(stroke, v.panel_fill);
            assert!(ratio >= 7.0, "{name}: {ratio:.2}:1");
        }
        assert!(
            v.widgets.active.bg_stroke.width >= 3.0,
            "a thick focus ring"
        );
        assert!(v.widgets.inactive.bg_stroke.width >= 2.0, "strong borders");
    }

    #[test]
    fn egui_s_own_dark_theme_fails_where_ours_was_fixed() {
        // What this module changed, and why: egui's dark visuals as they were.
        let v = egui::Visuals::dark();
        let weak = contrast_ratio(over(v.weak_text_color(), v.panel_fill), v.panel_fill);
        assert!(weak < 4.5, "weak text {weak:.2}");
        let error = contrast_ratio(v.error_fg_color, v.panel_fill);
        assert!(error < 4.5, "error text {error:.2}");
        let rail = contrast_ratio(v.widgets.inactive.bg_fill, v.panel_fill);
        assert!(rail < 3.0, "slider rail {rail:.2}");
        let tab = contrast_ratio(v.selection.bg_fill, v.panel_fill);
        assert!(tab < 3.0, "selected tab {tab:.2}");
    }

    #[test]
    fn small_text_is_readable_and_motion_can_be_turned_off() {
        for high_contrast in [false, true] {
            let s = style(high_contrast, false);
            let small = egui::TextStyle::Small.resolve(&s).size;
            assert!(small >= 12.0, "small text {small}");
            assert!(s.animation_time > 0.0);
            let calm = style(high_contrast, true);
            assert_eq!(calm.animation_time, 0.0);
            assert_eq!(calm.visuals.widgets, s.visuals.widgets);
        }
    }

    #[test]
    fn install_puts_the_theme_in_the_context() {
        let ctx = egui::Context::default();
        install(&ctx, true, false);
        assert_eq!(ctx.style_of(egui::Theme::Dark).visuals, visuals(true));
        assert_eq!(ctx.theme(), egui::Theme::Dark);
        install(&ctx, false, true);
        assert_eq!(
            ctx.style_of(egui::Theme::Dark).visuals.widgets,
            visuals(false).widgets
        );
        assert_eq!(ctx.style_of(egui::Theme::Dark).animation_time, 0.0);
    }
}
