//! The artificial fish's vision sensor (Tu & Terzopoulos 1994 §5.1, Fig. 10): a
//! cyclopean eye with a 300° spherical field of view (a 60° blind cone behind)
//! reaching out to an effective radius V_r set by the water's visibility. An
//! object is *seen* when some part of it enters this view volume and it is not
//! fully occluded behind an opaque object (a rock, or another fish's body).
//!
//! Occlusion is tested with rays from the eye to the object's centre and to four
//! points on its silhouette (its bounding sphere seen from the eye): the object
//! is seen if any ray is clear. Fish bodies block rays as spheres of
//! [`PerceptionParams::occluder_radius_body_lengths`] body lengths; rocks, pillars and ledges by
//! their exact shapes (sphere tracing of `Obstacle::signed_distance_m`).
//!
//! [`Retina`] renders the fish-eye "retinal image" of Fig. 11 by casting one ray
//! per pixel (equidistant fisheye over the 300° field): fish, rocks, food, sand,
//! glass and the surface, lit by the water's light field and fogged by distance.
//! The fish reads the image's mean brightness (§5.1: "the fish determines only
//! the overall brightness of its environment by computing the mean intensity of
//! the retinal image").

use crate::sim::common::fmath;
use glam::Vec3;

use crate::sim::common::obstacle::Obstacle;
use crate::sim::reef::environment::Environment;
use crate::sim::reef::params::PerceptionParams;

/// The paper's field of view, radians (300°).
pub const FIELD_OF_VIEW_RAD: f32 = 300.0 * std::f32::consts::PI / 180.0;

/// The sphere by which a fish of `body_length_m` centred at `center_m` hides
/// what lies behind it.
pub fn fish_occluder(params: &PerceptionParams, center_m: Vec3, body_length_m: f32) -> Sphere {
    Sphere {
        center_m,
        radius_m: params.occluder_radius_body_lengths * body_length_m,
    }
}

/// A sphere that may be seen or may hide things.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    pub center_m: Vec3,
    pub radius_m: f32,
}

/// The eye of one fish.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eye {
    /// Where the eye is (the head), metres.
    pub position_m: Vec3,
    /// Where the fish looks (unit).
    pub forward: Vec3,
    /// V_r, metres.
    pub radius_m: f32,
    /// Full angle of the field of view, radians (300° in the paper).
    pub field_of_view_rad: f32,
}

impl Eye {
    pub fn new(position_m: Vec3, forward: Vec3, radius_m: f32) -> Self {
        Self {
            position_m,
            forward: forward.normalize_or(Vec3::X),
            radius_m,
            field_of_view_rad: FIELD_OF_VIEW_RAD,
        }
    }

    /// Does some part of `object` enter the view volume (within V_r and outside
    /// the blind cone behind)?
    pub fn in_view_volume(&self, object: Sphere) -> bool {
        let to = object.center_m - self.position_m;
        let d = to.length();
        if !d.is_finite() || d - object.radius_m > self.radius_m {
            return false;
        }
        if d <= object.radius_m {
            return true;
        }
        let angle = fmath::acos(self.forward.dot(to / d).clamp(-1.0, 1.0));
        let angular_radius = fmath::asin((object.radius_m / d).clamp(-1.0, 1.0));
        angle - angular_radius <= 0.5 * self.field_of_view_rad
    }

    /// Is `object` seen: in the view volume and not fully hidden behind one of
    /// `occluders` (other fish; the object itself and the viewer must not be in
    /// the list) or `obstacles`?
    pub fn sees(&self, object: Sphere, occluders: &[Sphere], obstacles: &[Obstacle]) -> bool {
        if !self.in_view_volume(object) {
            return false;
        }
        silhouette_points(self.position_m, object)
            .iter()
            .any(|&p| self.in_field(p) && clear_line(self.position_m, p, occluders, obstacles))
    }

    /// Is the direction to `p_m` outside the blind cone and within V_r?
    fn in_field(&self, p_m: Vec3) -> bool {
        let to = p_m - self.position_m;
        let d = to.length();
        if d < 1e-6 {
            return true;
        }
        d <= self.radius_m
            && self.forward.dot(to / d) >= fmath::cos(0.5 * self.field_of_view_rad) - 1e-6
    }
}

