//! The neighbour forces of the SIMBA boid layer (Lim & Tan; Reynolds 1987):
//! separation, alignment and cohesion among the neighbours a fish can see.
//!
//! A neighbour is seen when it is within the vision distance and inside the vision
//! angle: the field of view is a cone of half-angle `vision_angle_rad / 2` around
//! the heading, leaving a blind cone behind (a vision angle of 300° leaves a 60°
//! blind cone, as in Tu & Terzopoulos §5). Each force is a steering force in the
//! papers' form, desired velocity − current velocity, reached within the
//! response time and limited to the maximum force (docs/boids.md).
//!
//! **Topological interaction.** A fish heeds only the
//! [`SteeringTuning::topological_neighbours`] nearest
//! fish it sees, not every fish within the vision distance. Ballerini et al. 2008
//! (PNAS 105:1232) showed that starlings in a flock each interact with their 6–7
//! nearest neighbours whatever the flock's density; the same "topological range"
//! keeps a school together when it stretches and keeps the cost per fish
//! constant when 20,000 fish crowd the tank (with 5 m vision each would otherwise
//! see thousands). The neighbours are found through the spatial grid, ring by
//! ring outward from the fish ([`SpatialGrid::k_nearest`]), never by all pairs.
//!
//! The recipe's numbers (the topological range, clear sight, the far field's
//! share and arrival, swaying round fish) are the calling world's
//! [`SteeringTuning`]; [`Perception`] holds the senses and limits the sliders set.

use crate::sim::common::fmath;
use glam::{Vec3, Vec4};

use crate::sim::common::fish::heading_of;
use crate::sim::common::spatial_grid::{MAX_NEAREST, Nearest, SpatialGrid};
use crate::sim::common::steering::limit;
use crate::sim::common::steering_tuning::SteeringTuning;

/// What a fish perceives of its neighbours and how hard it may steer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Perception {
    /// How far a fish sees its neighbours, metres.
    pub vision_distance_m: f32,
    /// Full width of the field of view, radians (2π: no blind spot).
    pub vision_angle_rad: f32,
    /// Speed a fish steers towards, m/s.
    pub max_speed_m_per_s: f32,
    /// Largest steering acceleration, m/s².
    pub max_force_m_per_s2: f32,
    /// Neighbours closer than this push the fish away (its personal space),
    /// metres; farther ones only attract and align it.
    pub separation_distance_m: f32,
    /// Time in which a steering force would reach its desired velocity, seconds:
    /// each force is `(desired − current) / response_time`, then limited.
    pub response_time_s: f32,
    /// Distance within which a fish reads a neighbour's heading in full, metres;
    /// beyond it the neighbour counts for `clear_sight / distance` in alignment
    /// (the angle a neighbour's body fills falls as 1/distance, so a far fish's
    /// heading is harder to read). `f32::INFINITY`: every heeded neighbour
    /// counts in full; 0: no heading is read, alignment has nothing to copy.
    /// The schooling lab's *Clear sight* slider (default 0.3 m, about one body
    /// length; `docs/boids.md` measures what it does).
    pub clear_sight_m: f32,
    /// Strength of the pull towards the distant fish a fish sees (the far
    /// field, part of cohesion), as a share of the near neighbours' pull, 0–1.
    /// The schooling lab's *Distant fish* slider (default 0.5: two schools that
    /// see each other merge within a minute, while a fish inside a school follows
    /// its neighbours). 0: only the heeded neighbours attract.
    pub far_pull: f32,
    /// Lowest speed, m/s: a fish never stops (a slow fish keeps its heading and
    /// swims at this speed). The schooling lab's *Slowest speed* slider (default
    /// 0.15 m/s, half a body length per second).
    pub min_speed_m_per_s: f32,
}

/// The school seen from afar: fish bucketed into coarse cells (count and
/// position sum per cell, built once per step), so that a fish can find the
/// centre of all the fish it sees in O(cells), not O(fish). Topological
/// neighbours alone never see a second school a few metres away; real fish do,
/// and swim to it (schools in a tank merge). This far field gives cohesion
/// that view.
#[derive(Clone, Debug, Default)]
pub struct FarField {
    min_m: Vec3,
    cell_m: f32,
    /// Cells along x, y and z.
    dims: [usize; 3],
    /// Non-empty cells as structure of arrays: mean position, count and the
    /// cell's index.
    mean_x_m: Vec<f32>,
    mean_y_m: Vec<f32>,
    mean_z_m: Vec<f32>,
    count: Vec<f32>,
    cell: Vec<u32>,
    sums: Vec<(Vec3, u32)>,
}

impl FarField {
    /// Buckets `positions_m` into cubes of side `cell_m` over `min_m..max_m`.
    pub fn rebuild(&mut self, min_m: Vec3, max_m: Vec3, cell_m: f32, positions_m: &[Vec3]) {
        self.cell_m = if cell_m.is_finite() && cell_m > 0.1 {
            cell_m
        } else {
            1.0
        };
        self.min_m = min_m;
        let dims = ((max_m - min_m) / self.cell_m)
            .ceil()
            .max(Vec3::ONE)
            .min(Vec3::splat(32.0));
        self.dims = [dims.x as usize, dims.y as usize, dims.z as usize];
        self.sums.clear();
        self.sums
            .resize(self.dims.iter().product(), (Vec3::ZERO, 0));
        for &p in positions_m {
            if let Some(c) = self.cell_of(p) {
                let cell = &mut self.sums[c];
                cell.0 += p;
                cell.1 += 1;
            }
        }
        self.mean_x_m.clear();
        self.mean_y_m.clear();
        self.mean_z_m.clear();
        self.count.clear();
        self.cell.clear();
        for (c, &(sum, n)) in self.sums.iter().enumerate().filter(|(_, c)| c.1 > 0) {
            let mean = sum / n as f32;
            self.mean_x_m.push(mean.x);
            self.mean_y_m.push(mean.y);
            self.mean_z_m.push(mean.z);
            self.count.push(n as f32);
            self.cell.push(c as u32);
        }
    }

    /// The index of the cell holding `p` (points outside are clamped into the
    /// border cells), or `None` for a point that is not finite.
    fn cell_of(&self, p: Vec3) -> Option<usize> {
        let q = (p - self.min_m) / self.cell_m;
        if !q.is_finite() {
            return None;
        }
        // Truncation equals `floor` here: negative values clamp to 0.
        let [dx, dy, dz] = self.dims;
        let x = (q.x.max(0.0) as usize).min(dx - 1);
        let y = (q.y.max(0.0) as usize).min(dy - 1);
        let z = (q.z.max(0.0) as usize).min(dz - 1);
        Some(x + dx * (y + dy * z))
    }

