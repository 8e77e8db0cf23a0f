//! The reef: fish with minds (Tu & Terzopoulos §5–7). Each step every animal
//! perceives (`perception`), its mind chooses an intention (`mind`), a
//! behaviour routine turns it into a wish (`behaviour`, `courtship`), the
//! motor choice drives the muscle body (`motor_choice`) or the point mass
//! follows it; the world (`world`) holds the step order, feeding and
//! predation, plankton, seaweed, the demos and the event log; `school_watch`
//! logs what the prey school does (splits, joins up, meets the pillar). Light and
//! temperature of the water: `environment`. The reef's tuning: `params`.

pub mod behaviour;
#[cfg(not(target_arch = "wasm32"))]
pub mod census;
pub mod courtship;
pub mod demos;
pub mod environment;
pub mod events;
pub mod feeding;
pub mod mind;
pub mod motor_choice;
pub mod params;
pub mod perception;
pub mod report;
pub mod school_watch;
pub mod world;

#[cfg(test)]
mod tests;
