//! Lessons played by tokio clients over protocol v1 against a real `shoal-class`
//! process: the load harness (`examples/load.rs`) and the kill/restart test
//! (`tests/kill_restart.rs`) share it.
//!
//! Each class: `POST /api/classes`, the teacher connects and holds the class at
//! `predict`; each student joins, sends the steps `look` and `predict`, a
//! prediction, waits for the release, sends `run`, its results, `explain` and an
//! answer; the teacher releases once every prediction is in (and reveals them),
//! and again once every result is in. A client behaves as the app must: it keeps
//! every message until its ack arrives, reconnects by itself when the connection
//! drops (`resume` with its student token, or `teacher` with the teacher token),
//! and resends what was not acknowledged, with the same ids. At the end every
//! class's CSV and the teacher's roster are checked against what the students
//! sent: every row once, none missing, none twice.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, AtomicU32, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use futures_util::{SinkExt, StreamExt};
use rand::Rng;
use serde_json::{json, Value};
use tokio::net::TcpStream;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::{MaybeTlsStream, WebSocketStream};

type Ws = WebSocketStream<MaybeTlsStream<TcpStream>>;

/// What to play.
#[derive(Clone, Debug)]
pub struct Plan {
    pub classes: usize,
    pub students: usize,
    /// Results each student posts (each with two measures: two CSV rows).
    pub results: usize,
    /// A student waits 0..think_ms (uniform) before each message.
    pub think_ms: u64,
    /// Classes start and students join spread over this many milliseconds.
    pub ramp_ms: u64,
    /// Kill the server (SIGKILL) once this fraction of all results is
    /// acknowledged, and start it again on the same database after `down_ms`.
    pub kill_at: Option<f64>,
    pub down_ms: u64,
    /// A client gives up (its unacknowledged messages count as lost) after this.
    pub deadline: Duration,
}

/// How to start the server.
#[derive(Clone, Debug)]
pub struct ServerSpec {
    pub binary: PathBuf,
    pub database: String,
    pub port: u16,
    pub dist: PathBuf,
}

/// The server process, restartable.
pub struct Server {
    spec: ServerSpec,
    child: Child,
}

impl Server {
    /// Starts the binary and waits until it accepts connections.
    pub async fn start(spec: &ServerSpec) -> Result<Server, String> {
        let child = Command::new(&spec.binary)
            .args(["--address", "127.0.0.1", "--port"])
            .arg(spec.port.to_string())
            .arg("--database")
            .arg(&spec.database)
            .arg("--dist")
            .arg(&spec.dist)
            .stdout(Stdio::null())
            .stderr(Stdio::inherit())
            .spawn()
            .map_err(|e| format!("cannot start {}: {e}", spec.binary.display()))?;
        let mut server = Server {
            spec: spec.clone(),
            child,
        };
        let until = Instant::now() + Duration::from_secs(60);
        loop {
            if TcpStream::connect(("127.0.0.1", spec.port)).await.is_ok() {
                return Ok(server);
            }
            if let Ok(Some(status)) = server.child.try_wait() {
                return Err(format!("the server exited at start: {status}"));
            }
            if Instant::now() > until {
                return Err("the server did not listen within 60 s".into());
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    }

    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// SIGKILL, and wait for the process to be gone.
    pub fn kill(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }

    pub async fn restart(&mut self) -> Result<(), String> {
        self.kill();
        let fresh = Server::start(&self.spec).await?;
        *self = fresh;
        Ok(())
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.kill();
    }
}

/// `VmRSS` and `VmHWM` (peak) of a process, in KiB, from /proc.
pub fn memory_kib(pid: u32) -> Option<(u64, u64)> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let field = |name: &str| {
        status
            .lines()
            .find(|l| l.starts_with(name))
            .and_then(|l| l.split_whitespace().nth(1))
            .and_then(|v| v.parse::<u64>().ok())
    };
    Some((field("VmRSS:")?, field("VmHWM:")?))
}

/// A free TCP port on 127.0.0.1.
pub fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .map(|a| a.port())
        .unwrap_or(18080)
}

