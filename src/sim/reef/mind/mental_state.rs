//! Hunger, libido and fear: the three mental state variables of Tu & Terzopoulos
//! 1994 §6.1, each in [0, 1], higher meaning a stronger urge to eat, mate and
//! avoid danger.
//!
//! - Hunger H(t) = min[1 − n_e(t)·R(Δt_H)/α, 1], R(x) = 1 − p0·x (digestion), n_e
//!   the food eaten, Δt_H the time since the last meal, α the appetite.
//! - Libido L(t) = min[s(Δt_L)·(1 − H(t)), 1], s(x) = p1·x, Δt_L the time since
//!   the last mating.
//! - Fear F(t) = min[Σ_i F_i, 1], F_i = min[D0/d_i, 1], d_i the distance to seen
//!   predator i.
//!
//! **Time.** Δt_H and Δt_L are counted in the paper's time units, one of which is
//! 1/40 s in Shoal, the same unit the body runs on (`sim::paper_time`), and p0, p1
//! are per paper time unit. With the paper's nominal p0 = 0.00067 a fish that has
//! just eaten its fill (n_e = α) is hungry again (H > 0.25) after 0.25/p0 = 373
//! units = 9.3 s and fully hungry after 1/p0 = 1493 units = 37.3 s; with its
//! nominal p1 = 0.0025 a fed, rested pacifist's libido passes 0.25 after 100 units
//! = 2.5 s. Shoal's fish default to slower, "calm" rates
//! ([`CALM_DIGESTION_RATE`], [`CALM_LIBIDO_RATE`]); the paper's are presets.
//!
//! **Food eaten.** H falls below 1 only while R > 0, so n_e is read as the food
//! in the stomach right after the last meal: at each meal the undigested rest
//! n_e·R(Δt_H) (never below 0) plus the new food becomes the new n_e, and Δt_H
//! restarts. Between meals this is the paper's formula exactly; H is also kept
//! at or above 0 (a fish that ate more than its appetite is simply full).
//!
//! **Fear distance.** D0 = 100 paper units, the paper's fish being 26 units
//! long (`body::PAPER_BODY_LENGTH`): D0 = 100/26 = 3.85 body lengths of the
//! frightened fish.

use serde::{Deserialize, Serialize};

use crate::sim::body::body_layout::PAPER_BODY_LENGTH;
use crate::sim::common::paper_time::paper_units;

/// The paper's nominal digestion rate p0, per paper time unit.
pub const NOMINAL_DIGESTION_RATE: f32 = 0.00067;
/// Shoal's default digestion rate p0, per paper time unit: 0.0003, chosen, a
/// departure from the paper's nominal [`NOMINAL_DIGESTION_RATE`]. On the one
/// clock (1/40 s a unit) the paper's nominal value makes a fish that ate its fill
/// hungry again (H > 0.25, the urge threshold) after 9.3 s; 0.0003 keeps the pace
/// the reef's behaviours were tuned at before the one clock (the mind then counted
/// p0 per 0.055 s step): hungry again after 21 s, fully hungry after 83 s.
pub const CALM_DIGESTION_RATE: f32 = 0.0003;
/// The paper's "ravenous" digestion rate p0, per paper time unit.
pub const RAVENOUS_DIGESTION_RATE: f32 = 0.005;
/// The paper's nominal libido rate p1, per paper time unit.
pub const NOMINAL_LIBIDO_RATE: f32 = 0.0025;
/// Shoal's default libido rate p1, per paper time unit: 0.0011, chosen with
/// [`CALM_DIGESTION_RATE`] (both about 0.45 of the paper's nominal values, the pace
/// the reef's behaviours were tuned at), a departure from
/// [`NOMINAL_LIBIDO_RATE`]. With the paper's value on the one clock a fed pacifist
/// wants to mate (L > 0.25) 2.5 s after mating, with 0.0011 after 5.7 s. Measured
/// (default reef, points, seed 2, 3 minutes, spawnings / fish collisions): calm
/// p0 and p1 6 / 50; calm p0 with the nominal p1 7 / 70 (over one collision per
/// fish per minute, the long-run test's limit); both nominal 5 / 38.
pub const CALM_LIBIDO_RATE: f32 = 0.0011;
/// The paper's "sexual mania" libido rate p1, per paper time unit.
pub const MANIC_LIBIDO_RATE: f32 = 0.01;
/// The paper's fear distance D0, paper units (a fish is 26 long).
pub const FEAR_DISTANCE_PAPER_UNITS: f32 = 100.0;

