//! The behaviour routines of Tu & Terzopoulos 1994 §6.4: given the intention
//! and the focusser's target, bring the fish one step closer to its goal. Each
//! routine returns the velocity the fish wants now (tank frame, m/s); for the
//! muscle-driven body the routine's motor choice (`reef/motor_choice.rs`) picks the
//! swim-MC, turn-MC and fin settings that swim it, and the eating fish and the
//! courted female hover instead (the point-mass body is steered to the velocity
//! by the boid layer).
//!
//! - *avoiding-static-obstacle* and *avoiding-fish*: turn away from the side the
//!   obstacle is on, slowing down (the paper picks a left or right turn-MC);
//! - *eating-food*: chase the food (chasing-target) until it is within reach of
//!   the mouth, then hover (tail still, fins braking) while the vacuum sucks it
//!   in (the world applies the suck-in);
//! - *mating*: chase the partner (the courtship sequence is in `reef/courtship.rs`);
//! - *leaving*: swim up the gradient of the light or temperature the fish likes;
//! - *wandering*: the wander steering of the boid layer;
//! - *escaping*: swim away from the predator, sideways if it is ahead;
//! - *schooling* (Fig. 16): match the neighbours' heading and mean speed, keep
//!   about one body length from the nearest, close up on the group if it drifts
//!   away.
//!
//! *chasing-target* underlies eating, mating and (for predators) hunting. The
//! routines' numbers are [`BehaviourParams`] (`ReefParams::behaviour`).

use crate::sim::common::fmath;
use glam::Vec3;

use crate::sim::reef::params::BehaviourParams;

/// The fish whose behaviour is computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Me {
    pub position_m: Vec3,
    pub head_m: Vec3,
    pub heading: Vec3,
    pub velocity_m_per_s: Vec3,
    pub body_length_m: f32,
    pub top_speed_m_per_s: f32,
}

/// chasing-target: head for `target_m` at `speed_fraction` of top speed,
/// slowing inside `arrival_m` so the fish does not overshoot. A body that turns
/// in circles of radius `turn_radius_m` (0 for the point-mass body) cannot
/// reach a target inside one of its turning circles by turning towards it: it
/// would circle it for ever. It swims straight on until the target leaves the
/// circle, then turns (the shortest path of a car that cannot turn tighter,
/// Dubins 1957).
pub fn chase(
    params: &BehaviourParams,
    me: &Me,
    target_m: Vec3,
    speed_fraction: f32,
    arrival_m: f32,
    turn_radius_m: f32,
) -> Vec3 {
    let offset = target_m - me.head_m;
    let d = offset.length();
    let mut speed = speed_fraction * me.top_speed_m_per_s;
    if arrival_m > 0.0 && d < arrival_m {
        speed *= (d / arrival_m).max(0.3);
    }
    if turn_radius_m > 0.0 {
        let flat = Vec3::new(1.0, 0.0, 1.0);
        let forward = (me.heading * flat).normalize_or(Vec3::X);
        let left = Vec3::Y.cross(forward);
        let level = offset * flat;
        let side = if level.dot(left) >= 0.0 { left } else { -left };
        let centre = side * turn_radius_m;
        let inside_circle =
            (level - centre).length() < turn_radius_m && level.dot(forward) < 2.0 * turn_radius_m;
        let horizontal = if inside_circle {
            forward
        } else {
            level.normalize_or(forward)
        };
        // Climb or dive no steeper than the body can: a target overhead is
        // reached by spiralling up.
        let pitch = fmath::atan2(offset.y, level.length())
            .clamp(-params.max_chase_pitch_rad, params.max_chase_pitch_rad);
        // Slow down for a sharp turn: the circle shrinks with the speed.
        let bearing_cos = horizontal.dot(forward).max(0.0);
        let speed = speed * (0.5 + 0.5 * bearing_cos);
        return (horizontal * fmath::cos(pitch) + Vec3::Y * fmath::sin(pitch)) * speed;
    }
    offset.normalize_or(me.heading) * speed
}

