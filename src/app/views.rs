//! The 3D views: one or two tanks laid out side by side or stacked, the
//! camera's input and framing, following the selected fish, and what each
//! scene draws over its view.

use eframe::egui;

use crate::render::OrbitCamera;
use crate::settings::{Settings, Side};
use crate::ui::{ViewContext, ViewInput};

use super::ShoalApp;

/// Time constant of the follow camera gliding to the selected fish, seconds (0.4,
/// chosen: smooth, and a fish at top speed never leaves the view, at any frame rate).
const FOLLOW_TIME_CONSTANT_SECS: f32 = 0.4;

/// The moment the water's caustics, light shafts and ripples are frozen at
/// with reduced motion (they animate with this time, nothing else does):
/// 3 s, chosen, a frame with a clear web of light on the sand.
const CALM_WATER_TIME_SECS: f32 = 3.0;

impl ShoalApp {
    /// Frames what the scene is about (the whole tank unless its panel says
    /// otherwise), and stops following.
    pub(super) fn reset_view(&mut self) {
        let tank = self.lab.scene().tank();
        let settings = self.lab.settings();
        self.camera = match self
            .scene_panel
            .for_scene(settings.scene)
            .framing(&self.lab.runs()[0], settings)
        {
            Some(framing) => OrbitCamera::framed(&framing, self.framed_aspect),
            None => OrbitCamera::framing(tank.min_m, tank.max_m, self.framed_aspect),
        };
        self.camera_is_default = true;
        self.following = false;
    }

    /// The interface scale (automatic unless chosen) and, on the first frame,
    /// the side panel closed in a narrow window (a phone sees the tank first).
    pub(super) fn choose_screen_layout(&mut self) {
        use crate::ui::screen::{auto_scale, is_narrow};
        let zoom = self.ctx.zoom_factor();
        let css = self.ctx.content_rect().size() * zoom;
        let wanted = self
            .interface_scale
            .unwrap_or_else(|| auto_scale(css.x, css.y));
        if (wanted - zoom).abs() > 0.005 {
            self.ctx.set_zoom_factor(wanted);
        }
        if !self.layout_chosen && css.x > 0.0 {
            self.layout_chosen = true;
            if is_narrow(css.x / wanted) {
                self.panel_open = false;
            }
        }
    }

    /// Orbit, zoom and pan from mouse and touch input on a 3D view.
    pub(super) fn camera_input(
        &mut self,
        ui: &egui::Ui,
        response: &egui::Response,
        rect: egui::Rect,
    ) {
        let camera_before = self.camera.clone();
        let (zoom, scroll, multi_touch) =
            ui.input(|i| (i.zoom_delta(), i.smooth_scroll_delta(), i.multi_touch()));
        if let Some(touch) = multi_touch {
            // Two fingers: pinch to zoom, drag to pan.
            if response.contains_pointer() || response.hovered() {
                self.camera.zoom(touch.zoom_delta);
                self.camera.pan(
                    touch.translation_delta.x,
                    touch.translation_delta.y,
                    rect.height(),
                );
            }
        } else {
            if response.dragged_by(egui::PointerButton::Primary)
                && !self.scene_panel.get().holds_drag()
            {
                let delta = response.drag_delta();
                self.camera.rotate(delta.x, delta.y);
            }
            if response.dragged_by(egui::PointerButton::Secondary)
                || response.dragged_by(egui::PointerButton::Middle)
            {
                let delta = response.drag_delta();
                self.camera.pan(delta.x, delta.y, rect.height());
            }
            if response.hovered() {
                self.camera.zoom(zoom * (scroll.y * 0.0015).exp());
            }
        }
        if self.camera != camera_before {
            self.camera_is_default = false;
        }
    }

