//! A class together (issue 37) on screen: *Start a class* and *Join a class*
//! in the side panel, the teacher's dashboard window, and the student's line
//! saying how their class is (connected, held, paused, revealed). Shown only
//! when the page was served by a class server (`GET /api/info`, asked once at
//! start, on the web only); otherwise Shoal works alone as it always has.
//!
//! The protocol's logic is `crate::class` (pure, tested natively); the
//! WebSocket, `fetch` and the browser's storage are `web/class_net.rs`.

use eframe::egui;
use serde_json::{Value, json};

use crate::class::session::{Link, Session, Student, Teacher, Who};
use crate::class::stats;
use crate::i18n::{num, tr, ts};
use crate::investigation::{INVESTIGATIONS, InvestigationReport, Step};
use crate::settings::Settings;
use crate::tr;
use crate::ui::{Notice, WidgetRects};

#[cfg(target_arch = "wasm32")]
use crate::web::class_net as net;

/// Where this browser keeps a student's session (their token and unsent work).
#[cfg(target_arch = "wasm32")]
const STUDENT_KEY: &str = "shoal.class.student";
/// Where this browser keeps the teacher's session (the teacher link's token).
#[cfg(target_arch = "wasm32")]
const TEACHER_KEY: &str = "shoal.class.teacher";

/// What the class asks of the app.
pub enum ClassAction {
    /// Open the class's lesson with this student's seed: an investigation by
    /// id, or a studio setup (a share link's settings).
    OpenLesson {
        setup: Value,
        seed: u64,
    },
    /// The teacher sent a setting (a settings patch): applied as `shoal.set()`
    /// applies one, the studio's locks holding.
    ApplySetting(Value),
    /// Pause (or play) the tank.
    Pause(bool),
    Notice(Notice),
}

/// What the student's investigation already told the server.
#[derive(Default)]
struct Reported {
    step: Option<&'static str>,
    prediction: Option<String>,
    result: bool,
    /// The (step, prompt) the explain answer was last sent at.
    explain_at: Option<(Step, Option<usize>)>,
    explain: String,
}

/// What the teacher picks to start a class with.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Lesson {
    Investigation(usize),
    Studio,
}

/// The class features' state.
pub struct ClassPanel {
    /// Did a class server answer `/api/info`? (`None`: not yet known.)
    server: Option<bool>,
    session: Option<Session>,
    /// The text last written to the browser's storage.
    stored: String,
    start_open: bool,
    lesson: Lesson,
    join_open: bool,
    join_code: String,
    join_nickname: String,
    dashboard_open: bool,
    confirm_delete: bool,
    /// The QR code of the join link, made once per link.
    qr: Option<(String, Result<qrcodegen::QrCode, String>)>,
    reported: Reported,
    /// The pacing last acted on (pause, setting), so each change acts once.
    seen_paused: bool,
    seen_setting: Option<Value>,
    /// The lesson opened for this session (a student's), once.
    lesson_opened: bool,
    /// An error to show in the windows (a refused start, a failed download).
    error: Option<String>,
    #[cfg(target_arch = "wasm32")]
    net: Net,
}

#[cfg(target_arch = "wasm32")]
#[derive(Default)]
struct Net {
    info: Option<net::Reply>,
    socket: Option<net::Socket>,
    starting: Option<(net::Reply, Value)>,
    csv: Option<net::Reply>,
    delete: Option<net::Reply>,
}

impl Default for ClassPanel {
    fn default() -> Self {
        ClassPanel {
            server: if cfg!(target_arch = "wasm32") {
                None
            } else {
                Some(false)
            },
            session: None,
            stored: String::new(),
            start_open: false,
            lesson: Lesson::Investigation(0),
            join_open: false,
            join_code: String::new(),
            join_nickname: String::new(),
            dashboard_open: false,
            confirm_delete: false,
            qr: None,
            reported: Reported::default(),
            seen_paused: false,
            seen_setting: None,
            lesson_opened: false,
            error: None,
            #[cfg(target_arch = "wasm32")]
            net: Net::default(),
        }
    }
}

/// The join link of `code` on `page`: `page?class=CODE`.
pub fn join_link(page: &str, code: &str) -> String {
    crate::settings::share_link::with_query(page, "class", code) // words: a link's key
}

/// The teacher link: `page#teacher=CODE.TOKEN` (in the fragment, which a
/// browser never sends to a server or in a Referer).
pub fn teacher_link(page: &str, code: &str, token: &str) -> String {
    format!("{page}#teacher={code}.{token}") // words: a link's fragment
}

/// The code and token of a teacher link's fragment (`#teacher=CODE.TOKEN`).
pub fn parse_teacher_fragment(fragment: &str) -> Option<(String, String)> {
    let rest = fragment.trim_start_matches('#').strip_prefix("teacher=")?; // words: a link's fragment
    let (code, token) = rest.split_once('.')?;
    let code = crate::class::normalise_code(code)?;
    (!token.is_empty() && token.len() <= 128 && token.chars().all(|c| c.is_ascii_hexdigit()))
        .then(|| (code, token.to_owned()))
}

impl ClassPanel {
    /// Is the page served by a class server (the class features shown)?
    pub fn available(&self) -> bool {
        self.server == Some(true)
    }