    /// Centre of the other fish in the cells whose mean position the fish at
    /// `position_m` (one of the bucketed fish) heading `heading` sees (inside
    /// its field of view `cone`), or `None` if it sees none. The fish itself
    /// is left out of its cell.
    pub fn seen_centre_m(&self, position_m: Vec3, heading: Vec3, cone: &ViewCone) -> Option<Vec3> {
        let mut sum = Vec3::ZERO;
        let mut count = 0.0;
        let cells = self.count.len();
        let (xs, ys, zs) = (
            &self.mean_x_m[..cells],
            &self.mean_y_m[..cells],
            &self.mean_z_m[..cells],
        );
        let mine = self.cell_of(position_m).map(|c| c as u32);
        let add = |k: usize, sum: &mut Vec3, count: &mut f32| {
            let mean_m = Vec3::new(xs[k], ys[k], zs[k]);
            let n = self.count[k];
            *sum += mean_m * n;
            *count += n;
            if Some(self.cell[k]) == mine {
                *sum -= position_m;
                *count -= 1.0;
            }
        };
        // The view test four cells at a time (the same operations as
        // `cone.sees`, lane by lane), the sums cell by cell in order.
        let (px, py, pz) = (
            Vec4::splat(position_m.x),
            Vec4::splat(position_m.y),
            Vec4::splat(position_m.z),
        );
        let (hx, hy, hz) = (
            Vec4::splat(heading.x),
            Vec4::splat(heading.y),
            Vec4::splat(heading.z),
        );
        let mut k = 0;
        while k + 4 <= cells {
            let dx = Vec4::from_slice(&xs[k..k + 4]) - px;
            let dy = Vec4::from_slice(&ys[k..k + 4]) - py;
            let dz = Vec4::from_slice(&zs[k..k + 4]) - pz;
            let d2 = dx * dx + dy * dy + dz * dz;
            let dot = hx * dx + hy * dy + hz * dz;
            let mut seen = cone.sees_lanes(dot, d2);
            while seen != 0 {
                let lane = seen.trailing_zeros() as usize;
                add(k + lane, &mut sum, &mut count);
                seen &= seen - 1;
            }
            k += 4;
        }
        for k in k..cells {
            let mean_m = Vec3::new(xs[k], ys[k], zs[k]);
            if cone.sees(heading, mean_m - position_m) {
                add(k, &mut sum, &mut count);
            }
        }
        (count > 0.5).then(|| sum / count)
    }
}

/// The field of view as a test without square roots: within the vision
/// distance and inside the cone of half-angle `vision_angle_rad / 2` around the
/// heading.
#[derive(Clone, Copy, Debug, Default)]
pub struct ViewCone {
    vision_sq_m2: f32,
    cos_half: f32,
    cos_half_sq: f32,
}

impl ViewCone {
    /// The field of view of `perception` (one cosine: build it once per step,
    /// not once per fish).
    pub fn new(perception: &Perception) -> Self {
        let half_angle = (perception.vision_angle_rad * 0.5).clamp(0.0, std::f32::consts::PI);
        let cos_half = fmath::cos(half_angle) - 1e-6;
        Self {
            vision_sq_m2: perception.vision_distance_m * perception.vision_distance_m,
            cos_half,
            cos_half_sq: cos_half * cos_half,
        }
    }

    /// Is `offset` (from the eye) seen by a fish heading along the unit
    /// `heading`? `heading·offset ≥ cos(half angle)·‖offset‖`, squared.
    fn sees(&self, heading: Vec3, offset: Vec3) -> bool {
        let d2 = offset.length_squared();
        d2 <= self.vision_sq_m2 && self.in_angle(heading.dot(offset), d2)
    }

    /// [`Self::sees`] for four offsets at once, given their `dot`s with the
    /// heading and squared lengths `d2`: bit `l` of the result is lane `l`'s
    /// answer.
    fn sees_lanes(&self, dot: Vec4, d2: Vec4) -> u32 {
        let within = d2.cmple(Vec4::splat(self.vision_sq_m2));
        let ahead = dot.cmpge(Vec4::ZERO);
        let dot_sq = dot * dot;
        let wide = d2 * Vec4::splat(self.cos_half_sq);
        let angle = if self.cos_half >= 0.0 {
            ahead & dot_sq.cmpge(wide)
        } else {
            ahead | dot_sq.cmple(wide)
        };
        (within & angle).bitmask()
    }

    /// The angle part of [`Self::sees`], given `dot = heading·offset` and the
    /// squared distance.
    fn in_angle(&self, dot: f32, d2: f32) -> bool {
        let dot_sq = dot * dot;
        if self.cos_half >= 0.0 {
            dot >= 0.0 && dot_sq >= self.cos_half_sq * d2
        } else {
            dot >= 0.0 || dot_sq <= self.cos_half_sq * d2
        }
    }
}

/// Separation, alignment and cohesion for one fish.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NeighbourForces {
    pub separation_m_per_s2: Vec3,
    pub alignment_m_per_s2: Vec3,
    pub cohesion_m_per_s2: Vec3,
    /// How much the fish needs to separate now, 0–1: the mean intrusion of its
    /// heeded neighbours into its personal space, (1/n) Σ max(0, 1 − d / personal
    /// space). Classic mode ranks separation by it (see
    /// [`crate::sim::boids::control_mode::combine`]); the force itself grows with the summed
    /// intrusion.
    pub separation_need: f32,
    /// How much the fish needs to close up now, 0–1: its distance from the
    /// centre of its heeded neighbours over its personal space (the near pull's
    /// arrival), or, when it heeds no neighbour, the far field's pull. Classic
    /// mode ranks cohesion by it: the far field is a background pull towards a
    /// distant school and does not make cohesion pressing for a fish that is
    /// already among its neighbours (ranked with it, cohesion won 37 % of a
    /// school's steps and the Group weights reached polarization 0.61 instead of
    /// 0.76; `docs/boids.md`).
    pub cohesion_need: f32,
    /// How many neighbours the fish heeded (at most
    /// [`SteeringTuning::topological_neighbours`]).
    pub neighbours: u32,
}

/// Is `other` inside the field of view of a fish at `position` heading `heading`?
pub fn sees(position_m: Vec3, heading: Vec3, other_m: Vec3, perception: &Perception) -> bool {
    let offset = other_m - position_m;
    let distance = offset.length();
    if !(distance > 0.0 && distance <= perception.vision_distance_m) {
        return false;
    }
    let half_angle = (perception.vision_angle_rad * 0.5).clamp(0.0, std::f32::consts::PI);
    heading.dot(offset / distance) >= fmath::cos(half_angle) - 1e-6
}

