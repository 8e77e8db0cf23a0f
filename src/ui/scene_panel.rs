//! The panel interface: what each scene shows around its tank.
//!
//! The app draws what every scene has (the scene tabs, play, pause, step, reset,
//! speed, seed, share and view in the side panel; the status line; the 3D views
//! and the camera) and asks the scene's [`ScenePanel`] for the rest: its own
//! controls, the panel under the tank, the drawings over each view, what a click
//! or drag on a view does, which animal is selected or followed, and where the
//! default camera looks. Each scene's class (`crate::scenes`) makes its panel;
//! the app knows no scene by name.

use eframe::egui;

use super::WidgetRects;
use crate::lab::{Lab, Run};
use crate::render::{Framing, OrbitCamera};
use crate::settings::{Settings, Side};

/// One-off things the user asked for this frame that every scene has. A scene's
/// own one-off actions (turn the selected fish, start a race…) stay inside its
/// panel and run in [`ScenePanel::apply`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PanelAction {
    /// Advance the simulation by one step.
    Step,
    /// Start the run again from the same seed.
    Reset,
    /// Put the camera back where it started.
    ResetView,
    /// Collapse the panel so the aquarium fills the screen.
    HidePanel,
    /// Put the link to this exact setting on the clipboard.
    CopyLink,
    /// Download the scene's own data (metrics, muscles, the reef's counts,
    /// events and minds, the learning history) as a CSV file.
    ExportCsv,
    /// Say the tank in words (the notice and the screen reader's live region).
    Describe,
    /// Open or close the *Keyboard* window.
    Keyboard,
}

/// A message shown at the top of the 3D view until dismissed.
#[derive(Clone, Debug, PartialEq)]
pub struct Notice {
    pub text: String,
    pub is_error: bool,
    /// The world (`Lab::world_generation`) the notice speaks of: it goes when
    /// that world is rebuilt (a new scene, demo or seed). `None`: it stays until
    /// closed.
    pub about_world: Option<u64>,
}

impl Notice {
    /// News the user asked for (a download started, a link copied).
    pub fn info(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            is_error: false,
            about_world: None,
        }
    }

    /// Something went wrong; nothing was changed.
    pub fn error(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            is_error: true,
            about_world: None,
        }
    }

    /// The same notice, gone once world `generation` is rebuilt.
    pub fn about_world(self, generation: u64) -> Self {
        Self {
            about_world: Some(generation),
            ..self
        }
    }
}

/// One 3D view as a scene panel sees it, to draw over it.
pub struct ViewContext<'a> {
    pub painter: &'a egui::Painter,
    pub rect: egui::Rect,
    pub camera: &'a OrbitCamera,
    pub run: &'a Run,
    /// How far the drawing is between the last two simulation steps.
    pub alpha: f32,
    pub side: Side,
    /// Two tanks are shown.
    pub comparing: bool,
    /// The two tanks are one above the other.
    pub stacked: bool,
    /// The side panel is hidden (its *Controls* button then sits at the top left).
    pub panel_hidden: bool,
}

/// A click or drag on one 3D view.
pub struct ViewInput<'a> {
    pub response: &'a egui::Response,
    pub rect: egui::Rect,
    pub camera: &'a OrbitCamera,
    pub lab: &'a Lab,
    pub side: Side,
}

impl ViewInput<'_> {
    /// The view's width over its height.
    pub fn aspect(&self) -> f32 {
        self.rect.width() / self.rect.height().max(1.0)
    }
}

/// What one scene adds to the screen. Every method but [`Self::controls_ui`] has
/// a default that adds nothing.
pub trait ScenePanel {
    /// Once a frame, before any panel is drawn: refresh what the panel shows
    /// from the simulation (a fish's retinal image, the learner's current
    /// drill), and use what arrived since the last frame (a file the user
    /// picked). A notice, if something needs saying.
    fn before_frame(
        &mut self,
        _lab: &mut Lab,
        _now_secs: f64,
        _ctx: &egui::Context,
    ) -> Option<Notice> {
        None
    }

    /// The scene's section of the side panel, under the controls every scene
    /// has. It edits `settings`; one-off actions wait for [`Self::apply`].
    fn controls_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings, rects: &mut WidgetRects);

    /// The panel under the tank, if the scene has one (see
    /// [`super::show_bottom_panel`]: its height comes from the window only). It
    /// may edit `settings` (a click on an event selects its fish).
    fn bottom_ui(
        &mut self,
        _ui: &mut egui::Ui,
        _lab: &Lab,
        _settings: &mut Settings,
        _rects: &mut WidgetRects,
    ) {
    }

    /// Drawings over a 3D view (skeletons, vision, selection rings…), and where
    /// pickable animals are on screen for the browser tests (`animal_0`, …).
    fn draw_overlays(&self, _view: &ViewContext, _settings: &Settings, _rects: &mut WidgetRects) {}

    /// A click or drag on a view: select a fish, add or move a rock. It may
    /// change `settings`, and say why it did not.
    fn view_input(&mut self, _input: &ViewInput, _settings: &mut Settings) -> Option<Notice> {
        None
    }

    /// Does the side panel offer *Experiment…* in this scene (at its top,
    /// beside *Investigations*, where a laptop's first screen shows it)?
    fn offers_experiment(&self) -> bool {
        false
    }

    /// True while a drag on the view belongs to the scene (a rock being moved),
    /// not to the camera.
    fn holds_drag(&self) -> bool {
        false
    }

    /// The scene's one-off actions asked for this frame, once the new settings
    /// are in use.
    fn apply(&mut self, _lab: &mut Lab, _ctx: &egui::Context) -> Option<Notice> {
        None
    }

    /// The animal drawn highlighted: the scene's selected one.
    fn selected(&self, settings: &Settings) -> Option<u32> {
        settings.selected()
    }

    /// The animal the camera follows.
    fn followed(&self, _settings: &Settings) -> Option<u32> {
        None
    }

    /// What the default camera shows, when not the whole tank from the front
    /// (the demo's subject: the pair, the shark and its prey…).
    fn framing(&self, _run: &Run, _settings: &Settings) -> Option<Framing> {
        None
    }

    /// The name of what the scene shows now (a demo), if it can change within
    /// the scene: a new subject is framed afresh, as a new scene is.
    fn view_subject(&self, _settings: &Settings) -> &'static str {
        ""
    }
}
