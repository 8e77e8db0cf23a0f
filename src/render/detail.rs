//! How many pixels the tank is drawn with: all of them, or fewer on a computer whose
//! graphics cannot keep up.
//!
//! Drawing the 3D tank is most of a frame's cost on a weak GPU (a school
//! Chromebook, or a software renderer), and that cost grows with the pixels drawn.
//! With *Auto* on (the default) the tank is drawn into a smaller image when frames
//! are slow because of the drawing, and the image is stretched over the view; the
//! panels, plots and text keep every pixel. The scale comes back up when frames are
//! fast again. Dynamic resolution of this kind is what games do on weak hardware.
//!
//! The rule: a tank that runs (not paused) at fewer than 24 frames per second for a
//! second, while less than 60 % of each frame is the page's own work (so the wait
//! is for the graphics), is drawn with 0.8 × the pixels per side, down to half. At
//! more than 45 frames per second for three seconds it is drawn with 1.25 × as
//! many, up to all. One step changes the pixels drawn by 1.56×, less than the 1.9×
//! between the two thresholds, so the scale settles instead of swinging. Only the
//! picture changes: the simulation never reads it.

/// The smallest scale per side: half, a quarter of the pixels.
pub const MIN_SCALE: f32 = 0.5;
/// One step down multiplies the scale per side by this; one step up divides by it.
const STEP: f32 = 0.8;
/// Frames slower than this, seconds (24 per second), count as slow.
const SLOW_FRAME_SECS: f64 = 1.0 / 24.0;
/// Frames faster than this, seconds (45 per second), count as fast.
const FAST_FRAME_SECS: f64 = 1.0 / 45.0;
/// Seconds of slow frames before a step down.
const SLOW_FOR_SECS: f64 = 1.0;
/// Seconds of fast frames before a step up.
const FAST_FOR_SECS: f64 = 3.0;
/// A frame slower than this, seconds, is a hiccup (a hidden tab, loading), not a
/// measure of the drawing.
const HICCUP_SECS: f64 = 1.0;
/// A slow frame counts only when the page's own work (simulation, panels) is less
/// than this share of it: otherwise fewer pixels would not make it faster.
const GPU_BOUND_BELOW_CPU_SHARE: f64 = 0.6;

/// The tank's drawing scale, chosen automatically or pinned at full.
#[derive(Clone, Debug)]
pub struct SceneDetail {
    /// Whether the scale follows the frame rate (`true`, the default) or stays at 1.
    pub auto: bool,
    scale: f32,
    slow_secs: f64,
    fast_secs: f64,
}

impl Default for SceneDetail {
    fn default() -> Self {
        Self {
            auto: true,
            scale: 1.0,
            slow_secs: 0.0,
            fast_secs: 0.0,
        }
    }
}

impl SceneDetail {
    /// Pixels per side the tank is drawn with, as a share of the view's (1 = all).
    pub fn scale(&self) -> f32 {
        if self.auto { self.scale } else { 1.0 }
    }

    /// Turns the automatic scale on or off; off draws every pixel at once.
    pub fn set_auto(&mut self, auto: bool) {
        self.auto = auto;
        if !auto {
            self.scale = 1.0;
        }
        self.slow_secs = 0.0;
        self.fast_secs = 0.0;
    }

    /// Takes one frame into account: it lasted `frame_secs`, of which the page's
    /// own work took `cpu_secs` (when known); `running` is whether the tank moves
    /// by itself (a paused tank draws only when asked, so its frame times say
    /// nothing about the drawing).
    pub fn observe(&mut self, frame_secs: f64, cpu_secs: Option<f64>, running: bool) {
        let measurable = frame_secs > 0.0 && frame_secs <= HICCUP_SECS;
        if !self.auto || !running || !measurable {
            return;
        }
        let drawing_bound = cpu_secs.is_none_or(|cpu| cpu < GPU_BOUND_BELOW_CPU_SHARE * frame_secs);
        if frame_secs > SLOW_FRAME_SECS && drawing_bound {
            self.slow_secs += frame_secs;
            self.fast_secs = 0.0;
        } else if frame_secs < FAST_FRAME_SECS {
            self.fast_secs += frame_secs;
            self.slow_secs = 0.0;
        } else {
            self.slow_secs = 0.0;
            self.fast_secs = 0.0;
        }
        if self.slow_secs >= SLOW_FOR_SECS && self.scale > MIN_SCALE {
            self.scale = (self.scale * STEP).max(MIN_SCALE);
            self.slow_secs = 0.0;
        } else if self.fast_secs >= FAST_FOR_SECS && self.scale < 1.0 {
            self.scale = (self.scale / STEP).min(1.0);
            self.fast_secs = 0.0;
        }
    }

