//! The student's record: every investigation done this session (question,
//! prediction, measured result, explanations, the reveal) as one self-contained
//! HTML file a teacher opens without Shoal (inline CSS, the plots as inline SVG,
//! no scripts), and the runs' measured numbers as CSV.

use std::fmt::Write as _;

use super::Progress;
use super::catalogue::PredictionKind;
use super::outcome::{Chart, CurvePoint, Outcome, x_span};
use crate::i18n::{fmt, lang, num, tr, ts};
use crate::tr;

/// Text made safe inside HTML (element content and attribute values).
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

const STYLE: &str = "body{font-family:system-ui,sans-serif;max-width:46em;margin:2em auto;\
padding:0 1em;color:#1d2733;line-height:1.45}h1{font-size:1.6em}section{border-top:2px solid \
#2a6f97;margin-top:2em;padding-top:.5em}h3{margin-bottom:.2em;color:#2a6f97}.q{font-size:1.15em;\
font-weight:600}.locked{background:#eef5fa;padding:.3em .6em;border-left:4px solid #2a6f97}\
table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:.2em .6em;text-align:left}\
td.n{text-align:right}.ref{font-size:.9em;color:#555}svg{max-width:100%;height:auto}\
.answer{white-space:pre-wrap;background:#fafafa;padding:.3em .6em;border:1px solid #ddd}\
.who{font-size:1.1em;font-weight:600}.run>a{overflow-wrap:anywhere}";

/// Who made the record, when, and where Shoal runs: what makes it ready to
/// hand in.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RecordInfo {
    /// The student's name as typed (may be empty).
    pub student: String,
    /// The local date, `2026-11-28`.
    pub date: String,
    /// The local time, `14:05`.
    pub time: String,
    /// The page's address, for the links that run each investigation again.
    pub page: String,
}

/// The HTML file of `done` (the investigations with a committed prediction),
/// in the language in force.
pub fn html(done: &[Progress], info: &RecordInfo) -> String {
    let mut out = String::new();
    let title = escape(ts("inv-record-title"));
    let _ = write!(
        out,
        concat!(
            "<!DOCTYPE html>\n<html lang=\"{}\"><head><meta charset=\"utf-8\">", // words: HTML markup
            "<title>{title}</title><style>{STYLE}</style></head><body>\n", // words: HTML markup
            "<h1>{title}</h1>\n<p class=\"who\">{}</p>\n<p>{}</p>\n"       // words: HTML markup
        ),
        lang().code(),
        escape(&byline(info)),
        escape(ts("inv-record-intro")),
        title = title,
        STYLE = STYLE,
    );
    if done.is_empty() {
        let _ = writeln!(out, "<p>{}</p>", escape(ts("inv-record-none")));
    }
    for p in done {
        section(&mut out, p, &info.page);
    }
    out.push_str("</body></html>\n");
    out
}

/// "Ana Pérez, 2026-11-28 at 14:05" (or "No name given, …").
fn byline(info: &RecordInfo) -> String {
    let name = info.student.trim();
    let name = if name.is_empty() {
        tr("inv-record-no-name")
    } else {
        name.to_owned()
    };
    tr!(
        "inv-record-byline",
        name = name,
        date = info.date.as_str(),
        time = info.time.as_str()
    )
}

