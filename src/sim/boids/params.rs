//! The boid world's tuning (issue 17: one tuning struct per model, as rapier's
//! `IntegrationParameters`): the chosen and tuned numbers of the world's step
//! that are not a preset's (the boid weights and senses are
//! [`super::world::BoidParams`], the steering limits
//! [`crate::sim::common::steering::SteeringParams`]), among them the shared
//! steering recipe's ([`SteeringTuning`]) and the sharks' and stingrays' body
//! and species numbers ([`SharkParams`], [`StingrayParams`]). The world holds
//! one ([`BoidWorldParams::default`]); `World::world_params` shows it.
//!
//! Consts stay for what is not behaviour tuning: the step and the animal limits
//! (`DT_SECS`, `MAX_FISH_COUNT`, `MAX_SHARKS`, `MAX_STINGRAYS`: settings
//! ranges); the shark's `MAX_CONFUSING_NEIGHBOURS` (a cost bound); the hard rule's margins (`TANK_MARGIN_M`,
//! `OBSTACLE_MARGIN_M`, `SHARK_MARGIN_M`: half a body's width, geometry the
//! scene building also reads before a world exists); placement and the
//! teacher's edit check (`OBSTACLE_GAP_M`, `EDITED_OBSTACLE_GAP_M`,
//! `PLACEMENT_ATTEMPTS`, `SPAWN_CLEARANCE_M`); and the neighbour search's and
//! metrics' schedules and cell sizes (`NEIGHBOUR_SEARCH_EVERY_STEPS`,
//! `SPATIAL_METRICS_EVERY_STEPS`, `FAR_FIELD_CELL_SHARE`,
//! `FISH_PER_NEIGHBOUR_CELL`, `MIN_NEIGHBOUR_CELL_M`), performance choices
//! the benchmarks read.

use crate::sim::common::steering_tuning::SteeringTuning;

/// Length of one simulation step in seconds. Default 1/60 s: one step per
/// frame on a 60 Hz display. The step is fixed (the app runs as many steps as
/// real time requires) so that results do not depend on the frame rate and a
/// seed always replays the same way.
pub const DT_SECS: f32 = 1.0 / 60.0;

/// The boid world's tuning: the steering recipe, the glass and the pond's edge
/// for the SIMBA layer, fear of sharks, the sharks' hunting, and the sharks'
/// and stingrays' body and species numbers.
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
    /// Joint flight on or off (the settings' `predation.joint_flight`). Default
    /// on: the alarm passes between neighbours ([`BoidWorldParams::alarm_share`]).
    /// Off, a fish flees only from a shark it notices itself.
    pub joint_flight: bool,
    /// The sharks' hunting: confusion, strike and lunge.
    pub shark: SharkHuntParams,
    /// The sharks' body and species numbers: length, speeds, force, vision.
    pub shark_species: SharkParams,
    /// The stingrays' body and species numbers: size, glide height, speeds,
    /// gap, and when they are avoided as one polygon.
    pub stingray: StingrayParams,
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
            joint_flight: true,
            shark: SharkHuntParams::default(),
            shark_species: SharkParams::default(),
            stingray: StingrayParams::default(),
        }
    }
}

/// The boid world's sharks' hunting tuning (`boids/shark.rs`, the confusion
/// effect and the strike). The sharks' body and species numbers are
/// [`SharkParams`]; `MAX_SHARKS` (a settings range) and
/// `MAX_CONFUSING_NEIGHBOURS` (a cost bound: the capacity of the neighbour
/// list counted) stay consts in `boids/shark.rs`.
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
    /// The confusion effect on or off (the settings' `predation.confusion`).
    /// Default on. Off, a shark never loses its lock to the fish around its
    /// target (the rate above counts as 0).
    pub confusion: bool,
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
            confusion: true,
            strike_lock_secs: 0.5,
            lunge_distance_m: 1.5,
            lunge_max_secs: 2.0,
            lunge_m_per_s: 3.0,
            lunge_force_m_per_s2: 12.0,
            refocus_secs: 1.0,
        }
    }
}

