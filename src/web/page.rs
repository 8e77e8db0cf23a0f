//! Messages on the page itself, outside the canvas: the "no GPU" explanation and the
//! panic notice. Text goes in with `set_text_content`, never as HTML.

use std::cell::RefCell;

use wasm_bindgen::JsCast;
use wasm_bindgen::closure::Closure;

use crate::i18n::ts;
use crate::tr;

/// Stands for the panic's details in the words made before it.
const DETAIL_MARK: &str = "\u{1}";

thread_local! {
    /// The panic notice's words in the language in force, made before any
    /// panic (a panic hook must not build them: the catalogue may be the
    /// thing that panicked). Set by [`set_language`].
    static PANIC_WORDS: RefCell<Option<([&'static str; 3], String)>> = const { RefCell::new(None) };
}

/// Makes the page's own words (the panic notice) ready in the language in
/// force; called whenever the language changes.
pub fn set_language() {
    let words = [
        ts("page-panic-title"),
        ts("page-panic-sorry"),
        ts("page-reload"),
    ];
    // The details go where the marker is.
    let details = tr!("page-panic-details", detail = DETAIL_MARK);
    PANIC_WORDS.with(|w| *w.borrow_mut() = Some((words, details)));
}

fn document() -> Option<web_sys::Document> {
    web_sys::window()?.document()
}

/// The canvas eframe draws on.
pub fn canvas() -> Option<web_sys::HtmlCanvasElement> {
    document()?
        .get_element_by_id("shoal_canvas")?
        .dyn_into::<web_sys::HtmlCanvasElement>()
        .ok()
}

/// Does the page's query string contain `flag` (as in `?bench`)?
pub fn query_has(flag: &str) -> bool {
    web_sys::window()
        .and_then(|w| w.location().search().ok())
        .is_some_and(|search| {
            search
                .trim_start_matches('?')
                .split('&')
                .any(|part| part.split('=').next() == Some(flag))
        })
}

/// The page's query string (`?bench&motion=reduce`), or "".
pub fn query() -> String {
    web_sys::window()
        .and_then(|w| w.location().search().ok())
        .unwrap_or_default()
}

/// Does the browser match the media query `query` (as in
/// `(prefers-reduced-motion: reduce)`)? False where it cannot tell.
pub fn media_matches(query: &str) -> bool {
    web_sys::window()
        .and_then(|w| w.match_media(query).ok().flatten())
        .is_some_and(|list| list.matches())
}

/// Marks the page's timeline when the app's first frame is drawn
/// (`performance.getEntriesByName("shoal-first-frame")`): the benchmark's time from
/// navigation to the first frame (web/tests/bench.mjs).
pub fn mark_first_frame() {
    let mark = "shoal-first-frame"; // words: a performance mark's name, never shown
    if let Some(performance) = web_sys::window().and_then(|w| w.performance())
        && let Err(err) = performance.mark(mark)
    {
        log::warn!("performance.mark failed: {err:?}");
    }
}

/// Hides the loading notice once the app runs.
pub fn hide_notice() {
    if let Some(notice) = document().and_then(|d| d.get_element_by_id("shoal_notice")) {
        notice.set_class_name("hidden");
    }
}

/// Shows `title` and `detail` in the page's notice box, with a reload button.
pub fn show_error(title: &str, detail: &str) {
    show(title, &[detail], "error", ts("page-reload"));
}

/// The browser offered neither WebGPU nor WebGL2.
pub fn show_no_gpu(detail: &str) {
    show(
        ts("page-no-gpu-title"),
        &[
            ts("page-no-gpu-why"),
            ts("page-no-gpu-where"),
            &tr!("page-details", detail = detail),
        ],
        "error",
        ts("page-reload"),
    );
    if let Some(canvas) = canvas() {
        canvas.set_class_name("hidden");
    }
}

fn show(title: &str, paragraphs: &[&str], class: &str, reload: &str) {
    let Some(document) = document() else {
        return;
    };
    let Some(notice) = document.get_element_by_id("shoal_notice") else {
        return;
    };
    notice.set_inner_html("");
    notice.set_class_name(class);
    let add = |tag: &str, text: &str| {
        if let Ok(element) = document.create_element(tag) {
            element.set_text_content(Some(text));
            let _ = notice.append_child(&element);
        }
    };
    add("h2", title);
    for paragraph in paragraphs {
        add("p", paragraph);
    }
    if let Ok(button) = document.create_element("button") {
        button.set_text_content(Some(reload));
        // A listener, not an `onclick` attribute: a Content Security Policy
        // without 'unsafe-inline' refuses inline handlers.
        let reload = Closure::<dyn Fn()>::new(|| {
            if let Some(window) = web_sys::window() {
                let _ = window.location().reload();
            }
        });
        let _ = button.add_event_listener_with_callback("click", reload.as_ref().unchecked_ref());
        reload.forget(); // One button per page load.
        let _ = notice.append_child(&button);
    }
}

/// Chains a panic hook that puts the panic message on the page.
pub fn show_panics_on_page() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        previous(info);
        let ([title, sorry, reload], details) = PANIC_WORDS
            .with(|w| w.try_borrow().ok().and_then(|w| w.clone()))
            .unwrap_or_else(|| {
                // Only if a panic comes before the language is set (see
                // `crate::web::start`): English.
                (
                    [
                        "Shoal stopped because of an internal error", // words: English before any language is set
                        "Sorry: something went wrong inside Shoal. Reloading the page starts it again.", // words: English before any language is set
                        "Reload Shoal", // words: English before any language is set
                    ],
                    format!("Details for the developers: {DETAIL_MARK}"), // words: English before any language is set
                )
            });
        let details = details.replace(DETAIL_MARK, &info.to_string());
        show(title, &[sorry, &details], "error", reload);
    }));
}