/// The centre of `object` and four points on its outline as seen from `eye_m`
/// (pulled in by 10 % so that grazing rays count as blocked).
fn silhouette_points(eye_m: Vec3, object: Sphere) -> [Vec3; 5] {
    let axis = (object.center_m - eye_m).normalize_or(Vec3::X);
    let side = axis.any_orthonormal_vector();
    let up = axis.cross(side);
    let r = 0.9 * object.radius_m;
    let c = object.center_m;
    [c, c + side * r, c - side * r, c + up * r, c - up * r]
}

/// Is the straight line from `a` to `b` free of `occluders` and `obstacles`?
pub fn clear_line(a: Vec3, b: Vec3, occluders: &[Sphere], obstacles: &[Obstacle]) -> bool {
    let ab = b - a;
    let len = ab.length();
    if len < 1e-6 {
        return true;
    }
    let dir = ab / len;
    for s in occluders {
        if let Some(t) = ray_sphere(a, dir, *s)
            && t < len
        {
            return false;
        }
    }
    obstacles
        .iter()
        .filter(|o| segment_near_obstacle(a, b, o))
        .all(|o| sphere_trace(a, dir, len, |p| o.signed_distance_m(p)).is_none())
}

/// Distance along the ray (`dir` unit) to its first entry into `s`, if ahead.
pub fn ray_sphere(origin: Vec3, dir: Vec3, s: Sphere) -> Option<f32> {
    let oc = origin - s.center_m;
    let b = oc.dot(dir);
    let c = oc.length_squared() - s.radius_m * s.radius_m;
    if c <= 0.0 {
        // Starts inside: a fish does not see out of a sphere around itself,
        // but the caller never lists the viewer; treat as not blocking.
        return None;
    }
    let disc = b * b - c;
    if disc < 0.0 || b > 0.0 {
        return None;
    }
    Some(-b - disc.sqrt())
}

/// Cheap reject: the segment passes farther from the obstacle's bounding
/// sphere than its radius.
fn segment_near_obstacle(a: Vec3, b: Vec3, o: &Obstacle) -> bool {
    let (lo, hi) = o.vertical_extent_m();
    let footprint = o.footprint_center_m();
    let centre = Vec3::new(footprint.x, 0.5 * (lo + hi), footprint.y);
    let radius = o.radius_m().max(0.5 * (hi - lo)) * 1.5 + 0.01;
    let ab = b - a;
    let t = ((centre - a).dot(ab) / ab.length_squared().max(1e-12)).clamp(0.0, 1.0);
    (a + ab * t).distance(centre) <= radius
}

/// March along the ray by the signed distance until it enters the solid
/// (returns the distance) or passes `max_t_m`.
pub fn sphere_trace(
    origin: Vec3,
    dir: Vec3,
    max_t_m: f32,
    sdf: impl Fn(Vec3) -> f32,
) -> Option<f32> {
    let mut t = 0.0;
    for _ in 0..64 {
        let d = sdf(origin + dir * t);
        if !d.is_finite() {
            return None;
        }
        if d < 2e-3 {
            return Some(t);
        }
        t += d;
        if t >= max_t_m {
            return None;
        }
    }
    None
}

/// What the retina can see: everything drawn is an opaque sphere, ellipsoid or
/// obstacle; food is small bright spheres.
#[derive(Clone, Debug, Default)]
pub struct RetinaScene<'a> {
    /// Fish bodies: centre, heading (unit), body length, colour (linear RGB).
    pub fish: Vec<(Vec3, Vec3, f32, [f32; 3])>,
    pub food_m: Vec<Vec3>,
    pub obstacles: &'a [Obstacle],
}

/// A fish-eye retinal image: `size` × `size` RGB pixels, an equidistant
/// fisheye (distance from the centre ∝ angle from the optical axis) covering
/// the whole field of view; pixels outside the disc are black.
#[derive(Clone, Debug, PartialEq)]
pub struct Retina {
    pub size: usize,
    /// Row-major, top row first, linear RGB in [0, 1].
    pub pixels: Vec<[f32; 3]>,
    /// Mean intensity (luminance) over the field of view, each pixel weighted
    /// by the solid angle it covers, [0, 1].
    pub mean_brightness: f32,
}

/// Colour of sand, water and rocks in the retinal image (linear RGB).
const SAND: [f32; 3] = [0.76, 0.68, 0.5];
const WATER: [f32; 3] = [0.05, 0.28, 0.38];
const ROCK: [f32; 3] = [0.42, 0.4, 0.38];
const SURFACE: [f32; 3] = [0.75, 0.9, 0.95];
const FOOD: [f32; 3] = [0.95, 0.9, 0.45];
/// Radius of a food particle in the retina, metres.
const FOOD_RADIUS_M: f32 = 0.06;