/// The boid world's sharks' body and species numbers (`boids/shark.rs`,
/// `boids/predators.rs`, `boids/placement.rs`): a reef shark 1.5–2 m long,
/// slower than a fish when cruising, twice as fast attacking, turning wide.
#[derive(Clone, Debug, PartialEq)]
pub struct SharkParams {
    /// Shortest shark, nose to tail, in metres. Default 1.5 m (chosen): a reef
    /// shark, four to six times the fish; each new shark draws its length
    /// uniformly between this and [`SharkParams::max_length_m`].
    pub min_length_m: f32,
    /// Longest shark, nose to tail, in metres. Default 2.0 m (chosen).
    pub max_length_m: f32,
    /// Cruising speed in m/s. Default 0.5 m/s (chosen): slower than a fish's
    /// top speed, so a resting shark does not catch anything by accident.
    pub cruise_m_per_s: f32,
    /// Attack speed in m/s. Default 1.5 m/s (tuned): about twice the fish's
    /// 0.8 m/s top speed (a shark's burst is several times its cruise), so a
    /// shark that keeps its lock catches a lone fish within seconds; fish can
    /// only escape by turning (they may steer 8 m/s², the shark
    /// [`SharkParams::max_force_m_per_s2`]) or by hiding in a school.
    pub attack_m_per_s: f32,
    /// Slowest shark speed in m/s. Default 0.3 m/s (chosen): sharks must keep
    /// swimming to breathe (ram ventilation).
    pub min_m_per_s: f32,
    /// Largest steering acceleration of a shark in m/s². Default 2.5 m/s²
    /// (chosen): a big body turns wider than a fish: at attack speed its
    /// tightest turn has a radius of v²/a ≈ 0.9 m, a fish's about 0.1 m.
    pub max_force_m_per_s2: f32,
    /// How far a shark sees fish, in metres. Default 6 m (chosen): half the
    /// tank; murky water limits vision to some metres. A lock on a fish farther
    /// than 1.5 times this is lost.
    pub vision_m: f32,
    /// The shark's field of view, radians. Default 300° (as the fish's, TT §5).
    pub vision_angle_rad: f32,
    /// A caught fish reappears at least this far from every shark, in metres.
    /// Default 5 m (chosen): out of reach, on the other side of the tank.
    pub respawn_distance_m: f32,
}

impl Default for SharkParams {
    fn default() -> Self {
        Self {
            min_length_m: 1.5,
            max_length_m: 2.0,
            cruise_m_per_s: 0.5,
            attack_m_per_s: 1.5,
            min_m_per_s: 0.3,
            max_force_m_per_s2: 2.5,
            vision_m: 6.0,
            vision_angle_rad: 300.0 * std::f32::consts::PI / 180.0,
            respawn_distance_m: 5.0,
        }
    }
}

/// The boid world's stingrays' body and species numbers (`boids/stingray.rs`,
/// `boids/predators.rs`, `boids/placement.rs`): a flat ray 1 m across that
/// glides slowly just above the sand. `MAX_STINGRAYS` (a settings range) stays
/// a const in `boids/stingray.rs`.
#[derive(Clone, Debug, PartialEq)]
pub struct StingrayParams {
    /// Half the stingray's wingspan, in metres. Default 0.5 m (chosen): a ray
    /// 1 m across. The fish avoid a disc of this radius.
    pub radius_m: f32,
    /// Thickness of the stingray's body, in metres. Default 0.15 m (chosen).
    pub thickness_m: f32,
    /// Lowest glide height of the stingray's centre above the sand, in metres.
    /// Default 0.2 m (chosen): rays skim the bottom; each one keeps its own
    /// height, drawn between this and [`StingrayParams::max_glide_height_m`].
    pub min_glide_height_m: f32,
    /// Highest glide height of the stingray's centre above the sand, in metres.
    /// Default 0.6 m (chosen).
    pub max_glide_height_m: f32,
    /// Cruising speed in m/s. Default 0.3 m/s (chosen): a slow glide, a third
    /// of a fish's top speed.
    pub cruise_m_per_s: f32,
    /// Top speed in m/s. Default 0.4 m/s (chosen).
    pub max_m_per_s: f32,
    /// Lowest speed in m/s. Default 0.15 m/s (chosen).
    pub min_m_per_s: f32,
    /// Largest steering acceleration in m/s². Default 0.5 m/s² (chosen): wide,
    /// calm turns.
    pub max_force_m_per_s2: f32,
    /// Gap a stingray keeps between its wing tips and the glass or any fixed
    /// obstacle, in metres. Default 0.6 m (chosen): a fish always fits between
    /// (so pushing a fish out of a stingray can never push it into a rock or
    /// through the glass).
    pub gap_m: f32,
    /// Stingrays whose centres are closer than this are "close together", in
    /// metres. Default 2.0 m (chosen): their wing tips are less than 1 m apart
    /// (two to three fish lengths), too narrow for a school to pass between.
    pub cluster_link_m: f32,
    /// Fewest close stingrays the fish avoid as one polygon. Default 3 (the
    /// SIMBA paper: "at least three particles").
    pub cluster_min_stingrays: usize,
}

impl Default for StingrayParams {
    fn default() -> Self {
        Self {
            radius_m: 0.5,
            thickness_m: 0.15,
            min_glide_height_m: 0.2,
            max_glide_height_m: 0.6,
            cruise_m_per_s: 0.3,
            max_m_per_s: 0.4,
            min_m_per_s: 0.15,
            max_force_m_per_s2: 0.5,
            gap_m: 0.6,
            cluster_link_m: 2.0,
            cluster_min_stingrays: 3,
        }
    }
}
