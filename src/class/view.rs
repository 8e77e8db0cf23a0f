//! The server's messages, parsed. Anything the app does not know (a newer
//! server's extra fields) is ignored; a message it cannot read is
//! [`Incoming::Unreadable`], never a panic.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use serde_json::Value;

/// The class's pacing, in both views.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ClassState {
    /// The step the teacher holds the class at (`None`: no hold).
    #[serde(default)]
    pub held_step: Option<String>,
    #[serde(default)]
    pub paused: bool,
    /// The setting the teacher sent to everyone (a settings patch), if any.
    #[serde(default)]
    pub setting: Option<Value>,
    #[serde(default)]
    pub revealed: bool,
}

/// One measured value of a student's run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ResultRow {
    #[serde(default)]
    pub levels: BTreeMap<String, f64>,
    pub measure: String,
    pub value: f64,
}

/// One student's record (the roster's entry, or the student's own `me`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StudentRecord {
    pub join_order: i64,
    /// `None` while the teacher anonymises the dashboard.
    #[serde(default)]
    pub nickname: Option<String>,
    #[serde(default)]
    pub seed: i64,
    #[serde(default)]
    pub step: Option<String>,
    #[serde(default)]
    pub prediction: Option<String>,
    #[serde(default)]
    pub answer: Option<String>,
    #[serde(default)]
    pub results: Vec<ResultRow>,
    /// Runs reported (one `result` message each, whatever its measures); an
    /// older server leaves it out.
    #[serde(default)]
    pub runs: Option<usize>,
}

/// The teacher's view of the class.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ClassView {
    pub code: String,
    #[serde(default)]
    pub seed: i64,
    #[serde(default)]
    pub setup: Value,
    #[serde(default)]
    pub anonymise: bool,
    #[serde(default)]
    pub state: ClassState,
    #[serde(default)]
    pub roster: Vec<StudentRecord>,
    /// The count of each prediction.
    #[serde(default)]
    pub histogram: BTreeMap<String, u64>,
}

/// A student's view: their own record and what the teacher shows.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct YouView {
    #[serde(default)]
    pub state: ClassState,
    #[serde(default)]
    pub me: StudentRecord,
    /// `None` until the teacher reveals it.
    #[serde(default)]
    pub histogram: Option<BTreeMap<String, u64>>,
}

/// A student's `joined` answer.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Joined {
    pub re: String,
    pub student_token: String,
    pub join_order: i64,
    pub seed: i64,
    #[serde(default)]
    pub setup: Value,
}

/// One message from the server.
#[derive(Clone, Debug, PartialEq)]
pub enum Incoming {
    Joined(Joined),
    Ack {
        re: String,
    },
    Error {
        re: Option<String>,
        code: String,
        message: String,
    },
    Class(Box<ClassView>),
    You(Box<YouView>),
    /// Not JSON, or a type or shape this app does not know.
    Unreadable(String),
}

/// Parses one text frame from the server.
pub fn parse(text: &str) -> Incoming {
    let value: Value = match serde_json::from_str(text) {
        Ok(v) => v,
        Err(e) => return Incoming::Unreadable(e.to_string()),
    };
    let kind = value.get("type").and_then(Value::as_str).unwrap_or("");
    let str_of = |k: &str| value.get(k).and_then(Value::as_str).map(str::to_owned);
    let parsed = match kind {
        "joined" => serde_json::from_value(value.clone()).map(Incoming::Joined),
        "ack" => match str_of("re") {
            Some(re) => Ok(Incoming::Ack { re }),
            None => return Incoming::Unreadable("ack without re".to_owned()), // words: diagnostic
        },
        "error" => Ok(Incoming::Error {
            re: str_of("re"),
            code: str_of("code").unwrap_or_default(),
            message: str_of("message").unwrap_or_default(),
        }),
        "class" => serde_json::from_value(value.clone()).map(|v| Incoming::Class(Box::new(v))),
        "you" => serde_json::from_value(value.clone()).map(|v| Incoming::You(Box::new(v))),
        other => return Incoming::Unreadable(format!("type {other:?}")), // words: diagnostic
    };
    parsed.unwrap_or_else(|e| Incoming::Unreadable(e.to_string()))
}

/// `POST /api/classes`' answer.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Started {
    pub code: String,
    pub teacher_token: String,
    pub seed: i64,
}

/// `GET /api/info`: is this a class server speaking our protocol?
pub fn is_class_server(body: &str) -> bool {
    serde_json::from_str::<Value>(body).is_ok_and(|v| {
        v.get("server").and_then(Value::as_str) == Some("shoal-class")
            && v.get("protocol").and_then(Value::as_u64) == Some(super::PROTOCOL)
    })
}