/// A steering force from a desired velocity: `limit((desired − current) /
/// response_time, max_force)`. A response time of zero or less (or NaN) counts
/// as instant, i.e. the full maximum force.
pub fn steer_towards(
    desired_m_per_s: Vec3,
    current_m_per_s: Vec3,
    perception: &Perception,
) -> Vec3 {
    let response_time_s = if perception.response_time_s > 0.0 {
        perception.response_time_s
    } else {
        1e-3
    };
    limit(
        (desired_m_per_s - current_m_per_s) / response_time_s,
        perception.max_force_m_per_s2,
    )
}

/// The up-to-[`SteeringTuning::topological_neighbours`] nearest neighbours
/// that the fish at `positions_m[i]`, swimming with `velocities_m_per_s[i]`,
/// sees (the neighbours it heeds), looked up in `grid` (built over
/// `positions_m`, any cell size), nearest first.
pub fn heeded_neighbours(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    i: usize,
    grid: &SpatialGrid,
    perception: &Perception,
    tuning: &SteeringTuning,
) -> Nearest {
    search_heeded(
        positions_m,
        velocities_m_per_s,
        i,
        grid,
        perception,
        tuning,
        &ViewCone::new(perception),
        Nearest::new(tuning.topological_neighbours),
    )
}

/// [`heeded_neighbours`] with the field of view `cone` (of `perception`),
/// starting from `known`: neighbours the fish sees now with their distances now (those it heeded in the last step, as
/// [`recheck_heeded`] gives them), kept unless nearer ones are found. Finds
/// the same neighbours as a search from scratch (the order of ties aside),
/// but the known ones bound the search from the start, so it visits fewer
/// cells and points.
#[allow(clippy::too_many_arguments)]
pub fn search_heeded(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    i: usize,
    grid: &SpatialGrid,
    perception: &Perception,
    tuning: &SteeringTuning,
    cone: &ViewCone,
    known: Nearest,
) -> Nearest {
    search_heeded_in::<false>(
        positions_m,
        heading_of(velocities_m_per_s[i]),
        i,
        grid,
        perception,
        tuning,
        cone,
        known,
    )
}

/// [`search_heeded`] in `grid`'s slot numbering: `positions_m` are in slot
/// order ([`SpatialGrid::slots`]), `slot` and the neighbours in `known` and
/// in the result are slots, and `heading` is the fish's ([`heading_of`] its
/// velocity). The same neighbours, renumbered; the boid step keeps its
/// snapshot in slot order so that a fish's neighbours lie close together in
/// memory.
#[allow(clippy::too_many_arguments)]
pub fn search_heeded_slots(
    positions_m: &[Vec3],
    heading: Vec3,
    slot: usize,
    grid: &SpatialGrid,
    perception: &Perception,
    tuning: &SteeringTuning,
    cone: &ViewCone,
    known: Nearest,
) -> Nearest {
    search_heeded_in::<true>(
        positions_m,
        heading,
        slot,
        grid,
        perception,
        tuning,
        cone,
        known,
    )
}

/// [`search_heeded`] (`BY_SLOT` false) or [`search_heeded_slots`].
#[allow(clippy::too_many_arguments)]
fn search_heeded_in<const BY_SLOT: bool>(
    positions_m: &[Vec3],
    heading: Vec3,
    i: usize,
    grid: &SpatialGrid,
    perception: &Perception,
    tuning: &SteeringTuning,
    cone: &ViewCone,
    known: Nearest,
) -> Nearest {
    let position_m = positions_m[i];
    let max_neighbours = tuning.topological_neighbours;
    let mut nearest = if known.capacity() == max_neighbours.min(MAX_NEAREST) {
        known
    } else {
        Nearest::new(max_neighbours)
    };
    let accept = |j: usize, other_m: Vec3, distance_sq_m2: f32| {
        j != i
            && distance_sq_m2 > 0.0
            && cone.in_angle(heading.dot(other_m - position_m), distance_sq_m2)
    };
    if BY_SLOT {
        grid.k_nearest_slots(
            position_m,
            perception.vision_distance_m,
            &mut nearest,
            accept,
        );
    } else {
        grid.k_nearest(
            position_m,
            perception.vision_distance_m,
            &mut nearest,
            accept,
        );
    }
    nearest
}

/// The neighbours a fish heeded in an earlier step (`previous`, found by
/// [`heeded_neighbours`]) as it sees them now: each one still inside the
/// field of view `cone` of the fish at `positions_m[i]`,
/// swimming with `velocities_m_per_s[i]`, with its distance now, nearest first;
/// the others (and any index that is no longer a fish) are dropped. Costs a
/// few multiplications per neighbour instead of a search: the boid layer
/// searches each fish's neighbours every few steps and rechecks them in
/// between (see `neighbours::NEIGHBOUR_SEARCH_EVERY_STEPS`).
pub fn recheck_heeded(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    i: usize,
    previous: &Nearest,
    cone: &ViewCone,
) -> Nearest {
    recheck_heeded_facing(
        positions_m,
        heading_of(velocities_m_per_s[i]),
        i,
        previous,
        cone,
    )
}

/// [`recheck_heeded`] with the fish's `heading` ([`heading_of`] its
/// velocity) worked out beforehand.
pub fn recheck_heeded_facing(
    positions_m: &[Vec3],
    heading: Vec3,
    i: usize,
    previous: &Nearest,
    cone: &ViewCone,
) -> Nearest {
    let position_m = positions_m[i];
    let mut nearest = Nearest::new(previous.capacity());
    for (j, _) in previous.iter() {
        let Some(&other_m) = positions_m.get(j) else {
            continue;
        };
        let offset = other_m - position_m;
        let distance_sq_m2 = offset.length_squared();
        if j != i && distance_sq_m2 > 0.0 && cone.sees(heading, offset) {
            nearest.offer(j, distance_sq_m2);
        }
    }
    nearest
}

/// The three neighbour forces on the fish at `positions_m[i]` (a snapshot of
/// the school as structure of arrays: positions and velocities), heeding its
/// [`heeded_neighbours`]:
///
/// - separation: away from the heeded neighbours closer than
///   `separation_distance_m` (each weighted by 1/distance), desired speed the
///   maximum, scaled by the intrusion Σ (1 − distance / separation distance),
///   at most 1, so it fades out at the edge of the personal space;
/// - alignment: towards the heeded neighbours' mean heading, at the maximum speed;
/// - cohesion: seek the heeded neighbours' centre at the maximum speed, scaled
///   by min(1, distance to the centre / separation distance) (arrival), plus
///   the far field's pull (see [`FarField`]).
pub fn neighbour_forces(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    i: usize,
    grid: &SpatialGrid,
    far_field: Option<&FarField>,
    perception: &Perception,
    tuning: &SteeringTuning,
) -> NeighbourForces {
    let nearest = heeded_neighbours(positions_m, velocities_m_per_s, i, grid, perception, tuning);
    let far_centre_m = far_field.and_then(|f| {
        f.seen_centre_m(
            positions_m[i],
            heading_of(velocities_m_per_s[i]),
            &ViewCone::new(perception),
        )
    });
    forces_from_neighbours(
        positions_m,
        velocities_m_per_s,
        i,
        &nearest,
        far_centre_m,
        perception,
        tuning,
    )
}

