//! The panels under the tank (the boid metrics, the physics fish's muscle plots,
//! the learning plots, the reef inspector) have a height chosen from the window,
//! never from what they hold: a panel that takes its contents' height while the
//! contents take the panel's height grows by its margin every frame until the
//! tank is a strip (issue 14).

use eframe::egui;

use crate::i18n::{fmt, ts};

/// The largest share of the window's height a panel under the tank takes: the
/// tank and the control panel keep the rest.
pub const BOTTOM_PANEL_MAX_SHARE: f32 = 0.3;

/// The smallest height of a panel under the tank, points (frame included): less
/// and its plots are unreadable. In a window so low that this is more than
/// [`BOTTOM_PANEL_MAX_SHARE`] of it, the share wins.
pub const BOTTOM_PANEL_MIN_HEIGHT: f32 = 100.0;

/// The height, points (frame included), of a panel under the tank that would like
/// `wanted` points in a window `window_height` points high: `wanted`, but at most
/// [`BOTTOM_PANEL_MAX_SHARE`] of the window, and not below
/// [`BOTTOM_PANEL_MIN_HEIGHT`] unless the window is too low for it. It depends on
/// nothing else, so it cannot creep from one frame to the next.
pub fn bottom_panel_height(window_height: f32, wanted: f32) -> f32 {
    let cap = BOTTOM_PANEL_MAX_SHARE * window_height.max(0.0);
    wanted
        .min(cap)
        .max(BOTTOM_PANEL_MIN_HEIGHT.min(cap))
        .round()
}

/// The height left for a plot under a caption row: the panel's content height
/// less the caption and the spacing below it, and never negative.
pub fn plot_height_under_caption(content_height: f32, caption_height: f32, spacing: f32) -> f32 {
    (content_height - caption_height - spacing).max(0.0)
}

/// A "nice" step (1, 2, 2.5 or 5 times a power of ten) at least `raw`.
fn nice_step(raw: f64) -> f64 {
    if !(raw.is_finite() && raw > 0.0) {
        return 1.0;
    }
    let power = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .into_iter()
        .map(|m| m * power)
        .find(|step| *step >= raw * (1.0 - 1e-9))
        .unwrap_or(10.0 * power)
}

/// Grid marks for a plot's value axis that a class can read from the back: a
/// nice step giving two to four numbered lines over the visible range, so even a
/// low plot shows more than "0" (`egui_plot`'s own spacer numbers only lines
/// far enough apart for its default label spacing).
pub fn readable_marks(input: egui_plot::GridInput) -> Vec<egui_plot::GridMark> {
    let (lo, hi) = input.bounds;
    let step = nice_step((hi - lo) / 3.0).max(input.base_step_size);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last)
        .map(|k| egui_plot::GridMark {
            value: k as f64 * step,
            step_size: step,
        })
        .collect()
}

/// A number on a plot axis: as many decimals as the grid step needs.
pub fn axis_number(value: f64, step: f64) -> String {
    let decimals = (0..3)
        .find(|d| {
            let scaled = step * 10f64.powi(*d);
            (scaled - scaled.round()).abs() < 1e-6 * scaled.max(1.0)
        })
        .unwrap_or(3) as usize;
    fmt(value, decimals)
}

/// A plot over time a class reads: `height` points tall, numbered value and
/// time axes (seconds), not dragged, zoomed or scrolled by a stray gesture.
pub fn time_plot<'a>(
    id: impl std::hash::Hash + std::fmt::Debug,
    height: f32,
) -> egui_plot::Plot<'a> {
    egui_plot::Plot::new(id)
        .height(height)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .y_grid_spacer(readable_marks)
        .y_axis_formatter(|mark, _| axis_number(mark.value, mark.step_size))
        .x_grid_spacer(readable_marks)
        .custom_x_axes(vec![readable_x_axis(|mark, _| {
            // As many decimals as the marks' spacing needs (0.5 s early in a run).
            format!("{} s", axis_number(mark.value, mark.step_size))
        })])
}

/// An x axis whose numbers are drawn at full strength: egui_plot fades x
/// labels fewer than 80 points apart (down to nothing at 60), and a narrow
/// plot's few [`readable_marks`] are often closer, so its numbers came out
/// faint (under 4.5:1). 44 points apart is room for "100 s".
pub fn readable_x_axis<'a>(
    formatter: impl Fn(egui_plot::GridMark, &std::ops::RangeInclusive<f64>) -> String + 'a,
) -> egui_plot::AxisHints<'a> {
    egui_plot::AxisHints::new_x()
        .formatter(formatter)
        .label_spacing(40.0..=44.0)
}

