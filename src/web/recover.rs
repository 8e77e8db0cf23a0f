//! A lost graphics device, recovered in the page. A Chromebook that sleeps or
//! changes screens can take the GPU away: WebGL2 fires `webglcontextlost` on
//! the canvas (and `webglcontextrestored` when it may draw again), WebGPU
//! resolves its device's `lost`. The renderer is then dead, but nothing of the
//! lesson lives on the GPU: eframe is stopped, and a new one is started on the
//! same canvas with the old app's [`crate::app::Session`] (the fish, the clock,
//! the settings, the camera, the open windows), and a notice says what
//! happened. If no new renderer can be had, the page says so, and its address
//! already holds the settings, so reloading brings the same tank back.

use std::cell::{Cell, RefCell};

use wasm_bindgen::JsCast;
use wasm_bindgen::closure::Closure;

use super::{a11y_dom, api, page};
use crate::ShoalApp;
use crate::i18n::ts;

thread_local! {
    /// The running eframe.
    static RUNNER: RefCell<Option<eframe::WebRunner>> = const { RefCell::new(None) };
    /// The running renderer's device (for `shoal.lose_gpu()`), and which
    /// start it belongs to.
    static DEVICE: RefCell<Option<eframe::wgpu::Device>> = const { RefCell::new(None) };
    /// Each start of eframe, counted: a device lost from an earlier start (the
    /// one just replaced) is not news.
    static GENERATION: Cell<u64> = const { Cell::new(0) };
    /// A recovery is under way.
    static RECOVERING: Cell<bool> = const { Cell::new(false) };
    /// Is the WebGL2 context lost and not yet given back?
    static GL_LOST: Cell<bool> = const { Cell::new(false) };
}

/// Keeps the started `runner`, and listens for the canvas's WebGL context
/// being lost and restored (once per page).
pub fn keep(runner: eframe::WebRunner) {
    RUNNER.with(|r| *r.borrow_mut() = Some(runner));
    static LISTENING: std::sync::Once = std::sync::Once::new();
    LISTENING.call_once(listen_to_canvas);
}

/// Watches the new renderer's device (WebGPU reports its loss there).
pub fn watch_device(cc: &eframe::CreationContext<'_>) {
    let Some(render_state) = &cc.wgpu_render_state else {
        return;
    };
    let generation = GENERATION.get();
    render_state
        .device
        .set_device_lost_callback(move |reason, message| {
            log::warn!("the graphics device was lost ({reason:?}): {message}");
            if generation == GENERATION.get() {
                // Not from inside wgpu's callback: on the next turn of the page.
                later(0, || recover("device lost")); // words: logged, for developers
            }
        });
    DEVICE.with(|d| *d.borrow_mut() = Some(render_state.device.clone()));
}

/// Makes the graphics device be lost, as a sleeping computer does
/// (`shoal.lose_gpu()`, for tests): WebGPU's device is destroyed; WebGL2's
/// context is lost through `WEBGL_lose_context` (the test restores it).
pub fn lose_device() -> bool {
    DEVICE.with(|d| match d.borrow().as_ref() {
        Some(device) => {
            device.destroy();
            true
        }
        None => false,
    })
}

fn listen_to_canvas() {
    let Some(canvas) = page::canvas() else {
        return;
    };
    let lost = Closure::<dyn Fn(web_sys::Event)>::new(|event: web_sys::Event| {
        // Asks the browser to give the context back when it can.
        event.prevent_default();
        log::warn!("the WebGL context was lost");
        GL_LOST.set(true);
        // If it never comes back, try anyway after a while (and say so if that
        // fails too).
        later(10_000, || {
            if GL_LOST.get() {
                recover("context not restored"); // words: logged, for developers
            }
        });
    });
    let restored = Closure::<dyn Fn(web_sys::Event)>::new(|_: web_sys::Event| {
        log::info!("the WebGL context was restored");
        GL_LOST.set(false);
        recover("context restored"); // words: logged, for developers
    });
    for (name, handler) in [
        ("webglcontextlost", &lost),
        ("webglcontextrestored", &restored),
    ] {
        let _ = canvas.add_event_listener_with_callback(name, handler.as_ref().unchecked_ref());
    }
    // Both live as long as the page.
    lost.forget();
    restored.forget();
}

/// Runs `f` after `ms` milliseconds.
fn later(ms: i32, f: impl FnOnce() + 'static) {
    let Some(window) = web_sys::window() else {
        return;
    };
    let f = Closure::once_into_js(f);
    let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(f.unchecked_ref(), ms);
}

/// Stops the dead renderer and starts a new one with the old app's lesson.
fn recover(why: &str) {
    if RECOVERING.replace(true) {
        return;
    }
    let Some(runner) = RUNNER.with(|r| r.borrow_mut().take()) else {
        RECOVERING.set(false);
        return;
    };
    log::warn!("starting the renderer again ({why})");
    let session = runner.app_mut::<ShoalApp>().map(|mut app| {
        // The settings in the address bar: a reload, if it comes to that,
        // opens the same tank.
        page::replace_address(&app.share_link());
        app.take_session()
    });
    GENERATION.set(GENERATION.get() + 1);
    DEVICE.with(|d| d.borrow_mut().take());
    runner.destroy();
    a11y_dom::uninstall();
    let Some(session) = session else {
        failed("the app could not be reached"); // words: logged, for developers
        return;
    };
    let Some(canvas) = page::canvas() else {
        failed("no canvas"); // words: logged, for developers
        return;
    };
    wasm_bindgen_futures::spawn_local(async move {
        let runner = eframe::WebRunner::new();
        let started = runner
            .start(
                canvas,
                eframe::WebOptions::default(),
                Box::new(move |cc| {
                    watch_device(cc);
                    let app = ShoalApp::resume(cc, session)?;
                    if let Err(err) = a11y_dom::install(&cc.egui_ctx) {
                        log::warn!("the accessible controls could not be set up: {err:?}");
                    }
                    Ok(Box::new(app))
                }),
            )
            .await;
        match started {
            Ok(()) => {
                if let Err(err) = api::install(&runner) {
                    log::error!("could not install window.shoal: {err:?}");
                }
                RUNNER.with(|r| *r.borrow_mut() = Some(runner));
                RECOVERING.set(false);
            }
            Err(err) => failed(&format!("{err:?}")),
        }
    });
}

/// No new renderer: the page says so; its address holds the settings.
fn failed(detail: &str) {
    log::error!("the renderer could not start again: {detail}");
    page::show_error(ts("app-gpu-lost-title"), ts("app-gpu-lost-why"));
    RECOVERING.set(false);
}
