//! The app's fonts: subsets of egui's Ubuntu Light (text) and Hack (monospace),
//! with egui's five icons, installed in place of egui's whole default fonts.
//!
//! egui's defaults weigh 660 KB, about a tenth of the gzipped download. The
//! subsets (`assets/fonts`, made by `assets/fonts/subset.py`) keep every script
//! the catalogue and a class's typing use (Latin with every accent, Greek,
//! punctuation, arrows, maths) and every character in the sources, with the
//! hinting, so text is drawn exactly as before; together they gzip to about
//! 147 KB instead of 320 KB. The families are egui's: Hack first for monospace
//! with Ubuntu Light behind it, and egui's icons last in both.

use eframe::egui;
use egui::{FontData, FontDefinitions, FontFamily, FontTweak};
use std::sync::Arc;

/// Ubuntu Light, subset (Ubuntu Font Licence: `assets/fonts/UFL.txt`).
const TEXT_FONT: &[u8] = include_bytes!("../../assets/fonts/Ubuntu-Light-subset.ttf");
/// Hack, subset (MIT and Bitstream Vera: `assets/fonts/Hack-LICENSE.txt`).
const MONO_FONT: &[u8] = include_bytes!("../../assets/fonts/Hack-Regular-subset.ttf");
/// egui's own five icons (MIT: `assets/fonts/emoji-icon-font-mit-license.txt`).
const ICON_FONT: &[u8] = include_bytes!("../../assets/fonts/egui-icons.ttf");

const TEXT: &str = "Ubuntu-Light"; // words: a font's key, never shown
const MONO: &str = "Hack"; // words: a font's key, never shown
const ICONS: &str = "egui-icons"; // words: a font's key, never shown

/// The fonts every view of the app draws with.
pub fn definitions() -> FontDefinitions {
    let mut defs = FontDefinitions::empty();
    defs.font_data
        .insert(TEXT.to_owned(), Arc::new(FontData::from_static(TEXT_FONT)));
    defs.font_data
        .insert(MONO.to_owned(), Arc::new(FontData::from_static(MONO_FONT)));
    // egui draws its icons a tenth smaller than the text; so do we.
    let icons = FontData::from_static(ICON_FONT).tweak(FontTweak {
        scale: 0.90,
        ..Default::default()
    });
    defs.font_data.insert(ICONS.to_owned(), Arc::new(icons));
    defs.families.insert(
        FontFamily::Proportional,
        vec![TEXT.to_owned(), ICONS.to_owned()],
    );
    defs.families.insert(
        FontFamily::Monospace,
        vec![MONO.to_owned(), TEXT.to_owned(), ICONS.to_owned()],
    );
    defs
}

/// Installs the app's fonts in `ctx`.
pub fn install(ctx: &egui::Context) {
    ctx.set_fonts(definitions());
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::epaint::text::{Fonts, TextOptions};

    fn fonts(defs: FontDefinitions) -> Fonts {
        Fonts::new(TextOptions::default(), defs)
    }

    /// Every character the catalogue and the sources show, and every character
    /// of the scripts a class types (Latin, Greek, punctuation, maths), is drawn
    /// by the subsets wherever egui's whole fonts drew it: nothing turns into a
    /// missing-glyph box.
    #[test]
    fn the_subset_fonts_draw_every_character_egui_s_fonts_drew() {
        let mut ours = fonts(definitions());
        let mut egui_s = fonts(FontDefinitions::default());
        let ranges = [
            0x20..=0x7E,
            0xA0..=0x24F,
            0x370..=0x3FF,
            0x1E00..=0x1EFF,
            0x2000..=0x22FF,
        ];
        let mut catalogue: Vec<char> = Vec::new();
        for dir in ["locales/en", "locales/es"] {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
            for entry in std::fs::read_dir(path).expect("the catalogue") {
                let text = std::fs::read_to_string(entry.expect("a file").path()).expect("text");
                catalogue.extend(text.chars());
            }
        }
        catalogue.sort_unstable();
        catalogue.dedup();
        let text: Vec<char> = ranges
            .into_iter()
            .flatten()
            .filter_map(char::from_u32)
            .chain(catalogue.iter().copied())
            .collect();
        // Monospace shows numbers, values and links: Latin-1 and the catalogue's
        // symbols; any other character falls back to the text font.
        let mono: Vec<char> = (0x20..=0xFF)
            .filter_map(char::from_u32)
            .chain(catalogue.iter().copied())
            .collect();
        let mut lost = Vec::new();
        for (family, chars) in [
            (FontFamily::Proportional, &text),
            (FontFamily::Monospace, &mono),
        ] {
            let id = egui::FontId::new(14.0, family);
            for &c in chars {
                if egui_s.has_glyph(&id, c) && !ours.has_glyph(&id, c) {
                    lost.push((id.family.clone(), c));
                }
            }
        }
        lost.dedup();
        assert!(lost.is_empty(), "glyphs lost: {lost:?}");
        // And the test can fail: a font without Greek loses ζ.
        let mut latin_only = FontDefinitions::empty();
        latin_only
            .font_data
            .insert(MONO.to_owned(), Arc::new(FontData::from_static(MONO_FONT)));
        latin_only
            .families
            .insert(FontFamily::Proportional, vec![MONO.to_owned()]);
        let id = egui::FontId::proportional(14.0);
        assert!(!fonts(latin_only).has_glyph(&id, 'ζ'));
        assert!(egui_s.has_glyph(&id, 'ζ'));
    }
}
