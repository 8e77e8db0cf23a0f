//! How a fish combines its five SIMBA steering forces into one (Lim & Tan; see
//! `docs/boids.md`, "The control modes"). The two papers name the modes
//! differently; all four are here:
//!
//! - **Blended** (the steering paper's "direct"): every force, every step, as a
//!   weighted sum.
//! - **Classic**: one action per step, the most pressing weighted urge (weight ×
//!   share × how much the urge is needed now, 0–1; see [`combine`]).
//! - **Direct alternate**: draw ρ ∈ [0, 1) once per step; each force whose weight
//!   w ∈ [0, 1] satisfies ρ < w is applied (so force i acts on a fraction wᵢ of
//!   the steps).
//! - **Monte Carlo**: draw ρ ∈ [0, Σw); only the force whose cumulative interval
//!   holds ρ is applied (force i acts on a fraction wᵢ/Σw of the steps). The
//!   published partition of 3.2 is [`MONTE_CARLO_PAPER_WEIGHTS`].
//!
//! Weights are on the papers' 0–100 slider scale. Following the steering paper's
//! implementation section, a full containment, alignment, cohesion or separation
//! slider gives at most 25 % of the maximum steering force and a full avoidance
//! slider 100 % ([`FORCE_SHARE_AT_FULL_WEIGHT`]). In Blended mode each force acts
//! at its weighted share. In the three one-action modes the weight decides how
//! often (Direct alternate, Monte Carlo) or whether (Classic) a force is chosen,
//! and the chosen force acts at its full share: its average effect then grows with
//! the weight, as in Blended mode, not with the weight squared.
//!
//! Wander and fleeing from a shark are not among the five: they act on top of
//! every mode (a fish does not roll dice about fleeing), and the UI says so.

use glam::Vec3;
use rand::Rng;
use serde::{Deserialize, Serialize};

use super::metrics::ForceWindow;

/// The five forces, in this order everywhere.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Force {
    Containment,
    Alignment,
    Cohesion,
    Separation,
    Avoidance,
}

impl Force {
    pub const ALL: [Self; 5] = [
        Self::Containment,
        Self::Alignment,
        Self::Cohesion,
        Self::Separation,
        Self::Avoidance,
    ];
}

/// Share of the maximum steering force that a weight of 100 gives, per force
/// (containment, alignment, cohesion, separation, avoidance): the steering paper's
/// implementation section.
pub const FORCE_SHARE_AT_FULL_WEIGHT: [f32; 5] = [0.25, 0.25, 0.25, 0.25, 1.0];

/// Share of the maximum steering force that a wander slider of 100 gives.
/// Default 0.25 (chosen): the same as a full containment, alignment, cohesion or
/// separation slider, so wander is read on the urges' scale.
pub const WANDER_SHARE_AT_FULL_WEIGHT: f32 = 0.25;

/// The Monte Carlo partition of 3.2 published by Lim & Tan: containment 0–0.6,
/// alignment 0.6–1.3, avoidance 1.3–1.5, cohesion 1.5–2.8, separation 2.8–3.2,
/// as weights in [`Force::ALL`] order.
pub const MONTE_CARLO_PAPER_WEIGHTS: [f32; 5] = [0.6, 0.7, 1.3, 0.4, 0.2];

/// Lim & Tan's Table 1, "individual" (solitary) animals, in [`Force::ALL`] order:
/// containment 17–18, alignment 17–18, cohesion 0, separation 64–66, avoidance
/// 64–66 (whole numbers inside the published ranges, so the sliders show them).
pub const INDIVIDUAL_WEIGHTS: [f32; 5] = [18.0, 18.0, 0.0, 65.0, 65.0];

/// Lim & Tan's Table 1, "group" (schooling) animals, in [`Force::ALL`] order:
/// containment 25–26, alignment 25–26, cohesion 28–30, separation 25–26,
/// avoidance 97–100.
pub const GROUP_WEIGHTS: [f32; 5] = [26.0, 26.0, 29.0, 26.0, 98.0];