/// Starts a browser download of `text` as a file called `name`.
pub fn download_text(name: &str, mime: &str, text: &str) -> Result<(), String> {
    let describe = |err: wasm_bindgen::JsValue| format!("{err:?}");
    let parts = js_sys::Array::of1(&wasm_bindgen::JsValue::from_str(text));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob =
        web_sys::Blob::new_with_str_sequence_and_options(&parts, &options).map_err(describe)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(describe)?;
    let document = document().ok_or("no document")?; // words: a developer's error
    let anchor: web_sys::HtmlAnchorElement = document
        .create_element("a")
        .map_err(describe)?
        .dyn_into()
        .map_err(|_| "not an anchor".to_owned())?; // words: a developer's error
    anchor.set_href(&url);
    anchor.set_download(name);
    anchor.click();
    web_sys::Url::revoke_object_url(&url).map_err(describe)?;
    Ok(())
}

/// Opens the browser's file dialog for one text file; when the user picks one,
/// its text (or a reason it could not be read) is put in `into` and
/// `on_done` runs (the app then repaints).
pub fn pick_text_file(
    accept: &str,
    into: std::rc::Rc<std::cell::RefCell<Option<Result<String, String>>>>,
    on_done: impl Fn() + 'static,
) -> Result<(), String> {
    use wasm_bindgen::closure::Closure;
    let describe = |err: wasm_bindgen::JsValue| format!("{err:?}");
    let document = document().ok_or("no document")?; // words: a developer's error
    let input: web_sys::HtmlInputElement = document
        .create_element("input")
        .map_err(describe)?
        .dyn_into()
        .map_err(|_| "not an input".to_owned())?; // words: a developer's error
    input.set_type("file");
    input.set_accept(accept);
    let picked = input.clone();
    let on_change = Closure::once(move |_event: web_sys::Event| {
        let Some(file) = picked.files().and_then(|files| files.get(0)) else {
            return;
        };
        let into = into.clone();
        wasm_bindgen_futures::spawn_local(async move {
            let text = wasm_bindgen_futures::JsFuture::from(file.text()).await;
            *into.borrow_mut() = Some(match text {
                Ok(value) => value.as_string().ok_or_else(|| tr!("page-file-not-text")),
                Err(err) => Err(tr!("page-file-unreadable", error = format!("{err:?}"))),
            });
            on_done();
        });
    });
    input.set_onchange(Some(on_change.as_ref().unchecked_ref()));
    on_change.forget();
    input.click();
    Ok(())
}

/// The page's address without its fragment (for share links).
pub fn url_without_fragment() -> Option<String> {
    let location = web_sys::window()?.location();
    let href = location.href().ok()?;
    Some(href.split('#').next().unwrap_or_default().to_owned())
}

/// The page's fragment (`#…`), if any.
pub fn fragment() -> String {
    web_sys::window()
        .and_then(|w| w.location().hash().ok())
        .unwrap_or_default()
}

/// Puts `url` in the address bar without loading it (a reload then opens it).
pub fn replace_address(url: &str) {
    if let Some(history) = web_sys::window().and_then(|w| w.history().ok()) {
        let _ = history.replace_state_with_url(&wasm_bindgen::JsValue::NULL, "", Some(url));
    }
}