/// The per-species constants of the mental state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MentalConstants {
    /// p0, digestion rate per paper time unit (nominal 0.00067, ravenous 0.005).
    #[serde(alias = "digestion_rate_per_step")]
    pub digestion_rate_per_unit: f32,
    /// p1, libido growth per paper time unit (nominal 0.0025, sexual mania 0.01).
    #[serde(alias = "libido_rate_per_step")]
    pub libido_rate_per_unit: f32,
    /// α, appetite in food units (a plankton particle is 1, a prey fish
    /// [`PREY_FOOD_UNITS`]). Bigger fishes have a bigger α.
    pub appetite_food_units: f32,
    /// D0 in body lengths of this fish (paper: 100/26 = 3.85).
    pub fear_distance_body_lengths: f32,
}

/// Food units in one prey fish: a shark (appetite 4) is full after one.
pub const PREY_FOOD_UNITS: f32 = 4.0;

impl MentalConstants {
    /// Shoal's default constants with appetite `appetite_food_units`: the
    /// paper's nominal ones except the two rates, [`CALM_DIGESTION_RATE`] and
    /// [`CALM_LIBIDO_RATE`].
    pub fn shoal_default(appetite_food_units: f32) -> Self {
        Self {
            digestion_rate_per_unit: CALM_DIGESTION_RATE,
            libido_rate_per_unit: CALM_LIBIDO_RATE,
            ..Self::nominal(appetite_food_units)
        }
    }

    /// The paper's nominal constants with appetite `appetite_food_units`.
    pub fn nominal(appetite_food_units: f32) -> Self {
        Self {
            digestion_rate_per_unit: NOMINAL_DIGESTION_RATE,
            libido_rate_per_unit: NOMINAL_LIBIDO_RATE,
            appetite_food_units,
            fear_distance_body_lengths: FEAR_DISTANCE_PAPER_UNITS / PAPER_BODY_LENGTH,
        }
    }
}

/// Hunger, libido and fear of one fish, with the clocks they are computed from.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MentalState {
    /// H in [0, 1].
    pub hunger: f32,
    /// L in [0, 1].
    pub libido: f32,
    /// F in [0, 1].
    pub fear: f32,
    /// n_e: food in the stomach right after the last meal, food units.
    pub food_eaten: f32,
    /// Δt_H, seconds since the last meal.
    pub secs_since_meal: f32,
    /// Δt_L, seconds since the last mating.
    pub secs_since_mating: f32,
}

impl MentalState {
    /// A fish that has just eaten `food_eaten` units and mated `secs_since_mating`
    /// seconds ago; the variables are computed at once.
    pub fn new(constants: &MentalConstants, food_eaten: f32, secs_since_mating: f32) -> Self {
        let mut state = Self {
            hunger: 0.0,
            libido: 0.0,
            fear: 0.0,
            food_eaten: finite_or(food_eaten, 0.0).max(0.0),
            secs_since_meal: 0.0,
            secs_since_mating: finite_or(secs_since_mating, 0.0).max(0.0),
        };
        state.update(constants, 0.0, std::iter::empty());
        state
    }

    /// Advances the clocks by `dt_secs` and recomputes H, L and F from the
    /// distances (in the fish's body lengths) to the predators it sees now.
    pub fn update(
        &mut self,
        constants: &MentalConstants,
        dt_secs: f32,
        predator_distances_body_lengths: impl IntoIterator<Item = f32>,
    ) {
        let dt = finite_or(dt_secs, 0.0).max(0.0);
        self.secs_since_meal += dt;
        self.secs_since_mating += dt;
        self.hunger = hunger(constants, self.food_eaten, self.secs_since_meal);
        self.libido = libido(constants, self.hunger, self.secs_since_mating);
        self.fear = total_fear(constants, predator_distances_body_lengths);
    }

    /// The fish eats `food_units`: the undigested rest plus the new food fill the
    /// stomach and the meal clock restarts.
    pub fn eat(&mut self, constants: &MentalConstants, food_units: f32) {
        let rest = self.food_eaten * digestion_left(constants, self.secs_since_meal);
        self.food_eaten = rest.max(0.0) + finite_or(food_units, 0.0).max(0.0);
        self.secs_since_meal = 0.0;
        self.hunger = hunger(constants, self.food_eaten, 0.0);
        self.libido = libido(constants, self.hunger, self.secs_since_mating);
    }