/// Length of the shortest level path to `offset_m` (the target's offset from
/// the mouth, tank frame; its height is ignored) for a body heading along
/// `heading` that turns in circles of radius `turn_radius_m`: an arc of one of
/// its two turning circles, then the tangent straight to the target (Dubins
/// 1957, for a point goal). A target inside the circle on its side is reached
/// by the circle on the other side (an upper bound of the shortest path).
/// With no turning circle, the straight distance.
pub fn level_reach_m(heading: Vec3, offset_m: Vec3, turn_radius_m: f32) -> f32 {
    let level = Vec3::new(offset_m.x, 0.0, offset_m.z);
    let forward = Vec3::new(heading.x, 0.0, heading.z).normalize_or_zero();
    if turn_radius_m <= 0.0 || forward == Vec3::ZERO {
        return level.length();
    }
    let r = turn_radius_m;
    let x = level.dot(forward);
    let y = level.dot(Vec3::Y.cross(forward));
    // Turning left (to the side of a target at `lateral` > 0; the right turn is
    // the mirror image): the circle's centre is at (0, r) in the fish's level
    // frame (x forward, y left). The tangent point is where the heading, turned
    // by `arc`, points along the straight to the target.
    let path = |lateral: f32| {
        let (dx, dy) = (x, lateral - r);
        let dc2 = dx * dx + dy * dy;
        if dc2 < r * r {
            return f32::INFINITY;
        }
        let t = (dc2 - r * r).sqrt();
        let arc = (fmath::atan2(dy, dx) + fmath::atan2(r, t)).rem_euclid(std::f32::consts::TAU);
        r * arc + t
    };
    path(y).min(path(-y))
}

/// avoiding-static-obstacle / avoiding-fish: turn away from `obstacle_m`
/// (the nearest point of the obstacle), towards the side it is not on. A calm
/// fish slows down to turn tightly; a frightened one (`fear` in [0, 1]) keeps
/// its speed, swerving without losing ground to the predator.
pub fn avoid(params: &BehaviourParams, me: &Me, obstacle_m: Vec3, fear: f32) -> Vec3 {
    let to = obstacle_m - me.position_m;
    let flat = Vec3::new(1.0, 0.0, 1.0);
    let forward = (me.heading * flat).normalize_or(Vec3::X);
    let right = forward.cross(Vec3::Y);
    let side = if to.dot(right) > 0.0 { -right } else { right };
    let away_up = if to.y > 0.2 * me.body_length_m {
        -0.3
    } else {
        0.0
    };
    let direction = (forward * 0.4 + side + Vec3::Y * away_up).normalize_or(side);
    direction * params.avoid_fraction.max(fear.clamp(0.0, 1.0)) * me.top_speed_m_per_s
}

/// avoiding-fish for a fish swimming the same way just ahead: fall back to a
/// little slower than it, edging to the side it is not on.
pub fn fall_back(
    params: &BehaviourParams,
    me: &Me,
    other_m: Vec3,
    other_velocity_m_per_s: Vec3,
) -> Vec3 {
    let right = me.heading.cross(Vec3::Y).normalize_or(Vec3::Z);
    let side = if (other_m - me.position_m).dot(right) > 0.0 {
        -right
    } else {
        right
    };
    let speed =
        (0.8 * other_velocity_m_per_s.length()).min(params.avoid_fraction * me.top_speed_m_per_s);
    (me.heading + 0.3 * side).normalize_or(me.heading) * speed
}

/// escaping: away from the predator at full speed; if it is ahead, mostly
/// sideways (turning straight back would swim past it).
pub fn escape(me: &Me, predator_m: Vec3) -> Vec3 {
    let away = (me.position_m - predator_m).normalize_or(-me.heading);
    let ahead = me.heading.dot(-away) > 0.5;
    let direction = if ahead {
        let right = me.heading.cross(Vec3::Y).normalize_or(Vec3::Z);
        let side = if away.dot(right) >= 0.0 {
            right
        } else {
            -right
        };
        (side * 2.0 + away).normalize_or(side)
    } else {
        away
    };
    // Stay roughly level: fleeing into the sand or the surface is no escape.
    let direction = (direction * Vec3::new(1.0, 0.4, 1.0)).normalize_or(direction);
    direction * me.top_speed_m_per_s
}

/// escaping, for a fish that schools and sees schoolmates: away from the
/// predator at top speed like [`escape`], but also towards the schoolmates'
/// heading and centre (the school routine at `fright`, its urgency: 1 is full
/// fright, the tightest spacing; see
/// [`BehaviourParams::escape_fright_in_school_gait`]), so that the
/// school flees as a group instead of scattering one by one. Weight of the
/// flight against the school: [`BehaviourParams::escape_share_in_school`]. Collective
/// evasion keeps the confusion effect working on the predator (Magurran &
/// Pitcher 1987 describe schools fleeing as one, "flash expansion" and
/// re-forming; Pitcher & Parrish 1993).
pub fn escape_with_school(
    params: &BehaviourParams,
    me: &Me,
    neighbours: &[Neighbour],
    predator_m: Vec3,
    fright: f32,
) -> Vec3 {
    let flee = escape(me, predator_m).normalize_or(me.heading);
    let together = school(params, me, neighbours, fright, Some(predator_m)).normalize_or(flee);
    (flee * params.escape_share_in_school + together * (1.0 - params.escape_share_in_school))
        .normalize_or(flee)
        * me.top_speed_m_per_s
}

