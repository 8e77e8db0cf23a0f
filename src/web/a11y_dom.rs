//! The page's side of the accessibility mirror (see `crate::a11y::mirror`).
//!
//! eframe draws every control on one canvas and, on the web, gives the
//! browser none of egui's accessibility tree. This module keeps one real HTML
//! element per control in the page, over the canvas where egui drew it,
//! invisible but read by screen readers and reached with Tab:
//!
//! - each frame egui sends its tree; [`Bridge::output_hook`] turns it into
//!   [`Mirror`] items and brings the elements up to date (only what changed);
//! - what a student does to an element (a click, a new slider value, typed
//!   text, focus) becomes an AccessKit action request that
//!   [`Bridge::input_hook`] hands to egui on the next frame, so the egui
//!   widget, and through it the setting, changes exactly as with the mouse;
//! - a ring drawn round the focused element shows where the keyboard is;
//! - a polite live region says what happens in the tank
//!   ([`announce`], fed by `crate::a11y::describe`).
//!
//! All DOM state lives in this thread's [`MIRROR`] (the browser runs us on
//! one thread); the egui plugin itself holds nothing.

use std::cell::RefCell;
use std::collections::HashMap;

use eframe::egui;
use egui::accesskit::{Action, ActionData, ActionRequest, NodeId, TreeId};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::a11y::mirror::{Item, Kind, Mirror};

const ROOT_ID: &str = "shoal_a11y";
const RING_ID: &str = "shoal_focus_ring";
const LIVE_ID: &str = "shoal_live";

// The mirror's style (invisible elements over the canvas, the focus ring) is in
// web/shoal-page.css: a school's Content Security Policy refuses a <style>
// element made here.

thread_local! {
    static MIRROR: RefCell<Option<DomMirror>> = const { RefCell::new(None) };
    /// Actions and keys from the page, waiting for egui's next frame.
    static PENDING: RefCell<Vec<egui::Event>> = const { RefCell::new(Vec::new()) };
}

/// Turns egui's accessibility tree on and puts the mirror in the page.
pub fn install(ctx: &egui::Context) -> Result<(), JsValue> {
    let mirror = DomMirror::new(ctx.clone())?;
    MIRROR.with(|m| *m.borrow_mut() = Some(mirror));
    ctx.enable_accesskit();
    ctx.add_plugin(Bridge);
    Ok(())
}

/// Takes the mirror out of the page (the app it mirrors is gone: a lost
/// graphics device, see `super::recover`); [`install`] puts a new one in.
pub fn uninstall() {
    MIRROR.with(|m| {
        if let Ok(mut mirror) = m.try_borrow_mut()
            && let Some(mirror) = mirror.take()
        {
            mirror.root.remove();
            mirror.ring.remove();
            mirror.live.remove();
        }
    });
    PENDING.with(|p| p.borrow_mut().clear());
}

/// Says `text` through the polite live region (a screen reader reads it when
/// the student is not busy). The same words twice are said twice.
pub fn announce(text: &str) {
    MIRROR.with(|m| {
        if let Ok(mirror) = m.try_borrow()
            && let Some(mirror) = mirror.as_ref()
        {
            // Emptied first, so a repeated message is a change too.
            mirror.live.set_text_content(None);
            mirror.live.set_text_content(Some(text));
        }
    });
}

/// eframe's hidden text box, right after the canvas, that takes what is
/// typed into a text field clicked with the mouse.
fn text_agent(canvas: &web_sys::Element) -> Option<web_sys::Element> {
    canvas
        .next_element_sibling()
        .filter(|agent| agent.tag_name().eq_ignore_ascii_case("input"))
}

/// Names the mirror's root, the canvas and eframe's text box in the language
/// in force.
fn name_elements(document: &web_sys::Document) -> Result<(), JsValue> {
    use crate::i18n::ts;
    if let Some(root) = document.get_element_by_id(ROOT_ID) {
        root.set_attribute("aria-label", ts("app-name"))?;
    }
    if let Some(canvas) = document.get_element_by_id("shoal_canvas") {
        canvas.set_attribute("aria-label", ts("page-canvas"))?;
        if let Some(agent) = text_agent(&canvas) {
            agent.set_attribute("aria-label", ts("page-text-agent"))?;
        }
    }
    Ok(())
}