/// Shared counters of one run.
#[derive(Default)]
pub struct Stats {
    /// (message type, latency from first send to ack, resent across a reconnect)
    samples: Mutex<Vec<(&'static str, Duration, bool)>>,
    /// Sent and not yet acknowledged, now.
    in_flight: AtomicUsize,
    result_acks: AtomicUsize,
    /// Successful reconnects (after the first connection).
    reconnects: AtomicUsize,
    errors: Mutex<BTreeMap<String, usize>>,
    lost: AtomicUsize,
    failures: Mutex<Vec<String>>,
    /// Milliseconds since the run's start of the last reconnect.
    last_back_ms: AtomicU64,
    start: Mutex<Option<Instant>>,
}

impl Stats {
    fn error(&self, code: &str) {
        *self
            .errors
            .lock()
            .unwrap()
            .entry(code.to_owned())
            .or_insert(0) += 1;
    }
    fn fail(&self, what: String) {
        self.failures.lock().unwrap().push(what);
    }
}

struct Pending {
    id: String,
    kind: &'static str,
    msg: String,
    first_sent: Instant,
    reconnects_at_send: usize,
    retry_at: Option<Instant>,
}

/// One client connection that survives its server: see the module comment.
struct Agent {
    url: String,
    ws: Option<Ws>,
    /// The message saying who this is (`join` until joined, then `resume`; or `teacher`).
    hello: Value,
    pending: Vec<Pending>,
    view: Value,
    next_id: usize,
    connected_once: bool,
    reconnects: usize,
    stats: Arc<Stats>,
    deadline: Instant,
}

fn re_of(v: &Value) -> Option<&str> {
    v.get("re").and_then(Value::as_str)
}

impl Agent {
    fn new(url: &str, hello: Value, stats: Arc<Stats>, deadline: Instant) -> Agent {
        Agent {
            url: url.to_owned(),
            ws: None,
            hello,
            pending: Vec::new(),
            view: Value::Null,
            next_id: 0,
            connected_once: false,
            reconnects: 0,
            stats,
            deadline,
        }
    }

    /// Connects (retrying until the deadline), says hello until answered, and
    /// resends every unacknowledged message. Returns the hello's answer.
    async fn connect(&mut self) -> Result<Value, String> {
        let first = !self.connected_once;
        let mut backoff = Duration::from_millis(50);
        loop {
            if Instant::now() > self.deadline {
                return Err("could not reconnect before the deadline".into());
            }
            // A small read buffer (tungstenite zeroes its 128 KiB default on
            // every read: 1,440 clients would spend the cores the server needs)
            // and no Nagle delay, as a browser's WebSocket.
            let config = tokio_tungstenite::tungstenite::protocol::WebSocketConfig::default()
                .read_buffer_size(4 * 1024);
            let mut ws = match tokio_tungstenite::connect_async_with_config(
                self.url.as_str(),
                Some(config),
                true,
            )
            .await
            {
                Ok((ws, _)) => ws,
                Err(_) => {
                    tokio::time::sleep(backoff).await;
                    backoff = (backoff * 2).min(Duration::from_millis(400));
                    continue;
                }
            };
            let sent = Instant::now();
            if ws
                .send(Message::text(self.hello.to_string()))
                .await
                .is_err()
            {
                continue;
            }
            let hello_id = self.hello["id"].as_str().unwrap_or("").to_owned();
            // Wait for the hello's answer; views may not come before it.
            let answer = loop {
                let next = tokio::time::timeout(Duration::from_secs(30), ws.next()).await;
                match next {
                    Ok(Some(Ok(Message::Text(t)))) => {
                        let v: Value = serde_json::from_str(t.as_str()).unwrap_or(Value::Null);
                        if re_of(&v) == Some(hello_id.as_str()) {
                            break Some(v);
                        }
                    }
                    Ok(Some(Ok(_))) => {}
                    _ => break None,
                }
            };
            let Some(answer) = answer else {
                tokio::time::sleep(backoff).await;
                continue;
            };
            if answer["type"] == "error" {
                let code = answer["code"].as_str().unwrap_or("?").to_owned();
                self.stats.error(&code);
                if code == "internal" || code == "rate_limited" {
                    tokio::time::sleep(Duration::from_millis(200)).await;
                    continue;
                }
                return Err(format!("hello refused: {answer}"));
            }
            self.connected_once = true;
            let kind = if first { "hello" } else { "resume" };
            self.stats
                .samples
                .lock()
                .unwrap()
                .push((kind, sent.elapsed(), false));
            if !first {
                self.reconnects += 1;
                self.stats.reconnects.fetch_add(1, Ordering::SeqCst);
                let start = self
                    .stats
                    .start
                    .lock()
                    .unwrap()
                    .unwrap_or_else(Instant::now);
                self.stats
                    .last_back_ms
                    .fetch_max(start.elapsed().as_millis() as u64, Ordering::SeqCst);
            }
            for p in &mut self.pending {
                p.retry_at = None;
                if ws.send(Message::text(p.msg.clone())).await.is_err() {
                    break;
                }
            }
            self.ws = Some(ws);
            return Ok(answer);
        }
    }

