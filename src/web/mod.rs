//! Browser glue: starts eframe on the page's canvas, explains failures on the page
//! itself (no GPU, a panic), and installs the `window.shoal` automation API.

mod a11y_dom;
mod api;
pub(crate) mod class_net;
pub(crate) mod page;
mod recover;

use crate::ShoalApp;
use crate::settings::Settings;

pub use a11y_dom::announce;
pub use page::{download_text, pick_text_file};

/// Where this browser remembers the language last chosen.
const LANGUAGE_STORE_KEY: &str = "shoal.lang";

/// Where this browser remembers the student's name for the record (only
/// here: it never leaves the browser).
const STUDENT_STORE_KEY: &str = "shoal.student";

/// The student's name this browser remembers (empty if none).
pub fn stored_student_name() -> String {
    web_sys::window()
        .and_then(|w| w.local_storage().ok().flatten())
        .and_then(|s| s.get_item(STUDENT_STORE_KEY).ok().flatten())
        .unwrap_or_default()
}

/// Remembers the student's name in this browser (forgets it when empty).
pub fn store_student_name(name: &str) {
    if let Some(storage) = web_sys::window().and_then(|w| w.local_storage().ok().flatten()) {
        let _ = if name.is_empty() {
            storage.remove_item(STUDENT_STORE_KEY)
        } else {
            storage.set_item(STUDENT_STORE_KEY, name)
        };
    }
}

/// Puts `lang` on the page: `<html lang>` (what a screen reader speaks in),
/// the names the page gives the canvas and its text box, the page's own
/// notices, and, if `remember`, this browser's memory of the choice.
/// `lang` must already be in force (`crate::i18n::set_lang`).
pub fn set_language(lang: crate::i18n::Lang, remember: bool) {
    page::set_language();
    a11y_dom::set_language();
    let Some(window) = web_sys::window() else {
        return;
    };
    if let Some(html) = window.document().and_then(|d| d.document_element()) {
        let _ = html.set_attribute("lang", lang.code());
    }
    if remember && let Ok(Some(storage)) = window.local_storage() {
        let _ = storage.set_item(LANGUAGE_STORE_KEY, lang.code());
    }
}

/// The language the page opens in (see `ui::language::initial`).
fn initial_language() -> crate::i18n::Lang {
    let window = web_sys::window();
    let stored = window
        .as_ref()
        .and_then(|w| w.local_storage().ok().flatten())
        .and_then(|s| s.get_item(LANGUAGE_STORE_KEY).ok().flatten());
    let preferred: Vec<String> = window
        .as_ref()
        .map(|w| {
            w.navigator()
                .languages()
                .iter()
                .filter_map(|l| l.as_string())
                .collect()
        })
        .unwrap_or_default();
    crate::ui::language::initial(
        &page::query(),
        stored.as_deref(),
        preferred.iter().map(String::as_str),
    )
}

/// Starts Shoal in the page. Called once from `main`.
pub async fn start() {
    if eframe::WebLogger::init(log::LevelFilter::Info).is_err() {
        // A logger was already installed: keep it.
    }
    // Every word from here on, the page's own notices too, in the language chosen.
    let lang = initial_language();
    crate::i18n::set_lang(lang);
    set_language(lang, false);
    let runner = eframe::WebRunner::new();
    // After eframe's own hook, so a panic is both logged and shown.
    page::show_panics_on_page();

    let Some(canvas) = page::canvas() else {
        page::show_error(
            crate::i18n::ts("page-could-not-start"),
            crate::i18n::ts("page-no-canvas"),
        );
        return;
    };
    let bench = page::query_has("bench");
    // Reduced motion and high contrast: the person's own settings, or the link's.
    let (seeing, start_paused) = crate::ui::seeing::initial(
        &page::query(),
        page::media_matches("(prefers-reduced-motion: reduce)"),
        page::media_matches("(prefers-contrast: more)"),
    );
    // A teacher link's fragment (`#teacher=CODE.TOKEN`, issue 37) is no share
    // link: the class takes it, and it leaves the address bar at once (the
    // dashboard is projected; the browser keeps the token in its storage).
    let fragment = page::fragment();
    let teacher_fragment = crate::ui::class_panel::parse_teacher_fragment(&fragment)
        .is_some()
        .then(|| fragment.clone());
    if teacher_fragment.is_some()
        && let Some(url) = page::url_without_fragment()
    {
        page::replace_address(&url);
    }
    // A share link's settings, or the defaults and a notice saying why not.
    let decoded = match &teacher_fragment {
        Some(_) => Ok(None),
        None => crate::settings::share_link::decode(&fragment),
    };
    let link_settings = matches!(decoded, Ok(Some(_)));
    let (settings, link_error) = match decoded {
        Ok(settings) => (settings.unwrap_or_default(), None),
        Err(err) => (
            Settings::default(),
            Some(crate::tr!("page-link-error", error = err.to_string())),
        ),
    };
    if let Some(message) = &link_error {
        log::warn!("{message}");
    }
    let mut settings = settings;
    if start_paused {
        settings.paused = true;
    }
    let started = runner
        .start(
            canvas,
            eframe::WebOptions::default(),
            Box::new(move |cc| {
                crate::ui::seeing::set(&cc.egui_ctx, seeing);
                recover::watch_device(cc);
                let mut app = ShoalApp::new(cc, settings)?;
                // Every control as a real element for screen readers and Tab.
                if let Err(err) = a11y_dom::install(&cc.egui_ctx) {
                    log::warn!("the accessible controls could not be set up: {err:?}");
                }
                if start_paused {
                    app.show_info_notice(crate::ui::seeing::STARTED_PAUSED);
                }
                if let Some(url) = page::url_without_fragment() {
                    app.open_class_from_page(&url, teacher_fragment.as_deref().unwrap_or(""));
                    app.set_page_url(url, link_settings);
                }
                if let Some(message) = link_error {
                    app.show_error_notice(message);
                }
                if bench {
                    app.start_benchmark();
                }
                Ok(Box::new(app))
            }),
        )
        .await;
    match started {
        Ok(()) => {
            page::hide_notice();
            if let Err(err) = api::install(&runner) {
                log::error!("could not install window.shoal: {err:?}");
            }
            recover::keep(runner);
        }
        Err(err) => {
            let detail = err
                .as_string()
                .or_else(|| {
                    js_sys::Reflect::get(&err, &"message".into())
                        .ok()
                        .and_then(|m| m.as_string())
                })
                .unwrap_or_else(|| format!("{err:?}"));
            log::error!("eframe failed to start: {detail}");
            page::show_no_gpu(&detail);
        }
    }
}