/// Names the page's elements again in the language now in force (the
/// controls' own names follow by themselves: egui sends them every frame).
pub fn set_language() {
    if let Some(document) = web_sys::window().and_then(|w| w.document())
        && let Err(err) = name_elements(&document)
    {
        log::warn!("accessibility mirror: {err:?}");
    }
}

/// The egui plugin that carries the tree out and the actions in.
struct Bridge;

impl egui::Plugin for Bridge {
    fn debug_name(&self) -> &'static str {
        "shoal_a11y_mirror"
    }

    fn input_hook(&mut self, _ctx: &egui::Context, input: &mut egui::RawInput) {
        PENDING.with(|p| input.events.append(&mut p.borrow_mut()));
    }

    fn output_hook(&mut self, ctx: &egui::Context, output: &mut egui::FullOutput) {
        let Some(update) = output.platform_output.accesskit_update.as_ref() else {
            return;
        };
        let mirror = Mirror::from_update(update);
        let zoom = ctx.zoom_factor();
        MIRROR.with(|m| {
            if let Some(dom) = m.borrow_mut().as_mut() {
                dom.apply(mirror, zoom);
            }
        });
    }
}

fn push_event(event: egui::Event) {
    PENDING.with(|p| p.borrow_mut().push(event));
}

fn push_action(node: u64, action: Action, data: Option<ActionData>) {
    push_event(egui::Event::AccessKitActionRequest(ActionRequest {
        action,
        target_tree: TreeId::ROOT,
        target_node: NodeId(node),
        data,
    }));
}

/// One element and the item it last showed.
struct Entry {
    element: web_sys::HtmlElement,
    item: Item,
}

struct DomMirror {
    ctx: egui::Context,
    document: web_sys::Document,
    root: web_sys::HtmlElement,
    ring: web_sys::HtmlElement,
    live: web_sys::HtmlElement,
    elements: HashMap<u64, Entry>,
    last: Mirror,
    last_zoom: f32,
    /// The listeners stay alive as long as the page.
    _listeners: Vec<Closure<dyn FnMut(web_sys::Event)>>,
}

fn html(element: web_sys::Element) -> Result<web_sys::HtmlElement, JsValue> {
    element
        .dyn_into::<web_sys::HtmlElement>()
        .map_err(|_| JsValue::from_str("not an HTML element")) // words: a developer's error, logged
}

impl DomMirror {
    fn new(ctx: egui::Context) -> Result<Self, JsValue> {
        let document = web_sys::window()
            .and_then(|w| w.document())
            .ok_or("no document")?; // words: a developer's error, logged
        let body = document.body().ok_or("no body")?; // words: a developer's error, logged

        // Before the canvas: Tab reaches the controls first, the tank after.
        let root = html(document.create_element("div")?)?;
        root.set_id(ROOT_ID);
        let canvas = document.get_element_by_id("shoal_canvas");
        body.insert_before(&root, canvas.as_ref().map(|c| c.as_ref()))?;
        if let Some(canvas) = &canvas {
            // The picture egui draws, and where its own keys go.
            canvas.set_attribute("role", "application")?;
            if let Some(agent) = text_agent(canvas) {
                // Not a Tab stop of its own: eframe focuses it while a text
                // field is being edited.
                agent.set_attribute("tabindex", "-1")?;
            }
        }
        name_elements(&document)?;

        let live = html(document.create_element("div")?)?;
        live.set_id(LIVE_ID);
        live.set_class_name("shoal_sr_only");
        live.set_attribute("role", "status")?;
        live.set_attribute("aria-live", "polite")?;
        live.set_attribute("aria-atomic", "true")?;
        body.append_child(&live)?;

        let ring = html(document.create_element("div")?)?;
        ring.set_id(RING_ID);
        ring.set_attribute("aria-hidden", "true")?;
        body.append_child(&ring)?;

        let mut mirror = Self {
            ctx,
            document,
            root,
            ring,
            live,
            elements: HashMap::new(),
            last: Mirror::default(),
            last_zoom: 1.0,
            _listeners: Vec::new(),
        };
        mirror.listen()?;
        Ok(mirror)
    }

