//! The boid world's tuning (issue 17: one tuning struct per model, as rapier's
//! `IntegrationParameters`): the chosen and tuned numbers of the world's step
//! that are not a preset's (the boid weights and senses are
//! [`super::world::BoidParams`], the steering limits
//! [`crate::sim::common::steering::SteeringParams`]). The world holds one
//! ([`BoidWorldParams::default`]); `World::world_params` shows it.
//!
//! Consts stay for what is not behaviour tuning: the step and the fish limit
//! (`DT_SECS`, `MAX_FISH_COUNT`); the hard rule's margins (`TANK_MARGIN_M`,
//! `OBSTACLE_MARGIN_M`, `SHARK_MARGIN_M`: half a body's width, geometry the
//! scene building also reads before a world exists); placement and the
//! teacher's edit check (`OBSTACLE_GAP_M`, `EDITED_OBSTACLE_GAP_M`,
//! `PLACEMENT_ATTEMPTS`, `SPAWN_CLEARANCE_M`); and the neighbour search's and
//! metrics' schedules and cell sizes (`NEIGHBOUR_SEARCH_EVERY_STEPS`,
//! `SPATIAL_METRICS_EVERY_STEPS`, `FAR_FIELD_CELL_SHARE`,
//! `FISH_PER_NEIGHBOUR_CELL`, `MIN_NEIGHBOUR_CELL_M`), performance choices
//! the benchmarks read.

/// The boid world's tuning: the glass and the pond's edge for the SIMBA layer,
/// and fear of sharks.
#[derive(Clone, Debug, PartialEq)]
pub struct BoidWorldParams {
    /// How far from a vertical glass wall the boid layer's wall algorithm starts
    /// to act, in metres. Default 1.5 m (tuned): with containment's Table 1 share
    /// (26 % of 25 % of the 8 m/s² maximum ≈ 0.5 m/s²) a fish at top speed turns
    /// along the glass within about 1.3 m, so it rarely needs the hard rule.
    pub wall_range_m: f32,
    /// How far from the glass, sand and surface the boid layer's containment
    /// ("stay in the pond") keeps a fish's predicted path (1.5 s ahead), in metres.
    /// Default 1.0 m (tuned on seeds 1–12, `docs/boids.md`): about three body
    /// lengths, so the containment slider visibly keeps fish out of the pond's edge
    /// zone (at 0.5 m the wall algorithm acted first and the slider did little).
    pub pond_comfort_margin_m: f32,
    /// Fish notice a shark within this distance when it is inside their field of
    /// view (300°), in metres. Default 4 m (chosen): a shark 2 m long is plain to
    /// see at that range in an aquarium; beyond it the fish keep schooling. Also
    /// the neighbour grid's vision distance for wandering fish.
    pub fear_radius_m: f32,
    /// Fish notice a shark within this distance from any direction, in metres,
    /// through the pressure waves on their lateral line. Default 3 m (chosen): the
    /// bow wave of a 2 m shark carries a body length or two beyond it; without it a
    /// fleeing fish forgot the shark as soon as it had turned its back (the shark
    /// fell into the blind cone) and slowed down.
    pub lateral_line_m: f32,
    /// Share of a frightened neighbour's urgency that a fish takes on when it sees
    /// that neighbour flee (dimensionless, 0–1). Default 0.8 (chosen): the "many
    /// eyes" of a school, whose fright spreads faster than the predator swims (the
    /// Trafalgar effect, Treherne & Foster 1981, Anim. Behav. 29:911), so the
    /// whole school turns away together instead of one fish bolting alone. Each
    /// hop fades the alarm by this factor; see [`BoidWorldParams::alarm_threshold`].
    pub alarm_share: f32,
    /// Farthest heeded neighbour whose fright a fish takes on, metres. Default
    /// 1.0 m (chosen): two to three body lengths, the spacing of a school; a
    /// neighbour's fast start is plain to see that close. Solitary fish keep
    /// farther apart and so mostly meet a shark alone.
    pub alarm_range_m: f32,
    /// Smallest passed-on alarm that frightens a fish (urgency, 0–1). Default
    /// 0.25 (chosen): the alarm crosses about six neighbours (0.8⁶ ≈ 0.26) and then
    /// dies out, so a school far from the shark keeps schooling.
    pub alarm_threshold: f32,
    /// Factor on the cohesion weight of a frightened fish (capped at 100).
    /// Default 2: prey tighten their school under threat (Magurran & Pitcher 1987,
    /// Proc. R. Soc. B 229:439: minnow shoals compact when a pike approaches).
    pub fear_cohesion_factor: f32,
    /// Factor on the separation weight of a frightened fish. Default 0.5: with
    /// doubled cohesion, the school halves its spacing.
    pub fear_separation_factor: f32,
}

impl Default for BoidWorldParams {
    fn default() -> Self {
        Self {
            wall_range_m: 1.5,
            pond_comfort_margin_m: 1.0,
            fear_radius_m: 4.0,
            lateral_line_m: 3.0,
            alarm_share: 0.8,
            alarm_range_m: 1.0,
            alarm_threshold: 0.25,
            fear_cohesion_factor: 2.0,
            fear_separation_factor: 0.5,
        }
    }
}
