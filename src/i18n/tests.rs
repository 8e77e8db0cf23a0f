//! The catalogue is complete in every language, every message the code asks
//! for exists, and no words reach the screen without going through it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use fluent_syntax::ast;

use super::*;
use crate::tr;

/// Every message and attribute of `lang`, with the variables each uses.
fn messages(lang: Lang) -> BTreeMap<String, BTreeSet<String>> {
    let mut out = BTreeMap::new();
    for (name, text) in files(lang) {
        let resource = fluent_syntax::parser::parse(text).unwrap_or_else(|(_, errors)| {
            panic!("locales/{}/{name} does not parse: {errors:?}", lang.code())
        });
        for entry in resource.body {
            let ast::Entry::Message(message) = entry else {
                continue;
            };
            let id = message.id.name.to_owned();
            if let Some(value) = &message.value {
                let fresh = out.insert(id.clone(), variables(value)).is_none();
                assert!(fresh, "{id} twice in locales/{}", lang.code());
            } else {
                assert!(!message.attributes.is_empty(), "{id} is empty");
            }
            for attribute in &message.attributes {
                let key = format!("{id}.{}", attribute.id.name);
                let fresh = out
                    .insert(key.clone(), variables(&attribute.value))
                    .is_none();
                assert!(fresh, "{key} twice in locales/{}", lang.code());
            }
        }
    }
    out
}

fn variables(p: &ast::Pattern<&str>) -> BTreeSet<String> {
    fn inline(e: &ast::InlineExpression<&str>, out: &mut BTreeSet<String>) {
        match e {
            ast::InlineExpression::VariableReference { id } => {
                out.insert(id.name.to_owned());
            }
            ast::InlineExpression::Placeable { expression } => expr(expression, out),
            ast::InlineExpression::FunctionReference { arguments, .. } => {
                arguments.positional.iter().for_each(|a| inline(a, out));
            }
            _ => {}
        }
    }
    fn expr(e: &ast::Expression<&str>, out: &mut BTreeSet<String>) {
        match e {
            ast::Expression::Inline(i) => inline(i, out),
            ast::Expression::Select { selector, variants } => {
                inline(selector, out);
                for v in variants {
                    walk(&v.value, out);
                }
            }
        }
    }
    fn walk(p: &ast::Pattern<&str>, out: &mut BTreeSet<String>) {
        for element in &p.elements {
            if let ast::PatternElement::Placeable { expression } = element {
                expr(expression, out);
            }
        }
    }
    let mut out = BTreeSet::new();
    walk(p, &mut out);
    out
}

/// Every message and attribute of `lang` as it reads without variables.
pub(crate) fn texts(lang: Lang) -> BTreeMap<String, String> {
    messages(lang)
        .into_keys()
        .map(|id| {
            let text = tr_in(lang, &id, None);
            (id, text)
        })
        .collect()
}

#[test]
fn every_language_has_every_message_with_the_same_variables() {
    let english = messages(Lang::En);
    assert!(!english.is_empty());
    for lang in Lang::ALL {
        let other = messages(lang);
        let missing: Vec<_> = english.keys().filter(|k| !other.contains_key(*k)).collect();
        assert!(missing.is_empty(), "{} lacks {missing:?}", lang.code());
        let extra: Vec<_> = other.keys().filter(|k| !english.contains_key(*k)).collect();
        assert!(
            extra.is_empty(),
            "{} has messages English lacks: {extra:?}",
            lang.code()
        );
        for (id, vars) in &english {
            assert_eq!(
                &other[id],
                vars,
                "{id} in {} uses other variables than in English",
                lang.code()
            );
        }
        // Each file of English has its counterpart.
        let names = |l: Lang| files(l).map(|(n, _)| n).collect::<BTreeSet<_>>();
        assert_eq!(names(lang), names(Lang::En), "{}'s files", lang.code());
    }
}

#[test]
fn every_message_formats_in_every_language_without_errors() {
    for lang in Lang::ALL {
        for id in messages(lang).keys() {
            let text = tr_in(lang, id, None);
            assert!(!text.starts_with('['), "{id} in {}: {text}", lang.code());
            assert!(!text.trim().is_empty(), "{id} in {} is empty", lang.code());
        }
    }
}

/// The Rust sources under `src/`, with their text.
fn sources() -> Vec<(PathBuf, String)> {
    fn walk(dir: &Path, out: &mut Vec<(PathBuf, String)>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                out.push((path, text));
            }
        }
    }
    let mut out = Vec::new();
    walk(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), &mut out);
    out.sort();
    out
}