    /// The fish has mated: the libido clock restarts.
    pub fn mated(&mut self, constants: &MentalConstants) {
        self.secs_since_mating = 0.0;
        self.libido = libido(constants, self.hunger, 0.0);
    }
}

/// R(Δt_H) = 1 − p0·Δt_H, with Δt_H in paper time units.
pub fn digestion_left(constants: &MentalConstants, secs_since_meal: f32) -> f32 {
    1.0 - constants.digestion_rate_per_unit * paper_units(secs_since_meal)
}

/// H = min[1 − n_e·R(Δt_H)/α, 1], kept at or above 0.
pub fn hunger(constants: &MentalConstants, food_eaten: f32, secs_since_meal: f32) -> f32 {
    let appetite = constants.appetite_food_units.max(1e-3);
    let h = 1.0 - food_eaten * digestion_left(constants, secs_since_meal) / appetite;
    finite_or(h, 1.0).clamp(0.0, 1.0)
}

/// L = min[p1·Δt_L·(1 − H), 1], with Δt_L in paper time units.
pub fn libido(constants: &MentalConstants, hunger: f32, secs_since_mating: f32) -> f32 {
    let s = constants.libido_rate_per_unit * paper_units(secs_since_mating);
    finite_or(s * (1.0 - hunger), 0.0).clamp(0.0, 1.0)
}

/// F_i = min[D0/d_i, 1] for one predator at `distance_body_lengths`.
pub fn fear_of(constants: &MentalConstants, distance_body_lengths: f32) -> f32 {
    if distance_body_lengths.is_nan() || distance_body_lengths <= 0.0 {
        return 1.0;
    }
    (constants.fear_distance_body_lengths / distance_body_lengths).clamp(0.0, 1.0)
}

/// F = min[Σ F_i, 1].
pub fn total_fear(
    constants: &MentalConstants,
    predator_distances_body_lengths: impl IntoIterator<Item = f32>,
) -> f32 {
    let sum: f32 = predator_distances_body_lengths
        .into_iter()
        .map(|d| fear_of(constants, d))
        .fold(0.0, |a, b| a + b);
    sum.min(1.0)
}

fn finite_or(x: f32, fallback: f32) -> f32 {
    if x.is_finite() { x } else { fallback }
}

#[cfg(test)]
mod tests {
    use crate::sim::reef::mind::mental_state::*;

    /// One paper time unit, seconds.
    const UNIT: f32 = 1.0 / crate::sim::common::paper_time::PAPER_TIME_UNITS_PER_SEC;

    #[test]
    fn hunger_matches_the_formula_by_hand() {
        let c = MentalConstants::nominal(4.0);
        // Ate 2 units 1000 paper time units ago: H = 1 − 2·(1 − 0.67)/4 = 0.835.
        let h = hunger(&c, 2.0, 1000.0 * UNIT);
        assert!((h - 0.835).abs() < 1e-4, "{h}");
        // Just ate 4 = α: H = 0.
        assert_eq!(hunger(&c, 4.0, 0.0), 0.0);
        // Digested completely after 1/p0 = 1493 units: H = 1, and stays 1.
        assert!((hunger(&c, 4.0, 1493.0 * UNIT) - 1.0).abs() < 1e-3);
        assert_eq!(hunger(&c, 4.0, 5000.0 * UNIT), 1.0);
        // Overeating is simply full.
        assert_eq!(hunger(&c, 9.0, 0.0), 0.0);
    }

    #[test]
    fn hunger_and_libido_run_on_the_bodys_clock() {
        use crate::sim::common::paper_time::PAPER_TIME_UNITS_PER_SEC;
        // One paper time unit is 1/40 s for the body and the mind alike.
        assert_eq!(
            crate::sim::body::BodyParams::default().paper_time_units_per_sec,
            PAPER_TIME_UNITS_PER_SEC
        );
        // A fish that ate its fill: hungry (0.25) after 0.25/p0 = 373 units =
        // 9.3 s, fully hungry after 1/p0 = 1493 units = 37.3 s.
        let c = MentalConstants::nominal(4.0);
        assert!((hunger(&c, 4.0, 9.33) - 0.25).abs() < 2e-3);
        assert!((hunger(&c, 4.0, 37.31) - 1.0).abs() < 2e-3);
        // A fed pacifist's libido: 0.25 after 0.25/p1 = 100 units = 2.5 s.
        assert!((libido(&c, 0.0, 2.5) - 0.25).abs() < 1e-4);
    }

