//! The experiment file and its validation.
//!
//! A [`Design`] is what a student writes (or the browser panel fills in): base
//! settings, one or two factors (settings named by the keys `shoal.set()`, share
//! links and the CSV use, such as `left.alignment`), replicates (seeds), a
//! warm-up and a measuring time, and the measures. [`Design::validate`] turns it
//! into a [`Plan`], refusing with a [`DesignError`] that names the field; the
//! plan enumerates the runs in a fixed order, so a run index means the same run
//! on every machine, in every shard and in the browser.

use serde::{Deserialize, Serialize};
use serde_json::Value;

pub use crate::experiment::measure::{Measure, Summary};
use crate::i18n::{localize_decimal, num};
use crate::settings::{Scene, Settings, SettingsError};
use crate::tr;

/// Most runs in one experiment. Default 10,000: a day of a 64-core node at a few
/// seconds per run, and a CSV a spreadsheet still opens.
pub const MAX_RUNS: usize = 10_000;
/// Most levels of one factor. Default 1,000.
pub const MAX_LEVELS: usize = 1_000;
/// Most factors. Two: a dose–response curve, or a family of them.
pub const MAX_FACTORS: usize = 2;
/// Longest warm-up or measuring time, simulated seconds. Default 36,000 (ten
/// hours), far beyond what a lesson or a sweep needs.
pub const MAX_SECS: f64 = 36_000.0;

/// Why a design was refused: the field (`factors[0].levels[2]`,
/// `replicates.count`, `measures[1].measure`) and a sentence a student reads.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DesignError {
    pub field: String,
    pub reason: String,
}

impl std::fmt::Display for DesignError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&tr!(
            "experiment-error",
            field = self.field.as_str(),
            reason = self.reason.as_str()
        ))
    }
}

impl std::error::Error for DesignError {}

impl DesignError {
    fn new(field: impl Into<String>, reason: impl Into<String>) -> Self {
        Self {
            field: field.into(),
            reason: reason.into(),
        }
    }
}

/// An experiment file, as written. Field by field in `docs/experiments.md`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Design {
    /// A short name, for the CSV's first line and the file names.
    #[serde(default)]
    pub name: String,
    /// What the experiment asks, in a sentence.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub description: String,
    /// A share link (the whole address or the fragment after `#`): the base
    /// settings. Applied first.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub link: Option<String>,
    /// Settings as `shoal.set()` takes them (a full settings object or only the
    /// changes), applied over the link's settings (or the defaults).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub settings: Option<Value>,
    /// Zero, one or two settings to vary.
    #[serde(default)]
    pub factors: Vec<Factor>,
    pub replicates: Replicates,
    /// Simulated seconds before measuring (the school forms).
    pub warmup_secs: f64,
    /// Simulated seconds measured after the warm-up.
    pub measure_secs: f64,
    pub measures: Vec<MeasureChoice>,
}

/// One setting to vary.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Factor {
    /// The setting's key, as `shoal.set()` and share links name it
    /// (`left.alignment`, `reef.prey_count`).
    pub key: String,
    /// A list (`[0, 25, 50]`, `[false, true]`) or a range
    /// (`{"from": 0, "to": 100, "steps": 5}`: five evenly spaced values, both
    /// ends included).
    pub levels: Value,
}

/// The seeds: `count` seeds from `first_seed` (1 when absent), or a list.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Replicates {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub count: Option<u32>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_seed: Option<u64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seeds: Option<Vec<u64>>,
}

/// One measure and how a run's values over the measuring window become numbers.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeasureChoice {
    /// A [`Measure`] name (`polarization`, `catches`, …).
    pub measure: String,
    /// `mean` (default), `final` or `series`.
    #[serde(default = "default_summary")]
    pub summary: String,
}

fn default_summary() -> String {
    Summary::Mean.name().to_owned()
}

/// One run of an experiment: its place in the fixed order, its factor levels
/// (in the order of the design's factors) and its seed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RunSpec {
    pub index: usize,
    pub levels: Vec<Value>,
    pub seed: u64,
}

/// A factor after validation: its key and levels, each a value the setting
/// takes (an integer, a number or a boolean).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlannedFactor {
    pub key: String,
    pub levels: Vec<Value>,
}

