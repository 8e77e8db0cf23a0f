//! One class connection's life, without the socket: the app tells it when the
//! socket opens, what arrives and when it closes; it answers with the frames to
//! send. A student's or teacher's identity and outbox are JSON for the
//! browser's storage, so a reload (or a lost connection) picks up where it was.

use serde::{Deserialize, Serialize};
use serde_json::{Value, json};

use super::outbox::{Outbox, Retry};
use super::view::{ClassView, Incoming, YouView};

/// A student of a class.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Student {
    pub code: String,
    pub nickname: String,
    /// Given by the server when the join is accepted.
    #[serde(default)]
    pub token: Option<String>,
    #[serde(default)]
    pub join_order: i64,
    /// The seed this student's tank runs (class seed + join order).
    #[serde(default)]
    pub seed: i64,
    /// The lesson (investigation or studio setup).
    #[serde(default)]
    pub setup: Value,
}

/// The teacher of a class (the holder of the teacher link).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Teacher {
    pub code: String,
    pub token: String,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "role", rename_all = "snake_case")]
pub enum Who {
    Student(Student),
    Teacher(Teacher),
}

/// The connection, as the status line tells it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Link {
    /// No socket; the next attempt is due at `retry_at`.
    Closed,
    /// Opening, or open and waiting for the hello's answer.
    Connecting,
    /// Open and the server knows who this is.
    Connected,
    /// The class is gone or refuses this link: no more attempts.
    Ended,
}

/// Reconnect delay after `failures` failed attempts in a row: 1, 2, 4, 8, 16,
/// then 30 seconds.
pub fn backoff_secs(failures: u32) -> f64 {
    if failures == 0 {
        0.0
    } else {
        f64::from(1u32 << (failures - 1).min(5)).min(30.0)
    }
}

/// Something the user should read (an error the server gave a message).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Refusal {
    /// The message type refused (`predict`, `step`, …).
    pub kind: String,
    pub code: String,
    pub message: String,
}

/// One sender's session.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Session {
    pub who: Who,
    pub outbox: Outbox,
    #[serde(skip, default = "closed")]
    link: Link,
    #[serde(skip)]
    hello_id: Option<String>,
    #[serde(skip)]
    failures: u32,
    #[serde(skip)]
    retry_at: f64,
    /// When to resend what waits after a `rate_limited` or `internal` answer.
    #[serde(skip)]
    resend_at: Option<f64>,
    /// The teacher's latest view.
    #[serde(skip)]
    pub class: Option<ClassView>,
    /// The student's latest view.
    #[serde(skip)]
    pub you: Option<YouView>,
    /// Refusals not yet shown.
    #[serde(skip)]
    pub refusals: Vec<Refusal>,
    /// Why the link ended (the server's words), once it has.
    #[serde(skip)]
    pub ended: Option<String>,
}

fn closed() -> Link {
    Link::Closed
}

impl Session {
    /// A new session for `who`; `prefix` makes its message ids unique (random).
    pub fn new(who: Who, prefix: &str) -> Self {
        Session {
            who,
            outbox: Outbox::new(prefix),
            link: Link::Closed,
            hello_id: None,
            failures: 0,
            retry_at: 0.0,
            resend_at: None,
            class: None,
            you: None,
            refusals: Vec::new(),
            ended: None,
        }
    }

    /// The session kept in the browser's storage (`None` if unreadable).
    pub fn from_storage(text: &str) -> Option<Self> {
        serde_json::from_str(text).ok()
    }

    /// What the browser keeps: who this is and what waits to be sent.
    pub fn to_storage(&self) -> String {
        serde_json::to_string(self).unwrap_or_default()
    }

    pub fn link(&self) -> Link {
        self.link
    }

    pub fn code(&self) -> &str {
        match &self.who {
            Who::Student(s) => &s.code,
            Who::Teacher(t) => &t.code,
        }
    }

    pub fn student(&self) -> Option<&Student> {
        match &self.who {
            Who::Student(s) => Some(s),
            Who::Teacher(_) => None,
        }
    }

    pub fn is_teacher(&self) -> bool {
        matches!(self.who, Who::Teacher(_))
    }

    /// Should the app open a socket now (`now`: seconds)?
    pub fn should_connect(&self, now: f64) -> bool {
        self.link == Link::Closed && now >= self.retry_at
    }

    /// Seconds until the next attempt (0 when due or connected).
    pub fn retry_in(&self, now: f64) -> f64 {
        if self.link == Link::Closed {
            (self.retry_at - now).max(0.0)
        } else {
            0.0
        }
    }

    /// The app is opening a socket.
    pub fn connecting(&mut self) {
        if self.link != Link::Ended {
            self.link = Link::Connecting;
        }
    }

