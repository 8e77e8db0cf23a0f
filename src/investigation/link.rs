//! Opening an investigation by link (`?investigation=why-school`) and through
//! `shoal.set({investigation: "why-school"})`, validated: an unknown id is
//! refused with a message naming the known ones, and nothing else in the link
//! or the patch is lost.

use serde_json::Value;

use super::catalogue::{Investigation, find, known_ids};
use crate::settings::share_link::{query_value, with_query, without_query};
use crate::tr;

/// The query parameter (and `set()` key) that opens an investigation.
pub const KEY: &str = "investigation";

/// Why an investigation could not be opened.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LinkError {
    /// No investigation has this id; `known` lists those there are.
    UnknownId { id: String, known: String },
    /// The value is not an id (nor null).
    NotAnId(String),
}

impl std::fmt::Display for LinkError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let text = match self {
            Self::UnknownId { id, known } => tr!("inv-link-unknown", id = id, known = known),
            Self::NotAnId(got) => tr!("inv-link-not-an-id", got = got),
        };
        f.write_str(&text)
    }
}

impl std::error::Error for LinkError {}

fn lookup(id: &str) -> Result<&'static Investigation, LinkError> {
    find(id).ok_or_else(|| LinkError::UnknownId {
        id: id.to_owned(),
        known: known_ids(),
    })
}

/// The investigation a page address asks for (`?investigation=<id>`, before
/// any `#`), if it asks for one.
pub fn from_url(url: &str) -> Option<Result<&'static Investigation, LinkError>> {
    query_value(url, KEY).map(lookup)
}

/// The address without its `investigation` parameter (and without a `?` left
/// empty), so a share link names the investigation only when one is open.
pub fn without_investigation(url: &str) -> String {
    without_query(url, KEY)
}

/// `url` with `?investigation=<id>` (replacing any it had).
pub fn with_investigation(url: &str, id: &str) -> String {
    with_query(url, KEY, id)
}

/// What a `set()` patch asks of the investigations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Request {
    /// The patch does not name one.
    None,
    Open(&'static Investigation),
    /// `investigation: null`: close the one open.
    Close,
}

/// Splits `investigation` off a `set()` patch: what it asks, and the rest of
/// the patch (the settings), unchanged. An unknown id refuses the whole call.
pub fn split_patch(patch: &Value) -> Result<(Request, Value), LinkError> {
    let Some(object) = patch.as_object() else {
        return Ok((Request::None, patch.clone()));
    };
    let Some(value) = object.get(KEY) else {
        return Ok((Request::None, patch.clone()));
    };
    let request = match value {
        Value::Null => Request::Close,
        Value::String(id) => Request::Open(lookup(id)?),
        other => return Err(LinkError::NotAnId(other.to_string())),
    };
    let mut rest = object.clone();
    rest.remove(KEY);
    Ok((request, Value::Object(rest)))
}