    /// The 3D views: one tank, or two side by side (one above the other when
    /// that shows the tanks clearly bigger, see [`compare_layout`]).
    pub(super) fn views_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings) {
        let full = ui.available_rect_before_wrap();
        self.widget_rects.insert("aquarium", full);
        let frame_secs = ui.input(|i| i.stable_dt).min(0.5);
        self.follow_selected(settings, frame_secs);
        // The investigation window docks beside (or under) the tanks: they are
        // laid out in the room it leaves, so it never covers them.
        let tanks = self.investigations.tanks_area(ui.ctx(), full);
        let count = self.lab.runs().len();
        let rects = compare_layout(tanks, count);
        self.views_stacked = rects.len() > 1 && rects[0].left() == rects[1].left();
        let aspect = rects[0].width() / rects[0].height().max(1.0);
        if self.camera_is_default && (aspect - self.framed_aspect).abs() > 0.01 {
            self.framed_aspect = aspect;
            self.reset_view();
        }
        for (index, rect) in rects.into_iter().enumerate() {
            self.view_ui(ui, rect, index, settings);
        }
    }

    /// Glides the camera's target towards the animal the scene follows.
    pub(super) fn follow_selected(&mut self, settings: &Settings, frame_secs: f32) {
        let Some(selected) = self.scene_panel.get().followed(settings) else {
            self.following = false;
            return;
        };
        let run = &self.lab.runs()[0];
        let Some((_, centre, length)) = run
            .selectable_animals(self.lab.draw_alpha())
            .into_iter()
            .find(|a| a.0 == selected as usize)
        else {
            return;
        };
        if crate::ui::seeing::get(&self.ctx).reduce_motion {
            // Reduced motion: still while the fish is near the middle, then
            // just enough to keep it in view.
            self.camera.target_m = crate::ui::seeing::calm_follow_target(
                self.camera.target_m,
                centre,
                self.camera.distance_m,
            );
        } else {
            let share = 1.0 - (-frame_secs.max(0.0) / FOLLOW_TIME_CONSTANT_SECS).exp();
            self.camera.target_m = self.camera.target_m.lerp(centre, share);
        }
        // On starting to follow, come close enough to see the body bend: about eight
        // body lengths away (the teacher may zoom afterwards).
        if !self.following {
            self.following = true;
            self.camera.distance_m = self.camera.distance_m.min(8.0 * length);
        }
        self.camera_is_default = false;
        self.ctx.request_repaint();
    }

    pub(super) fn view_ui(
        &mut self,
        ui: &mut egui::Ui,
        rect: egui::Rect,
        index: usize,
        settings: &mut Settings,
    ) {
        let side = Side::BOTH[index];
        let response = ui.interact(
            rect,
            egui::Id::unique(("aquarium_view", index)),
            egui::Sense::click_and_drag(),
        );
        self.widget_rects
            .insert(&format!("view_{}", side.name()), rect);
        let input = ViewInput {
            response: &response,
            rect,
            camera: &self.camera,
            lab: &self.lab,
            side,
        };
        if let Some(notice) = self.scene_panel.get_mut().view_input(&input, settings) {
            self.notice = Some(notice);
        }
        self.camera_input(ui, &response, rect);

        let pixels_per_point = ui.ctx().pixels_per_point();
        let size_px = self.scene_detail.image_size([
            rect.width() * pixels_per_point,
            rect.height() * pixels_per_point,
        ]);
        let run = &self.lab.runs()[index];
        // The water animates with simulated time: pausing freezes the whole
        // picture. With reduced motion its caustics and light shafts stand still.
        let time_secs = if crate::ui::seeing::get(&self.ctx).reduce_motion {
            CALM_WATER_TIME_SECS
        } else {
            run.time_secs() as f32
        };
        self.frame_builders[index].set_selected(self.scene_panel.get().selected(settings));
        let frame = self.frame_builders[index].build(
            run,
            self.lab.draw_alpha(),
            &self.camera,
            size_px,
            time_secs,
            index as u32,
        );
        ui.painter()
            .add(eframe::egui_wgpu::Callback::new_paint_callback(rect, frame));

        let painter = ui.painter_at(rect);
        let view = ViewContext {
            painter: &painter,
            rect,
            camera: &self.camera,
            run,
            alpha: self.lab.draw_alpha(),
            side,
            comparing: self.lab.comparing(),
            stacked: self.views_stacked,
            panel_hidden: !self.panel_open,
        };
        self.scene_panel
            .get()
            .draw_overlays(&view, settings, &mut self.widget_rects);

        // Reset view, always at hand: at the top right of the last view.
        if index + 1 == self.lab.runs().len() {
            let size = egui::vec2(112.0, 26.0);
            let at = rect.right_top() + egui::vec2(-size.x - 8.0, 8.0);
            let button = ui
                .put(
                    egui::Rect::from_min_size(at, size),
                    egui::Button::new(crate::i18n::ts("app-reset-view")),
                )
                .on_hover_text(crate::i18n::ts("app-reset-view.help"));
            self.widget_rects.insert("reset_view", button.rect);
            if button.clicked() {
                self.reset_view();
            }
        }
    }
}

/// Width over height of the tank as the default camera frames it (about 2:1).
/// Used to judge which layout of two views shows the tanks bigger.
const FRAMED_TANK_ASPECT: f32 = 1.9;

/// Where `count` views (1 or 2) go in `full`. Two tanks sit side by side, or
/// one above the other when that draws them at least 15 % bigger (a tall
/// window, a portrait tablet): a framed tank fills the width of a view or the
/// height times [`FRAMED_TANK_ASPECT`], whichever is smaller.
fn compare_layout(full: egui::Rect, count: usize) -> Vec<egui::Rect> {
    const GAP: f32 = 4.0;
    if count < 2 {
        return vec![full];
    }
    let (w, h) = (full.width(), full.height());
    let side_by_side = ((w - GAP) / 2.0).min(h * FRAMED_TANK_ASPECT);
    let stacked = w.min((h - GAP) / 2.0 * FRAMED_TANK_ASPECT);
    if stacked > 1.15 * side_by_side {
        let height = (h - GAP) / 2.0;
        (0..count)
            .map(|i| {
                egui::Rect::from_min_size(
                    full.min + egui::vec2(0.0, i as f32 * (height + GAP)),
                    egui::vec2(w, height),
                )
            })
            .collect()
    } else {
        let width = (w - GAP) / 2.0;
        (0..count)
            .map(|i| {
                egui::Rect::from_min_size(
                    full.min + egui::vec2(i as f32 * (width + GAP), 0.0),
                    egui::vec2(width, h),
                )
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(w: f32, h: f32) -> egui::Rect {
        egui::Rect::from_min_size(egui::pos2(330.0, 0.0), egui::vec2(w, h))
    }

    #[test]
    fn two_tanks_sit_side_by_side_on_a_wide_screen_and_stack_on_a_tall_one() {
        // A projector (16:9 less the panel): side by side.
        let wide = compare_layout(rect(1590.0, 800.0), 2);
        assert_eq!(wide.len(), 2);
        assert_eq!(wide[0].top(), wide[1].top());
        assert!(wide[0].right() < wide[1].left());
        // A portrait tablet: one above the other, each the full width.
        let tall = compare_layout(rect(1036.0, 1000.0), 2);
        assert_eq!(tall[0].left(), tall[1].left());
        assert!(tall[0].bottom() < tall[1].top());
        assert_eq!(tall[0].width(), 1036.0);
        for layout in [wide, tall] {
            assert!(
                layout
                    .iter()
                    .all(|r| rect(1590.0, 1000.0).contains_rect(*r))
            );
        }
        assert_eq!(
            compare_layout(rect(800.0, 600.0), 1),
            vec![rect(800.0, 600.0)]
        );
    }
}