/// Shows a panel under the tank (`id`), [`bottom_panel_height`] high for a
/// panel that would like `wanted` points. It is not resizable: its height is
/// exact, so nothing inside it can make it grow. `add_contents` gets the height
/// its contents have, points (the panel's less its frame), and must fit in it.
pub fn show_bottom_panel<R>(
    ui: &mut egui::Ui,
    id: &str,
    wanted: f32,
    rects: &mut super::WidgetRects,
    add_contents: impl FnOnce(&mut egui::Ui, f32, &mut super::WidgetRects) -> R,
) -> R {
    let height = bottom_panel_height(ui.ctx().content_rect().height(), wanted);
    let response = egui::Panel::bottom(id)
        .resizable(false)
        .exact_size(height)
        .show(ui, |ui| {
            let content_height = ui.available_height();
            add_contents(ui, content_height, rects)
        });
    rects.insert(&format!("panel_{id}"), response.response.rect);
    // The panel's name for a screen reader.
    let _ = response
        .response
        .accessible_name(ts("metrics-bottom-panel.name"));
    response.inner
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_axes_get_two_to_four_nice_numbered_lines() {
        for (lo, hi) in [
            (0.0, 1.0),
            (0.0, 1.83),
            (0.0, 0.42),
            (0.0, 31.0),
            (0.3, 0.9),
        ] {
            let marks = readable_marks(egui_plot::GridInput {
                bounds: (lo, hi),
                base_step_size: 1e-6,
            });
            assert!((2..=4).contains(&marks.len()), "{lo}–{hi}: {marks:?}");
            assert!(marks.iter().all(|m| (lo..=hi).contains(&m.value)));
        }
        assert_eq!(axis_number(0.5, 0.25), "0.50");
        assert_eq!(axis_number(0.4, 0.2), "0.4");
        assert_eq!(axis_number(10.0, 5.0), "10");
        assert_eq!(nice_step(0.61), 1.0);
        assert_eq!(nice_step(0.14), 0.2);
    }
    use crate::lab::Lab;
    use crate::settings::{Scene, Settings};
    use crate::ui::learning_panel::{LEARNING_PANEL_HEIGHT, learning_plots_ui};
    use crate::ui::reef_inspector::{reef_inspector_height, reef_inspector_ui};
    use crate::ui::{
        BODY_PLOTS_PANEL_HEIGHT, METRICS_PANEL_HEIGHT, WidgetRects, body_plots_ui, metrics_panel_ui,
    };

    /// Draws `frames` frames of a window `size` points big, with `panel` under a
    /// central panel (the tank), and returns each frame's widget rectangles
    /// (`tank` is the central panel).
    fn run_frames(
        size: egui::Vec2,
        frames: usize,
        mut panel: impl FnMut(&mut egui::Ui, &mut WidgetRects),
    ) -> Vec<WidgetRects> {
        let ctx = egui::Context::default();
        (0..frames)
            .map(|frame| {
                let input = egui::RawInput {
                    screen_rect: Some(egui::Rect::from_min_size(egui::Pos2::ZERO, size)),
                    time: Some(frame as f64 / 60.0),
                    ..Default::default()
                };
                let mut rects = WidgetRects::new();
                let mut output = ctx.run_ui(input, |ui| {
                    panel(ui, &mut rects);
                    egui::CentralPanel::default().show(ui, |ui| {
                        rects.insert("tank", ui.max_rect());
                    });
                });
                // No painter here: the font atlas is not uploaded.
                output.textures_delta.clear();
                rects
            })
            .collect()
    }

    /// The height of `name` in every frame.
    fn heights(frames: &[WidgetRects], name: &str) -> Vec<f32> {
        frames
            .iter()
            .map(|r| {
                r.get(name)
                    .unwrap_or_else(|| panic!("{name} not drawn"))
                    .height()
            })
            .collect()
    }

    /// Asserts that the panel `panel` and the tank keep one height over all the
    /// frames, the panel the one [`bottom_panel_height`] gives for `wanted`, and
    /// that `inside` (widgets in the panel) lie within it.
    fn assert_steady(
        frames: &[WidgetRects],
        window: egui::Vec2,
        panel: &str,
        wanted: f32,
        inside: &[&str],
    ) {
        let expected = bottom_panel_height(window.y, wanted);
        for h in heights(frames, panel) {
            assert_eq!(h, expected, "{panel}: {:?}", heights(frames, panel));
        }
        let tank = heights(frames, "tank");
        assert!(tank.iter().all(|h| *h == tank[0]), "the tank: {tank:?}");
        let last = frames.last().unwrap();
        let panel_rect = *last.get(panel).unwrap();
        // Never wider than the window: an over-wide panel under the tank once
        // made clicks in the side panel go astray (compare mode, long captions).
        assert!(
            panel_rect.width() <= window.x + 0.5,
            "{panel} is {} wide in a {} window",
            panel_rect.width(),
            window.x
        );
        for name in inside {
            let r = last.get(name).unwrap_or_else(|| panic!("{name} not drawn"));
            assert!(
                panel_rect.expand(0.5).contains_rect(*r),
                "{name} {r:?} spills out of {panel} {panel_rect:?}"
            );
        }
    }

    #[test]
    fn contents_that_take_the_panels_height_grow_a_resizable_panel_but_not_this_one() {
        let window = egui::vec2(1280.0, 720.0);
        // The pattern of issue 14: a caption row, then a plot as tall as the height
        // available before the caption.
        let greedy = |ui: &mut egui::Ui, available: f32| {
            ui.horizontal(|ui| ui.label("caption"));
            ui.allocate_space(egui::vec2(100.0, available - 22.0));
        };
        let resizable = run_frames(window, 100, |ui, rects| {
            let r = egui::Panel::bottom("greedy")
                .resizable(true)
                .default_size(170.0)
                .show(ui, |ui| greedy(ui, ui.available_height()));
            rects.insert("panel_greedy", r.response.rect);
        });
        let grown = heights(&resizable, "panel_greedy");
        assert!(
            grown[99] > grown[0] + 50.0,
            "the old panel grows: {grown:?}"
        );

        let fixed = run_frames(window, 100, |ui, rects| {
            show_bottom_panel(ui, "greedy", 170.0, rects, |ui, height, _| {
                greedy(ui, height)
            });
        });
        assert_steady(&fixed, window, "panel_greedy", 170.0, &[]);
    }

    #[test]
    fn the_physics_fish_plots_keep_their_height() {
        let mut settings = Settings {
            scene: Scene::Physics,
            ..Settings::default()
        };
        settings.physics.selected = Some(0);
        let mut lab = Lab::new(settings);
        lab.step(40);
        for window in [egui::vec2(1366.0, 1000.0), egui::vec2(1024.0, 400.0)] {
            let frames = run_frames(window, 300, |ui, rects| {
                show_bottom_panel(
                    ui,
                    "body_plots",
                    BODY_PLOTS_PANEL_HEIGHT,
                    rects,
                    |ui, height, rects| {
                        body_plots_ui(ui, &lab.runs()[0], Some(0), height, rects);
                    },
                );
            });
            assert_steady(
                &frames,
                window,
                "panel_body_plots",
                BODY_PLOTS_PANEL_HEIGHT,
                &["muscle_plot_0", "muscle_plot_2", "speed_plot"],
            );
            let plot = frames[299].get("muscle_plot_0").unwrap().height();
            assert!(plot > 60.0, "a readable plot: {plot}");
        }
    }

    #[test]
    fn the_metrics_and_reef_panels_keep_their_height() {
        let window = egui::vec2(1280.0, 720.0);
        let boids = Lab::new(Settings {
            scene: Scene::Boids,
            compare: true,
            ..Settings::default()
        });
        let labels = vec!["left".to_owned(), "right".to_owned()];
        let frames = run_frames(window, 120, |ui, rects| {
            show_bottom_panel(
                ui,
                "metrics",
                METRICS_PANEL_HEIGHT,
                rects,
                |ui, height, rects| {
                    metrics_panel_ui(ui, boids.runs(), &labels, height, rects);
                },
            );
        });
        assert_steady(
            &frames,
            window,
            "panel_metrics",
            METRICS_PANEL_HEIGHT,
            &["plot_0", "plot_4", "plot_urges"],
        );

        let mut settings = Settings {
            scene: Scene::Reef,
            ..Settings::default()
        };
        settings.reef.selected = Some(0);
        let mut reef = Lab::new(settings);
        reef.step(20);
        for selected in [Some(0), None] {
            let wanted = reef_inspector_height(selected.is_some());
            let frames = run_frames(window, 120, |ui, rects| {
                show_bottom_panel(ui, "reef_inspector", wanted, rects, |ui, height, rects| {
                    reef_inspector_ui(ui, &reef.runs()[0], selected, None, height, rects);
                });
            });
            let inside: &[&str] = if selected.is_some() {
                &["reef_mind_plot", "reef_events"]
            } else {
                &["reef_events"]
            };
            assert_steady(&frames, window, "panel_reef_inspector", wanted, inside);
        }
    }

    #[test]
    fn on_a_phone_the_reef_inspector_shows_one_column_under_tabs() {
        // 390 points wide, a fish selected: tabs, the mind column alone at
        // the full width, the panel within the window and of a steady height.
        let window = egui::vec2(390.0, 844.0);
        let mut settings = Settings {
            scene: Scene::Reef,
            ..Settings::default()
        };
        settings.reef.selected = Some(0);
        let reef = Lab::new(settings);
        let wanted = reef_inspector_height(true);
        let frames = run_frames(window, 30, |ui, rects| {
            show_bottom_panel(ui, "reef_inspector", wanted, rects, |ui, height, rects| {
                reef_inspector_ui(ui, &reef.runs()[0], Some(0), None, height, rects);
            });
        });
        assert_steady(
            &frames,
            window,
            "panel_reef_inspector",
            wanted,
            &["reef_inspector"],
        );
        let last = frames.last().unwrap();
        for tab in ["mind", "history", "sees", "log"] {
            let r = last.get(&format!("reef_tab_{tab}")).expect(tab);
            assert!(r.right() <= window.x, "{tab}: {r:?}");
        }
        assert!(last.get("reef_events").is_none(), "one column at a time");
        assert!(last.get("reef_mind_plot").is_none(), "one column at a time");
        // A wide window keeps the columns side by side, without tabs.
        let frames = run_frames(egui::vec2(1366.0, 1000.0), 3, |ui, rects| {
            show_bottom_panel(ui, "reef_inspector", wanted, rects, |ui, height, rects| {
                reef_inspector_ui(ui, &reef.runs()[0], Some(0), None, height, rects);
            });
        });
        let last = frames.last().unwrap();
        assert!(last.get("reef_tab_mind").is_none());
        assert!(last.get("reef_events").is_some() && last.get("reef_mind_plot").is_some());
    }

    #[test]
    fn the_learning_plots_keep_their_height() {
        let window = egui::vec2(1366.0, 1000.0);
        let lab = Lab::new(Settings {
            scene: Scene::Learning,
            ..Settings::default()
        });
        let abstraction = lab.runs()[0]
            .scene()
            .learning()
            .map(|l| l.current_abstraction());
        let frames = run_frames(window, 120, |ui, rects| {
            show_bottom_panel(
                ui,
                "learning_plots",
                LEARNING_PANEL_HEIGHT,
                rects,
                |ui, height, rects| {
                    learning_plots_ui(ui, &lab.runs()[0], abstraction.as_ref(), height, rects);
                },
            );
        });
        assert_steady(
            &frames,
            window,
            "panel_learning_plots",
            LEARNING_PANEL_HEIGHT,
            &[
                "learning_objective_plot",
                "learning_raw_plot",
                "learning_abstract_plot",
            ],
        );
    }

    #[test]
    fn a_panel_gets_what_it_wants_up_to_a_share_of_the_window() {
        assert_eq!(bottom_panel_height(1000.0, 180.0), 180.0);
        assert_eq!(bottom_panel_height(720.0, 180.0), 180.0);
        // A panel that asks for a lot gets 30 % of the window, whatever it asks.
        assert_eq!(bottom_panel_height(720.0, 10_000.0), 216.0);
        assert_eq!(bottom_panel_height(1000.0, f32::INFINITY), 300.0);
        // A low window: the share wins over the wish and the minimum.
        assert_eq!(bottom_panel_height(300.0, 180.0), 90.0);
        // A small wish is raised to the minimum when the window has room.
        assert_eq!(bottom_panel_height(1000.0, 20.0), BOTTOM_PANEL_MIN_HEIGHT);
        assert_eq!(bottom_panel_height(0.0, 180.0), 0.0);
    }

    #[test]
    fn a_plot_under_a_caption_fits_the_content_height() {
        assert_eq!(plot_height_under_caption(170.0, 20.0, 3.0), 147.0);
        assert_eq!(plot_height_under_caption(10.0, 20.0, 3.0), 0.0);
    }
}