    /// One listener per kind of event on the mirror's root, for every element.
    fn listen(&mut self) -> Result<(), JsValue> {
        for name in ["click", "input", "focusin", "focusout", "keydown"] {
            let ctx = self.ctx.clone();
            let closure =
                Closure::<dyn FnMut(web_sys::Event)>::new(move |event: web_sys::Event| {
                    if on_event(&event) {
                        ctx.request_repaint();
                    }
                });
            self.root
                .add_event_listener_with_callback(name, closure.as_ref().unchecked_ref())?;
            self._listeners.push(closure);
        }
        Ok(())
    }

    /// Brings the page's elements up to `mirror`.
    fn apply(&mut self, mirror: Mirror, zoom: f32) {
        if mirror == self.last && zoom == self.last_zoom {
            return;
        }
        if let Err(err) = self.update_elements(&mirror, zoom) {
            log::warn!("accessibility mirror: {err:?}");
        }
        if mirror.focus != self.last.focus {
            self.follow_egui_focus(&mirror);
        }
        self.place_ring();
        self.last = mirror;
        self.last_zoom = zoom;
    }

    fn update_elements(&mut self, mirror: &Mirror, zoom: f32) -> Result<(), JsValue> {
        let present: std::collections::HashSet<u64> = mirror.items.iter().map(|i| i.id).collect();
        self.elements.retain(|id, entry| {
            let keep = present.contains(id);
            if !keep {
                entry.element.remove();
            }
            keep
        });
        let mut children: HashMap<Option<u64>, Vec<web_sys::HtmlElement>> = HashMap::new();
        for item in &mirror.items {
            let same_element = self
                .elements
                .get(&item.id)
                .is_some_and(|e| same_element(&e.item.kind, &item.kind));
            if !same_element {
                if let Some(old) = self.elements.remove(&item.id) {
                    old.element.remove();
                }
                let element = create(&self.document, item)?;
                write(&element, item, zoom)?;
                self.elements.insert(
                    item.id,
                    Entry {
                        element,
                        item: item.clone(),
                    },
                );
            } else if let Some(entry) = self.elements.get_mut(&item.id)
                && (entry.item != *item || zoom != self.last_zoom)
            {
                write(&entry.element, item, zoom)?;
                entry.item = item.clone();
            }
            if let Some(entry) = self.elements.get(&item.id) {
                children
                    .entry(item.parent)
                    .or_default()
                    .push(entry.element.clone());
            }
        }
        // Each group's elements in reading order (moved only when out of order).
        for (parent, elements) in children {
            let container: &web_sys::HtmlElement = match parent {
                None => &self.root,
                Some(id) => match self.elements.get(&id) {
                    Some(entry) => &entry.element,
                    None => &self.root,
                },
            };
            let mut cursor = container.first_element_child();
            for element in elements {
                let element: &web_sys::Element = element.as_ref();
                if cursor.as_ref() == Some(element) {
                    cursor = element.next_element_sibling();
                } else {
                    container.insert_before(element, cursor.as_ref().map(|c| c.as_ref()))?;
                }
            }
        }
        Ok(())
    }

    /// egui moved its keyboard focus (Tab on the canvas): move the page's focus
    /// to the same control, so a screen reader follows. Not for a text field a
    /// click gave focus to: eframe types into it through its own input.
    fn follow_egui_focus(&self, mirror: &Mirror) {
        let Some(id) = mirror.focus else {
            return;
        };
        let Some(entry) = self.elements.get(&id) else {
            return;
        };
        if matches!(entry.item.kind, Kind::TextInput { .. }) {
            return;
        }
        let active = self.document.active_element();
        let on_canvas = active.as_ref().is_some_and(|a| a.id() == "shoal_canvas");
        if on_canvas {
            focus_without_scroll(&entry.element);
        }
    }

