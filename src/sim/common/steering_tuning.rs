//! The shared steering layer's tuning (issue 17: one tuning struct per model,
//! as rapier's `IntegrationParameters`): the chosen and tuned numbers of the
//! steering recipe itself (`common/steering.rs`: wander, pursuit, the wall and
//! rock algorithms; `boids/forces.rs`: the neighbour forces and swaying round
//! other fish), as opposed to the slider-facing limits of
//! [`super::steering::SteeringParams`] (speeds, force, weights). Each world
//! that steers with this layer holds one and passes it to the free functions:
//! the boid world (`BoidWorldParams::steering`), the physics tank
//! (`PhysicsParams::steering`) and the reef (`ReefParams::steering`).
//!
//! Consts stay for what is not tuning: the numerical floors inside a formula
//! that only keep it finite (`avoid_obstacles`' smallest gap,
//! `avoid_neighbours`' shortest time to contact), and the neighbour search's
//! capacity (`spatial_grid::MAX_NEAREST`, a fixed array size that bounds
//! [`SteeringTuning::topological_neighbours`]).

/// The steering recipe's tuning. `Default` gives the values the docs quote
/// (`docs/model.md`, Lim & Tan sections).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteeringTuning {
    /// Fraction of the wander pitch that fades away each step (dimensionless).
    /// Default 0.01 (chosen, Shoal's 3-D addition): at 60 steps/s a tilt halves
    /// in about 1.2 s, so fish glide up or down for a moment and then level out
    /// instead of drifting to the floor or surface; with the default jitter the
    /// typical tilt is about 14°.
    pub wander_pitch_fade_per_step: f32,
    /// Extra room a fish keeps from an obstacle's surface when planning its
    /// path (the rock algorithm's clearance), in metres. Default 0.3 m (chosen):
    /// about one body length, so a fish passes a rock with a visible gap instead
    /// of scraping along it. The muscle fish add half their body length to it.
    pub avoidance_clearance_m: f32,
    /// Longest look into the future that pursuit and evasion use, in seconds.
    /// Default 2 s (chosen): Reynolds' prediction `T = distance / speed` grows
    /// without bound for a far target; beyond a couple of seconds a fish's path
    /// is no longer predictable from its velocity (it turns within about a
    /// second).
    pub max_prediction_s: f32,
    /// How strongly the wall algorithm turns the velocity's into-the-wall part
    /// around, dimensionless (the SIMBA paper's k1, a coefficient without a
    /// number). Default 0.3 (chosen): the fish ends up swimming along the wall
    /// and slightly away from it, not bouncing back.
    pub wall_away_gain: f32,
    /// How much of the velocity's along-the-wall part the wall algorithm keeps,
    /// dimensionless (the paper's k2). Default 1 (chosen): the fish keeps
    /// swimming along the wall at its speed.
    pub wall_along_gain: f32,
    /// Smallest remaining range used by the boid layer's wall strength
    /// `range / max(gap, this)`, in metres. Default 0.1 m (chosen, as the rock
    /// algorithm's): the push grows tenfold from the edge of the range to
    /// 0.1 m from the glass and no further, so it stays finite at the glass.
    pub min_wall_gap_m: f32,
    /// How many of the nearest seen neighbours a fish heeds (the topological
    /// range), at most [`crate::sim::common::spatial_grid::MAX_NEAREST`].
    /// Default 7: the upper end of the 6–7 nearest neighbours starlings interact
    /// with whatever the flock's density (Ballerini et al. 2008, PNAS 105:1232).
    pub topological_neighbours: usize,
    /// Distance within which the far field's pull fades out (its arrival
    /// distance), metres. Default 1.6 m (tuned on seeds 1–12, `docs/boids.md`):
    /// a fish inside the school it sees feels little of it, a straggler or a
    /// second school several metres off feels it in full.
    pub far_field_arrival_m: f32,
    /// How far ahead in time a fish checks its course against the neighbours it
    /// heeds, seconds. Default 1 s (chosen): about two body lengths at cruising
    /// speed, enough to sway round a fish swimming the other way.
    pub fish_avoid_look_ahead_s: f32,
    /// A neighbour whose predicted closest approach is nearer than this is on a
    /// collision course, metres. Default 0.3 m (chosen): about one body length.
    pub fish_avoid_clearance_m: f32,
    /// Heeded neighbours this close to the one in the way belong to one
    /// obstacle with it, metres; three or more are avoided as one (the SIMBA
    /// paper's polygon of at least three close agents). Default 0.6 m (chosen:
    /// two body lengths).
    pub fish_cluster_link_m: f32,
}

impl Default for SteeringTuning {
    fn default() -> Self {
        Self {
            wander_pitch_fade_per_step: 0.01,
            avoidance_clearance_m: 0.3,
            max_prediction_s: 2.0,
            wall_away_gain: 0.3,
            wall_along_gain: 1.0,
            min_wall_gap_m: 0.1,
            topological_neighbours: 7,
            far_field_arrival_m: 1.6,
            fish_avoid_look_ahead_s: 1.0,
            fish_avoid_clearance_m: 0.3,
            fish_cluster_link_m: 0.6,
        }
    }
}
