//! Each numeric setting described once: its key, range, label, hover help, unit,
//! the control that edits it and how to read and write it on its settings struct
//! ([`NumberSetting`]). Each settings struct lists its settings in one table
//! (`NUMBERS`, of [`Number`]s): validation and clamping iterate it, the panels
//! draw each row from its entry (`ui/setting_slider.rs`), the studio takes its
//! keys from it, and the tests walk it.

use std::cell::RefCell;
use std::collections::HashSet;

use super::range::{Range, SettingError, SettingValue};
use crate::i18n::ts;

/// Where a setting's number lives on its settings struct `S`.
pub enum Access<S, T> {
    /// A number that is always set.
    Plain {
        get: fn(&S) -> T,
        get_mut: fn(&mut S) -> &mut T,
    },
    /// A number that may be left unset (`null`), in which case `otherwise`
    /// gives the value that applies (the reef demo's own prey count); a value
    /// that is not a number clamps to unset.
    Optional {
        get: fn(&S) -> Option<T>,
        get_mut: fn(&mut S) -> &mut Option<T>,
        otherwise: fn(&S) -> T,
    },
}

/// [`Access::Plain`] to the field `$field` of a settings struct, the type of which
/// the table's entry gives: `field!(alignment)`.
///
/// `field!(prey_count, |r| …)` is [`Access::Optional`] to an `Option` field, the
/// closure giving the value that applies while it is unset.
macro_rules! field {
    ($field:ident) => {
        $crate::settings::number::Access::Plain {
            get: |s| s.$field,
            get_mut: |s| &mut s.$field,
        }
    };
    ($field:ident, $otherwise:expr) => {
        $crate::settings::number::Access::Optional {
            get: |s| s.$field,
            get_mut: |s| &mut s.$field,
            otherwise: $otherwise,
        }
    };
}
pub(crate) use field;

// By hand: derived, they would ask `S` to be `Copy` too.
impl<S, T> Clone for Access<S, T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S, T> Copy for Access<S, T> {}

/// The control a setting is edited with on the side panel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Widget {
    /// A slider over the whole range: `logarithmic` for ranges over orders of
    /// magnitude; at most `decimals` decimals shown (and kept), `None` for as
    /// many as egui picks.
    Slider {
        logarithmic: bool,
        decimals: Option<usize>,
    },
    /// A number to type in or drag (`drag_speed` per point of drag), with
    /// hover help of its own (`own_help`: the `.field` attribute of the
    /// setting's message) when it says something else than the label's.
    Field { drag_speed: f64, own_help: bool },
    /// A count with − and + buttons that take away and add `step` (their hover
    /// help the `.fewer` and `.more` attributes of the setting's message),
    /// around a field to type in (`typed`) or the number as text.
    Count { step: u32, typed: bool },
    /// No control of its own: only the setting's named values
    /// ([`NumberSetting::named`]), as buttons (a fish's character: timid,
    /// ordinary, courageous).
    NamedOnly,
}

impl Widget {
    /// A linear slider, egui picking the decimals.
    pub const SLIDER: Self = Self::Slider {
        logarithmic: false,
        decimals: None,
    };

    /// A logarithmic slider, egui picking the decimals.
    pub const LOG_SLIDER: Self = Self::Slider {
        logarithmic: true,
        decimals: None,
    };

    /// A linear slider showing (and keeping) `decimals` decimals at most.
    pub const fn slider(decimals: usize) -> Self {
        Self::Slider {
            logarithmic: false,
            decimals: Some(decimals),
        }
    }
}

/// A value of a setting with a name of its own ("Calm", "Devoted"), offered as
/// a button beside its control. Its words are the catalogue's message
/// `<setting's id>-<name>` ([`NumberSetting::named_label`]) with `.help`, what
/// it means, shown after the label when the pointer rests on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NamedValue<T> {
    /// Its name in the catalogue's ids, kebab-case ("sexual-mania"); with `_`
    /// for `-`, it ends the button's rectangle name (`<rect>_sexual_mania`).
    pub name: &'static str,
    pub value: T,
}

impl<T> NamedValue<T> {
    pub const fn new(name: &'static str, value: T) -> Self {
        Self { name, value }
    }

    /// The name of its button's rectangle, after the setting's `rect`.
    pub fn rect(&self, rect: &str) -> String {
        format!("{rect}_{}", self.name.replace('-', "_"))
    }
}

/// What a control shows after the number (the catalogue's `setting-unit-…`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// A plain number.
    None,
    Metres,
    MetresPerSecond,
    MetresPerSecondSquared,
    Degrees,
    /// Times as fast (the speed).
    Times,
    /// Food units (a plankton particle is 1).
    Food,
    BodyLengths,
}

