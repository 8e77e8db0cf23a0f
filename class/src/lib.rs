//! `shoal-class`: the class server (issue 37). Serves the web app's static
//! files and relays a lesson: `POST /api/classes` starts a class, `/ws` carries
//! protocol v1 (versioned JSON, see docs/class.md), and
//! `GET /api/classes/{code}/csv` gives the teacher the class's tidy CSV.

pub mod db;
pub mod protocol;
mod store;

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use axum::extract::ws::{Message, WebSocket, WebSocketUpgrade};
use axum::extract::{Path, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::{Json, Router};
use serde_json::json;
use sqlx::AnyPool;
use tokio::sync::broadcast;
use tower_http::services::{ServeDir, ServeFile};
use tower_http::set_header::SetResponseHeaderLayer;

use protocol::{ClientMessage, ErrorCode, ServerError, MAX_MESSAGE_BYTES};

/// The Content-Security-Policy of every response.
pub const CSP: &str = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; connect-src 'self'; object-src 'none'; base-uri 'none'; frame-ancestors 'none'";

/// What the server needs besides its database.
#[derive(Clone, Debug)]
pub struct Config {
    /// The Trunk output served at `/`.
    pub dist: PathBuf,
    /// Messages a connection may send in a burst.
    pub burst: f64,
    /// Messages per second a connection may send in the long run.
    pub per_second: f64,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            dist: PathBuf::from("dist"),
            burst: 30.0,
            per_second: 10.0,
        }
    }
}

/// Whose view a change of a class alters: every connection of the class; the
/// teacher's and the connections of one student (their own record); or a
/// prediction: the teacher's, and the students' once the counts are revealed.
#[derive(Clone, Debug)]
pub enum Change {
    Everyone,
    Student(Arc<str>),
    Prediction,
}

impl Change {
    /// Whether a connection playing `role` must send a fresh view; `revealed`:
    /// whether the last view it sent showed the prediction counts.
    fn concerns(&self, role: &Role, revealed: bool) -> bool {
        match (self, role) {
            (Change::Everyone, _) | (_, Role::Teacher { .. }) => true,
            (Change::Student(changed), Role::Student { id, .. }) => **changed == **id,
            (Change::Prediction, Role::Student { .. }) => revealed,
        }
    }
}

/// A live class's copy in memory (`None` until a view needs it). Its lock is
/// held while a message is written, so the copy changes in the database's order.
type Slot = Arc<tokio::sync::Mutex<Option<store::ClassState>>>;

/// Shared state: the pool, one change signal per live class, and each live
/// class's copy in memory.
#[derive(Clone)]
pub struct AppState {
    pool: AnyPool,
    config: Arc<Config>,
    hubs: Arc<Mutex<HashMap<String, broadcast::Sender<Change>>>>,
    classes: Arc<Mutex<HashMap<String, Slot>>>,
}

impl AppState {
    fn hub(&self, code: &str) -> broadcast::Sender<Change> {
        let mut hubs = self.hubs.lock().unwrap_or_else(|e| e.into_inner());
        hubs.retain(|_, tx| tx.receiver_count() > 0);
        // A class nobody is connected to leaves memory (unless a task holds it).
        self.classes
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .retain(|code, slot| hubs.contains_key(code) || Arc::strong_count(slot) > 1);
        hubs.entry(code.to_owned())
            .or_insert_with(|| broadcast::channel(16).0)
            .clone()
    }

    /// The class's copy in memory (taken by `lock().await`).
    fn slot(&self, code: &str) -> Slot {
        self.classes
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .entry(code.to_owned())
            .or_default()
            .clone()
    }

    /// Drops a deleted class's copy.
    fn forget(&self, code: &str) {
        self.classes
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .remove(code);
    }