impl Retina {
    /// Renders what `eye` sees (its `up` gives the image's vertical).
    pub fn render(
        eye: &Eye,
        up: Vec3,
        size: usize,
        scene: &RetinaScene,
        env: &Environment,
    ) -> Self {
        let size = size.clamp(4, 256);
        let forward = eye.forward;
        let right = forward
            .cross(up)
            .normalize_or(forward.any_orthonormal_vector());
        let up = right.cross(forward);
        let half_fov = 0.5 * eye.field_of_view_rad;
        let mut pixels = vec![[0.0; 3]; size * size];
        let (mut sum, mut total_weight) = (0.0f32, 0.0f32);
        for row in 0..size {
            for col in 0..size {
                let x = (col as f32 + 0.5) / size as f32 * 2.0 - 1.0;
                let y = 1.0 - (row as f32 + 0.5) / size as f32 * 2.0;
                let r = (x * x + y * y).sqrt();
                if r > 1.0 {
                    continue;
                }
                let theta = r * half_fov;
                let (sin_t, cos_t) = fmath::sin_cos(theta);
                let (cx, cy) = if r > 1e-6 { (x / r, y / r) } else { (0.0, 0.0) };
                let dir = (forward * cos_t + (right * cx + up * cy) * sin_t).normalize_or(forward);
                let c = shade_ray(eye, dir, scene, env);
                pixels[row * size + col] = c;
                // Weighted by the pixel's solid angle, sin θ / θ in an
                // equidistant fisheye, so the stretched rim behind does not
                // outweigh the view ahead.
                let weight = if theta > 1e-6 { sin_t / theta } else { 1.0 };
                sum += weight * (0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]);
                total_weight += weight;
            }
        }
        Self {
            size,
            pixels,
            mean_brightness: if total_weight > 0.0 {
                (sum / total_weight).clamp(0.0, 1.0)
            } else {
                0.0
            },
        }
    }

    /// The image as 8-bit sRGB-ish RGBA (gamma 2.2), for display.
    pub fn to_rgba8(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.pixels.len() * 4);
        for p in &self.pixels {
            for c in p {
                out.push((fmath::powf(c.clamp(0.0, 1.0), 1.0 / 2.2) * 255.0).round() as u8);
            }
            out.push(255);
        }
        out
    }
}

/// The colour seen along one ray.
fn shade_ray(eye: &Eye, dir: Vec3, scene: &RetinaScene, env: &Environment) -> [f32; 3] {
    let o = eye.position_m;
    let far = eye.radius_m;
    let mut best_t = far;
    let mut colour = WATER;
    // Tank walls, floor and surface.
    let tank = env.tank;
    for axis in 0..3 {
        let d = dir[axis];
        if d.abs() < 1e-6 {
            continue;
        }
        let bound = if d > 0.0 {
            tank.max_m[axis]
        } else {
            tank.min_m[axis]
        };
        let t = (bound - o[axis]) / d;
        if t > 0.0 && t < best_t {
            best_t = t;
            colour = match (axis, d > 0.0) {
                (1, false) => SAND,
                (1, true) => SURFACE,
                _ => [0.12, 0.3, 0.36],
            };
        }
    }
    for &(centre, heading, length, c) in &scene.fish {
        if let Some(t) = ray_ellipsoid(o, dir, centre, heading, 0.5 * length, 0.15 * length)
            && t < best_t
        {
            best_t = t;
            colour = c;
        }
    }
    for &f in &scene.food_m {
        let s = Sphere {
            center_m: f,
            radius_m: FOOD_RADIUS_M,
        };
        if let Some(t) = ray_sphere(o, dir, s)
            && t < best_t
        {
            best_t = t;
            colour = FOOD;
        }
    }
    for obstacle in scene.obstacles {
        if let Some(t) = sphere_trace(o, dir, best_t, |p| obstacle.signed_distance_m(p))
            && t < best_t
        {
            best_t = t;
            colour = ROCK;
        }
    }
    let hit = o + dir * best_t;
    let light = if colour == SURFACE {
        1.0
    } else {
        0.25 + 0.75 * env.brightness_at(hit)
    };
    // Fog towards the water colour with distance (visibility V_r).
    let fog = fmath::powf((best_t / far.max(1e-3)).clamp(0.0, 1.0), 0.8);
    let water = env.brightness_at(o) * 0.8 + 0.2;
    let mut out = [0.0; 3];
    for k in 0..3 {
        out[k] = (colour[k] * light) * (1.0 - fog) + WATER[k] * water * fog;
    }
    out
}

