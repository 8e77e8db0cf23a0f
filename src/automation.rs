//! The automation API: what `window.shoal` offers tests and power users.
//!
//! | call | effect |
//! | --- | --- |
//! | `shoal.state()` | a plain object, see [`StateReport`] |
//! | `shoal.settings()` | the current settings, by the names `set` takes |
//! | `shoal.set({name: value, …})` | applies settings by the UI's names (see `settings.rs`); all or nothing |
//! | `shoal.step(n)` | runs `n` simulation steps now (1 ≤ n ≤ 100,000), even while paused |
//! | `shoal.pause()` / `shoal.play()` | stops / resumes the simulation |
//! | `shoal.reset(seed?)` | rebuilds the world, from `seed` when given |
//! | `shoal.turn(deg)` | physics scene: the selected fish starts a turn of `deg` degrees (+ left, −180 to 180) |
//! | `shoal.share_link()` | the link that reopens exactly the current settings |
//! | `shoal.student_link()` | the teacher's studio's *Share with class* link: the same settings in the student view (`settings/studio.rs`) |
//! | `shoal.metrics_csv()` | the school metrics of the last minutes as CSV text (the aquarium's and schooling lab's table, in every scene) |
//! | `shoal.export_csv()` | `{name, text}`: the scene's data file *Download data* saves (see `export.rs`), e.g. `shoal-reef-t0125s.csv` |
//! | `shoal.widgets()` | where the main widgets are on the page, `{name: {x, y, width, height}}` in CSS pixels (for tests that click real widgets) |
//! | `shoal.memory()` | `{wasm_bytes, heap_bytes, js_heap_bytes}`: the module's memory (its high-water mark: wasm memory never shrinks), the Rust heap in use in it, and Chromium's JS heap in use (`web/api.rs`) |
//! | `shoal.soak_change(request)` / `shoal.soak_check()` | the soak's next change and its checks (`crate::soak`) |
//!
//! Arguments arrive as JSON values; this module parses and validates them, so the
//! browser glue (`web/api.rs`) stays a thin shim and everything here is tested
//! natively. A bad argument is an [`AutomationError`] that the browser throws as a JS
//! `Error` with the same message; nothing changes.

use serde::Serialize;
use serde_json::Value;

use crate::lab::{Lab, LabError};
use crate::metrics_history::MetricsSample;
use crate::settings::{SEED_MAX, Settings, SettingsError, Side};
use crate::sim::boids::attention::AttentionReport;

/// Most steps one `shoal.step(n)` call may ask for (about 28 simulated minutes),
/// so a typo cannot freeze the tab for minutes.
pub const MAX_STEPS_PER_CALL: u32 = 100_000;

/// One call of the automation API.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    Set(Value),
    Step(u32),
    Pause,
    Play,
    Reset(Option<u64>),
    Turn(f32),
    /// Learning lab: run this many annealing steps now.
    Train(u32),
    /// Learning lab: start the race.
    Race,
    /// Learning lab: use the learned controllers in this JSON text.
    LoadControllers(String),
    /// The reef's demos: look ahead for the demo's moment (the frames that
    /// follow do it; `state().skip` reports).
    Skip,
    /// Stop looking ahead.
    CancelSkip,
}

/// Most annealing steps one `shoal.train(n)` call may ask for (a drill of the
/// paper's longest training).
pub const MAX_TRAIN_PER_CALL: u32 = 20_000;