/// The seeds of `p`'s run, "6" or "1, 2, 3".
fn seeds_text(p: &Progress) -> String {
    p.seeds()
        .iter()
        .map(u64::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

fn section(out: &mut String, p: &Progress, page: &str) {
    let inv = p.investigation;
    let _ = write!(
        out,
        "<section>\n<h2>{}</h2>\n<p>{}</p>\n<p class=\"q\">{}</p>\n<h3>{}</h3>\n", // words: HTML markup
        escape(inv.title.text()),
        escape(inv.intro.text()),
        escape(inv.question.text()),
        escape(ts("inv-record-my-prediction"))
    );
    match p.prediction {
        Some(pred) => {
            let _ = writeln!(
                out,
                "<p class=\"locked\">{}</p>", // words: HTML markup
                escape(&tr!(
                    "inv-record-locked",
                    prediction = p.answer_text(pred.choice)
                ))
            );
        }
        None => {
            let _ = writeln!(out, "<p>{}</p>", escape(ts("inv-record-no-prediction")));
        }
    }
    let _ = writeln!(out, "<h3>{}</h3>", escape(ts("inv-record-measured")));
    if let Some(link) = p.rerun_link(page) {
        let _ = writeln!(
            out,
            "<p class=\"run\">{} <a href=\"{}\">{}</a></p>", // words: HTML markup
            escape(&tr!("inv-record-seeds", seeds = seeds_text(p))),
            escape(&link),
            escape(ts("inv-record-rerun"))
        );
    }
    match p.outcome.as_ref().map(|o| o.localized()) {
        Some(outcome) => {
            let _ = writeln!(out, "<p>{}</p>", escape(&outcome.summary));
            table(out, outcome);
            out.push_str(&svg(p, outcome));
            if !outcome.timelines.is_empty() {
                out.push('\n');
                out.push_str(&timelines_svg(outcome));
            }
            let _ = writeln!(out, "\n<p>{}</p>", escape(&outcome.verdict));
        }
        None => {
            let _ = writeln!(out, "<p>{}</p>", escape(ts("inv-record-not-finished")));
        }
    }
    if p.explanations.iter().any(|e| !e.trim().is_empty()) {
        let _ = writeln!(out, "<h3>{}</h3>", escape(ts("inv-record-my-explanations")));
        for (prompt, answer) in inv.prompts.iter().zip(&p.explanations) {
            let _ = writeln!(
                out,
                "<p><b>{}</b></p><p class=\"answer\">{}</p>", // words: HTML markup
                escape(prompt.text()),
                if answer.trim().is_empty() {
                    escape(ts("inv-record-no-answer"))
                } else {
                    escape(answer)
                }
            );
        }
    }
    if p.step == super::Step::Reveal {
        let _ = writeln!(
            out,
            "<h3>{}</h3>\n<p>{}</p>\n<p class=\"ref\">{}</p>", // words: HTML markup
            escape(ts("inv-found")),
            escape(inv.reveal.text()),
            escape(inv.reference.text())
        );
    }
    out.push_str("</section>\n");
}

fn table(out: &mut String, outcome: &Outcome) {
    let _ = writeln!(
        out,
        "<table><tr><th>{}</th><th>{}</th><th>{}</th></tr>",
        escape(ts("inv-record-table-measured")),
        escape(ts("inv-record-table-value")),
        escape(ts("inv-record-table-unit"))
    );
    for row in &outcome.rows {
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td class=\"n\">{}</td><td>{}</td></tr>", // words: HTML markup
            escape(&row.label),
            number(row.value),
            escape(row.unit)
        );
    }
    out.push_str("</table>\n");
}

/// A number as the record prints it, the language's way: whole numbers bare,
/// others to 3 decimals.
pub fn number(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e12 {
        fmt(v, 0)
    } else {
        fmt(v, 3)
    }
}

const W: f64 = 520.0;
const H: f64 = 240.0;
const LEFT: f64 = 60.0;
const BOTTOM: f64 = 40.0;
const TOP: f64 = 14.0;
const RIGHT: f64 = 16.0;

/// An SVG picture's opening, on a white ground.
fn svg_open() -> String {
    format!(
        concat!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {W} {H}\" width=\"{W}\" ", // words: HTML markup
            "height=\"{H}\" role=\"img\" font-family=\"sans-serif\" font-size=\"11\">", // words: HTML markup
            "<rect width=\"{W}\" height=\"{H}\" fill=\"#fff\"/>" // words: HTML markup
        ),
        W = W,
        H = H
    )
}

/// The result's chart as an inline SVG picture.
pub fn svg(p: &Progress, outcome: &Outcome) -> String {
    let mut s = svg_open();
    match &outcome.chart {
        Chart::Bars { unit, whole } => bars(&mut s, outcome, unit, *whole),
        Chart::Curve {
            x_label,
            y_label,
            points,
            y_max,
        } => curve(&mut s, p, points, *y_max, x_label, y_label),
    }
    s.push_str("</svg>");
    s
}

