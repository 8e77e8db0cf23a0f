//! One clock for the fish world: the paper's time unit in seconds.
//!
//! Tu & Terzopoulos give their constants in their own time unit: the body's
//! stiffness, damping and time step Δt = 0.055 (footnote 2) and the mind's
//! digestion and libido rates p0 and p1 (§6.1) are all per *paper time unit*,
//! and the paper never says how long one is. Shoal fixes it once, here:
//!
//! **one paper time unit = 1/40 s** ([`PAPER_TIME_UNITS_PER_SEC`] = 40).
//!
//! The body sets it: read as seconds, the paper's springs and masses bend at
//! about 0.25 Hz and the fish crawls; at 40 units per second the tail beats at
//! 1–3 Hz and the fish swims at about 0.6 body lengths/s (`body/fish_body.rs`,
//! "Time scale"). The mind reads the same unit: the time since the last meal Δt_H
//! and since the last mating Δt_L are counted in paper time units, so hunger and
//! libido grow at the paper's p0 and p1 per unit, 40 × p0 and 40 × p1 per second
//! (`reef/mind/mental_state.rs`).
//!
//! Shoal's fish world advances in steps of [`FISH_STEP_SECS`] = 0.055 s of
//! simulated time = 2.2 paper time units, the length of 40 of the paper's steps.
//! The muscle body splits each into substeps (`BodyParams::substeps`); the
//! point-mass body and the minds take it whole.

/// Paper time units in one second of simulated time. 40, chosen for the body
/// (see the module doc); every part of the fish world uses this one value.
pub const PAPER_TIME_UNITS_PER_SEC: f32 = 40.0;

/// One step of the fish world (muscle bodies, point-mass reef bodies, minds),
/// seconds: 0.055 s = 2.2 paper time units = 40 of the paper's Δt = 0.055.
pub const FISH_STEP_SECS: f32 = 0.055;

/// `secs` of simulated time in paper time units.
pub fn paper_units(secs: f32) -> f32 {
    secs * PAPER_TIME_UNITS_PER_SEC
}

#[cfg(test)]
mod tests {
    use crate::sim::common::paper_time::*;

    #[test]
    fn a_fish_step_is_forty_of_the_papers_steps() {
        let paper_dt = 0.055;
        assert!((paper_units(FISH_STEP_SECS) / paper_dt - 40.0).abs() < 1e-4);
        assert_eq!(paper_units(1.0), 40.0);
    }
}
