//! Triangle meshes built on the CPU once: the animals (fish, its low-poly LOD, shark,
//! stingray), rocks, pillars, the sand floor and the tank frame.
//!
//! Animal meshes share one frame: one body length long, snout towards +x, back up
//! (+y), scaled and oriented per instance by the vertex shader, which also animates
//! them (`vs_fish` beats the tail of fish and sharks, `vs_ray` flaps the stingray's
//! wings; see `scene.wgsl`). The `Material` of each vertex picks the shading. The
//! bodies of the fish and the shark follow the outlines in [`super::profile`], which
//! the skinned muscle bodies (`body_skin`) follow too.
//!
//! Everything here is plain geometry (no GPU types), so it is tested natively: normals
//! are unit length, animals point along +x, rocks are closed.

use bytemuck::{Pod, Zeroable};
use std::f32::consts::TAU;

use glam::{Vec3, vec3};

use super::profile::{self, PlacedProfile, Section, Up};
use crate::sim::common::spare::release_spare;
use crate::sim::{Obstacle, Tank};

/// How the fragment shader colours a surface (the `material` vertex attribute).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum Material {
    /// Lit with the vertex colour (rocks, pillars).
    Plain = 0,
    /// Procedural sand ripples and grain.
    Sand = 1,
    /// Dark anodised aluminium of the tank frame; no caustics.
    Frame = 2,
    /// Fish body: instance colour, countershading, stripes.
    FishBody = 3,
    /// Fish fins: lighter, a little translucent-looking.
    FishFin = 4,
    /// Eye of any animal: near black with a glint.
    FishEye = 5,
    /// Shark skin, body and fins: instance colour on top, a pale belly below a soft
    /// countershading line (by the surface's facing), gill slits, darker fin tips.
    SharkSkin = 6,
    /// Stingray's back and tail: instance colour, mottled, with dark spots (instance
    /// alpha = spot strength).
    RayBack = 7,
    /// Stingray's underside: pale cream.
    RayBelly = 8,
    /// Deformed fish body (`body_skin`): the vertex colour is already countershaded;
    /// dark vertical bars by the pattern strength (colour alpha).
    SkinFish = 9,
    /// Deformed fish fins: lighter than the body, lit through from behind.
    SkinFin = 10,
    /// Deformed shark body: the vertex colour is already countershaded; gill slits.
    SkinShark = 11,
    /// Deformed shark fins: pale where they face down, dark tips by the pattern
    /// strength (colour alpha).
    SkinSharkFin = 12,
}

/// One vertex of a static or fish mesh. 32 bytes.
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C)]
pub struct Vertex {
    pub position: [f32; 3],
    /// A [`Material`]; deformed bodies also pack a highlight level and their skin
    /// coordinates in the upper bits (see `body_skin`).
    pub material: u32,
    pub normal: [f32; 3],
    /// Packed RGBA8 colour (rocks, pillars, deformed bodies); unused for instanced
    /// animals.
    pub color: u32,
}

/// An indexed triangle list.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

/// Packs a linear-ish RGB colour into RGBA8, opaque.
pub fn pack_rgb(rgb: [f32; 3]) -> u32 {
    pack_rgba(rgb, 255)
}

/// Packs a linear-ish RGB colour and an alpha byte into RGBA8.
pub fn pack_rgba(rgb: [f32; 3], alpha: u32) -> u32 {
    let c = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u32;
    c(rgb[0]) | (c(rgb[1]) << 8) | (c(rgb[2]) << 16) | (alpha.min(255) << 24)
}

impl Mesh {
    /// Gives memory back after the mesh shrank a lot (fewer fish than at its
    /// largest): a buffer kept for reuse holds at most four times what the
    /// last frame drew (and at least a small floor), so a tank that once held
    /// 300 muscle fish does not keep their 15 MB of skin once it has 10
    /// (found by the browser soak, issue 35).
    pub fn release_spare(&mut self) {
        release_spare(&mut self.vertices, 4096);
        release_spare(&mut self.indices, 4096);
    }

    fn push(&mut self, position: Vec3, normal: Vec3, material: Material, color: u32) -> u32 {
        self.vertices.push(Vertex {
            position: position.to_array(),
            material: material as u32,
            normal: normal.normalize_or_zero().to_array(),
            color,
        });
        (self.vertices.len() - 1) as u32
    }

    fn triangle(&mut self, a: u32, b: u32, c: u32) {
        self.indices.extend_from_slice(&[a, b, c]);
    }

    /// Appends `other`, re-indexing.
    pub fn append(&mut self, other: &Mesh) {
        let base = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.indices.extend(other.indices.iter().map(|i| i + base));
    }

    /// A flat, double-sided triangle (fins).
    fn fin_triangle(&mut self, a: Vec3, b: Vec3, c: Vec3, material: Material) {
        let normal = (b - a).cross(c - a).normalize_or_zero();
        for n in [normal, -normal] {
            let ia = self.push(a, n, material, 0);
            let ib = self.push(b, n, material, 0);
            let ic = self.push(c, n, material, 0);
            if n == normal {
                self.triangle(ia, ib, ic);
            } else {
                self.triangle(ia, ic, ib);
            }
        }
    }

    /// A box from `min` to `max` with flat faces.
    fn cuboid(&mut self, min: Vec3, max: Vec3, material: Material, color: u32) {
        let corners = |axis: usize, sign: f32| -> [Vec3; 4] {
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            let mut out = [Vec3::ZERO; 4];
            for (k, (su, sv)) in [(0, 0), (1, 0), (1, 1), (0, 1)].into_iter().enumerate() {
                let mut p = Vec3::ZERO;
                p[axis] = if sign > 0.0 { max[axis] } else { min[axis] };
                p[u] = if su == 1 { max[u] } else { min[u] };
                p[v] = if sv == 1 { max[v] } else { min[v] };
                out[k] = p;
            }
            out
        };
        for axis in 0..3 {
            for sign in [-1.0_f32, 1.0] {
                let mut normal = Vec3::ZERO;
                normal[axis] = sign;
                let q = corners(axis, sign);
                let ids: Vec<u32> = q
                    .iter()
                    .map(|&p| self.push(p, normal, material, color))
                    .collect();
                if sign > 0.0 {
                    self.triangle(ids[0], ids[1], ids[2]);
                    self.triangle(ids[0], ids[2], ids[3]);
                } else {
                    self.triangle(ids[0], ids[2], ids[1]);
                    self.triangle(ids[0], ids[3], ids[2]);
                }
            }
        }
    }
}

