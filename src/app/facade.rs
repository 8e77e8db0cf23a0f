//! The app's side of `window.shoal` (`src/web/api.rs` calls these): the page
//! address and its links, the state report, settings as JSON, share and
//! student links, CSV exports, commands, experiments, investigations and the
//! benchmark.

use crate::automation::{AutomationError, CameraReport, Command, SceneDetailReport, StateReport};
use crate::bench::Benchmark;
use crate::settings::Settings;
use crate::ui::{Notice, WidgetRects};

use super::ShoalApp;

impl ShoalApp {
    /// Tells the app its page address (for share links). An
    /// `?investigation=<id>` in it opens that investigation, an
    /// `?experiment=…` reopens that experiment (its scene set up, its runs
    /// started); a link that cannot be opened is explained in a notice, and
    /// the rest of the link stays as it was opened. `link_settings`: the
    /// page opened with a share link's settings (`#v1.…`), which an
    /// investigation then keeps instead of its own setup (the record's link
    /// that runs an investigation again, its seed and all).
    pub fn set_page_url(&mut self, url: String, link_settings: bool) {
        use crate::experiment::link as experiment_link;
        use crate::investigation::link as investigation_link;
        let investigation = investigation_link::from_url(&url);
        let experiment = experiment_link::from_url(&url);
        self.page_url = Some(crate::settings::share_link::without_query(
            &crate::settings::share_link::without_query(
                &experiment_link::without_experiment(&investigation_link::without_investigation(
                    &url,
                )),
                crate::ui::language::KEY,
            ),
            "class", // words: the join link's key (ui/class_panel.rs)
        ));
        match investigation {
            Some(Ok(investigation)) => {
                let opened = if link_settings {
                    self.open_investigation_as_linked(investigation)
                } else {
                    self.open_investigation(investigation, None)
                };
                if let Err(err) = opened {
                    self.notice = Some(Notice::error(err.to_string()));
                }
            }
            Some(Err(err)) => {
                self.notice = Some(Notice::error(crate::tr!(
                    "notice-investigation-link-error",
                    error = err.to_string()
                )));
            }
            None => {}
        }
        match experiment {
            Some(Ok(plan)) => self.reopen_experiment(plan),
            Some(Err(err)) => {
                self.notice = Some(Notice::error(crate::tr!(
                    "notice-experiment-link-error",
                    error = err.to_string()
                )));
            }
            None => {}
        }
    }

    /// An experiment link's plan: the tank shows the experiment's scene and
    /// base settings, and its runs start.
    pub(super) fn reopen_experiment(&mut self, plan: crate::experiment::Plan) {
        let mut settings = plan.base.clone();
        settings.paused = false;
        settings.speed = self.lab.settings().speed;
        self.lab.apply_settings(settings);
        let cost = self.lab_cost();
        self.experiment.start_plan(&self.ctx, plan, cost);
        self.notice = Some(Notice::info(crate::tr!(
            "notice-experiment-reopened",
            name = self.experiment.design().map_or("", |d| d.name.as_str())
        )));
    }

    /// The page's address for the links Shoal makes: without parameters of
    /// ours but the language in force (`?lang=`, unless English).
    pub(super) fn page(&self) -> String {
        crate::ui::language::with_lang(self.page_url.as_deref().unwrap_or_default())
    }

    /// The link that reopens the experiment in the *Experiment* window and runs
    /// it again (`shoal.experiment_link()`); `None` if the window was never
    /// opened.
    pub fn experiment_link(&self) -> Option<String> {
        let page = self.page();
        self.experiment
            .design()
            .map(|design| crate::experiment::link::link(&page, design))
    }

    /// Opens `investigation` (its scene set up through the settings), then
    /// applies `patch` over its settings. All or nothing.
    pub(super) fn open_investigation(
        &mut self,
        investigation: &'static crate::investigation::Investigation,
        patch: Option<&serde_json::Value>,
    ) -> Result<(), AutomationError> {
        let mut settings = crate::investigation::setup_settings(investigation)?;
        if let Some(patch) = patch {
            settings.apply_patch(patch)?;
        }
        self.investigations
            .open(&self.ctx, investigation)
            .map_err(AutomationError::BadArgument)?;
        self.lab.apply_settings(settings);
        self.ctx.request_repaint();
        Ok(())
    }

