//! Every word Shoal shows, in every language of its catalogue.
//!
//! The catalogue is Project Fluent's format (`fluent-bundle`): one folder per
//! language under `locales/` (`locales/en/`, `locales/es/`), one `.ftl` file
//! per part of the interface, each message an id and its text
//! (`hide-panel = Hide`), with attributes for its parts (`.help = …`),
//! variables (`{ $count }`) and plural forms
//! (`{ $count -> [one] fish *[other] fish }`). `build.rs` lists the files, so a
//! new file needs no edit here.
//!
//! Code asks for words by id: [`tr!`] for a message with variables, [`tr`]
//! for one without, [`ts`] where a `&'static str` is needed (each message is
//! kept once per language). `id.attribute` names an attribute. The language
//! in force is the thread's ([`set_lang`]; the app's UI thread); a missing
//! message shows its id in brackets (the tests make sure none is missing).
//!
//! Numbers are written the language's way ([`fmt`], [`num`]): `1,234.5` in
//! English, `1.234,5` in Spanish (CLDR's `es`), grouped from five digits.

use std::cell::{Cell, RefCell};
use std::collections::HashMap;

use fluent_bundle::types::{FluentNumber, FluentNumberOptions};
use fluent_bundle::{FluentArgs, FluentBundle, FluentResource, FluentValue};
use serde::{Deserialize, Serialize};

#[cfg(test)]
pub(crate) mod tests;

mod catalogue {
    include!(concat!(env!("OUT_DIR"), "/catalogue.rs"));
}

pub use fluent_bundle::FluentArgs as Args;

/// A language of the catalogue.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Lang {
    #[default]
    #[serde(rename = "en")]
    En,
    #[serde(rename = "es")]
    Es,
}

impl Lang {
    pub const ALL: [Lang; 2] = [Lang::En, Lang::Es];

    /// The BCP 47 code (`<html lang>`, `?lang=`, the catalogue's folder).
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Es => "es",
        }
    }

    /// The language's name in itself, as the language picker shows it.
    pub fn native_name(self) -> &'static str {
        match self {
            Lang::En => "English",
            Lang::Es => "Español",
        }
    }

    /// The language of a code such as `es`, `es-MX` or `EN_us`; `None` for a
    /// language the catalogue does not have.
    pub fn from_code(code: &str) -> Option<Lang> {
        let primary = code
            .trim()
            .split(['-', '_'])
            .next()
            .unwrap_or_default()
            .to_ascii_lowercase();
        Lang::ALL.into_iter().find(|l| l.code() == primary)
    }

    /// The first language of `preferred` (the browser's, best first) that the
    /// catalogue has.
    pub fn first_known<'a>(preferred: impl IntoIterator<Item = &'a str>) -> Option<Lang> {
        preferred.into_iter().find_map(Lang::from_code)
    }

    fn decimal_separator(self) -> char {
        match self {
            Lang::En => '.',
            Lang::Es => ',',
        }
    }

    fn group_separator(self) -> char {
        match self {
            Lang::En => ',',
            Lang::Es => '.',
        }
    }
}

thread_local! {
    static CURRENT: Cell<Lang> = const { Cell::new(Lang::En) };
    static BUNDLES: RefCell<HashMap<Lang, &'static FluentBundle<FluentResource>>> =
        RefCell::new(HashMap::new());
    static STATIC: RefCell<HashMap<(Lang, &'static str), &'static str>> =
        RefCell::new(HashMap::new());
}

/// The language in force on this thread.
pub fn lang() -> Lang {
    CURRENT.with(Cell::get)
}

/// Puts `lang` in force on this thread (the app's UI thread).
pub fn set_lang(lang: Lang) {
    CURRENT.with(|c| c.set(lang));
}

/// Runs `f` with `lang` in force, then puts the previous language back (for
/// words that must be in one language whatever the screen shows, and tests).
pub fn with_lang<T>(lang: Lang, f: impl FnOnce() -> T) -> T {
    let before = self::lang();
    set_lang(lang);
    let out = f();
    set_lang(before);
    out
}

/// The catalogue's files of `lang`: (file name, contents).
pub fn files(lang: Lang) -> impl Iterator<Item = (&'static str, &'static str)> {
    catalogue::FILES
        .iter()
        .filter(move |(code, _, _)| *code == lang.code())
        .map(|(_, name, text)| (*name, *text))
}

fn build(lang: Lang) -> FluentBundle<FluentResource> {
    let id: unic_langid::LanguageIdentifier = lang.code().parse().expect("a valid code");
    let mut bundle = FluentBundle::new(vec![id]);
    // No invisible bidirectional marks around variables: egui would draw them.
    bundle.set_use_isolating(false);
    bundle.set_formatter(Some(match lang {
        Lang::En => |v, _| format_value(Lang::En, v),
        Lang::Es => |v, _| format_value(Lang::Es, v),
    }));
    for (name, text) in files(lang) {
        let resource = FluentResource::try_new(text.to_owned()).unwrap_or_else(|(r, errors)| {
            log::error!("locales/{}/{name}: {errors:?}", lang.code());
            r
        });
        if let Err(errors) = bundle.add_resource(resource) {
            log::error!("locales/{}/{name}: {errors:?}", lang.code());
        }
    }
    bundle
}

/// The bundle of `lang`, built once per thread and kept for the program's life.
fn bundle(lang: Lang) -> &'static FluentBundle<FluentResource> {
    BUNDLES.with(|b| {
        *b.borrow_mut()
            .entry(lang)
            .or_insert_with(|| Box::leak(Box::new(build(lang))))
    })
}

