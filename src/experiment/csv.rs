//! An experiment's tidy CSV, and the merge of shard files.
//!
//! The file starts with `#` lines carrying the design (the whole experiment file
//! on one line, the base settings' share link, the run count), then one header
//! line and one row per run × measure (× sample, for series):
//!
//! `run,seed,<each factor's key>,measure,summary,time_s,value,<every setting of
//! the scene>`
//!
//! `time_s` is the sample's simulated time for series rows and empty otherwise;
//! the settings columns (the scene and its own section, `left.*` in the boid
//! scenes) hold the run's exact settings, so any row can be filtered or
//! plotted without the design. Rows come in run order and the numbers are
//! written the same way on every machine, so the file of an experiment is the
//! same bytes whether one core or sixty-four ran it, in one piece or merged from
//! shards. A shard's file (or a cancelled experiment's) has the same lines with
//! its own runs only, and says so in a `# shard:` or `# completed:` line.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

use serde_json::Value;

use crate::experiment::design::{Plan, Summary, settings_value};
use crate::experiment::runner::RunResult;
use crate::i18n::{Lang, with_lang};

/// The first line of every experiment CSV.
const FIRST_LINE_PREFIX: &str = "# Shoal experiment: ";
/// The line that holds the run count (read by the merge).
const RUNS_LINE_PREFIX: &str = "# runs: ";
/// Lines of a shard's or a cancelled experiment's file that the full file lacks.
const SHARD_LINE_PREFIX: &str = "# shard: ";
const COMPLETED_LINE_PREFIX: &str = "# completed: ";

/// The CSV of `results` (any order; written in run order). `shard` (`i`, `n`)
/// marks a shard's file; a file with fewer runs than the plan says how many it
/// holds. English in every language of the interface, like the scene's CSV
/// (programs read its column names; the scene's name in it is English too).
pub fn experiment_csv(plan: &Plan, results: &[RunResult], shard: Option<(usize, usize)>) -> String {
    with_lang(Lang::En, || english_experiment_csv(plan, results, shard))
}

fn english_experiment_csv(
    plan: &Plan,
    results: &[RunResult],
    shard: Option<(usize, usize)>,
) -> String {
    let mut out = header_lines(plan);
    let total = plan.run_count();
    if let Some((i, n)) = shard {
        let _ = writeln!(
            out,
            "{SHARD_LINE_PREFIX}{i}/{n} (runs {i}, {}, … every {n}th; merge the shards with shoal-lab merge)", // words: a CSV comment line, English like the whole file
            i + n
        );
    } else if results.len() < total {
        let _ = writeln!(
            out,
            "{COMPLETED_LINE_PREFIX}{} of {total} runs (cancelled or unfinished)", // words: a CSV comment line, English like the whole file
            results.len()
        );
    }
    out.push_str(&column_line(plan));
    let mut sorted: Vec<&RunResult> = results.iter().collect();
    sorted.sort_by_key(|r| r.index);
    for result in sorted {
        write_rows(plan, result, &mut out);
    }
    out
}

/// The `#` lines every file of the experiment shares.
fn header_lines(plan: &Plan) -> String {
    let mut out = String::new();
    let design = &plan.design;
    let scene = plan.base.scene;
    let _ = writeln!(out, "{FIRST_LINE_PREFIX}{}", one_line(&design.name));
    if !design.description.is_empty() {
        let _ = writeln!(out, "# {}", one_line(&design.description));
    }
    let _ = writeln!(out, "# design: {}", design.to_json_line());
    let _ = writeln!(
        out,
        "# base settings link: #{} (before each run's levels and seed)",
        crate::settings::share_link::encode(&plan.base)
    );
    let mut shape: Vec<String> = plan
        .factors
        .iter()
        .map(|f| format!("{} levels of {}", f.levels.len(), f.key)) // words: in a CSV comment line, English like the whole file
        .collect();
    shape.push(format!("{} seeds", plan.seeds.len()));
    let _ = writeln!(
        out,
        "{RUNS_LINE_PREFIX}{} ({}), each {} warm-up steps + {} measured steps of {:.4} s in the {} ({})", // words: a CSV comment line, English like the whole file
        plan.run_count(),
        shape.join(" × "),
        plan.warmup_steps,
        plan.measure_steps,
        plan.dt_secs,
        scene.class().facts().label(),
        scene.name()
    );
    let _ = writeln!(
        out,
        "# one row per run and measure: summary is mean (over the measuring window's samples, every {:.3} s), \
final (the last sample) or series (one row per sample, at time_s); counters (catches, food_eaten, spawnings, \
missed_strikes, fish_collisions) count from the start of the window",
        plan.sample_every_steps as f64 * plan.dt_secs
    );
    out
}