    #[test]
    fn ravenous_fish_get_hungry_seven_times_sooner() {
        let nominal = MentalConstants::nominal(4.0);
        let ravenous = MentalConstants {
            digestion_rate_per_unit: RAVENOUS_DIGESTION_RATE,
            ..nominal
        };
        let t = 100.0 * UNIT;
        let (hn, hr) = (hunger(&nominal, 4.0, t), hunger(&ravenous, 4.0, t));
        assert!(
            (hn - 0.067).abs() < 1e-4 && (hr - 0.5).abs() < 1e-4,
            "{hn} {hr}"
        );
    }

    #[test]
    fn libido_matches_the_formula_and_is_zero_when_starving() {
        let c = MentalConstants::nominal(4.0);
        // 200 units since mating, H = 0.4: L = 0.0025·200·0.6 = 0.3.
        assert!((libido(&c, 0.4, 200.0 * UNIT) - 0.3).abs() < 1e-5);
        assert_eq!(libido(&c, 1.0, 1e6), 0.0);
        assert_eq!(libido(&c, 0.0, 1e6), 1.0);
        let mania = MentalConstants {
            libido_rate_per_unit: MANIC_LIBIDO_RATE,
            ..c
        };
        assert!((libido(&mania, 0.0, 50.0 * UNIT) - 0.5).abs() < 1e-5);
    }

    #[test]
    fn fear_saturates_inside_d0_and_sums_over_predators() {
        let c = MentalConstants::nominal(1.0);
        let d0 = c.fear_distance_body_lengths;
        assert!((d0 - 100.0 / 26.0).abs() < 1e-6);
        assert_eq!(fear_of(&c, d0), 1.0);
        assert_eq!(fear_of(&c, 0.5 * d0), 1.0);
        assert_eq!(fear_of(&c, 0.0), 1.0);
        assert!((fear_of(&c, 4.0 * d0) - 0.25).abs() < 1e-6);
        assert!((total_fear(&c, [4.0 * d0, 2.0 * d0]) - 0.75).abs() < 1e-6);
        assert_eq!(total_fear(&c, [2.0 * d0, 2.0 * d0, 2.0 * d0]), 1.0);
        assert_eq!(total_fear(&c, []), 0.0);
        assert_eq!(fear_of(&c, f32::NAN), 1.0);
    }

    #[test]
    fn eating_keeps_the_undigested_rest_and_restarts_the_clock() {
        let c = MentalConstants::nominal(4.0);
        let mut s = MentalState::new(&c, 0.0, 0.0);
        assert_eq!(s.hunger, 1.0);
        s.eat(&c, 2.0);
        assert!((s.hunger - 0.5).abs() < 1e-6);
        // 500 units later: 2·(1 − 0.335) = 1.33 left; one more unit → 2.33.
        for _ in 0..500 {
            s.update(&c, UNIT, []);
        }
        s.eat(&c, 1.0);
        assert!((s.food_eaten - 2.33).abs() < 1e-3, "{}", s.food_eaten);
        assert!((s.hunger - (1.0 - 2.33 / 4.0)).abs() < 1e-3);
        assert_eq!(s.secs_since_meal, 0.0);
    }

    #[test]
    fn urges_grow_with_time_and_stay_in_range() {
        let c = MentalConstants::nominal(2.0);
        let mut s = MentalState::new(&c, 2.0, 0.0);
        let mut last = (s.hunger, s.libido);
        for k in 0..20_000 {
            let d = if k % 3 == 0 {
                Some(1.0 + (k % 17) as f32)
            } else {
                None
            };
            s.update(&c, UNIT, d);
            for v in [s.hunger, s.libido, s.fear] {
                assert!((0.0..=1.0).contains(&v), "{v}");
            }
            assert!(s.hunger >= last.0 - 1e-6);
            last = (s.hunger, s.libido);
        }
        assert_eq!(s.hunger, 1.0);
        assert_eq!(s.libido, 0.0);
        s.update(&c, f32::NAN, [f32::INFINITY]);
        assert!(s.hunger.is_finite() && s.fear == 0.0);
    }
}