/// The axes, marked 0 to `y_max` in quarters, or (`whole`) in whole numbers
/// up to the first mark at or above `y_max`: returns the axis's top.
fn axes(s: &mut String, y_max: f64, y_label: &str, whole: bool) -> f64 {
    let (x0, y0, y1) = (LEFT, H - BOTTOM, TOP);
    let _ = write!(
        s,
        concat!(
            "<line x1=\"{x0}\" y1=\"{y0}\" x2=\"{}\" y2=\"{y0}\" stroke=\"#333\"/>", // words: HTML markup
            "<line x1=\"{x0}\" y1=\"{y0}\" x2=\"{x0}\" y2=\"{y1}\" stroke=\"#333\"/>" // words: HTML markup
        ),
        W - RIGHT,
        x0 = x0,
        y0 = y0,
        y1 = y1,
    );
    let marks: Vec<f64> = if whole {
        super::outcome::whole_ticks(y_max, 5)
    } else {
        (0..=4).map(|k| y_max * f64::from(k) / 4.0).collect()
    };
    let top = marks
        .last()
        .copied()
        .unwrap_or(y_max)
        .max(f64::MIN_POSITIVE);
    for &v in &marks {
        let y = y0 - (y0 - y1) * v / top;
        let _ = write!(
            s,
            "<text x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>", // words: HTML markup
            x0 - 4.0,
            y + 4.0,
            if whole { fmt(v, 0) } else { tick(v) }
        );
    }
    let _ = write!(
        s,
        concat!(
            "<text x=\"12\" y=\"{:.1}\" transform=\"rotate(-90 12 {:.1})\" ", // words: HTML markup
            "text-anchor=\"middle\">{}</text>"                                // words: HTML markup
        ),
        (y0 + y1) / 2.0,
        (y0 + y1) / 2.0,
        escape(y_label)
    );
    top
}

fn tick(v: f64) -> String {
    if v >= 10.0 || v == 0.0 {
        fmt(v, 0)
    } else {
        fmt(v, 2)
    }
}

fn bars(s: &mut String, outcome: &Outcome, unit: &str, whole: bool) {
    let top = outcome.rows.iter().map(|r| r.value).fold(0.0, f64::max);
    let y_max = if top > 0.0 { top * 1.15 } else { 1.0 };
    let y_max = axes(s, y_max, unit, whole);
    let n = outcome.rows.len().max(1) as f64;
    let slot = (W - LEFT - RIGHT) / n;
    let plot_h = H - BOTTOM - TOP;
    for (k, row) in outcome.rows.iter().enumerate() {
        let h = plot_h * (row.value.max(0.0) / y_max);
        let x = LEFT + slot * k as f64 + slot * 0.2;
        let _ = write!(
            s,
            concat!(
                "<rect x=\"{x:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{h:.1}\" fill=\"#2a6f97\"/>", // words: HTML markup
                "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>", // words: HTML markup
                "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\" font-size=\"9\">{}</text>" // words: HTML markup
            ),
            H - BOTTOM - h,
            slot * 0.6,
            x + slot * 0.3,
            H - BOTTOM - h - 3.0,
            number(row.value),
            x + slot * 0.3,
            H - BOTTOM + 14.0,
            escape(&short(&row.label)),
            x = x,
            h = h,
        );
    }
}

/// A label short enough to sit under a bar.
fn short(label: &str) -> String {
    let chars: Vec<char> = label.chars().collect();
    if chars.len() > 28 {
        chars[chars.len() - 28..].iter().collect::<String>()
    } else {
        label.to_owned()
    }
}

