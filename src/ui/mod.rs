//! The egui panels around the aquarium. They edit `Settings` and report one-off
//! actions; they never touch the simulation directly.

mod control_panel;
mod status_line;

pub use control_panel::{PanelAction, control_panel_ui};
pub use status_line::status_line_ui;

/// Where the named widgets were drawn this frame, in egui points (CSS pixels in the
/// browser). `shoal.widgets()` reports them so browser tests can click real widgets.
pub type WidgetRects = std::collections::BTreeMap<&'static str, eframe::egui::Rect>;
