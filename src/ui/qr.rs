//! A QR code of a link, drawn with egui rectangles (dark modules on a white
//! square with the standard quiet zone), big enough to project.

use eframe::egui;
use qrcodegen::{QrCode, QrCodeEcc};

/// Light modules round the code, on each side (4: the standard's quiet zone,
/// which phone cameras need to find the code).
const QUIET_ZONE_MODULES: i32 = 4;

/// The QR code of `text`, at the lowest error correction level that holds it
/// (a projected code is sharp; a lower level keeps the modules bigger).
pub fn encode(text: &str) -> Result<QrCode, String> {
    QrCode::encode_text(text, QrCodeEcc::Low)
        .map_err(|_| crate::tr!("about-qr-too-long", count = text.len()))
}

/// The modules across, quiet zone included.
pub fn modules_across(code: &QrCode) -> i32 {
    code.size() + 2 * QUIET_ZONE_MODULES
}

/// Draws `code` in a square of `side` points and returns its response.
pub fn draw(ui: &mut egui::Ui, code: &QrCode, side: f32) -> egui::Response {
    let (rect, response) = ui.allocate_exact_size(egui::vec2(side, side), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, egui::Color32::WHITE);
    let across = modules_across(code) as f32;
    let module = side / across;
    for y in 0..code.size() {
        for x in 0..code.size() {
            if code.get_module(x, y) {
                let min = rect.min
                    + egui::vec2(
                        (x + QUIET_ZONE_MODULES) as f32 * module,
                        (y + QUIET_ZONE_MODULES) as f32 * module,
                    );
                // A hair wider than a module, so neighbours join without seams.
                let size = egui::vec2(module + 0.5, module + 0.5);
                painter.rect_filled(
                    egui::Rect::from_min_size(min, size),
                    0.0,
                    egui::Color32::BLACK,
                );
            }
        }
    }
    response
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_share_link_fits_and_a_huge_text_is_refused_with_a_reason() {
        let mut settings = crate::settings::Settings::default();
        settings.studio.question = "Why do the fish bunch up when the shark comes? ".repeat(20);
        let link = format!(
            "https://example.org/shoal/#{}",
            crate::settings::share_link::encode(&settings)
        );
        let code = encode(&link).expect("a share link with a long question fits");
        assert!(code.size() >= 21 && code.size() <= 177);
        assert_eq!(modules_across(&code), code.size() + 8);
        let Err(err) = encode(&"x".repeat(5000)) else {
            panic!("5,000 characters fit no QR code");
        };
        assert!(err.contains("too long"), "{err}");
    }

    /// The student link's QR code at the studio's defaults and at a typical
    /// lesson, before (every setting in the link, the first format) and now
    /// (only what differs from the defaults, the mystery values sealed): the
    /// figures in docs/reliability.md (`cargo test --lib qr:: -- --nocapture`).
    #[test]
    fn student_links_are_short_enough_for_a_coarse_qr_code() {
        use crate::settings::Settings;
        use crate::settings::share_link::{decode, pack_json};
        let page = "https://example.org/shoal/";
        let version = |link: &str| (encode(link).unwrap().size() - 17) / 4;
        let lesson = crate::settings::studio::tests::two_mysteries(false);
        let mut no_question = lesson.clone();
        no_question.studio.question.clear();
        for (what, settings, max_version) in [
            ("the defaults", Settings::default(), 4),
            ("three locks, two mysteries", no_question, 10),
            ("three locks, two mysteries, a question", lesson, 11),
        ] {
            let link = crate::ui::studio_panel::student_link(&settings, page);
            let mut student = settings.clone();
            student.studio.student_view = true;
            let before = format!(
                "{page}#{}",
                pack_json(&serde_json::to_string(&student).unwrap())
            );
            eprintln!(
                "student link, {what}: before {} characters, QR version {}; now {} characters, QR version {}",
                before.len(),
                version(&before),
                link.len(),
                version(&link),
            );
            assert!(version(&link) <= max_version, "{what}: {link}");
            assert!(version(&link) < version(&before), "{what}: shorter");
            let opened = decode(link.split_once('#').unwrap().1).unwrap().unwrap();
            assert_eq!(opened, student, "{what}");
        }
    }
}