fn curve(
    s: &mut String,
    p: &Progress,
    points: &[CurvePoint],
    y_max: f64,
    x_label: &str,
    y_label: &str,
) {
    let top = points.iter().map(|q| q.high).fold(y_max, f64::max);
    axes(s, top, y_label, false);
    let (x0, x1) = x_span(points);
    let span = if x1 > x0 { x1 - x0 } else { 1.0 };
    let px = |x: f64| LEFT + (W - LEFT - RIGHT) * (x - x0) / span;
    let py = |y: f64| H - BOTTOM - (H - BOTTOM - TOP) * (y / top).clamp(-0.05, 1.05);
    for q in points {
        let _ = write!(
            s,
            concat!(
                "<line x1=\"{0:.1}\" y1=\"{1:.1}\" x2=\"{0:.1}\" y2=\"{2:.1}\" stroke=\"#e07a1f\" ", // words: HTML markup
                "stroke-width=\"2\"/><text x=\"{0:.1}\" y=\"{3:.1}\" text-anchor=\"middle\">{4}</text>" // words: HTML markup
            ),
            px(q.x),
            py(q.low),
            py(q.high),
            H - BOTTOM + 14.0,
            tick(q.x)
        );
    }
    let path: Vec<String> = points
        .iter()
        .map(|q| format!("{:.1},{:.1}", px(q.x), py(q.mean)))
        .collect();
    let _ = write!(
        s,
        "<polyline points=\"{}\" fill=\"none\" stroke=\"#e07a1f\" stroke-width=\"2.5\"/>", // words: HTML markup
        path.join(" ")
    );
    for q in points {
        let _ = write!(
            s,
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3.5\" fill=\"#e07a1f\"/>", // words: HTML markup
            px(q.x),
            py(q.mean)
        );
    }
    if let (Some(pred), PredictionKind::Curve { shapes, .. }) =
        (p.prediction, p.investigation.prediction)
        && let Some(shape) = shapes.get(pred.choice)
    {
        let sketch: Vec<String> = (0..=40)
            .map(|k| {
                let u = f64::from(k) / 40.0;
                format!("{:.1},{:.1}", px(x0 + u * span), py(shape.at(u) * y_max))
            })
            .collect();
        let _ = write!(
            s,
            concat!(
                "<polyline points=\"{}\" fill=\"none\" stroke=\"#2a6f97\" stroke-width=\"2\" ", // words: HTML markup
                "stroke-dasharray=\"6 4\"/>" // words: HTML markup
            ),
            sketch.join(" ")
        );
    }
    let _ = write!(
        s,
        concat!(
            "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>", // words: HTML markup
            "<text x=\"{:.1}\" y=\"{TOP}\" text-anchor=\"end\" fill=\"#e07a1f\">{}</text>", // words: HTML markup
            "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\" fill=\"#2a6f97\">{}</text>" // words: HTML markup
        ),
        (LEFT + W - RIGHT) / 2.0,
        H - 6.0,
        escape(x_label),
        W - RIGHT,
        escape(ts("inv-record-svg-measured")),
        W - RIGHT,
        TOP + 14.0,
        escape(ts("inv-record-svg-prediction")),
        TOP = TOP,
    );
}

/// The counts over the run (the catches plot) as an inline SVG picture.
pub fn timelines_svg(outcome: &Outcome) -> String {
    const COLORS: [&str; 2] = ["#e07a1f", "#2a8fc7"];
    let mut s = svg_open();
    let all = outcome.timelines.iter().flat_map(|t| t.points.iter());
    let x_max = all.clone().map(|p| p[0]).fold(1.0, f64::max);
    let y_top = all.map(|p| p[1]).fold(0.0, f64::max).max(1.0) * 1.15;
    let y_top = axes(&mut s, y_top, ts("inv-unit-fish-caught"), true);
    let px = |x: f64| LEFT + (W - LEFT - RIGHT) * x / x_max;
    let py = |y: f64| H - BOTTOM - (H - BOTTOM - TOP) * y / y_top;
    for (k, t) in outcome.timelines.iter().enumerate() {
        let color = COLORS[k % COLORS.len()];
        let path: Vec<String> = t
            .points
            .iter()
            .map(|p| format!("{:.1},{:.1}", px(p[0]), py(p[1])))
            .collect();
        let _ = write!(
            s,
            concat!(
                "<polyline points=\"{}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"/>", // words: HTML markup
                "<text x=\"{:.1}\" y=\"{:.1}\" fill=\"{color}\">{}</text>" // words: HTML markup
            ),
            path.join(" "),
            LEFT + 8.0,
            TOP + 12.0 + 14.0 * k as f64,
            escape(&t.label),
            color = color,
        );
    }
    let _ = write!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text></svg>", // words: HTML markup
        (LEFT + W - RIGHT) / 2.0,
        H - 6.0,
        escape(&tr!("inv-record-svg-seconds", secs = num(x_max, 0)))
    );
    s
}

/// The CSV of every measured number of `done`: one row per number. Its
/// comment lines and labels are in the language in force; its column names
/// and numbers are the same in every language (programs read them).
pub fn csv(done: &[Progress], info: &RecordInfo) -> String {
    let mut out = tr("inv-record-csv-title");
    out.push('\n');
    let _ = writeln!(out, "# {}", byline(info).replace('\n', " "));
    for p in done {
        if let Some(link) = p.rerun_link(&info.page) {
            let _ = writeln!(
                out,
                "{}",
                tr!(
                    "inv-record-csv-run",
                    id = p.investigation.id,
                    seeds = seeds_text(p),
                    link = link
                )
            );
        }
        if let Some(pred) = p.prediction {
            let _ = writeln!(
                out,
                "{}",
                tr!(
                    "inv-record-csv-predicted",
                    id = p.investigation.id,
                    prediction = p.answer_text(pred.choice).replace('\n', " ")
                )
            );
        }
    }
    out.push_str("investigation,label,value,unit\n"); // words: the CSV's column names, read by programs
    for p in done {
        if let Some(outcome) = &p.outcome {
            outcome.localized().csv_lines(p.investigation.id, &mut out);
        }
    }
    out
}