impl Mesh {
    /// A closed, tube-like body along −x: an apex at `snout`, one ring of `segments`
    /// points at each of `xs` (decreasing: snout to tail), and a fan closing the last
    /// ring. `surface(x, angle)` is a point on the skin; angle 0 is the +z side and
    /// π/2 the top. Normals come from finite differences and point outwards.
    fn loft(
        &mut self,
        snout: Vec3,
        xs: &[f32],
        segments: u32,
        surface: impl Fn(f32, f32) -> Vec3,
        material: Material,
    ) {
        let apex = self.push(snout, Vec3::X, material, 0);
        let mut ring_starts = Vec::with_capacity(xs.len());
        for &x in xs {
            ring_starts.push(self.vertices.len() as u32);
            for s in 0..segments {
                let angle = s as f32 / segments as f32 * TAU;
                let (dx, da) = (0.01, 0.01);
                let along = surface(x - dx, angle) - surface(x + dx, angle);
                let around = surface(x, angle + da) - surface(x, angle - da);
                self.push(surface(x, angle), around.cross(along), material, 0);
            }
        }
        let Some((&first, &last)) = ring_starts.first().zip(ring_starts.last()) else {
            return;
        };
        let seg = segments;
        for s in 0..seg {
            self.triangle(apex, first + (s + 1) % seg, first + s);
        }
        for pair in ring_starts.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            for s in 0..seg {
                let s1 = (s + 1) % seg;
                self.triangle(a + s, a + s1, b + s);
                self.triangle(a + s1, b + s1, b + s);
            }
        }
        let ring = &self.vertices[last as usize..(last + seg) as usize];
        let center = ring.iter().map(|v| Vec3::from(v.position)).sum::<Vec3>() / seg as f32;
        let tail = self.push(center, -Vec3::X, material, 0);
        for s in 0..seg {
            self.triangle(tail, last + s, last + (s + 1) % seg);
        }
    }

    /// An eye: a shallow cone of `ring` points around `center`, bulging by `radius`
    /// along the unit `outward` direction.
    fn eye(&mut self, center: Vec3, outward: Vec3, radius: f32, ring: u32) {
        let outward = outward.normalize_or_zero();
        let (u, v) = outward.any_orthonormal_pair();
        let apex = self.push(center + outward * radius, outward, Material::FishEye, 0);
        let first = self.vertices.len() as u32;
        for k in 0..ring {
            let a = k as f32 / ring as f32 * TAU;
            let offset = (u * a.cos() + v * a.sin()) * radius;
            self.push(
                center + offset,
                offset.normalize_or_zero() + outward * 0.6,
                Material::FishEye,
                0,
            );
        }
        // (u, v, outward) is right-handed, so (apex, a, b) faces outwards.
        for k in 0..ring {
            self.triangle(apex, first + k, first + (k + 1) % ring);
        }
    }
}

/// Where every animal mesh's snout is (x, body lengths).
const SNOUT_X: f32 = 0.5;

/// The fish's body: [`profile::FISH`], one body length from the snout to the tail
/// root at x = −0.5, where the tail fin begins.
pub(super) const FISH_BODY: PlacedProfile = PlacedProfile {
    profile: profile::FISH,
    snout_x: SNOUT_X,
    tail_root_x: -0.5,
    up: Up::Y,
};

/// Ring positions from the snout (+0.5) to the tail root (−0.5), closer together at
/// the snout where the profile curves most.
fn fish_rings(rings: usize) -> Vec<f32> {
    (1..=rings)
        .map(|i| SNOUT_X - FISH_BODY.length() * (i as f32 / rings as f32).powf(1.15))
        .collect()
}

/// The forked caudal fin of both fish meshes, in the vertical plane.
fn fish_tail_fin(mesh: &mut Mesh, with_notch: bool) {
    let root = -0.5 + 0.03;
    for (tip, notch) in [
        (vec3(-0.74, 0.17, 0.0), vec3(-0.62, 0.02, 0.0)),
        (vec3(-0.74, -0.17, 0.0), vec3(-0.62, -0.02, 0.0)),
    ] {
        let root_edge = vec3(root, tip.y.signum() * 0.035, 0.0);
        let base = vec3(root, 0.0, 0.0);
        if with_notch {
            mesh.fin_triangle(base, root_edge, tip, Material::FishFin);
            mesh.fin_triangle(base, tip, notch, Material::FishFin);
        } else {
            mesh.fin_triangle(vec3(root, 0.0, 0.0), root_edge, tip, Material::FishFin);
        }
    }
}

/// The dorsal fin of both fish meshes, sized by the height of the back at x = 0.05.
fn fish_dorsal_fin(mesh: &mut Mesh) {
    let back = FISH_BODY.top(0.05);
    mesh.fin_triangle(
        vec3(0.12, back - 0.01, 0.0),
        vec3(-0.2, back * 0.8 - 0.012, 0.0),
        vec3(-0.12, back + 0.12, 0.0),
        Material::FishFin,
    );
}

/// The fish mesh, one body length long, snout at +x = 0.5, tail fin to x ≈ −0.74,
/// back up (+y). The vertex shader bends it with the tail beat.
pub fn fish() -> Mesh {
    let mut mesh = Mesh::default();
    mesh.loft(
        FISH_BODY.snout(),
        &fish_rings(18),
        14,
        |x, angle| FISH_BODY.surface(x, angle),
        Material::FishBody,
    );
    fish_tail_fin(&mut mesh, true);
    fish_dorsal_fin(&mut mesh);
    // Anal fin.
    mesh.fin_triangle(
        vec3(-0.12, -0.09, 0.0),
        vec3(-0.3, -0.05, 0.0),
        vec3(-0.27, -0.14, 0.0),
        Material::FishFin,
    );
    // Pectoral fins, angled out and back from behind the gills.
    for side in [-1.0_f32, 1.0] {
        let w = FISH_BODY.section(0.22).half_width;
        mesh.fin_triangle(
            vec3(0.24, -0.05, side * w * 0.9),
            vec3(0.16, -0.06, side * w * 0.9),
            vec3(0.08, -0.1, side * (w + 0.09)),
            Material::FishFin,
        );
    }
    // Eyes: small domes on each side of the head.
    for side in [-1.0_f32, 1.0] {
        let s = FISH_BODY.section(0.38);
        let center = vec3(0.38, s.half_height() * 0.35, side * s.half_width * 0.92);
        mesh.eye(center, vec3(0.0, 0.0, side), 0.028, 8);
    }
    mesh
}