/// Distance to an ellipsoid with semi-axis `a` along `axis` (unit) and `b`
/// across, centred at `centre`.
fn ray_ellipsoid(o: Vec3, dir: Vec3, centre: Vec3, axis: Vec3, a: f32, b: f32) -> Option<f32> {
    let axis = axis.normalize_or(Vec3::X);
    let squash = |v: Vec3| {
        let along = axis * v.dot(axis);
        along / a.max(1e-4) + (v - along) / b.max(1e-4)
    };
    let o2 = squash(o - centre);
    let d2 = squash(dir);
    let len = d2.length();
    if len < 1e-9 {
        return None;
    }
    let t = ray_sphere(
        o2,
        d2 / len,
        Sphere {
            center_m: Vec3::ZERO,
            radius_m: 1.0,
        },
    )?;
    Some(t / len)
}

// The reef's perception stage: what each animal sees, its retina and its fellows.

use crate::sim::common::tank::Tank;
use crate::sim::reef::animal::{ReefAnimal, Seen};
use crate::sim::reef::behaviour::Neighbour;
use crate::sim::reef::bodies::ReefBody;
use crate::sim::reef::courtship::{Courtship, Partner};
use crate::sim::reef::feeding::FoodParticle;
use crate::sim::reef::mind::{FishKind, Intention, Percept, Sex, Target};
use crate::sim::reef::params::ReefParams;

/// β1 of the prey cost: schooling prey are harder to take (paper: 0.5).
pub const PREY_BETA_SCHOOL: f32 = 0.5;

/// β2 of the prey cost: prey that needs a large turn costs more (paper: 0.2).
pub const PREY_BETA_TURN: f32 = 0.2;

/// Does fish `i` swim in a school: at least
/// [`PerceptionParams::schoolmates_for_s_k`] live fish of its kind and species
/// near it swimming roughly its way?
pub(super) fn in_a_school(params: &PerceptionParams, seen: &[Seen], i: usize) -> bool {
    let me = seen[i];
    if !me.alive {
        return false;
    }
    let radius = params.schoolmate_radius_body_lengths * me.length_m;
    let min_cos = fmath::cos(params.schoolmate_max_angle_rad);
    seen.iter()
        .enumerate()
        .filter(|&(j, o)| {
            j != i
                && o.alive
                && o.kind == me.kind
                && o.species == me.species
                && o.position_m.distance(me.position_m) <= radius
                && o.heading.dot(me.heading) >= min_cos
        })
        .take(params.schoolmates_for_s_k)
        .count()
        >= params.schoolmates_for_s_k
}

/// A display colour for the retina (linear RGB) from a hue.
pub(super) fn hue_rgb(hue: f32, kind: FishKind) -> [f32; 3] {
    if kind == FishKind::Predator {
        return [0.35, 0.38, 0.42];
    }
    let h = hue.rem_euclid(1.0) * 6.0;
    let x = 1.0 - (h % 2.0 - 1.0).abs();
    let (r, g, b) = match h as u32 {
        0 => (1.0, x, 0.0),
        1 => (x, 1.0, 0.0),
        2 => (0.0, 1.0, x),
        3 => (0.0, x, 1.0),
        4 => (x, 0.0, 1.0),
        _ => (1.0, 0.0, x),
    };
    [0.15 + 0.75 * r, 0.15 + 0.75 * g, 0.15 + 0.75 * b]
}

/// The perception stage's state: how every animal looks this step, read
/// before anyone moves.
#[derive(Clone, Debug)]
pub struct Perception {
    seen: Vec<Seen>,
    /// By animal: the sphere by which its body hides what lies behind it (of
    /// radius 0 for the dead).
    occluders: Vec<Sphere>,
}

/// What the perception stage reads besides the animal that looks: the
/// tuning, the water's visibility V_r, light and temperature, the tank, the
/// rocks, the plankton and the courting pairs.
pub(super) struct PerceptionInputs<'a> {
    pub params: &'a ReefParams,
    pub visibility_m: f32,
    pub env: &'a Environment,
    pub tank: &'a Tank,
    pub obstacles: &'a [Obstacle],
    pub food: &'a [FoodParticle],
    pub courtship: &'a Courtship,
}

/// What one animal perceived.
pub(super) struct Sight {
    /// The percept for its intention generator.
    pub percept: Percept,
    /// Its schooling neighbours.
    pub neighbours: Vec<Neighbour>,
    /// Its distances (in its body lengths) to the predators it fears.
    pub predator_distances: Vec<f32>,
    /// The most frightening predator actually in view, and where it is.
    pub sighted: Option<(u32, Vec3)>,
    /// The courting partner it follows (its pair's other fish, or the one it
    /// courts), if in view, and how it looks.
    pub mate_sighted: Option<(u32, Partner)>,
}