    /// Opens `investigation` on the settings the page's link set (not its
    /// setup): the link that runs a recorded investigation again.
    pub(super) fn open_investigation_as_linked(
        &mut self,
        investigation: &'static crate::investigation::Investigation,
    ) -> Result<(), AutomationError> {
        let settings = self.lab.settings().clone();
        self.investigations
            .open(&self.ctx, investigation)
            .map_err(AutomationError::BadArgument)?;
        self.lab.apply_settings(settings);
        self.ctx.request_repaint();
        Ok(())
    }

    /// `shoal.set(patch)`, where the patch may name an `investigation` to open
    /// (or `null` to close it). All or nothing: an unknown id or a bad setting
    /// changes nothing.
    pub fn set_with_investigation(
        &mut self,
        patch: serde_json::Value,
    ) -> Result<(), AutomationError> {
        use crate::investigation::link::{Request, split_patch};
        let (request, rest) =
            split_patch(&patch).map_err(|err| AutomationError::BadArgument(err.to_string()))?;
        match request {
            Request::None => self.run_command(Command::Set(rest)),
            Request::Open(investigation) => self.open_investigation(investigation, Some(&rest)),
            Request::Close => {
                self.run_command(Command::Set(rest))?;
                self.investigations.close();
                Ok(())
            }
        }
    }

    /// `shoal.state().investigation`: the one open, if any.
    pub fn investigation_report(&self) -> Option<crate::investigation::InvestigationReport> {
        self.investigations.report()
    }

    /// The student's record as `(html, csv, the HTML file's name)`
    /// (`shoal.investigation_record()`).
    pub fn investigation_record(&self) -> (String, String, String) {
        self.investigations.record_files(&self.page())
    }

    /// Shows an explanation at the top of the view (e.g. a share link that could not
    /// be opened).
    pub fn show_error_notice(&mut self, text: String) {
        self.notice = Some(Notice::error(text));
    }

    /// Shows a message at the top of the view (e.g. why the fish start paused).
    pub fn show_info_notice(&mut self, text: impl Into<String>) {
        self.notice = Some(Notice::info(text));
    }

    /// What `shoal.state()` reports.
    pub fn state_report(&self) -> StateReport {
        // The world's part (names of fish, events) in English whatever the
        // interface speaks: scripts read it. What the person was shown and
        // told (`notice`, `said`) stays in their language.
        let mut report = crate::i18n::with_lang(crate::i18n::Lang::En, || {
            StateReport::new(
                &self.lab,
                self.caps.tier.name(),
                self.fps_meter.rate_per_sec(),
            )
        });
        // ...but the language reported is the one the person sees.
        report.lang = crate::i18n::lang();
        report.bench = self.benchmark.as_ref().map(Benchmark::report);
        report.frames = self.frames_drawn;
        report.camera = Some(CameraReport {
            yaw_deg: self.camera.yaw_rad.to_degrees(),
            pitch_deg: self.camera.pitch_rad.to_degrees(),
            distance_m: self.camera.distance_m,
            target_m: self.camera.target_m.to_array(),
        });
        report.notice = self.notice.as_ref().map(|n| n.text.clone());
        report.said = self.last_said.clone();
        report.ui_scale = Some(self.ctx.zoom_factor());
        report.scene_detail = Some(SceneDetailReport {
            scale: self.scene_detail.scale(),
            auto: self.scene_detail.auto,
        });
        report.seeing = Some(crate::ui::seeing::get(&self.ctx));
        report
    }

    /// Makes the next frame panic (`shoal.crash_test()`), so tests can check that a
    /// panic is explained on the page and that reloading brings Shoal back.
    pub fn request_crash_test(&mut self) {
        self.crash_requested = true;
        self.ctx.request_repaint();
    }