/// Commas and line breaks in a name would break the `#` line: never.
fn one_line(text: &str) -> String {
    text.replace(['\n', '\r'], " ")
}

/// The setting columns of `plan`'s runs: the scene, then every leaf of the
/// scene's section in alphabetical order (`left.avoidance`, `left.cohesion`,
/// …); not the seed (its own column) nor the factors (theirs).
fn setting_columns(plan: &Plan) -> Vec<String> {
    let value = settings_value(&plan.base);
    let section = plan.base.scene.class().facts().settings_section;
    let mut keys = vec!["scene".to_owned()];
    if let Some(inner) = value.get(section) {
        flatten_keys(section, inner, &mut keys);
    }
    keys.retain(|k| !plan.factors.iter().any(|f| &f.key == k));
    keys
}

fn flatten_keys(prefix: &str, value: &Value, out: &mut Vec<String>) {
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                flatten_keys(&format!("{prefix}.{k}"), v, out);
            }
        }
        _ => out.push(prefix.to_owned()),
    }
}

fn column_line(plan: &Plan) -> String {
    let mut columns = vec!["run".to_owned(), "seed".to_owned()];
    columns.extend(plan.factors.iter().map(|f| f.key.clone()));
    for c in ["measure", "summary", "time_s", "value"] {
        columns.push(c.to_owned());
    }
    columns.extend(setting_columns(plan));
    let mut line = columns
        .iter()
        .map(|c| field(c))
        .collect::<Vec<_>>()
        .join(",");
    line.push('\n');
    line
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
fn field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// A setting's or level's value as a CSV field: numbers as JSON writes them,
/// names without quotes, nothing for "not set".
fn value_field(value: &Value) -> String {
    match value {
        Value::Null => String::new(),
        Value::String(s) => field(s),
        other => field(&other.to_string()),
    }
}

/// A measured value: integers as integers (counts), others to 6 decimals;
/// nothing for a missing one.
fn number(x: f64) -> String {
    if !x.is_finite() {
        String::new()
    } else if x.fract() == 0.0 && x.abs() < 1e15 {
        format!("{}", x as i64)
    } else {
        format!("{x:.6}")
    }
}

fn write_rows(plan: &Plan, result: &RunResult, out: &mut String) {
    let spec = crate::experiment::design::RunSpec {
        index: result.index,
        levels: result.levels.clone(),
        seed: result.seed,
    };
    let settings = settings_value(&plan.settings_for(&spec));
    let mut tail = String::new();
    for key in setting_columns(plan) {
        tail.push(',');
        let v = crate::experiment::design::value_at(&settings, &key).unwrap_or(&Value::Null);
        tail.push_str(&value_field(v));
    }
    let mut head = format!("{},{}", result.index, result.seed);
    for level in &result.levels {
        head.push(',');
        head.push_str(&value_field(level));
    }
    for (m, &(measure, summary)) in plan.measures.iter().enumerate() {
        let name = measure.name();
        match summary {
            Summary::Mean | Summary::Final => {
                let v = if summary == Summary::Mean {
                    result.mean(m)
                } else {
                    result.last(m)
                };
                let _ = writeln!(out, "{head},{name},{},,{}{tail}", summary.name(), number(v));
            }
            Summary::Series => {
                for (t, v) in result.times_secs.iter().zip(&result.values[m]) {
                    let _ = writeln!(out, "{head},{name},series,{t:.3},{}{tail}", number(*v));
                }
            }
        }
    }
}

/// Why shard files could not be merged (`shoal-lab merge`'s errors, English
/// like the command line's reports and the files themselves).
#[derive(Clone, Debug, PartialEq)]
pub enum MergeError {
    NotAnExperiment {
        file: String,
    },
    DifferentExperiment {
        file: String,
        first: String,
    },
    BadRow {
        file: String,
        line: usize,
        reason: String,
    },
    Duplicate {
        runs: String,
        files: String,
    },
    Missing {
        runs: String,
        missing: usize,
        total: usize,
    },
    NoFiles,
}

impl std::fmt::Display for MergeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NotAnExperiment { file } => write!(
                f,
                "{file}: not a Shoal experiment CSV (it must start with '{FIRST_LINE_PREFIX}')" // words: shoal-lab merge's error
            ),
            Self::DifferentExperiment { file, first } => write!(
                f,
                "{file}: a different experiment from {first} (their '#' lines or columns differ)" // words: shoal-lab merge's error
            ),
            Self::BadRow { file, line, reason } => write!(f, "{file}, line {line}: {reason}"),
            Self::Duplicate { runs, files } => write!(
                f,
                "run(s) {runs} appear in more than one file ({files})" // words: shoal-lab merge's error
            ),
            Self::Missing {
                runs,
                missing,
                total,
            } => write!(
                f,
                "run(s) {runs} are in no file ({missing} of {total} runs missing)" // words: shoal-lab merge's error
            ),
            Self::NoFiles => f.write_str("no files to merge"), // words: shoal-lab merge's error
        }
    }
}