    /// The size in pixels to draw a view of `view_px` pixels with.
    pub fn image_size(&self, view_px: [f32; 2]) -> [u32; 2] {
        let scale = self.scale();
        view_px.map(|side| (side * scale).round().max(1.0) as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(detail: &mut SceneDetail, secs: f64, frame_secs: f64, cpu_secs: Option<f64>) {
        let mut t = 0.0;
        while t < secs {
            detail.observe(frame_secs, cpu_secs, true);
            t += frame_secs;
        }
    }

    #[test]
    fn slow_drawing_lowers_the_scale_step_by_step_down_to_half() {
        let mut d = SceneDetail::default();
        assert_eq!(d.scale(), 1.0);
        // A software GPU: 4 frames a second, the page's own work 30 ms of each.
        run(&mut d, 1.1, 0.25, Some(0.03));
        assert!(
            (d.scale() - 0.8).abs() < 1e-6,
            "one step after a second: {}",
            d.scale()
        );
        run(&mut d, 10.0, 0.25, Some(0.03));
        assert_eq!(d.scale(), MIN_SCALE);
        assert_eq!(d.image_size([1000.0, 600.0]), [500, 300]);
    }

    #[test]
    fn fast_frames_bring_every_pixel_back_and_the_middle_band_holds() {
        let mut d = SceneDetail::default();
        run(&mut d, 10.0, 0.1, None);
        assert_eq!(d.scale(), MIN_SCALE);
        // 30 frames a second: between the thresholds, the scale stays.
        run(&mut d, 20.0, 1.0 / 30.0, None);
        assert_eq!(d.scale(), MIN_SCALE);
        run(&mut d, 3.1, 1.0 / 60.0, None);
        assert!(
            (d.scale() - 0.625).abs() < 1e-6,
            "one step up: {}",
            d.scale()
        );
        run(&mut d, 30.0, 1.0 / 60.0, None);
        assert_eq!(d.scale(), 1.0);
    }

    #[test]
    fn slow_frames_of_the_pages_own_work_paused_tanks_and_hiccups_change_nothing() {
        let mut d = SceneDetail::default();
        // The simulation takes most of the frame: fewer pixels would not help.
        run(&mut d, 10.0, 0.1, Some(0.08));
        assert_eq!(d.scale(), 1.0);
        // Paused: frames come when the user does something.
        for _ in 0..100 {
            d.observe(0.5, Some(0.01), false);
        }
        assert_eq!(d.scale(), 1.0);
        // A hidden tab or loading: one frame of seconds.
        for _ in 0..10 {
            d.observe(3.0, Some(0.01), true);
        }
        assert_eq!(d.scale(), 1.0);
        for bad in [f64::NAN, -1.0, 0.0] {
            d.observe(bad, None, true);
        }
        assert_eq!(d.scale(), 1.0);
    }

    #[test]
    fn auto_off_draws_every_pixel_and_on_again_starts_from_there() {
        let mut d = SceneDetail::default();
        run(&mut d, 10.0, 0.25, None);
        assert_eq!(d.scale(), MIN_SCALE);
        d.set_auto(false);
        assert_eq!(d.scale(), 1.0);
        run(&mut d, 10.0, 0.25, None);
        assert_eq!(d.scale(), 1.0, "off stays at every pixel");
        assert_eq!(d.image_size([1280.4, 720.0]), [1280, 720]);
        d.set_auto(true);
        assert_eq!(d.scale(), 1.0);
        run(&mut d, 1.1, 0.25, None);
        assert!(d.scale() < 1.0);
    }
}
