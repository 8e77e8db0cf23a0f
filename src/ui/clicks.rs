//! Clicks on a slow machine.
//!
//! egui counts a press and its release as a click only if the button was down
//! for less than `max_click_duration` (0.8 s), timed by the frames in which
//! the press and the release arrive. On a school laptop that draws one frame a
//! second (a loaded Chromebook, a large tank on a software GPU) a quick click
//! whose press and release fall in two frames measures a whole frame, more
//! than 0.8 s, and is lost: the button does nothing. [`allow_slow_frames`]
//! widens that window by two frames of the time the page takes to draw one, so
//! a click is a click at any frame rate; at 60 frames a second it stays 0.83 s.

use eframe::egui;

/// egui's own limit, seconds (its default).
const QUICK_CLICK_SECS: f64 = 0.8;

/// The longest frame counted, seconds: a tab woken from the background can
/// report minutes.
const LONGEST_FRAME_SECS: f64 = 5.0;

/// The longest press that still counts as a click after a frame of
/// `frame_secs`: egui's 0.8 s plus two such frames.
pub fn max_click_secs(frame_secs: f64) -> f64 {
    let frame = if frame_secs.is_finite() {
        frame_secs.clamp(0.0, LONGEST_FRAME_SECS)
    } else {
        0.0
    };
    QUICK_CLICK_SECS + 2.0 * frame
}

/// Sets egui's click window for the frames to come from the time the last
/// frame took (called once a frame).
pub fn allow_slow_frames(ctx: &egui::Context, frame_secs: f64) {
    let secs = max_click_secs(frame_secs);
    if ctx.options(|o| o.input_options.max_click_duration) != secs {
        ctx.options_mut(|o| o.input_options.max_click_duration = secs);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs one frame at `time` with `events`, the button drawn; was it clicked?
    fn frame(ctx: &egui::Context, time: f64, events: Vec<egui::Event>) -> bool {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(400.0, 300.0),
            )),
            time: Some(time),
            events,
            ..Default::default()
        };
        let mut clicked = false;
        let mut output = ctx.run_ui(input, |ui| {
            clicked = ui.button("Join").clicked(); // words: a test's button
        });
        output.textures_delta.clear();
        clicked
    }

    fn button(down: bool) -> egui::Event {
        egui::Event::PointerButton {
            pos: egui::pos2(20.0, 12.0),
            button: egui::PointerButton::Primary,
            pressed: down,
            modifiers: egui::Modifiers::NONE,
        }
    }

    /// A quick click whose press and release fall in two frames one second
    /// apart (a page at 1 frame a second): clicked or not?
    fn click_across_slow_frames(widened: bool) -> bool {
        let ctx = egui::Context::default();
        let at = egui::Event::PointerMoved(egui::pos2(20.0, 12.0));
        frame(&ctx, 0.0, vec![at.clone()]);
        frame(&ctx, 1.0, vec![at]);
        if widened {
            allow_slow_frames(&ctx, 1.0);
        }
        let pressed = frame(&ctx, 2.0, vec![button(true)]);
        let released = frame(&ctx, 3.0, vec![button(false)]);
        pressed || released
    }

    #[test]
    fn a_click_split_over_two_one_second_frames_counts_only_with_the_widened_window() {
        assert!(!click_across_slow_frames(false), "egui alone loses it");
        assert!(click_across_slow_frames(true));
    }

    #[test]
    fn the_window_is_egui_s_at_a_fast_frame_rate_and_bounded_for_a_stalled_one() {
        assert!((max_click_secs(1.0 / 60.0) - 0.8333).abs() < 1e-3);
        assert!((max_click_secs(1.0) - 2.8).abs() < 1e-9);
        assert_eq!(max_click_secs(600.0), max_click_secs(LONGEST_FRAME_SECS));
        assert_eq!(max_click_secs(f64::NAN), QUICK_CLICK_SECS);
        assert_eq!(max_click_secs(-1.0), QUICK_CLICK_SECS);
    }
}
