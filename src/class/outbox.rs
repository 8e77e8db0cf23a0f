//! Messages waiting for their `ack`: each has a unique id (a prefix chosen at
//! random once per browser and class, then a counter), is kept until the server
//! acknowledges it, and is sent again after every reconnect. The server applies
//! an id it has seen once and answers it with the same ack, so a resend never
//! counts twice. The whole outbox is JSON, kept in the browser's storage, so a
//! reload loses nothing either.

use serde::{Deserialize, Serialize};
use serde_json::{Value, json};

/// One message not yet acknowledged.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pending {
    pub id: String,
    /// The whole message, `v`, `id` and `type` included.
    pub message: Value,
}

/// What an error answer means for the message it names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Retry {
    /// The server could not take it now (`rate_limited`, `internal`): keep it,
    /// send it again later.
    Later,
    /// The server refused it for good (`invalid`, `held`, `forbidden`,
    /// `not_found`, `too_large`): drop it and say why.
    Never,
}

impl Retry {
    /// How an error `code` treats its message.
    pub fn of(code: &str) -> Self {
        match code {
            "rate_limited" | "internal" => Retry::Later,
            _ => Retry::Never,
        }
    }
}

/// The outbox of one sender.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Outbox {
    /// Unique to this sender (random, chosen once).
    prefix: String,
    /// The next message's number.
    next: u64,
    pending: Vec<Pending>,
}

impl Outbox {
    /// An empty outbox whose ids start with `prefix` (1–40 characters).
    pub fn new(prefix: &str) -> Self {
        Outbox {
            prefix: prefix.chars().take(40).collect(),
            next: 1,
            pending: Vec::new(),
        }
    }

    /// The key a join is sent with: this sender's random prefix (the same when
    /// the join is resent after a dropped connection, so the server gives back
    /// the student it made). `None` for a prefix the server would refuse.
    pub fn join_key(&self) -> Option<&str> {
        let valid = (8..=64).contains(&self.prefix.chars().count())
            && self
                .prefix
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        valid.then_some(self.prefix.as_str())
    }

    /// A fresh id (also for messages that are not queued: the hello).
    pub fn fresh_id(&mut self) -> String {
        let id = format!("{}-{}", self.prefix, self.next);
        self.next += 1;
        id
    }

    /// Queues a message of `type` with the fields of `body` (an object) and
    /// returns it, ready to send, with its new id.
    pub fn push(&mut self, kind: &str, body: Value) -> Value {
        let id = self.fresh_id();
        let mut message = json!({"v": super::PROTOCOL, "id": id, "type": kind});
        if let (Some(m), Value::Object(fields)) = (message.as_object_mut(), body) {
            for (k, v) in fields {
                m.insert(k, v);
            }
        }
        self.pending.push(Pending {
            id,
            message: message.clone(),
        });
        message
    }

    /// The server acknowledged `id`: it is no longer waiting. True if it was.
    pub fn ack(&mut self, id: &str) -> bool {
        let before = self.pending.len();
        self.pending.retain(|p| p.id != id);
        self.pending.len() < before
    }

    /// The server answered `id` with an error `code`: the message is dropped
    /// when it will never be taken, and returned (so the user is told).
    pub fn refused(&mut self, id: &str, code: &str) -> Option<Pending> {
        if Retry::of(code) == Retry::Later {
            return None;
        }
        let at = self.pending.iter().position(|p| p.id == id)?;
        Some(self.pending.remove(at))
    }

    /// Every message still waiting, oldest first (what a reconnect resends).
    pub fn waiting(&self) -> &[Pending] {
        &self.pending
    }

    pub fn len(&self) -> usize {
        self.pending.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pending.is_empty()
    }

    /// Is a message of `type` waiting?
    pub fn has_waiting(&self, kind: &str) -> bool {
        self.pending
            .iter()
            .any(|p| p.message.get("type").and_then(Value::as_str) == Some(kind))
    }
}