    /// Starts the benchmark (the `?bench` page mode).
    pub fn start_benchmark(&mut self) {
        // Frame times at every pixel, comparable between machines and runs.
        self.scene_detail.set_auto(false);
        self.benchmark = Some(Benchmark::new());
    }

    /// The interface scale in use: CSS pixels per egui point, beyond the
    /// screen's own pixel ratio.
    pub fn interface_scale_now(&self) -> f32 {
        self.ctx.zoom_factor()
    }

    /// Where the named widgets are, for `shoal.widgets()`.
    pub fn widget_rects(&self) -> &WidgetRects {
        &self.widget_rects
    }

    /// The current settings (`shoal.settings()`), by the names `shoal.set` takes.
    pub fn state_settings(&self) -> &Settings {
        self.lab.settings()
    }

    /// `shoal.soak_change(request)`: the soak's change number `index` for the
    /// tank as it is now (`crate::soak::ChangeRequest`; `web/tests/soak.mjs`).
    pub fn soak_change(
        &self,
        request: Option<serde_json::Value>,
    ) -> Result<serde_json::Value, AutomationError> {
        let request: crate::soak::ChangeRequest =
            serde_json::from_value(request.unwrap_or_default()).map_err(|err| {
                AutomationError::BadArgument(format!(
                    "soak_change(request): expected {{scene, seed, index}}: {err}" // words: the automation API's error, for test scripts
                ))
            })?;
        Ok(request.change(&self.lab))
    }

    /// `shoal.soak_check()`: the soak's rules checked on every animal now.
    pub fn soak_check(&self) -> serde_json::Value {
        crate::soak::check_json(&self.lab)
    }

    /// `shoal.settings()`: the current settings as JSON, with the mystery
    /// values masked in the student view.
    pub fn settings_json(&self) -> serde_json::Value {
        let settings = self.lab.settings();
        let mut json = serde_json::to_value(settings).unwrap_or_default();
        settings.studio.mask_settings_json(&mut json);
        // The studio, even when empty (links leave an empty one out).
        if let (Some(object), Ok(studio)) =
            (json.as_object_mut(), serde_json::to_value(&settings.studio))
        {
            object.insert("studio".to_owned(), studio);
        }
        json
    }

    /// Masks in `state()`'s JSON what would give a mystery value away
    /// (student view only).
    pub fn mask_state_json(&self, state: &mut serde_json::Value) {
        self.lab.settings().studio.mask_state_json(state);
    }

    /// The link *Share with class* gives (`shoal.student_link()`): these
    /// settings in the student view.
    pub fn student_link(&self) -> String {
        crate::ui::studio_panel::student_link(self.lab.settings(), &self.page())
    }

    /// The link that reopens the current settings (`shoal.share_link()`).
    pub fn share_link(&self) -> String {
        let page = self.page();
        let page = match self.investigations.open_id() {
            Some(id) => crate::investigation::link::with_investigation(&page, id),
            None => page,
        };
        format!(
            "{}#{}",
            page,
            crate::settings::share_link::encode(self.lab.settings())
        )
    }

    /// The metrics of the last minutes as CSV (`shoal.metrics_csv()`).
    pub fn metrics_csv(&self) -> String {
        self.lab.metrics_csv()
    }

    /// The scene's data file, what *Download data* saves (`shoal.export_csv()`).
    pub fn export_csv(&self) -> crate::export::CsvExport {
        crate::export::scene_csv(&self.lab)
    }

    /// Runs an automation command and asks for a repaint so the change shows.
    pub fn run_command(&mut self, command: Command) -> Result<(), AutomationError> {
        let result = command.execute(&mut self.lab);
        self.ctx.request_repaint();
        result
    }

    /// What the lab measured of its own steps, to scale an experiment's estimate.
    pub(super) fn lab_cost(&self) -> crate::ui::LabCost {
        crate::ui::LabCost {
            secs_per_step: self.lab.step_cost_secs(),
            animals: self.lab.runs().iter().map(|r| r.animal_count()).sum(),
            fps: self.fps_meter.rate_per_sec(),
        }
    }