impl std::error::Error for MergeError {}

/// "3, 7, 12" (the first 20, then "… and 14 more").
fn list_runs(runs: &[usize]) -> String {
    let mut text = runs
        .iter()
        .take(20)
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    if runs.len() > 20 {
        let _ = write!(text, " … and {} more", runs.len() - 20); // words: shoal-lab merge's error
    }
    text
}

/// One file split: its shared lines (header and columns), its rows by run.
struct Parsed<'a> {
    shared: Vec<&'a str>,
    total: usize,
    rows: BTreeMap<usize, Vec<&'a str>>,
}

fn parse<'a>(name: &str, text: &'a str) -> Result<Parsed<'a>, MergeError> {
    if !text.starts_with(FIRST_LINE_PREFIX) {
        return Err(MergeError::NotAnExperiment { file: name.into() });
    }
    let mut shared = Vec::new();
    let mut total = None;
    let mut rows: BTreeMap<usize, Vec<&str>> = BTreeMap::new();
    let mut columns_seen = false;
    for (n, line) in text.split_inclusive('\n').enumerate() {
        if !columns_seen {
            if line.starts_with(SHARD_LINE_PREFIX) || line.starts_with(COMPLETED_LINE_PREFIX) {
                continue;
            }
            if let Some(rest) = line.strip_prefix(RUNS_LINE_PREFIX) {
                total = rest
                    .split(' ')
                    .next()
                    .and_then(|count| count.parse::<usize>().ok());
            }
            shared.push(line);
            columns_seen = !line.starts_with('#');
            continue;
        }
        let run = line
            .split(',')
            .next()
            .and_then(|r| r.parse::<usize>().ok())
            .ok_or_else(|| MergeError::BadRow {
                file: name.into(),
                line: n + 1,
                reason: "a row starts with its run index".into(), // words: shoal-lab merge's error
            })?;
        rows.entry(run).or_default().push(line);
    }
    let total = total.ok_or_else(|| MergeError::NotAnExperiment { file: name.into() })?;
    if !columns_seen {
        return Err(MergeError::NotAnExperiment { file: name.into() });
    }
    Ok(Parsed {
        shared,
        total,
        rows,
    })
}