/// A validated design: everything a run needs, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    pub design: Design,
    /// The settings every run starts from, before its levels and seed (one tank,
    /// not paused).
    pub base: Settings,
    pub factors: Vec<PlannedFactor>,
    pub seeds: Vec<u64>,
    pub measures: Vec<(Measure, Summary)>,
    /// One step of the scene, seconds.
    pub dt_secs: f64,
    pub warmup_steps: u64,
    pub measure_steps: u64,
    /// Steps between two metrics samples (the lab's, the plots').
    pub sample_every_steps: u64,
}

/// How long a plan takes, for the panel's "about 3 minutes" and the cluster's
/// time limit.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Estimate {
    pub runs: usize,
    pub steps_per_run: u64,
    /// Steps of every run together.
    pub total_steps: u64,
    /// Σ over runs of steps × animals: what the time is proportional to within
    /// a scene.
    pub animal_steps: f64,
    /// Seconds on one native core at the rates measured for
    /// `docs/benchmarks.md` (a browser is about two to three times slower).
    pub secs_one_core: f64,
}

impl Design {
    /// Reads an experiment file. A JSON error names the line and column (and the
    /// field, for an unknown or missing one).
    pub fn from_json(text: &str) -> Result<Self, DesignError> {
        serde_json::from_str(text).map_err(|err| {
            let message = err.to_string();
            // serde names an unknown or missing field between backquotes.
            let field = ["unknown field `", "missing field `"] // words: serde's words, matched
                .iter()
                .find_map(|start| message.strip_prefix(start)?.split('`').next())
                .map_or_else(
                    || {
                        tr!(
                            "experiment-error-json-place",
                            line = err.line(),
                            column = err.column()
                        )
                    },
                    str::to_owned,
                );
            DesignError::new(field, message)
        })
    }

