//! The learning centre of the artificial fish, Tu & Terzopoulos 1994 §4: a
//! "brain-dead" fish with a working body learns to use its twelve muscles by
//! practice, then abstracts what it learned into a few sinusoids per muscle and
//! uses them as motor controllers.
//!
//! # Low-level learning (§4.2, `muscle_spline.rs`, `objective.rs`, `annealing.rs`)
//! The actuation functions u(t) = [u₁ … u₁₂](t), each in [0, 1], are sampled at
//! N (default 15) times over the training interval [t₀, t₁] and recovered by a
//! linear or cubic spline ([`MuscleSpline`]). The objective, eq. (2),
//!
//! E(u) = ∫_{t₀}^{t₁} (μ₁ E_u(u(t)) + μ₂ E_v(v(t))) dt,
//!
//! with the smoothness term, eq. (3) (a penalty: the sign in the text is garbled),
//!
//! E_u = ½ (ν₁ ‖du/dt‖² + ν₂ ‖d²u/dt²‖²),
//!
//! and a trajectory term E_v ([`Task`]: final distance to a target, the paper's usual
//! choice; closeness to a speed; a turn at a given rate). Each evaluation of E is a
//! forward simulation of the physical fish ([`evaluate`]). Simulated annealing
//! ([`Trainer`]) perturbs the samples, keeps improvements and sometimes worse moves.
//!
//! # Abstraction (§4.3, `abstraction.rs`)
//! A short-time FFT of the learned controls finds the few frequencies that carry
//! them; u(t) ≈ Σ_{i=0}^{M} αᵢ Bᵢ(t) with B₀ = 1 and M (usually 1–2) sinusoids
//! ([`AbstractedController`]).
//!
//! # Use (§4.3, `learned_motor.rs`, `target_tracking.rs`, `race.rs`)
//! Abstracted controllers of routine drills (straight swims, left and right turns)
//! are interpolated in amplitude, frequency and phase into a speed and steering map
//! ([`LearnedMotorMap`], [`LearnedMotor`]) that drives the muscles step by step like
//! the hand-tuned swim-MC and turn-MC. A learned fish swims between two buoys with it
//! (Fig. 9, [`BuoyTracker`]); sharks trained for more annealing steps race farther
//! (Fig. 7, [`Race`]). Controller sets are saved and loaded as JSON
//! ([`LearnedControllerSet`]).

pub mod abstraction;
pub mod annealing;
#[cfg(not(target_arch = "wasm32"))]
pub mod census;
pub mod learned_motor;
pub mod learned_set;
pub mod learning_lab;
pub mod muscle_spline;
pub mod objective;
pub mod race;
pub mod report;
pub mod target_tracking;

pub use abstraction::{
    AbstractedController, Abstraction, AbstractionSettings, FourierMode, abstract_controls,
};
pub use annealing::{AnnealingSchedule, Checkpoint, HistoryPoint, Trainer};
pub use learned_motor::{
    LearnedController, LearnedMapError, LearnedMotor, LearnedMotorMap, MotionMeasurement,
};
pub use learned_set::{
    LearnedControllerSet, LearnedSetError, TrainedDrill, routine_drills, train_set,
};
pub use muscle_spline::{Interpolation, MuscleSpline};
pub use objective::{Evaluation, ObjectiveWeights, Task, TrainingSetup, evaluate};
pub use race::{PAPER_RACE_STEPS, Race, RaceEntrant};
pub use target_tracking::BuoyTracker;