impl Perception {
    /// Takes in how every animal looks now, and which of them swim in a
    /// school (S_k of the predator's prey cost, whatever they intend).
    pub(super) fn look(params: &PerceptionParams, animals: &[ReefAnimal]) -> Self {
        let mut seen: Vec<Seen> = animals.iter().map(Seen::of).collect();
        let schooling: Vec<bool> = (0..seen.len())
            .map(|i| in_a_school(params, &seen, i))
            .collect();
        for (s, schooling) in seen.iter_mut().zip(schooling) {
            s.schooling = schooling;
        }
        let occluders = seen
            .iter()
            .map(|s| fish_occluder(params, s.position_m, if s.alive { s.length_m } else { 0.0 }))
            .collect();
        Self { seen, occluders }
    }

    /// How every animal looked at the start of this step.
    pub(super) fn seen(&self) -> &[Seen] {
        &self.seen
    }

    /// What animal `i` sees: the percept for its intention generator, its
    /// schooling neighbours, and its distances (in its body lengths) to the
    /// predators it fears, and the most frightening predator actually in view.
    pub(super) fn perceive(
        &self,
        i: usize,
        animal: &ReefAnimal,
        inputs: &PerceptionInputs,
    ) -> Sight {
        let seen = &self.seen[..];
        let bodies = &self.occluders[..];
        let me = seen[i];
        let habits = &animal.habits;
        let eye = Eye::new(me.head_m, me.heading, inputs.visibility_m);
        let sees_animal = |j: usize| -> bool {
            let target = bodies[j];
            if !eye.in_view_volume(target) {
                return false;
            }
            let others: Vec<Sphere> = bodies
                .iter()
                .enumerate()
                .filter(|(k, s)| *k != i && *k != j && s.radius_m > 0.0)
                .map(|(_, s)| *s)
                .filter(|s| {
                    s.center_m.distance(me.head_m)
                        < target.center_m.distance(me.head_m) + target.radius_m
                })
                .collect();
            eye.sees(target, &others, inputs.obstacles)
        };
        let mut percept = Percept {
            content: habits.light.content_at(animal.brightness)
                && habits
                    .temperature
                    .content_at(inputs.env.temperature_01_at(me.position_m)),
            ..Default::default()
        };
        // Candidates by distance, nearest first.
        let mut others: Vec<(usize, f32)> = seen
            .iter()
            .enumerate()
            .filter(|(j, s)| *j != i && s.alive)
            .map(|(j, s)| (j, s.position_m.distance(me.head_m)))
            .filter(|(_, d)| *d < inputs.visibility_m + 1.0)
            .collect();
        others.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));

        // Predators (prey and pacifists look out for them).
        let mut predator_distances = Vec::new();
        if habits.kind != FishKind::Predator {
            for &(j, d) in others
                .iter()
                .filter(|(j, _)| seen[*j].kind == FishKind::Predator)
            {
                if sees_animal(j) {
                    let body_lengths = d / me.length_m.max(1e-3);
                    predator_distances.push(body_lengths);
                    let fear =
                        crate::sim::reef::mind::mental_state::fear_of(&habits.mental, body_lengths);
                    percept.predators.push((j as u32, fear));
                }
            }
        }
        // The most frightening predator in view, then one just lost from view,
        // still feared where it was seen.
        let sighted = percept
            .predators
            .iter()
            .max_by(|x, y| x.1.total_cmp(&y.1).then(y.0.cmp(&x.0)))
            .map(|p| p.0);
        if habits.kind != FishKind::Predator {
            match (percept.predators.first(), animal.last_threat) {
                (None, Some((j, at, left)))
                    if left > 0.0 && seen.get(j as usize).is_some_and(|s| s.alive) =>
                {
                    let body_lengths = at.distance(me.head_m) / me.length_m.max(1e-3);
                    predator_distances.push(body_lengths);
                    let fear =
                        crate::sim::reef::mind::mental_state::fear_of(&habits.mental, body_lengths);
                    percept.predators.push((j, fear));
                }
                _ => {}
            }
        }
        // Prey for predators: cost C_k = d_k (1 + β1 S_k + β2 E_k / π).
        if habits.kind == FishKind::Predator {
            let mut candidates: Vec<(usize, f32)> = others
                .iter()
                .filter(|(j, _)| seen[*j].kind == FishKind::Prey)
                .map(|&(j, d)| {
                    let to = (seen[j].position_m - me.head_m).normalize_or(me.heading);
                    let turn = fmath::acos(me.heading.dot(to).clamp(-1.0, 1.0));
                    let schooling = if seen[j].schooling { 1.0 } else { 0.0 };
                    (
                        j,
                        d * (1.0
                            + PREY_BETA_SCHOOL * schooling
                            + PREY_BETA_TURN * turn / std::f32::consts::PI),
                    )
                })
                .collect();
            candidates.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
            // The current target is always checked, then the cheapest few.
            let current = match animal.focus.target {
                Some(Target::Animal(id)) => candidates.iter().position(|c| c.0 == id as usize),
                _ => None,
            };
            // The cheapest three in view (and the current target, if in view).
            for (k, &(j, cost)) in candidates.iter().enumerate() {
                if (percept.prey.len() < 3 || Some(k) == current) && sees_animal(j) {
                    percept.prey.push((j as u32, cost));
                }
            }
        }
        // Food (prey and pacifists): the nearest few seen particles, by the
        // effort of reaching them (see `ReefParams::climb_effort_muscle_body`
        // and `ReefParams::turning_path_weight`).
        if habits.kind != FishKind::Predator {
            let climb_effort = match animal.body {
                ReefBody::Physical(_) => inputs.params.climb_effort_muscle_body,
                ReefBody::Point(_) => 1.0,
            };
            // The muscle body's level path goes round its turning circle.
            let turn_radius_m = match animal.body {
                ReefBody::Physical(_) => inputs.params.body_turn_radius_body_lengths * me.length_m,
                ReefBody::Point(_) => 0.0,
            };
            let path_weight = inputs.params.turning_path_weight;
            let effort = |p: Vec3| {
                let o = p - me.head_m;
                let d = Vec3::new(o.x, 0.0, o.z).length();
                let path = crate::sim::reef::behaviour::level_reach_m(me.heading, o, turn_radius_m);
                fmath::hypot(d + path_weight * (path - d), climb_effort * o.y)
            };
            let mut food: Vec<(u32, f32, f32)> = inputs
                .food
                .iter()
                .map(|f| (f.id, f.position_m.distance(me.head_m), effort(f.position_m)))
                .filter(|(_, d, _)| *d < inputs.visibility_m)
                .collect();
            food.sort_by(|a, b| a.2.total_cmp(&b.2).then(a.0.cmp(&b.0)));
            let current = match animal.focus.target {
                Some(Target::Food(id)) => Some(id),
                _ => None,
            };
            for (k, &(id, d, effort)) in food.iter().enumerate() {
                if k >= 4 && Some(id) != current {
                    continue;
                }
                let Some(f) = inputs.food.iter().find(|f| f.id == id) else {
                    continue;
                };
                let s = Sphere {
                    center_m: f.position_m,
                    radius_m: 0.03,
                };
                let blockers: Vec<Sphere> = bodies
                    .iter()
                    .enumerate()
                    .filter(|(k, b)| {
                        *k != i && b.radius_m > 0.0 && b.center_m.distance(me.head_m) < d
                    })
                    .map(|(_, b)| *b)
                    .collect();
                if eye.sees(s, &blockers, inputs.obstacles) {
                    percept.food.push((id, effort));
                }
            }
        }
        // Partners (pacifists): same species first, then nearer; females
        // prefer bigger males.
        if habits.kind == FishKind::Pacifist {
            let mut mates: Vec<(usize, f32)> = others
                .iter()
                .filter(|(j, _)| {
                    seen[*j].kind == FishKind::Pacifist
                        && seen[*j].sex != habits.sex
                        && inputs
                            .courtship
                            .rejected_by(i)
                            .is_none_or(|f| f as usize != *j)
                })
                .map(|&(j, d)| {
                    let other_species = if seen[j].species == habits.species {
                        0.0
                    } else {
                        20.0
                    };
                    let rank = match habits.sex {
                        Sex::Male => d,
                        Sex::Female => 0.2 * d - 10.0 * seen[j].length_m,
                    };
                    (j, rank + other_species)
                })
                .collect();
            mates.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
            for &(j, rank) in mates.iter().take(4) {
                if sees_animal(j) {
                    percept.mates.push((j as u32, rank));
                }
            }
        }
        // Schoolmates: the seven nearest seen schooling fish of the species.
        let mut neighbours = Vec::new();
        if habits.schools {
            for &(j, _) in others
                .iter()
                .filter(|(j, _)| seen[*j].kind == habits.kind && seen[*j].species == habits.species)
            {
                if neighbours.len() >= 7 {
                    break;
                }
                if eye.in_view_volume(bodies[j]) {
                    neighbours.push(Neighbour {
                        position_m: seen[j].position_m,
                        heading: seen[j].heading,
                        velocity_m_per_s: seen[j].velocity_m_per_s,
                    });
                }
            }
            percept.schoolmates_seen = neighbours.len();
        }
        percept.collision = collision_check(i, animal, seen, &neighbours, inputs);
        // The partner it courts: its pair's other fish, or the one its
        // courting is aimed at.
        let courted = match (inputs.courtship.pair_of(i), animal.focus) {
            (Some(pair), _) => Some(if pair.male as usize == i {
                pair.female
            } else {
                pair.male
            }),
            (None, focus) if focus.intention == Intention::Mate => match focus.target {
                Some(Target::Animal(j)) => Some(j),
                _ => None,
            },
            _ => None,
        };
        let mate_sighted = courted
            .filter(|&j| seen.get(j as usize).is_some_and(|s| s.alive) && sees_animal(j as usize))
            .map(|j| {
                let o = &seen[j as usize];
                (
                    j,
                    Partner {
                        position_m: o.position_m,
                        head_m: o.head_m,
                        heading: o.heading,
                        body_length_m: o.length_m,
                    },
                )
            });
        Sight {
            percept,
            neighbours,
            predator_distances,
            sighted: sighted.map(|j| (j, seen[j as usize].position_m)),
            mate_sighted,
        }
    }
}