    /// The JSON of the design on one line, as the CSV's `# design:` line holds it.
    pub fn to_json_line(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|_| "{}".to_owned())
    }

    /// Checks everything and builds the plan. The first problem found is
    /// returned, with its field.
    pub fn validate(&self) -> Result<Plan, DesignError> {
        let base = self.base_settings()?;
        let scene = base.scene;
        if self.factors.len() > MAX_FACTORS {
            return Err(DesignError::new(
                "factors",
                tr!(
                    "experiment-error-too-many-factors",
                    count = self.factors.len(),
                    max = MAX_FACTORS
                ),
            ));
        }
        let base_value = settings_value(&base);
        let mut factors: Vec<PlannedFactor> = Vec::new();
        for (i, factor) in self.factors.iter().enumerate() {
            let planned = plan_factor(i, factor, &base, &base_value)?;
            if factors.iter().any(|f| f.key == planned.key) {
                return Err(DesignError::new(
                    format!("factors[{i}].key"),
                    tr!("experiment-error-factor-twice", key = planned.key.as_str()),
                ));
            }
            factors.push(planned);
        }
        let seeds = self.seeds()?;
        let measures = self.measures(scene)?;
        let dt_secs = scene.class().facts().clock.step_secs;
        let warmup_steps = steps_of("warmup_secs", self.warmup_secs, dt_secs, true)?;
        let measure_steps = steps_of("measure_secs", self.measure_secs, dt_secs, false)?;
        let sample_every_steps = scene.class().facts().clock.sample_every_steps;
        let first_sample = (warmup_steps / sample_every_steps + 1) * sample_every_steps;
        if first_sample > warmup_steps + measure_steps {
            return Err(DesignError::new(
                "measure_secs",
                tr!(
                    "experiment-error-no-sample",
                    secs = self.measure_secs,
                    min = num(sample_every_steps as f64 * dt_secs, 3)
                ),
            ));
        }
        let runs = factors
            .iter()
            .map(|f| f.levels.len())
            .product::<usize>()
            .saturating_mul(seeds.len());
        if runs > MAX_RUNS {
            return Err(DesignError::new(
                "factors",
                // As written (10000), like the file's numbers.
                tr!(
                    "experiment-error-too-many-runs",
                    runs = runs.to_string(),
                    max = MAX_RUNS.to_string()
                ),
            ));
        }
        Ok(Plan {
            design: self.clone(),
            base,
            factors,
            seeds,
            measures,
            dt_secs,
            warmup_steps,
            measure_steps,
            sample_every_steps,
        })
    }

    /// The link's settings (or the defaults), then `settings` over them; one
    /// tank, running.
    fn base_settings(&self) -> Result<Settings, DesignError> {
        let mut settings = match &self.link {
            Some(link) => {
                let fragment = link.rsplit_once('#').map_or(link.as_str(), |(_, f)| f);
                crate::settings::share_link::decode(fragment)
                    .map_err(|err| DesignError::new("link", err.to_string()))?
                    .ok_or_else(|| DesignError::new("link", tr!("experiment-error-link-empty")))?
            }
            None => Settings::default(),
        };
        if let Some(patch) = &self.settings {
            settings
                .apply_patch(patch)
                .map_err(|err| settings_error("settings", &err))?;
        }
        // An experiment measures one tank (the left one); nothing waits.
        settings.compare = false;
        settings.paused = false;
        Ok(settings)
    }

    fn seeds(&self) -> Result<Vec<u64>, DesignError> {
        let r = &self.replicates;
        let seeds = match (&r.seeds, r.count) {
            (Some(_), Some(_)) => {
                return Err(DesignError::new(
                    "replicates",
                    tr!("experiment-error-seeds-and-count"),
                ));
            }
            (Some(seeds), None) => {
                if r.first_seed.is_some() {
                    return Err(DesignError::new(
                        "replicates.first_seed",
                        tr!("experiment-error-first-seed-with-list"),
                    ));
                }
                seeds.clone()
            }
            (None, Some(count)) => {
                // Refused before counting: a damaged count (four billion) would
                // fill the memory first.
                if count as usize > MAX_RUNS {
                    return Err(DesignError::new(
                        "replicates.count",
                        tr!(
                            "experiment-error-too-many-seeds",
                            count = count.to_string(),
                            max = MAX_RUNS.to_string()
                        ),
                    ));
                }
                // Saturating: a first seed near 2^64 is refused below as out of
                // range, not overflowed.
                let first = r.first_seed.unwrap_or(1);
                (0..u64::from(count))
                    .map(|k| first.saturating_add(k))
                    .collect()
            }
            (None, None) => {
                return Err(DesignError::new(
                    "replicates",
                    tr!("experiment-error-how-many-seeds"),
                ));
            }
        };
        let field = if r.seeds.is_some() {
            "replicates.seeds"
        } else {
            "replicates.count"
        };
        if seeds.is_empty() {
            return Err(DesignError::new(
                field,
                tr!("experiment-error-no-replicates"),
            ));
        }
        if seeds.len() > MAX_RUNS {
            return Err(DesignError::new(
                field,
                tr!(
                    "experiment-error-too-many-seeds",
                    count = seeds.len().to_string(),
                    max = MAX_RUNS.to_string()
                ),
            ));
        }
        for (k, &seed) in seeds.iter().enumerate() {
            if seed > crate::settings::SEED_MAX {
                let field = if r.seeds.is_some() {
                    format!("replicates.seeds[{k}]")
                } else {
                    "replicates.first_seed".to_owned()
                };
                return Err(DesignError::new(
                    field,
                    tr!(
                        "experiment-error-seed-range",
                        seed = seed.to_string(),
                        max = crate::settings::SEED_MAX.to_string()
                    ),
                ));
            }
            if seeds[..k].contains(&seed) {
                return Err(DesignError::new(
                    format!("replicates.seeds[{k}]"),
                    tr!("experiment-error-seed-twice", seed = seed.to_string()),
                ));
            }
        }
        Ok(seeds)
    }

    fn measures(&self, scene: Scene) -> Result<Vec<(Measure, Summary)>, DesignError> {
        if self.measures.is_empty() {
            return Err(DesignError::new(
                "measures",
                tr!("experiment-error-no-measures"),
            ));
        }
        let mut out: Vec<(Measure, Summary)> = Vec::new();
        for (i, choice) in self.measures.iter().enumerate() {
            let Some(measure) = Measure::from_name(&choice.measure) else {
                let known: Vec<&str> = Measure::ALL.iter().map(|m| m.name()).collect();
                return Err(DesignError::new(
                    format!("measures[{i}].measure"),
                    tr!(
                        "experiment-error-unknown-measure",
                        name = choice.measure.as_str(),
                        known = known.join(", ")
                    ),
                ));
            };
            if !measure.available_in(scene) {
                let known: Vec<&str> = Measure::ALL
                    .iter()
                    .filter(|m| m.available_in(scene))
                    .map(|m| m.name())
                    .collect();
                return Err(DesignError::new(
                    format!("measures[{i}].measure"),
                    tr!(
                        "experiment-error-measure-not-here",
                        name = measure.name(),
                        scene = scene.class().facts().label(),
                        id = scene.name(),
                        known = if known.is_empty() {
                            tr!("experiment-error-nothing")
                        } else {
                            known.join(", ")
                        }
                    ),
                ));
            }
            let Some(summary) = Summary::from_name(&choice.summary) else {
                return Err(DesignError::new(
                    format!("measures[{i}].summary"),
                    tr!(
                        "experiment-error-unknown-summary",
                        name = choice.summary.as_str()
                    ),
                ));
            };
            if out.contains(&(measure, summary)) {
                return Err(DesignError::new(
                    format!("measures[{i}]"),
                    tr!(
                        "experiment-error-measured-twice",
                        name = measure.name(),
                        summary = summary.name()
                    ),
                ));
            }
            out.push((measure, summary));
        }
        Ok(out)
    }
}

