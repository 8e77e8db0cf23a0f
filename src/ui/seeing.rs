//! The *Seeing* view options: a high-contrast theme and reduced motion. They
//! belong to this screen, not to the run a link shares, and live in egui's
//! memory for the session like the other view options, so any panel can read
//! them without a new argument ([`get`]) and changing one reinstalls the
//! theme ([`set`]).
//!
//! In the browser they start from the person's own settings (the media
//! queries `prefers-reduced-motion: reduce` and `prefers-contrast: more`) and
//! from the page address (`?contrast=high`, `?motion=reduce`), see
//! [`initial`]; natively from nothing, with the toggles in the View section.

use eframe::egui;
use serde::Serialize;

use super::WidgetRects;
use crate::i18n::ts;

/// The view options for people who see differently (`state().seeing`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Seeing {
    /// The high-contrast theme (white on black, strong borders, a thick
    /// yellow focus ring), see [`super::theme`].
    pub high_contrast: bool,
    /// Calm motion: the water's caustics and light shafts stand still, the
    /// camera that follows a fish moves only when the fish nears the edge of
    /// the view, and the panels open without animation.
    pub reduce_motion: bool,
}

fn id() -> egui::Id {
    egui::Id::unique("shoal_seeing_options")
}

/// The options in force.
pub fn get(ctx: &egui::Context) -> Seeing {
    ctx.data(|d| d.get_temp(id())).unwrap_or_default()
}

/// Keeps `seeing` for the session and installs its theme.
pub fn set(ctx: &egui::Context, seeing: Seeing) {
    ctx.data_mut(|d| d.insert_temp(id(), seeing));
    install(ctx);
}

/// Installs the theme of the options in force (the app calls it once at
/// start).
pub fn install(ctx: &egui::Context) {
    let seeing = get(ctx);
    super::theme::install(ctx, seeing.high_contrast, seeing.reduce_motion);
    ctx.request_repaint();
}

/// The options a page opens with, and whether it starts paused: from the
/// person's settings (`prefers_reduced_motion`, `prefers_more_contrast`,
/// the browser's media queries) and the page's query string `search`
/// (`?contrast=high` or `?contrast=normal`, `?motion=reduce` or
/// `?motion=full`, which win). Reduced motion at the start also starts the
/// fish paused: nothing moves until someone presses Play.
pub fn initial(
    search: &str,
    prefers_reduced_motion: bool,
    prefers_more_contrast: bool,
) -> (Seeing, bool) {
    use crate::settings::share_link::query_value;
    let url = format!("?{}", search.trim_start_matches('?'));
    let mut seeing = Seeing {
        high_contrast: prefers_more_contrast,
        reduce_motion: prefers_reduced_motion,
    };
    match query_value(&url, "contrast") {
        Some("high" | "more") => seeing.high_contrast = true,
        Some("normal" | "standard") => seeing.high_contrast = false,
        _ => {}
    }
    match query_value(&url, "motion") {
        Some("reduce" | "reduced") => seeing.reduce_motion = true,
        Some("full" | "normal") => seeing.reduce_motion = false,
        _ => {}
    }
    (seeing, seeing.reduce_motion)
}

/// What the notice says when a page starts paused for reduced motion: its
/// words, in the language in force, are what it turns `Into` (a `String`).
pub const STARTED_PAUSED: StartedPaused = StartedPaused;

/// The notice of a page that starts paused for reduced motion (see
/// [`STARTED_PAUSED`]).
#[derive(Clone, Copy, Debug)]
pub struct StartedPaused;

impl From<StartedPaused> for String {
    fn from(_: StartedPaused) -> String {
        ts("seeing-started-paused").to_owned()
    }
}

/// Hover help of the two toggles.
pub fn high_contrast_help() -> &'static str {
    ts("seeing-high-contrast.help")
}

pub fn reduce_motion_help() -> &'static str {
    ts("seeing-reduce-motion.help")
}