/// The most dangerous thing inside animal `i`'s collision-sensitivity box:
/// a box ahead of the head, as wide as the body, `collision_box_ahead`
/// long (halved for a schooling fish in formation, §7.2).
fn collision_check(
    i: usize,
    a: &ReefAnimal,
    seen: &[Seen],
    neighbours: &[Neighbour],
    inputs: &PerceptionInputs,
) -> Option<Target> {
    let me = seen[i];
    // In formation: schooling, or swerving within the school (an avoidance
    // that interrupted schooling).
    let schooling = a.focus.intention == Intention::School
        || a.generator
            .memory
            .is_some_and(|m| m.intention == Intention::School);
    let in_formation = schooling && neighbours.len() >= 2;
    let mut ahead = a.habits.collision_box_ahead_body_lengths * me.length_m;
    if in_formation {
        ahead *= 0.5;
    }
    let half_width = 0.3 * me.length_m;
    // The glass, the sand and the surface.
    let probe = me.head_m + me.heading * ahead;
    if !inputs.tank.contains(probe, 0.3 * me.length_m) {
        return Some(Target::Glass);
    }
    // Rocks.
    let mut best: Option<(f32, Target)> = None;
    for (k, o) in inputs.obstacles.iter().enumerate() {
        let steps = 4;
        for s in 0..=steps {
            let p = me.head_m + me.heading * (ahead * s as f32 / steps as f32);
            let d = o.signed_distance_m(p);
            if d < half_width && best.is_none_or(|b| d < b.0) {
                best = Some((d, Target::Obstacle(k as u32)));
            }
        }
    }
    // Other fish, except the prey a predator is about to swallow and a
    // courting partner (the pair's sensitivity regions are set tightly to
    // their bodies, §7.3).
    let exempt = match a.focus.target {
        Some(Target::Animal(j)) if a.focus.intention == Intention::Eat => Some(j as usize),
        _ => inputs.courtship.pair_of(i).map(|p| {
            if p.male as usize == i {
                p.female as usize
            } else {
                p.male as usize
            }
        }),
    };
    for (j, o) in seen.iter().enumerate() {
        if j == i || !o.alive || Some(j) == exempt {
            continue;
        }
        // Prey do not swerve from the shark here: fear handles it.
        let offset = o.position_m - me.head_m;
        let along = offset.dot(me.heading);
        if along < -0.2 * me.length_m || along > ahead + 0.5 * o.length_m {
            continue;
        }
        let across = (offset - me.heading * along).length();
        if across < half_width + 0.15 * o.length_m {
            let d = offset.length();
            if best.is_none_or(|b| d < b.0) {
                best = Some((d, Target::Animal(j as u32)));
            }
        }
    }
    best.map(|b| b.1)
}