/// A settings error under `field` (`settings.left.alignment`).
fn settings_error(field: &str, err: &SettingsError) -> DesignError {
    match err {
        SettingsError::Invalid(e) if e.key != "?" => {
            DesignError::new(format!("{field}.{}", e.key), e.reason.clone())
        }
        SettingsError::UnknownKey { key, known } => DesignError::new(
            format!("{field}.{key}"),
            tr!(
                "experiment-error-unknown-setting-there",
                known = known.as_str()
            ),
        ),
        other => DesignError::new(field, other.to_string()),
    }
}

/// The settings as plain JSON, with `f32`s written as they read (0.1, not
/// 0.10000000149011612): serialised to text, then parsed.
pub fn settings_value(settings: &Settings) -> Value {
    serde_json::to_string(settings)
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or(Value::Null)
}

/// The value at a dotted key (`left.alignment`) of a JSON object.
pub fn value_at<'a>(root: &'a Value, key: &str) -> Option<&'a Value> {
    key.split('.').try_fold(root, |v, k| v.as_object()?.get(k))
}

/// `{"left": {"alignment": value}}` for the key `left.alignment`.
pub fn patch_for(key: &str, value: Value) -> Value {
    key.rsplit('.').fold(value, |inner, k| {
        let mut map = serde_json::Map::new();
        map.insert(k.to_owned(), inner);
        Value::Object(map)
    })
}

/// Why a factor on `key` would change nothing in `scene`, if it would not.
fn inert_reason(key: &str, scene: Scene) -> Option<String> {
    let section = scene.class().facts().settings_section;
    match key {
        "seed" => return Some(tr!("experiment-error-seed-factor")),
        "speed" | "paused" | "show_vision" | "compare" => {
            return Some(tr!("experiment-error-display-only", key = key));
        }
        _ if key.ends_with(".selected") || key.ends_with(".follow") => {
            return Some(tr!("experiment-error-selection", key = key));
        }
        _ => {}
    }
    (!scene.class().acts(key)).then(|| {
        tr!(
            "experiment-error-does-not-act",
            key = key,
            scene = scene.class().facts().label(),
            id = scene.name(),
            section = section
        )
    })
}