/// [`neighbour_forces`] from the heeded neighbours and the seen centre of the
/// far field ([`FarField::seen_centre_m`]) already found.
pub fn forces_from_neighbours(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    i: usize,
    nearest: &Nearest,
    far_centre_m: Option<Vec3>,
    perception: &Perception,
    tuning: &SteeringTuning,
) -> NeighbourForces {
    forces_from_neighbours_in(
        positions_m,
        velocities_m_per_s,
        |j| velocities_m_per_s[j].normalize_or_zero(),
        i,
        nearest,
        far_centre_m,
        perception,
        tuning,
    )
}

/// [`forces_from_neighbours`] with every fish's direction of motion
/// (`directions[j]` = `velocities_m_per_s[j].normalize_or_zero()`) worked
/// out beforehand, once per fish: the same result, cheaper when every fish
/// heeds several neighbours.
#[allow(clippy::too_many_arguments)]
pub fn forces_from_neighbours_with_directions(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    directions: &[Vec3],
    i: usize,
    nearest: &Nearest,
    far_centre_m: Option<Vec3>,
    perception: &Perception,
    tuning: &SteeringTuning,
) -> NeighbourForces {
    forces_from_neighbours_in(
        positions_m,
        velocities_m_per_s,
        |j| directions[j],
        i,
        nearest,
        far_centre_m,
        perception,
        tuning,
    )
}

/// [`forces_from_neighbours`] with `direction(j)` the direction of motion of
/// fish `j`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn forces_from_neighbours_in(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    direction: impl Fn(usize) -> Vec3,
    i: usize,
    nearest: &Nearest,
    far_centre_m: Option<Vec3>,
    perception: &Perception,
    tuning: &SteeringTuning,
) -> NeighbourForces {
    let position_m = positions_m[i];
    let velocity_m_per_s = velocities_m_per_s[i];
    if nearest.is_empty() && far_centre_m.is_none() {
        return NeighbourForces::default();
    }
    let mut away = Vec3::ZERO;
    let mut intrusion = 0.0_f32;
    let mut velocity_sum = Vec3::ZERO;
    let mut align_strength = 0.0_f32;
    let mut position_sum = Vec3::ZERO;
    let separation_m = perception.separation_distance_m.max(0.0);
    for (j, distance_sq_m2) in nearest.iter() {
        let offset = position_m - positions_m[j];
        let distance_m = distance_sq_m2.sqrt();
        if distance_m < separation_m {
            // Unit direction / distance = offset / distance².
            away += offset / distance_sq_m2.max(1e-6);
            intrusion += 1.0 - distance_m / separation_m;
        }
        // A near neighbour's heading is read in full, a far one's less
        // (its silhouette shrinks with distance).
        // Infinite clear sight reads every heading in full, 0 none.
        let clarity = (perception.clear_sight_m / distance_m.max(1e-3)).clamp(0.0, 1.0);
        velocity_sum += direction(j) * clarity;
        align_strength += clarity;
        position_sum += positions_m[j];
    }
    let n = (nearest.len() as f32).max(1.0);
    let speed = perception.max_speed_m_per_s;
    let steer = |desired: Vec3| steer_towards(desired, velocity_m_per_s, perception);
    // Separation grows as neighbours intrude into the personal space (one
    // neighbour at half the distance: half strength; at contact: full).
    let separation_m_per_s2 = steer(away.normalize_or_zero() * speed) * intrusion.min(1.0);
    // Cohesion "arrives" (Lim & Tan's arrival): it fades out within a personal
    // space of the neighbours' centre instead of pulling the fish onto it.
    let to_centre_m = if nearest.is_empty() {
        Vec3::ZERO
    } else {
        position_sum / n - position_m
    };
    let arrival = if separation_m > 0.0 {
        (to_centre_m.length() / separation_m).min(1.0)
    } else {
        1.0
    };
    // Near pull (arriving) plus the far field's pull towards the seen school's
    // centre, at the far-field share of full strength, arriving too: both are
    // cohesion and scale with its weight.
    let near = to_centre_m.normalize_or_zero() * arrival;
    let far = far_centre_m.map_or(Vec3::ZERO, |c| {
        let to_far_m = c - position_m;
        let far_arrival = (to_far_m.length() / tuning.far_field_arrival_m.max(1e-3)).min(1.0);
        to_far_m.normalize_or_zero() * perception.far_pull * far_arrival
    });
    let pull = near + far;
    let cohesion_m_per_s2 = if pull == Vec3::ZERO {
        Vec3::ZERO
    } else {
        steer(pull.normalize_or_zero() * speed) * pull.length().min(1.0)
    };
    let alignment_m_per_s2 = if nearest.is_empty() {
        Vec3::ZERO
    } else {
        steer(velocity_sum.normalize_or_zero() * speed) * (align_strength / n).min(1.0)
    };
    NeighbourForces {
        separation_m_per_s2,
        alignment_m_per_s2,
        cohesion_m_per_s2,
        separation_need: if nearest.is_empty() {
            0.0
        } else {
            (intrusion / n).min(1.0)
        },
        cohesion_need: if nearest.is_empty() {
            pull.length().min(1.0)
        } else {
            arrival
        },
        neighbours: nearest.len() as u32,
    }
}

/// Avoiding other fish, the SIMBA way (other agents are obstacles, avoided
/// like rocks by swaying): among the heeded neighbours, the one the fish at
/// `positions_m[i]` would meet soonest, judged from their relative velocity
/// (closest approach under [`SteeringTuning::fish_avoid_clearance_m`] within
/// [`SteeringTuning::fish_avoid_look_ahead_s`]); if two or more other heeded
/// neighbours are within [`SteeringTuning::fish_cluster_link_m`] of it, the
/// obstacle is the centre of that
/// cluster. The fish sways sideways, away from the obstacle's offset from
/// its path, with a strength inversely proportional to the time left:
///
/// `Δv = normalize(−offset) · max_speed · look_ahead / max(t, 0.1 s)`.
///
/// Fish swimming side by side in a school have no closing speed and feel
/// nothing. Returns a velocity change (m/s), unlimited: the caller adds it to
/// the other obstacles' and limits the sum.
pub fn avoid_neighbours(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    i: usize,
    nearest: &Nearest,
    max_speed_m_per_s: f32,
    tuning: &SteeringTuning,
) -> Vec3 {
    avoid_neighbours_facing(
        positions_m,
        velocities_m_per_s,
        velocities_m_per_s[i].normalize_or_zero(),
        i,
        nearest,
        max_speed_m_per_s,
        tuning,
    )
}