    /// The ring round the focused element, or none.
    fn place_ring(&self) {
        // The browser scrolls the mirror to show an element that Tab focused
        // below the fold; the mirror must stay over the canvas, where egui
        // drew each control (egui scrolls its own panel).
        if self.root.scroll_top() != 0 || self.root.scroll_left() != 0 {
            self.root.set_scroll_top(0);
            self.root.set_scroll_left(0);
        }
        let style = self.ring.style();
        let focused = self
            .document
            .active_element()
            .and_then(|a| a.get_attribute("data-node"))
            .and_then(|id| id.parse::<u64>().ok())
            .and_then(|id| self.elements.get(&id));
        match focused.and_then(|e| e.item.bounds) {
            Some([left, top, right, bottom]) => {
                let z = self.last_zoom;
                let _ = style.set_property("display", "block");
                let _ = style.set_property("left", &format!("{}px", left * z)); // words: CSS
                let _ = style.set_property("top", &format!("{}px", top * z)); // words: CSS
                let _ = style.set_property("width", &format!("{}px", (right - left) * z)); // words: CSS
                let _ = style.set_property("height", &format!("{}px", (bottom - top) * z)); // words: CSS
            }
            None => {
                let _ = style.set_property("display", "none");
            }
        }
    }
}

fn focus_without_scroll(element: &web_sys::HtmlElement) {
    let options = js_sys::Object::new();
    let _ = js_sys::Reflect::set(&options, &"preventScroll".into(), &true.into());
    if let Ok(focus) = js_sys::Reflect::get(element, &"focus".into())
        && let Some(focus) = focus.dyn_ref::<js_sys::Function>()
    {
        let _ = focus.call1(element, &options);
    }
}

/// Whether an element made for `old` can show `new` (same tag and type).
fn same_element(old: &Kind, new: &Kind) -> bool {
    old.tag() == new.tag() && old.input_type() == new.input_type()
}

fn create(document: &web_sys::Document, item: &Item) -> Result<web_sys::HtmlElement, JsValue> {
    let (tag, role) = item.kind.tag();
    let element = html(document.create_element(tag)?)?;
    element.set_attribute("data-node", &item.id.to_string())?;
    if let Some(kind) = item.kind.input_type() {
        element.set_attribute("type", kind)?;
    }
    if let Some(role) = role {
        element.set_attribute("role", role)?;
    }
    match item.kind {
        Kind::Link => element.set_attribute("href", "#")?,
        Kind::ListOption { .. } => element.set_attribute("tabindex", "-1")?,
        Kind::Group { window: true } => element.set_attribute("aria-modal", "false")?,
        _ => {}
    }
    Ok(element)
}

fn set_or_remove(element: &web_sys::Element, name: &str, value: Option<&str>) {
    let _ = match value {
        Some(value) if element.get_attribute(name).as_deref() != Some(value) => {
            element.set_attribute(name, value)
        }
        Some(_) => Ok(()),
        None => element.remove_attribute(name),
    };
}