    /// Starts an experiment from a design (`shoal.experiment()`), with the
    /// current settings under any the design leaves out.
    pub fn start_experiment(
        &mut self,
        design: &serde_json::Value,
    ) -> Result<(), crate::experiment::DesignError> {
        let design = crate::experiment::Design::from_json(&design.to_string())?;
        let cost = self.lab_cost();
        self.experiment.start(&self.ctx, &design, cost)
    }

    /// Cancels the experiment under way (`shoal.cancel_experiment()`), keeping
    /// its completed runs; false if none was running.
    pub fn cancel_experiment(&mut self) -> bool {
        self.ctx.request_repaint();
        self.experiment.cancel()
    }

    /// `shoal.state().experiment`.
    pub fn experiment_report(&self) -> Option<crate::experiment::ExperimentReport> {
        self.experiment.report()
    }

    /// The learned controllers in use, as JSON (`shoal.save_controllers()`).
    pub fn controllers_json(&self) -> Result<String, crate::ui::SaveControllersError> {
        crate::ui::controllers_json(&self.lab)
    }
}

impl ShoalApp {
    /// The page's class link: `?class=CODE` opens the join window, a teacher
    /// link's fragment (`#teacher=CODE.TOKEN`) the dashboard; a class this
    /// browser was in comes back (issue 37).
    pub fn open_class_from_page(&mut self, url: &str, fragment: &str) {
        self.class.open_from_page(url, fragment);
    }

    /// `shoal.class()`: the class as this page sees it (read only).
    pub fn class_report(&self) -> serde_json::Value {
        self.class.report()
    }

    /// Carries out what the class asks: open the lesson with the student's
    /// seed, apply a setting the teacher sent (as `shoal.set()` does, the
    /// studio's locks holding), pause or play, tell something.
    pub(super) fn class_actions(&mut self, actions: Vec<crate::ui::class_panel::ClassAction>) {
        use crate::ui::class_panel::ClassAction;
        for action in actions {
            let done = match action {
                ClassAction::OpenLesson { setup, seed } => self.open_class_lesson(&setup, seed),
                ClassAction::ApplySetting(patch) => self
                    .run_command(Command::Set(patch))
                    .map_err(|e| e.to_string()),
                ClassAction::Pause(paused) => self
                    .run_command(if paused {
                        Command::Pause
                    } else {
                        Command::Play
                    })
                    .map_err(|e| e.to_string()),
                ClassAction::Notice(notice) => {
                    self.notice = Some(notice);
                    Ok(())
                }
            };
            if let Err(err) = done {
                self.notice = Some(Notice::error(err));
            }
        }
    }

    /// A class's lesson on this student's seed: `{"investigation": id}` or
    /// `{"studio": <share link's settings>}`.
    fn open_class_lesson(&mut self, setup: &serde_json::Value, seed: u64) -> Result<(), String> {
        let seed_patch = serde_json::json!({ "seed": seed });
        if let Some(id) = setup.get("investigation").and_then(|v| v.as_str()) {
            let investigation = crate::investigation::INVESTIGATIONS
                .iter()
                .find(|i| i.id == id)
                .ok_or_else(|| crate::tr!("class-unknown-lesson", lesson = id.to_owned()))?;
            return self
                .open_investigation(investigation, Some(&seed_patch))
                .map_err(|e| e.to_string());
        }
        if let Some(link) = setup.get("studio").and_then(|v| v.as_str()) {
            let mut settings = crate::settings::share_link::decode(link)
                .map_err(|e| e.to_string())?
                .ok_or_else(|| crate::tr!("class-unknown-lesson", lesson = link.to_owned()))?;
            settings.seed = seed;
            self.lab.apply_settings(settings);
            self.ctx.request_repaint();
            return Ok(());
        }
        Err(crate::tr!(
            "class-unknown-lesson",
            lesson = setup.to_string()
        ))
    }
}