/// [`avoid_neighbours`] with the fish's direction of motion (`heading`, its
/// velocity's `normalize_or_zero`) worked out beforehand.
pub fn avoid_neighbours_facing(
    positions_m: &[Vec3],
    velocities_m_per_s: &[Vec3],
    heading: Vec3,
    i: usize,
    nearest: &Nearest,
    max_speed_m_per_s: f32,
    tuning: &SteeringTuning,
) -> Vec3 {
    /// Shortest time to contact used in the strength, seconds.
    const MIN_TIME_S: f32 = 0.1;
    let position_m = positions_m[i];
    let velocity_m_per_s = velocities_m_per_s[i];
    if heading == Vec3::ZERO {
        return Vec3::ZERO;
    }
    let mut threat: Option<(f32, usize)> = None;
    for (j, _) in nearest.iter() {
        let offset_m = positions_m[j] - position_m;
        let closing_m_per_s = velocity_m_per_s - velocities_m_per_s[j];
        let closing_sq = closing_m_per_s.length_squared();
        if closing_sq < 1e-6 {
            continue;
        }
        let closing_dot = offset_m.dot(closing_m_per_s);
        // Not closing in (t ≤ 0, or NaN): skip before dividing.
        if closing_dot.is_nan() || closing_dot <= 0.0 {
            continue;
        }
        // Contact beyond the look-ahead (most neighbours in a school close
        // in slowly): skip before dividing. The bound is a millionth above
        // look-ahead × closing², far more than the rounding of either side,
        // so it skips only neighbours whose quotient below is past the
        // look-ahead too (and none when the bound is not a normal number).
        let beyond = tuning.fish_avoid_look_ahead_s * closing_sq * (1.0 + 1e-6);
        if beyond.is_normal() && closing_dot > beyond {
            continue;
        }
        let t_s = closing_dot / closing_sq;
        if !(t_s > 0.0 && t_s <= tuning.fish_avoid_look_ahead_s) {
            continue;
        }
        let miss_m = (offset_m - closing_m_per_s * t_s).length();
        if miss_m < tuning.fish_avoid_clearance_m && threat.is_none_or(|(soonest, _)| t_s < soonest)
        {
            threat = Some((t_s, j));
        }
    }
    let Some((t_s, j)) = threat else {
        return Vec3::ZERO;
    };
    let mut centre_m = positions_m[j];
    let mut members = 1.0;
    let link_sq_m2 = fmath::powi(tuning.fish_cluster_link_m, 2);
    for (k, _) in nearest.iter() {
        if k != j && positions_m[k].distance_squared(positions_m[j]) < link_sq_m2 {
            centre_m += positions_m[k];
            members += 1.0;
        }
    }
    let core_m = if members >= 3.0 {
        centre_m / members
    } else {
        positions_m[j]
    };
    let to_core_m = core_m - position_m;
    let offset_m = to_core_m - heading * to_core_m.dot(heading);
    let away = (-offset_m).normalize_or(heading.cross(Vec3::Y).normalize_or(Vec3::Z));
    let urgency = tuning.fish_avoid_look_ahead_s / t_s.max(MIN_TIME_S);
    let sway = away * max_speed_m_per_s * urgency;
    if sway.is_finite() { sway } else { Vec3::ZERO }
}

#[cfg(test)]
mod tests {
    use crate::sim::boids::forces::*;
    use crate::sim::common::fish::Fish;

    const PERCEPTION: Perception = Perception {
        vision_distance_m: 2.0,
        vision_angle_rad: 300f32.to_radians(),
        max_speed_m_per_s: 0.8,
        max_force_m_per_s2: 1.5,
        separation_distance_m: 1.0,
        response_time_s: 1.0,
        // Every heeded neighbour's heading read in full.
        clear_sight_m: f32::INFINITY,
        far_pull: 0.5,
        min_speed_m_per_s: 0.15,
    };

    /// The default tuning.
    fn tuning() -> SteeringTuning {
        SteeringTuning::default()
    }

    fn positions(fish: &[Fish]) -> Vec<Vec3> {
        fish.iter().map(|f| f.position_m).collect()
    }

    fn velocities(fish: &[Fish]) -> Vec<Vec3> {
        fish.iter().map(|f| f.velocity_m_per_s).collect()
    }

    fn grid_for(fish: &[Fish]) -> SpatialGrid {
        let mut grid = SpatialGrid::default();
        let positions: Vec<Vec3> = fish.iter().map(|f| f.position_m).collect();
        grid.rebuild(
            Vec3::new(-6.0, 0.0, -4.0),
            Vec3::new(6.0, 4.5, 4.0),
            2.0,
            &positions,
        );
        grid
    }

    #[test]
    fn a_neighbour_in_the_blind_cone_or_too_far_is_not_seen() {
        let p = Vec3::new(0.0, 2.0, 0.0);
        assert!(sees(p, Vec3::X, p + Vec3::X, &PERCEPTION), "ahead");
        assert!(sees(p, Vec3::X, p + Vec3::Z, &PERCEPTION), "beside");
        assert!(
            !sees(p, Vec3::X, p - Vec3::X, &PERCEPTION),
            "straight behind"
        );
        let behind_25_deg = p + Vec3::new(
            -fmath::cos(25f32.to_radians()),
            0.0,
            fmath::sin(25f32.to_radians()),
        );
        assert!(
            !sees(p, Vec3::X, behind_25_deg, &PERCEPTION),
            "inside the 60° blind cone"
        );
        assert!(
            !sees(p, Vec3::X, p + Vec3::X * 2.5, &PERCEPTION),
            "beyond vision distance"
        );
    }