impl Unit {
    /// The catalogue's id of its words; `None` for a plain number.
    pub fn id(self) -> Option<&'static str> {
        Some(match self {
            Self::None => return None,
            Self::Metres => "setting-unit-metres",
            Self::MetresPerSecond => "setting-unit-metres-per-second",
            Self::MetresPerSecondSquared => "setting-unit-metres-per-second-squared",
            Self::Degrees => "setting-unit-degrees",
            Self::Times => "setting-unit-times",
            Self::Food => "setting-unit-food",
            Self::BodyLengths => "setting-unit-body-lengths",
        })
    }

    /// What the control shows after the number, with its space (" m/s",
    /// "°"); empty for a plain number.
    pub fn text(self) -> &'static str {
        self.id().map_or("", ts)
    }
}

/// The catalogue id `id`, kept once for the program's life (ids made from a
/// setting's section and key are asked for every frame).
pub fn static_id(id: String) -> &'static str {
    thread_local! {
        static IDS: RefCell<HashSet<&'static str>> = RefCell::new(HashSet::new());
    }
    IDS.with(|ids| {
        let mut ids = ids.borrow_mut();
        match ids.get(id.as_str()) {
            Some(kept) => kept,
            None => {
                let kept: &'static str = Box::leak(id.into_boxed_str());
                ids.insert(kept);
                kept
            }
        }
    })
}

/// One numeric setting of the settings struct `S`, holding a `T`: everything
/// validation, clamping, the panel, the studio and a screen reader need. Its
/// words are in the catalogue (`locales/*/settings.ftl`) under its identity,
/// `setting-<section>-<key>` (`setting-tank-vision-distance-m`): the label,
/// `.help`, and the widget's own `.field`, `.fewer`, `.more`.
pub struct NumberSetting<S, T: 'static> {
    /// The part of the settings it belongs to, in its catalogue id (`tank`,
    /// `minds`, `physics`, `reef`, `learning`, `app`; `aquarium` for the
    /// aquarium's own words for a tank's fish count).
    pub section: &'static str,
    /// Its key (`shoal.set` and share links, under the struct's prefix:
    /// `alignment` is `left.alignment`), valid values and what a value that is
    /// not a number clamps to.
    pub range: Range<T>,
    /// How to read and write it on `S`.
    pub access: Access<S, T>,
    /// What the control shows after the number.
    pub unit: Unit,
    /// The control that edits it.
    pub widget: Widget,
    /// The name of its control's rectangle in `WidgetRects` (the browser tests
    /// click it); a count's buttons add `_minus` and `_plus`, its field `_count`,
    /// a named value's button `_` and its name ([`NamedValue::rect`]).
    pub rect: &'static str,
    /// Values with names of their own, as buttons under the control (picking
    /// one sets it, even to the value it has: an unset optional one is then
    /// set); empty for most.
    pub named: &'static [NamedValue<T>],
}

impl<S, T: Copy + 'static> Clone for NumberSetting<S, T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S, T: Copy + 'static> Copy for NumberSetting<S, T> {}

impl<S, T: Copy + 'static> NumberSetting<S, T> {
    /// A setting edited on a linear slider ([`Widget::SLIDER`]), without a
    /// unit, its rectangle named by its key; the methods below say otherwise.
    pub const fn new(section: &'static str, range: Range<T>, access: Access<S, T>) -> Self {
        Self {
            section,
            range,
            access,
            unit: Unit::None,
            widget: Widget::SLIDER,
            rect: range.key,
            named: &[],
        }
    }

    /// Shown with `unit` after the number (" m/s").
    pub const fn unit(self, unit: Unit) -> Self {
        Self { unit, ..self }
    }

    /// Edited with `widget`.
    pub const fn widget(self, widget: Widget) -> Self {
        Self { widget, ..self }
    }

    /// Its control's rectangle named `rect`.
    pub const fn rect(self, rect: &'static str) -> Self {
        Self { rect, ..self }
    }

    /// Offers `named` values as buttons.
    pub const fn named(self, named: &'static [NamedValue<T>]) -> Self {
        Self { named, ..self }
    }
}