/// Why a call was refused.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum AutomationError {
    #[error(transparent)]
    Settings(#[from] SettingsError),
    #[error("{0}")]
    BadArgument(String),
    /// A command's whole-number argument (`call` names it: "step(n)").
    #[error("{call}: {reason}")]
    BadNumber {
        call: &'static str,
        reason: WholeNumberError,
    },
    #[error(transparent)]
    Lab(#[from] LabError),
    #[error("Shoal is not running (it stopped after an error; reload the page)")]
    NotRunning,
}

impl Command {
    /// `shoal.step(n)`: `n` defaults to 1.
    pub fn step(n: Option<&Value>) -> Result<Self, AutomationError> {
        match n {
            None | Some(Value::Null) => Ok(Self::Step(1)),
            Some(value) => whole_number(value, 1, u64::from(MAX_STEPS_PER_CALL))
                .map(|n| Self::Step(n as u32))
                .map_err(|reason| AutomationError::BadNumber {
                    call: "step(n)",
                    reason,
                }),
        }
    }

    /// `shoal.reset(seed?)`.
    pub fn reset(seed: Option<&Value>) -> Result<Self, AutomationError> {
        match seed {
            None | Some(Value::Null) => Ok(Self::Reset(None)),
            Some(value) => whole_number(value, 0, SEED_MAX)
                .map(|seed| Self::Reset(Some(seed)))
                .map_err(|reason| AutomationError::BadNumber {
                    call: "reset(seed)",
                    reason,
                }),
        }
    }

    /// `shoal.turn(deg)`.
    pub fn turn(angle: Option<&Value>) -> Result<Self, AutomationError> {
        match angle.and_then(Value::as_f64) {
            Some(deg) if deg.abs() <= f64::from(crate::settings::physics::TURN_MAX_DEG) => {
                Ok(Self::Turn(deg as f32))
            }
            _ => Err(AutomationError::BadArgument(format!(
                "turn(deg): expected a number of degrees from -{0} to {0} (+ turns left), got {1}",
                crate::settings::physics::TURN_MAX_DEG,
                angle.map_or("nothing".to_owned(), Value::to_string)
            ))),
        }
    }

    /// `shoal.train(n)`.
    pub fn train(n: Option<&Value>) -> Result<Self, AutomationError> {
        match n {
            None | Some(Value::Null) => Ok(Self::Train(1)),
            Some(value) => whole_number(value, 1, u64::from(MAX_TRAIN_PER_CALL))
                .map(|n| Self::Train(n as u32))
                .map_err(|reason| AutomationError::BadNumber {
                    call: "train(n)",
                    reason,
                }),
        }
    }

    /// `shoal.load_controllers(text)`.
    pub fn load_controllers(text: Option<&Value>) -> Result<Self, AutomationError> {
        match text.and_then(Value::as_str) {
            Some(text) => Ok(Self::LoadControllers(text.to_owned())),
            None => Err(AutomationError::BadArgument(
                "load_controllers(text): expected the text of a saved controllers file".to_owned(),
            )),
        }
    }

    /// Carries the command out on `lab`.
    pub fn execute(self, lab: &mut Lab) -> Result<(), AutomationError> {
        match self {
            Self::Set(patch) => {
                let settings = patched_settings(lab.settings(), &patch)?;
                lab.apply_settings(settings);
            }
            Self::Step(n) => lab.step(n),
            Self::Pause | Self::Play => {
                let settings = crate::settings::Settings {
                    paused: self == Self::Pause,
                    ..lab.settings().clone()
                };
                lab.apply_settings(settings);
            }
            Self::Reset(seed) => lab.reset(seed),
            Self::Turn(deg) => lab.turn_selected(deg)?,
            Self::Train(n) => {
                lab.train(n)?;
            }
            Self::Race => lab
                .learning_mut()
                .ok_or(LabError::LearningLabOnly("race"))?
                .start_race()
                .map_err(LabError::from)?,
            Self::Skip => {
                lab.skip_to_moment()?;
            }
            Self::CancelSkip => lab.cancel_skip(),
            Self::LoadControllers(text) => {
                let loaded = match lab.learning_mut() {
                    Some(l) => l.load_json(&text).map_err(|e| e.to_string()),
                    None => Err(LabError::LearningLabOnly("load_controllers").to_string()),
                };
                loaded
                    .map_err(|e| AutomationError::BadArgument(format!("load_controllers: {e}")))?;
            }
        }
        Ok(())
    }
}

/// What `shoal.set(patch)` makes of `before`: the whole patch applied, or
/// why not (then nothing changes). A student view refuses what the teacher's
/// studio keeps.
pub fn patched_settings(before: &Settings, patch: &Value) -> Result<Settings, AutomationError> {
    let mut settings = before.clone();
    settings.apply_patch(patch)?;
    before
        .studio
        .check_unchanged(before, &settings)
        .map_err(SettingsError::from)?;
    Ok(settings)
}

/// Why an argument is not a whole number in its range.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum WholeNumberError {
    #[error("{n} is out of range: choose from {min} to {max}")]
    OutOfRange { n: u64, min: u64, max: u64 },
    #[error("expected a whole number from {min} to {max}, got {value}")]
    NotAWholeNumber { value: Value, min: u64, max: u64 },
}

fn whole_number(value: &Value, min: u64, max: u64) -> Result<u64, WholeNumberError> {
    match value.as_u64() {
        Some(n) if (min..=max).contains(&n) => Ok(n),
        Some(n) => Err(WholeNumberError::OutOfRange { n, min, max }),
        None => Err(WholeNumberError::NotAWholeNumber {
            value: value.clone(),
            min,
            max,
        }),
    }
}