    #[test]
    fn separation_pushes_away_alignment_matches_and_cohesion_pulls_in() {
        let me = Fish::new(Vec3::new(0.0, 2.0, 0.0), Vec3::X * 0.5, 0.4, 0.0);
        let close = Fish::new(Vec3::new(0.5, 2.0, 0.3), Vec3::Z * 0.5, 0.4, 0.0);
        let far = Fish::new(Vec3::new(1.5, 2.0, 0.9), Vec3::Z * 0.5, 0.4, 0.0);
        let fish = [me, close, far];
        let f = neighbour_forces(
            &positions(&fish),
            &velocities(&fish),
            0,
            &grid_for(&fish),
            None,
            &PERCEPTION,
            &tuning(),
        );
        assert_eq!(f.neighbours, 2);
        assert!(f.separation_m_per_s2.z < 0.0, "away from neighbours at +z");
        assert!(
            f.alignment_m_per_s2.z > 0.0,
            "turn towards the neighbours' +z heading"
        );
        assert!(
            f.cohesion_m_per_s2.z > 0.0,
            "towards the neighbours' centre"
        );
        for v in [
            f.separation_m_per_s2,
            f.alignment_m_per_s2,
            f.cohesion_m_per_s2,
        ] {
            assert!(v.length() <= PERCEPTION.max_force_m_per_s2 + 1e-5);
        }
    }

    #[test]
    fn classic_needs_are_the_mean_intrusion_and_the_near_arrival() {
        // Personal space 1 m: neighbours at 0.25 m and 0.75 m intrude by 0.75
        // and 0.25, a third at 1.5 m not at all: mean intrusion 1/3, while the
        // force's summed intrusion saturates at 1.
        let p = Vec3::new(0.0, 2.0, 0.0);
        let offsets = [Vec3::Z * 0.25, Vec3::Z * 0.75, Vec3::X * 1.5];
        let mut all = vec![p];
        all.extend(offsets.iter().map(|o| p + *o));
        let velocities = vec![Vec3::X * 0.5; all.len()];
        let mut nearest = Nearest::new(7);
        for (j, o) in offsets.iter().enumerate() {
            nearest.offer(j + 1, o.length_squared());
        }
        let centre_distance_m = (offsets.iter().sum::<Vec3>() / 3.0).length();
        for far_centre_m in [None, Some(p + Vec3::X * 4.0)] {
            let f = forces_from_neighbours(
                &all,
                &velocities,
                0,
                &nearest,
                far_centre_m,
                &PERCEPTION,
                &tuning(),
            );
            assert!((f.separation_need - 1.0 / 3.0).abs() < 1e-5, "{f:?}");
            // The far field does not make cohesion pressing among neighbours.
            assert!((f.cohesion_need - centre_distance_m).abs() < 1e-5, "{f:?}");
        }
        // Alone but seeing a distant school: the far field's pull is the need.
        let f = forces_from_neighbours(
            &all[..1],
            &velocities[..1],
            0,
            &Nearest::new(7),
            Some(p + Vec3::X * 4.0),
            &PERCEPTION,
            &tuning(),
        );
        assert!(
            (f.cohesion_need - PERCEPTION.far_pull).abs() < 1e-5,
            "{f:?}"
        );
        assert_eq!(f.separation_need, 0.0);
    }

    #[test]
    fn a_lone_or_coincident_fish_feels_nothing_and_never_nan() {
        let lone = [Fish::new(Vec3::new(0.0, 2.0, 0.0), Vec3::X, 0.4, 0.0)];
        assert_eq!(
            neighbour_forces(
                &positions(&lone),
                &velocities(&lone),
                0,
                &grid_for(&lone),
                None,
                &PERCEPTION,
                &tuning()
            ),
            NeighbourForces::default()
        );
        let twins = [lone[0], lone[0]];
        let f = neighbour_forces(
            &positions(&twins),
            &velocities(&twins),
            0,
            &grid_for(&twins),
            None,
            &PERCEPTION,
            &tuning(),
        );
        assert!(f.separation_m_per_s2.is_finite() && f.cohesion_m_per_s2.is_finite());
    }

    #[test]
    fn a_fish_heeds_only_its_seven_nearest_seen_neighbours() {
        // Twenty neighbours in a row ahead: only the seven nearest count, so the
        // cohesion pulls towards them, not towards the whole row's middle.
        let mut fish = vec![Fish::new(
            Vec3::new(-5.0, 2.0, 0.0),
            Vec3::X * 0.5,
            0.4,
            0.0,
        )];
        for k in 1..=20 {
            fish.push(Fish::new(
                Vec3::new(-5.0 + 0.2 * k as f32, 2.0, 0.0),
                Vec3::X * 0.5,
                0.4,
                0.0,
            ));
        }
        let perception = Perception {
            vision_distance_m: 5.0,
            ..PERCEPTION
        };
        let f = neighbour_forces(
            &positions(&fish),
            &velocities(&fish),
            0,
            &grid_for(&fish),
            None,
            &perception,
            &tuning(),
        );
        assert_eq!(f.neighbours, 7);
    }

    #[test]
    fn the_far_field_is_the_centre_of_the_other_fish_seen() {
        let tank = (Vec3::new(-6.0, 0.0, -4.0), Vec3::new(6.0, 4.5, 4.0));
        let me = Vec3::new(-4.0, 2.0, 0.0);
        let cone = ViewCone::new(&Perception {
            vision_distance_m: 8.0,
            ..PERCEPTION
        });
        let mut far = FarField::default();
        far.rebuild(tank.0, tank.1, 2.5, &[me]);
        assert_eq!(far.seen_centre_m(me, Vec3::X, &cone), None, "alone");
        // Two fish ahead (one in the same cell as me), one behind in the blind cone.
        let others = [
            Vec3::new(-3.5, 2.0, 0.5),
            Vec3::new(2.0, 2.0, 0.0),
            Vec3::new(-5.9, 2.0, 0.0),
        ];
        let mut all = vec![me];
        all.extend(others);
        far.rebuild(tank.0, tank.1, 2.5, &all);
        let centre = far.seen_centre_m(me, Vec3::X, &cone).unwrap();
        let expected = (others[0] + others[1]) / 2.0;
        assert!(centre.distance(expected) < 1e-4, "{centre} != {expected}");
    }

