//! Opening an investigation by link (`?investigation=why-school`) and through
//! `shoal.set({investigation: "why-school"})`, validated: an unknown id is
//! refused with a message naming the known ones, and nothing else in the link
//! or the patch is lost.

use serde_json::Value;

use super::catalogue::{Investigation, find, known_ids};

/// The query parameter (and `set()` key) that opens an investigation.
pub const KEY: &str = "investigation";

/// Why an investigation could not be opened.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LinkError {
    #[error("there is no investigation '{id}'; the investigations are: {known}")]
    UnknownId { id: String, known: String },
    #[error("investigation: expected an id such as \"why-school\" (or null to close it), got {0}")]
    NotAnId(String),
}

fn lookup(id: &str) -> Result<&'static Investigation, LinkError> {
    find(id).ok_or_else(|| LinkError::UnknownId {
        id: id.to_owned(),
        known: known_ids(),
    })
}

/// The investigation a page address asks for (`?investigation=<id>`, before
/// any `#`), if it asks for one.
pub fn from_url(url: &str) -> Option<Result<&'static Investigation, LinkError>> {
    let before_fragment = url.split('#').next().unwrap_or_default();
    let (_, query) = before_fragment.split_once('?')?;
    query.split('&').find_map(|part| {
        let (key, value) = part.split_once('=').unwrap_or((part, ""));
        (key == KEY).then(|| lookup(value.trim()))
    })
}

/// The address without its `investigation` parameter (and without a `?` left
/// empty), so a share link names the investigation only when one is open.
pub fn without_investigation(url: &str) -> String {
    let (address, query) = match url.split_once('?') {
        Some((a, q)) => (a, q),
        None => return url.to_owned(),
    };
    let kept: Vec<&str> = query
        .split('&')
        .filter(|part| !part.is_empty() && part.split('=').next() != Some(KEY))
        .collect();
    if kept.is_empty() {
        address.to_owned()
    } else {
        format!("{address}?{}", kept.join("&"))
    }
}

/// `url` with `?investigation=<id>` (replacing any it had).
pub fn with_investigation(url: &str, id: &str) -> String {
    let base = without_investigation(url);
    let sep = if base.contains('?') { '&' } else { '?' };
    format!("{base}{sep}{KEY}={id}")
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
