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
            let r = ui
                .add(
                    egui::Hyperlink::from_label_and_url(ts("about-odd"), odd_url(page.odd))
                        .open_in_new_tab(true),
                )
                .on_hover_text(ts("about-odd.help"));
            rects.insert("about_odd", r.rect);
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

/// Where the About window's *Model description (ODD)* link goes: in the browser
/// the page `odd/<name>.html` that the build makes from the markdown
/// (`web/odd-pages.sh`) and serves with the app; in the desktop app the markdown
/// itself, in the project's docs/ folder.
fn odd_url(odd: &str) -> String {
    if cfg!(target_arch = "wasm32") {
        format!("odd/{odd}.html")
    } else {
        format!("file://{}/docs/odd-{odd}.md", env!("CARGO_MANIFEST_DIR"))
    }
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

    /// Every scene's About links an ODD description that exists, and every
    /// docs/odd-*.md has the seven sections of the ODD protocol.
    #[test]
    fn every_scene_links_an_odd_with_the_seven_sections() {
        const SECTIONS: [&str; 7] = [
            "## 1. Purpose and patterns",
            "## 2. Entities, state variables and scales",
            "## 3. Process overview and scheduling",
            "## 4. Design concepts",
            "## 5. Initialisation",
            "## 6. Input data",
            "## 7. Submodels",
        ];
        let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
        for scene in Scene::ALL {
            let odd = scene.class().facts().about.odd;
            let file = docs.join(format!("odd-{odd}.md"));
            assert!(file.is_file(), "{scene:?} links {file:?}, which is missing");
            assert!(odd_url(odd).ends_with(&format!("docs/odd-{odd}.md")));
        }
        let mut odds = 0;
        for entry in std::fs::read_dir(&docs).unwrap() {
            let path = entry.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().to_string();
            if !(name.starts_with("odd-") && name.ends_with(".md")) {
                continue;
            }
            odds += 1;
            let text = std::fs::read_to_string(&path).unwrap();
            let headings: Vec<&str> = text.lines().filter(|l| l.starts_with("## ")).collect();
            for (k, section) in SECTIONS.iter().enumerate() {
                let at = headings.iter().position(|h| h == section);
                assert!(at.is_some(), "{name} lacks the heading {section:?}");
                if k > 0 {
                    let before = headings.iter().position(|h| h == &SECTIONS[k - 1]);
                    assert!(before < at, "{name}: {section:?} comes out of order");
                }
            }
            for concept in [
                "Basic principles",
                "Emergence",
                "Adaptation",
                "Objectives",
                "Learning",
                "Prediction",
                "Sensing",
                "Interaction",
                "Stochasticity",
                "Collectives",
                "Observation",
            ] {
                assert!(
                    text.contains(&format!("**{concept}**")),
                    "{name} lacks the design concept {concept}"
                );
            }
            assert!(!text.contains("../shared"), "{name} names ../shared");
        }
        // Each distinct ODD a scene links, and no ODD that no scene links.
        let linked: std::collections::BTreeSet<_> = Scene::ALL
            .iter()
            .map(|s| s.class().facts().about.odd)
            .collect();
        assert_eq!(
            odds,
            linked.len(),
            "an ODD in docs/ that no About links, or the reverse"
        );
        // The service worker keeps each page for offline use.
        let sw = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("web/shoal-sw.js"),
        )
        .unwrap();
        for name in &linked {
            assert!(
                sw.contains(&format!("\"odd/{name}.html\"")),
                "shoal-sw.js does not cache odd/{name}.html"
            );
        }
    }

    /// The link is in the window, under its catalogue name, in both languages.
    #[test]
    fn the_odd_link_has_words_in_both_languages() {
        assert_eq!(ts("about-odd"), "Model description (ODD)");
        crate::i18n::with_lang(crate::i18n::Lang::Es, || {
            assert_eq!(ts("about-odd"), "Descripción del modelo (ODD)");
        });
    }
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
