//! The egui panels around the aquarium. The controls every scene has are in
//! `control_panel.rs`; each scene's own controls, panel under the tank, overlays
//! and picking are its [`ScenePanel`] (each scene's class in `crate::scenes`
//! makes it). Panels
//! edit `Settings` and report one-off actions; the only simulation calls they
//! make are a scene's own actions, in [`ScenePanel::apply`].

mod about;
pub mod about_text;
pub mod body_overlay;
pub(crate) mod boids_attention;
pub mod boids_panel;
pub mod bottom_panel;
pub mod class_panel;
pub mod clicks;
mod control_panel;
mod experiment_panel;
mod experiment_plot;
mod files;
pub mod focus_view;
pub mod fonts;
mod investigation_panel;
mod investigation_plot;
pub mod language;
pub mod learning_panel;
mod metrics_panel;
pub mod palette;
pub mod physics_panel;
pub mod predation_panel;
mod qr;
pub mod reef_inspector;
mod reef_minds;
pub mod reef_overlay;
pub mod reef_panel;
mod reef_skip;
pub mod scene_panel;
pub mod screen;
pub mod seeing;
pub mod setting_slider;
mod status_line;
pub mod studio_panel;
mod tank_panel;
pub mod theme;

pub use about::about_window;
pub use bottom_panel::show_bottom_panel;
pub use control_panel::{ViewOptions, control_panel_ui};
pub use experiment_panel::{ExperimentOutcome, ExperimentPanel, LabCost};
pub use files::{FileError, save_text_file};
pub use investigation_panel::{InvestigationAction, InvestigationPanel, investigations_button};
pub use learning_panel::{SaveControllersError, controllers_json};
pub use metrics_panel::{METRICS_PANEL_HEIGHT, metrics_panel_ui, side_color};
pub use physics_panel::{BODY_PLOTS_PANEL_HEIGHT, body_plots_ui};
pub use scene_panel::{Notice, PanelAction, ScenePanel, ViewContext, ViewInput};
pub use status_line::status_line_ui;
pub use studio_panel::StudioPanel;
pub use tank_panel::mode_label;

/// Where the named widgets were drawn this frame, in egui points (CSS pixels in the
/// browser). `shoal.widgets()` reports them so browser tests can click real widgets.
#[derive(Clone, Debug, Default)]
pub struct WidgetRects(std::collections::BTreeMap<String, eframe::egui::Rect>);

impl WidgetRects {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn insert(&mut self, name: &str, rect: eframe::egui::Rect) {
        self.0.insert(name.to_owned(), rect);
    }

    pub fn clear(&mut self) {
        self.0.clear();
    }

    pub fn get(&self, name: &str) -> Option<&eframe::egui::Rect> {
        self.0.get(name)
    }

    pub fn iter(&self) -> impl Iterator<Item = (&String, &eframe::egui::Rect)> {
        self.0.iter()
    }
}