    /// What `role` may see of its class now, from the copy in memory (read from
    /// the database the first time).
    async fn view(&self, role: &Role) -> Result<serde_json::Value, ServerError> {
        let code = role.code();
        let slot = self.slot(code);
        let mut live = slot.lock().await;
        if live.is_none() {
            *live = Some(store::load(&self.pool, code).await?);
        }
        match live.as_ref() {
            Some(class) => class.view(code, role),
            None => Err(ServerError::new(
                ErrorCode::Internal,
                "the class could not be read",
            )),
        }
    }

    fn changed(&self, code: &str, change: Change) {
        let _ = self.hub(code).send(change);
    }
}

/// The whole application (API, WebSocket, static files, headers).
pub fn app(pool: AnyPool, config: Config) -> Router {
    let dist = config.dist.clone();
    let state = AppState {
        pool,
        config: Arc::new(config),
        hubs: Arc::default(),
        classes: Arc::default(),
    };
    let statics = ServeDir::new(&dist)
        // The build writes brotli and gzip copies (tools/web-finish): sent as they
        // are to a browser that accepts them.
        .precompressed_br()
        .precompressed_gzip()
        .fallback(ServeFile::new(dist.join("index.html")));
    Router::new()
        .route("/api/info", get(info))
        .route("/api/classes", post(start_class))
        .route("/api/classes/{code}", axum::routing::delete(delete_class))
        .route("/api/classes/{code}/csv", get(class_csv))
        .route("/ws", get(ws_upgrade))
        .fallback_service(statics)
        .with_state(state)
        .layer(axum::extract::DefaultBodyLimit::max(MAX_MESSAGE_BYTES))
        .layer(SetResponseHeaderLayer::overriding(
            header::CONTENT_SECURITY_POLICY,
            HeaderValue::from_static(CSP),
        ))
        .layer(SetResponseHeaderLayer::overriding(
            header::X_CONTENT_TYPE_OPTIONS,
            HeaderValue::from_static("nosniff"),
        ))
        .layer(SetResponseHeaderLayer::overriding(
            header::REFERRER_POLICY,
            HeaderValue::from_static("no-referrer"),
        ))
}

/// Deletes every class created more than `keep_days` days ago (with all its
/// students, results and messages). Returns how many classes went.
pub async fn delete_expired(pool: &AnyPool, keep_days: u32) -> Result<u64, sqlx::Error> {
    store::delete_older_than(pool, store::now() - i64::from(keep_days) * 86_400).await
}

/// `GET /api/info`: tells the web app that a class server (and which protocol)
/// serves it, so the app shows its class features only then.
async fn info() -> Json<serde_json::Value> {
    Json(json!({"server": "shoal-class", "protocol": protocol::VERSION}))
}

fn error_response(status: StatusCode, err: ServerError) -> Response {
    (status, Json(err.to_json(None))).into_response()
}

fn bearer(headers: &HeaderMap) -> Option<&str> {
    headers
        .get(header::AUTHORIZATION)?
        .to_str()
        .ok()?
        .strip_prefix("Bearer ")
}

async fn start_class(State(state): State<AppState>, body: axum::body::Bytes) -> Response {
    let request: protocol::StartClass = match protocol::parse_json(&body) {
        Ok(r) => r,
        Err(e) => return error_response(StatusCode::BAD_REQUEST, e),
    };
    match store::create_class(&state.pool, &request.setup).await {
        Ok(started) => (StatusCode::CREATED, Json(started)).into_response(),
        Err(e) => error_response(StatusCode::INTERNAL_SERVER_ERROR, e),
    }
}

async fn authorised_teacher(
    state: &AppState,
    code: &str,
    headers: &HeaderMap,
) -> Result<(), Response> {
    let token = bearer(headers).unwrap_or("");
    match store::check_teacher(&state.pool, code, token).await {
        Ok(true) => Ok(()),
        Ok(false) => Err(error_response(
            StatusCode::FORBIDDEN,
            ServerError::new(
                ErrorCode::Forbidden,
                "no class with that code and teacher token",
            ),
        )),
        Err(e) => Err(error_response(StatusCode::INTERNAL_SERVER_ERROR, e)),
    }
}