impl<S, T: 'static> NumberSetting<S, T> {
    /// Its message's id in the catalogue: `setting-<section>-<key>`, the key
    /// in kebab-case (`setting-tank-vision-distance-m`).
    pub fn id(&self) -> &'static str {
        static_id(format!(
            "setting-{}-{}",
            self.section,
            self.range.key.replace('_', "-")
        ))
    }

    /// The id of its message's `attribute` (`<id>.help`).
    pub fn attribute_id(&self, attribute: &str) -> &'static str {
        static_id(format!("{}.{attribute}", self.id()))
    }

    /// Its name on the panel ("Vision distance").
    pub fn label(&self) -> &'static str {
        ts(self.id())
    }

    /// The hover help of its label and control, as a 12-year-old reads it.
    pub fn help(&self) -> &'static str {
        ts(self.attribute_id("help"))
    }

    /// What the control shows after the number, with its space (" m/s",
    /// "°"); empty for a plain number.
    pub fn unit_text(&self) -> &'static str {
        self.unit.text()
    }

    /// The hover help of a [`Widget::Field`]: its own, or the label's.
    pub fn field_help(&self) -> &'static str {
        match self.widget {
            Widget::Field { own_help: true, .. } => ts(self.attribute_id("field")),
            _ => self.help(),
        }
    }

    /// The hover help of a [`Widget::Count`]'s − button ("Take 10 away").
    pub fn fewer_help(&self) -> &'static str {
        ts(self.attribute_id("fewer"))
    }

    /// The hover help of a [`Widget::Count`]'s + button ("Add 10").
    pub fn more_help(&self) -> &'static str {
        ts(self.attribute_id("more"))
    }

    /// The id of `named`'s message: `<id>-<name>`.
    pub fn named_id(&self, named: &NamedValue<T>) -> &'static str {
        static_id(format!("{}-{}", self.id(), named.name))
    }

    /// `named`'s button text ("Calm").
    pub fn named_label(&self, named: &NamedValue<T>) -> &'static str {
        ts(self.named_id(named))
    }

    /// What `named` means ("p0 = 0.0003 (Shoal's default)").
    pub fn named_help(&self, named: &NamedValue<T>) -> &'static str {
        ts(static_id(format!("{}.help", self.named_id(named))))
    }

    /// Every catalogue id its words come from (the label, its help, its
    /// widget's, its unit's, its named values' and their help), for the test
    /// that each exists in every language.
    pub fn ids(&self) -> Vec<&'static str> {
        let mut ids = vec![self.id(), self.attribute_id("help")];
        match self.widget {
            Widget::Field { own_help: true, .. } => ids.push(self.attribute_id("field")),
            Widget::Count { .. } => {
                ids.push(self.attribute_id("fewer"));
                ids.push(self.attribute_id("more"));
            }
            _ => {}
        }
        ids.extend(self.unit.id());
        for named in self.named {
            let id = self.named_id(named);
            ids.push(id);
            ids.push(static_id(format!("{id}.help")));
        }
        ids
    }
}

impl<S, T: SettingValue> NumberSetting<S, T> {
    /// The key under `prefix` ("left." gives "left.alignment"), as the studio's
    /// rules and error messages name the setting.
    pub fn full_key(&self, prefix: &str) -> String {
        format!("{prefix}{}", self.range.key)
    }

    /// The value `settings` holds, or, for an unset optional one, the value
    /// that applies.
    pub fn value(&self, settings: &S) -> T {
        match self.access {
            Access::Plain { get, .. } => get(settings),
            Access::Optional { get, otherwise, .. } => {
                get(settings).unwrap_or_else(|| otherwise(settings))
            }
        }
    }

    /// The value `settings` holds; `None` for an unset optional one.
    pub fn given(&self, settings: &S) -> Option<T> {
        match self.access {
            Access::Plain { get, .. } => Some(get(settings)),
            Access::Optional { get, .. } => get(settings),
        }
    }

    /// Puts `value` in `settings` (an optional one is then set).
    pub fn set(&self, settings: &mut S, value: T) {
        match self.access {
            Access::Plain { get_mut, .. } => *get_mut(settings) = value,
            Access::Optional { get_mut, .. } => *get_mut(settings) = Some(value),
        }
    }

    /// Refuses a value outside the range, naming the setting under `prefix`;
    /// an unset optional one is fine.
    pub fn check(&self, prefix: &str, settings: &S) -> Result<(), SettingError> {
        match self.given(settings) {
            Some(value) => self.range.check(prefix, value),
            None => Ok(()),
        }
    }

    /// Brings the value into the range; an unset optional one stays unset,
    /// and one that is not a number becomes unset (the value that otherwise
    /// applies).
    pub fn clamp(&self, settings: &mut S) {
        match self.access {
            Access::Plain { get_mut, .. } => {
                let value = get_mut(settings);
                *value = self.range.clamp(*value);
            }
            Access::Optional { get_mut, .. } => {
                let value = get_mut(settings);
                *value = value.filter(|v| v.is_number()).map(|v| self.range.clamp(v));
            }
        }
    }
}