/// What animal `viewer` of `animals` sees on its retina: the other living
/// fish, the plankton and the rocks.
pub(super) fn retina_scene<'a>(
    animals: &[ReefAnimal],
    food: &[FoodParticle],
    obstacles: &'a [Obstacle],
    viewer: usize,
) -> RetinaScene<'a> {
    RetinaScene {
        fish: animals
            .iter()
            .enumerate()
            .filter(|(j, a)| *j != viewer && a.alive)
            .map(|(_, a)| {
                (
                    a.body.position_m(),
                    a.body.heading(),
                    a.body.body_length_m(),
                    hue_rgb(a.hue, a.habits.kind),
                )
            })
            .collect(),
        food_m: food.iter().map(|f| f.position_m).collect(),
        obstacles,
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::common::tank::Tank;
    use crate::sim::reef::perception::*;

    fn eye() -> Eye {
        Eye::new(Vec3::new(0.0, 2.0, 0.0), Vec3::X, 5.0)
    }

    fn ball(x: f32, z: f32) -> Sphere {
        Sphere {
            center_m: Vec3::new(x, 2.0, z),
            radius_m: 0.1,
        }
    }

    #[test]
    fn the_field_of_view_is_300_degrees() {
        let e = eye();
        // 140° off the heading: seen; 160° off: in the blind cone.
        for (deg, seen) in [
            (0.0f32, true),
            (90.0, true),
            (140.0, true),
            (160.0, false),
            (180.0, false),
        ] {
            let a = deg.to_radians();
            let target = ball(3.0 * fmath::cos(a), 3.0 * fmath::sin(a));
            assert_eq!(e.sees(target, &[], &[]), seen, "{deg}°");
        }
    }

    #[test]
    fn objects_beyond_the_radius_are_not_seen() {
        let e = eye();
        assert!(e.sees(ball(4.8, 0.0), &[], &[]));
        assert!(!e.sees(ball(5.5, 0.0), &[], &[]));
    }

    #[test]
    fn a_rock_or_a_fish_in_between_hides_a_target() {
        let e = eye();
        let target = ball(4.0, 0.0);
        let rock = Obstacle::Rock {
            center_m: Vec3::new(2.0, 2.0, 0.0),
            radius_m: 0.5,
        };
        assert!(!e.sees(target, &[], std::slice::from_ref(&rock)));
        let fish = Sphere {
            center_m: Vec3::new(2.0, 2.0, 0.0),
            radius_m: 0.25,
        };
        assert!(!e.sees(target, &[fish], &[]));
        // A rock off to the side does not hide it.
        let aside = Obstacle::Rock {
            center_m: Vec3::new(2.0, 2.0, 2.0),
            radius_m: 0.5,
        };
        assert!(e.sees(target, &[], std::slice::from_ref(&aside)));
        // A target larger than the occluder peeks out around it.
        let big = Sphere {
            center_m: Vec3::new(4.0, 2.0, 0.0),
            radius_m: 1.0,
        };
        assert!(e.sees(big, &[fish], &[]));
    }

    #[test]
    fn the_retina_is_brighter_looking_up_than_down() {
        let env = Environment::new(Tank::default());
        let scene = RetinaScene::default();
        let at = Vec3::new(0.0, 2.0, 0.0);
        let up = Retina::render(&Eye::new(at, Vec3::Y, 8.0), Vec3::X, 24, &scene, &env);
        let down = Retina::render(&Eye::new(at, -Vec3::Y, 8.0), Vec3::X, 24, &scene, &env);
        assert!(
            up.mean_brightness > down.mean_brightness,
            "{} {}",
            up.mean_brightness,
            down.mean_brightness
        );
        assert_eq!(up.pixels.len(), 24 * 24);
        assert!(up.pixels.iter().flatten().all(|c| c.is_finite()));
        assert_eq!(up.to_rgba8().len(), 24 * 24 * 4);
    }

    #[test]
    fn the_retina_shows_a_fish_in_front_in_its_colour() {
        let env = Environment::new(Tank::default());
        let red = [0.9, 0.1, 0.1];
        let scene = RetinaScene {
            fish: vec![(Vec3::new(1.0, 2.0, 0.0), Vec3::Z, 0.5, red)],
            ..Default::default()
        };
        let e = Eye::new(Vec3::new(0.0, 2.0, 0.0), Vec3::X, 8.0);
        let img = Retina::render(&e, Vec3::Y, 33, &scene, &env);
        let centre = img.pixels[16 * 33 + 16];
        assert!(centre[0] > 2.0 * centre[2] && centre[0] > 0.3, "{centre:?}");
    }
}
