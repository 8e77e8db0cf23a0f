//! The reef: fish with minds (Tu & Terzopoulos §5–7). The step is a pipeline
//! of stages, each owning its state and taking explicit inputs; `world` holds
//! them and lists their order. The animals (bodies and minds) are `animal`;
//! each step every animal perceives (`perception`), its mind chooses an
//! intention (`animal`'s minds stage, `mind`), a behaviour routine turns it
//! into a wish (`behaviour`, and a courting pair's `pair`), and its body moves (`bodies`: the
//! motor choice drives the muscle body, `motor_choice`, or the point mass
//! follows the wish). Then mouths feed (`feeding`, which also owns the
//! plankton), pairs court (`courtship`), seaweed sways (`seaweed`), collisions
//! are counted (`contacts`), and `school_watch` logs what the prey school does
//! (splits, joins up, meets the pillar) to the event log (`events`). The demos
//! and how they are stocked: `demos`. Light and temperature of the water:
//! `environment`. The reef's tuning: `params`.

pub mod animal;
pub mod behaviour;
pub mod bodies;
#[cfg(not(target_arch = "wasm32"))]
pub mod census;
pub mod contacts;
pub mod courtship;
pub mod demos;
pub mod environment;
pub mod events;
pub mod feeding;
pub mod mind;
pub mod motor_choice;
pub mod pair;
pub mod params;
pub mod perception;
pub mod report;
pub mod school_watch;
pub mod seaweed;
pub mod world;

#[cfg(test)]
mod tests;