    #[test]
    fn a_search_seeded_with_the_last_neighbours_finds_the_nearest_seen() {
        // A school of 400 fish in a 3 m cube, all heading about +x.
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        let fish: Vec<Fish> = (0..400)
            .map(|_| {
                let p = Vec3::new(
                    rng.random_range(-1.5..1.5),
                    rng.random_range(1.0..4.0),
                    rng.random_range(-1.5..1.5),
                );
                let v = Vec3::new(
                    0.5,
                    rng.random_range(-0.1..0.1),
                    rng.random_range(-0.1..0.1),
                );
                Fish::new(p, v, 0.3, 0.0)
            })
            .collect();
        let (ps, vs) = (positions(&fish), velocities(&fish));
        let mut grid = SpatialGrid::default();
        grid.rebuild(
            Vec3::new(-6.0, 0.0, -4.0),
            Vec3::new(6.0, 4.5, 4.0),
            0.4,
            &ps,
        );
        let cone = ViewCone::new(&PERCEPTION);
        for i in (0..fish.len()).step_by(13) {
            let fresh = heeded_neighbours(&ps, &vs, i, &grid, &PERCEPTION, &tuning());
            assert_eq!(fresh.len(), 7);
            // Seeds: every other of the true neighbours, plus a farther fish
            // it sees that is not among them.
            let mut seeds = Nearest::new(7);
            for (j, d2) in fresh.iter().step_by(2) {
                seeds.offer(j, d2);
            }
            let extra = (0..fish.len())
                .find(|&j| {
                    j != i
                        && !fresh.contains(j)
                        && sees(ps[i], heading_of(vs[i]), ps[j], &PERCEPTION)
                })
                .unwrap();
            seeds.offer(extra, ps[extra].distance_squared(ps[i]));
            let rechecked = recheck_heeded(&ps, &vs, i, &seeds, &cone);
            assert_eq!(rechecked.len(), seeds.len(), "all seeds are still seen");
            let seeded =
                search_heeded(&ps, &vs, i, &grid, &PERCEPTION, &tuning(), &cone, rechecked);
            let a: Vec<usize> = fresh.iter().map(|(j, _)| j).collect();
            let b: Vec<usize> = seeded.iter().map(|(j, _)| j).collect();
            assert_eq!(a, b, "fish {i}: each found once, nearest first");
        }
    }

    #[test]
    fn a_rechecked_neighbour_that_left_the_view_is_dropped() {
        let me = Fish::new(Vec3::new(0.0, 2.0, 0.0), Vec3::X * 0.5, 0.4, 0.0);
        let ahead = Fish::new(Vec3::new(1.0, 2.0, 0.0), Vec3::X * 0.5, 0.4, 0.0);
        let beside = Fish::new(Vec3::new(0.0, 2.0, 0.8), Vec3::X * 0.5, 0.4, 0.0);
        let mut fish = vec![me, ahead, beside];
        let heeded = heeded_neighbours(
            &positions(&fish),
            &velocities(&fish),
            0,
            &grid_for(&fish),
            &PERCEPTION,
            &tuning(),
        );
        assert_eq!(heeded.len(), 2);
        // The fish ahead is now straight behind (in the blind cone), the one
        // beside too far; a removed fish's index is no fish at all.
        fish[1].position_m = Vec3::new(-1.0, 2.0, 0.0);
        fish[2].position_m = Vec3::new(0.0, 2.0, 3.0);
        let cone = ViewCone::new(&PERCEPTION);
        let now = recheck_heeded(&positions(&fish), &velocities(&fish), 0, &heeded, &cone);
        assert!(now.is_empty());
        fish[1].position_m = Vec3::new(1.2, 2.0, 0.0);
        fish.truncate(2);
        let now = recheck_heeded(&positions(&fish), &velocities(&fish), 0, &heeded, &cone);
        let kept: Vec<(usize, f32)> = now.iter().collect();
        assert_eq!(kept.len(), 1);
        assert_eq!(kept[0].0, 1);
        assert!((kept[0].1 - 1.44).abs() < 1e-4, "its distance now");
    }

    /// The heeded neighbours of fish 0: every other fish, nearest first.
    fn all_heeded(positions_m: &[Vec3]) -> Nearest {
        let mut nearest = Nearest::new(7);
        for (j, p) in positions_m.iter().enumerate().skip(1) {
            nearest.offer(j, p.distance_squared(positions_m[0]));
        }
        nearest
    }

    #[test]
    fn a_fish_sways_sideways_round_a_fish_coming_straight_at_it_but_not_round_a_schoolmate() {
        let me = Vec3::new(0.0, 2.0, 0.0);
        // Head-on, 0.6 m ahead and slightly to the left (−z is left of +x).
        let positions = [me, me + Vec3::new(0.6, 0.0, -0.05)];
        let velocities = [Vec3::X * 0.5, -Vec3::X * 0.5];
        let sway = avoid_neighbours(
            &positions,
            &velocities,
            0,
            &all_heeded(&positions),
            0.8,
            &tuning(),
        );
        assert!(sway.z > 0.0, "away from the oncoming fish's side: {sway}");
        assert!(sway.x.abs() < 1e-4, "sideways, not braking: {sway}");
        // The same fish swimming alongside at the same velocity: nothing to avoid.
        let alongside = [Vec3::X * 0.5, Vec3::X * 0.5];
        let calm = avoid_neighbours(
            &positions,
            &alongside,
            0,
            &all_heeded(&positions),
            0.8,
            &tuning(),
        );
        assert_eq!(calm, Vec3::ZERO);
        // Farther off (contact in more than the look-ahead), nothing yet.
        let far = [me, me + Vec3::new(1.5, 0.0, -0.05)];
        assert_eq!(
            avoid_neighbours(&far, &velocities, 0, &all_heeded(&far), 0.8, &tuning()),
            Vec3::ZERO
        );
        // The sooner the contact, the harder the sway.
        let near = [me, me + Vec3::new(0.3, 0.0, -0.05)];
        let hard = avoid_neighbours(&near, &velocities, 0, &all_heeded(&near), 0.8, &tuning());
        assert!(hard.length() > sway.length());
    }

    #[test]
    fn three_close_fish_in_the_way_are_avoided_as_one_obstacle() {
        let me = Vec3::new(0.0, 2.0, 0.0);
        // A still fish just right of the path (+z), with two companions further
        // right: the cluster's centre is right of the path, so the sway is left.
        let ahead = me + Vec3::new(0.5, 0.0, 0.1);
        let positions = [
            me,
            ahead,
            ahead + Vec3::new(0.0, 0.0, 0.4),
            ahead + Vec3::new(0.1, 0.0, 0.5),
        ];
        let velocities = [Vec3::X * 0.5, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO];
        let sway = avoid_neighbours(
            &positions,
            &velocities,
            0,
            &all_heeded(&positions),
            0.8,
            &tuning(),
        );
        assert!(sway.z < 0.0, "away from the cluster: {sway}");
        // One of the cluster on the other side of the path: the obstacle is the
        // cluster's centre (right of the path), not that fish (left of it).
        let mixed = [
            me,
            me + Vec3::new(0.5, 0.0, -0.05),
            me + Vec3::new(0.5, 0.0, 0.45),
            me + Vec3::new(0.6, 0.0, 0.5),
        ];
        let sway = avoid_neighbours(&mixed, &velocities, 0, &all_heeded(&mixed), 0.8, &tuning());
        assert!(
            sway.z < 0.0,
            "round the cluster, not the nearest fish: {sway}"
        );
        let alone = [me, me + Vec3::new(0.5, 0.0, -0.05)];
        let sway = avoid_neighbours(
            &alone,
            &velocities[..2],
            0,
            &all_heeded(&alone),
            0.8,
            &tuning(),
        );
        assert!(
            sway.z > 0.0,
            "a lone fish on the left is passed on the right: {sway}"
        );
    }

