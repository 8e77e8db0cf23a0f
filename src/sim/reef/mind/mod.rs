//! The artificial fish's mind (Tu & Terzopoulos 1994 §6–7): innate habits, the
//! mental state (hunger, libido, fear) and the intention generator with its
//! memory and focusser. Perception (`sim/perception.rs`) feeds it; the behaviour
//! routines (`sim/behaviour.rs`) carry out the intention it chooses.

pub mod habits;
pub mod intention;
pub mod mental_state;

pub use habits::{FishKind, Habits, Liking, Sex};
pub use intention::{Focus, Intention, IntentionGenerator, Percept, Target};
pub use mental_state::{MentalConstants, MentalState};