    /// The page opened with `?class=CODE` and/or `#teacher=CODE.TOKEN`
    /// (`fragment`): the join window with the code filled in, or the dashboard.
    /// A session this browser kept comes back too.
    pub fn open_from_page(&mut self, url: &str, fragment: &str) {
        let query_code = crate::settings::share_link::query_value(url, "class") // words: a link's key
            .and_then(crate::class::normalise_code);
        if let Some((code, token)) = parse_teacher_fragment(fragment) {
            self.session = Some(Session::new(
                Who::Teacher(Teacher { code, token }),
                &prefix(),
            ));
            self.dashboard_open = true;
            return;
        }
        #[cfg(target_arch = "wasm32")]
        {
            let kept_student = net::load(STUDENT_KEY).and_then(|t| Session::from_storage(&t));
            let kept_teacher = net::load(TEACHER_KEY).and_then(|t| Session::from_storage(&t));
            if let Some(s) = kept_student
                && query_code.as_deref().is_none_or(|c| c == s.code())
            {
                self.session = Some(s);
                return;
            }
            if query_code.is_none()
                && let Some(t) = kept_teacher
            {
                self.session = Some(t);
                self.dashboard_open = true;
                return;
            }
        }
        if let Some(code) = query_code {
            self.join_code = code;
            self.join_open = true;
        }
    }

    /// A student's class step is held here (the investigation window stops
    /// at it): the held step, if any.
    pub fn held_step(&self) -> Option<String> {
        let s = self.session.as_ref()?;
        if s.is_teacher() {
            return None;
        }
        s.state()?.held_step.clone()
    }

    /// `shoal.class()`: the class as this page sees it (read only).
    pub fn report(&self) -> Value {
        let Some(s) = &self.session else {
            // The join window as typed so far (what a test checks before it
            // presses Join).
            let join = self.join_open.then(|| {
                json!({"code": self.join_code, "nickname": self.join_nickname, "error": self.error})
            });
            return json!({"server": self.server, "role": null, "join": join});
        };
        let link = s.link();
        let common = json!({
            "server": self.server,
            "code": s.code(),
            "link": link,
            "waiting": s.outbox.len(),
            "refusals": s.refusals,
            "ended": s.ended,
        });
        let mut out = common;
        let Some(o) = out.as_object_mut() else {
            return out;
        };
        match &s.who {
            Who::Teacher(_) => {
                o.insert("role".into(), json!("teacher"));
                if let Some(view) = &s.class {
                    o.insert(
                        "view".into(),
                        serde_json::to_value(view).unwrap_or_default(),
                    );
                    o.insert(
                        "pooled".into(),
                        serde_json::to_value(stats::pooled(&view.roster)).unwrap_or_default(),
                    );
                }
            }
            Who::Student(st) => {
                o.insert("role".into(), json!("student"));
                o.insert("seed".into(), json!(st.seed));
                o.insert("join_order".into(), json!(st.join_order));
                o.insert("nickname".into(), json!(st.nickname));
                if let Some(view) = &s.you {
                    o.insert(
                        "view".into(),
                        serde_json::to_value(view).unwrap_or_default(),
                    );
                }
            }
        }
        out
    }

    /// This frame's network work: the server check, the socket's events,
    /// reconnecting, answers to requests. Returns what the app must do.
    pub fn frame(&mut self, ctx: &egui::Context, now: f64) -> Vec<ClassAction> {
        let mut actions = Vec::new();
        #[cfg(target_arch = "wasm32")]
        self.net_frame(ctx, now, &mut actions);
        #[cfg(not(target_arch = "wasm32"))]
        let _ = (ctx, now);
        if self.available() {
            self.pacing(&mut actions);
            self.store();
        }
        actions
    }

    /// The pacing of a student's class acted on once per change.
    fn pacing(&mut self, actions: &mut Vec<ClassAction>) {
        let Some(s) = &self.session else {
            return;
        };
        if let Some(student) = s.student()
            && student.token.is_some()
            && !self.lesson_opened
        {
            self.lesson_opened = true;
            actions.push(ClassAction::OpenLesson {
                setup: student.setup.clone(),
                seed: u64::try_from(student.seed).unwrap_or(1),
            });
        }
        if s.is_teacher() {
            return;
        }
        let Some(state) = s.state().cloned() else {
            return;
        };
        if state.paused != self.seen_paused {
            self.seen_paused = state.paused;
            actions.push(ClassAction::Pause(state.paused));
            if state.paused {
                actions.push(ClassAction::Notice(Notice::info(tr("class-paused-notice"))));
            }
        }
        if state.setting != self.seen_setting {
            self.seen_setting = state.setting.clone();
            if let Some(mut setting) = state.setting {
                // The student's tank keeps its own seed and view.
                if let Some(o) = setting.as_object_mut() {
                    for key in ["seed", "studio", "paused", "investigation"] {
                        // words: settings keys
                        o.remove(key);
                    }
                }
                actions.push(ClassAction::ApplySetting(setting));
            }
        }
    }

    /// Writes the session to the browser's storage when it changed.
    fn store(&mut self) {
        #[cfg(target_arch = "wasm32")]
        if let Some(s) = &self.session {
            let text = s.to_storage();
            if text != self.stored {
                let key = if s.is_teacher() {
                    TEACHER_KEY
                } else {
                    STUDENT_KEY
                };
                net::store(key, Some(&text));
                self.stored = text;
            }
        }
    }

