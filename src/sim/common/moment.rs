//! The moment a scene is about (the shark's catch, the spawning), which
//! *Skip to the moment* runs ahead to: a type every scene may name without
//! knowing the scene interface.

use serde::Serialize;

/// The moment a scene is about (the shark's catch, the spawning), which
/// *Skip to the moment* runs ahead to.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Moment {
    /// What the student will see, in English whatever the screen's language
    /// (`shoal.state()` reads it): "the shark's next catch".
    pub what: &'static str,
    /// Its message in the catalogue, for the button (see [`Moment::words`]).
    #[serde(skip)]
    pub what_id: &'static str,
    /// Seconds of the run shown before it (the chase, the approach).
    pub lead_secs: f64,
    /// Follow the animal it is about (a catch, a bite), or keep the demo's
    /// own view (the whole school at the pillar, seen from above).
    pub follow: bool,
}

impl Moment {
    /// What the student will see, in the language in force (the button).
    pub fn words(&self) -> &'static str {
        crate::i18n::ts(self.what_id)
    }
}

/// A scene's moment, found: when it happens, whom it is about and the log's
/// line for it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FoundMoment {
    pub time_secs: f64,
    /// The animal it is about.
    pub subject: u32,
    /// Select and follow it (see [`Moment::follow`]).
    pub follow: bool,
    /// The log's line for it in English (`shoal.state()` reads it).
    pub text: String,
    /// The same line in the language in force when it was found (the
    /// notice on the screen).
    #[serde(skip)]
    pub words: String,
}
