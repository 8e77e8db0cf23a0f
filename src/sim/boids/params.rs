//! The boid world's tuning (issue 17: one tuning struct per model, as rapier's
//! `IntegrationParameters`): the chosen and tuned numbers of the world's step
//! that are not a preset's (the boid weights and senses are
//! [`super::world::BoidParams`], the steering limits
//! [`crate::sim::common::steering::SteeringParams`]), among them the shared
//! steering recipe's ([`SteeringTuning`]). The world holds one
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

use crate::sim::common::steering_tuning::SteeringTuning;

/// The boid world's tuning: the steering recipe, the glass and the pond's edge
/// for the SIMBA layer, fear of sharks, and the sharks' hunting.
#[derive(Clone, Debug, PartialEq)]
pub struct BoidWorldParams {
    /// The shared steering layer's recipe (wander, the wall and rock
    /// algorithms, the neighbour forces; [`SteeringTuning::default`]), for the
    /// fish, the sharks and the stingrays alike.
    pub steering: SteeringTuning,
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
    /// The sharks' hunting: confusion, strike and lunge.
    pub shark: SharkHuntParams,
}

impl Default for BoidWorldParams {
    fn default() -> Self {
        Self {
            steering: SteeringTuning::default(),
            wall_range_m: 1.5,
            pond_comfort_margin_m: 1.0,
            fear_radius_m: 4.0,
            lateral_line_m: 3.0,
            alarm_share: 0.8,
            alarm_range_m: 1.0,
            alarm_threshold: 0.25,
            fear_cohesion_factor: 2.0,
            fear_separation_factor: 0.5,
            shark: SharkHuntParams::default(),
        }
    }
}

/// The boid world's sharks' hunting tuning (`boids/shark.rs`, the confusion
/// effect and the strike). The sharks' body and species numbers (length,
/// speeds, force, vision) stay consts in `boids/shark.rs`, as do
/// `MAX_SHARKS`, `MAX_CONFUSING_NEIGHBOURS` (a cost bound) and
/// `RESPAWN_DISTANCE_M` (placement).
#[derive(Clone, Debug, PartialEq)]
pub struct SharkHuntParams {
    /// Distance from the shark's mouth (half a body length ahead of its centre) to
    /// the target's centre that counts as a catch, in metres. Default 0.4 m
    /// (tuned): about one fish length, a bite with a sweep of the head.
    pub catch_distance_m: f32,
    /// Time a shark cruises without hunting after a catch, in seconds. Default 5 s:
    /// long enough to see the school re-form, short enough to keep a lesson lively.
    pub satiated_secs: f32,
    /// Fish closer than this to the shark's target confuse the shark, in metres.
    /// Default 0.8 m (tuned): two fish lengths, the spacing inside a school;
    /// loners are seldom within it of each other, so a shark hunting loners is
    /// rarely confused.
    pub confusion_radius_m: f32,
    /// Rate of losing the lock per confusing fish, per second. Default 2.0 /s
    /// (tuned): with the 7 close neighbours of a schooling fish the lock lasts
    /// about a fourteenth of a second on average, almost never the
    /// [`SharkHuntParams::strike_lock_secs`] a strike needs; a lone fish is never lost (Landeau &
    /// Terborgh 1986: lone prey caught at once, shoals of 8+ rarely).
    pub confusion_rate_per_neighbour_per_s: f32,
    /// Time a shark must keep its lock on one fish before it can bite, in seconds.
    /// Default 0.5 s (chosen): a strike needs aiming; a predator fixates its prey
    /// before the final lunge. With the confusion rate above, a shark keeps a lock
    /// on a fish with 7 close neighbours that long in about one attack in a
    /// thousand, on a fish with one neighbour in three, on a lone fish always.
    pub strike_lock_secs: f32,
    /// A shark lunges at its target once it has kept its lock for
    /// [`SharkHuntParams::strike_lock_secs`] and the target is closer than this, in metres. Default
    /// 1.5 m (chosen): under a body length of the shark; predators strike from
    /// close range, where a burst cannot be outturned.
    pub lunge_distance_m: f32,
    /// Longest a shark keeps a lock after it could first strike, seconds. Default
    /// 2 s (chosen): a strike is a short burst; a shark that has not caught its
    /// target by then breaks off, loses the lock and needs [`SharkHuntParams::refocus_secs`] to pick
    /// a fish again (instead of circling one agile fish for minutes).
    pub lunge_max_secs: f32,
    /// Top speed of the lunge, m/s. Default 3.0 m/s (chosen): a burst of about
    /// two body lengths per second for a 1.5–2 m reef shark, several times the
    /// fish's 0.8 m/s; sharks strike prey at bursts of a few metres per second.
    pub lunge_m_per_s: f32,
    /// Largest steering acceleration during the lunge, m/s². Default 12 m/s²
    /// (chosen): a predator's strike out-accelerates small fish for the fraction
    /// of a second it lasts (Domenici 2001: fast-start accelerations of tens of
    /// m/s² in predators as in prey), so a lone fish cannot simply dodge at its
    /// 8 m/s²; only the confusion of a school (no lock lasts long enough) saves it.
    pub lunge_force_m_per_s2: f32,
    /// Time a shark that lost its target needs to pick a new one, in seconds.
    /// Default 1 s: it swims on, confused, before singling out another fish.
    pub refocus_secs: f32,
}

impl Default for SharkHuntParams {
    fn default() -> Self {
        Self {
            catch_distance_m: 0.4,
            satiated_secs: 5.0,
            confusion_radius_m: 0.8,
            confusion_rate_per_neighbour_per_s: 2.0,
            strike_lock_secs: 0.5,
            lunge_distance_m: 1.5,
            lunge_max_secs: 2.0,
            lunge_m_per_s: 3.0,
            lunge_force_m_per_s2: 12.0,
            refocus_secs: 1.0,
        }
    }
}