fn number(value: f64) -> String {
    // Enough digits for any setting, without float noise ("0.80000001").
    let text = format!("{value:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text.is_empty() || text == "-" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}

/// Writes `item` into its element.
fn write(element: &web_sys::HtmlElement, item: &Item, zoom: f32) -> Result<(), JsValue> {
    let e: &web_sys::Element = element.as_ref();
    // Where egui drew it (groups place nothing: their items place themselves).
    if !item.kind.is_group()
        && let Some([left, top, right, bottom]) = item.bounds
    {
        let style = element.style();
        style.set_property("left", &format!("{}px", left * zoom))?; // words: CSS
        style.set_property("top", &format!("{}px", top * zoom))?; // words: CSS
        style.set_property("width", &format!("{}px", ((right - left) * zoom).max(1.0)))?; // words: CSS
        style.set_property("height", &format!("{}px", ((bottom - top) * zoom).max(1.0)))?; // words: CSS
    }
    let name = (!item.name.trim().is_empty()).then_some(item.name.as_str());
    let description = item.description.as_deref().filter(|d| Some(*d) != name);
    set_or_remove(e, "aria-description", description);
    // A greyed-out button or field says so (a text field stays readable).
    let disabled = item.disabled.then_some("true");
    let (tag, _) = item.kind.tag();
    if matches!(tag, "button" | "input") && !matches!(item.kind, Kind::TextInput { .. }) {
        set_or_remove(e, "disabled", item.disabled.then_some(""));
    }
    match &item.kind {
        Kind::Text => {
            if element.text_content().as_deref() != Some(&item.name) {
                element.set_text_content(Some(&item.name));
            }
        }
        Kind::Button { pressed } => {
            write_text(element, &item.name);
            // A language's button is its name in itself, read in its own voice
            // (WCAG 3.1.2).
            let own = crate::i18n::Lang::ALL
                .into_iter()
                .find(|l| l.native_name() == item.name);
            set_or_remove(e, "lang", own.map(crate::i18n::Lang::code));
            set_or_remove(
                e,
                "aria-pressed",
                pressed.map(|p| if p { "true" } else { "false" }),
            );
        }
        Kind::Disclosure { expanded } => {
            write_text(element, &item.name);
            set_or_remove(
                e,
                "aria-expanded",
                Some(if *expanded { "true" } else { "false" }),
            );
        }
        Kind::ComboBox { value, expanded } => {
            write_text(element, value);
            set_or_remove(
                e,
                "aria-label",
                name.map(|n| format!("{n}: {value}")).as_deref(),
            );
            set_or_remove(e, "aria-haspopup", Some("listbox"));
            set_or_remove(
                e,
                "aria-expanded",
                Some(if *expanded { "true" } else { "false" }),
            );
        }
        Kind::Link => write_text(element, &item.name),
        Kind::CheckBox { checked } => {
            let input = element.unchecked_ref::<web_sys::HtmlInputElement>();
            input.set_checked(checked.unwrap_or(false));
            input.set_indeterminate(checked.is_none());
            set_or_remove(e, "aria-label", name);
        }
        Kind::Radio { checked } => {
            let input = element.unchecked_ref::<web_sys::HtmlInputElement>();
            input.set_checked(*checked);
            set_or_remove(e, "aria-label", name);
        }
        Kind::Slider {
            value,
            min,
            max,
            step,
            text,
        } => {
            let input = element.unchecked_ref::<web_sys::HtmlInputElement>();
            set_or_remove(e, "min", Some(&number(*min)));
            set_or_remove(e, "max", Some(&number(*max)));
            // A hundred steps over the range when egui gives none.
            let step = step.unwrap_or((max - min) / 100.0);
            set_or_remove(e, "step", Some(&number(step)));
            if input.value_as_number() != *value {
                input.set_value(&number(*value));
            }
            set_or_remove(e, "aria-valuetext", text.as_deref());
            set_or_remove(e, "aria-label", name);
        }
        Kind::Number {
            value,
            min,
            max,
            step,
        } => {
            let input = element.unchecked_ref::<web_sys::HtmlInputElement>();
            set_or_remove(e, "min", min.map(number).as_deref());
            set_or_remove(e, "max", max.map(number).as_deref());
            set_or_remove(e, "step", Some(&step.map_or("any".to_owned(), number)));
            if input.value_as_number() != *value {
                input.set_value(&number(*value));
            }
            set_or_remove(e, "aria-label", name);
        }
        Kind::TextInput {
            value,
            multiline,
            placeholder,
        } => {
            if *multiline {
                let area = element.unchecked_ref::<web_sys::HtmlTextAreaElement>();
                if area.value() != *value {
                    area.set_value(value);
                }
            } else {
                let input = element.unchecked_ref::<web_sys::HtmlInputElement>();
                if input.value() != *value {
                    input.set_value(value);
                }
            }
            set_or_remove(e, "placeholder", placeholder.as_deref());
            set_or_remove(e, "aria-label", name);
            set_or_remove(e, "aria-disabled", disabled);
        }
        Kind::ListBox => set_or_remove(e, "aria-label", name),
        Kind::ListOption { selected } => {
            write_text(element, &item.name);
            set_or_remove(
                e,
                "aria-selected",
                Some(if *selected { "true" } else { "false" }),
            );
        }
        Kind::Progress { value } => {
            set_or_remove(e, "aria-label", name);
            set_or_remove(e, "aria-valuemin", Some("0"));
            set_or_remove(e, "aria-valuemax", Some("100"));
            set_or_remove(
                e,
                "aria-valuenow",
                value.map(|v| number((v * 100.0).round())).as_deref(),
            );
        }
        Kind::Group { .. } => set_or_remove(e, "aria-label", name),
    }
    Ok(())
}

fn write_text(element: &web_sys::HtmlElement, text: &str) {
    if element.text_content().as_deref() != Some(text) {
        element.set_text_content(Some(text));
    }
}

/// The keys that work anywhere in Shoal (see `app::keyboard_shortcuts`),
/// passed on to egui when a mirrored control has the focus. Space, Enter,
/// the arrows and Tab stay with the control.
const SHORTCUT_KEYS: &[&str] = &[
    "p", "s", "r", "v", "d", "n", "b", "f", "?", "[", "]", "+", "-", "1", "2", "3", "4", "5",
];

/// Handles one event on a mirrored element. Returns whether egui has
/// something new to read.
fn on_event(event: &web_sys::Event) -> bool {
    let Some(target) = event
        .target()
        .and_then(|t| t.dyn_into::<web_sys::HtmlElement>().ok())
    else {
        return false;
    };
    let Some(node) = target
        .get_attribute("data-node")
        .and_then(|id| id.parse::<u64>().ok())
    else {
        return false;
    };
    // `try_borrow`: the mirror itself fires events while it updates the page
    // (moving or removing a focused element, focusing one): those are news to
    // no one.
    let kind = MIRROR.with(|m| {
        m.try_borrow().ok().and_then(|m| {
            m.as_ref()
                .and_then(|m| m.elements.get(&node).map(|e| e.item.kind.clone()))
        })
    });
    let Some(kind) = kind else {
        return false;
    };
    match event.type_().as_str() {
        "click" => {
            if matches!(kind, Kind::Link) {
                event.prevent_default();
            }
            let clickable = matches!(
                kind,
                Kind::Button { .. }
                    | Kind::Disclosure { .. }
                    | Kind::ComboBox { .. }
                    | Kind::Link
                    | Kind::CheckBox { .. }
                    | Kind::Radio { .. }
                    | Kind::ListOption { .. }
            );
            if clickable {
                push_action(node, Action::Focus, None);
                push_action(node, Action::Click, None);
            }
            clickable
        }
        "input" => match kind {
            Kind::Slider { .. } | Kind::Number { .. } => {
                let value = target
                    .unchecked_ref::<web_sys::HtmlInputElement>()
                    .value_as_number();
                if value.is_finite() {
                    push_action(
                        node,
                        Action::SetValue,
                        Some(ActionData::NumericValue(value)),
                    );
                    true
                } else {
                    false
                }
            }
            Kind::TextInput { multiline, .. } => {
                let text = if multiline {
                    target
                        .unchecked_ref::<web_sys::HtmlTextAreaElement>()
                        .value()
                } else {
                    target.unchecked_ref::<web_sys::HtmlInputElement>().value()
                };
                push_action(
                    node,
                    Action::SetValue,
                    Some(ActionData::Value(text.into_boxed_str())),
                );
                true
            }
            _ => false,
        },
        "focusin" => {
            push_action(node, Action::Focus, None);
            MIRROR.with(|m| {
                if let Ok(m) = m.try_borrow()
                    && let Some(m) = m.as_ref()
                {
                    m.place_ring();
                }
            });
            true
        }
        "focusout" => {
            MIRROR.with(|m| {
                if let Ok(m) = m.try_borrow()
                    && let Some(m) = m.as_ref()
                {
                    let _ = m.ring.style().set_property("display", "none");
                }
            });
            false
        }
        "keydown" => {
            let Some(key_event) = event.dyn_ref::<web_sys::KeyboardEvent>() else {
                return false;
            };
            let typing = matches!(kind, Kind::TextInput { .. } | Kind::Number { .. });
            let key = key_event.key();
            let modifiers = key_event.ctrl_key() || key_event.alt_key() || key_event.meta_key();
            if typing || modifiers || !SHORTCUT_KEYS.contains(&key.to_lowercase().as_str()) {
                return false;
            }
            let Some(egui_key) = egui::Key::from_name(&key) else {
                return false;
            };
            event.prevent_default();
            let modifiers = egui::Modifiers {
                shift: key_event.shift_key(),
                ..Default::default()
            };
            for pressed in [true, false] {
                push_event(egui::Event::Key {
                    key: egui_key,
                    physical_key: None,
                    pressed,
                    repeat: false,
                    modifiers,
                });
            }
            true
        }
        _ => false,
    }
}