/// A row of a settings struct's table: a [`NumberSetting`] of any number type.
pub enum Number<S> {
    F32(NumberSetting<S, f32>),
    U32(NumberSetting<S, u32>),
    U64(NumberSetting<S, u64>),
}

impl<S> Clone for Number<S> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S> Copy for Number<S> {}

/// Runs `$body` with `$setting` bound to the [`NumberSetting`] inside `$number`,
/// whatever its number type.
macro_rules! with_setting {
    ($number:expr, $setting:ident => $body:expr) => {
        match $number {
            Number::F32($setting) => $body,
            Number::U32($setting) => $body,
            Number::U64($setting) => $body,
        }
    };
}

impl<S> Number<S> {
    /// The setting's key ("alignment").
    pub fn key(&self) -> &'static str {
        with_setting!(self, s => s.range.key)
    }

    /// See [`NumberSetting::ids`].
    pub fn ids(&self) -> Vec<&'static str> {
        with_setting!(self, s => s.ids())
    }

    /// See [`NumberSetting::check`].
    pub fn check(&self, prefix: &str, settings: &S) -> Result<(), SettingError> {
        with_setting!(self, s => s.check(prefix, settings))
    }

    /// See [`NumberSetting::clamp`].
    pub fn clamp(&self, settings: &mut S) {
        with_setting!(self, s => s.clamp(settings))
    }
}

/// Refuses the first value of `table` outside its range, naming it under `prefix`.
pub fn check_all<S>(table: &[Number<S>], prefix: &str, settings: &S) -> Result<(), SettingError> {
    table.iter().try_for_each(|n| n.check(prefix, settings))
}

/// Brings every value of `table` into its range.
pub fn clamp_all<S>(table: &[Number<S>], settings: &mut S) {
    for n in table {
        n.clamp(settings);
    }
}

/// For every setting of `table`: a value just outside each bound, written into
/// `settings` by key through JSON, is refused by `validate` with an error naming
/// `prefix` + key, and `clamp` brings it to the bound. And the table holds every
/// number `settings` serialise to, so a setting left out of it is not left
/// unchecked. Shared by each settings struct's tests.
#[cfg(test)]
pub(crate) fn check_table<S>(
    settings: &S,
    prefix: &str,
    table: &[Number<S>],
    validate: impl Fn(&S) -> Result<(), SettingError>,
    clamp: impl Fn(&mut S),
) where
    S: serde::Serialize + serde::de::DeserializeOwned,
{
    use serde_json::{Value, json};
    let fields = serde_json::to_value(settings).expect("settings serialise");
    for (key, value) in fields.as_object().expect("settings are an object") {
        if value.is_number() {
            assert!(
                table.iter().any(|n| n.key() == key),
                "{prefix}{key} is a number missing from the table"
            );
        }
    }
    let mut cases: Vec<(&str, Value, Value)> = Vec::new();
    for n in table {
        match n {
            Number::F32(s) => {
                let r = s.range;
                let step = (r.max - r.min).abs().max(1.0) * 1e-3;
                cases.push((r.key, json!(r.min - step), json!(r.min)));
                cases.push((r.key, json!(r.max + step), json!(r.max)));
            }
            Number::U32(s) => {
                let r = s.range;
                if r.min > 0 {
                    cases.push((r.key, json!(r.min - 1), json!(r.min)));
                }
                cases.push((r.key, json!(u64::from(r.max) + 1), json!(r.max)));
            }
            Number::U64(s) => {
                let r = s.range;
                if r.min > 0 {
                    cases.push((r.key, json!(r.min - 1), json!(r.min)));
                }
                cases.push((r.key, json!(r.max + 1), json!(r.max)));
            }
        }
    }
    assert!(!cases.is_empty());
    for (key, outside, bound) in cases {
        assert!(fields.get(key).is_some(), "{prefix}{key} is a setting");
        let mut value = fields.clone();
        value[key] = outside.clone();
        let mut s: S = serde_json::from_value(value).expect("a number the field takes");
        let err = validate(&s).expect_err(&format!("{key} = {outside} is refused"));
        assert_eq!(err.key, format!("{prefix}{key}"), "{err}");
        assert!(err.reason.contains("out of range"), "{err}");
        clamp(&mut s);
        let clamped = serde_json::to_value(&s).expect("settings serialise")[key].clone();
        assert_eq!(
            clamped.as_f64(),
            bound.as_f64(),
            "{key} = {outside} clamps to the bound"
        );
        assert!(validate(&s).is_ok(), "{key}: clamp makes it valid");
    }
}