async fn class_csv(
    State(state): State<AppState>,
    Path(code): Path<String>,
    headers: HeaderMap,
) -> Response {
    if let Err(r) = authorised_teacher(&state, &code, &headers).await {
        return r;
    }
    match store::class_csv(&state.pool, &code).await {
        Ok(csv) => ([(header::CONTENT_TYPE, "text/csv; charset=utf-8")], csv).into_response(),
        Err(e) => error_response(StatusCode::INTERNAL_SERVER_ERROR, e),
    }
}

async fn delete_class(
    State(state): State<AppState>,
    Path(code): Path<String>,
    headers: HeaderMap,
) -> Response {
    if let Err(r) = authorised_teacher(&state, &code, &headers).await {
        return r;
    }
    let slot = state.slot(&code);
    let mut live = slot.lock().await;
    let deleted = store::delete_class(&state.pool, &code).await;
    *live = None;
    drop(live);
    state.forget(&code);
    match deleted {
        Ok(()) => {
            state.changed(&code, Change::Everyone);
            StatusCode::NO_CONTENT.into_response()
        }
        Err(e) => error_response(StatusCode::INTERNAL_SERVER_ERROR, e),
    }
}

/// A connection's read buffer: larger messages are read in several pieces.
const READ_BUFFER_BYTES: usize = 4 * 1024;

async fn ws_upgrade(State(state): State<AppState>, ws: WebSocketUpgrade) -> Response {
    // The socket accepts a little more than the limit so that an oversized
    // message gets a clear error instead of a dropped connection. Its read buffer
    // is a few KiB, not tungstenite's default 128 KiB: that buffer is zeroed on
    // every read, which took an eighth of the server's time under load, and held
    // 128 KiB per connection (most of the memory of a 1,400-student lesson).
    ws.max_message_size(4 * MAX_MESSAGE_BYTES)
        .read_buffer_size(READ_BUFFER_BYTES)
        .on_upgrade(move |socket| connection(state, socket))
}

/// Who is at the other end of a connection, once it has said hello.
#[derive(Clone, Debug)]
pub enum Role {
    Teacher { code: String },
    Student { code: String, id: String },
}

/// A token bucket.
struct Bucket {
    tokens: f64,
    last: Instant,
    burst: f64,
    per_second: f64,
}

impl Bucket {
    fn take(&mut self) -> bool {
        let now = Instant::now();
        self.tokens = (self.tokens + now.duration_since(self.last).as_secs_f64() * self.per_second)
            .min(self.burst);
        self.last = now;
        if self.tokens >= 1.0 {
            self.tokens -= 1.0;
            true
        } else {
            false
        }
    }
}

async fn send(socket: &mut WebSocket, value: serde_json::Value) -> bool {
    socket
        .send(Message::Text(value.to_string().into()))
        .await
        .is_ok()
}