/// The fish seen from afar: the same silhouette as [`fish`] from 5 rings of 8
/// points, the tail fin without its notch, the dorsal fin and flat eyes (a dark dot
/// is still visible on a fish 30 pixels long); about a sixth of the triangles.
pub fn fish_lod() -> Mesh {
    let mut mesh = Mesh::default();
    mesh.loft(
        FISH_BODY.snout(),
        &fish_rings(5),
        8,
        |x, angle| FISH_BODY.surface(x, angle),
        Material::FishBody,
    );
    fish_tail_fin(&mut mesh, false);
    fish_dorsal_fin(&mut mesh);
    for side in [-1.0_f32, 1.0] {
        let s = FISH_BODY.section(0.38);
        let center = vec3(0.38, s.half_height() * 0.35, side * s.half_width * 0.92);
        mesh.eye(center, vec3(0.0, 0.0, side), 0.03, 3);
    }
    mesh
}

/// Where the shark's body ends and its tail fin begins (x, body lengths).
const SHARK_TAIL_ROOT_X: f32 = -0.3;

/// The shark's body: [`profile::SHARK`], 0.8 body lengths from the snout to the
/// tail root.
pub(super) const SHARK_BODY: PlacedProfile = PlacedProfile {
    profile: profile::SHARK,
    snout_x: SNOUT_X,
    tail_root_x: SHARK_TAIL_ROOT_X,
    up: Up::Y,
};

/// A shark (requiem-shark shape), one body length from the snout at +x = 0.5 to the
/// tip of the upper tail lobe at −0.5, back up: a grey torpedo with a pointed snout,
/// a tall triangular first dorsal fin, a small second dorsal and anal fin, big swept
/// pectoral fins, pelvic fins and a heterocercal tail whose upper lobe is twice as
/// long as the lower. Animated like a fish (`vs_fish`); `SharkSkin` throughout.
pub fn shark() -> Mesh {
    const RINGS: usize = 20;
    const SEGMENTS: u32 = 14;
    let skin = Material::SharkSkin;
    let mut mesh = Mesh::default();
    let xs: Vec<f32> = (1..=RINGS)
        .map(|i| SNOUT_X - SHARK_BODY.length() * (i as f32 / RINGS as f32).powf(1.2))
        .collect();
    let surface = |x, angle| SHARK_BODY.surface(x, angle);
    mesh.loft(SHARK_BODY.snout(), &xs, SEGMENTS, surface, skin);

    // First dorsal fin: a tall triangle whose apex leans back, and a free rear tip.
    let base = |x: f32| vec3(x, SHARK_BODY.top(x) - 0.01, 0.0);
    let apex = vec3(-0.07, SHARK_BODY.top(0.02) + 0.14, 0.0);
    mesh.fin_triangle(base(0.13), base(-0.04), apex, skin);
    mesh.fin_triangle(
        base(-0.04),
        vec3(-0.08, SHARK_BODY.top(-0.08) + 0.012, 0.0),
        apex,
        skin,
    );
    // Second dorsal and anal fins, small, near the tail.
    mesh.fin_triangle(
        base(-0.17),
        base(-0.23),
        vec3(-0.245, SHARK_BODY.top(-0.2) + 0.04, 0.0),
        skin,
    );
    let belly = |x: f32| vec3(x, SHARK_BODY.bottom(x) + 0.01, 0.0);
    mesh.fin_triangle(
        belly(-0.23),
        belly(-0.18),
        belly(-0.25) - vec3(0.0, 0.035, 0.0),
        skin,
    );
    for side in [-1.0_f32, 1.0] {
        // Pectoral fins: long, swept back and angled down, behind the gills.
        let s = SHARK_BODY.section(0.16);
        let root_y = s.axis - 0.04;
        mesh.fin_triangle(
            vec3(0.21, root_y, side * s.half_width * 0.75),
            vec3(0.09, root_y, side * s.half_width * 0.75),
            vec3(0.0, root_y - 0.075, side * 0.22),
            skin,
        );
        // Pelvic fins.
        let s = SHARK_BODY.section(-0.12);
        mesh.fin_triangle(
            vec3(-0.09, s.axis - 0.03, side * s.half_width * 0.6),
            vec3(-0.16, s.axis - 0.025, side * s.half_width * 0.5),
            vec3(-0.17, s.axis - 0.06, side * (s.half_width + 0.04)),
            skin,
        );
        // Eyes, on the sides of the head.
        let s = SHARK_BODY.section(0.37);
        mesh.eye(
            vec3(0.37, s.axis + s.back * 0.3, side * s.half_width * 0.92),
            vec3(0.15, 0.2, side),
            0.013,
            8,
        );
    }
    // Heterocercal tail: a long, narrow upper lobe following the spine up and back,
    // a short lower lobe, fanned from the middle of the caudal peduncle.
    let Section {
        axis: axis_y,
        back: h,
        ..
    } = SHARK_BODY.section(SHARK_TAIL_ROOT_X);
    let root = vec3(SHARK_TAIL_ROOT_X + 0.02, axis_y, 0.0);
    let outline = [
        vec3(SHARK_TAIL_ROOT_X + 0.02, axis_y + h + 0.01, 0.0),
        vec3(-0.5, axis_y + 0.16, 0.0),
        vec3(-0.47, axis_y + 0.125, 0.0),
        vec3(-0.38, axis_y + 0.01, 0.0),
        vec3(-0.415, axis_y - 0.095, 0.0),
        vec3(SHARK_TAIL_ROOT_X - 0.02, axis_y - h - 0.01, 0.0),
    ];
    for pair in outline.windows(2) {
        mesh.fin_triangle(root, pair[0], pair[1], skin);
    }
    mesh
}