    async fn send(&mut self, kind: &'static str, mut body: Value) {
        self.next_id += 1;
        let id = format!("m{}", self.next_id);
        body["v"] = json!(1);
        body["id"] = json!(id);
        let msg = body.to_string();
        self.stats.in_flight.fetch_add(1, Ordering::SeqCst);
        self.pending.push(Pending {
            id,
            kind,
            msg: msg.clone(),
            first_sent: Instant::now(),
            reconnects_at_send: self.reconnects,
            retry_at: None,
        });
        if let Some(ws) = &mut self.ws {
            if ws.send(Message::text(msg)).await.is_err() {
                self.ws = None;
            }
        }
    }

    fn handle(&mut self, v: Value) {
        match v["type"].as_str() {
            Some("ack") | Some("joined") => {
                let Some(re) = re_of(&v) else { return };
                if let Some(i) = self.pending.iter().position(|p| p.id == re) {
                    let p = self.pending.remove(i);
                    self.stats.in_flight.fetch_sub(1, Ordering::SeqCst);
                    if p.kind == "result" {
                        self.stats.result_acks.fetch_add(1, Ordering::SeqCst);
                    }
                    self.stats.samples.lock().unwrap().push((
                        p.kind,
                        p.first_sent.elapsed(),
                        p.reconnects_at_send != self.reconnects,
                    ));
                }
            }
            Some("error") => {
                let code = v["code"].as_str().unwrap_or("?").to_owned();
                self.stats.error(&code);
                let Some(re) = re_of(&v) else { return };
                if let Some(i) = self.pending.iter().position(|p| p.id == re) {
                    if code == "internal" || code == "rate_limited" {
                        // The protocol's advice: resend later, with the same id.
                        self.pending[i].retry_at =
                            Some(Instant::now() + Duration::from_millis(200));
                    } else {
                        let p = self.pending.remove(i);
                        self.stats.in_flight.fetch_sub(1, Ordering::SeqCst);
                        self.stats
                            .fail(format!("{} refused: {v} (sent {})", p.kind, p.msg));
                    }
                }
            }
            Some("you") | Some("class") => self.view = v,
            _ => {}
        }
    }

    /// Reads messages (reconnecting and resending as needed) until `done(self)`
    /// or `until`. Returns whether `done` became true.
    async fn pump(
        &mut self,
        done: &(dyn Fn(&Agent) -> bool + Sync),
        until: Instant,
    ) -> Result<bool, String> {
        loop {
            if done(self) {
                return Ok(true);
            }
            let now = Instant::now();
            if now >= until || now >= self.deadline {
                return Ok(false);
            }
            if self.ws.is_none() {
                self.connect().await?;
                continue;
            }
            let due: Vec<String> = self
                .pending
                .iter()
                .filter(|p| p.retry_at.is_some_and(|t| t <= now))
                .map(|p| p.msg.clone())
                .collect();
            for p in &mut self.pending {
                if p.retry_at.is_some_and(|t| t <= now) {
                    p.retry_at = None;
                }
            }
            let ws = self.ws.as_mut().expect("connected");
            for msg in due {
                if ws.send(Message::text(msg)).await.is_err() {
                    self.ws = None;
                    break;
                }
            }
            let Some(ws) = self.ws.as_mut() else { continue };
            let wait = until
                .min(now + Duration::from_millis(100))
                .saturating_duration_since(now);
            match tokio::time::timeout(wait, ws.next()).await {
                Err(_) => {}
                Ok(Some(Ok(Message::Text(t)))) => {
                    if let Ok(v) = serde_json::from_str::<Value>(t.as_str()) {
                        self.handle(v);
                    }
                }
                Ok(Some(Ok(_))) => {}
                Ok(Some(Err(_))) | Ok(None) => self.ws = None,
            }
        }
    }

