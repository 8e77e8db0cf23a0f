//! Surviving a lost graphics device. A Chromebook that sleeps or changes
//! screens can take the GPU away from the page (WebGL's `webglcontextlost`,
//! WebGPU's device `lost`). Everything the GPU held is gone, but nothing of the
//! lesson is on the GPU: the page starts a new renderer on the same canvas and
//! hands it the [`Session`] taken from the old app, so the fish, the clock, the
//! settings, the camera and the open windows carry on (`src/web/mod.rs`).

use crate::lab::Lab;
use crate::render::OrbitCamera;
use crate::render::SceneDetail;
use crate::scenes::CurrentPanel;
use crate::settings::{Scene, Settings};
use crate::ui::Notice;

use super::{ShoalApp, StartError};

/// What a running app owns that is not on the GPU and must outlive it.
pub struct Session {
    lab: Lab,
    camera: OrbitCamera,
    camera_is_default: bool,
    framed_aspect: f32,
    scene_detail: SceneDetail,
    panel_open: bool,
    interface_scale: Option<f32>,
    frames_drawn: u64,
    following: bool,
    viewed: Option<(Scene, &'static str)>,
    scene_panel: CurrentPanel,
    experiment: crate::ui::ExperimentPanel,
    studio: crate::ui::StudioPanel,
    investigations: crate::ui::InvestigationPanel,
    narrator: crate::a11y::describe::Narrator,
    keys_open: bool,
    page_url: Option<String>,
}

impl ShoalApp {
    /// Takes the lesson out of this app, whose GPU is gone; what is left
    /// behind is a default tank, about to be dropped.
    pub fn take_session(&mut self) -> Session {
        let scene = self.lab.settings().scene;
        Session {
            lab: std::mem::replace(&mut self.lab, Lab::new(Settings::default())),
            camera: self.camera.clone(),
            camera_is_default: self.camera_is_default,
            framed_aspect: self.framed_aspect,
            scene_detail: self.scene_detail.clone(),
            panel_open: self.panel_open,
            interface_scale: self.interface_scale,
            frames_drawn: self.frames_drawn,
            following: self.following,
            viewed: self.viewed,
            scene_panel: std::mem::replace(&mut self.scene_panel, CurrentPanel::new(scene)),
            experiment: std::mem::take(&mut self.experiment),
            studio: std::mem::take(&mut self.studio),
            investigations: std::mem::take(&mut self.investigations),
            narrator: std::mem::take(&mut self.narrator),
            keys_open: self.keys_open,
            page_url: self.page_url.take(),
        }
    }

    /// A new app on the new GPU that carries on `session`, saying what
    /// happened.
    pub fn resume(cc: &eframe::CreationContext<'_>, session: Session) -> Result<Self, StartError> {
        let mut app = Self::new(cc, session.lab.settings().clone())?;
        let Session {
            mut lab,
            camera,
            camera_is_default,
            framed_aspect,
            scene_detail,
            panel_open,
            interface_scale,
            frames_drawn,
            following,
            viewed,
            scene_panel,
            experiment,
            studio,
            investigations,
            narrator,
            keys_open,
            page_url,
        } = session;
        lab.set_frame_budget(Some(crate::lab::INTERACTIVE_FRAME_BUDGET_SECS));
        app.lab = lab;
        app.camera = camera;
        app.camera_is_default = camera_is_default;
        app.framed_aspect = framed_aspect;
        app.scene_detail = scene_detail;
        app.panel_open = panel_open;
        app.interface_scale = interface_scale;
        app.layout_chosen = true;
        app.frames_drawn = frames_drawn;
        app.following = following;
        app.viewed = viewed;
        app.scene_panel = scene_panel;
        app.experiment = experiment;
        app.studio = studio;
        app.investigations = investigations;
        app.narrator = narrator;
        app.keys_open = keys_open;
        app.page_url = page_url;
        app.notice = Some(Notice::info(crate::i18n::tr("app-gpu-recovered")));
        Ok(app)
    }
}