/// Half length of the stingray's disc in front of and behind its centre, its half
/// width, and where its centre is (x, body lengths).
const RAY_DISC_FRONT: f32 = 0.28;
const RAY_DISC_BACK: f32 = 0.24;
const RAY_DISC_HALF_WIDTH: f32 = 0.37;
const RAY_DISC_CENTER_X: f32 = 0.5 - RAY_DISC_FRONT;

/// How far the disc reaches from its centre in the direction `angle` (0 = forward,
/// towards +x; π/2 = +z): a rhombus with rounded corners (a superellipse of
/// exponent 1.5), longer in front than behind.
fn ray_disc_radius(angle: f32) -> f32 {
    let (s, c) = angle.sin_cos();
    let a = if c >= 0.0 {
        RAY_DISC_FRONT
    } else {
        RAY_DISC_BACK
    };
    const P: f32 = 1.5;
    ((c.abs() / a).powf(P) + (s.abs() / RAY_DISC_HALF_WIDTH).powf(P)).powf(-1.0 / P)
}

/// Height of the stingray's back above the disc plane at `(x, z)`, where `s` ∈ [0, 1]
/// is how far out on the disc the point is (0 centre, 1 rim): a raised body along the
/// midline, thin wings.
fn ray_back_height(x: f32, z: f32, s: f32) -> f32 {
    let trunk = (-((x - RAY_DISC_CENTER_X - 0.02) / 0.2).powi(2) - (z / 0.1).powi(2)).exp();
    (0.055 * trunk + 0.012 * (1.0 - s)) * (1.0 - s.powi(4))
}

/// Depth of the stingray's underside below the disc plane (a flatter belly).
fn ray_belly_depth(x: f32, z: f32, s: f32) -> f32 {
    0.4 * ray_back_height(x, z, s)
}

/// A stingray, one body length from the snout at +x = 0.5 to the tip of its tail at
/// −0.5: a flat, rounded-rhombic disc 0.74 wide and 0.52 long with a raised body
/// along the midline and two small raised eyes, and a long, thin whip of a tail.
/// `RayBack` above, `RayBelly` below. `vs_ray` makes the wings ripple: a wave running
/// from front to back whose height grows towards the wing tips, and sways the tail.
pub fn stingray() -> Mesh {
    const RINGS: u32 = 9;
    const SEGMENTS: u32 = 36;
    let mut mesh = Mesh::default();
    let point = |s: f32, angle: f32| {
        let r = ray_disc_radius(angle) * s;
        (RAY_DISC_CENTER_X + r * angle.cos(), r * angle.sin())
    };
    // The top (sign +1) and the underside (sign −1), each a polar grid over the disc
    // meeting at the rim. Normals from the gradient of the height field.
    for (sign, material) in [(1.0_f32, Material::RayBack), (-1.0, Material::RayBelly)] {
        let height = |x: f32, z: f32, s: f32| {
            if sign > 0.0 {
                ray_back_height(x, z, s)
            } else {
                -ray_belly_depth(x, z, s)
            }
        };
        let vertex = |mesh: &mut Mesh, s: f32, angle: f32| {
            let (x, z) = point(s, angle);
            let e = 0.004;
            // s varies with the point; the radial parameter of the neighbours follows.
            let s_at = |x: f32, z: f32| {
                let d = vec3(x - RAY_DISC_CENTER_X, 0.0, z);
                let a = d.z.atan2(d.x);
                (d.length() / ray_disc_radius(a)).min(1.0)
            };
            let dh_dx =
                (height(x + e, z, s_at(x + e, z)) - height(x - e, z, s_at(x - e, z))) / (2.0 * e);
            let dh_dz =
                (height(x, z + e, s_at(x, z + e)) - height(x, z - e, s_at(x, z - e))) / (2.0 * e);
            let normal = vec3(-dh_dx, 1.0, -dh_dz) * sign;
            mesh.push(vec3(x, height(x, z, s), z), normal, material, 0)
        };
        let center = vertex(&mut mesh, 0.0, 0.0);
        let first = mesh.vertices.len() as u32;
        for ring in 1..=RINGS {
            let s = ring as f32 / RINGS as f32;
            for k in 0..SEGMENTS {
                vertex(&mut mesh, s, k as f32 / SEGMENTS as f32 * TAU);
            }
        }
        // Angle runs from +x towards +z, which is clockwise seen from above: the top
        // is wound (centre, k + 1, k), the underside the other way.
        let wind = |mesh: &mut Mesh, a: u32, b: u32, c: u32| {
            if sign > 0.0 {
                mesh.triangle(a, c, b);
            } else {
                mesh.triangle(a, b, c);
            }
        };
        for k in 0..SEGMENTS {
            wind(&mut mesh, center, first + k, first + (k + 1) % SEGMENTS);
        }
        for ring in 0..RINGS - 1 {
            let (a, b) = (first + ring * SEGMENTS, first + (ring + 1) * SEGMENTS);
            for k in 0..SEGMENTS {
                let k1 = (k + 1) % SEGMENTS;
                wind(&mut mesh, a + k, b + k, a + k1);
                wind(&mut mesh, a + k1, b + k, b + k1);
            }
        }
    }
    // Eyes: small domes on the raised head, looking up and out.
    for side in [-1.0_f32, 1.0] {
        let (x, z) = (0.37, side * 0.055);
        let s = (x - RAY_DISC_CENTER_X) / RAY_DISC_FRONT;
        let center = vec3(x, ray_back_height(x, z, s) - 0.004, z);
        mesh.eye(center, vec3(0.1, 1.0, side * 0.7), 0.016, 8);
    }
    // The tail: a thin whip from behind the disc, tapering to a point.
    let root_x = RAY_DISC_CENTER_X - RAY_DISC_BACK + 0.04;
    let xs: Vec<f32> = (1..=10)
        .map(|i| root_x - (root_x + 0.5) * i as f32 / 10.0)
        .collect();
    let tail = |x: f32, angle: f32| {
        let t = ((root_x - x) / (root_x + 0.5)).clamp(0.0, 1.0);
        let r = 0.022 * (1.0 - t).powf(1.3) + 0.002;
        vec3(x, 0.004 + r * angle.sin(), r * angle.cos())
    };
    mesh.loft(
        vec3(root_x + 0.03, 0.004, 0.0),
        &xs,
        6,
        tail,
        Material::RayBack,
    );
    mesh
}