/// The two toggles, in the View section of the side panel.
pub fn seeing_ui(ui: &mut egui::Ui, rects: &mut WidgetRects) {
    let mut seeing = get(ui.ctx());
    let before = seeing;
    ui.horizontal_wrapped(|ui| {
        let r = ui
            .checkbox(&mut seeing.high_contrast, ts("seeing-high-contrast"))
            .on_hover_text(high_contrast_help());
        rects.insert("high_contrast", r.rect);
        let r = ui
            .checkbox(&mut seeing.reduce_motion, ts("seeing-reduce-motion"))
            .on_hover_text(reduce_motion_help());
        rects.insert("reduce_motion", r.rect);
    });
    if seeing != before {
        set(ui.ctx(), seeing);
    }
}

/// How far, as a share of the camera's distance, a followed fish may stray
/// from the point the camera looks at before a calm camera moves: 0.25,
/// chosen (the fish stays in the middle half of the view).
pub const CALM_FOLLOW_SLACK: f32 = 0.25;

/// Where a calm follow camera looks when its fish is at `fish` and it looked
/// at `target`, `distance` away: it stays put while the fish is within
/// [`CALM_FOLLOW_SLACK`] of the distance, and otherwise moves just enough to
/// bring the fish back to that edge (no gliding, no overshoot).
pub fn calm_follow_target(target: glam::Vec3, fish: glam::Vec3, distance: f32) -> glam::Vec3 {
    let slack = CALM_FOLLOW_SLACK * distance.max(0.0);
    let away = fish - target;
    let length = away.length();
    if length <= slack {
        target
    } else {
        fish - away / length * slack
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn the_person_s_settings_and_the_link_choose_the_start() {
        assert_eq!(initial("", false, false), (Seeing::default(), false));
        let (seeing, paused) = initial("", true, false);
        assert!(seeing.reduce_motion && !seeing.high_contrast && paused);
        let (seeing, _) = initial("?bench", false, true);
        assert!(seeing.high_contrast);
        let (seeing, paused) = initial("?contrast=high&motion=reduce", false, false);
        assert_eq!(
            seeing,
            Seeing {
                high_contrast: true,
                reduce_motion: true
            }
        );
        assert!(paused);
        // The link wins over the computer's setting.
        let (seeing, paused) = initial("motion=full&contrast=normal", true, true);
        assert_eq!(seeing, Seeing::default());
        assert!(!paused);
    }

    #[test]
    fn the_toggles_change_the_theme_and_are_remembered() {
        let ctx = egui::Context::default();
        install(&ctx);
        assert_eq!(get(&ctx), Seeing::default());
        assert_eq!(
            ctx.style_of(egui::Theme::Dark).visuals,
            super::super::theme::visuals(false)
        );
        set(
            &ctx,
            Seeing {
                high_contrast: true,
                reduce_motion: true,
            },
        );
        assert!(get(&ctx).high_contrast && get(&ctx).reduce_motion);
        let style = ctx.style_of(egui::Theme::Dark);
        assert_eq!(
            style.visuals.widgets,
            super::super::theme::visuals(true).widgets
        );
        assert_eq!(style.animation_time, 0.0);
    }

    #[test]
    fn the_toggles_are_drawn_with_their_names() {
        let ctx = egui::Context::default();
        let mut rects = WidgetRects::new();
        let mut output = ctx.run_ui(egui::RawInput::default(), |ui| {
            egui::CentralPanel::default().show(ui, |ui| seeing_ui(ui, &mut rects));
        });
        output.textures_delta.clear();
        assert!(rects.get("high_contrast").is_some());
        assert!(rects.get("reduce_motion").is_some());
        assert!(high_contrast_help().len() > 40 && reduce_motion_help().len() > 40);
        assert!(String::from(STARTED_PAUSED).starts_with("Reduced motion is on"));
    }

    #[test]
    fn a_calm_camera_moves_only_when_its_fish_nears_the_edge() {
        let target = Vec3::new(1.0, 1.0, 1.0);
        // Within a quarter of the distance (10 m): the camera stays.
        assert_eq!(
            calm_follow_target(target, target + Vec3::X * 2.0, 10.0),
            target
        );
        // Beyond: just enough to keep the fish at the edge.
        let fish = target + Vec3::X * 4.0;
        let moved = calm_follow_target(target, fish, 10.0);
        assert!((moved.distance(fish) - 2.5).abs() < 1e-5);
        assert!((moved - (target + Vec3::X * 1.5)).length() < 1e-5);
    }
}