async fn connection(state: AppState, mut socket: WebSocket) {
    let mut bucket = Bucket {
        tokens: state.config.burst,
        last: Instant::now(),
        burst: state.config.burst,
        per_second: state.config.per_second,
    };
    let mut role: Option<Role> = None;
    let mut changes: Option<broadcast::Receiver<Change>> = None;
    // Whether the last view sent showed the prediction counts (a student's
    // view then changes with every prediction).
    let mut revealed = false;
    loop {
        let incoming = tokio::select! {
            m = socket.recv() => m,
            changed = async {
                match changes.as_mut() {
                    Some(rx) => rx.recv().await,
                    None => std::future::pending().await,
                }
            } => {
                let concerns = match (&changed, &role) {
                    (Err(broadcast::error::RecvError::Closed), _) => { changes = None; continue; }
                    // Lagged: some changes were missed, so the view is redone.
                    (Err(broadcast::error::RecvError::Lagged(_)), _) => true,
                    (Ok(c), Some(r)) => c.concerns(r, revealed),
                    (Ok(_), None) => false,
                };
                // Changes that arrived meanwhile are covered by the view read now.
                let concerns = drain(&mut changes, role.as_ref(), revealed) || concerns;
                if !concerns { continue; }
                if let Some(r) = &role {
                    match state.view(r).await {
                        Ok(v) => {
                            revealed = shows_counts(&v);
                            if !send(&mut socket, v).await { return }
                        }
                        Err(e) => if !send(&mut socket, e.to_json(None)).await { return },
                    }
                }
                continue;
            }
        };
        let text = match incoming {
            Some(Ok(Message::Text(t))) => t,
            Some(Ok(Message::Binary(_))) => {
                let e = ServerError::new(ErrorCode::Invalid, "messages are JSON text");
                if !send(&mut socket, e.to_json(None)).await {
                    return;
                }
                continue;
            }
            Some(Ok(Message::Close(_))) | None | Some(Err(_)) => return,
            Some(Ok(_)) => continue,
        };
        if !bucket.take() {
            let e = ServerError::new(
                ErrorCode::RateLimited,
                "too many messages; slow down and resend",
            );
            if !send(&mut socket, e.to_json(protocol::peek_id(&text).as_deref())).await {
                return;
            }
            continue;
        }
        if text.len() > MAX_MESSAGE_BYTES {
            let e = ServerError::new(
                ErrorCode::TooLarge,
                &format!("a message may be at most {MAX_MESSAGE_BYTES} bytes"),
            );
            if !send(&mut socket, e.to_json(protocol::peek_id(&text).as_deref())).await {
                return;
            }
            continue;
        }
        let message: ClientMessage = match protocol::parse_message(&text) {
            Ok(m) => m,
            Err(e) => {
                if !send(&mut socket, e.to_json(protocol::peek_id(&text).as_deref())).await {
                    return;
                }
                continue;
            }
        };
        let id = message.id.clone();
        let outcome = handle(&state, &mut role, message).await;
        match outcome {
            Ok(reply) => {
                if !send(&mut socket, reply).await {
                    return;
                }
                if let Some(r) = &role {
                    if changes.is_none() {
                        changes = Some(state.hub(r.code()).subscribe());
                    }
                    // The view read now covers every change already signalled.
                    drain(&mut changes, Some(r), revealed);
                    match state.view(r).await {
                        Ok(v) => {
                            revealed = shows_counts(&v);
                            if !send(&mut socket, v).await {
                                return;
                            }
                        }
                        Err(e) => {
                            if !send(&mut socket, e.to_json(None)).await {
                                return;
                            }
                        }
                    }
                }
            }
            Err(e) => {
                if !send(&mut socket, e.to_json(Some(&id))).await {
                    return;
                }
            }
        }
    }
}

/// Whether a view carries the class's prediction counts (a revealed student view).
fn shows_counts(view: &serde_json::Value) -> bool {
    view["type"] == "you" && !view["histogram"].is_null()
}

/// Takes every change already waiting; says whether one concerns `role`.
fn drain(
    changes: &mut Option<broadcast::Receiver<Change>>,
    role: Option<&Role>,
    revealed: bool,
) -> bool {
    let Some(rx) = changes.as_mut() else {
        return false;
    };
    let mut concerns = false;
    loop {
        match rx.try_recv() {
            Ok(c) => concerns |= role.is_some_and(|r| c.concerns(r, revealed)),
            Err(broadcast::error::TryRecvError::Lagged(_)) => concerns = true,
            Err(_) => return concerns,
        }
    }
}

impl Role {
    pub fn code(&self) -> &str {
        match self {
            Role::Teacher { code } | Role::Student { code, .. } => code,
        }
    }
}