/// The message ids the code names in `tr!("…")`, `tr("…")`, `ts("…")`,
/// `tr_in(…, "…")` and `tr_with("…")`.
fn ids_in_code() -> BTreeSet<(String, String)> {
    let mut out = BTreeSet::new();
    for (path, text) in sources() {
        for call in ["tr!(", "tr(", "ts(", "tr_with(", "tr_in("] {
            for (at, _) in text.match_indices(call) {
                // A call, not the end of another name (`attr(`).
                let before = text[..at].chars().next_back();
                if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
                    continue;
                }
                let rest = &text[at + call.len()..];
                let rest = if call == "tr_in(" {
                    match rest.split_once(',') {
                        Some((_, r)) => r,
                        None => continue,
                    }
                } else {
                    rest
                };
                let rest = rest.trim_start();
                if let Some(literal) = rest.strip_prefix('"') {
                    let id = literal.split('"').next().unwrap();
                    out.insert((id.to_owned(), path.display().to_string()));
                }
            }
        }
    }
    out
}

#[test]
fn every_message_the_code_asks_for_exists() {
    let english = messages(Lang::En);
    let ids = ids_in_code();
    assert!(ids.len() > 10, "the scan finds the calls: {}", ids.len());
    let missing: Vec<_> = ids
        .iter()
        .filter(|(id, path)| !english.contains_key(id) && !path.contains("/i18n/"))
        .collect();
    assert!(missing.is_empty(), "not in the catalogue: {missing:?}");
}

/// Files whose words are not yet in the catalogue. Empty when every word is.
pub(crate) const NOT_YET: &[&str] = &[];

/// Files that show nothing to a student: the simulation's own diagnostics,
/// the benchmarks, the soak's report (for whoever runs it), the command-line lab (its reports are for whoever runs a
/// cluster, in English), the departures census (a document), the browser
/// automation API (for test scripts) and the catalogue itself.
fn not_shown(path: &str) -> bool {
    let shown_from_sim = [
        "sim/reef/demos.rs",
        "sim/reef/events.rs",
        "sim/reef/courtship.rs",
        "sim/reef/feeding.rs",
        "sim/reef/animal.rs",
        "sim/reef/school_watch.rs",
        "sim/common/obstacle.rs",
        "sim/boids/placement.rs",
        "sim/learning/learned_set.rs",
        "sim/learning/learned_motor.rs",
        "sim/learning/learning_lab.rs",
        "sim/boids/control_mode.rs",
    ];
    (path.contains("/sim/") && !shown_from_sim.iter().any(|s| path.ends_with(s)))
        || path.ends_with("census.rs")
        || path.contains("/bin/")
        || path.ends_with("bench.rs")
        || path.ends_with("soak.rs")
        || path.contains("/i18n/")
        || path.ends_with("tests.rs")
        || path.contains("/tests/")
        || path.ends_with("web/api.rs")
        || path.ends_with("automation.rs")
}

/// Whether a string literal reads as words to a person: two words with a
/// space between, or one capitalised word.
fn is_prose(literal: &str) -> bool {
    // Format placeholders and escapes are not words.
    let mut text = String::new();
    let mut depth = 0;
    for c in literal.chars() {
        match c {
            '{' => {
                if depth == 0 {
                    text.push('x');
                }
                depth += 1;
            }
            '}' => depth -= 1,
            _ if depth == 0 => text.push(c),
            _ => {}
        }
    }
    let words: Vec<&str> = text
        .split(|c: char| !c.is_alphabetic() && c != '\'')
        .filter(|w| w.chars().filter(|c| c.is_alphabetic()).count() >= 2)
        .collect();
    let spaced = text
        .as_bytes()
        .windows(3)
        .any(|w| w[0].is_ascii_alphabetic() && w[1] == b' ' && w[2].is_ascii_alphabetic());
    let capitalised = words.len() == 1
        && words[0].chars().next().is_some_and(char::is_uppercase)
        && words[0].chars().skip(1).all(char::is_lowercase);
    (spaced && words.len() >= 2) || capitalised
}