/// A schooling neighbour as the fish sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Neighbour {
    pub position_m: Vec3,
    pub heading: Vec3,
    pub velocity_m_per_s: Vec3,
}

/// schooling (Fig. 16, §7.2): too close to the nearest → veer away; too far
/// from the group → swim to it faster; otherwise match the neighbours' heading
/// and their speed: a fish slower than its neighbours' mean speeds up by the
/// difference, a faster one slows down, and a school whose members swim alike
/// cruises at [`BehaviourParams::cruise_fraction`] (kept between
/// [`BehaviourParams::school_min_speed_fraction`] and
/// the top speed of this fish's body). Matching the difference, not copying the
/// neighbours' speed, is chosen: a body delivers a little less than it is asked
/// while it steers, so copying ratchets a muscle school's speed down each round
/// (measured on the pillar scene, seed 8: 0.16 m/s at 9 s, 0.06–0.09 m/s from
/// 18 s on, in three groups before the pillar; matching the difference: 0.15–0.25
/// m/s, one school again 30 s after the pillar). `urgency` in [0, 1] (fear) makes the school swim
/// faster (up to 0.3 of the top speed more) and tighter, and away from
/// `threat_m` (the predator the fish fears, if any): a frightened school moves
/// off together instead of scattering.
pub fn school(
    params: &BehaviourParams,
    me: &Me,
    neighbours: &[Neighbour],
    urgency: f32,
    threat_m: Option<Vec3>,
) -> Vec3 {
    if neighbours.is_empty() {
        return match threat_m {
            Some(t) if urgency > 0.0 => escape(me, t),
            _ => me.heading * params.cruise_fraction * me.top_speed_m_per_s,
        };
    }
    let spacing = params.school_spacing_body_lengths * me.body_length_m * (1.0 - 0.3 * urgency);
    let n = neighbours.len() as f32;
    let centre = neighbours.iter().map(|o| o.position_m).sum::<Vec3>() / n;
    let heading = neighbours
        .iter()
        .map(|o| o.heading)
        .sum::<Vec3>()
        .normalize_or(me.heading);
    let mut separation = Vec3::ZERO;
    for o in neighbours {
        let away = me.position_m - o.position_m;
        let d = away.length();
        if d < spacing && d > 1e-4 {
            separation += away / d * (1.0 - d / spacing);
        }
    }
    let to_centre = centre - me.position_m;
    let gap = to_centre.length();
    let cohesion = if gap > 1.5 * spacing {
        to_centre / gap
    } else {
        Vec3::ZERO
    };
    let away = threat_m.map_or(Vec3::ZERO, |t| {
        (me.position_m - t).normalize_or_zero()
            * Vec3::new(1.0, 0.4, 1.0)
            * 1.5
            * urgency.clamp(0.0, 1.0)
    });
    let direction = (heading + 1.5 * separation + cohesion + away).normalize_or(me.heading);
    let catch_up = if gap > 3.0 * spacing { 0.2 } else { 0.0 };
    let top = me.top_speed_m_per_s.max(1e-6);
    let neighbours_speed = neighbours
        .iter()
        .map(|o| o.velocity_m_per_s.length())
        .sum::<f32>()
        / n;
    let mine = me.velocity_m_per_s.length();
    let matched = (params.cruise_fraction + (neighbours_speed - mine) / top)
        .clamp(params.school_min_speed_fraction, 1.0);
    let speed = (matched + 0.3 * urgency.clamp(0.0, 1.0) + catch_up).min(1.0);
    direction * speed * me.top_speed_m_per_s
}

/// leaving: swim up `gradient` (unit, towards water the fish likes), level-ish.
pub fn leave(params: &BehaviourParams, me: &Me, gradient: Vec3) -> Vec3 {
    let direction = (gradient * Vec3::new(1.0, 0.5, 1.0)).normalize_or(me.heading);
    direction * params.cruise_fraction * me.top_speed_m_per_s
}

// The reef's behaviour stage: each animal's routine turns its intention into a wish.

use rand_chacha::ChaCha8Rng;