/// A lumpy boulder: an icosphere displaced by a smooth pseudo-random field, so each
/// rock (by `seed`) looks different. Vertices are within ±16 % of `radius`.
pub fn rock(center: Vec3, radius: f32, seed: u32, color: [f32; 3]) -> Mesh {
    let (positions, triangles) = icosphere(3);
    let phase = seed as f32 * 1.618;
    let bump = |d: Vec3| -> f32 {
        let a = (d.x * 3.1 + phase).sin() * (d.y * 2.7 + phase * 0.7).cos();
        let b = (d.z * 4.3 - phase * 1.3).sin() * (d.x * 1.9 + d.y * 2.3).cos();
        let c = (d.y * 7.0 + d.z * 5.0 + phase).sin();
        1.0 + 0.09 * a + 0.05 * b + 0.02 * c
    };
    let mut mesh = Mesh::default();
    let displaced: Vec<Vec3> = positions.iter().map(|&d| d * bump(d)).collect();
    // Flat-ish shading per face reads as rock.
    for [a, b, c] in triangles {
        let (pa, pb, pc) = (displaced[a], displaced[b], displaced[c]);
        let face = (pb - pa).cross(pc - pa).normalize_or_zero();
        let shade = 0.85 + 0.15 * ((pa.y + pb.y + pc.y) / 3.0);
        let tint = pack_rgb([color[0] * shade, color[1] * shade, color[2] * shade]);
        let ids: Vec<u32> = [(a, pa), (b, pb), (c, pc)]
            .iter()
            .map(|&(i, p)| {
                let smooth = positions[i];
                let normal = (face * 0.8 + smooth * 0.2).normalize_or_zero();
                mesh.push(center + p * radius, normal, Material::Plain, tint)
            })
            .collect();
        mesh.triangle(ids[0], ids[1], ids[2]);
    }
    mesh
}

/// A vertical prism (reef ledge) over a convex footprint of (x, z) corners, flat
/// faces, from `base_y` up by `height`.
pub fn prism(footprint: &[glam::Vec2], base_y: f32, height: f32, color: [f32; 3]) -> Mesh {
    let mut mesh = Mesh::default();
    let tint = pack_rgb(color);
    let mut corners: Vec<glam::Vec2> = footprint.to_vec();
    if crate::sim::common::obstacle::signed_area_m2(&corners) < 0.0 {
        corners.reverse();
    }
    let n = corners.len();
    let at = |c: glam::Vec2, y: f32| vec3(c.x, y, c.y);
    for i in 0..n {
        let (a, b) = (corners[i], corners[(i + 1) % n]);
        let edge = b - a;
        let normal = vec3(edge.y, 0.0, -edge.x);
        let ids = [
            mesh.push(at(a, base_y), normal, Material::Plain, tint),
            mesh.push(at(a, base_y + height), normal, Material::Plain, tint),
            mesh.push(at(b, base_y), normal, Material::Plain, tint),
            mesh.push(at(b, base_y + height), normal, Material::Plain, tint),
        ];
        mesh.triangle(ids[0], ids[1], ids[2]);
        mesh.triangle(ids[2], ids[1], ids[3]);
    }
    let top: Vec<u32> = corners
        .iter()
        .map(|&c| mesh.push(at(c, base_y + height), Vec3::Y, Material::Plain, tint))
        .collect();
    for i in 1..n.saturating_sub(1) {
        mesh.triangle(top[0], top[i + 1], top[i]);
    }
    mesh
}

/// A vertical pillar (coral column) on the floor, with a rounded cap.
pub fn pillar(base_center: Vec3, radius: f32, height: f32, color: [f32; 3]) -> Mesh {
    const SEGMENTS: u32 = 20;
    const ROWS: u32 = 8;
    let mut mesh = Mesh::default();
    let tint = pack_rgb(color);
    let groove = |a: f32| 1.0 + 0.05 * (a * 7.0).sin();
    for row in 0..=ROWS {
        let y = height * row as f32 / ROWS as f32;
        for s in 0..SEGMENTS {
            let a = s as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
            let r = radius * groove(a);
            let p = base_center + vec3(a.cos() * r, y, a.sin() * r);
            mesh.push(p, vec3(a.cos(), 0.0, a.sin()), Material::Plain, tint);
        }
    }
    for row in 0..ROWS {
        for s in 0..SEGMENTS {
            let s1 = (s + 1) % SEGMENTS;
            let a = row * SEGMENTS;
            let b = (row + 1) * SEGMENTS;
            mesh.triangle(a + s, b + s, a + s1);
            mesh.triangle(a + s1, b + s, b + s1);
        }
    }
    // Cap: a shallow dome.
    let top = base_center + vec3(0.0, height, 0.0);
    let apex = mesh.push(
        top + vec3(0.0, radius * 0.35, 0.0),
        Vec3::Y,
        Material::Plain,
        tint,
    );
    let rim = ROWS * SEGMENTS;
    for s in 0..SEGMENTS {
        mesh.triangle(apex, rim + (s + 1) % SEGMENTS, rim + s);
    }
    mesh
}

/// The sand floor: a grid over the tank's footprint, gently undulating, with the
/// `Sand` material (the shader adds ripples and caustics).
pub fn sand_floor(tank: &Tank) -> Mesh {
    const CELLS: u32 = 48;
    let mut mesh = Mesh::default();
    let size = tank.size_m();
    let height = |x: f32, z: f32| 0.03 * (x * 0.9).sin() * (z * 1.3).cos() - 0.02;
    for j in 0..=CELLS {
        for i in 0..=CELLS {
            let x = tank.min_m.x + size.x * i as f32 / CELLS as f32;
            let z = tank.min_m.z + size.z * j as f32 / CELLS as f32;
            let e = 0.05;
            let normal = vec3(
                height(x - e, z) - height(x + e, z),
                2.0 * e,
                height(x, z - e) - height(x, z + e),
            );
            mesh.push(vec3(x, height(x, z), z), normal, Material::Sand, 0);
        }
    }
    let row = CELLS + 1;
    for j in 0..CELLS {
        for i in 0..CELLS {
            let a = j * row + i;
            mesh.triangle(a, a + row, a + 1);
            mesh.triangle(a + 1, a + row, a + row + 1);
        }
    }
    mesh
}