/// The four ways of combining forces.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ControlMode {
    #[default]
    Blended,
    Classic,
    DirectAlternate,
    MonteCarlo,
}

impl ControlMode {
    pub const ALL: [Self; 4] = [
        Self::Blended,
        Self::Classic,
        Self::DirectAlternate,
        Self::MonteCarlo,
    ];

    /// One sentence a student understands.
    pub fn explanation(self) -> &'static str {
        crate::i18n::ts(match self {
            Self::Blended => "boids-mode-blended-explanation",
            Self::Classic => "boids-mode-classic-explanation",
            Self::DirectAlternate => "boids-mode-direct-alternate-explanation",
            Self::MonteCarlo => "boids-mode-monte-carlo-explanation",
        })
    }
}

/// The steering force for this step and which forces were applied (for the
/// "how often was each force chosen" statistics).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Combined {
    pub force_m_per_s2: Vec3,
    pub applied: [bool; 5],
}

/// How much each urge is needed now, 0–1, read from the forces themselves:
/// ‖force‖ / maximum force. The boid layer uses it for every urge but
/// separation, whose force saturates in any school (see
/// [`crate::sim::boids::forces::NeighbourForces::separation_need`]).
pub fn needs_from_forces(forces: &[Vec3; 5], max_force_m_per_s2: f32) -> [f32; 5] {
    std::array::from_fn(|i| {
        if max_force_m_per_s2 > 0.0 {
            forces[i].length() / max_force_m_per_s2
        } else {
            0.0
        }
    })
}

/// Combines `forces` (each a full-strength steering force, already limited to
/// `max_force`) by `weights` (0–100 each) under `mode`.
///
/// `needs` (0–1 each) say how much each urge is needed now; only Classic
/// reads them. Classic applies the urge with the largest weight × share ×
/// need, so a heavily weighted urge acts whenever it has something to do and
/// a lightly weighted one when the others are content. (Ranking by the
/// forces' magnitudes alone let separation win every step inside a school,
/// where every fish is in its neighbours' personal space and the summed
/// intrusion saturates: see `docs/boids.md`.)
pub fn combine(
    mode: ControlMode,
    forces: &[Vec3; 5],
    needs: &[f32; 5],
    weights: &[f32; 5],
    max_force_m_per_s2: f32,
    rng: &mut impl Rng,
) -> Combined {
    let w: [f32; 5] = std::array::from_fn(|i| sanitize_weight(weights[i]) / 100.0);
    let mut applied = [false; 5];
    match mode {
        ControlMode::Blended => {
            for (i, a) in applied.iter_mut().enumerate() {
                *a = w[i] > 0.0;
            }
        }
        ControlMode::Classic => {
            let score = |i: usize| {
                let need = if needs[i].is_finite() {
                    needs[i].clamp(0.0, 1.0)
                } else {
                    0.0
                };
                w[i] * FORCE_SHARE_AT_FULL_WEIGHT[i] * need
            };
            let most_pressing = (0..5)
                .filter(|&i| forces[i].length_squared() > 0.0 && score(i) > 0.0)
                .max_by(|&a, &b| score(a).total_cmp(&score(b)));
            if let Some(i) = most_pressing {
                applied[i] = true;
            }
        }
        ControlMode::DirectAlternate => {
            let rho: f32 = rng.random();
            for (i, a) in applied.iter_mut().enumerate() {
                *a = rho < w[i];
            }
        }
        ControlMode::MonteCarlo => {
            if let Some(i) = monte_carlo_pick(&w, rng) {
                applied[i] = true;
            }
        }
    }
    Combined {
        force_m_per_s2: applied_sum(
            &contributions(mode, forces, weights),
            &applied,
            max_force_m_per_s2,
        ),
        applied,
    }
}