/// How the tank is drawn (`state().scene_detail`).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SceneDetailReport {
    /// Pixels per side the tank is drawn with, as a share of the view's (1 = all).
    pub scale: f32,
    /// Whether the share follows the frame rate (the View section's *Auto*).
    pub auto: bool,
}

/// What `shoal.state()` returns. Field names are stable: tests and teachers' scripts
/// read them.
#[derive(Clone, Debug, Serialize)]
pub struct StateReport {
    /// Simulated seconds since the last reset.
    pub time_secs: f64,
    /// Simulation steps since the last reset.
    pub steps: u64,
    pub fish_count: usize,
    /// `"webgpu"` or `"webgl2"` in the browser; `"native"` on the desktop.
    pub tier: &'static str,
    /// Frames drawn per second over the last second.
    pub fps: f64,
    /// Frames drawn since the page opened (filled in by the app): a test that
    /// changed something waits for this to grow before it takes a screenshot.
    pub frames: u64,
    /// Simulation steps per second of real time over the last second.
    pub steps_per_sec: f64,
    pub paused: bool,
    pub seed: u64,
    pub scene: &'static str,
    pub speed: f32,
    /// True when the machine cannot keep up and the simulation runs slower than asked.
    pub fell_behind: bool,
    /// Behind for more than a moment (`clock::SLOWED_DOWN_AFTER_SECS`): the
    /// status line then says "slowed down".
    pub slowed_down: bool,
    /// Where the camera looks from (filled in by the app, which owns the camera).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub camera: Option<CameraReport>,
    /// The interface scale (egui's zoom factor): 1 on a laptop, more on a big
    /// screen (app only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ui_scale: Option<f32>,
    /// How the tank is drawn: the pixels per side as a share of the view's, and
    /// whether that share follows the frame rate (app only; see
    /// `render::detail`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scene_detail: Option<SceneDetailReport>,
    /// The View section's *High contrast* and *Reduce motion* (app only; see
    /// `ui::seeing`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seeing: Option<crate::ui::seeing::Seeing>,
    /// The language the interface speaks (`"en"`, `"es"`).
    pub lang: crate::i18n::Lang,
    /// The (left) tank's school metrics, see [`MetricsSample`], and in the
    /// schooling lab what its selected fish pays attention to.
    pub metrics: TankReport,
    /// The right tank's metrics while comparing.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub metrics_right: Option<TankReport>,
    /// Whether two tanks are shown.
    pub compare: bool,
    /// Is this page the student view of a teacher's studio link (the studio's
    /// rules apply, mystery values are masked)?
    pub student_view: bool,
    /// The message shown at the top of the view, if any (e.g. a share link that
    /// could not be opened).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub notice: Option<String>,
    /// The last words the screen reader's live region said about the tank
    /// (app only; see `crate::a11y::describe`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub said: Option<String>,
    /// The scene's own part: `physics`, `reef` or `learning` (see
    /// [`crate::sim::SceneReport`]).
    #[serde(flatten)]
    pub scene_report: crate::sim::SceneReport,
    /// *Skip to the moment*: the search under way and how the last one ended
    /// (the reef's demos only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skip: Option<SkipReport>,
    /// Benchmark progress and results, in `?bench` mode only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bench: Option<crate::bench::BenchReport>,
}

/// `shoal.state().skip`.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SkipReport {
    /// What the scene's moment is ("the shark's next catch").
    pub moment: &'static str,
    /// The search under way, if any.
    pub searching: Option<crate::lab::SkipProgress>,
    /// How the last search ended.
    pub last: Option<crate::lab::SkipOutcome>,
}

/// `shoal.state().metrics` (and `metrics_right`): the tank's school metrics
/// (the fields of [`MetricsSample`]) and, in the schooling lab with a fish
/// selected (`left.selected`, `right.selected`), `attention`: what that fish
/// paid attention to in the last step ([`crate::sim::World::attention`]).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct TankReport {
    #[serde(flatten)]
    pub sample: MetricsSample,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub attention: Option<AttentionReport>,
}

impl TankReport {
    fn new(run: &crate::lab::Run, settings: &crate::settings::Settings) -> Self {
        let attention = settings
            .selected_in(run.side())
            .and_then(|i| run.scene().attention(i as usize))
            .map(|a| AttentionReport::from(&a));
        Self {
            sample: run.metrics(),
            attention,
        }
    }
}