/// The aquarium's frame: the twelve edges of the tank as thin dark beams, plus a
/// plinth under the floor.
pub fn tank_frame(tank: &Tank) -> Mesh {
    let mut mesh = Mesh::default();
    let color = pack_rgb([0.08, 0.09, 0.1]);
    let t = 0.06;
    let (lo, hi) = (tank.min_m - Vec3::splat(t), tank.max_m + Vec3::splat(t));
    let (a, b) = (tank.min_m, tank.max_m);
    for &y in &[lo.y, b.y] {
        let (y0, y1) = (y, y + t);
        mesh.cuboid(
            vec3(lo.x, y0, lo.z),
            vec3(hi.x, y1, a.z),
            Material::Frame,
            color,
        );
        mesh.cuboid(
            vec3(lo.x, y0, b.z),
            vec3(hi.x, y1, hi.z),
            Material::Frame,
            color,
        );
        mesh.cuboid(
            vec3(lo.x, y0, a.z),
            vec3(a.x, y1, b.z),
            Material::Frame,
            color,
        );
        mesh.cuboid(
            vec3(b.x, y0, a.z),
            vec3(hi.x, y1, b.z),
            Material::Frame,
            color,
        );
    }
    for &(x0, x1) in &[(lo.x, a.x), (b.x, hi.x)] {
        for &(z0, z1) in &[(lo.z, a.z), (b.z, hi.z)] {
            mesh.cuboid(
                vec3(x0, lo.y, z0),
                vec3(x1, hi.y, z1),
                Material::Frame,
                color,
            );
        }
    }
    // Plinth (the cabinet the tank stands on).
    mesh.cuboid(
        vec3(lo.x - 0.1, lo.y - 0.6, lo.z - 0.1),
        vec3(hi.x + 0.1, lo.y, hi.z + 0.1),
        Material::Frame,
        pack_rgb([0.16, 0.12, 0.09]),
    );
    mesh
}

/// Colour of plankton particles (linear RGB): pale gold, easy to spot.
pub const FOOD_RGB: [f32; 3] = [0.98, 0.88, 0.45];
/// Colour of the learning lab's buoys (linear RGB): signal orange.
pub const BUOY_RGB: [f32; 3] = [1.0, 0.45, 0.1];
/// Colour of seaweed (linear RGB).
pub const SEAWEED_RGB: [f32; 3] = [0.16, 0.5, 0.2];

/// Appends one small octahedron of radius `radius_m` per particle (plankton),
/// lit with the vertex colour.
pub fn append_particles(mesh: &mut Mesh, positions_m: &[Vec3], radius_m: f32, rgb: [f32; 3]) {
    let color = pack_rgb(rgb);
    let axes = [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z];
    // The eight faces as (x, y, z) sign choices, wound outwards.
    let faces = [
        (0, 2, 4),
        (2, 1, 4),
        (1, 3, 4),
        (3, 0, 4),
        (2, 0, 5),
        (1, 2, 5),
        (3, 1, 5),
        (0, 3, 5),
    ];
    for &p in positions_m {
        if !p.is_finite() {
            continue;
        }
        for &(a, b, c) in &faces {
            let normal = (axes[a] + axes[b] + axes[c]).normalize_or_zero();
            let ia = mesh.push(p + axes[a] * radius_m, normal, Material::Plain, color);
            let ib = mesh.push(p + axes[b] * radius_m, normal, Material::Plain, color);
            let ic = mesh.push(p + axes[c] * radius_m, normal, Material::Plain, color);
            mesh.triangle(ia, ib, ic);
        }
    }
}

/// Appends a double-sided ribbon `width_m` wide along `spine_m` (a seaweed
/// strand, root first), narrowing to half its width at the tip, facing
/// `across` (horizontal, unit).
pub fn append_ribbon(mesh: &mut Mesh, spine_m: &[Vec3], width_m: f32, across: Vec3, rgb: [f32; 3]) {
    if spine_m.len() < 2 || !spine_m.iter().all(|p| p.is_finite()) {
        return;
    }
    let n = spine_m.len();
    for side in [1.0f32, -1.0] {
        let base = mesh.vertices.len() as u32;
        for (k, &p) in spine_m.iter().enumerate() {
            let along =
                (spine_m[(k + 1).min(n - 1)] - spine_m[k.saturating_sub(1)]).normalize_or(Vec3::Y);
            let normal = along.cross(across).normalize_or(Vec3::Z) * side;
            let half = 0.5 * width_m * (1.0 - 0.5 * k as f32 / (n - 1) as f32);
            // Darker at the root, lighter towards the sunlit tip.
            let t = k as f32 / (n - 1) as f32;
            let color = pack_rgb(rgb.map(|c| c * (0.7 + 0.5 * t)));
            mesh.push(p - across * half, normal, Material::Plain, color);
            mesh.push(p + across * half, normal, Material::Plain, color);
        }
        for k in 0..(n as u32 - 1) {
            let (a, b, c, d) = (
                base + 2 * k,
                base + 2 * k + 1,
                base + 2 * k + 2,
                base + 2 * k + 3,
            );
            if side > 0.0 {
                mesh.triangle(a, b, d);
                mesh.triangle(a, d, c);
            } else {
                mesh.triangle(a, d, b);
                mesh.triangle(a, c, d);
            }
        }
    }
}

/// Rocks and pillars for a world's obstacles. `seed` varies the rock shapes.
pub fn obstacles(obstacles: &[Obstacle], seed: u64) -> Mesh {
    let mut mesh = Mesh::default();
    for (i, obstacle) in obstacles.iter().enumerate() {
        let k = i as u32 + (seed as u32).wrapping_mul(7);
        let warm = (k % 3) as f32 * 0.04;
        match obstacle {
            &Obstacle::Rock { center_m, radius_m } => mesh.append(&rock(
                center_m,
                radius_m,
                k,
                [0.42 + warm, 0.40 + warm * 0.5, 0.37],
            )),
            &Obstacle::Cylinder {
                base_center_m,
                radius_m,
                height_m,
            } => mesh.append(&pillar(
                base_center_m,
                radius_m,
                height_m,
                [0.78 + warm, 0.52, 0.44 - warm],
            )),
            Obstacle::Polygon {
                footprint_m,
                base_y_m,
                height_m,
            } => mesh.append(&prism(
                footprint_m,
                *base_y_m,
                *height_m,
                [0.55 + warm, 0.47, 0.40],
            )),
        }
    }
    mesh
}

