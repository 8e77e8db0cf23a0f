//! `window.shoal`: the automation API in the browser (see `automation.rs` for what
//! each call does). A thin shim: arguments become JSON values, results plain objects,
//! and an `AutomationError` becomes a thrown JS `Error` with the same message.

use eframe::WebRunner;
use js_sys::{Object, Reflect};
use wasm_bindgen::prelude::*;

use crate::ShoalApp;
use crate::automation::{AutomationError, Command};

type Method =
    dyn Fn(&mut ShoalApp, Option<serde_json::Value>) -> Result<serde_json::Value, AutomationError>;

/// Installs `window.shoal`.
pub fn install(runner: &WebRunner) -> Result<(), JsValue> {
    let api = Object::new();
    let methods: [(&str, Box<Method>); 30] = [
        (
            "state",
            Box::new(|app, _| {
                let mut state = to_json(&app.state_report())?;
                app.mask_state_json(&mut state);
                if let (Some(report), Some(object)) =
                    (app.experiment_report(), state.as_object_mut())
                {
                    object.insert("experiment".into(), to_json(&report)?);
                }
                if let Some(object) = state.as_object_mut() {
                    object.insert(
                        "investigation".into(),
                        to_json(&app.investigation_report())?,
                    );
                }
                Ok(state)
            }),
        ),
        (
            // Destroys the WebGPU device, as a sleeping computer loses it (on
            // WebGL2 a test uses WEBGL_lose_context instead): true if there was one.
            "lose_gpu",
            Box::new(|_, _| Ok(serde_json::Value::Bool(super::recover::lose_device()))),
        ),
        (
            "experiment",
            Box::new(|app, arg| {
                let design = arg.ok_or_else(|| {
                    AutomationError::BadArgument(
                        "shoal.experiment(design): give a design object, as in experiments/*.json"
                            .into(),
                    )
                })?;
                app.start_experiment(&design)
                    .map_err(|err| AutomationError::BadArgument(err.to_string()))?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "investigations",
            Box::new(|_, _| to_json(&crate::investigation::list())),
        ),
        (
            // A class together (issue 37), read only: the server check, the
            // role, the connection, messages waiting, the last view.
            "class",
            Box::new(|app, _| Ok(app.class_report())),
        ),
        (
            "investigation_record",
            Box::new(|app, _| {
                let (html, csv, file) = app.investigation_record();
                Ok(serde_json::json!({"html": html, "csv": csv, "file": file}))
            }),
        ),
        (
            "cancel_experiment",
            Box::new(|app, _| Ok(serde_json::Value::Bool(app.cancel_experiment()))),
        ),
        (
            "experiment_link",
            Box::new(|app, _| to_json(&app.experiment_link())),
        ),
        (
            "share_link",
            Box::new(|app, _| Ok(serde_json::Value::String(app.share_link()))),
        ),
        (
            "metrics_csv",
            Box::new(|app, _| Ok(serde_json::Value::String(app.metrics_csv()))),
        ),
        ("export_csv", Box::new(|app, _| to_json(&app.export_csv()))),
        ("settings", Box::new(|app, _| Ok(app.settings_json()))),
        ("memory", Box::new(|_, _| Ok(memory_json()))),
        ("soak_change", Box::new(|app, arg| app.soak_change(arg))),
        ("soak_check", Box::new(|app, _| Ok(app.soak_check()))),
        (
            "student_link",
            Box::new(|app, _| Ok(serde_json::Value::String(app.student_link()))),
        ),
        ("widgets", Box::new(|app, _| Ok(widgets_json(app)))),
        (
            "crash_test",
            Box::new(|app, _| {
                app.request_crash_test();
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "set",
            Box::new(|app, arg| {
                let patch = arg.unwrap_or(serde_json::Value::Null);
                app.set_with_investigation(patch)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "step",
            Box::new(|app, arg| {
                app.run_command(Command::step(arg.as_ref())?)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "pause",
            Box::new(|app, _| {
                app.run_command(Command::Pause)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "play",
            Box::new(|app, _| {
                app.run_command(Command::Play)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "reset",
            Box::new(|app, arg| {
                app.run_command(Command::reset(arg.as_ref())?)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "turn",
            Box::new(|app, arg| {
                app.run_command(Command::turn(arg.as_ref())?)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "train",
            Box::new(|app, arg| {
                app.run_command(Command::train(arg.as_ref())?)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "race",
            Box::new(|app, _| {
                app.run_command(Command::Race)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "load_controllers",
            Box::new(|app, arg| {
                app.run_command(Command::load_controllers(arg.as_ref())?)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "skip",
            Box::new(|app, _| {
                app.run_command(Command::Skip)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "cancel_skip",
            Box::new(|app, _| {
                app.run_command(Command::CancelSkip)?;
                Ok(serde_json::Value::Null)
            }),
        ),
        (
            "save_controllers",
            Box::new(|app, _| {
                let text = app
                    .controllers_json()
                    .map_err(|err| AutomationError::BadArgument(err.to_string()))?;
                Ok(serde_json::Value::String(text))
            }),
        ),
    ];
    for (name, method) in methods {
        let runner = runner.clone();
        let closure = Closure::<dyn Fn(JsValue) -> Result<JsValue, JsValue>>::new(
            move |arg: JsValue| -> Result<JsValue, JsValue> {
                let arg = from_js(&arg)?;
                let mut app = runner
                    .app_mut::<ShoalApp>()
                    .ok_or_else(|| js_error(&AutomationError::NotRunning.to_string()))?;
                let result = method(&mut app, arg).map_err(|err| js_error(&err.to_string()))?;
                to_js(&result)
            },
        );
        Reflect::set(&api, &name.into(), closure.as_ref())?;
        closure.forget(); // Lives as long as the page.
    }
    Reflect::set(&api, &"run_experiment".into(), &run_experiment_js(&api))?;
    let window = web_sys::window().ok_or_else(|| js_error("no window"))?;
    Reflect::set(&window, &"shoal".into(), &api)?;
    Ok(())
}

/// `shoal.run_experiment(design)`: starts the experiment and returns a Promise
/// that resolves with `{summary, csv}` when it is done (polling `state()` every
/// 200 ms), or rejects if the design is refused or the experiment cancelled.
/// Written in Rust, not as JavaScript source: a school's Content Security
/// Policy refuses to evaluate a string as code.
fn run_experiment_js(api: &Object) -> JsValue {
    let api = api.clone();
    let closure = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |design: JsValue| {
        let api = api.clone();
        wasm_bindgen_futures::future_to_promise(async move {
            call(&api, "experiment", &design)?;
            loop {
                let state = call(&api, "state", &JsValue::UNDEFINED)?;
                let experiment = Reflect::get(&state, &"experiment".into())?;
                let field = |name: &str| Reflect::get(&experiment, &name.into());
                let present = experiment.is_object();
                if present && field("running")?.is_truthy() {
                    sleep_ms(200).await?;
                    continue;
                }
                if present && !field("cancelled")?.is_truthy() && field("summary")?.is_truthy() {
                    let result = Object::new();
                    Reflect::set(&result, &"summary".into(), &field("summary")?)?;
                    Reflect::set(&result, &"csv".into(), &field("csv")?)?;
                    return Ok(result.into());
                }
                return Err(js_error("the experiment was cancelled"));
            }
        })
    });
    let function = closure.as_ref().clone();
    closure.forget(); // Lives as long as the page.
    function
}

/// Calls `api.name(arg)`.
fn call(api: &Object, name: &str, arg: &JsValue) -> Result<JsValue, JsValue> {
    let method: js_sys::Function = Reflect::get(api, &name.into())?.dyn_into()?;
    method.call1(&JsValue::NULL, arg)
}

/// A Promise that resolves after `ms` milliseconds.
async fn sleep_ms(ms: i32) -> Result<JsValue, JsValue> {
    let promise = js_sys::Promise::new(&mut |resolve, _reject| {
        if let Some(window) = web_sys::window() {
            let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, ms);
        }
    });
    wasm_bindgen_futures::JsFuture::from(promise).await
}

/// `{name: {x, y, width, height}}` in CSS pixels.
/// Where the widgets are, in CSS pixels: egui's points times the interface
/// scale (its zoom factor), so a test clicks where a person would.
fn widgets_json(app: &ShoalApp) -> serde_json::Value {
    let scale = app.interface_scale_now();
    app.widget_rects()
        .iter()
        .map(|(name, rect)| {
            (
                (*name).to_owned(),
                serde_json::json!({
                    "x": rect.min.x * scale, "y": rect.min.y * scale,
                    "width": rect.width() * scale, "height": rect.height() * scale,
                }),
            )
        })
        .collect::<serde_json::Map<_, _>>()
        .into()
}

/// Counts the Rust heap in use in the page. The module's linear memory only
/// grows (wasm cannot give memory back), so after 20,000 fish it stays at
/// their size: only the bytes in use tell a leak from that high-water mark.
#[global_allocator]
static ALLOCATOR: cap::Cap<std::alloc::System> = cap::Cap::new(std::alloc::System, usize::MAX);

/// `shoal.memory()`: `{wasm_bytes, heap_bytes, js_heap_bytes}`, the module's
/// linear memory (its high-water mark), the Rust heap in use in it, and, where
/// the browser tells (Chromium's `performance.memory`), the JavaScript heap in
/// use (`null` elsewhere).
fn memory_json() -> serde_json::Value {
    let number = |object: &JsValue, key: &str| {
        Reflect::get(object, &key.into())
            .ok()
            .and_then(|v| v.as_f64())
    };
    let wasm_bytes = Reflect::get(&wasm_bindgen::memory(), &"buffer".into())
        .ok()
        .and_then(|buffer| number(&buffer, "byteLength"));
    let js_heap_bytes = web_sys::window()
        .and_then(|w| Reflect::get(&w, &"performance".into()).ok())
        .and_then(|p| Reflect::get(&p, &"memory".into()).ok())
        .filter(|m| m.is_object())
        .and_then(|m| number(&m, "usedJSHeapSize"));
    let heap_bytes = ALLOCATOR.allocated();
    serde_json::json!({"wasm_bytes": wasm_bytes, "heap_bytes": heap_bytes, "js_heap_bytes": js_heap_bytes})
}

fn to_json(value: &impl serde::Serialize) -> Result<serde_json::Value, AutomationError> {
    serde_json::to_value(value).map_err(|err| AutomationError::BadArgument(err.to_string()))
}

fn from_js(arg: &JsValue) -> Result<Option<serde_json::Value>, JsValue> {
    if arg.is_undefined() {
        return Ok(None);
    }
    let text = js_sys::JSON::stringify(arg)
        .map_err(|_| js_error("the argument cannot be turned into JSON"))?;
    let text = String::from(text);
    serde_json::from_str(&text)
        .map(Some)
        .map_err(|err| js_error(&format!("the argument is not valid JSON: {err}")))
}

fn to_js(value: &serde_json::Value) -> Result<JsValue, JsValue> {
    js_sys::JSON::parse(&value.to_string())
}

fn js_error(message: &str) -> JsValue {
    js_sys::Error::new(message).into()
}