use crate::sim::body::motor_bridge::TOP_SPEED_BODY_LENGTHS_PER_SEC;
use crate::sim::common::obstacle::Obstacle;
use crate::sim::common::steering::SteeringParams;
use crate::sim::common::tank::Tank;
use crate::sim::reef::animal::{ReefAnimal, Seen};
use crate::sim::reef::bodies::ReefBody;
use crate::sim::reef::courtship::{Courtship, Partner};
use crate::sim::reef::environment::Environment;
use crate::sim::reef::feeding::{FoodParticle, Plankton, in_suck_reach};
use crate::sim::reef::mind::{Intention, Liking, Target};
use crate::sim::reef::motor_choice::{Gait, Wish};
use crate::sim::reef::params::ReefParams;

/// What the behaviour stage reads besides the animal that behaves and what
/// it saw: the tuning, the tank, the water's light and temperature, the
/// rocks, the plankton, the courting pairs and the clock.
pub(super) struct BehaviourInputs<'a> {
    pub params: &'a ReefParams,
    pub tank: &'a Tank,
    pub env: &'a Environment,
    pub obstacles: &'a [Obstacle],
    pub plankton: &'a Plankton,
    pub courtship: &'a Courtship,
    pub time_secs: f32,
}

/// How animal `i` knows courting partner `k`: itself as it is; another as
/// it sees it now or last saw it, while remembered (`ReefAnimal::last_mate`,
/// the rule a fleeing fish keeps for a predator); `None` once forgotten, so a
/// courting fish never steers by where an unseen partner went.
fn known_partner(i: usize, animal: &ReefAnimal, seen: &[Seen], k: u32) -> Option<Partner> {
    if k as usize == i {
        let o = seen.get(i)?;
        return Some(Partner {
            position_m: o.position_m,
            head_m: o.head_m,
            heading: o.heading,
            body_length_m: o.length_m,
        });
    }
    animal
        .last_mate
        .filter(|(j, _, _)| *j == k)
        .map(|(_, looks, _)| looks)
}

/// What animal `i`'s behaviour routine asks of its body. `seen` is how every
/// animal looked at the start of the step, `neighbours` the schoolmates it
/// sees; the wander routine draws from `rng`.
pub(super) fn behave(
    i: usize,
    animal: &mut ReefAnimal,
    seen: &[Seen],
    neighbours: &[Neighbour],
    rng: &mut ChaCha8Rng,
    inputs: &BehaviourInputs,
) -> Wish {
    let velocity_m_per_s = behave_velocity(i, animal, seen, neighbours, rng, inputs);
    let a = &*animal;
    let s = seen[i];
    let gait = match (a.focus.intention, a.focus.target) {
        // eating-food: hover while the vacuum sucks the food in.
        (Intention::Eat, Some(Target::Food(id))) => inputs
            .plankton
            .find(id)
            .filter(|f| in_suck_reach(inputs.params, s.head_m, s.heading, s.length_m, f.position_m))
            .map_or(Gait::Forage, |_| Gait::Hover),
        (Intention::Eat, Some(Target::Animal(_))) => Gait::Pursue,
        // schooling, and foraging with the school (see Gait::School).
        (Intention::School, _) => Gait::School,
        (Intention::Eat, None) if a.habits.schools && !neighbours.is_empty() => Gait::School,
        // escaping with the school (see BehaviourParams::escape_in_school_gait).
        (Intention::Escape, _)
            if inputs.params.behaviour.escape_in_school_gait
                && inputs.params.joint_flight
                && a.habits.schools
                && !neighbours.is_empty() =>
        {
            Gait::School
        }
        // mating: the courtship routine says (the female hovers).
        (Intention::Mate, Some(_)) => {
            inputs.courtship.pair_of(i).map_or(Gait::Pursue, |pair| {
                match (
                    known_partner(i, a, seen, pair.male),
                    known_partner(i, a, seen, pair.female),
                ) {
                    (Some(m), Some(f)) if pair.female as usize == i => {
                        let (_, wish) = pair.wishes(
                            &inputs.params.courtship,
                            &m,
                            &f,
                            inputs.time_secs,
                            inputs.tank.max_m.y,
                        );
                        wish.gait
                    }
                    _ => Gait::Pursue,
                }
            })
        }
        _ => Gait::Swim,
    };
    Wish {
        velocity_m_per_s,
        gait,
    }
}