/// Whether `lang` has the message `id` (`id.attribute` for an attribute).
pub fn has(lang: Lang, id: &str) -> bool {
    lookup(lang, id, None).is_some()
}

fn lookup(lang: Lang, id: &str, args: Option<&FluentArgs>) -> Option<String> {
    let bundle = bundle(lang);
    let (message, attribute) = match id.split_once('.') {
        Some((m, a)) => (m, Some(a)),
        None => (id, None),
    };
    let message = bundle.get_message(message)?;
    let pattern = match attribute {
        Some(a) => message.get_attribute(a)?.value(),
        None => message.value()?,
    };
    let mut errors = Vec::new();
    let text = bundle.format_pattern(pattern, args, &mut errors);
    if !errors.is_empty() {
        log::warn!("message {id} ({}): {errors:?}", lang.code());
    }
    Some(text.into_owned())
}

/// The message `id` in `lang` with `args`; English where `lang` lacks it, and
/// `[id]` where English does too.
pub fn tr_in(lang: Lang, id: &str, args: Option<&FluentArgs>) -> String {
    lookup(lang, id, args)
        .or_else(|| {
            log::warn!("message {id} is missing in {}", lang.code());
            lookup(Lang::En, id, args)
        })
        .unwrap_or_else(|| format!("[{id}]"))
}

/// The message `id` in the language in force.
pub fn tr(id: &str) -> String {
    tr_in(lang(), id, None)
}

/// The message `id` with `args` in the language in force (see [`tr!`]).
pub fn tr_with(id: &str, args: &FluentArgs) -> String {
    tr_in(lang(), id, Some(args))
}

/// The message `id` (without variables) in the language in force, as a
/// `&'static str`: each (language, message) is made once and kept.
pub fn ts(id: &'static str) -> &'static str {
    let lang = lang();
    STATIC.with(|s| {
        *s.borrow_mut()
            .entry((lang, id))
            .or_insert_with(|| Box::leak(tr_in(lang, id, None).into_boxed_str()))
    })
}

/// A message with variables in the language in force:
/// `tr!("fish-count", count = 12, name = "Nemo")`; `tr!("hide")` without.
/// Numbers given as [`num`] keep their decimals.
#[macro_export]
macro_rules! tr {
    ($id:expr) => {
        $crate::i18n::tr($id)
    };
    ($id:expr, $($key:ident = $value:expr),+ $(,)?) => {{
        let mut args = $crate::i18n::Args::new();
        $(args.set(stringify!($key), $crate::i18n::arg($value));)+
        $crate::i18n::tr_with($id, &args)
    }};
}

/// A variable of a message: numbers, text, and [`num`] values.
pub fn arg<'a>(value: impl Into<Arg<'a>>) -> FluentValue<'a> {
    value.into().0
}

/// A message variable (see [`arg`]).
pub struct Arg<'a>(FluentValue<'a>);

macro_rules! arg_from_number {
    ($($t:ty)+) => {$(
        impl From<$t> for Arg<'_> {
            fn from(n: $t) -> Self {
                Arg(FluentValue::from(n))
            }
        }
    )+};
}
arg_from_number!(i8 i16 i32 i64 isize u8 u16 u32 u64 usize f32 f64);

