//! *Skip to the moment* for the reef's demos: the button and the search's
//! progress in the side panel, a banner over the tank while it looks ahead,
//! and when the moment is found, a notice and the camera on the fish it is
//! about (see `lab/skip.rs`: the run is put back a few seconds before it).

use eframe::egui;

use super::WidgetRects;
use super::scene_panel::Notice;
use crate::i18n::ts;
use crate::lab::{Lab, SkipOutcome, SkipProgress};
use crate::settings::Settings;
use crate::tr;

/// What the user asked for this frame.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Request {
    Start,
    Cancel,
}

/// The skip's part of the reef panel.
#[derive(Default)]
pub struct SkipUi {
    /// The demo's moment ("the shark's next catch"), refreshed every frame.
    moment: Option<&'static str>,
    progress: Option<SkipProgress>,
    /// Skips whose ending was shown.
    seen_finished: u64,
    request: Option<Request>,
    /// The animal to select and follow once the panel next edits settings.
    follow: Option<u32>,
}

impl SkipUi {
    /// Reads the search's progress; a notice when a skip has just ended.
    pub fn before_frame(&mut self, lab: &Lab) -> Option<Notice> {
        self.moment = lab.scene().moment().map(|m| m.words());
        self.progress = lab.skipping();
        if lab.skips_finished() == self.seen_finished {
            return None;
        }
        self.seen_finished = lab.skips_finished();
        let notice = match lab.skip_outcome()? {
            SkipOutcome::Found {
                moment,
                resumed_at_secs,
            } => {
                self.follow = moment.follow.then_some(moment.subject);
                let wait = (moment.time_secs - resumed_at_secs).round();
                Notice::info(tr!(
                    "reef-skip-found",
                    time = clock(*resumed_at_secs),
                    seconds = wait as i64,
                    line = &moment.words
                ))
            }
            SkipOutcome::NotFound {
                what,
                searched_secs,
            } => Notice::info(tr!(
                "reef-skip-not-found",
                // The moment of this scene, in the language in force.
                what = self.moment.unwrap_or(what),
                time = clock(*searched_secs)
            )),
        };
        // It speaks of this run's moment: another demo or seed makes it wrong.
        Some(notice.about_world(lab.world_generation()))
    }

    /// The button, or the search's progress and *Cancel*. Also selects and
    /// follows the moment's animal once found.
    pub fn controls_ui(
        &mut self,
        ui: &mut egui::Ui,
        settings: &mut Settings,
        rects: &mut WidgetRects,
    ) {
        self.take_follow(settings);
        let Some(what) = self.moment else {
            return;
        };
        match self.progress {
            None => {
                let r = ui
                    .button(tr!("reef-skip", what = what))
                    .on_hover_text(ts("reef-skip.help"));
                rects.insert("reef_skip", r.rect);
                if r.clicked() {
                    self.request = Some(Request::Start);
                    settings.paused = false;
                }
            }
            Some(p) => {
                ui.horizontal(|ui| {
                    ui.add(
                        egui::ProgressBar::new((p.searched_secs / p.limit_secs) as f32)
                            .desired_width(140.0)
                            .text(tr!("reef-skip-looked", time = clock(p.searched_secs))),
                    );
                    let r = ui.button(ts("reef-skip-cancel"));
                    rects.insert("reef_skip_cancel", r.rect);
                    if r.clicked() {
                        self.request = Some(Request::Cancel);
                    }
                });
            }
        }
    }

    /// Selects and follows the animal of a moment just found.
    pub fn take_follow(&mut self, settings: &mut Settings) {
        if let Some(subject) = self.follow.take() {
            settings.reef.selected = Some(subject);
            settings.reef.follow = true;
        }
    }

    /// Starts or cancels the search the user asked for.
    pub fn apply(&mut self, lab: &mut Lab) -> Option<Notice> {
        match self.request.take()? {
            Request::Start => lab
                .skip_to_moment()
                .err()
                .map(|e| Notice::error(e.to_string())),
            Request::Cancel => {
                lab.cancel_skip();
                None
            }
        }
    }

    /// While looking ahead: a banner at the top of the tank saying so.
    pub fn draw_banner(&self, painter: &egui::Painter, rect: egui::Rect) {
        let (Some(p), Some(what)) = (self.progress, self.moment) else {
            return;
        };
        let galley = painter.layout_no_wrap(
            tr!(
                "reef-skip-banner",
                what = what,
                time = clock(p.searched_secs)
            ),
            egui::FontId::proportional(16.0),
            egui::Color32::WHITE,
        );
        let at = egui::pos2(rect.center().x, rect.top() + 40.0);
        let banner = egui::Rect::from_center_size(at, galley.size()).expand(6.0);
        painter.rect_filled(banner, 4.0, egui::Color32::from_black_alpha(170));
        painter.galley(
            banner.min + egui::vec2(6.0, 6.0),
            galley,
            egui::Color32::WHITE,
        );
    }
}

/// Simulated time as "1:05".
fn clock(secs: f64) -> String {
    let s = secs.max(0.0).round() as u64;
    format!("{}:{:02}", s / 60, s % 60)
}
