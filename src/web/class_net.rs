//! The class's transport in the browser, kept thin: a WebSocket to the page's
//! own server (`/ws`) whose events wait in a queue the app drains each frame,
//! `fetch` for the HTTP API, and the browser's storage. The protocol's logic
//! (ids, resend, views) is `crate::class`, tested natively.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::rc::Rc;

use eframe::egui;
use wasm_bindgen::JsCast;
use wasm_bindgen::closure::Closure;

/// What happened on a socket since the last drain.
#[derive(Clone, Debug, PartialEq)]
pub enum SocketEvent {
    Open,
    Message(String),
    Closed,
}

/// An open (or opening) WebSocket.
pub struct Socket {
    ws: web_sys::WebSocket,
    events: Rc<RefCell<VecDeque<SocketEvent>>>,
    _on_open: Closure<dyn FnMut(web_sys::Event)>,
    _on_message: Closure<dyn FnMut(web_sys::MessageEvent)>,
    _on_close: Closure<dyn FnMut(web_sys::Event)>,
}

impl Socket {
    /// Opens `/ws` on the page's own server; events wake `ctx` up.
    pub fn open(ctx: &egui::Context) -> Result<Self, String> {
        let url = ws_url().ok_or("no page address")?; // words: a developer's error
        let ws = web_sys::WebSocket::new(&url).map_err(|e| format!("{e:?}"))?;
        let events: Rc<RefCell<VecDeque<SocketEvent>>> = Rc::default();
        let push = |event_of: fn(Option<String>) -> SocketEvent| {
            let events = events.clone();
            let ctx = ctx.clone();
            move |text: Option<String>| {
                events.borrow_mut().push_back(event_of(text));
                ctx.request_repaint();
            }
        };
        let opened = push(|_| SocketEvent::Open);
        let on_open = Closure::<dyn FnMut(web_sys::Event)>::new(move |_| opened(None));
        let received = push(|t| SocketEvent::Message(t.unwrap_or_default()));
        let on_message =
            Closure::<dyn FnMut(web_sys::MessageEvent)>::new(move |e: web_sys::MessageEvent| {
                if let Some(text) = e.data().as_string() {
                    received(Some(text));
                }
            });
        let closed = push(|_| SocketEvent::Closed);
        let on_close = Closure::<dyn FnMut(web_sys::Event)>::new(move |_| closed(None));
        ws.set_onopen(Some(on_open.as_ref().unchecked_ref()));
        ws.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
        // An error is always followed by a close; the close is what counts.
        ws.set_onclose(Some(on_close.as_ref().unchecked_ref()));
        Ok(Socket {
            ws,
            events,
            _on_open: on_open,
            _on_message: on_message,
            _on_close: on_close,
        })
    }

    /// Sends one text frame; false if the socket is not open.
    pub fn send(&self, text: &str) -> bool {
        self.ws.ready_state() == web_sys::WebSocket::OPEN && self.ws.send_with_str(text).is_ok()
    }

    /// The events since the last call.
    pub fn drain(&self) -> Vec<SocketEvent> {
        self.events.borrow_mut().drain(..).collect()
    }
}

impl Drop for Socket {
    fn drop(&mut self) {
        self.ws.set_onopen(None);
        self.ws.set_onmessage(None);
        self.ws.set_onclose(None);
        let _ = self.ws.close();
    }
}

/// `ws://host/ws` (or `wss://` on an HTTPS page).
fn ws_url() -> Option<String> {
    let location = web_sys::window()?.location();
    let scheme = if location.protocol().ok()? == "https:" {
        "wss" // words: a URL scheme
    } else {
        "ws" // words: a URL scheme
    };
    Some(format!("{scheme}://{}/ws", location.host().ok()?))
}

/// An HTTP answer: status and body text, or why there was none.
pub type Reply = Rc<RefCell<Option<Result<(u16, String), String>>>>;

/// Starts `method path` on the page's own server with an optional JSON body
/// and bearer token; the answer lands in the returned cell (and wakes `ctx`).
pub fn fetch(
    ctx: &egui::Context,
    method: &str,
    path: &str,
    body: Option<String>,
    bearer: Option<&str>,
) -> Reply {
    let reply: Reply = Rc::default();
    let into = reply.clone();
    let ctx = ctx.clone();
    let init = web_sys::RequestInit::new();
    init.set_method(method);
    let headers = web_sys::Headers::new().ok();
    if let Some(h) = &headers {
        if body.is_some() {
            let _ = h.set("Content-Type", "application/json"); // words: an HTTP header
        }
        if let Some(token) = bearer {
            let _ = h.set("Authorization", &format!("Bearer {token}")); // words: an HTTP header
        }
        init.set_headers(h);
    }
    if let Some(body) = &body {
        init.set_body(&wasm_bindgen::JsValue::from_str(body));
    }
    let path = path.to_owned();
    wasm_bindgen_futures::spawn_local(async move {
        let result = async {
            let window = web_sys::window().ok_or("no window")?; // words: a developer's error
            let promise = window.fetch_with_str_and_init(&path, &init);
            let response: web_sys::Response = wasm_bindgen_futures::JsFuture::from(promise)
                .await
                .map_err(|e| format!("{e:?}"))?
                .dyn_into()
                .map_err(|_| "not a response".to_owned())?; // words: a developer's error
            let status = response.status();
            let text = wasm_bindgen_futures::JsFuture::from(
                response.text().map_err(|e| format!("{e:?}"))?,
            )
            .await
            .map_err(|e| format!("{e:?}"))?
            .as_string()
            .unwrap_or_default();
            Ok::<_, String>((status, text))
        }
        .await;
        *into.borrow_mut() = Some(result);
        ctx.request_repaint();
    });
    reply
}

fn storage() -> Option<web_sys::Storage> {
    web_sys::window()?.local_storage().ok().flatten()
}

/// The text kept under `key` in this browser.
pub fn load(key: &str) -> Option<String> {
    storage()?.get_item(key).ok().flatten()
}

/// Keeps `text` under `key` (forgets it when `None`).
pub fn store(key: &str, text: Option<&str>) {
    if let Some(s) = storage() {
        let _ = match text {
            Some(t) => s.set_item(key, t),
            None => s.remove_item(key),
        };
    }
}

/// Twelve random characters (message id prefixes).
pub fn random_prefix() -> String {
    const DIGITS: &[u8] = b"0123456789abcdefghijklmnopqrstuvwxyz";
    (0..12)
        .map(|_| {
            let k = (js_sys::Math::random() * DIGITS.len() as f64) as usize;
            DIGITS[k.min(DIGITS.len() - 1)] as char
        })
        .collect()
}