async fn handle(
    state: &AppState,
    role: &mut Option<Role>,
    message: ClientMessage,
) -> Result<serde_json::Value, ServerError> {
    use protocol::Body;
    match (&*role, &message.body) {
        (
            None,
            Body::Join {
                code,
                nickname,
                join_key,
            },
        ) => {
            let slot = state.slot(code);
            let mut live = slot.lock().await;
            let joined = store::join(&state.pool, code, nickname, join_key.as_deref()).await?;
            if let Some(class) = live.as_mut() {
                class.add_student(&joined, nickname);
            }
            drop(live);
            *role = Some(Role::Student {
                code: code.clone(),
                id: joined.student_id.clone(),
            });
            // A new student alters only the teacher's roster.
            state.changed(code, Change::Student(joined.student_id.as_str().into()));
            Ok(
                json!({"v": 1, "type": "joined", "re": message.id, "student_token": joined.token,
                      "join_order": joined.join_order, "seed": joined.seed, "setup": joined.setup}),
            )
        }
        (
            None,
            Body::Resume {
                code,
                student_token,
            },
        ) => {
            let id = store::resume(&state.pool, code, student_token).await?;
            *role = Some(Role::Student {
                code: code.clone(),
                id,
            });
            Ok(json!({"v": 1, "type": "ack", "re": message.id}))
        }
        (
            None,
            Body::Teacher {
                code,
                teacher_token,
            },
        ) => {
            if !store::check_teacher(&state.pool, code, teacher_token).await? {
                return Err(ServerError::new(
                    ErrorCode::Forbidden,
                    "no class with that code and teacher token",
                ));
            }
            *role = Some(Role::Teacher { code: code.clone() });
            Ok(json!({"v": 1, "type": "ack", "re": message.id}))
        }
        (Some(_), Body::Join { .. } | Body::Resume { .. } | Body::Teacher { .. }) => {
            Err(ServerError::new(
                ErrorCode::Invalid,
                "this connection has already said who it is",
            ))
        }
        (None, _) => Err(ServerError::new(
            ErrorCode::Forbidden,
            "say join, resume or teacher first",
        )),
        (Some(r), body) => {
            let r = r.clone();
            let slot = state.slot(r.code());
            let mut live = slot.lock().await;
            let reply = match store::apply(&state.pool, &r, &message.id, body).await {
                Ok((reply, store::Effect::Deleted)) => {
                    *live = None;
                    state.forget(r.code());
                    reply
                }
                Ok((reply, effect)) => {
                    if let Some(class) = live.as_mut() {
                        class.apply(&r, effect);
                    }
                    reply
                }
                Err(e) => {
                    // A refused message changed nothing; after a database error
                    // or a class gone, read the class again next time.
                    if matches!(e.code, ErrorCode::Internal | ErrorCode::NotFound) {
                        *live = None;
                    }
                    return Err(e);
                }
            };
            drop(live);
            // A student's step, result or answer alters only their own record
            // (and the teacher's roster); a prediction may alter the histogram
            // every student sees once revealed; a teacher's message, everyone's.
            let change = match (&r, body) {
                (Role::Student { .. }, Body::Predict { .. }) => Change::Prediction,
                (Role::Teacher { .. }, _) => Change::Everyone,
                (Role::Student { id, .. }, _) => Change::Student(id.as_str().into()),
            };
            state.changed(r.code(), change);
            if matches!(body, Body::DeleteClass {}) {
                *role = None;
            }
            Ok(reply)
        }
    }
}

/// Runs the retention task forever: every hour, deletes expired classes.
pub async fn retention_task(pool: AnyPool, keep_days: u32) {
    let mut tick = tokio::time::interval(Duration::from_secs(3600));
    loop {
        tick.tick().await;
        match delete_expired(&pool, keep_days).await {
            Ok(0) => {}
            Ok(n) => eprintln!("shoal-class: deleted {n} classes older than {keep_days} days"),
            Err(e) => eprintln!("shoal-class: retention failed: {e}"),
        }
    }
}