/// Merges the CSVs of an experiment's shards (`(file name, text)`, any order)
/// into the file one machine would have written, byte for byte. Refuses files of
/// different experiments, a run in two files and a run in none, naming them.
pub fn merge_csv(files: &[(String, String)]) -> Result<String, MergeError> {
    let Some((first_name, _)) = files.first() else {
        return Err(MergeError::NoFiles);
    };
    let parsed = files
        .iter()
        .map(|(name, text)| parse(name, text))
        .collect::<Result<Vec<_>, _>>()?;
    let reference = &parsed[0];
    for (p, (name, _)) in parsed.iter().zip(files).skip(1) {
        if p.shared != reference.shared || p.total != reference.total {
            return Err(MergeError::DifferentExperiment {
                file: name.clone(),
                first: first_name.clone(),
            });
        }
    }
    let mut owner: BTreeMap<usize, usize> = BTreeMap::new();
    let mut duplicates = BTreeSet::new();
    let mut duplicate_files = BTreeSet::new();
    for (f, p) in parsed.iter().enumerate() {
        for &run in p.rows.keys() {
            if let Some(&other) = owner.get(&run) {
                duplicates.insert(run);
                duplicate_files.insert(files[other].0.clone());
                duplicate_files.insert(files[f].0.clone());
            } else {
                owner.insert(run, f);
            }
        }
    }
    if !duplicates.is_empty() {
        return Err(MergeError::Duplicate {
            runs: list_runs(&duplicates.into_iter().collect::<Vec<_>>()),
            files: duplicate_files.into_iter().collect::<Vec<_>>().join(", "),
        });
    }
    let total = reference.total;
    let missing: Vec<usize> = (0..total).filter(|r| !owner.contains_key(r)).collect();
    let beyond: Vec<usize> = owner.keys().copied().filter(|&r| r >= total).collect();
    if let Some(&run) = beyond.first() {
        return Err(MergeError::BadRow {
            file: files[owner[&run]].0.clone(),
            line: 0,
            reason: format!("run {run} is beyond the experiment's {total} runs"), // words: shoal-lab merge's error
        });
    }
    if !missing.is_empty() {
        return Err(MergeError::Missing {
            runs: list_runs(&missing),
            missing: missing.len(),
            total,
        });
    }
    let mut out: String = reference.shared.concat();
    for (run, f) in owner {
        for line in &parsed[f].rows[&run] {
            out.push_str(line);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;
    use crate::experiment::design::Design;
    use crate::experiment::runner::ExperimentRun;

    #[test]
    fn the_csv_is_the_same_in_every_language_of_the_interface() {
        let design = json!({
            "name": "tiny",
            "settings": {"scene": "boids", "left": {"fish_count": 12}},
            "factors": [{"key": "left.alignment", "levels": [20.5, 60]}],
            "replicates": {"count": 2, "first_seed": 5},
            "warmup_secs": 0.5,
            "measure_secs": 1.0,
            "measures": [{"measure": "polarization"}]
        });
        let plan = Design::from_json(&design.to_string())
            .and_then(|d| d.validate())
            .expect("a valid design");
        let results: Vec<RunResult> = plan
            .runs()
            .iter()
            .map(|spec| ExperimentRun::new(&plan, spec).run_to_end())
            .collect();
        let english = with_lang(Lang::En, || experiment_csv(&plan, &results, None));
        for lang in Lang::ALL {
            let csv = with_lang(lang, || experiment_csv(&plan, &results, None));
            assert_eq!(csv, english, "{}", lang.code());
            let shard = with_lang(lang, || experiment_csv(&plan, &results[..1], Some((0, 4))));
            assert_eq!(
                shard,
                with_lang(Lang::En, || experiment_csv(
                    &plan,
                    &results[..1],
                    Some((0, 4))
                ))
            );
        }
        assert!(english.contains("warm-up steps"), "{english}");
        assert!(
            english.contains("\n0,5,20.5,polarization,mean,,"),
            "{english}"
        );
    }
}