    /// Sends a message now or when the connection is back.
    fn send(&mut self, kind: &str, body: Value) {
        let Some(s) = &mut self.session else {
            return;
        };
        let frame = s.send(kind, body);
        #[cfg(target_arch = "wasm32")]
        if let (Some(frame), Some(socket)) = (frame, &self.net.socket) {
            socket.send(&frame);
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = frame;
    }

    /// A student's investigation, reported: the step (never beyond a hold),
    /// the committed prediction, the run's measured numbers, the answers.
    pub fn report_investigation(&mut self, report: Option<&InvestigationReport>) {
        let Some(report) = report else {
            return;
        };
        let Some(s) = &self.session else {
            return;
        };
        if s.is_teacher() || s.student().is_none_or(|st| st.token.is_none()) {
            return;
        }
        let step = crate::class::class_step(report.step);
        if self.reported.step != Some(step) && s.may_go_to(step) {
            self.reported.step = Some(step);
            self.send("step", json!({"step": step}));
        }
        if let Some(p) = &report.prediction
            && self.reported.prediction.as_deref() != Some(p.key)
        {
            self.reported.prediction = Some(p.key.to_owned());
            self.send("predict", json!({"prediction": p.key}));
        }
        if let Some(outcome) = &report.result
            && !self.reported.result
            && let Some(inv) = INVESTIGATIONS.iter().find(|i| i.id == report.id)
        {
            self.reported.result = true;
            let values = crate::class::result_values(inv, outcome);
            if !values.is_empty() {
                self.send("result", json!({"levels": {}, "values": values}));
            }
        }
        let at = (report.step, report.prompt);
        if matches!(report.step, Step::Explain | Step::Reveal)
            && self.reported.explain_at != Some(at)
        {
            let answer: String = report
                .explanations
                .iter()
                .filter(|a| !a.trim().is_empty())
                .map(|a| a.trim())
                .collect::<Vec<_>>()
                .join("\n\n");
            let answer: String = answer.chars().take(2000).collect();
            self.reported.explain_at = Some(at);
            if !answer.is_empty() && answer != self.reported.explain {
                self.reported.explain = answer.clone();
                self.send("explain", json!({"answer": answer}));
            }
        }
    }

    /// *Start a class* and *Join a class* (or the class's status line) in the
    /// side panel.
    pub fn side_ui(&mut self, ui: &mut egui::Ui, rects: &mut WidgetRects) {
        if !self.available() {
            return;
        }
        match &self.session {
            None => {
                ui.horizontal(|ui| {
                    let start = ui
                        .button(ts("class-start"))
                        .on_hover_text(ts("class-start.help"));
                    rects.insert("class_start", start.rect);
                    if start.clicked() {
                        self.start_open = !self.start_open;
                    }
                    let join = ui
                        .button(ts("class-join"))
                        .on_hover_text(ts("class-join.help"));
                    rects.insert("class_join", join.rect);
                    if join.clicked() {
                        self.join_open = !self.join_open;
                    }
                });
            }
            Some(s) => {
                let line = status_text(s, ui.input(|i| i.time));
                let teacher = s.is_teacher();
                ui.label(line);
                if teacher {
                    let b = ui.button(ts("class-dashboard"));
                    rects.insert("class_dashboard", b.rect);
                    if b.clicked() {
                        self.dashboard_open = true;
                    }
                } else {
                    self.student_lines(ui);
                }
            }
        }
    }

    /// What a student reads about the class: held, paused, the revealed
    /// histogram, refusals.
    fn student_lines(&mut self, ui: &mut egui::Ui) {
        let Some(s) = &mut self.session else {
            return;
        };
        if let Some(st) = s.student() {
            ui.label(tr!(
                "class-you-are",
                nickname = st.nickname.clone(),
                order = st.join_order,
                seed = st.seed
            ));
        }
        if let Some(state) = s.state() {
            if let Some(step) = &state.held_step {
                ui.label(egui::RichText::new(tr!("class-held", step = step_name(step))).strong());
            }
            if state.paused {
                ui.label(egui::RichText::new(ts("class-paused-notice")).strong());
            }
        }
        if let Some(h) = s.you.as_ref().and_then(|y| y.histogram.as_ref()) {
            ui.label(egui::RichText::new(ts("class-revealed")).strong());
            histogram_ui(ui, h);
        }
        for r in s.refusals.drain(..) {
            self.error = Some(tr!("class-refused", kind = r.kind, reason = r.message));
        }
        if let Some(e) = &self.error {
            ui.colored_label(ui.visuals().error_fg_color, e);
        }
        let mut leave = false;
        if let Some(why) = &s.ended {
            ui.colored_label(
                ui.visuals().error_fg_color,
                tr!("class-ended", reason = why.clone()),
            );
            leave = ui.button(ts("class-leave")).clicked();
        }
        if leave {
            self.leave();
        }
    }

    /// Forgets this browser's class session.
    fn leave(&mut self) {
        #[cfg(target_arch = "wasm32")]
        if let Some(s) = &self.session {
            net::store(
                if s.is_teacher() {
                    TEACHER_KEY
                } else {
                    STUDENT_KEY
                },
                None,
            );
            self.net.socket = None;
        }
        self.session = None;
        self.stored.clear();
        self.dashboard_open = false;
        self.lesson_opened = false;
        self.reported = Reported::default();
    }

    /// The windows: start, join, the dashboard.
    pub fn windows_ui(
        &mut self,
        ctx: &egui::Context,
        settings: &Settings,
        page: &str,
        rects: &mut WidgetRects,
    ) -> Vec<ClassAction> {
        let mut actions = Vec::new();
        if !self.available() {
            return actions;
        }
        if self.session.is_none() {
            self.start_window(ctx, settings, rects);
            self.join_window(ctx, rects);
        }
        if self.session.as_ref().is_some_and(Session::is_teacher) {
            self.dashboard(ctx, settings, page, rects, &mut actions);
        }
        actions
    }

    fn start_window(&mut self, ctx: &egui::Context, settings: &Settings, rects: &mut WidgetRects) {
        if !self.start_open {
            return;
        }
        let mut open = true;
        egui::Window::new(ts("class-start"))
            .open(&mut open)
            .collapsible(false)
            .show(ctx, |ui| {
                ui.label(ts("class-start-intro"));
                for (k, inv) in INVESTIGATIONS.iter().enumerate() {
                    let r = ui.radio_value(
                        &mut self.lesson,
                        Lesson::Investigation(k),
                        inv.title.text(),
                    );
                    rects.insert(&format!("class_lesson_{k}"), r.rect);
                }
                let r = ui.radio_value(&mut self.lesson, Lesson::Studio, ts("class-lesson-studio"));
                rects.insert("class_lesson_studio", r.rect);
                let go = ui.button(egui::RichText::new(ts("class-start-go")).strong());
                rects.insert("class_start_go", go.rect);
                if go.clicked() {
                    let setup = match self.lesson {
                        Lesson::Investigation(k) => {
                            json!({"investigation": INVESTIGATIONS[k].id}) // words: a JSON key
                        }
                        Lesson::Studio => {
                            let mut s = settings.clone();
                            s.studio.student_view = true;
                            json!({"studio": crate::settings::share_link::encode(&s)}) // words: a JSON key
                        }
                    };
                    self.start_class(ctx, setup);
                }
                #[cfg(target_arch = "wasm32")]
                if self.net.starting.is_some() {
                    ui.label(ts("class-starting"));
                }
                if let Some(e) = &self.error {
                    ui.colored_label(ui.visuals().error_fg_color, e);
                }
            });
        self.start_open &= open;
    }

    fn start_class(&mut self, ctx: &egui::Context, setup: Value) {
        #[cfg(target_arch = "wasm32")]
        {
            let body = json!({"setup": setup}).to_string();
            let reply = net::fetch(ctx, "POST", "/api/classes", Some(body), None);
            self.net.starting = Some((reply, setup));
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = (ctx, setup);
    }

    fn join_window(&mut self, ctx: &egui::Context, rects: &mut WidgetRects) {
        if !self.join_open {
            return;
        }
        let mut open = true;
        egui::Window::new(ts("class-join"))
            .open(&mut open)
            .collapsible(false)
            .show(ctx, |ui| {
                ui.label(ts("class-join-intro"));
                let code_label = ui.label(ts("class-code"));
                let code = ui
                    .add(egui::TextEdit::singleline(&mut self.join_code).char_limit(8))
                    .labelled_by(code_label.id);
                rects.insert("class_code", code.rect);
                let nick_label = ui.label(ts("class-nickname"));
                let nick = ui
                    .add(egui::TextEdit::singleline(&mut self.join_nickname).char_limit(24))
                    .labelled_by(nick_label.id);
                rects.insert("class_nickname", nick.rect);
                ui.label(egui::RichText::new(ts("class-nickname.help")).weak());
                let go = ui.button(egui::RichText::new(ts("class-join-go")).strong());
                rects.insert("class_join_go", go.rect);
                if go.clicked() {
                    match (
                        crate::class::normalise_code(&self.join_code),
                        crate::class::normalise_nickname(&self.join_nickname),
                    ) {
                        (None, _) => self.error = Some(tr("class-bad-code")),
                        (_, None) => self.error = Some(tr("class-bad-nickname")),
                        (Some(code), Some(nickname)) => {
                            self.error = None;
                            self.session = Some(Session::new(
                                Who::Student(Student {
                                    code,
                                    nickname,
                                    token: None,
                                    join_order: 0,
                                    seed: 0,
                                    setup: Value::Null,
                                }),
                                &prefix(),
                            ));
                            self.join_open = false;
                        }
                    }
                }
                if let Some(e) = &self.error {
                    ui.colored_label(ui.visuals().error_fg_color, e);
                }
            });
        self.join_open &= open;
    }

    fn dashboard(
        &mut self,
        ctx: &egui::Context,
        settings: &Settings,
        page: &str,
        rects: &mut WidgetRects,
        actions: &mut Vec<ClassAction>,
    ) {
        if !self.dashboard_open {
            return;
        }
        let Some(s) = &self.session else {
            return;
        };
        let Who::Teacher(teacher) = &s.who else {
            return;
        };
        let code = teacher.code.clone();
        let token = teacher.token.clone();
        let join = join_link(page, &code);
        if self.qr.as_ref().is_none_or(|(l, _)| *l != join) {
            self.qr = Some((join.clone(), super::qr::encode(&join)));
        }
        let view = s.class.clone();
        let status = status_text(s, ctx.input(|i| i.time));
        let ended = s.ended.clone();
        let mut open = true;
        let screen = ctx.content_rect();
        let shown = egui::Window::new(ts("class-dashboard"))
            .id(egui::Id::unique("class_dashboard"))
            .open(&mut open)
            .default_width(560.0_f32.min(screen.width() - 24.0))
            .default_pos(screen.right_top() + egui::vec2(-590.0, 40.0))
            .constrain(true)
            .show(ctx, |ui| {
                egui::ScrollArea::vertical()
                    .max_height((screen.height() - 120.0).max(200.0))
                    .show(ui, |ui| {
                        ui.horizontal(|ui| {
                            ui.vertical(|ui| {
                                ui.label(ts("class-code-to-join"));
                                let c = ui.label(
                                    egui::RichText::new(&code).size(44.0).strong().monospace(),
                                );
                                rects.insert("class_code_big", c.rect);
                                ui.label(egui::RichText::new(&join).small());
                                ui.label(&status);
                                if let Some(why) = &ended {
                                    ui.colored_label(
                                        ui.visuals().error_fg_color,
                                        tr!("class-ended", reason = why.clone()),
                                    );
                                }
                            });
                            if let Some((_, Ok(qr))) = &self.qr {
                                let r = super::qr::draw(ui, qr, 150.0);
                                rects.insert("class_qr", r.rect);
                            }
                        });
                        let copy = ui
                            .button(ts("class-copy-teacher-link"))
                            .on_hover_text(ts("class-copy-teacher-link.help"));
                        if copy.clicked() {
                            ui.ctx().copy_text(teacher_link(page, &code, &token));
                            actions.push(ClassAction::Notice(Notice::info(tr(
                                "class-teacher-link-copied",
                            ))));
                        }
                        ui.separator();
                        self.pacing_ui(ui, view.as_ref(), settings, rects);
                        ui.separator();
                        match &view {
                            Some(view) => self.class_ui(ui, view, rects),
                            None => {
                                ui.label(ts("class-waiting-for-view"));
                            }
                        }
                        ui.separator();
                        self.data_ui(ui, &code, &token, rects);
                    });
            });
        if let Some(shown) = shown {
            rects.insert("class_dashboard_window", shown.response.rect);
        }
        self.dashboard_open &= open;
    }

    fn pacing_ui(
        &mut self,
        ui: &mut egui::Ui,
        view: Option<&crate::class::view::ClassView>,
        settings: &Settings,
        rects: &mut WidgetRects,
    ) {
        let state = view.map(|v| v.state.clone()).unwrap_or_default();
        ui.label(egui::RichText::new(ts("class-pacing")).strong());
        ui.horizontal_wrapped(|ui| {
            let label = ui.label(ts("class-hold-at"));
            let current = state.held_step.clone();
            let mut chosen = current.clone();
            let combo = egui::ComboBox::from_id_salt("class_hold")
                .selected_text(current.as_deref().map_or(ts("class-no-hold"), step_name))
                .show_ui(ui, |ui| {
                    ui.selectable_value(&mut chosen, None, ts("class-no-hold"));
                    for step in crate::class::STEPS {
                        ui.selectable_value(&mut chosen, Some(step.to_owned()), step_name(step));
                    }
                });
            let combo = combo.response.labelled_by(label.id);
            rects.insert("class_hold", combo.rect);
            if chosen != current {
                self.send("hold", json!({"step": chosen}));
            }
            let release = ui
                .add_enabled(
                    state.held_step.is_some(),
                    egui::Button::new(ts("class-release")),
                )
                .on_hover_text(ts("class-release.help"));
            rects.insert("class_release", release.rect);
            if release.clicked() {
                self.send("release", json!({}));
            }
        });
        ui.horizontal_wrapped(|ui| {
            let mut paused = state.paused;
            let p = ui
                .toggle_value(&mut paused, ts("class-pause-all"))
                .on_hover_text(ts("class-pause-all.help"));
            rects.insert("class_pause", p.rect);
            if paused != state.paused {
                self.send("pause", json!({"paused": paused}));
            }
            let mut revealed = state.revealed;
            let r = ui
                .toggle_value(&mut revealed, ts("class-reveal"))
                .on_hover_text(ts("class-reveal.help"));
            rects.insert("class_reveal", r.rect);
            if revealed != state.revealed {
                self.send("reveal", json!({"revealed": revealed}));
            }
            let send = ui
                .button(ts("class-send-setting"))
                .on_hover_text(ts("class-send-setting.help"));
            rects.insert("class_send_setting", send.rect);
            if send.clicked() {
                match serde_json::to_value(settings) {
                    Ok(mut v) => {
                        if let Some(o) = v.as_object_mut() {
                            for key in ["seed", "studio", "paused"] {
                                // words: settings keys
                                o.remove(key);
                            }
                        }
                        if v.to_string().len() > 8 * 1024 {
                            self.error = Some(tr("class-setting-too-large"));
                        } else {
                            self.send("send_setting", json!({"setting": v}));
                        }
                    }
                    Err(e) => self.error = Some(e.to_string()),
                }
            }
        });
    }

    fn class_ui(
        &mut self,
        ui: &mut egui::Ui,
        view: &crate::class::view::ClassView,
        rects: &mut WidgetRects,
    ) {
        let name = |s: &crate::class::view::StudentRecord| match &s.nickname {
            Some(n) => n.clone(),
            None => tr!("class-student-n", n = s.join_order),
        };
        let (counts, _) = stats::step_counts(&view.roster);
        ui.label(egui::RichText::new(tr!("class-roster", count = view.roster.len())).strong());
        ui.label(tr!(
            "class-step-counts",
            look = counts[0],
            predict = counts[1],
            run = counts[2],
            explain = counts[3]
        ));
        let grid = egui::Grid::new("class_roster")
            .striped(true)
            .show(ui, |ui| {
                ui.label(egui::RichText::new(ts("class-col-student")).strong());
                ui.label(egui::RichText::new(ts("class-col-step")).strong());
                ui.label(egui::RichText::new(ts("class-col-prediction")).strong());
                ui.label(egui::RichText::new(ts("class-col-runs")).strong());
                ui.end_row();
                for s in &view.roster {
                    ui.label(name(s));
                    ui.label(s.step.as_deref().map_or("–", step_name));
                    ui.label(s.prediction.as_deref().map_or("–", prediction_words));
                    ui.label(s.runs.unwrap_or(s.results.len()).to_string());
                    ui.end_row();
                }
            });
        rects.insert("class_roster", grid.response.rect);
        ui.separator();
        ui.label(egui::RichText::new(ts("class-predictions")).strong());
        ui.label(
            egui::RichText::new(if view.state.revealed {
                ts("class-predictions-revealed")
            } else {
                ts("class-predictions-hidden")
            })
            .weak(),
        );
        let h = ui.scope(|ui| histogram_ui(ui, &view.histogram)).response;
        rects.insert("class_histogram", h.rect);
        ui.separator();
        ui.label(egui::RichText::new(ts("class-pooled")).strong());
        let pooled = stats::pooled(&view.roster);
        if pooled.is_empty() {
            ui.label(ts("class-pooled-none"));
        }
        let p = ui
            .scope(|ui| {
                for m in &pooled {
                    pooled_ui(ui, m);
                }
            })
            .response;
        rects.insert("class_pooled", p.rect);
        ui.separator();
        ui.horizontal(|ui| {
            ui.label(egui::RichText::new(ts("class-answers")).strong());
            let mut anon = view.anonymise;
            let a = ui
                .checkbox(&mut anon, ts("class-anonymise"))
                .on_hover_text(ts("class-anonymise.help"));
            rects.insert("class_anonymise", a.rect);
            if anon != view.anonymise {
                self.send("anonymise", json!({"on": anon}));
            }
        });
        let mut any = false;
        for s in &view.roster {
            if let Some(answer) = s.answer.as_deref().filter(|a| !a.trim().is_empty()) {
                any = true;
                ui.label(egui::RichText::new(name(s)).strong());
                // Plain text: whatever was typed is shown as typed.
                ui.label(answer);
            }
        }
        if !any {
            ui.label(ts("class-answers-none"));
        }
    }

    fn data_ui(&mut self, ui: &mut egui::Ui, code: &str, token: &str, rects: &mut WidgetRects) {
        ui.horizontal_wrapped(|ui| {
            let csv = ui
                .button(ts("class-download"))
                .on_hover_text(ts("class-download.help"));
            rects.insert("class_download", csv.rect);
            if csv.clicked() {
                #[cfg(target_arch = "wasm32")]
                {
                    self.net.csv = Some(net::fetch(
                        ui.ctx(),
                        "GET",
                        &format!("/api/classes/{code}/csv"),
                        None,
                        Some(token),
                    ));
                }
            }
            let delete = ui
                .button(ts("class-delete"))
                .on_hover_text(ts("class-delete.help"));
            rects.insert("class_delete", delete.rect);
            if delete.clicked() {
                self.confirm_delete = true;
            }
            let leave = ui
                .button(ts("class-leave"))
                .on_hover_text(ts("class-leave.help"));
            if leave.clicked() {
                self.leave();
            }
        });
        if self.confirm_delete {
            ui.colored_label(ui.visuals().warn_fg_color, ts("class-delete-confirm"));
            ui.horizontal(|ui| {
                let yes = ui.button(ts("class-delete-yes"));
                rects.insert("class_delete_yes", yes.rect);
                if yes.clicked() {
                    self.confirm_delete = false;
                    #[cfg(target_arch = "wasm32")]
                    {
                        self.net.delete = Some(net::fetch(
                            ui.ctx(),
                            "DELETE",
                            &format!("/api/classes/{code}"),
                            None,
                            Some(token),
                        ));
                    }
                }
                if ui.button(ts("class-delete-no")).clicked() {
                    self.confirm_delete = false;
                }
            });
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = (code, token);
        if let Some(e) = &self.error {
            ui.colored_label(ui.visuals().error_fg_color, e);
        }
    }
}

#[cfg(target_arch = "wasm32")]
impl ClassPanel {
    fn net_frame(&mut self, ctx: &egui::Context, now: f64, actions: &mut Vec<ClassAction>) {
        // Is this a class server? Asked once.
        if self.server.is_none() {
            match &self.net.info {
                None => self.net.info = Some(net::fetch(ctx, "GET", "api/info", None, None)),
                Some(reply) => {
                    let answer = reply.borrow_mut().take();
                    if let Some(answer) = answer {
                        let kept = self.session.is_some();
                        // No answer at all (the network is down) with a class
                        // this browser kept: it is the class server, offline;
                        // the work goes on and waits to be sent.
                        self.server = Some(match answer {
                            Ok((200, body)) => crate::class::view::is_class_server(&body),
                            Ok(_) => false,
                            Err(_) => kept,
                        });
                        self.net.info = None;
                        if self.server == Some(false) {
                            self.session = None;
                        }
                    }
                }
            }
            return;
        }
        if !self.available() {
            return;
        }
        self.started(ctx);
        self.downloads(actions);
        let Some(s) = &mut self.session else {
            return;
        };
        if s.should_connect(now) {
            s.connecting();
            match net::Socket::open(ctx) {
                Ok(socket) => self.net.socket = Some(socket),
                Err(_) => s.on_close(now),
            }
        }
        let events = self
            .net
            .socket
            .as_ref()
            .map(net::Socket::drain)
            .unwrap_or_default();
        let mut out = Vec::new();
        let mut closed = false;
        for event in events {
            match event {
                net::SocketEvent::Open => out.extend(s.on_open()),
                net::SocketEvent::Message(text) => out.extend(s.on_message(&text, now)),
                net::SocketEvent::Closed => {
                    s.on_close(now);
                    closed = true;
                }
            }
        }
        out.extend(s.poll(now));
        if closed {
            self.net.socket = None;
        } else if let Some(socket) = &self.net.socket {
            for frame in out {
                socket.send(&frame);
            }
        }
        let s = self.session.as_ref();
        if s.is_some_and(|s| s.link() == Link::Closed || s.link() == Link::Connecting) {
            // Wake up for the next attempt even if nothing else happens.
            ctx.request_repaint_after(std::time::Duration::from_millis(500));
        }
    }

    fn started(&mut self, ctx: &egui::Context) {
        let Some(answer) = self
            .net
            .starting
            .as_ref()
            .and_then(|(r, _)| r.borrow_mut().take())
        else {
            return;
        };
        self.net.starting = None;
        match answer {
            Ok((201, body)) => match serde_json::from_str::<crate::class::view::Started>(&body) {
                Ok(started) => {
                    self.error = None;
                    self.session = Some(Session::new(
                        Who::Teacher(Teacher {
                            code: started.code,
                            token: started.teacher_token,
                        }),
                        &prefix(),
                    ));
                    self.start_open = false;
                    self.dashboard_open = true;
                    ctx.request_repaint();
                }
                Err(e) => self.error = Some(tr!("class-start-failed", reason = e.to_string())),
            },
            Ok((status, body)) => {
                self.error = Some(tr!(
                    "class-start-failed",
                    reason = format!("{status} {body}")
                ));
            }
            Err(e) => self.error = Some(tr!("class-start-failed", reason = e)),
        }
    }

    fn downloads(&mut self, actions: &mut Vec<ClassAction>) {
        let csv = self.net.csv.as_ref().and_then(|r| r.borrow_mut().take());
        if let Some(answer) = csv {
            match answer {
                Ok((200, csv)) => {
                    let name = format!(
                        "shoal-class-{}.csv",
                        self.session.as_ref().map_or("", Session::code)
                    ); // words: a file name
                    match super::save_text_file(
                        &name,
                        "text/csv",
                        &csv,
                        Some(ts("notice-csv-next")),
                    ) {
                        Ok(message) => actions.push(ClassAction::Notice(Notice::info(message))),
                        Err(e) => self.error = Some(e.to_string()),
                    }
                }
                Ok((status, body)) => {
                    self.error = Some(tr!(
                        "class-download-failed",
                        reason = format!("{status} {body}")
                    ));
                }
                Err(e) => self.error = Some(tr!("class-download-failed", reason = e)),
            }
            self.net.csv = None;
        }
        let deleted = self.net.delete.as_ref().and_then(|r| r.borrow_mut().take());
        if let Some(answer) = deleted {
            self.net.delete = None;
            match answer {
                Ok((204, _)) => {
                    actions.push(ClassAction::Notice(Notice::info(tr("class-deleted"))));
                    self.leave();
                }
                Ok((status, body)) => {
                    self.error = Some(tr!(
                        "class-delete-failed",
                        reason = format!("{status} {body}")
                    ));
                }
                Err(e) => self.error = Some(tr!("class-delete-failed", reason = e)),
            }
        }
    }
}

/// A random id prefix (the browser's random numbers), or a fixed one natively
/// where no class is ever joined.
fn prefix() -> String {
    #[cfg(target_arch = "wasm32")]
    {
        net::random_prefix()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        "native".to_owned() // words: an id prefix
    }
}

/// A step's name in the language in force.
fn step_name(step: &str) -> &'static str {
    match step {
        "look" => ts("class-step-look"),
        "predict" => ts("class-step-predict"),
        "run" => ts("class-step-run"),
        "explain" => ts("class-step-explain"),
        _ => "?",
    }
}

/// "Connected", "Reconnecting in 4 s", "3 messages waiting".
fn status_text(s: &Session, now: f64) -> String {
    let link = match s.link() {
        Link::Connected => tr("class-connected"),
        Link::Connecting => tr("class-connecting"),
        Link::Closed => tr!("class-reconnecting", secs = num(s.retry_in(now).ceil(), 0)),
        Link::Ended => tr("class-link-ended"),
    };
    let waiting = s.outbox.len();
    if waiting == 0 {
        tr!("class-status", code = s.code().to_owned(), link = link)
    } else {
        tr!(
            "class-status-waiting",
            code = s.code().to_owned(),
            link = link,
            count = waiting
        )
    }
}

/// A prediction as the reader's language says it: students send the answer's
/// message id (the same in every language); anything else is shown as sent.
fn prediction_words(key: &str) -> &str {
    INVESTIGATIONS
        .iter()
        .flat_map(|i| i.texts())
        .find(|t| t.id() == key)
        .map_or(key, |t| t.text())
}

/// The prediction histogram as labelled bars (the count in words too).
fn histogram_ui(ui: &mut egui::Ui, histogram: &std::collections::BTreeMap<String, u64>) {
    let bars = stats::histogram_bars(histogram);
    if bars.is_empty() {
        ui.label(ts("class-predictions-none"));
        return;
    }
    let most = bars.iter().map(|b| b.1).max().unwrap_or(1).max(1) as f32;
    let width = (ui.available_width() - 40.0).max(80.0);
    for (answer, count) in bars {
        ui.label(prediction_words(&answer));
        ui.horizontal(|ui| {
            let (rect, _) = ui.allocate_exact_size(
                egui::vec2(width * count as f32 / most, 14.0),
                egui::Sense::hover(),
            );
            ui.painter().rect_filled(rect, 2.0, super::palette::BLUE);
            ui.label(count.to_string());
        });
    }
}

/// One pooled measure: every run as a dot on a line from the smallest to the
/// largest value, the mean and its 95 % interval over it, and the numbers.
fn pooled_ui(ui: &mut egui::Ui, m: &stats::Pooled) {
    ui.label(egui::RichText::new(&m.measure).monospace());
    let width = ui.available_width().clamp(120.0, 500.0);
    let (rect, _) = ui.allocate_exact_size(egui::vec2(width, 34.0), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    let (lo, hi) = if m.max > m.min {
        (m.min, m.max)
    } else {
        (m.min - 1.0, m.max + 1.0)
    };
    let x = |v: f64| rect.left() + 8.0 + (rect.width() - 16.0) * ((v - lo) / (hi - lo)) as f32;
    let text = ui.visuals().text_color();
    painter.line_segment(
        [
            egui::pos2(rect.left() + 8.0, rect.bottom() - 6.0),
            egui::pos2(rect.right() - 8.0, rect.bottom() - 6.0),
        ],
        egui::Stroke::new(1.0, ui.visuals().weak_text_color()),
    );
    for (k, v) in m.values.iter().enumerate() {
        // Equal values stack upwards so each run shows.
        let same = m.values[..k].iter().filter(|w| *w == v).count() as f32;
        painter.circle_filled(
            egui::pos2(x(*v), rect.bottom() - 10.0 - 5.0 * same.min(4.0)),
            3.5,
            super::palette::ORANGE,
        );
    }
    if m.low.is_finite() && m.high.is_finite() {
        painter.line_segment(
            [
                egui::pos2(x(m.low), rect.top() + 6.0),
                egui::pos2(x(m.high), rect.top() + 6.0),
            ],
            egui::Stroke::new(3.0, text),
        );
    }
    painter.line_segment(
        [
            egui::pos2(x(m.mean), rect.top()),
            egui::pos2(x(m.mean), rect.top() + 12.0),
        ],
        egui::Stroke::new(2.0, text),
    );
    let words = if m.low.is_finite() {
        tr!(
            "class-pooled-line",
            mean = num(m.mean, 2),
            low = num(m.low, 2),
            high = num(m.high, 2),
            n = m.n,
            students = m.students
        )
    } else {
        tr!(
            "class-pooled-line-one",
            mean = num(m.mean, 2),
            n = m.n,
            students = m.students
        )
    };
    ui.label(words);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_teacher_link_keeps_its_token_in_the_fragment() {
        let link = teacher_link("https://school.example/", "K7QX2M", "ab12");
        assert_eq!(link, "https://school.example/#teacher=K7QX2M.ab12");
        let (_, fragment) = link.split_once('#').unwrap();
        assert_eq!(
            parse_teacher_fragment(fragment),
            Some(("K7QX2M".to_owned(), "ab12".to_owned()))
        );
        assert_eq!(parse_teacher_fragment("#teacher=K7QX2M."), None);
        assert_eq!(parse_teacher_fragment("#teacher=K7QX2M.<script>"), None);
        assert_eq!(parse_teacher_fragment("#v1.abc"), None);
        assert_eq!(
            join_link("https://school.example/", "K7QX2M"),
            "https://school.example/?class=K7QX2M"
        );
    }

    #[test]
    fn without_a_class_server_nothing_of_the_class_shows() {
        let panel = ClassPanel::default();
        assert!(!panel.available());
        assert_eq!(panel.report()["role"], Value::Null);
    }
}