    /// The socket opened: the hello to send (join, resume or teacher).
    pub fn on_open(&mut self) -> Vec<String> {
        if self.link == Link::Ended {
            return Vec::new();
        }
        self.link = Link::Connecting;
        let id = self.outbox.fresh_id();
        let hello = match &self.who {
            Who::Student(s) => match &s.token {
                Some(token) => json!({"v": super::PROTOCOL, "id": id, "type": "resume",
                    "code": s.code, "student_token": token}),
                None => {
                    let mut join = json!({"v": super::PROTOCOL, "id": id, "type": "join",
                        "code": s.code, "nickname": s.nickname});
                    if let Some(key) = self.outbox.join_key() {
                        join["join_key"] = json!(key);
                    }
                    join
                }
            },
            Who::Teacher(t) => json!({"v": super::PROTOCOL, "id": id, "type": "teacher",
                "code": t.code, "teacher_token": t.token}),
        };
        self.hello_id = Some(id);
        vec![hello.to_string()]
    }

    /// The socket closed (or failed to open) at `now`: try again after the
    /// backoff.
    pub fn on_close(&mut self, now: f64) {
        if self.link == Link::Ended {
            return;
        }
        if self.link != Link::Connected {
            self.failures += 1;
        } else {
            self.failures = 1;
        }
        self.link = Link::Closed;
        self.hello_id = None;
        self.retry_at = now + backoff_secs(self.failures);
    }

    /// Queues a message (a student's step, prediction, result, answer, or a
    /// teacher's pacing) and returns the frame to send now, if connected.
    pub fn send(&mut self, kind: &str, body: Value) -> Option<String> {
        let message = self.outbox.push(kind, body);
        (self.link == Link::Connected).then(|| message.to_string())
    }

    /// Every waiting message as frames (what a reconnect resends).
    fn resend_all(&self) -> Vec<String> {
        self.outbox
            .waiting()
            .iter()
            .map(|p| p.message.to_string())
            .collect()
    }

    /// Called every frame: frames due again after a `rate_limited` answer.
    pub fn poll(&mut self, now: f64) -> Vec<String> {
        match self.resend_at {
            Some(at) if self.link == Link::Connected && now >= at => {
                self.resend_at = None;
                self.resend_all()
            }
            _ => Vec::new(),
        }
    }

    /// One frame from the server at `now`; returns the frames to send.
    pub fn on_message(&mut self, text: &str, now: f64) -> Vec<String> {
        match super::view::parse(text) {
            Incoming::Joined(joined) => {
                if self.hello_id.as_deref() == Some(joined.re.as_str())
                    && let Who::Student(s) = &mut self.who
                {
                    s.token = Some(joined.student_token);
                    s.join_order = joined.join_order;
                    s.seed = joined.seed;
                    s.setup = joined.setup;
                    return self.hello_accepted();
                }
                Vec::new()
            }
            Incoming::Ack { re } => {
                if self.hello_id.as_deref() == Some(re.as_str()) {
                    return self.hello_accepted();
                }
                self.outbox.ack(&re);
                Vec::new()
            }
            Incoming::Error { re, code, message } => {
                let Some(re) = re else {
                    return Vec::new();
                };
                if self.hello_id.as_deref() == Some(re.as_str()) {
                    if Retry::of(&code) == Retry::Never {
                        self.link = Link::Ended;
                        self.ended = Some(message);
                    }
                    return Vec::new();
                }
                if Retry::of(&code) == Retry::Later {
                    self.resend_at = Some(now + 2.0);
                }
                if let Some(p) = self.outbox.refused(&re, &code) {
                    let kind = p
                        .message
                        .get("type")
                        .and_then(Value::as_str)
                        .unwrap_or("")
                        .to_owned();
                    self.refusals.push(Refusal {
                        kind,
                        code,
                        message,
                    });
                }
                Vec::new()
            }
            Incoming::Class(view) => {
                self.class = Some(*view);
                Vec::new()
            }
            Incoming::You(view) => {
                self.you = Some(*view);
                Vec::new()
            }
            Incoming::Unreadable(_) => Vec::new(),
        }
    }

    fn hello_accepted(&mut self) -> Vec<String> {
        self.link = Link::Connected;
        self.failures = 0;
        self.hello_id = None;
        self.resend_all()
    }

    /// The class's pacing as this session last saw it.
    pub fn state(&self) -> Option<&super::view::ClassState> {
        self.you
            .as_ref()
            .map(|y| &y.state)
            .or(self.class.as_ref().map(|c| &c.state))
    }

    /// May this student go to `step` (the hold rule over the last view)?
    pub fn may_go_to(&self, step: &str) -> bool {
        super::may_go_to(step, self.state().and_then(|s| s.held_step.as_deref()))
    }
}
