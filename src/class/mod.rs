//! A class together (issue 37), the app's side of the class server's protocol
//! v1 (`class/`, docs/class.md). Pure and tested natively:
//!
//! - [`outbox`]: every message a student or teacher sends gets a unique id and
//!   waits (kept in the browser's storage) until its `ack` arrives; after a
//!   reconnect everything unacknowledged is sent again, and the server applies
//!   a resent id once.
//! - [`view`]: the server's messages (`joined`, `ack`, `error`, the teacher's
//!   `class` view, the student's `you` view) parsed into types.
//! - [`stats`]: the prediction histogram and the pooled result (every
//!   student's measured value of a measure as one distribution, its mean and
//!   95 % interval).
//! - [`session`]: one connection's life: who it is (student or teacher), the
//!   hello it opens with, the reconnect backoff, the status line, the step a
//!   held class may reach.
//!
//! The transport (a WebSocket and `fetch`) is the thin web-only layer in
//! `web/class_net.rs`; the windows are `ui/class_panel.rs`.

pub mod outbox;
pub mod session;
pub mod stats;
pub mod view;

#[cfg(test)]
mod tests;

/// The protocol version the app speaks.
pub const PROTOCOL: u64 = 1;

/// The steps a class server knows, in order.
pub const STEPS: [&str; 4] = ["look", "predict", "run", "explain"];

/// The class step of an investigation's step: the intro is *look*, the reveal
/// (after the last prompt) still *explain*.
pub fn class_step(step: crate::investigation::Step) -> &'static str {
    use crate::investigation::Step;
    match step {
        Step::Intro => "look",
        Step::Predict => "predict",
        Step::Run => "run",
        Step::Explain | Step::Reveal => "explain",
    }
}

/// Where `step` is in [`STEPS`] (`None` for a name the protocol does not have).
pub fn step_index(step: &str) -> Option<usize> {
    STEPS.iter().position(|s| *s == step)
}

/// The hold rule: may a student go to `step` while the teacher holds the class
/// at `held` (`None`: no hold)? A student may reach the held step, not beyond.
pub fn may_go_to(step: &str, held: Option<&str>) -> bool {
    match (step_index(step), held.and_then(step_index)) {
        (_, None) => true,
        (Some(s), Some(h)) => s <= h,
        (None, Some(_)) => false,
    }
}

/// A class code as a student types it: upper case, without spaces or dashes;
/// `None` unless it is 6 characters of the server's alphabet.
pub fn normalise_code(text: &str) -> Option<String> {
    const ALPHABET: &str = "ABCDEFGHJKMNPQRSTUVWXYZ23456789"; // words: class code alphabet
    let code: String = text
        .chars()
        .filter(|c| !c.is_whitespace() && *c != '-')
        .map(|c| c.to_ascii_uppercase())
        .collect();
    (code.chars().count() == 6 && code.chars().all(|c| ALPHABET.contains(c))).then_some(code)
}

/// A nickname as typed, trimmed; `None` when empty, longer than 24 characters
/// or holding control characters (the server's rule).
pub fn normalise_nickname(text: &str) -> Option<String> {
    let name = text.trim();
    (!name.is_empty() && name.chars().count() <= 24 && !name.chars().any(char::is_control))
        .then(|| name.to_owned())
}

/// The measured numbers of an investigation's outcome as a `result` message's
/// `values`: one stable name per row (the same in every language), so the
/// teacher's dashboard pools the same measure across students.
pub fn result_values(
    investigation: &crate::investigation::Investigation,
    outcome: &crate::investigation::Outcome,
) -> std::collections::BTreeMap<String, f64> {
    use crate::investigation::MeasurementKind;
    let names: &[&str] = match investigation.measurement {
        // words: measure names in the class protocol
        MeasurementKind::CatchesInBothTanks { .. } => &["caught_loners", "caught_school"],
        // words: measure names in the class protocol
        MeasurementKind::AlignmentOnOff { .. } => &["polarization_on", "polarization_off"],
        _ => &[],
    };
    outcome
        .rows
        .iter()
        .enumerate()
        .filter(|(_, r)| r.value.is_finite())
        .take(16)
        .map(|(k, r)| {
            let name = names
                .get(k)
                .map_or_else(|| format!("row{}", k + 1), |n| (*n).to_owned()); // words: measure name
            (name, r.value)
        })
        .collect()
}