/// A name made safe for a file name on every system: ASCII letters and digits
/// in lower case, accents dropped from their letters (é → e, ñ → n), anything
/// else a single dash, no dash at either end, at most 40 characters. Empty
/// when nothing of the name is left.
pub fn slug(name: &str) -> String {
    let mut out = String::new();
    for c in name.chars().flat_map(fold_accent) {
        if c.is_ascii_alphanumeric() {
            if out.len() >= 40 {
                break;
            }
            out.push(c.to_ascii_lowercase());
        } else if !out.is_empty() && !out.ends_with('-') {
            out.push('-');
        }
    }
    out.trim_end_matches('-').to_owned()
}

/// A letter without its accent (the Latin letters of the catalogue's
/// languages and their neighbours); other characters as they are.
fn fold_accent(c: char) -> Vec<char> {
    let plain = match c {
        'á' | 'à' | 'â' | 'ä' | 'ã' | 'å' | 'ā' => 'a',
        'Á' | 'À' | 'Â' | 'Ä' | 'Ã' | 'Å' | 'Ā' => 'A',
        'é' | 'è' | 'ê' | 'ë' | 'ē' => 'e',
        'É' | 'È' | 'Ê' | 'Ë' | 'Ē' => 'E',
        'í' | 'ì' | 'î' | 'ï' | 'ī' => 'i',
        'Í' | 'Ì' | 'Î' | 'Ï' | 'Ī' => 'I',
        'ó' | 'ò' | 'ô' | 'ö' | 'õ' | 'ø' | 'ō' => 'o',
        'Ó' | 'Ò' | 'Ô' | 'Ö' | 'Õ' | 'Ø' | 'Ō' => 'O',
        'ú' | 'ù' | 'û' | 'ü' | 'ū' => 'u',
        'Ú' | 'Ù' | 'Û' | 'Ü' | 'Ū' => 'U',
        'ñ' => 'n',
        'Ñ' => 'N',
        'ç' => 'c',
        'Ç' => 'C',
        'ý' | 'ÿ' => 'y',
        'Ý' => 'Y',
        'ß' => return vec!['s', 's'],
        'æ' => return vec!['a', 'e'],
        'Æ' => return vec!['A', 'E'],
        other => other,
    };
    vec![plain]
}

/// The record's file name: `shoal-<investigation>-<name>-<date>.<ext>`; the
/// investigation is the one `done` holds (`investigations` when it holds
/// several), the name is [`slug`]ged (left out when empty).
pub fn file_name(done: &[Progress], info: &RecordInfo, ext: &str) -> String {
    let what = match done {
        [one] => one.investigation.id,
        _ => "investigations", // words: a file name's part, the same in every language
    };
    let mut parts = vec!["shoal".to_owned(), what.to_owned()];
    let name = slug(&info.student);
    if !name.is_empty() {
        parts.push(name);
    }
    let date = slug(&info.date);
    if !date.is_empty() {
        parts.push(date);
    }
    format!("{}.{ext}", parts.join("-"))
}

/// The local date and time now: `("2026-11-28", "14:05")` (the browser's
/// clock and time zone; natively the system clock in UTC).
pub fn local_now() -> (String, String) {
    #[cfg(target_arch = "wasm32")]
    {
        let d = js_sys::Date::new_0();
        (
            format!(
                "{:04}-{:02}-{:02}",
                d.get_full_year(),
                d.get_month() + 1,
                d.get_date()
            ),
            format!("{:02}:{:02}", d.get_hours(), d.get_minutes()),
        )
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let secs = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_secs());
        let (y, m, d) = civil_from_days((secs / 86_400) as i64);
        let s = secs % 86_400;
        (
            format!("{y:04}-{m:02}-{d:02}"),
            format!("{:02}:{:02}", s / 3600, (s / 60) % 60),
        )
    }
}

/// The date of day `days` since 1970-01-01 (Howard Hinnant's algorithm).
#[cfg(not(target_arch = "wasm32"))]
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}