fn plan_factor(
    i: usize,
    factor: &Factor,
    base: &Settings,
    base_value: &Value,
) -> Result<PlannedFactor, DesignError> {
    let key_field = format!("factors[{i}].key");
    let current = match value_at(base_value, &factor.key) {
        Some(v) => v,
        None => {
            // apply_patch names the unknown part and lists its neighbours.
            let err = base
                .clone()
                .apply_patch(&patch_for(&factor.key, Value::Null))
                .err()
                .map_or_else(
                    || tr!("experiment-error-unknown-setting"),
                    |e| e.to_string(),
                );
            return Err(DesignError::new(key_field, err));
        }
    };
    let (is_bool, is_float) = match current {
        Value::Bool(_) => (true, false),
        Value::Number(n) => (false, n.is_f64()),
        // An optional count or number that is not set (the reef's prey count).
        Value::Null => (false, false),
        _ => {
            return Err(DesignError::new(
                key_field,
                tr!("experiment-error-not-a-slider", key = factor.key.as_str()),
            ));
        }
    };
    if let Some(reason) = inert_reason(&factor.key, base.scene) {
        return Err(DesignError::new(key_field, reason));
    }
    let levels_field = format!("factors[{i}].levels");
    let raw = raw_levels(&levels_field, &factor.levels)?;
    if raw.is_empty() {
        return Err(DesignError::new(
            levels_field,
            tr!("experiment-error-no-levels"),
        ));
    }
    if raw.len() > MAX_LEVELS {
        return Err(DesignError::new(
            levels_field,
            tr!(
                "experiment-error-too-many-levels",
                count = raw.len().to_string(),
                max = MAX_LEVELS.to_string()
            ),
        ));
    }
    let mut levels: Vec<Value> = Vec::new();
    for (j, (field, level)) in raw.into_iter().enumerate() {
        let field = field.unwrap_or_else(|| format!("{levels_field}[{j}]"));
        let value = match (&level, is_bool) {
            (Value::Bool(_), true) => level,
            (Value::Number(n), false) => {
                let x = n.as_f64().unwrap_or(f64::NAN);
                if !is_float && x.fract() == 0.0 && (0.0..9.0e15).contains(&x) {
                    Value::from(x as u64)
                } else {
                    level
                }
            }
            _ => {
                return Err(DesignError::new(
                    field,
                    tr!(
                        if is_bool {
                            "experiment-error-level-not-switch"
                        } else {
                            "experiment-error-level-not-number"
                        },
                        level = level.to_string(),
                        key = factor.key.as_str()
                    ),
                ));
            }
        };
        // The settings' own ranges and types decide (the slider's bounds).
        let mut settings = base.clone();
        settings
            .apply_patch(&patch_for(&factor.key, value))
            .map_err(|err| match err {
                SettingsError::Invalid(e) => DesignError::new(field.clone(), e.to_string()),
                other => DesignError::new(field.clone(), other.to_string()),
            })?;
        // The level as the setting holds it (an f32 slider holds 0.1 as 0.1).
        let held = value_at(&settings_value(&settings), &factor.key)
            .cloned()
            .unwrap_or(Value::Null);
        if levels.contains(&held) {
            return Err(DesignError::new(
                field,
                tr!("experiment-error-level-twice", level = held.to_string()),
            ));
        }
        levels.push(held);
    }
    Ok(PlannedFactor {
        key: factor.key.clone(),
        levels,
    })
}

/// The levels as written: a list, or `{from, to, steps}` evenly spaced. Each
/// with the field to name if it is refused (`None`: its place in the list).
fn raw_levels(field: &str, levels: &Value) -> Result<Vec<(Option<String>, Value)>, DesignError> {
    match levels {
        Value::Array(list) => Ok(list.iter().map(|v| (None, v.clone())).collect()),
        Value::Object(map) => {
            for key in map.keys() {
                if !["from", "to", "steps"].contains(&key.as_str()) {
                    return Err(DesignError::new(
                        format!("{field}.{key}"),
                        tr!("experiment-error-range-field"),
                    ));
                }
            }
            let number = |name: &str| {
                map.get(name)
                    .and_then(Value::as_f64)
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| {
                        DesignError::new(
                            format!("{field}.{name}"),
                            tr!("experiment-error-not-a-number"),
                        )
                    })
            };
            let (from, to) = (number("from")?, number("to")?);
            let steps = map.get("steps").and_then(Value::as_u64).ok_or_else(|| {
                DesignError::new(format!("{field}.steps"), tr!("experiment-error-not-whole"))
            })?;
            if steps == 0 {
                return Err(DesignError::new(
                    format!("{field}.steps"),
                    tr!("experiment-error-no-levels"),
                ));
            }
            if steps > MAX_LEVELS as u64 {
                return Err(DesignError::new(
                    format!("{field}.steps"),
                    tr!(
                        "experiment-error-too-many-levels",
                        count = steps.to_string(),
                        max = MAX_LEVELS.to_string()
                    ),
                ));
            }
            if steps == 1 && from != to {
                return Err(DesignError::new(
                    format!("{field}.steps"),
                    tr!("experiment-error-one-step"),
                ));
            }
            Ok((0..steps)
                .map(|k| {
                    let x = if steps == 1 {
                        from
                    } else {
                        from + (to - from) * k as f64 / (steps - 1) as f64
                    };
                    // Round away binary noise (0.30000000000000004) at 12 digits.
                    let x = (x * 1e12).round() / 1e12;
                    (
                        Some(field.to_owned()),
                        serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number),
                    )
                })
                .collect())
        }
        _ => Err(DesignError::new(
            field,
            tr!("experiment-error-levels-shape"),
        )),
    }
}