/// Lines where an English literal is expected: logs, panics and assertions
/// (for developers), attributes, ids and keys.
fn allowed_line(line: &str) -> bool {
    let line = line.trim_start();
    line.starts_with("//")
        || (line.starts_with("#[") && !line.starts_with("#[error("))
        || [
            "log::",
            "expect(",
            "panic!(",
            "unreachable!(",
            "assert",
            "Id::new(",
            "id_salt(",
            "// words:",
            "console",
            "include_str!(",
        ]
        .iter()
        .any(|p| line.contains(p))
}

/// The string literals of `code` (its test module left out) that read as
/// words, with their line numbers.
fn prose_literals(code: &str) -> Vec<(usize, String)> {
    let code = code.split("#[cfg(test)]").next().unwrap_or_default();
    let bytes = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    let mut line = 1;
    while i < bytes.len() {
        match bytes[i] {
            b'\n' => line += 1,
            b'/' if bytes.get(i + 1) == Some(&b'/') => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            b'\'' => {
                // A char literal ('"', '\'') or a lifetime: skip a char literal.
                if bytes.get(i + 2) == Some(&b'\'') {
                    i += 3;
                    continue;
                }
                if bytes.get(i + 1) == Some(&b'\\')
                    && let Some(end) = code[i + 2..].find('\'')
                {
                    i += end + 3;
                    continue;
                }
            }
            b'"' => {
                let start_line = line;
                let start = i + 1;
                let raw = i > 0 && (bytes[i - 1] == b'r' || bytes[i - 1] == b'#');
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    if bytes[i] == b'\\' && !raw {
                        i += 1;
                    }
                    if bytes.get(i) == Some(&b'\n') {
                        line += 1;
                    }
                    i += 1;
                }
                let literal = continued(&code[start..i.min(code.len())], raw);
                let literal = literal.as_str();
                let source_line = code.lines().nth(start_line - 1).unwrap_or_default();
                // A CSV file's comment lines are English like the whole file
                // (README, Languages): programs read its column names.
                let csv_comment = literal.starts_with("# ");
                if is_prose(literal) && !allowed_line(source_line) && !csv_comment {
                    out.push((start_line, literal.to_owned()));
                }
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// A string literal's text as Rust reads it across lines: a `\` at the end of
/// a line drops the line break and the next line's indent (not in a raw string).
fn continued(literal: &str, raw: bool) -> String {
    if raw {
        return literal.to_owned();
    }
    let mut out = String::new();
    let mut rest = literal;
    while let Some(at) = rest.find("\\\n") {
        out.push_str(&rest[..at]);
        rest = rest[at + 2..].trim_start();
    }
    out.push_str(rest);
    out
}

#[test]
fn the_lint_sees_words_and_not_keys() {
    assert!(is_prose("Hide this panel"));
    assert!(is_prose("Hide"));
    assert!(is_prose("{} fish in {} schools"));
    assert!(!is_prose("scene_{}"));
    assert!(!is_prose("hide-panel"));
    assert!(!is_prose("{:.2}"));
    assert!(!is_prose("position: absolute; left: 0"));
    assert!(!is_prose("shoal_canvas"));
    assert!(is_prose("{} and {} spawned"));
    let code = "fn f() {\n    ui.button(\"Hide\");\n    log::info!(\"a b c\");\n    tr!(\"hide\");\n}\n#[cfg(test)]\nmod tests { \"Ignored words\" }";
    assert_eq!(prose_literals(code), vec![(2, "Hide".to_owned())]);
    // A literal continued over lines reads as one line.
    let code = "fn f() {\n    ui.label(\"Hide \\\n        this\");\n}\n";
    assert_eq!(prose_literals(code), vec![(2, "Hide this".to_owned())]);
}

#[test]
fn no_words_reach_the_screen_without_the_catalogue() {
    let mut found = Vec::new();
    for (path, text) in sources() {
        let name = path.display().to_string();
        if not_shown(&name) || NOT_YET.iter().any(|f| name.ends_with(f)) {
            continue;
        }
        for (line, literal) in prose_literals(&text) {
            found.push(format!("{name}:{line}: {literal:?}"));
        }
    }
    assert!(
        found.is_empty(),
        "{} literals read as words outside the catalogue (use tr!, or end the line \
         with `// words: <why not>` if no person reads them):\n{}",
        found.len(),
        found.join("\n")
    );
}

#[test]
fn numbers_are_written_the_language_s_way() {
    assert_eq!(format_number(Lang::En, 0.5, Some(2), Some(2)), "0.50");
    assert_eq!(format_number(Lang::Es, 0.5, Some(2), Some(2)), "0,50");
    assert_eq!(format_number(Lang::En, 1234.5, Some(1), Some(1)), "1234.5");
    assert_eq!(
        format_number(Lang::En, 12345.5, Some(1), Some(1)),
        "12,345.5"
    );
    assert_eq!(format_number(Lang::Es, 1234567.0, None, None), "1.234.567");
    assert_eq!(format_number(Lang::Es, -0.25, None, None), "−0,25");
    assert_eq!(format_number(Lang::En, -0.0001, Some(2), Some(2)), "0.00");
    assert_eq!(format_number(Lang::En, 12.0, None, None), "12");
    assert_eq!(format_number(Lang::En, f64::NAN, None, None), "–");
    with_lang(Lang::Es, || assert_eq!(fmt(1.23456, 2), "1,23"));
    with_lang(Lang::En, || assert_eq!(fmt(1.23456, 2), "1.23"));
}

#[test]
fn sliders_write_and_read_numbers_the_language_s_way() {
    with_lang(Lang::Es, || {
        assert!(decimal_comma());
        assert_eq!(localize_decimal("1.25"), "1,25");
    });
    with_lang(Lang::En, || assert!(!decimal_comma()));
    assert_eq!(parse_decimal("1,25"), Some(1.25));
    assert_eq!(parse_decimal("1.25 m"), Some(1.25));
    assert_eq!(parse_decimal("−2"), Some(-2.0));
    assert_eq!(parse_decimal("abc"), None);
}

#[test]
fn languages_are_known_by_their_codes() {
    assert_eq!(Lang::from_code("es"), Some(Lang::Es));
    assert_eq!(Lang::from_code("es-MX"), Some(Lang::Es));
    assert_eq!(Lang::from_code("EN_us"), Some(Lang::En));
    assert_eq!(Lang::from_code("fr"), None);
    assert_eq!(Lang::first_known(["fr-FR", "es-419", "en"]), Some(Lang::Es));
    for lang in Lang::ALL {
        assert_eq!(Lang::from_code(lang.code()), Some(lang));
    }
}

#[test]
fn messages_take_variables_plurals_and_numbers() {
    for (lang, one, many, decimals) in [
        (Lang::En, "1 fish", "12,000 fish", "0.50"),
        (Lang::Es, "1 pez", "12.000 peces", "0,50"),
    ] {
        with_lang(lang, || {
            assert_eq!(tr!("fish-count", count = 1), one);
            assert_eq!(tr!("fish-count", count = 12000), many);
            assert!(tr!("polarization-reading", value = num(0.5, 2)).contains(decimals));
        });
    }
    // The static form is the same words, kept once.
    with_lang(Lang::Es, || {
        let a = ts("hide-panel");
        assert_eq!(a, tr("hide-panel"));
        assert!(std::ptr::eq(a, ts("hide-panel")));
    });
    assert_eq!(
        tr_in(Lang::Es, "no-such-message", None),
        "[no-such-message]"
    );
}

/// The words shown before the WebAssembly loads live in `web/shoal-page.js`
/// (the catalogue is not there yet): each must equal its message, in every
/// language, so a translator changes them in one place and this test says
/// where the copy is stale.
#[test]
fn the_page_s_words_before_loading_match_the_catalogue() {
    let script =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("web/shoal-page.js"))
            .unwrap();
    let table = script
        .split("/* words-begin */")
        .nth(1)
        .and_then(|rest| rest.split("/* words-end */").next())
        .expect("shoal-page.js marks its words");
    let copies: BTreeMap<String, BTreeMap<String, String>> =
        serde_json::from_str(table).expect("the words are JSON");
    assert_eq!(
        copies.keys().cloned().collect::<Vec<_>>(),
        Lang::ALL
            .iter()
            .map(|l| l.code().to_owned())
            .collect::<Vec<_>>(),
        "one table per language of the catalogue"
    );
    let mut args = FluentArgs::new();
    args.set("error", "{error}");
    for lang in Lang::ALL {
        let words = &copies[lang.code()];
        assert_eq!(
            words.keys().collect::<Vec<_>>(),
            copies["en"].keys().collect::<Vec<_>>(),
            "{} has the same words as English",
            lang.code()
        );
        for (id, copy) in words {
            assert_eq!(
                &tr_in(lang, id, Some(&args)),
                copy,
                "web/shoal-page.js's copy of {id} in {}",
                lang.code()
            );
        }
    }
}
