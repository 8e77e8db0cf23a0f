//! The language the interface speaks: chosen from the page address
//! (`?lang=es`), else the person's last choice on this browser, else the
//! browser's own languages, else English ([`initial`]); changed with the
//! picker in the View section ([`choose`]). It travels in every link Shoal
//! makes (`?lang=` when it is not English, see [`with_lang`]).

use eframe::egui;

use crate::i18n::{self, Lang};
use crate::settings::share_link::{query_value, with_query, without_query};

/// The query parameter that names the language.
pub const KEY: &str = "lang";

/// The language a page opens in: `?lang=` in `search` if the catalogue has
/// it, else `stored` (the last choice here), else the first of `preferred`
/// (the browser's languages, best first) the catalogue has, else English.
pub fn initial<'a>(
    search: &str,
    stored: Option<&str>,
    preferred: impl IntoIterator<Item = &'a str>,
) -> Lang {
    let search = format!("?{}", search.trim_start_matches('?'));
    query_value(&search, KEY)
        .and_then(Lang::from_code)
        .or_else(|| stored.and_then(Lang::from_code))
        .or_else(|| Lang::first_known(preferred))
        .unwrap_or_default()
}

/// `url` naming the language in force: `?lang=<code>` for any language but
/// English, none for English (a link without it opens in each reader's own).
pub fn with_lang(url: &str) -> String {
    let url = without_query(url, KEY);
    match i18n::lang() {
        Lang::En => url,
        lang => with_query(&url, KEY, lang.code()),
    }
}

/// Puts `lang` in force: every word from the next frame on, the page's
/// `<html lang>`, and this browser's memory of the choice.
pub fn choose(ctx: &egui::Context, lang: Lang) {
    i18n::set_lang(lang);
    #[cfg(target_arch = "wasm32")]
    crate::web::set_language(lang, true);
    ctx.request_repaint();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_link_wins_then_the_last_choice_then_the_browser() {
        assert_eq!(initial("?lang=es", Some("en"), ["en-US"]), Lang::Es);
        assert_eq!(initial("?bench&lang=es-MX", None, []), Lang::Es);
        assert_eq!(initial("?lang=xx", Some("es"), ["en"]), Lang::Es);
        assert_eq!(initial("", None, ["fr-FR", "es-419"]), Lang::Es);
        assert_eq!(initial("", None, ["fr-FR"]), Lang::En);
        assert_eq!(initial("", Some("en"), ["es"]), Lang::En);
    }

    #[test]
    fn links_carry_the_language_unless_it_is_english() {
        i18n::with_lang(Lang::Es, || {
            assert_eq!(with_lang("https://x.org/"), "https://x.org/?lang=es");
            assert_eq!(
                with_lang("https://x.org/?investigation=why-school&lang=en"),
                "https://x.org/?investigation=why-school&lang=es"
            );
        });
        i18n::with_lang(Lang::En, || {
            assert_eq!(with_lang("https://x.org/?lang=es"), "https://x.org/");
        });
    }
}