/// Seconds → whole steps of `dt_secs`, refusing what cannot be run.
fn steps_of(field: &str, secs: f64, dt_secs: f64, zero_ok: bool) -> Result<u64, DesignError> {
    if !secs.is_finite() || !(0.0..=MAX_SECS).contains(&secs) {
        return Err(DesignError::new(
            field,
            tr!(
                "experiment-error-secs-range",
                secs = localize_decimal(&secs.to_string()),
                max = MAX_SECS.to_string()
            ),
        ));
    }
    if !zero_ok && secs == 0.0 {
        return Err(DesignError::new(field, tr!("experiment-error-zero-secs")));
    }
    Ok((secs / dt_secs).round() as u64)
}

impl Plan {
    /// Runs in all: levels of each factor × seeds.
    pub fn run_count(&self) -> usize {
        self.factors
            .iter()
            .map(|f| f.levels.len())
            .product::<usize>()
            * self.seeds.len()
    }

    /// Steps of one run (warm-up and measuring).
    pub fn steps_per_run(&self) -> u64 {
        self.warmup_steps + self.measure_steps
    }

    /// Every run in the fixed order: the first factor's levels outermost, then
    /// the second's, then the seeds. Run `k` is the same run on every machine.
    pub fn runs(&self) -> Vec<RunSpec> {
        let mut combos: Vec<Vec<Value>> = vec![Vec::new()];
        for factor in &self.factors {
            combos = combos
                .into_iter()
                .flat_map(|combo| {
                    factor.levels.iter().map(move |level| {
                        let mut c = combo.clone();
                        c.push(level.clone());
                        c
                    })
                })
                .collect();
        }
        let mut runs = Vec::with_capacity(self.run_count());
        for levels in combos {
            for &seed in &self.seeds {
                runs.push(RunSpec {
                    index: runs.len(),
                    levels: levels.clone(),
                    seed,
                });
            }
        }
        runs
    }

    /// The runs of shard `shard` of `shards` (0-based): every `shards`-th run
    /// from `shard`, so each shard gets every level (the big schools are not
    /// all in the last shard). The shards together hold every run once.
    pub fn runs_for_shard(&self, shard: usize, shards: usize) -> Vec<RunSpec> {
        self.runs()
            .into_iter()
            .filter(|r| shards > 0 && r.index % shards == shard)
            .collect()
    }

    /// The settings of `run`: the base, its levels, its seed.
    pub fn settings_for(&self, run: &RunSpec) -> Settings {
        let mut settings = self.base.clone();
        for (factor, level) in self.factors.iter().zip(&run.levels) {
            // Checked in validate: every level applies.
            if let Err(err) = settings.apply_patch(&patch_for(&factor.key, level.clone())) {
                log::error!("experiment level {level} of {}: {err}", factor.key);
            }
        }
        settings.seed = run.seed;
        settings
    }

    /// How long the plan takes on one native core.
    pub fn estimate(&self) -> Estimate {
        let runs = self.runs();
        let steps_per_run = self.steps_per_run();
        let per_seed = self.seeds.len().max(1);
        // One world per level combination: the animals do not depend on the seed.
        let animal_steps: f64 = runs
            .iter()
            .step_by(per_seed)
            .map(|run| {
                let lab = crate::lab::Lab::new(self.settings_for(run));
                lab.runs()[0].animal_count() as f64 * steps_per_run as f64 * per_seed as f64
            })
            .sum();
        Estimate {
            runs: runs.len(),
            steps_per_run,
            total_steps: steps_per_run * runs.len() as u64,
            animal_steps,
            secs_one_core: animal_steps * self.base.scene.class().facts().secs_per_animal_step,
        }
    }
}