/// The velocity animal `i`'s behaviour routine asks for (the point-mass body
/// follows it; the muscle body's motor choice reads it).
fn behave_velocity(
    i: usize,
    animal: &mut ReefAnimal,
    seen: &[Seen],
    neighbours: &[Neighbour],
    rng: &mut ChaCha8Rng,
    inputs: &BehaviourInputs,
) -> Vec3 {
    let s = seen[i];
    let me = Me {
        position_m: s.position_m,
        head_m: s.head_m,
        heading: s.heading,
        velocity_m_per_s: s.velocity_m_per_s,
        body_length_m: s.length_m,
        top_speed_m_per_s: TOP_SPEED_BODY_LENGTHS_PER_SEC * s.length_m,
    };
    let bp = inputs.params.behaviour.clone();
    let focus = animal.focus;
    // Radius of the body's turning circle at its speed now (none for the
    // point mass, which turns as fast as its steering force allows).
    let turn_radius = match animal.body {
        ReefBody::Physical(_) => inputs.params.body_turn_radius_body_lengths * s.length_m,
        ReefBody::Point(_) => 0.0,
    };
    let animal_at = |t: Option<Target>| match t {
        Some(Target::Animal(j)) => seen
            .get(j as usize)
            .filter(|o| o.alive)
            .map(|o| o.position_m),
        _ => None,
    };
    // Where the predator the fish fears is: where it is now if the fish
    // sees it; where it was last seen if the fish only remembers it (the
    // fish must not know where an unseen predator went). The memory is
    // refreshed with the present position whenever the predator is seen.
    let last_threat = animal.last_threat;
    let threat_at = |t: Option<Target>| match (t, last_threat) {
        (Some(Target::Animal(j)), Some((k, at, _))) if j == k => animal_at(t).map(|_| at),
        _ => animal_at(t),
    };
    let tuning = &inputs.params.steering;
    let wander = |a: &mut ReefAnimal, rng: &mut ChaCha8Rng| {
        let params = SteeringParams {
            max_speed_m_per_s: me.top_speed_m_per_s,
            wander_distance_m: 2.0 * s.length_m,
            wander_radius_m: s.length_m,
            wander_jitter_rad: 0.36,
            ..SteeringParams::default()
        };
        let push = a
            .drive_mut()
            .wander_push(s.position_m, rng, &params, tuning);
        (s.heading + push.normalize_or_zero() * 0.8).normalize_or(s.heading)
            * bp.cruise_fraction
            * me.top_speed_m_per_s
    };
    match focus.intention {
        Intention::Avoid => {
            let point = match focus.target {
                Some(Target::Obstacle(k)) => inputs
                    .obstacles
                    .get(k as usize)
                    .map(|o| o.core_point_m(s.head_m))
                    .unwrap_or(s.head_m + s.heading),
                Some(Target::Animal(j)) => {
                    // The other fish is a box moving in a direction (§6.4): one
                    // swimming the same way ahead is avoided by falling back,
                    // not by swerving out of the school.
                    if let Some(o) = seen.get(j as usize).filter(|o| o.alive)
                        && o.heading.dot(s.heading) > 0.7
                    {
                        return fall_back(&bp, &me, o.position_m, o.velocity_m_per_s);
                    }
                    animal_at(Some(Target::Animal(j))).unwrap_or(s.head_m + s.heading)
                }
                _ => {
                    // The glass: the nearest point of it ahead.
                    let probe = s.head_m + s.heading * s.length_m * 2.0;
                    let inside = inputs.tank.clamp_inside(probe, 0.0);
                    probe + (probe - inside)
                }
            };
            avoid(&bp, &me, point, animal.mental.fear)
        }
        Intention::Escape => match threat_at(focus.target) {
            // A schooling fish flees with the schoolmates it sees.
            // On the muscle body in the school's gait, at a lesser fright.
            Some(p)
                if inputs.params.joint_flight
                    && animal.habits.schools
                    && !neighbours.is_empty() =>
            {
                let fright = match animal.body {
                    ReefBody::Physical(_) if bp.escape_in_school_gait => {
                        bp.escape_fright_in_school_gait
                    }
                    _ => 1.0,
                };
                escape_with_school(&bp, &me, neighbours, p, fright)
            }
            Some(p) => escape(&me, p),
            None => wander(animal, rng),
        },
        Intention::School => {
            let urgency = animal.mental.fear;
            let threat = threat_at(focus.target);
            if neighbours.is_empty() && threat.is_none() {
                wander(animal, rng)
            } else {
                school(&bp, &me, neighbours, urgency, threat)
            }
        }
        Intention::Eat => match focus.target {
            Some(Target::Food(id)) => match inputs.plankton.find(id) {
                Some(f) => chase(
                    &BehaviourParams {
                        max_chase_pitch_rad: bp.max_food_chase_pitch_rad,
                        ..bp.clone()
                    },
                    &me,
                    f.position_m,
                    bp.cruise_fraction,
                    0.8 * s.length_m,
                    turn_radius,
                ),
                None => wander(animal, rng),
            },
            Some(Target::Animal(j)) => match seen.get(j as usize).filter(|o| o.alive) {
                Some(prey) => {
                    // chasing-target with a short prediction of where the prey swims.
                    let lead = (prey.position_m.distance(s.head_m) / me.top_speed_m_per_s).min(2.0);
                    chase(
                        &bp,
                        &me,
                        prey.position_m + prey.velocity_m_per_s * lead,
                        1.0,
                        0.0,
                        turn_radius,
                    )
                }
                None => wander(animal, rng),
            },
            // No food in view: a schooling fish forages with its school, others
            // search alone.
            _ if animal.habits.schools && !neighbours.is_empty() => {
                school(&bp, &me, neighbours, 0.0, None)
            }
            _ => wander(animal, rng),
        },
        Intention::Mate => {
            let partner_of = |k: u32| known_partner(i, animal, seen, k);
            let t = inputs.time_secs;
            let surface = inputs.tank.max_m.y;
            let mine = inputs.courtship.pair_of(i).copied();
            let theirs = match focus.target {
                Some(Target::Animal(j)) => inputs.courtship.pair_of(j as usize).copied(),
                _ => None,
            };
            match (mine, theirs, focus.target) {
                // In a pair: the courtship routine.
                (Some(pair), _, _) => match (partner_of(pair.male), partner_of(pair.female)) {
                    (Some(m), Some(f)) => {
                        let (male_wish, female_wish) =
                            pair.wishes(&inputs.params.courtship, &m, &f, t, surface);
                        let wish = if pair.male as usize == i {
                            male_wish
                        } else {
                            female_wish
                        };
                        chase(
                            &bp,
                            &me,
                            wish.target_m,
                            wish.speed_fraction,
                            0.0,
                            turn_radius,
                        )
                    }
                    _ => wander(animal, rng),
                },
                // Her partner is another male: join the looping display
                // (case 2); she may prefer him.
                (None, Some(pair), Some(Target::Animal(j)))
                    if pair.female == j && !pair.bonded() =>
                {
                    match partner_of(j) {
                        Some(f) => chase(
                            &bp,
                            &me,
                            pair.loop_point_m(&inputs.params.courtship, &f, t),
                            0.9,
                            0.0,
                            turn_radius,
                        ),
                        None => wander(animal, rng),
                    }
                }
                // Not yet a pair: follow the chosen partner around (case 1).
                _ => match focus.target.and_then(|t| match t {
                    Target::Animal(j) => partner_of(j).map(|p| p.position_m),
                    _ => None,
                }) {
                    Some(p) => chase(
                        &bp,
                        &me,
                        p,
                        bp.cruise_fraction,
                        1.5 * s.length_m,
                        turn_radius,
                    ),
                    None => wander(animal, rng),
                },
            }
        }
        Intention::Leave => {
            let h = animal.habits;
            let sign = |l: Liking| match l {
                Liking::High => 1.0,
                Liking::Low => -1.0,
                Liking::Indifferent => 0.0,
            };
            let g = inputs
                .env
                .gradient_direction(s.position_m, Environment::brightness_at)
                * sign(h.light)
                + inputs
                    .env
                    .gradient_direction(s.position_m, Environment::temperature_01_at)
                    * sign(h.temperature);
            leave(&bp, &me, g.normalize_or(s.heading))
        }
        Intention::Wander => wander(animal, rng),
    }
}