/// What each force adds to the steering under `mode` when it is applied (m/s²):
/// in Blended mode each force at its weighted share (weight/100 × share); in the
/// one-action modes the weight decided how often (or whether) a force is chosen,
/// and the chosen force acts at its full share, so its average effect grows with
/// the weight, not with the weight squared.
pub fn contributions(mode: ControlMode, forces: &[Vec3; 5], weights: &[f32; 5]) -> [Vec3; 5] {
    std::array::from_fn(|i| match mode {
        ControlMode::Blended => {
            forces[i] * (sanitize_weight(weights[i]) / 100.0 * FORCE_SHARE_AT_FULL_WEIGHT[i])
        }
        _ => forces[i] * FORCE_SHARE_AT_FULL_WEIGHT[i],
    })
}

/// The steering of the applied `contributions` ([`contributions`]): their sum,
/// limited to `max_force_m_per_s2`.
pub fn applied_sum(
    contributions: &[Vec3; 5],
    applied: &[bool; 5],
    max_force_m_per_s2: f32,
) -> Vec3 {
    let sum: Vec3 = (0..5)
        .filter(|&i| applied[i])
        .map(|i| contributions[i])
        .sum();
    limit_finite(sum, max_force_m_per_s2)
}

/// Draws ρ ∈ [0, Σw) and returns the force whose cumulative interval holds it;
/// `None` when every weight is 0.
pub fn monte_carlo_pick(weights: &[f32; 5], rng: &mut impl Rng) -> Option<usize> {
    let total: f32 = weights.iter().map(|&w| sanitize_weight(w)).sum();
    if total <= 0.0 {
        return None;
    }
    let rho = rng.random::<f32>() * total;
    let mut upper = 0.0;
    for (i, &w) in weights.iter().enumerate() {
        upper += sanitize_weight(w);
        if rho < upper {
            return Some(i);
        }
    }
    // ρ rounded up to the total: the last force with a weight.
    weights.iter().rposition(|&w| sanitize_weight(w) > 0.0)
}

/// The control-mode stage of the boid step: combines each fish's urges under
/// the mode (the random modes draw from the world's generator, fish by fish in
/// the step's order) and counts how often each urge was applied, for the force
/// frequencies of the metrics.
#[derive(Clone, Debug, Default)]
pub(super) struct ControlStage {
    /// This step's way of combining.
    mode: ControlMode,
    /// This step's maximum steering force, m/s².
    max_force_m_per_s2: f32,
    /// How many fish applied each urge so far in this step.
    applied_counts: [u32; 5],
    window: ForceWindow,
}

impl ControlStage {
    /// Starts a step that combines under `mode`, limited to
    /// `max_force_m_per_s2`.
    pub(super) fn begin_step(&mut self, mode: ControlMode, max_force_m_per_s2: f32) {
        self.mode = mode;
        self.max_force_m_per_s2 = max_force_m_per_s2;
        self.applied_counts = [0; 5];
    }

    /// One fish's steering from its urges' `forces` and `needs` under its
    /// `weights` ([`combine`]), counted.
    pub(super) fn combine(
        &mut self,
        forces: &[Vec3; 5],
        needs: &[f32; 5],
        weights: &[f32; 5],
        rng: &mut impl Rng,
    ) -> Combined {
        let combined = combine(
            self.mode,
            forces,
            needs,
            weights,
            self.max_force_m_per_s2,
            rng,
        );
        for (count, applied) in self.applied_counts.iter_mut().zip(combined.applied) {
            *count += u32::from(applied);
        }
        combined
    }

    /// Ends a step of `fish_steps` fish: its counts join the window.
    pub(super) fn end_step(&mut self, fish_steps: u32) {
        self.window.push(self.applied_counts, fish_steps);
    }

    /// How often each urge was applied, recently and since the start.
    pub(super) fn window(&self) -> &ForceWindow {
        &self.window
    }
}

fn sanitize_weight(w: f32) -> f32 {
    if w.is_finite() { w.max(0.0) } else { 0.0 }
}

fn limit_finite(v: Vec3, max_len: f32) -> Vec3 {
    crate::sim::common::steering::limit(v, max_len)
}

#[cfg(test)]
mod tests {
    use crate::sim::boids::control_mode::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    const DRAWS: usize = 100_000;