impl<'a> From<&'a str> for Arg<'a> {
    fn from(s: &'a str) -> Self {
        Arg(FluentValue::from(s))
    }
}

impl<'a> From<&'a String> for Arg<'a> {
    fn from(s: &'a String) -> Self {
        Arg(FluentValue::from(s.as_str()))
    }
}

impl From<String> for Arg<'_> {
    fn from(s: String) -> Self {
        Arg(FluentValue::from(s))
    }
}

impl<'a> From<FluentValue<'a>> for Arg<'a> {
    fn from(v: FluentValue<'a>) -> Self {
        Arg(v)
    }
}

/// `value` as a message variable with exactly `decimals` decimals (its plural
/// form chosen on what is shown: "1.0 metres").
pub fn num(value: f64, decimals: usize) -> FluentValue<'static> {
    let options = FluentNumberOptions {
        minimum_fraction_digits: Some(decimals),
        maximum_fraction_digits: Some(decimals),
        ..Default::default()
    };
    FluentValue::Number(FluentNumber::new(value, options))
}

/// `value` with `decimals` decimals, written the way of the language in force.
pub fn fmt(value: f64, decimals: usize) -> String {
    format_number(lang(), value, Some(decimals), Some(decimals))
}

/// `value` written the way of `lang`: rounded to `max_decimals` (none given:
/// as few as show it exactly, at most 6), padded to `min_decimals`, grouped in
/// thousands from five integer digits.
pub fn format_number(
    lang: Lang,
    value: f64,
    min_decimals: Option<usize>,
    max_decimals: Option<usize>,
) -> String {
    if !value.is_finite() {
        return if value.is_nan() {
            "–".to_owned()
        } else if value > 0.0 {
            "∞".to_owned()
        } else {
            "−∞".to_owned()
        };
    }
    let max = max_decimals.unwrap_or(6);
    let mut text = format!("{:.*}", max, value.abs());
    if max_decimals.is_none() || min_decimals.is_some_and(|m| m < max) {
        // Trailing zeros beyond the minimum go.
        let keep = min_decimals.unwrap_or(0);
        if let Some(point) = text.find('.') {
            let mut end = text.len();
            while end > point + 1 + keep && text.as_bytes()[end - 1] == b'0' {
                end -= 1;
            }
            if end == point + 1 {
                end = point;
            }
            text.truncate(end);
        }
    }
    let (int, frac) = match text.split_once('.') {
        Some((i, f)) => (i.to_owned(), Some(f.to_owned())),
        None => (text.clone(), None),
    };
    let int = if int.len() >= 5 {
        let mut grouped = String::new();
        for (i, c) in int.chars().enumerate() {
            if i > 0 && (int.len() - i) % 3 == 0 {
                grouped.push(lang.group_separator());
            }
            grouped.push(c);
        }
        grouped
    } else {
        int
    };
    let negative = value < 0.0
        && (int.chars().any(|c| c != '0')
            || frac.as_ref().is_some_and(|f| f.chars().any(|c| c != '0')));
    let mut out = String::new();
    if negative {
        out.push('−');
    }
    out.push_str(&int);
    if let Some(frac) = frac {
        out.push(lang.decimal_separator());
        out.push_str(&frac);
    }
    out
}

/// Whether the language in force writes its decimal point as a comma (egui's
/// sliders and fields then show and read numbers its way, see
/// [`localize_decimal`] and [`parse_decimal`]).
pub fn decimal_comma() -> bool {
    lang().decimal_separator() == ','
}

/// A number as egui writes it (`1.25`), written the way of the language in
/// force (`1,25`).
pub fn localize_decimal(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '.' => lang().decimal_separator(),
            c => c,
        })
        .collect()
}

/// A number typed in either way (`1,25` or `1.25`, `−2`), as a value.
pub fn parse_decimal(text: &str) -> Option<f64> {
    let cleaned: String = text
        .trim()
        .chars()
        .filter_map(|c| match c {
            ',' => Some('.'),
            '−' => Some('-'),
            c if c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E') => Some(c),
            _ => None,
        })
        .collect();
    cleaned.parse().ok()
}

fn format_value(lang: Lang, value: &FluentValue) -> Option<String> {
    match value {
        FluentValue::Number(n) => Some(format_number(
            lang,
            n.value,
            n.options.minimum_fraction_digits,
            n.options.maximum_fraction_digits,
        )),
        _ => None,
    }
}
