//! Protocol v1: versioned JSON messages over the WebSocket at `/ws`.
//! Every client message is `{"v": 1, "id": "<client message id>", "type": …}`;
//! the full list is in docs/class.md.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use serde_json::{json, Value};

/// The protocol version this server speaks.
pub const VERSION: u64 = 1;
/// The largest message (and `POST` body) accepted, in bytes.
pub const MAX_MESSAGE_BYTES: usize = 16 * 1024;
/// The largest investigation or studio setup, in bytes of JSON.
pub const MAX_SETUP_BYTES: usize = 8 * 1024;
pub const MAX_NICKNAME_CHARS: usize = 24;
pub const MAX_ANSWER_CHARS: usize = 2000;
pub const MAX_PREDICTION_CHARS: usize = 100;
pub const MAX_ID_CHARS: usize = 64;
pub const MAX_NAMES: usize = 16;
pub const MAX_NAME_CHARS: usize = 48;

/// The steps of an investigation, in order.
pub const STEPS: [&str; 4] = ["look", "predict", "run", "explain"];

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ErrorCode {
    Invalid,
    TooLarge,
    RateLimited,
    Forbidden,
    NotFound,
    Held,
    Internal,
}

/// An error sent to the client as `{"v":1,"type":"error","re":id,"code","message"}`.
#[derive(Clone, Debug)]
pub struct ServerError {
    pub code: ErrorCode,
    pub message: String,
}

impl ServerError {
    pub fn new(code: ErrorCode, message: &str) -> Self {
        ServerError {
            code,
            message: message.to_owned(),
        }
    }

    pub fn to_json(&self, re: Option<&str>) -> Value {
        json!({"v": VERSION, "type": "error", "re": re, "code": self.code, "message": self.message})
    }
}

impl From<sqlx::Error> for ServerError {
    fn from(e: sqlx::Error) -> Self {
        eprintln!("shoal-class: database error: {e}");
        ServerError::new(
            ErrorCode::Internal,
            "the server could not store this; resend it later",
        )
    }
}

/// `POST /api/classes`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StartClass {
    /// The investigation id or studio setup (opaque JSON).
    pub setup: Value,
}

#[derive(Debug, Deserialize)]
pub struct ClientMessage {
    pub v: u64,
    pub id: String,
    #[serde(flatten)]
    pub body: Body,
}

#[derive(Debug, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Body {
    // Hello (the first message of a connection).
    Join {
        code: String,
        nickname: String,
        /// Random, one per join (the same when a join is resent): a resent
        /// join gets the student it already made, with a new token.
        #[serde(default)]
        join_key: Option<String>,
    },
    Resume {
        code: String,
        student_token: String,
    },
    Teacher {
        code: String,
        teacher_token: String,
    },
    // Student.
    Step {
        step: String,
    },
    Predict {
        prediction: String,
    },
    Result {
        levels: BTreeMap<String, f64>,
        values: BTreeMap<String, f64>,
    },
    Explain {
        answer: String,
    },
    // Teacher.
    Hold {
        step: Option<String>,
    },
    Release {},
    Pause {
        paused: bool,
    },
    SendSetting {
        setting: Value,
    },
    Reveal {
        revealed: bool,
    },
    Anonymise {
        on: bool,
    },
    DeleteClass {},
}

impl Body {
    pub fn is_teachers(&self) -> bool {
        matches!(
            self,
            Body::Hold { .. }
                | Body::Release {}
                | Body::Pause { .. }
                | Body::SendSetting { .. }
                | Body::Reveal { .. }
                | Body::Anonymise { .. }
                | Body::DeleteClass {}
        )
    }
}

fn invalid(message: &str) -> ServerError {
    ServerError::new(ErrorCode::Invalid, message)
}

pub fn parse_json<T: for<'de> Deserialize<'de>>(bytes: &[u8]) -> Result<T, ServerError> {
    if bytes.len() > MAX_MESSAGE_BYTES {
        return Err(ServerError::new(
            ErrorCode::TooLarge,
            "the request is too large",
        ));
    }
    serde_json::from_slice(bytes).map_err(|e| invalid(&format!("not a valid message: {e}")))
}