    #[test]
    fn monte_carlo_frequencies_match_the_published_partition_within_one_percent() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let mut counts = [0usize; 5];
        for _ in 0..DRAWS {
            counts[monte_carlo_pick(&MONTE_CARLO_PAPER_WEIGHTS, &mut rng).unwrap()] += 1;
        }
        let total: f32 = MONTE_CARLO_PAPER_WEIGHTS.iter().sum();
        assert!((total - 3.2).abs() < 1e-6);
        for i in 0..5 {
            let expected = MONTE_CARLO_PAPER_WEIGHTS[i] / total;
            let seen = counts[i] as f32 / DRAWS as f32;
            assert!(
                (seen - expected).abs() < 0.01,
                "force {i}: {seen} vs {expected}"
            );
        }
    }

    #[test]
    fn direct_alternate_applies_each_force_on_the_share_of_steps_its_weight_says() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let weights = [18.0, 25.0, 0.0, 65.0, 100.0];
        let forces = [Vec3::X; 5];
        let mut counts = [0usize; 5];
        for _ in 0..DRAWS {
            let c = combine(
                ControlMode::DirectAlternate,
                &forces,
                &[1.0; 5],
                &weights,
                10.0,
                &mut rng,
            );
            for (count, applied) in counts.iter_mut().zip(c.applied) {
                *count += usize::from(applied);
            }
        }
        for i in 0..5 {
            let seen = counts[i] as f32 / DRAWS as f32;
            assert!(
                (seen - weights[i] / 100.0).abs() < 0.01,
                "force {i}: {seen}"
            );
        }
    }

    #[test]
    fn table_1_presets_follow_the_solitary_versus_group_hypothesis() {
        // Solitary: high separation and containment share, low cohesion and alignment.
        let share = |w: &[f32; 5], i: usize| w[i] / w.iter().sum::<f32>();
        let (c, a, h, s) = (0, 1, 2, 3);
        assert!(share(&INDIVIDUAL_WEIGHTS, s) > share(&GROUP_WEIGHTS, s));
        assert!(share(&INDIVIDUAL_WEIGHTS, h) < share(&GROUP_WEIGHTS, h));
        assert!(INDIVIDUAL_WEIGHTS[a] < GROUP_WEIGHTS[a]);
        assert!(INDIVIDUAL_WEIGHTS[c] < GROUP_WEIGHTS[c]);
        // Shares close to the table's percentages (10/10/0/40/40 and 12/12/14/12/48).
        let expected_individual = [0.10, 0.10, 0.0, 0.40, 0.40];
        let expected_group = [0.12, 0.12, 0.14, 0.12, 0.48];
        for i in 0..5 {
            assert!((share(&INDIVIDUAL_WEIGHTS, i) - expected_individual[i]).abs() < 0.015);
            assert!((share(&GROUP_WEIGHTS, i) - expected_group[i]).abs() < 0.015);
        }
    }

    #[test]
    fn classic_applies_only_the_strongest_weighted_force() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let forces = [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y];
        // Avoidance's share is 4× the others', so 30 on avoidance beats 100 elsewhere.
        let c = combine(
            ControlMode::Classic,
            &forces,
            &needs_from_forces(&forces, 10.0),
            &[100.0, 0.0, 0.0, 0.0, 30.0],
            10.0,
            &mut rng,
        );
        assert_eq!(c.applied, [false, false, false, false, true]);
        // The one action acts at its full share (avoidance: 100 %), whatever its weight.
        assert!((c.force_m_per_s2 - (-Vec3::Y)).length() < 1e-6);
    }

    #[test]
    fn classic_ranks_the_urges_by_how_much_each_is_needed_not_by_force() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        // Separation saturated (full force) but barely needed; alignment weaker
        // but needed: alignment is the one action.
        let forces = [
            Vec3::ZERO,
            Vec3::X * 3.0,
            Vec3::ZERO,
            Vec3::Y * 8.0,
            Vec3::ZERO,
        ];
        let weights = [26.0, 26.0, 29.0, 26.0, 98.0];
        let c = combine(
            ControlMode::Classic,
            &forces,
            &[0.0, 0.375, 0.0, 0.2, 0.0],
            &weights,
            8.0,
            &mut rng,
        );
        assert_eq!(c.applied, [false, true, false, false, false]);
        assert!((c.force_m_per_s2 - Vec3::X * 0.75).length() < 1e-6);
        // The same forces ranked by magnitude: separation wins.
        let c = combine(
            ControlMode::Classic,
            &forces,
            &needs_from_forces(&forces, 8.0),
            &weights,
            8.0,
            &mut rng,
        );
        assert_eq!(c.applied, [false, false, false, true, false]);
        // A needed urge with no force to give is not chosen.
        let c = combine(
            ControlMode::Classic,
            &[Vec3::ZERO, Vec3::X, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO],
            &[1.0, 0.1, 1.0, 1.0, 1.0],
            &weights,
            8.0,
            &mut rng,
        );
        assert_eq!(c.applied, [false, true, false, false, false]);
    }

    /// Mean force over many draws of `mode` with one force on (along x) at `weight`.
    fn mean_force(mode: ControlMode, weight: f32) -> f32 {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let forces = [Vec3::ZERO, Vec3::X, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO];
        // The other weights fill the Monte Carlo partition so weights are chances.
        let weights = [0.0, weight, 100.0 - weight, 0.0, 0.0];
        let sum: f32 = (0..DRAWS)
            .map(|_| {
                combine(mode, &forces, &[1.0; 5], &weights, 10.0, &mut rng)
                    .force_m_per_s2
                    .x
            })
            .sum();
        sum / DRAWS as f32
    }

    #[test]
    fn in_the_random_modes_the_weight_sets_how_often_and_the_chosen_force_acts_in_full() {
        // A chosen force acts at its full share (0.25 of the force for alignment), so
        // the mean force grows in proportion to the weight, as in Blended mode: not as
        // the weight squared.
        for mode in [ControlMode::DirectAlternate, ControlMode::MonteCarlo] {
            for weight in [20.0, 50.0, 80.0] {
                let mean = mean_force(mode, weight);
                let blended = mean_force(ControlMode::Blended, weight);
                assert!(
                    (mean - blended).abs() < 0.01,
                    "{mode:?} at {weight}: {mean} vs blended {blended}"
                );
                assert!((blended - 0.25 * weight / 100.0).abs() < 1e-3, "{blended}");
            }
        }
    }

    #[test]
    fn blended_is_the_weighted_sum_with_the_papers_shares() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let forces = [Vec3::X * 2.0; 5];
        let c = combine(
            ControlMode::Blended,
            &forces,
            &[1.0; 5],
            &[100.0, 50.0, 0.0, 0.0, 10.0],
            10.0,
            &mut rng,
        );
        // 2·(1·0.25 + 0.5·0.25 + 0.1·1.0) = 0.95
        assert!((c.force_m_per_s2.x - 0.95).abs() < 1e-5);
        assert_eq!(c.applied, [true, true, false, false, true]);
    }

    #[test]
    fn zero_nan_and_huge_weights_stay_finite_and_bounded() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let forces = [Vec3::splat(1e30), Vec3::NAN, Vec3::ONE, Vec3::ZERO, Vec3::X];
        for mode in ControlMode::ALL {
            for weights in [
                [0.0; 5],
                [f32::NAN; 5],
                [1e9; 5],
                [-5.0, 100.0, 100.0, 100.0, 100.0],
            ] {
                let needs = [f32::NAN, 1e9, -1.0, 0.5, 1.0];
                let c = combine(mode, &forces, &needs, &weights, 1.5, &mut rng);
                assert!(c.force_m_per_s2.is_finite(), "{mode:?} {weights:?}");
                assert!(c.force_m_per_s2.length() <= 1.5 + 1e-4);
            }
        }
        assert_eq!(monte_carlo_pick(&[0.0; 5], &mut rng), None);
    }
}