/// A unit icosphere: positions on the sphere and triangles.
fn icosphere(subdivisions: u32) -> (Vec<Vec3>, Vec<[usize; 3]>) {
    let t = (1.0 + 5.0_f32.sqrt()) / 2.0;
    let mut positions: Vec<Vec3> = [
        (-1.0, t, 0.0),
        (1.0, t, 0.0),
        (-1.0, -t, 0.0),
        (1.0, -t, 0.0),
        (0.0, -1.0, t),
        (0.0, 1.0, t),
        (0.0, -1.0, -t),
        (0.0, 1.0, -t),
        (t, 0.0, -1.0),
        (t, 0.0, 1.0),
        (-t, 0.0, -1.0),
        (-t, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| vec3(x, y, z).normalize_or_zero())
    .collect();
    let mut triangles: Vec<[usize; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut midpoints = std::collections::HashMap::new();
        let mut midpoint = |a: usize, b: usize, positions: &mut Vec<Vec3>| -> usize {
            let key = (a.min(b), a.max(b));
            *midpoints.entry(key).or_insert_with(|| {
                positions.push(((positions[a] + positions[b]) * 0.5).normalize_or_zero());
                positions.len() - 1
            })
        };
        let mut next = Vec::with_capacity(triangles.len() * 4);
        for [a, b, c] in triangles {
            let ab = midpoint(a, b, &mut positions);
            let bc = midpoint(b, c, &mut positions);
            let ca = midpoint(c, a, &mut positions);
            next.extend_from_slice(&[[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        triangles = next;
    }
    (positions, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mesh_gives_back_what_many_fish_needed_once_few_remain() {
        let vertex = Vertex {
            position: [0.0; 3],
            material: 0,
            normal: [0.0, 1.0, 0.0],
            color: 0,
        };
        let mut mesh = Mesh::default();
        // 300 fish's skin, then 10 fish's, frame after frame.
        mesh.vertices.resize(300_000, vertex);
        mesh.indices.resize(900_000, 0);
        mesh.release_spare();
        assert!(mesh.vertices.capacity() >= 300_000, "kept while in use");
        let full = mesh.vertices.capacity();
        mesh.vertices.clear();
        mesh.indices.clear();
        mesh.vertices.resize(10_000, vertex);
        mesh.indices.resize(30_000, 0);
        mesh.release_spare();
        assert!(
            mesh.vertices.capacity() <= 20_000,
            "{}",
            mesh.vertices.capacity()
        );
        assert!(
            mesh.indices.capacity() <= 60_000,
            "{}",
            mesh.indices.capacity()
        );
        // A steady mesh keeps its buffer: no shrinking and regrowing every frame.
        let steady = mesh.vertices.capacity();
        for _ in 0..3 {
            mesh.vertices.clear();
            mesh.vertices.resize(10_000, vertex);
            mesh.release_spare();
            assert_eq!(mesh.vertices.capacity(), steady);
        }
        assert!(full > steady);
    }

    fn check_normals_and_indices(mesh: &Mesh) {
        assert!(!mesh.indices.is_empty());
        assert_eq!(mesh.indices.len() % 3, 0);
        for &i in &mesh.indices {
            assert!((i as usize) < mesh.vertices.len());
        }
        for v in &mesh.vertices {
            let n = Vec3::from(v.normal);
            assert!((n.length() - 1.0).abs() < 1e-3, "normal {n}");
            assert!(Vec3::from(v.position).is_finite());
        }
    }

    /// Well-formed, and every triangle is wound to face the way its vertex normals
    /// point (back-face culling keeps the outside).
    fn check_well_formed(mesh: &Mesh) {
        check_normals_and_indices(mesh);
        for tri in mesh.indices.chunks_exact(3) {
            let v = |k: usize| &mesh.vertices[tri[k] as usize];
            let p = |k: usize| Vec3::from(v(k).position);
            let face = (p(1) - p(0)).cross(p(2) - p(0));
            if face.length() < 1e-7 {
                continue;
            }
            let normals: Vec3 = (0..3).map(|k| Vec3::from(v(k).normal)).sum();
            assert!(
                face.dot(normals) > 0.0,
                "triangle at {} faces against its normals",
                p(0)
            );
        }
    }

    fn bounds(mesh: &Mesh) -> (Vec3, Vec3) {
        mesh.vertices.iter().fold(
            (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
            |(lo, hi), v| (lo.min(v.position.into()), hi.max(v.position.into())),
        )
    }

    /// Mean position of the vertices of `material`.
    fn centroid(mesh: &Mesh, material: Material) -> Vec3 {
        let points: Vec<Vec3> = mesh
            .vertices
            .iter()
            .filter(|v| v.material == material as u32)
            .map(|v| Vec3::from(v.position))
            .collect();
        assert!(!points.is_empty(), "no {material:?} vertices");
        points.iter().sum::<Vec3>() / points.len() as f32
    }

    fn triangles(mesh: &Mesh) -> usize {
        mesh.indices.len() / 3
    }

    #[test]
    fn fish_is_one_body_length_with_a_tail_fin_and_points_along_x() {
        let mesh = fish();
        check_normals_and_indices(&mesh);
        let xs = mesh.vertices.iter().map(|v| v.position[0]);
        let (min_x, max_x) = xs.fold((f32::MAX, f32::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)));
        assert!((max_x - 0.5).abs() < 1e-3, "snout at +0.5: {max_x}");
        assert!(min_x < -0.7, "tail fin reaches back: {min_x}");
        let body_height = mesh
            .vertices
            .iter()
            .filter(|v| v.material == Material::FishBody as u32)
            .map(|v| v.position[1].abs())
            .fold(0.0_f32, f32::max);
        let body_width = mesh
            .vertices
            .iter()
            .filter(|v| v.material == Material::FishBody as u32)
            .map(|v| v.position[2].abs())
            .fold(0.0_f32, f32::max);
        assert!(body_width < body_height, "a fish is taller than it is wide");
        assert!(
            mesh.vertices
                .iter()
                .any(|v| v.material == Material::FishEye as u32)
        );
        // Body normals point outwards: away from the body axis.
        for v in mesh
            .vertices
            .iter()
            .filter(|v| v.material == Material::FishBody as u32)
        {
            let p = Vec3::from(v.position);
            let radial = vec3(0.0, p.y + 0.01, p.z);
            if radial.length() > 0.02 {
                assert!(
                    Vec3::from(v.normal).dot(radial) > 0.0,
                    "inward normal at {p}"
                );
            }
        }
    }

    #[test]
    fn animal_meshes_are_well_formed() {
        for (name, mesh) in [
            ("fish", fish()),
            ("fish LOD", fish_lod()),
            ("shark", shark()),
            ("stingray", stingray()),
        ] {
            println!("{name}: {} triangles", triangles(&mesh));
            check_well_formed(&mesh);
        }
    }

    #[test]
    fn the_far_fish_has_under_a_quarter_of_the_triangles_and_the_same_outline() {
        let (near, far) = (fish(), fish_lod());
        check_well_formed(&far);
        assert!(
            4 * triangles(&far) < triangles(&near),
            "{} vs {}",
            triangles(&far),
            triangles(&near)
        );
        let ((near_lo, near_hi), (far_lo, far_hi)) = (bounds(&near), bounds(&far));
        assert!((near_hi.x - far_hi.x).abs() < 1e-3, "same snout");
        assert!((near_lo.x - far_lo.x).abs() < 1e-3, "same tail");
        assert!(
            (near_hi.y - far_hi.y).abs() < 0.02,
            "same dorsal fin height"
        );
    }

    #[test]
    fn shark_is_a_long_torpedo_pointing_along_x_with_a_tall_dorsal_fin() {
        let mesh = shark();
        check_well_formed(&mesh);
        let (lo, hi) = bounds(&mesh);
        assert!((hi.x - 0.5).abs() < 1e-3, "snout at +0.5: {}", hi.x);
        assert!((lo.x + 0.5).abs() < 1e-3, "tail tip at −0.5: {}", lo.x);
        // Pointing along +x: the eyes are in the front fifth.
        assert!(centroid(&mesh, Material::FishEye).x > 0.3);
        // Longer than tall: the body alone more than 5 times, fins included more
        // than twice.
        let body_depth = (0..=100)
            .map(|i| {
                let x = 0.5 - i as f32 / 100.0 * (0.5 - SHARK_TAIL_ROOT_X);
                SHARK_BODY.top(x) - SHARK_BODY.bottom(x)
            })
            .fold(0.0_f32, f32::max);
        assert!(body_depth * 5.0 < 1.0, "body depth {body_depth}");
        assert!(hi.y - lo.y < 0.5 * (hi.x - lo.x), "{lo} … {hi}");
        // A fin stands well above the back over the middle of the body.
        let fin_top = mesh
            .vertices
            .iter()
            .filter(|v| v.position[0].abs() < 0.15)
            .map(|v| v.position[1])
            .fold(f32::MIN, f32::max);
        assert!(
            fin_top > SHARK_BODY.top(0.0) + 0.1,
            "dorsal fin top {fin_top}"
        );
        // Heterocercal tail: the upper lobe reaches further from the spine than the
        // lower one.
        let axis_y = SHARK_BODY.section(SHARK_TAIL_ROOT_X).axis;
        let tail: Vec<f32> = mesh
            .vertices
            .iter()
            .filter(|v| v.position[0] < -0.35)
            .map(|v| v.position[1] - axis_y)
            .collect();
        let upper = tail.iter().copied().fold(f32::MIN, f32::max);
        let lower = -tail.iter().copied().fold(f32::MAX, f32::min);
        assert!(upper > 1.4 * lower, "upper lobe {upper}, lower {lower}");
        // Big pectoral fins: wider than the body by more than a third of its depth.
        assert!(
            hi.z > SHARK_BODY.section(0.16).half_width + body_depth / 3.0,
            "{}",
            hi.z
        );
    }

    #[test]
    fn stingray_is_a_flat_disc_wider_than_long_with_a_thin_tail_behind() {
        let mesh = stingray();
        check_well_formed(&mesh);
        let (lo, hi) = bounds(&mesh);
        let (width, height) = (hi.z - lo.z, hi.y - lo.y);
        assert!(height < 0.15 * width, "flat: {height} high, {width} wide");
        assert!((hi.x - 0.5).abs() < 1e-3, "snout at +0.5: {}", hi.x);
        assert!((lo.x + 0.5).abs() < 1e-3, "tail tip at −0.5: {}", lo.x);
        let disc = mesh
            .vertices
            .iter()
            .filter(|v| v.material == Material::RayBelly as u32)
            .fold((f32::MAX, f32::MIN), |(a, b), v| {
                (a.min(v.position[0]), b.max(v.position[0]))
            });
        assert!(width > 1.2 * (disc.1 - disc.0), "disc wider than long");
        // Pointing along +x: eyes in front, on top; the tail behind and thin.
        let eyes = centroid(&mesh, Material::FishEye);
        assert!(eyes.x > 0.3 && eyes.y > 0.0, "eyes at {eyes}");
        assert!(
            mesh.vertices
                .iter()
                .filter(|v| v.position[0] < disc.0 - 0.05)
                .all(|v| v.position[2].abs() < 0.03 && v.position[1].abs() < 0.03)
        );
        // The back is above the belly everywhere.
        assert!(centroid(&mesh, Material::RayBack).y > centroid(&mesh, Material::RayBelly).y);
    }

    #[test]
    fn rocks_stay_near_their_radius_and_differ_by_seed() {
        let a = rock(Vec3::ZERO, 1.0, 1, [0.5; 3]);
        let b = rock(Vec3::ZERO, 1.0, 2, [0.5; 3]);
        check_normals_and_indices(&a);
        for v in &a.vertices {
            let r = Vec3::from(v.position).length();
            assert!((0.8..=1.2).contains(&r), "{r}");
        }
        assert_ne!(a.vertices[5].position, b.vertices[5].position);
    }

    #[test]
    fn floor_frame_and_pillar_meshes_are_well_formed() {
        let tank = Tank::default();
        check_normals_and_indices(&sand_floor(&tank));
        check_normals_and_indices(&tank_frame(&tank));
        check_normals_and_indices(&pillar(Vec3::ZERO, 0.3, 2.0, [0.5; 3]));
    }
}
