//! *About this scene*: a window with what the scene is, how it works, things
//! to notice and to try, and the references; the equations one click deeper
//! (the words are in `about_text.rs`). The side panel's button opens it; it
//! stays open over the tank while the fish swim, and fits a phone's screen.

use eframe::egui;

use super::WidgetRects;
use crate::i18n::ts;
use crate::settings::Scene;
use crate::tr;

/// Whether the window is open, kept in egui's memory (it belongs to this
/// screen, not to the run a link shares).
fn open_id() -> egui::Id {
    egui::Id::unique("about_open")
}

/// The side panel's *About this scene* button.
pub fn about_button(ui: &mut egui::Ui, rects: &mut WidgetRects) {
    let r = ui
        .button(ts("about-button"))
        .on_hover_text(ts("about-button.help"));
    rects.insert("about", r.rect);
    if r.clicked() {
        let id = open_id();
        ui.data_mut(|d| {
            let open = d.get_temp_mut_or_default::<bool>(id);
            *open = !*open;
        });
    }
}

/// The window, when open, for `scene`.
pub fn about_window(ctx: &egui::Context, scene: Scene, rects: &mut WidgetRects) {
    let id = open_id();
    let mut open = ctx.data(|d| d.get_temp::<bool>(id).unwrap_or(false));
    if !open {
        return;
    }
    let screen = ctx.content_rect();
    let width = (screen.width() - 24.0).clamp(200.0, 560.0);
    let page = scene.class().facts().about;
    let shown = egui::Window::new(tr!(
        "about-window-title",
        scene = scene.class().facts().label()
    ))
    .id(egui::Id::unique(("about_window", scene.name())))
    .open(&mut open)
    .collapsible(false)
    .resizable(true)
    .default_width(width)
    .max_width(width)
    .default_height((screen.height() - 96.0).max(200.0))
    .max_height((screen.height() - 80.0).max(200.0))
    .default_pos(screen.right_top() + egui::vec2(-width - 12.0, 48.0))
    .constrain(true)
    .show(ctx, |ui| {
        egui::ScrollArea::vertical().show(ui, |ui| {
            ui.label(ts(page.what));
            section(ui, ts("about-how"));
            ui.label(ts(page.how));
            section(ui, ts("about-notice"));
            bullets(ui, page.notice);
            section(ui, ts("about-try"));
            bullets(ui, page.try_this);
            let r = egui::CollapsingHeader::new(ts("about-equations"))
                .id_salt("about_equations")
                .show(ui, |ui| {
                    for (k, (name, formula)) in
                        page.equations.iter().flat_map(|g| g.iter()).enumerate()
                    {
                        let r = ui.label(egui::RichText::new(ts(name)).strong());
                        if k == 0 {
                            rects.insert("about_equation_0", r.rect);
                        }
                        ui.label(ts(formula));
                        ui.add_space(4.0);
                    }
                    ui.label(egui::RichText::new(ts("about-equations-docs")).italics());
                });
            rects.insert("about_equations", r.header_response.rect);
            section(ui, ts("about-references"));
            for reference in page.references {
                ui.label(egui::RichText::new(ts(reference)).weak());
            }
        });
    });
    if let Some(shown) = shown {
        rects.insert("about_window", shown.response.rect);
    }
    ctx.data_mut(|d| d.insert_temp(id, open));
}

fn section(ui: &mut egui::Ui, title: &str) {
    ui.add_space(6.0);
    ui.label(egui::RichText::new(title).strong());
}

fn bullets(ui: &mut egui::Ui, items: &[&'static str]) {
    for item in items {
        ui.horizontal_wrapped(|ui| {
            ui.label("•");
            ui.label(ts(item));
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{Lang, has, tr, with_lang};

    #[test]
    fn every_scene_has_a_whole_page_in_every_language() {
        for lang in Lang::ALL {
            with_lang(lang, || {
                for scene in Scene::ALL {
                    let page = scene.class().facts().about;
                    let (what, how) = (tr(page.what), tr(page.how));
                    assert!(what.len() > 80 && how.len() > 150, "{scene:?} {lang:?}");
                    assert!(
                        page.notice.len() >= 2 && page.try_this.len() >= 2,
                        "{scene:?}"
                    );
                    assert!(!page.references.is_empty(), "{scene:?}");
                    assert!(
                        page.equations.iter().flat_map(|g| g.iter()).count() >= 3,
                        "{scene:?}"
                    );
                    // Every message is in the catalogue, a formula under its name.
                    for id in page.ids() {
                        assert!(has(lang, id), "{id} in {lang:?}");
                    }
                    for (name, formula) in page.equations.iter().flat_map(|g| g.iter()) {
                        assert_eq!(formula.strip_suffix(".formula"), Some(*name));
                    }
                    // The repository explains itself: no pointer outside it.
                    for text in [what, how] {
                        assert!(
                            !text.contains("shared") && !text.contains("NOTES"),
                            "{scene:?}"
                        );
                    }
                }
            });
        }
    }

    #[test]
    fn the_pages_speak_spanish_with_decimal_commas() {
        with_lang(Lang::Es, || {
            assert_eq!(ts("about-how"), "Cómo funciona");
            let notice = tr(crate::ui::about_text::SCHOOLING_LAB.notice[0]);
            assert!(
                notice.contains("cardumen") && notice.contains("0,8"),
                "{notice}"
            );
            let springs = tr("about-eq-mass-motion.formula");
            assert!(
                springs.contains("0,165") && springs.contains("γ = 0,05"),
                "{springs}"
            );
            let title = tr!("about-window-title", scene = "Arrecife");
            assert_eq!(title, "Acerca de: Arrecife");
            let Err(refused) = super::super::qr::encode(&"x".repeat(12_345)) else {
                panic!("12,345 characters fit no QR code");
            };
            assert!(
                refused.contains("demasiado largo") && refused.contains("12.345"),
                "{refused}"
            );
        });
        // English keeps its words and its decimal points.
        with_lang(Lang::En, || {
            let notice = tr(crate::ui::about_text::SCHOOLING_LAB.notice[0]);
            assert!(notice.starts_with("The Group preset makes a school: polarization near 0.8"));
        });
    }

    #[test]
    fn the_window_opens_from_its_button_and_fits_a_phone() {
        let ctx = egui::Context::default();
        let size = egui::vec2(390.0, 844.0);
        let mut rects = WidgetRects::new();
        for frame in 0..4 {
            let input = egui::RawInput {
                screen_rect: Some(egui::Rect::from_min_size(egui::Pos2::ZERO, size)),
                time: Some(f64::from(frame) / 60.0),
                ..Default::default()
            };
            rects.clear();
            let mut output = ctx.run_ui(input, |ui| {
                egui::CentralPanel::default().show(ui, |ui| about_button(ui, &mut rects));
                // Open it on the first frame, as its button does.
                if frame == 0 {
                    ui.ctx().data_mut(|d| d.insert_temp(open_id(), true));
                }
                about_window(ui.ctx(), Scene::Reef, &mut rects);
            });
            output.textures_delta.clear();
        }
        let window = rects.get("about_window").expect("the window is open");
        assert!(
            window.left() >= 0.0 && window.right() <= size.x,
            "{window:?}"
        );
        assert!(rects.get("about_equations").is_some());
        assert!(rects.get("about").is_some());
    }
}