/// The `id` of a message that failed to parse, if it has one (for the error's `re`).
pub fn peek_id(text: &str) -> Option<String> {
    let v: Value = serde_json::from_str(text).ok()?;
    let id = v.get("id")?.as_str()?;
    (id.chars().count() <= MAX_ID_CHARS).then(|| id.to_owned())
}

fn check_text(what: &str, text: &str, max: usize, allow_empty: bool) -> Result<(), ServerError> {
    let n = text.chars().count();
    if n > max {
        return Err(invalid(&format!("{what} may be at most {max} characters")));
    }
    if !allow_empty && text.trim().is_empty() {
        return Err(invalid(&format!("{what} is empty")));
    }
    if text.chars().any(|c| c.is_control() && c != '\n') {
        return Err(invalid(&format!("{what} has control characters")));
    }
    Ok(())
}

fn check_numbers(what: &str, map: &BTreeMap<String, f64>) -> Result<(), ServerError> {
    if map.len() > MAX_NAMES {
        return Err(invalid(&format!(
            "{what} may have at most {MAX_NAMES} entries"
        )));
    }
    for (name, value) in map {
        if name.is_empty()
            || name.chars().count() > MAX_NAME_CHARS
            || !name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '-'))
        {
            return Err(invalid(&format!(
                "{what}: names are 1 to {MAX_NAME_CHARS} of a-z, 0-9, _ . -"
            )));
        }
        if !value.is_finite() {
            return Err(invalid(&format!("{what}: {name} is not a finite number")));
        }
    }
    Ok(())
}

/// Parses and validates one client message (size, schema, lengths).
pub fn parse_message(text: &str) -> Result<ClientMessage, ServerError> {
    let m: ClientMessage = parse_json(text.as_bytes())?;
    if m.v != VERSION {
        return Err(invalid("this server speaks protocol version 1"));
    }
    if m.id.is_empty() || m.id.chars().count() > MAX_ID_CHARS || m.id.chars().any(char::is_control)
    {
        return Err(invalid(&format!(
            "id must be 1 to {MAX_ID_CHARS} characters"
        )));
    }
    match &m.body {
        Body::Join {
            code,
            nickname,
            join_key,
        } => {
            if let Some(key) = join_key {
                let n = key.chars().count();
                if !(8..=64).contains(&n)
                    || !key
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
                {
                    return Err(invalid("join_key is 8 to 64 letters, digits, '-' or '_'"));
                }
            }
            check_text("code", code, 16, false)?;
            check_text("nickname", nickname, MAX_NICKNAME_CHARS, false)?;
            if nickname.contains('\n') {
                return Err(invalid("nickname is one line"));
            }
        }
        Body::Resume {
            code,
            student_token: t,
        }
        | Body::Teacher {
            code,
            teacher_token: t,
        } => {
            check_text("code", code, 16, false)?;
            check_text("token", t, 128, false)?;
        }
        Body::Step { step } => check_step(step)?,
        Body::Hold { step: Some(step) } => check_step(step)?,
        Body::Predict { prediction } => {
            check_text("prediction", prediction, MAX_PREDICTION_CHARS, false)?
        }
        Body::Result { levels, values } => {
            check_numbers("levels", levels)?;
            check_numbers("values", values)?;
            if values.is_empty() {
                return Err(invalid("values is empty"));
            }
        }
        Body::Explain { answer } => check_text("answer", answer, MAX_ANSWER_CHARS, true)?,
        Body::SendSetting { setting } if setting.to_string().len() > MAX_SETUP_BYTES => {
            return Err(ServerError::new(
                ErrorCode::TooLarge,
                "the setting is too large",
            ));
        }
        _ => {}
    }
    Ok(m)
}

fn check_step(step: &str) -> Result<(), ServerError> {
    if STEPS.contains(&step) {
        Ok(())
    } else {
        Err(invalid("step is one of look, predict, run, explain"))
    }
}