/// The orbit camera, as `shoal.state().camera` reports it.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct CameraReport {
    pub yaw_deg: f32,
    pub pitch_deg: f32,
    pub distance_m: f32,
    pub target_m: [f32; 3],
}

impl StateReport {
    pub fn new(lab: &Lab, tier: &'static str, fps: f64) -> Self {
        let run = &lab.runs()[0];
        let settings = lab.settings();
        Self {
            time_secs: run.time_secs(),
            steps: run.steps(),
            fish_count: run.scene().fish_count(),
            tier,
            fps,
            frames: 0,
            steps_per_sec: lab.steps_per_sec(),
            paused: settings.paused,
            seed: settings.seed,
            scene: settings.scene.name(),
            speed: settings.speed,
            fell_behind: lab.fell_behind(),
            slowed_down: lab.slowed_down(),
            metrics: TankReport::new(run, settings),
            metrics_right: lab
                .run(Side::Right)
                .map(|run| TankReport::new(run, settings)),
            compare: lab.comparing(),
            student_view: settings.studio.student_view,
            notice: None,
            said: None,
            camera: None,
            ui_scale: None,
            scene_detail: None,
            seeing: None,
            lang: crate::i18n::lang(),
            scene_report: run.scene().report(settings.selected()),
            skip: run.scene().moment().map(|m| SkipReport {
                moment: m.what,
                searching: lab.skipping(),
                last: lab.skip_outcome().cloned(),
            }),
            bench: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Settings;
    use serde_json::json;

    #[test]
    fn each_scene_reports_its_own_part_of_the_state_and_no_other() {
        use crate::settings::Scene;
        let parts = ["physics", "reef", "learning"];
        for (scene, own) in [
            (Scene::Aquarium, None),
            (Scene::Boids, None),
            (Scene::Physics, Some("physics")),
            (Scene::Reef, Some("reef")),
            (Scene::Learning, Some("learning")),
        ] {
            let lab = Lab::new(Settings {
                scene,
                ..Settings::default()
            });
            let state = serde_json::to_value(StateReport::new(&lab, "webgl2", 0.0)).unwrap();
            for part in parts {
                assert_eq!(
                    state.get(part).is_some(),
                    own == Some(part),
                    "{scene:?} and {part}"
                );
            }
        }
    }

    #[test]
    fn step_runs_exactly_n_steps_even_when_paused() {
        let mut lab = Lab::new(Settings::default());
        Command::Pause.execute(&mut lab).unwrap();
        Command::step(Some(&json!(25)))
            .unwrap()
            .execute(&mut lab)
            .unwrap();
        let state = StateReport::new(&lab, "webgl2", 60.0);
        assert_eq!(state.steps, 25);
        assert!(state.paused);
        assert!((state.time_secs - 25.0 / 60.0).abs() < 1e-6);
    }

    #[test]
    fn bad_step_counts_are_refused() {
        for bad in [
            json!(0),
            json!(-1),
            json!(1.5),
            json!("3"),
            json!(1_000_000),
        ] {
            let err = Command::step(Some(&bad)).unwrap_err();
            assert!(err.to_string().starts_with("step(n):"), "{err}");
        }
        assert_eq!(Command::step(None).unwrap(), Command::Step(1));
    }

    #[test]
    fn reset_with_a_seed_sets_the_seed_and_restarts() {
        let mut lab = Lab::new(Settings::default());
        lab.step(5);
        Command::reset(Some(&json!(7)))
            .unwrap()
            .execute(&mut lab)
            .unwrap();
        let state = StateReport::new(&lab, "webgpu", 0.0);
        assert_eq!((state.seed, state.steps), (7, 0));
        assert!(Command::reset(Some(&json!(-7))).is_err());
        assert!(Command::reset(Some(&json!(u64::MAX))).is_err());
    }

    #[test]
    fn set_reports_the_same_names_back_in_state() {
        let mut lab = Lab::new(Settings::default());
        Command::Set(json!({"left": {"fish_count": 12}, "speed": 4, "paused": true}))
            .execute(&mut lab)
            .unwrap();
        let state = serde_json::to_value(StateReport::new(&lab, "webgpu", 0.0)).unwrap();
        assert_eq!(state["fish_count"], 12);
        assert_eq!(state["speed"], 4.0);
        assert_eq!(state["paused"], true);
        for key in [
            "time_secs",
            "steps",
            "fish_count",
            "tier",
            "fps",
            "paused",
            "seed",
            "scene",
            "metrics",
        ] {
            assert!(state.get(key).is_some(), "state() lacks {key}");
        }
    }

    #[test]
    fn a_refused_set_changes_nothing() {
        let mut lab = Lab::new(Settings::default());
        let err = Command::Set(json!({"left": {"fish_count": 12}, "speed": "fast"}))
            .execute(&mut lab)
            .unwrap_err();
        assert!(err.to_string().contains("speed"), "{err}");
        assert_eq!(lab.settings(), &Settings::default());
        assert_eq!(lab.scene().boids().unwrap().fish().len(), 200);
    }

    #[test]
    fn turn_and_the_physics_report() {
        for bad in [json!("left"), json!(181), json!(-400), json!(null)] {
            let err = Command::turn(Some(&bad)).unwrap_err();
            assert!(err.to_string().starts_with("turn(deg):"), "{err}");
        }
        let mut lab = Lab::new(Settings::default());
        let state = serde_json::to_value(StateReport::new(&lab, "webgl2", 0.0)).unwrap();
        assert!(state.get("physics").is_none(), "only in the physics scene");
        Command::Set(json!({"scene": "physics", "physics": {"fish_count": 3, "selected": 1}}))
            .execute(&mut lab)
            .unwrap();
        let err = Command::Set(json!({"physics": {"selected": 9}}))
            .execute(&mut lab)
            .unwrap_err();
        assert!(err.to_string().contains("physics.selected"), "{err}");
        Command::turn(Some(&json!(-60)))
            .unwrap()
            .execute(&mut lab)
            .unwrap();
        Command::Step(5).execute(&mut lab).unwrap();
        let state = serde_json::to_value(StateReport::new(&lab, "webgl2", 0.0)).unwrap();
        assert_eq!(state["scene"], "physics");
        assert_eq!(state["fish_count"], 3);
        assert_eq!(state["physics"]["fish"], 3);
        let selected = &state["physics"]["selected"];
        assert_eq!(selected["index"], 1);
        assert_eq!(selected["species"], "fish");
        assert_eq!(selected["turning"], true);
        assert_eq!(selected["muscles"].as_array().unwrap().len(), 12);
        assert!((state["time_secs"].as_f64().unwrap() - 5.0 * 0.055).abs() < 1e-4);
    }

    #[test]
    fn the_schooling_labs_selected_fish_reports_its_attention_and_is_let_go_with_its_fish() {
        let mut lab = Lab::new(Settings {
            scene: crate::settings::Scene::Boids,
            ..Settings::default()
        });
        Command::Set(json!({"left": {"preset": "group", "selected": 7, "fish_count": 40}}))
            .execute(&mut lab)
            .unwrap();
        assert_eq!(lab.settings().selected(), Some(7));
        let state = serde_json::to_value(StateReport::new(&lab, "webgpu", 0.0)).unwrap();
        assert!(
            state["metrics"].get("attention").is_none(),
            "no step since the settings changed: nothing to report yet"
        );
        lab.step(3);
        let state = serde_json::to_value(StateReport::new(&lab, "webgpu", 0.0)).unwrap();
        let attention = &state["metrics"]["attention"];
        assert_eq!(attention["fish"], 7, "the selection survives steps");
        assert_eq!(attention["mode"], "blended");
        assert_eq!(attention["urges"].as_array().unwrap().len(), 5);
        assert_eq!(attention["urges"][2]["urge"], "cohesion");
        assert!(attention["urges"][2]["strength_m_per_s2"].is_number());
        assert!(attention["neighbours"].as_array().unwrap().len() <= 7);
        assert!(
            state["metrics"]["polarization"].is_number(),
            "metrics as before"
        );
        // A selection past the fish is refused; a smaller school lets it go.
        assert!(
            Command::Set(json!({"left": {"selected": 40}}))
                .execute(&mut lab)
                .is_err()
        );
        Command::Set(json!({"left": {"fish_count": 5}}))
            .execute(&mut lab)
            .unwrap();
        assert_eq!(lab.settings().left.selected, None);
        let state = serde_json::to_value(StateReport::new(&lab, "webgpu", 0.0)).unwrap();
        assert!(state["metrics"].get("attention").is_none());
        // Only the schooling lab selects boid fish.
        Command::Set(json!({"left": {"selected": 2}, "scene": "aquarium"}))
            .execute(&mut lab)
            .unwrap();
        assert_eq!(lab.settings().selected(), None);
    }
}