/// The settings of `base`'s scene a factor may vary, as `factors[].key` names
/// them (`left.alignment`, `left.shark`): every number or on/off setting that
/// acts in the scene and that [`Design::validate`] accepts at its current
/// value. The experiment panel's list of factors comes from here, so it never
/// offers what the engine would refuse.
pub fn factor_keys(base: &Settings) -> Vec<String> {
    fn leaves(prefix: &str, value: &Value, out: &mut Vec<(String, Value)>) {
        match value {
            Value::Object(map) => {
                for (k, v) in map {
                    let key = if prefix.is_empty() {
                        k.clone()
                    } else {
                        format!("{prefix}.{k}")
                    };
                    leaves(&key, v, out);
                }
            }
            Value::Bool(_) | Value::Number(_) | Value::Null => {
                out.push((prefix.to_owned(), value.clone()));
            }
            _ => {}
        }
    }
    let base_value = settings_value(base);
    let mut all = Vec::new();
    leaves("", &base_value, &mut all);
    all.into_iter()
        .filter(|(key, _)| inert_reason(key, base.scene).is_none())
        .filter(|(key, current)| {
            // An unset optional setting (null) is offered if it takes a
            // number: its slider's least.
            let level = if current.is_null() {
                crate::settings::names::setting_name(key)
                    .and_then(|n| n.slider)
                    .and_then(|s| serde_json::Number::from_f64(s.min))
                    .map_or(Value::from(1), Value::Number)
            } else {
                current.clone()
            };
            let factor = Factor {
                key: key.clone(),
                levels: Value::Array(vec![level]),
            };
            plan_factor(0, &factor, base, &base_value).is_ok()
        })
        .map(|(key, _)| key)
        .collect()
}

/// The levels a new factor on `key` starts with, as `(from, to, steps)`: the
/// slider's whole range ([`crate::settings::names::Slider`]), or, for a
/// slider over orders of magnitude (the fish count, the annealing steps), a
/// round part of it around `base`'s value (half to twice it, to round
/// numbers), so the runs stay short. A whole-number setting gets levels that
/// are whole: `steps` grows by one or two, or the range ends a little lower,
/// if its steps would fall between two numbers. `None` for a key that is not
/// a number's.
pub fn default_levels(base: &Settings, key: &str, steps: u32) -> Option<(f64, f64, u32)> {
    let slider = crate::settings::names::setting_name(key)?.slider?;
    let (mut from, mut to) = (slider.min, slider.max);
    if slider.wide {
        let current = value_at(&settings_value(base), key)
            .and_then(Value::as_f64)
            .filter(|c| *c > 0.0)
            .unwrap_or_else(|| slider.min.max(1.0));
        from = round_below(current / 2.0).clamp(slider.min, slider.max);
        to = round_above(current * 2.0).clamp(slider.min, slider.max);
        if to <= from {
            (from, to) = (slider.min, slider.max);
        }
    }
    let mut steps = steps.max(1);
    if slider.whole && steps > 1 {
        let span = (to - from).round() as u64;
        let divides = |steps: u32| span.is_multiple_of(u64::from(steps - 1));
        if let Some(more) = (steps..=steps + 2).find(|&k| divides(k)) {
            steps = more;
        } else if span < 6 {
            steps = span as u32 + 1;
        } else {
            to = from + (span - span % u64::from(steps - 1)) as f64;
        }
    }
    Some((from, to, steps))
}

/// Round numbers: 1, 2 and 5 times a power of ten.
fn round_numbers(x: f64) -> impl Iterator<Item = f64> {
    use crate::sim::common::fmath::{log10_f64, powi_f64};
    let start = log10_f64(x.abs().max(1e-9)).floor() as i32 - 1;
    (start..start + 3).flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * powi_f64(10.0, e)))
}

/// The largest round number at or below `x` (`x` > 0).
fn round_below(x: f64) -> f64 {
    round_numbers(x)
        .filter(|&r| r <= x * (1.0 + 1e-9))
        .fold(0.0, f64::max)
}

/// The smallest round number at or above `x` (`x` > 0).
fn round_above(x: f64) -> f64 {
    round_numbers(x)
        .filter(|&r| r >= x * (1.0 - 1e-9))
        .fold(f64::INFINITY, f64::min)
}

/// Is `key` an on/off setting in `base` (its levels are then `false` and `true`)?
pub fn is_switch(base: &Settings, key: &str) -> bool {
    value_at(&settings_value(base), key).is_some_and(Value::is_boolean)
}
