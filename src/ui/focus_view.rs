//! The keyboard's focus is never hidden below the fold (WCAG 2.4.7, 2.4.11):
//! egui moves the focus with Tab but does not scroll to it, so a control
//! reached with Tab could sit outside its scrolled panel or window. Each
//! scrolling container calls [`keep_focus_in_view`] at the end of its
//! contents, and scrolls to the widget that has just received the focus if
//! that widget is one of its own and out of sight.

use eframe::egui;

/// Scrolls the enclosing scroll area to the widget that just got the keyboard
/// focus, if it is inside this area's contents (`ui`) and not fully in view.
/// `area` names the scroll area (each remembers the focus it has seen, so a
/// person's own scrolling is never fought: only a change of focus scrolls).
pub fn keep_focus_in_view(ui: &mut egui::Ui, area: &str) {
    let Some(focused) = ui.ctx().memory(|m| m.focused()) else {
        return;
    };
    let seen_id = egui::Id::unique(("shoal_focus_seen", area));
    let seen: Option<egui::Id> = ui.data(|d| d.get_temp(seen_id));
    if seen == Some(focused) {
        return;
    }
    ui.data_mut(|d| d.insert_temp(seen_id, focused));
    let Some(response) = ui.ctx().read_response(focused) else {
        return;
    };
    let rect = response.rect;
    // Only a widget of this area's contents.
    if !ui.min_rect().expand(1.0).contains_rect(rect) {
        return;
    }
    if !ui.clip_rect().contains_rect(rect) {
        ui.scroll_to_rect(rect.expand(6.0), None);
    }
}