    /// `avoid_neighbours` as it was before it skipped the division for
    /// neighbours not closing in or meeting beyond the look-ahead: the
    /// reference the faster one must match bit for bit.
    fn avoid_neighbours_reference(
        positions_m: &[Vec3],
        velocities_m_per_s: &[Vec3],
        i: usize,
        nearest: &Nearest,
        max_speed_m_per_s: f32,
        tuning: &SteeringTuning,
    ) -> Vec3 {
        let position_m = positions_m[i];
        let velocity_m_per_s = velocities_m_per_s[i];
        let heading = velocity_m_per_s.normalize_or_zero();
        if heading == Vec3::ZERO {
            return Vec3::ZERO;
        }
        let mut threat: Option<(f32, usize)> = None;
        for (j, _) in nearest.iter() {
            let offset_m = positions_m[j] - position_m;
            let closing_m_per_s = velocity_m_per_s - velocities_m_per_s[j];
            let closing_sq = closing_m_per_s.length_squared();
            if closing_sq < 1e-6 {
                continue;
            }
            let t_s = offset_m.dot(closing_m_per_s) / closing_sq;
            if !(t_s > 0.0 && t_s <= tuning.fish_avoid_look_ahead_s) {
                continue;
            }
            let miss_m = (offset_m - closing_m_per_s * t_s).length();
            if miss_m < tuning.fish_avoid_clearance_m
                && threat.is_none_or(|(soonest, _)| t_s < soonest)
            {
                threat = Some((t_s, j));
            }
        }
        let Some((t_s, j)) = threat else {
            return Vec3::ZERO;
        };
        let mut centre_m = positions_m[j];
        let mut members = 1.0;
        let link_sq_m2 = fmath::powi(tuning.fish_cluster_link_m, 2);
        for (k, _) in nearest.iter() {
            if k != j && positions_m[k].distance_squared(positions_m[j]) < link_sq_m2 {
                centre_m += positions_m[k];
                members += 1.0;
            }
        }
        let core_m = if members >= 3.0 {
            centre_m / members
        } else {
            positions_m[j]
        };
        let to_core_m = core_m - position_m;
        let offset_m = to_core_m - heading * to_core_m.dot(heading);
        let away = (-offset_m).normalize_or(heading.cross(Vec3::Y).normalize_or(Vec3::Z));
        let urgency = tuning.fish_avoid_look_ahead_s / t_s.max(0.1);
        let sway = away * max_speed_m_per_s * urgency;
        if sway.is_finite() { sway } else { Vec3::ZERO }
    }

    #[test]
    fn skipping_the_division_changes_no_sway_by_a_bit() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(36);
        let mut swayed = 0;
        for case in 0..20_000 {
            let mut tuning = tuning();
            if case % 3 == 1 {
                tuning.fish_avoid_look_ahead_s = rng.random_range(0.0..3.0);
            }
            let me = Vec3::new(0.0, 2.0, 0.0);
            let my_v = Vec3::new(
                rng.random_range(-0.8..0.8),
                rng.random_range(-0.2..0.2),
                rng.random_range(-0.8..0.8),
            );
            let mut positions = vec![me];
            let mut velocities = vec![my_v];
            for _ in 0..7 {
                let offset = Vec3::new(
                    rng.random_range(-1.5..1.5),
                    rng.random_range(-0.5..0.5),
                    rng.random_range(-1.5..1.5),
                );
                // Half the neighbours meet the fish at exactly (as near as
                // floats go) the look-ahead: the edge of the skip.
                let v = if rng.random_bool(0.5) {
                    my_v - offset / tuning.fish_avoid_look_ahead_s.max(0.05)
                } else {
                    Vec3::new(
                        rng.random_range(-0.8..0.8),
                        rng.random_range(-0.2..0.2),
                        rng.random_range(-0.8..0.8),
                    )
                };
                positions.push(me + offset);
                velocities.push(v);
            }
            let nearest = all_heeded(&positions);
            let fast = avoid_neighbours(&positions, &velocities, 0, &nearest, 0.8, &tuning);
            let reference =
                avoid_neighbours_reference(&positions, &velocities, 0, &nearest, 0.8, &tuning);
            assert_eq!(
                fast.to_array().map(f32::to_bits),
                reference.to_array().map(f32::to_bits),
                "case {case}"
            );
            swayed += usize::from(fast != Vec3::ZERO);
        }
        assert!(swayed > 1_000, "the cases reach the sway: {swayed}");
    }

    #[test]
    fn the_far_fields_four_cells_at_a_time_match_one_at_a_time() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(37);
        let tank = (Vec3::new(-6.0, 0.0, -4.0), Vec3::new(6.0, 4.5, 4.0));
        let points: Vec<Vec3> = (0..3_000)
            .map(|_| {
                Vec3::new(
                    rng.random_range(-6.0..6.0),
                    rng.random_range(0.0..4.5),
                    rng.random_range(-4.0..4.0),
                )
            })
            .collect();
        let mut far = FarField::default();
        far.rebuild(tank.0, tank.1, 2.5, &points);
        for angle in [300f32, 200.0, 120.0, 360.0] {
            let perception = Perception {
                vision_distance_m: 5.0,
                vision_angle_rad: angle.to_radians(),
                ..PERCEPTION
            };
            let cone = ViewCone::new(&perception);
            for (k, &p) in points.iter().enumerate().step_by(7) {
                let heading = Vec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                )
                .normalize_or(Vec3::X);
                // One cell at a time, as before.
                let mine = far.cell_of(p).map(|c| c as u32);
                let (mut sum, mut count) = (Vec3::ZERO, 0.0);
                for c in 0..far.count.len() {
                    let mean_m = Vec3::new(far.mean_x_m[c], far.mean_y_m[c], far.mean_z_m[c]);
                    if cone.sees(heading, mean_m - p) {
                        sum += mean_m * far.count[c];
                        count += far.count[c];
                        if Some(far.cell[c]) == mine {
                            sum -= p;
                            count -= 1.0;
                        }
                    }
                }
                let expected = (count > 0.5).then(|| sum / count);
                let found = far.seen_centre_m(p, heading, &cone);
                assert_eq!(
                    found.map(|c| c.to_array().map(f32::to_bits)),
                    expected.map(|c| c.to_array().map(f32::to_bits)),
                    "point {k}, angle {angle}"
                );
            }
        }
    }
}