    async fn acked(&mut self) -> Result<(), String> {
        if self.pump(&|a| a.pending.is_empty(), self.deadline).await? {
            Ok(())
        } else {
            Err(format!(
                "{} messages never acknowledged",
                self.pending.len()
            ))
        }
    }

    async fn think(&mut self, max_ms: u64) -> Result<(), String> {
        let ms = if max_ms == 0 {
            0
        } else {
            rand::thread_rng().gen_range(0..max_ms)
        };
        self.pump(&|_| false, Instant::now() + Duration::from_millis(ms))
            .await
            .map(|_| ())
    }

    fn close(mut self) {
        let lost = self.pending.len();
        if lost > 0 {
            self.stats.lost.fetch_add(lost, Ordering::SeqCst);
            self.stats.in_flight.fetch_sub(
                lost.min(self.stats.in_flight.load(Ordering::SeqCst)),
                Ordering::SeqCst,
            );
        }
        self.ws = None;
    }
}

/// What one student sent, to check the CSV against.
#[derive(Clone, Debug)]
struct Sent {
    join_order: i64,
    nickname: String,
    prediction: String,
    answer: String,
    /// (school level, measure, value)
    rows: Vec<(u8, &'static str, f64)>,
}

const MEASURES: [&str; 2] = ["lost", "eaten"];

fn held_at(view: &Value) -> Option<String> {
    view.pointer("/state/held_step")
        .and_then(Value::as_str)
        .map(str::to_owned)
}

async fn student(
    url: String,
    code: String,
    index: usize,
    plan: Plan,
    stats: Arc<Stats>,
    everyone_done: Arc<AtomicBool>,
    deadline: Instant,
) -> Result<Sent, String> {
    let nickname = format!("Fish {index}");
    let hello = json!({"v": 1, "id": "join", "type": "join", "code": code, "nickname": nickname});
    let mut a = Agent::new(&url, hello, stats.clone(), deadline);
    let joined = a.connect().await?;
    let token = joined["student_token"].as_str().unwrap_or("").to_owned();
    let join_order = joined["join_order"].as_i64().unwrap_or(-1);
    a.hello =
        json!({"v": 1, "id": "resume", "type": "resume", "code": code, "student_token": token});
    let prediction = ["fewer", "about the same", "more"][index % 3].to_owned();
    let answer = format!("The school saw the shark sooner ({nickname}).");
    let outcome = async {
        a.think(plan.think_ms).await?;
        a.send("step", json!({"type": "step", "step": "look"}))
            .await;
        a.think(plan.think_ms).await?;
        a.send("step", json!({"type": "step", "step": "predict"}))
            .await;
        a.think(plan.think_ms).await?;
        a.send(
            "predict",
            json!({"type": "predict", "prediction": prediction}),
        )
        .await;
        a.acked().await?;
        let released = |a: &Agent| held_at(&a.view).as_deref() != Some("predict");
        if !a.pump(&released, deadline).await? {
            return Err("never released from predict".to_string());
        }
        a.think(plan.think_ms).await?;
        a.send("step", json!({"type": "step", "step": "run"})).await;
        let mut rows = Vec::new();
        for r in 0..plan.results {
            a.think(plan.think_ms).await?;
            let school = ((join_order as usize + r) % 2) as u8;
            let mut values = serde_json::Map::new();
            for (m, measure) in MEASURES.iter().enumerate() {
                // Unique per student, result and measure: a duplicate or a
                // missing row shows in the CSV.
                let value = (join_order * 10_000) as f64 + (r * 10 + m) as f64;
                values.insert((*measure).to_owned(), json!(value));
                rows.push((school, *measure, value));
            }
            a.send(
                "result",
                json!({"type": "result", "levels": {"school": school}, "values": values}),
            )
            .await;
        }
        a.acked().await?;
        let released =
            |a: &Agent| !matches!(held_at(&a.view).as_deref(), Some("predict") | Some("run"));
        if !a.pump(&released, deadline).await? {
            return Err("never released from run".to_string());
        }
        a.think(plan.think_ms).await?;
        a.send("step", json!({"type": "step", "step": "explain"}))
            .await;
        a.think(plan.think_ms).await?;
        a.send("explain", json!({"type": "explain", "answer": answer}))
            .await;
        a.acked().await?;
        // Stay connected (and reconnect) until every class is done.
        let done = everyone_done.clone();
        a.pump(&move |_| done.load(Ordering::SeqCst), deadline)
            .await?;
        Ok(rows)
    }
    .await;
    a.close();
    Ok(Sent {
        join_order,
        nickname,
        prediction,
        answer,
        rows: outcome?,
    })
}

fn roster(view: &Value) -> Vec<Value> {
    view["roster"].as_array().cloned().unwrap_or_default()
}

async fn teacher(
    url: String,
    code: String,
    token: String,
    plan: Plan,
    stats: Arc<Stats>,
    everyone_done: Arc<AtomicBool>,
    deadline: Instant,
) -> Result<(), String> {
    let hello =
        json!({"v": 1, "id": "hello", "type": "teacher", "code": code, "teacher_token": token});
    let mut a = Agent::new(&url, hello, stats, deadline);
    a.connect().await?;
    let n = plan.students;
    let outcome = async {
        // Held before the first student joins (the caller waits for this).
        a.send("teacher", json!({"type": "hold", "step": "predict"}))
            .await;
        a.acked().await?;
        Ok::<(), String>(())
    }
    .await;
    if let Err(e) = outcome {
        a.close();
        return Err(e);
    }
    tokio::spawn(async move {
        let outcome = async {
            let all_predicted = |a: &Agent| {
                let r = roster(&a.view);
                r.len() == n && r.iter().all(|s| s["prediction"].is_string())
            };
            if !a.pump(&all_predicted, deadline).await? {
                return Err("not every prediction arrived".to_string());
            }
            a.send("teacher", json!({"type": "reveal", "revealed": true}))
                .await;
            a.send("teacher", json!({"type": "release"})).await;
            let all_results = |a: &Agent| {
                roster(&a.view).iter().all(|s| {
                    s["results"].as_array().map_or(0, Vec::len) == plan.results * MEASURES.len()
                })
            };
            if !a.pump(&all_results, deadline).await? {
                return Err("not every result arrived".to_string());
            }
            a.send("teacher", json!({"type": "release"})).await;
            let all_explained = |a: &Agent| {
                a.pending.is_empty() && roster(&a.view).iter().all(|s| s["answer"].is_string())
            };
            if !a.pump(&all_explained, deadline).await? {
                return Err("not every answer arrived".to_string());
            }
            // Stay connected (and reconnect) until every class is done.
            a.pump(&move |_| everyone_done.load(Ordering::SeqCst), deadline)
                .await?;
            Ok(())
        }
        .await;
        if let Err(e) = &outcome {
            a.stats.fail(format!("teacher of {}: {e}", a.hello["code"]));
        }
        a.close();
    });
    Ok(())
}

/// One run's figures.
#[derive(Debug, Default)]
pub struct Report {
    pub connections: usize,
    pub messages: usize,
    pub wall: Duration,
    /// Over every message not resent across a reconnect: (p50, p99, max).
    pub latency: (Duration, Duration, Duration),
    /// Per message type: (count, p50, p99, max).
    pub by_kind: BTreeMap<&'static str, (usize, Duration, Duration, Duration)>,
    pub errors: BTreeMap<String, usize>,
    pub lost: usize,
    /// Problems found: CSV rows missing or twice, wrong roster, refused messages.
    pub failures: Vec<String>,
    pub csv_rows: usize,
    pub csv_rows_expected: usize,
    pub rss_idle_kib: u64,
    pub rss_peak_kib: u64,
    pub kill: Option<KillReport>,
}

#[derive(Debug, Default)]
pub struct KillReport {
    /// Messages sent and not yet acknowledged when the server died.
    pub in_flight: usize,
    pub results_acked_before: usize,
    pub reconnects: usize,
    /// From the kill until the last client was back (hello answered).
    pub all_back: Duration,
    /// From the restart (listening again) until the last client was back.
    pub back_after_restart: Duration,
    /// Messages acknowledged only after a reconnect, and their longest wait.
    pub resent_acked: usize,
    pub resent_max: Duration,
}

fn percentile(sorted: &[Duration], p: f64) -> Duration {
    if sorted.is_empty() {
        return Duration::ZERO;
    }
    let i = ((sorted.len() as f64 * p).ceil() as usize).clamp(1, sorted.len()) - 1;
    sorted[i]
}

/// Plays `plan` against a server started from `spec`.
pub async fn run(plan: &Plan, spec: &ServerSpec) -> Result<Report, String> {
    let mut server = Server::start(spec).await?;
    tokio::time::sleep(Duration::from_millis(300)).await;
    let rss_idle_kib = memory_kib(server.pid()).map_or(0, |m| m.0);
    let pid = Arc::new(AtomicU32::new(server.pid()));
    let peak = Arc::new(AtomicU64::new(0));
    let sampling = Arc::new(AtomicBool::new(true));
    {
        let (pid, peak, sampling) = (pid.clone(), peak.clone(), sampling.clone());
        tokio::spawn(async move {
            while sampling.load(Ordering::SeqCst) {
                if let Some((_, hwm)) = memory_kib(pid.load(Ordering::SeqCst)) {
                    peak.fetch_max(hwm, Ordering::SeqCst);
                }
                tokio::time::sleep(Duration::from_millis(100)).await;
            }
        });
    }

    let base = format!("http://127.0.0.1:{}", spec.port);
    let url = format!("ws://127.0.0.1:{}/ws", spec.port);
    let http = reqwest::Client::new();
    let stats = Arc::new(Stats::default());
    let started = Instant::now();
    *stats.start.lock().unwrap() = Some(started);
    let deadline = started + plan.deadline;
    let everyone_done = Arc::new(AtomicBool::new(false));
    let mut classes = Vec::new();
    let mut students = Vec::new();
    for c in 0..plan.classes {
        let delay = plan.ramp_ms * c as u64 / plan.classes.max(1) as u64;
        let (plan, stats, url, base, http, done) = (
            plan.clone(),
            stats.clone(),
            url.clone(),
            base.clone(),
            http.clone(),
            everyone_done.clone(),
        );
        let (tx, rx) = tokio::sync::oneshot::channel();
        classes.push(rx);
        students.push(tokio::spawn(async move {
            tokio::time::sleep(Duration::from_millis(delay)).await;
            let sent = Instant::now();
            let started: Value = http
                .post(format!("{base}/api/classes"))
                .json(&json!({"setup": {"investigation": "why-school"}}))
                .send()
                .await
                .map_err(|e| e.to_string())?
                .json()
                .await
                .map_err(|e| e.to_string())?;
            stats
                .samples
                .lock()
                .unwrap()
                .push(("start", sent.elapsed(), false));
            let code = started["code"].as_str().unwrap_or("").to_owned();
            let token = started["teacher_token"].as_str().unwrap_or("").to_owned();
            let _ = tx.send((code.clone(), token.clone()));
            teacher(
                url.clone(),
                code.clone(),
                token,
                plan.clone(),
                stats.clone(),
                done.clone(),
                deadline,
            )
            .await?;
            let mut joins = Vec::new();
            for s in 0..plan.students {
                let wait = rand::thread_rng().gen_range(0..plan.ramp_ms.max(1));
                let (url, code, plan, stats, done) = (
                    url.clone(),
                    code.clone(),
                    plan.clone(),
                    stats.clone(),
                    done.clone(),
                );
                joins.push(tokio::spawn(async move {
                    tokio::time::sleep(Duration::from_millis(wait)).await;
                    student(url, code, s + 1, plan, stats, done, deadline).await
                }));
            }
            let mut sent = Vec::new();
            for j in joins {
                sent.push(j.await.map_err(|e| e.to_string())?);
            }
            Ok::<Vec<Result<Sent, String>>, String>(sent)
        }));
    }

    // The killer: once enough results are acknowledged, SIGKILL and restart.
    let mut kill = None;
    if let Some(fraction) = plan.kill_at {
        let total = plan.classes * plan.students * plan.results;
        let threshold = ((total as f64 * fraction).ceil() as usize).max(1);
        while stats.result_acks.load(Ordering::SeqCst) < threshold {
            if Instant::now() > deadline {
                return Err("the kill point was never reached".into());
            }
            tokio::time::sleep(Duration::from_millis(2)).await;
        }
        server.kill();
        let killed = Instant::now();
        let in_flight = stats.in_flight.load(Ordering::SeqCst);
        let results_acked_before = stats.result_acks.load(Ordering::SeqCst);
        let reconnects_before = stats.reconnects.load(Ordering::SeqCst);
        tokio::time::sleep(Duration::from_millis(plan.down_ms)).await;
        server.restart().await?;
        let restarted = Instant::now();
        pid.store(server.pid(), Ordering::SeqCst);
        // Every live client (all of them stay connected until the end) comes back.
        let clients = plan.classes * (plan.students + 1);
        while stats.reconnects.load(Ordering::SeqCst) - reconnects_before < clients {
            if Instant::now() > deadline {
                break;
            }
            tokio::time::sleep(Duration::from_millis(5)).await;
        }
        let back = started + Duration::from_millis(stats.last_back_ms.load(Ordering::SeqCst));
        kill = Some(KillReport {
            in_flight,
            results_acked_before,
            reconnects: stats.reconnects.load(Ordering::SeqCst) - reconnects_before,
            all_back: back.saturating_duration_since(killed),
            back_after_restart: back.saturating_duration_since(restarted),
            ..Default::default()
        });
    }

    let mut codes = Vec::new();
    for rx in classes {
        codes.push(rx.await.map_err(|_| "a class never started".to_string())?);
    }
    // Wait for every student's lesson, then for every teacher to see it all.
    let mut all_sent: Vec<Vec<Result<Sent, String>>> = Vec::new();
    // Students finish their lesson and then wait for `everyone_done`: release
    // them once every student has acknowledged its answer.
    let total_students = plan.classes * plan.students;
    let explains_needed = total_students;
    loop {
        let explained = stats
            .samples
            .lock()
            .unwrap()
            .iter()
            .filter(|s| s.0 == "explain")
            .count();
        if explained >= explains_needed || Instant::now() > deadline {
            break;
        }
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    let wall = started.elapsed();
    let connected_rss = memory_kib(pid.load(Ordering::SeqCst)).map_or(0, |m| m.0);
    everyone_done.store(true, Ordering::SeqCst);
    for s in students {
        match s.await {
            Ok(Ok(sent)) => all_sent.push(sent),
            Ok(Err(e)) => stats.fail(format!("class: {e}")),
            Err(e) => stats.fail(format!("class task: {e}")),
        }
    }
    sampling.store(false, Ordering::SeqCst);
    let rss_peak_kib = memory_kib(server.pid())
        .map_or(0, |m| m.1)
        .max(peak.load(Ordering::SeqCst))
        .max(connected_rss);

    // Check every class's CSV and roster against what its students sent.
    let mut csv_rows = 0;
    let mut csv_rows_expected = 0;
    for ((code, token), sent) in codes.iter().zip(&all_sent) {
        let mut expected: BTreeMap<(i64, String, String), usize> = BTreeMap::new();
        let mut by_order = BTreeMap::new();
        for s in sent {
            match s {
                Ok(s) => {
                    by_order.insert(s.join_order, s.clone());
                    for (school, measure, value) in &s.rows {
                        *expected
                            .entry((s.join_order, (*measure).to_owned(), format!("{value}")))
                            .or_insert(0) += 1;
                        let _ = school;
                    }
                }
                Err(e) => stats.fail(format!("student of {code}: {e}")),
            }
        }
        csv_rows_expected += plan.students * plan.results * MEASURES.len();
        let csv = http
            .get(format!("{base}/api/classes/{code}/csv"))
            .bearer_auth(token)
            .send()
            .await
            .map_err(|e| e.to_string())?
            .text()
            .await
            .map_err(|e| e.to_string())?;
        let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
        let header = lines.next().unwrap_or("");
        if header != "student,nickname,seed,school,prediction,measure,value" {
            stats.fail(format!("{code}: CSV header {header:?}"));
        }
        let mut seen: BTreeMap<(i64, String, String), usize> = BTreeMap::new();
        for line in lines {
            csv_rows += 1;
            let f: Vec<&str> = line.split(',').collect();
            if f.len() != 7 {
                stats.fail(format!("{code}: CSV row {line:?}"));
                continue;
            }
            let order: i64 = f[0].parse().unwrap_or(-1);
            match by_order.get(&order) {
                Some(s) if s.nickname == f[1] && s.prediction == f[4] => {
                    let school = s
                        .rows
                        .iter()
                        .find(|r| r.1 == f[5] && format!("{}", r.2) == f[6])
                        .map(|r| r.0.to_string());
                    if school.as_deref() != Some(f[3]) {
                        stats.fail(format!("{code}: CSV row {line:?} was not sent"));
                    }
                }
                _ => stats.fail(format!("{code}: CSV row {line:?} names no such student")),
            }
            *seen
                .entry((order, f[5].to_owned(), f[6].to_owned()))
                .or_insert(0) += 1;
        }
        if seen != expected {
            let missing = expected.keys().filter(|k| !seen.contains_key(*k)).count();
            let twice = seen.values().filter(|n| **n > 1).count();
            stats.fail(format!(
                "{code}: CSV has {} rows, {missing} missing, {twice} twice",
                seen.values().sum::<usize>()
            ));
        }
        // The roster from a fresh teacher connection.
        let hello =
            json!({"v": 1, "id": "check", "type": "teacher", "code": code, "teacher_token": token});
        let mut a = Agent::new(
            &url,
            hello,
            stats.clone(),
            Instant::now() + Duration::from_secs(60),
        );
        a.connect().await?;
        let got_view = a
            .pump(
                &|a| a.view["type"] == "class",
                Instant::now() + Duration::from_secs(30),
            )
            .await?;
        let roster = roster(&a.view);
        if !got_view || roster.len() != plan.students {
            stats.fail(format!("{code}: roster of {} students", roster.len()));
        }
        for r in &roster {
            let order = r["join_order"].as_i64().unwrap_or(-1);
            let ok = by_order.get(&order).is_some_and(|s| {
                r["step"] == "explain"
                    && r["prediction"] == json!(s.prediction)
                    && r["answer"] == json!(s.answer)
            });
            if !ok {
                stats.fail(format!(
                    "{code}: roster entry {order} differs from what was sent"
                ));
            }
        }
        a.close();
    }

    let samples = stats.samples.lock().unwrap().clone();
    let mut fresh: Vec<Duration> = samples
        .iter()
        .filter(|s| !s.2 && s.0 != "resume")
        .map(|s| s.1)
        .collect();
    fresh.sort();
    let mut by_kind = BTreeMap::new();
    let kinds: std::collections::BTreeSet<&'static str> = samples.iter().map(|s| s.0).collect();
    for kind in kinds {
        let mut l: Vec<Duration> = samples
            .iter()
            .filter(|s| s.0 == kind && !s.2)
            .map(|s| s.1)
            .collect();
        l.sort();
        by_kind.insert(
            kind,
            (
                l.len(),
                percentile(&l, 0.5),
                percentile(&l, 0.99),
                l.last().copied().unwrap_or_default(),
            ),
        );
    }
    if let Some(k) = &mut kill {
        let resent: Vec<Duration> = samples.iter().filter(|s| s.2).map(|s| s.1).collect();
        k.resent_acked = resent.len();
        k.resent_max = resent.iter().max().copied().unwrap_or_default();
    }
    let errors = stats.errors.lock().unwrap().clone();
    let failures = stats.failures.lock().unwrap().clone();
    Ok(Report {
        connections: plan.classes * (plan.students + 1),
        messages: samples.iter().filter(|s| s.0 != "resume").count(),
        wall,
        latency: (
            percentile(&fresh, 0.5),
            percentile(&fresh, 0.99),
            fresh.last().copied().unwrap_or_default(),
        ),
        by_kind,
        errors,
        lost: stats.lost.load(Ordering::SeqCst),
        failures,
        csv_rows,
        csv_rows_expected,
        rss_idle_kib,
        rss_peak_kib,
        kill,
    })
}