/// Where animal `i` of `animals` is swimming to, when it is closing in on
/// something: the food or prey it eats or the partner it courts.
pub(super) fn chase_target_m(
    animals: &[ReefAnimal],
    food: &[FoodParticle],
    i: usize,
) -> Option<Vec3> {
    let focus = animals[i].focus;
    if !matches!(focus.intention, Intention::Eat | Intention::Mate) {
        return None;
    }
    match focus.target? {
        Target::Animal(j) => animals
            .get(j as usize)
            .filter(|a| a.alive)
            .map(|a| a.body.position_m()),
        Target::Food(id) => food.iter().find(|f| f.id == id).map(|f| f.position_m),
        Target::Obstacle(_) | Target::Glass => None,
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::reef::behaviour::*;

    fn me() -> Me {
        Me {
            position_m: Vec3::ZERO,
            head_m: Vec3::X * 0.25,
            heading: Vec3::X,
            velocity_m_per_s: Vec3::X * 0.2,
            body_length_m: 0.5,
            top_speed_m_per_s: 0.3,
        }
    }

    #[test]
    fn chase_heads_for_the_target_and_slows_on_arrival() {
        let v = chase(
            &BehaviourParams::default(),
            &me(),
            Vec3::new(0.25, 0.0, 3.0),
            1.0,
            1.0,
            0.0,
        );
        assert!(v.normalize_or_zero().dot(Vec3::Z) > 0.99 && (v.length() - 0.3).abs() < 1e-5);
        let slow = chase(
            &BehaviourParams::default(),
            &me(),
            Vec3::new(0.25, 0.0, 0.5),
            1.0,
            1.0,
            0.0,
        );
        assert!(slow.length() < 0.2);
        // Inside the left turning circle of a body turning in 1 m circles: on.
        let on = chase(
            &BehaviourParams::default(),
            &me(),
            Vec3::new(0.6, 0.0, -0.5),
            1.0,
            0.0,
            1.0,
        );
        assert!(on.normalize_or_zero().dot(Vec3::X) > 0.99, "{on}");
        // Outside it: turn towards the target.
        let turn = chase(
            &BehaviourParams::default(),
            &me(),
            Vec3::new(0.6, 0.0, -2.5),
            1.0,
            0.0,
            1.0,
        );
        assert!(turn.normalize_or_zero().dot(-Vec3::Z) > 0.9, "{turn}");
        assert!(slow.length() < 0.2);
    }

    #[test]
    fn the_reach_path_goes_round_the_turning_circle() {
        let r = 0.6;
        // Straight ahead: the distance.
        assert!((level_reach_m(Vec3::X, Vec3::new(2.0, 0.3, 0.0), r) - 2.0).abs() < 1e-4);
        // No turning circle: the level distance, wherever the target is.
        assert!((level_reach_m(Vec3::X, Vec3::new(-1.0, 5.0, 0.0), 0.0) - 1.0).abs() < 1e-5);
        // A quarter circle to the left (−z with y up) ends at (r, r): the arc.
        let quarter = level_reach_m(Vec3::X, Vec3::new(r, 0.0, -r), r);
        assert!(
            (quarter - r * std::f32::consts::FRAC_PI_2).abs() < 1e-3,
            "{quarter}"
        );
        // Left and right alike.
        let right = level_reach_m(Vec3::X, Vec3::new(r, 0.0, r), r);
        assert!((quarter - right).abs() < 1e-4);
        // One metre behind is further than two metres ahead: more than half
        // a circle, then the metre back.
        let behind = level_reach_m(Vec3::X, Vec3::new(-1.0, 0.0, 0.0), r);
        assert!(
            behind > r * std::f32::consts::PI + 1.0 && behind > 2.0,
            "{behind}"
        );
        // Beside the mouth, inside the left circle: round the right one, further
        // than the same point outside the circle a body length on.
        let inside = level_reach_m(Vec3::X, Vec3::new(0.1, 0.0, -0.4), r);
        assert!(
            inside > level_reach_m(Vec3::X, Vec3::new(0.1, 0.0, -1.4), r),
            "{inside}"
        );
        // Never less than the straight distance, never NaN.
        for (x, z) in [
            (0.3, 0.2),
            (-0.2, -0.7),
            (1.5, -1.5),
            (-3.0, 0.01),
            (0.0, 0.0),
        ] {
            let p = level_reach_m(Vec3::X, Vec3::new(x, 0.0, z), r);
            assert!(
                p.is_finite() && p >= Vec3::new(x, 0.0, z).length() - 1e-4,
                "{x} {z}: {p}"
            );
        }
    }

    #[test]
    fn avoid_turns_to_the_free_side() {
        let right = Vec3::X.cross(Vec3::Y);
        let v = avoid(
            &BehaviourParams::default(),
            &me(),
            Vec3::new(1.0, 0.0, 0.0) + right * 0.3,
            0.0,
        );
        assert!(v.dot(right) < 0.0, "{v}");
        let v = avoid(
            &BehaviourParams::default(),
            &me(),
            Vec3::new(1.0, 0.0, 0.0) - right * 0.3,
            0.0,
        );
        assert!(v.dot(right) > 0.0, "{v}");
    }

    #[test]
    fn a_fish_falls_back_behind_one_swimming_the_same_way() {
        let ahead = Vec3::new(0.5, 0.0, 0.05);
        let v = fall_back(&BehaviourParams::default(), &me(), ahead, Vec3::X * 0.2);
        assert!(v.length() <= 0.8 * 0.2 + 1e-6);
        assert!(v.normalize_or_zero().dot(Vec3::X) > 0.9);
        let right = Vec3::X.cross(Vec3::Y);
        assert!(
            v.dot(right) < 0.0,
            "edges away from the side the other is on: {v}"
        );
    }

    #[test]
    fn escape_swims_away_from_a_predator_behind_and_sideways_from_one_ahead() {
        let v = escape(&me(), Vec3::new(-2.0, 0.0, 0.0));
        assert!(v.normalize_or_zero().dot(Vec3::X) > 0.9);
        let v = escape(&me(), Vec3::new(2.0, 0.0, 0.3));
        assert!(v.normalize_or_zero().dot(Vec3::Z).abs() > 0.7, "{v}");
    }

    #[test]
    fn schooling_spaces_aligns_and_closes_up() {
        let close = [Neighbour {
            position_m: Vec3::new(0.0, 0.0, 0.2),
            heading: Vec3::X,
            velocity_m_per_s: Vec3::X * 0.21,
        }];
        assert!(school(&BehaviourParams::default(), &me(), &close, 0.0, None).z < 0.0);
        let aligned = [Neighbour {
            position_m: Vec3::new(0.0, 0.0, 0.5),
            heading: Vec3::Z,
            velocity_m_per_s: Vec3::Z * 0.21,
        }];
        assert!(
            school(&BehaviourParams::default(), &me(), &aligned, 0.0, None)
                .normalize_or_zero()
                .dot(Vec3::Z)
                > 0.9
        );
        let far = [Neighbour {
            position_m: Vec3::new(0.0, 0.0, -3.0),
            heading: Vec3::X,
            velocity_m_per_s: Vec3::X * 0.21,
        }];
        let v = school(&BehaviourParams::default(), &me(), &far, 0.0, None);
        assert!(v.z < 0.0 && v.length() > BehaviourParams::default().cruise_fraction * 0.3);
    }

    #[test]
    fn schooling_matches_the_neighbours_speed_within_the_body_limits() {
        // Two schoolmates one body length to either side, swimming the same
        // way: no spacing or cohesion pull, only the match. me() swims at
        // 0.2 m/s, its top speed is 0.3 m/s.
        let pair = |a: f32, b: f32| {
            [
                Neighbour {
                    position_m: Vec3::new(0.0, 0.0, 0.5),
                    heading: Vec3::X,
                    velocity_m_per_s: Vec3::X * a,
                },
                Neighbour {
                    position_m: Vec3::new(0.0, 0.0, -0.5),
                    heading: Vec3::X,
                    velocity_m_per_s: Vec3::X * b,
                },
            ]
        };
        let top = 0.3;
        // Neighbours as fast as me: the school's cruise.
        let v = school(
            &BehaviourParams::default(),
            &me(),
            &pair(0.18, 0.22),
            0.0,
            None,
        );
        assert!(
            (v.length() - BehaviourParams::default().cruise_fraction * top).abs() < 1e-5,
            "{v}"
        );
        assert!(v.normalize_or_zero().dot(Vec3::X) > 0.99);
        // Neighbours 0.06 m/s faster than me: I ask 0.06 m/s more; slower: less.
        let v = school(
            &BehaviourParams::default(),
            &me(),
            &pair(0.25, 0.27),
            0.0,
            None,
        );
        assert!(
            (v.length() - (BehaviourParams::default().cruise_fraction * top + 0.06)).abs() < 1e-5,
            "{v}"
        );
        let v = school(
            &BehaviourParams::default(),
            &me(),
            &pair(0.12, 0.16),
            0.0,
            None,
        );
        assert!(
            (v.length() - (BehaviourParams::default().cruise_fraction * top - 0.06)).abs() < 1e-5,
            "{v}"
        );
        // Not faster than the body's top speed, nor slower than its minimum.
        let v = school(
            &BehaviourParams::default(),
            &me(),
            &pair(0.5, 0.6),
            0.0,
            None,
        );
        assert!((v.length() - top).abs() < 1e-5, "{v}");
        let v = school(
            &BehaviourParams::default(),
            &me(),
            &pair(0.0, 0.01),
            0.0,
            None,
        );
        assert!(
            (v.length() - BehaviourParams::default().school_min_speed_fraction * top).abs() < 1e-5,
            "{v}"
        );
    }
}
