//! Smooth, shaded fish surfaces deformed by the 23 nodes of a physical fish
//! ([`crate::sim::body`]) every frame, so the body undulates, the tail beats and
//! the body bends in a turn.
//!
//! A [`BodySkin`] is built once per [`BodyShape`] from a template surface in the body
//! frame of `body_layout` (paper units: head tip at x = 0, tail-fin tips at x = −26;
//! y to the fish's left, z dorsal): a closed, lofted body, single-sided fins and two
//! eyes. The body follows the outlines in [`super::profile`] (22 paper units from the
//! head node to the tail root at ring 5), as the rigid meshes of `mesh` do.
//! [`BodySkin::append_deformed`] writes it into a [`Mesh`] in world space.
//!
//! # Deformation
//!
//! Seven *stations* along the body carry a frame taken from the nodes: the head tip
//! (node 0, x = 0), the five rings (x = −5 … −22) and the tail fin (nodes 21 and
//! 22, x = −26). Each station has a centre (the node, the mean of the ring's four
//! nodes, the midpoint of the fin tips), a `left` and an `up` axis (ring: the
//! difference of its left and right, dorsal and ventral node pairs, divided by the
//! rest half size; head: ring 1's; tail: node 21 − node 22 over the rest fin height,
//! and ring 5's left axis) and an `along` axis (the central difference of the
//! neighbouring centres over their rest distance). At rest, every station's axes
//! are the fish's placement: a rotation times the metres per paper unit.
//!
//! A template point q = (x, y, z) maps to
//!
//! ```text
//! p(q) = S(x) + y·L(x) + z·U(x)
//! ```
//!
//! where S is the cubic Hermite spine through the station centres with the `along`
//! axes as tangents (C¹, and exactly the straight rest axis at rest), and L, U blend
//! the `left` and `up` axes of the two stations around x with a smoothstep (C¹).
//! Beyond the head and the tail fin the end station's frame is extended linearly.
//! The surface thereby follows bending (the spine), twisting (the cross-section
//! axes turn) and squashing or stretching (their lengths), and the rest pose gives
//! back the template, scaled, rotated and placed.
//!
//! Normals are transformed exactly: with J = ∂p/∂q (columns S′ + y L′ + z U′, L, U),
//! n′ = cof(J) n = n.x (L × U) + n.y (U × Jx) + n.z (Jx × L), normalised. This keeps
//! them consistent with the triangle winding whatever the deformation, and
//! `fs_lit` faces them towards the eye (the body pipeline draws both faces, so the
//! fins are single sheets).
//!
//! Work per frame: the template's vertices are sorted by x and grouped into
//! *slices* of equal x, whose spine and axes are computed once; a vertex then costs
//! two short linear combinations.
//!
//! # Shading
//!
//! The vertex colour carries the countershaded colour (belly → flank → back, from
//! the template, so the pattern stays on the skin as the fish rolls) and, in alpha,
//! the pattern strength. The material word carries, besides the [`Material`] (bits
//! 0–4), the highlight level (bits 5–7) and the template point in *skin
//! coordinates* (bits 8–31, 8 bits each): `(x / 26 + 0.5, z / 26, −y / 26)`, the
//! snout at +0.5 and the tail-fin nodes at −0.5, quantised over
//! [`SKIN_LOCAL_MIN`]..[`SKIN_LOCAL_MAX`]. `vs_body` in `scene.wgsl` unpacks them,
//! so bars, gill slits and fin tips are painted per pixel.
//!
//! The world frame is whatever the nodes are given in; the lighting in `scene.wgsl`
//! takes +y as up.

use std::f32::consts::{PI, TAU};

use glam::{Vec3, vec3};

use super::fish_palette::Livery;
use super::mesh::{Material, Mesh, Vertex, pack_rgba};
use super::profile::{self, PlacedProfile, Up};
use crate::sim::body::body_layout::{
    HEAD_NODE, NODE_COUNT, PAPER_BODY_LENGTH, REST_POSITIONS, RING_COUNT, TAIL_FIN_NODES,
    ring_nodes,
};

/// Lower corner of the skin-coordinate box packed into the material word (see the
/// module doc); `SKIN_LOCAL_MIN` in `scene.wgsl`.
pub const SKIN_LOCAL_MIN: [f32; 3] = [-0.65, -0.4, -0.4];
/// Upper corner of the skin-coordinate box; `SKIN_LOCAL_MAX` in `scene.wgsl`.
pub const SKIN_LOCAL_MAX: [f32; 3] = [0.6, 0.4, 0.4];
/// Bits of the material word that hold the [`Material`].
pub const MATERIAL_MASK: u32 = 0x1f;
/// Where the highlight level (0–7) sits in the material word.
pub const HIGHLIGHT_SHIFT: u32 = 5;
/// The largest highlight level.
pub const HIGHLIGHT_LEVELS: u32 = 7;

/// Colour of a shark's belly and of the undersides of its fins (`scene.wgsl` uses
/// the same for the fins).
pub const SHARK_BELLY_RGB: [f32; 3] = [0.80, 0.81, 0.80];

/// Stations: head tip, the rings, the tail fin.
const STATIONS: usize = RING_COUNT + 2;
/// Countershading levels precomputed per call.
const TONE_LEVELS: usize = 32;

/// Which template a skin is built from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BodyShape {
    /// A deep-bodied reef fish like `mesh::fish()`: rounded head, long dorsal fin,
    /// anal, pelvic and pectoral fins, a forked tail, eyes.
    Fish,
    /// A requiem shark like `mesh::shark()`: pointed snout, tall first dorsal,
    /// small second dorsal and anal fin, long swept pectorals, pelvic fins and a
    /// heterocercal tail.
    Shark,
}

/// How one fish is coloured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyLook {
    /// Flank colour, linear RGB; the back is drawn a little darker.
    pub body_rgb: [f32; 3],
    /// Belly colour, linear RGB.
    pub belly_rgb: [f32; 3],
    /// Pattern strength in [0, 1]: dark bars on a fish, dark fin tips on a shark.
    pub pattern: f32,
    /// Selection highlight in [0, 1] (0 = none): a warm tint and rim glow.
    pub highlight: f32,
}

impl BodyLook {
    /// A fish in `livery` (`fish_palette::livery`): the belly a pale tint of the
    /// body colour.
    pub fn fish(livery: Livery) -> Self {
        Self {
            body_rgb: livery.rgb,
            belly_rgb: livery.rgb.map(|c| (0.35 * c + 0.6).min(1.0)),
            pattern: livery.pattern,
            highlight: 0.0,
        }
    }

    /// A shark in `livery` (`fish_palette::shark_livery`): a pale grey belly.
    pub fn shark(livery: Livery) -> Self {
        Self {
            body_rgb: livery.rgb,
            belly_rgb: SHARK_BELLY_RGB,
            pattern: livery.pattern,
            highlight: 0.0,
        }
    }

    /// The same look with a selection highlight of `amount` in [0, 1].
    pub fn highlighted(self, amount: f32) -> Self {
        Self {
            highlight: amount,
            ..self
        }
    }

    /// The colour at countershading `tone`: 0 belly, 0.5 flank, 1 back.
    fn rgb_at(&self, tone: f32) -> [f32; 3] {
        let to_flank = smoothstep(0.15, 0.55, tone);
        let darker = 1.0 - 0.4 * smoothstep(0.6, 1.0, tone);
        std::array::from_fn(|i| {
            let c = self.belly_rgb[i] + (self.body_rgb[i] - self.belly_rgb[i]) * to_flank;
            c * darker
        })
    }

    /// Highlight level 0–[`HIGHLIGHT_LEVELS`] for the material word.
    fn highlight_level(&self) -> u32 {
        let h = if self.highlight.is_finite() {
            self.highlight.clamp(0.0, 1.0)
        } else {
            0.0
        };
        (h * HIGHLIGHT_LEVELS as f32).ceil() as u32
    }
}

/// One template vertex, in the body frame (paper units).
#[derive(Clone, Copy, Debug)]
struct SkinVertex {
    position: Vec3,
    normal: Vec3,
    /// Material word without the highlight (see the module doc).
    material: u32,
    /// Index into the per-call countershading table.
    tone: u8,
}

/// Template vertices that share one x, and how their frame comes from the stations.
#[derive(Clone, Copy, Debug)]
struct Slice {
    /// One past the slice's last vertex (slices are contiguous, in x order).
    end: u32,
    /// Blends stations `segment` and `segment + 1`.
    segment: usize,
    /// Weights of (centre, along) of the first station and (centre, along) of the
    /// second for the spine point S(x) …
    spine: [f32; 4],
    /// … and for its derivative S′(x).
    spine_dx: [f32; 4],
    /// Weight of the second station's cross-section axes, and its x derivative.
    blend: f32,
    blend_dx: f32,
}

/// A station's frame in world space.
#[derive(Clone, Copy, Debug, Default)]
struct Station {
    centre: Vec3,
    along: Vec3,
    left: Vec3,
    up: Vec3,
}

/// A smooth fish surface skinned to the 23 nodes of a physical fish (see the module
/// doc). Built once per shape; cheap to deform.
#[derive(Clone, Debug)]
pub struct BodySkin {
    shape: BodyShape,
    vertices: Vec<SkinVertex>,
    indices: Vec<u32>,
    slices: Vec<Slice>,
    /// Rest x of each station, paper units (decreasing).
    station_x: [f32; STATIONS],
    /// Rest half width and half height of each ring, and the rest half height of
    /// the tail fin (node 21 to 22), paper units.
    ring_half: [(f32, f32); RING_COUNT],
    fin_half_height: f32,
}

impl BodySkin {
    /// The skin of `shape`.
    pub fn new(shape: BodyShape) -> Self {
        let mut template = Template::default();
        match shape {
            BodyShape::Fish => build_fish(&mut template),
            BodyShape::Shark => build_shark(&mut template),
        }
        let station_x = station_rest_x();
        let ring_half = std::array::from_fn(|k| {
            let corner = REST_POSITIONS[ring_nodes(k)[0]];
            (corner.y, corner.z)
        });
        let [upper, lower] = TAIL_FIN_NODES.map(|i| REST_POSITIONS[i]);
        let fin_half_height = 0.5 * (upper.z - lower.z);

        // Sort the vertices by x (head first) so equal x form contiguous slices.
        let mut order: Vec<usize> = (0..template.vertices.len()).collect();
        order.sort_by(|&a, &b| {
            let (xa, xb) = (
                template.vertices[a].position.x,
                template.vertices[b].position.x,
            );
            xb.total_cmp(&xa)
        });
        let mut new_index = vec![0_u32; order.len()];
        for (new, &old) in order.iter().enumerate() {
            new_index[old] = new as u32;
        }
        let vertices: Vec<SkinVertex> = order
            .iter()
            .map(|&old| {
                let v = &template.vertices[old];
                SkinVertex {
                    position: v.position,
                    normal: v.normal.normalize_or(Vec3::X),
                    material: pack_material(v.material, v.position),
                    tone: (v.tone.clamp(0.0, 1.0) * (TONE_LEVELS - 1) as f32).round() as u8,
                }
            })
            .collect();
        let indices = template
            .indices
            .iter()
            .map(|&i| new_index[i as usize])
            .collect();
        let mut slices: Vec<Slice> = Vec::new();
        for (i, v) in vertices.iter().enumerate() {
            let same = i > 0 && vertices[i - 1].position.x.to_bits() == v.position.x.to_bits();
            match slices.last_mut() {
                Some(slice) if same => slice.end = i as u32 + 1,
                _ => {
                    let mut slice = slice_at(&station_x, v.position.x);
                    slice.end = i as u32 + 1;
                    slices.push(slice);
                }
            }
        }
        Self {
            shape,
            vertices,
            indices,
            slices,
            station_x,
            ring_half,
            fin_half_height,
        }
    }

    /// The shape this skin was built for.
    pub fn shape(&self) -> BodyShape {
        self.shape
    }

    /// Vertices [`Self::append_deformed`] writes per fish.
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }

    /// Triangles [`Self::append_deformed`] writes per fish.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Appends this skin deformed by the node positions `nodes_m` (world space,
    /// metres, in `body_layout` order, e.g. `FishBody::positions_m`) to `out`:
    /// world-space vertices with unit normals, coloured by `look`. A fish with a
    /// non-finite node is skipped.
    pub fn append_deformed(&self, nodes_m: &[Vec3; NODE_COUNT], look: &BodyLook, out: &mut Mesh) {
        if !nodes_m.iter().all(|p| p.is_finite()) {
            return;
        }
        let stations = self.stations(nodes_m);
        let alpha = (look.pattern.clamp(0.0, 1.0) * 255.0).round() as u32;
        let colours: [u32; TONE_LEVELS] = std::array::from_fn(|level| {
            let rgb = look.rgb_at(level as f32 / (TONE_LEVELS - 1) as f32);
            pack_rgba(rgb, alpha)
        });
        let highlight = look.highlight_level() << HIGHLIGHT_SHIFT;

        let base = out.vertices.len() as u32;
        out.vertices.reserve(self.vertices.len());
        out.indices.reserve(self.indices.len());
        let mut start = 0;
        for slice in &self.slices {
            let frame = SliceFrame::new(slice, &stations);
            for v in &self.vertices[start..slice.end as usize] {
                let (position, normal) = frame.apply(v.position, v.normal);
                out.vertices.push(Vertex {
                    position: position.to_array(),
                    material: v.material | highlight,
                    normal: normal.to_array(),
                    color: colours[usize::from(v.tone)],
                });
            }
            start = slice.end as usize;
        }
        out.indices.extend(self.indices.iter().map(|&i| i + base));
    }

    /// The stations' frames for node positions `p` (see the module doc).
    fn stations(&self, p: &[Vec3; NODE_COUNT]) -> [Station; STATIONS] {
        let mut s = [Station::default(); STATIONS];
        s[0].centre = p[HEAD_NODE];
        for k in 0..RING_COUNT {
            let [dl, dr, vr, vl] = ring_nodes(k).map(|i| p[i]);
            let (half_width, half_height) = self.ring_half[k];
            s[k + 1] = Station {
                centre: (dl + dr + vr + vl) * 0.25,
                along: Vec3::ZERO,
                left: (dl + vl - dr - vr) / (4.0 * half_width),
                up: (dl + dr - vr - vl) / (4.0 * half_height),
            };
        }
        let [upper, lower] = TAIL_FIN_NODES.map(|i| p[i]);
        s[0].left = s[1].left;
        s[0].up = s[1].up;
        s[STATIONS - 1] = Station {
            centre: (upper + lower) * 0.5,
            along: Vec3::ZERO,
            left: s[STATIONS - 2].left,
            up: (upper - lower) / (2.0 * self.fin_half_height),
        };
        let x = &self.station_x;
        for i in 0..STATIONS {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(STATIONS - 1));
            s[i].along = (s[a].centre - s[b].centre) / (x[a] - x[b]);
        }
        s
    }
}

/// Rest x of the stations: head tip, ring centres, tail-fin midpoint.
fn station_rest_x() -> [f32; STATIONS] {
    let mut x = [0.0; STATIONS];
    x[0] = REST_POSITIONS[HEAD_NODE].x;
    for k in 0..RING_COUNT {
        x[k + 1] = ring_nodes(k)
            .iter()
            .map(|&i| REST_POSITIONS[i].x)
            .sum::<f32>()
            / 4.0;
    }
    let [upper, lower] = TAIL_FIN_NODES.map(|i| REST_POSITIONS[i]);
    x[STATIONS - 1] = 0.5 * (upper.x + lower.x);
    x
}

/// How the frame at template x comes from the stations at rest x `station_x`.
fn slice_at(station_x: &[f32; STATIONS], x: f32) -> Slice {
    let last = STATIONS - 1;
    if x >= station_x[0] {
        // In front of the head tip: the head's frame, extended.
        return Slice {
            end: 0,
            segment: 0,
            spine: [1.0, x - station_x[0], 0.0, 0.0],
            spine_dx: [0.0, 1.0, 0.0, 0.0],
            blend: 0.0,
            blend_dx: 0.0,
        };
    }
    if x <= station_x[last] {
        // Behind the tail-fin nodes: the tail fin's frame, extended.
        return Slice {
            end: 0,
            segment: last - 1,
            spine: [0.0, 0.0, 1.0, x - station_x[last]],
            spine_dx: [0.0, 0.0, 0.0, 1.0],
            blend: 1.0,
            blend_dx: 0.0,
        };
    }
    let segment = (0..last)
        .find(|&j| x >= station_x[j + 1])
        .unwrap_or(last - 1);
    let length = station_x[segment] - station_x[segment + 1];
    let u = (station_x[segment] - x) / length;
    // Cubic Hermite basis on u ∈ [0, 1] (u grows towards the tail, du/dx = −1/L);
    // the tangents in u are −L × the stations' `along` axes.
    let (u2, u3) = (u * u, u * u * u);
    let h00 = 2.0 * u3 - 3.0 * u2 + 1.0;
    let h10 = u3 - 2.0 * u2 + u;
    let h01 = -2.0 * u3 + 3.0 * u2;
    let h11 = u3 - u2;
    let d00 = 6.0 * u2 - 6.0 * u;
    let d10 = 3.0 * u2 - 4.0 * u + 1.0;
    let d01 = -6.0 * u2 + 6.0 * u;
    let d11 = 3.0 * u2 - 2.0 * u;
    Slice {
        end: 0,
        segment,
        spine: [h00, -length * h10, h01, -length * h11],
        spine_dx: [-d00 / length, d10, -d01 / length, d11],
        blend: u2 * (3.0 - 2.0 * u),
        blend_dx: -6.0 * u * (1.0 - u) / length,
    }
}

/// The frame of one slice for this call: where its axis point is, its cross-section
/// axes, and the pieces of cof(J) (see the module doc).
struct SliceFrame {
    spine: Vec3,
    left: Vec3,
    up: Vec3,
    /// Image of a template x normal: L × U.
    n_x: Vec3,
    /// Image of a template y normal: U × Jx = `n_y` + y `n_yy` + z `n_yz`.
    n_y: Vec3,
    n_yy: Vec3,
    n_yz: Vec3,
    /// Image of a template z normal: Jx × L = `n_z` + y `n_zy` + z `n_zz`.
    n_z: Vec3,
    n_zy: Vec3,
    n_zz: Vec3,
    /// Jx = `spine_dx` + y `left_dx` + z `up_dx`: the fallback for a collapsed frame.
    spine_dx: Vec3,
    left_dx: Vec3,
    up_dx: Vec3,
}

impl SliceFrame {
    fn new(slice: &Slice, stations: &[Station; STATIONS]) -> Self {
        let (a, b) = (&stations[slice.segment], &stations[slice.segment + 1]);
        let combine =
            |w: &[f32; 4]| a.centre * w[0] + a.along * w[1] + b.centre * w[2] + b.along * w[3];
        let spine = combine(&slice.spine);
        let spine_dx = combine(&slice.spine_dx);
        let left = a.left.lerp(b.left, slice.blend);
        let up = a.up.lerp(b.up, slice.blend);
        let left_dx = (b.left - a.left) * slice.blend_dx;
        let up_dx = (b.up - a.up) * slice.blend_dx;
        Self {
            spine,
            left,
            up,
            n_x: left.cross(up),
            n_y: up.cross(spine_dx),
            n_yy: up.cross(left_dx),
            n_yz: up.cross(up_dx),
            n_z: spine_dx.cross(left),
            n_zy: left_dx.cross(left),
            n_zz: up_dx.cross(left),
            spine_dx,
            left_dx,
            up_dx,
        }
    }

    /// World position and unit normal of template point `q` with normal `n`.
    fn apply(&self, q: Vec3, n: Vec3) -> (Vec3, Vec3) {
        let position = self.spine + self.left * q.y + self.up * q.z;
        let normal = self.n_x * n.x
            + (self.n_y + self.n_yy * q.y + self.n_yz * q.z) * n.y
            + (self.n_z + self.n_zy * q.y + self.n_zz * q.z) * n.z;
        let normal = normal.try_normalize().unwrap_or_else(|| {
            // A collapsed frame: the normal carried along, else straight up.
            let jx = self.spine_dx + self.left_dx * q.y + self.up_dx * q.z;
            (jx * n.x + self.left * n.y + self.up * n.z)
                .try_normalize()
                .unwrap_or(Vec3::Y)
        });
        (position, normal)
    }
}

/// Skin coordinates of template point `p` (see the module doc).
fn skin_local(p: Vec3) -> Vec3 {
    vec3(
        p.x / PAPER_BODY_LENGTH + 0.5,
        p.z / PAPER_BODY_LENGTH,
        -p.y / PAPER_BODY_LENGTH,
    )
}

/// The material word of a template vertex at `p`, without the highlight.
fn pack_material(material: Material, p: Vec3) -> u32 {
    let local = skin_local(p).to_array();
    let mut word = material as u32 & MATERIAL_MASK;
    for axis in 0..3 {
        let (lo, hi) = (SKIN_LOCAL_MIN[axis], SKIN_LOCAL_MAX[axis]);
        let q = (((local[axis] - lo) / (hi - lo)).clamp(0.0, 1.0) * 255.0).round() as u32;
        word |= q << (8 + 8 * axis);
    }
    word
}

fn smoothstep(edge0: f32, edge1: f32, x: f32) -> f32 {
    let t = ((x - edge0) / (edge1 - edge0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

// ---------------------------------------------------------------- templates

/// A template vertex while the template is built.
#[derive(Clone, Copy, Debug)]
struct TemplateVertex {
    position: Vec3,
    normal: Vec3,
    material: Material,
    /// Countershading: 0 belly, 0.5 flank, 1 back.
    tone: f32,
}

/// A template surface under construction, in the body frame (paper units).
#[derive(Default)]
struct Template {
    vertices: Vec<TemplateVertex>,
    indices: Vec<u32>,
}

impl Template {
    fn push(&mut self, position: Vec3, normal: Vec3, material: Material, tone: f32) -> u32 {
        self.vertices.push(TemplateVertex {
            position,
            normal: normal.normalize_or(Vec3::X),
            material,
            tone,
        });
        (self.vertices.len() - 1) as u32
    }

    fn triangle(&mut self, a: u32, b: u32, c: u32) {
        self.indices.extend_from_slice(&[a, b, c]);
    }

    /// The closed skin of `body` along −x: an apex at its snout, a ring of
    /// `segments` points at each of `xs` (decreasing), a fan closing the last ring;
    /// ring points from θ = 0 on the left (+y) through π/2 on the back (+z). Normals
    /// by finite differences, outwards; `tone(p, n)` is the countershading.
    fn tube(
        &mut self,
        body: &PlacedProfile,
        xs: &[f32],
        segments: u32,
        material: Material,
        tone: &dyn Fn(Vec3, Vec3) -> f32,
    ) {
        let snout = body.snout();
        let apex = self.push(snout, Vec3::X, material, tone(snout, Vec3::X));
        let mut rings = Vec::with_capacity(xs.len());
        for &x in xs {
            rings.push(self.vertices.len() as u32);
            for k in 0..segments {
                let angle = k as f32 / segments as f32 * TAU;
                let (p, n) = surface_frame(body, x, angle);
                self.push(p, n, material, tone(p, n));
            }
        }
        let (Some(&first), Some(&last)) = (rings.first(), rings.last()) else {
            return;
        };
        let next = |k: u32| (k + 1) % segments;
        for k in 0..segments {
            self.triangle(apex, first + k, first + next(k));
        }
        for pair in rings.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            for k in 0..segments {
                self.triangle(a + k, b + k, a + next(k));
                self.triangle(a + next(k), b + k, b + next(k));
            }
        }
        let centre = (0..segments)
            .map(|k| self.vertices[(last + k) as usize].position)
            .sum::<Vec3>()
            / segments as f32;
        let tail = self.push(centre, Vec3::NEG_X, material, tone(centre, Vec3::NEG_X));
        for k in 0..segments {
            self.triangle(tail, last + next(k), last + k);
        }
    }

    /// A single-sided sheet through `grid` (rows of equal length); normals from the
    /// grid's differences, the triangles wound to match.
    fn sheet(&mut self, grid: &[Vec<Vec3>], material: Material, tone: f32) {
        let rows = grid.len();
        let cols = grid.first().map_or(0, Vec::len);
        if rows < 2 || cols < 2 || grid.iter().any(|row| row.len() != cols) {
            return;
        }
        let first = self.vertices.len() as u32;
        for i in 0..rows {
            for j in 0..cols {
                let du = grid[(i + 1).min(rows - 1)][j] - grid[i.saturating_sub(1)][j];
                let dv = grid[i][(j + 1).min(cols - 1)] - grid[i][j.saturating_sub(1)];
                self.push(grid[i][j], du.cross(dv), material, tone);
            }
        }
        let at = |i: usize, j: usize| first + (i * cols + j) as u32;
        for i in 0..rows - 1 {
            for j in 0..cols - 1 {
                self.triangle(at(i, j), at(i + 1, j), at(i, j + 1));
                self.triangle(at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
            }
        }
    }

    /// A fin fanned out from `centre` (inside the body) to the polyline `outline`:
    /// rows of the outline scaled about the centre by `fractions`.
    fn fan(&mut self, centre: Vec3, outline: &[Vec3], fractions: &[f32], material: Material) {
        let grid: Vec<Vec<Vec3>> = fractions
            .iter()
            .map(|&f| outline.iter().map(|&o| centre + (o - centre) * f).collect())
            .collect();
        self.sheet(&grid, material, 0.5);
    }

    /// An eye: a shallow cone of `ring` points around `centre`, bulging along the
    /// unit `outward` by `radius` × 0.6.
    fn eye(&mut self, centre: Vec3, outward: Vec3, radius: f32, ring: u32) {
        let outward = outward.normalize_or(Vec3::Y);
        let u = outward.any_orthonormal_vector();
        // u × v = outward, so (apex, k, k + 1) faces outwards.
        let v = outward.cross(u);
        let apex = self.push(
            centre + outward * radius * 0.6,
            outward,
            Material::FishEye,
            0.5,
        );
        let first = self.vertices.len() as u32;
        for k in 0..ring {
            let a = k as f32 / ring as f32 * TAU;
            let offset = (u * a.cos() + v * a.sin()) * radius;
            self.push(
                centre + offset,
                offset.normalize_or_zero() + outward * 0.8,
                Material::FishEye,
                0.5,
            );
        }
        for k in 0..ring {
            self.triangle(apex, first + k, first + (k + 1) % ring);
        }
    }
}

/// Ring positions from just behind the snout to `end_x`, `rings` of them, closer
/// together at the snout where the profile curves most.
fn ring_xs(end_x: f32, rings: usize, power: f32) -> Vec<f32> {
    (1..=rings)
        .map(|i| end_x * (i as f32 / rings as f32).powf(power))
        .collect()
}

/// A point on a body's skin and its outward normal by finite differences.
fn surface_frame(body: &PlacedProfile, x: f32, angle: f32) -> (Vec3, Vec3) {
    let surface = |x, angle| body.surface(x, angle);
    let along = surface(x - 0.02, angle) - surface(x + 0.02, angle);
    let around = surface(x, angle + 0.01) - surface(x, angle - 0.01);
    (surface(x, angle), along.cross(around).normalize_or(Vec3::Y))
}

/// Mirrors a point to the fish's other side.
fn mirror(p: Vec3) -> Vec3 {
    vec3(p.x, -p.y, p.z)
}

/// Where the body ends and the caudal fin begins, the profiles' tail root (x, paper
/// units): ring 5. The head node (x = 0) is the snout.
const TAIL_ROOT_X: f32 = -22.0;

/// Where the body tubes end, inside the caudal fin's root (a little past the tail
/// root, with the tail root's section).
const TUBE_END_X: f32 = -22.6;

/// The fish's body in the body frame (paper units): [`profile::FISH`] from the head
/// node to the tail root.
pub(super) const FISH_BODY: PlacedProfile = PlacedProfile {
    profile: profile::FISH,
    snout_x: 0.0,
    tail_root_x: TAIL_ROOT_X,
    up: Up::Z,
};

/// The shark's body in the body frame (paper units): [`profile::SHARK`] from the
/// head node to the tail root.
pub(super) const SHARK_BODY: PlacedProfile = PlacedProfile {
    profile: profile::SHARK,
    ..FISH_BODY
};

/// The reef fish (see [`BodyShape::Fish`]).
fn build_fish(t: &mut Template) {
    let tone = |p: Vec3, _n: Vec3| {
        let s = FISH_BODY.section(p.x);
        ((p.z - s.axis) / s.half_height()).clamp(-1.0, 1.0) * 0.5 + 0.5
    };
    let rings = ring_xs(TUBE_END_X, 24, 1.3);
    t.tube(&FISH_BODY, &rings, 18, Material::SkinFish, &tone);
    let fin = Material::SkinFin;

    // Forked caudal fin around the tail-fin nodes (x = −26, z = ±3): from the
    // peduncle to lobe tips at x = −27.4, z = ±4.4, notched to x = −24.6.
    let axis = FISH_BODY.section(-21.0).axis;
    let rows: Vec<Vec<Vec3>> = (0..=4)
        .map(|i| {
            let u = i as f32 / 4.0;
            (0..=6)
                .map(|j| {
                    let v = j as f32 / 3.0 - 1.0;
                    let trailing_x = -24.6 - 2.8 * v.abs().powf(1.3);
                    let x = -21.0 + (trailing_x + 21.0) * u;
                    let z = axis + 0.8 * v + (4.4 - 0.8) * v * u.powf(0.85);
                    vec3(x, 0.0, z)
                })
                .collect()
        })
        .collect();
    t.sheet(&rows, fin, 0.5);

    // Dorsal fin: long, along the back from above the pectorals to the peduncle,
    // its rays leaning back, a soft rounded rear.
    let dorsal = |v: f32| -> Vec<Vec3> {
        (0..=7)
            .map(|j| {
                let s = j as f32 / 7.0;
                let x = -5.0 - 11.5 * s;
                let height = 0.25
                    + 2.3
                        * (s / 0.15).min(1.0).sqrt()
                        * (1.0 - 0.25 * s)
                        * (1.0 - 0.85 * smoothstep(0.8, 1.0, s));
                vec3(
                    x - 0.6 * height * v,
                    0.0,
                    FISH_BODY.top(x) - 0.3 + height * v,
                )
            })
            .collect()
    };
    t.sheet(&[dorsal(0.0), dorsal(0.5), dorsal(1.0)], fin, 0.5);

    // Anal fin, under the rear half.
    let anal = |v: f32| -> Vec<Vec3> {
        (0..=5)
            .map(|j| {
                let s = j as f32 / 5.0;
                let x = -13.0 - 5.8 * s;
                let depth =
                    0.2 + 1.7 * (s / 0.2).min(1.0).sqrt() * (1.0 - 0.8 * smoothstep(0.75, 1.0, s));
                vec3(
                    x - 0.5 * depth * v,
                    0.0,
                    FISH_BODY.bottom(x) + 0.3 - depth * v,
                )
            })
            .collect()
    };
    t.sheet(&[anal(0.0), anal(0.5), anal(1.0)], fin, 0.5);

    for side in [1.0_f32, -1.0] {
        let place = |p: Vec3| if side > 0.0 { p } else { mirror(p) };
        // Pectoral fins: low on the flank behind the gills, fanned back and out.
        let root: Vec<Vec3> = [(-5.2, -0.05), (-5.6, -0.25), (-6.0, -0.45)]
            .iter()
            .map(|&(x, sine): &(f32, f32)| {
                let (p, n) = surface_frame(&FISH_BODY, x, sine.asin());
                p - n * 0.12
            })
            .collect();
        let outer = [
            root[0] + vec3(-3.2, 1.4, -0.3),
            root[1] + vec3(-3.6, 1.75, -0.35),
            root[2] + vec3(-2.8, 1.45, -0.4),
        ];
        let middle: Vec<Vec3> = root
            .iter()
            .zip(&outer)
            .map(|(&r, &o)| r.lerp(o, 0.5) + vec3(0.0, 0.15, 0.0))
            .collect();
        t.sheet(
            &[
                root.iter().map(|&p| place(p)).collect(),
                middle.iter().map(|&p| place(p)).collect(),
                outer.iter().map(|&p| place(p)).collect(),
            ],
            fin,
            0.5,
        );
        // Pelvic fins: under the belly, hanging down and back.
        let (b0, b1) = (FISH_BODY.bottom(-6.6) + 0.25, FISH_BODY.bottom(-7.6) + 0.25);
        t.sheet(
            &[
                vec![place(vec3(-6.6, 0.45, b0)), place(vec3(-7.6, 0.45, b1))],
                vec![
                    place(vec3(-8.6, 0.95, b0 - 1.6)),
                    place(vec3(-9.4, 1.0, b1 - 1.15)),
                ],
            ],
            fin,
            0.5,
        );
        // Eyes: domes on the sides of the head, above the axis.
        let angle = if side > 0.0 { 0.34 } else { PI - 0.34 };
        let (p, n) = surface_frame(&FISH_BODY, -2.3, angle);
        t.eye(p - n * 0.12, n, 0.55, 8);
    }
}

/// The shark (see [`BodyShape::Shark`]).
fn build_shark(t: &mut Template) {
    // Countershading by the facing of the skin: up and sideways the body colour,
    // down the belly colour; a little darker along the top.
    let tone =
        |_p: Vec3, n: Vec3| 0.5 * smoothstep(-0.3, -0.02, n.z) + 0.2 * smoothstep(0.4, 1.0, n.z);
    let rings = ring_xs(TUBE_END_X, 24, 1.2);
    t.tube(&SHARK_BODY, &rings, 18, Material::SkinShark, &tone);
    let fin = Material::SkinSharkFin;
    let top = |x: f32, dz: f32| vec3(x, 0.0, SHARK_BODY.top(x) + dz);
    let bottom = |x: f32, dz: f32| vec3(x, 0.0, SHARK_BODY.bottom(x) + dz);

    // First dorsal fin: tall, its apex leaning back, a concave trailing edge and a
    // free rear tip.
    let apex_z = SHARK_BODY.top(-8.6) + 4.6;
    t.fan(
        top(-8.6, -0.7),
        &[
            top(-5.6, -0.3),
            top(-7.2, 1.5),
            top(-8.9, 3.2),
            vec3(-10.6, 0.0, apex_z),
            top(-10.3, 2.2),
            top(-10.8, 0.9),
            top(-12.0, 0.35),
            top(-11.0, -0.3),
        ],
        &[0.12, 0.55, 1.0],
        fin,
    );
    // Second dorsal and anal fins, small, near the tail.
    t.fan(
        top(-17.4, -0.35),
        &[
            top(-16.3, -0.15),
            top(-17.1, 0.8),
            top(-18.2, 1.3),
            top(-18.3, 0.5),
            top(-19.2, 0.15),
            top(-18.5, -0.15),
        ],
        &[0.15, 1.0],
        fin,
    );
    t.fan(
        bottom(-18.0, 0.3),
        &[
            bottom(-17.0, 0.1),
            bottom(-17.8, -0.7),
            bottom(-18.8, -1.1),
            bottom(-18.9, -0.45),
            bottom(-19.6, -0.1),
            bottom(-19.0, 0.1),
        ],
        &[0.15, 1.0],
        fin,
    );

    // Heterocercal tail: the spine runs up into a long upper lobe that reaches well
    // past the upper tail-fin node (−26, +3); a short lower lobe near the lower one.
    let tail_axis = SHARK_BODY.section(TAIL_ROOT_X).axis;
    t.fan(
        vec3(-21.5, 0.0, tail_axis),
        &[
            top(-20.6, -0.1),
            vec3(-23.0, 0.0, 2.5),
            vec3(-25.6, 0.0, 4.1),
            vec3(-28.4, 0.0, 5.9),
            vec3(-27.9, 0.0, 4.9),
            vec3(-26.8, 0.0, 3.3),
            vec3(-24.8, 0.0, 0.5),
            vec3(-26.0, 0.0, -2.5),
            vec3(-23.8, 0.0, -1.3),
            bottom(TAIL_ROOT_X, 0.1),
        ],
        &[0.1, 0.4, 0.7, 1.0],
        fin,
    );

    for side in [1.0_f32, -1.0] {
        let place = |p: Vec3| if side > 0.0 { p } else { mirror(p) };
        // Pectoral fins: long, swept back and angled down, from low on the flank
        // behind the gills. Rows from root to tip, leading to trailing edge.
        let root_at = |x: f32| {
            let (p, n) = surface_frame(&SHARK_BODY, x, -0.5);
            p - n * 0.15
        };
        let (front, rear) = (root_at(-4.8), root_at(-7.6));
        let tip = vec3(-11.0, front.y + 4.2, front.z - 2.0);
        let rows: Vec<Vec<Vec3>> = [0.0_f32, 0.35, 0.7, 1.0]
            .iter()
            .map(|&f| {
                // A convex leading edge, a concave trailing edge, a rounded tip.
                let leading = front.lerp(tip, f) + vec3(0.5, 0.0, 0.2) * (f * (1.0 - f) * 4.0);
                let trailing = rear.lerp(tip + vec3(0.6, -0.2, 0.1), f)
                    + vec3(0.7, 0.0, 0.0) * (f * (1.0 - f) * 4.0);
                (0..=2)
                    .map(|c| place(leading.lerp(trailing, c as f32 / 2.0)))
                    .collect()
            })
            .collect();
        t.sheet(&rows, fin, 0.5);
        // Pelvic fins, small, under the rear of the belly.
        let (p0, p1) = (
            surface_frame(&SHARK_BODY, -13.6, -1.1).0,
            surface_frame(&SHARK_BODY, -14.9, -1.1).0,
        );
        t.sheet(
            &[
                vec![
                    place(p0 + vec3(0.0, -0.1, 0.1)),
                    place(p1 + vec3(0.0, -0.1, 0.1)),
                ],
                vec![
                    place(vec3(-15.4, p0.y + 1.0, p0.z - 0.8)),
                    place(vec3(-16.2, p1.y + 0.9, p1.z - 0.5)),
                ],
            ],
            fin,
            0.5,
        );
        // Eyes, on the sides of the head.
        let angle = if side > 0.0 { 0.3 } else { PI - 0.3 };
        let (p, n) = surface_frame(&SHARK_BODY, -2.6, angle);
        t.eye(p - n * 0.06, n + vec3(0.0, 0.0, 0.25), 0.3, 8);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Quat;

    const SHAPES: [BodyShape; 2] = [BodyShape::Fish, BodyShape::Shark];

    fn look() -> BodyLook {
        BodyLook::fish(crate::render::fish_palette::livery(0.05))
    }

    /// A rest-shaped fish `s` metres per paper unit long, turned by `rotation` and
    /// moved to `origin`; the map applied to template points.
    fn placement(origin: Vec3, rotation: Quat, s: f32) -> impl Fn(Vec3) -> Vec3 {
        move |q: Vec3| origin + rotation * (q * s)
    }

    fn deformed(skin: &BodySkin, nodes: &[Vec3; NODE_COUNT]) -> Mesh {
        let mut mesh = Mesh::default();
        skin.append_deformed(nodes, &look(), &mut mesh);
        mesh
    }

    fn position(mesh: &Mesh, i: usize) -> Vec3 {
        Vec3::from(mesh.vertices[i].position)
    }

    fn check_normals(mesh: &Mesh) {
        for v in &mesh.vertices {
            let n = Vec3::from(v.normal);
            assert!(n.is_finite(), "normal {n}");
            assert!((n.length() - 1.0).abs() < 1e-4, "normal {n} not unit");
            assert!(Vec3::from(v.position).is_finite());
        }
    }

    /// Every triangle of some area faces the way its vertex normals point.
    fn check_winding(mesh: &Mesh, min_area: f32) -> usize {
        let mut against = 0;
        for tri in mesh.indices.chunks_exact(3) {
            let p = |k: usize| Vec3::from(mesh.vertices[tri[k] as usize].position);
            let face = (p(1) - p(0)).cross(p(2) - p(0));
            if face.length() < 2.0 * min_area {
                continue;
            }
            let normals: Vec3 = (0..3)
                .map(|k| Vec3::from(mesh.vertices[tri[k] as usize].normal))
                .sum();
            if face.dot(normals) <= 0.0 {
                against += 1;
            }
        }
        against
    }

    /// A body bent into an arc of radius `radius` (paper units) to its left and
    /// twisted progressively by `twist` radians per paper unit, then placed.
    fn bent(radius: f32, twist: f32, place: &impl Fn(Vec3) -> Vec3) -> [Vec3; NODE_COUNT] {
        REST_POSITIONS.map(|p| {
            let roll = p.x * twist;
            let (s, c) = roll.sin_cos();
            let (y, z) = (p.y * c - p.z * s, p.y * s + p.z * c);
            let phi = p.x / radius;
            let r = radius - y;
            place(vec3(r * phi.sin(), radius - r * phi.cos(), z))
        })
    }

    #[test]
    fn the_rest_pose_gives_back_the_template_placed() {
        let rotation = Quat::from_euler(glam::EulerRot::YXZ, 0.7, -0.3, 0.2);
        let (origin, s) = (vec3(1.5, 2.0, -0.7), 0.3 / PAPER_BODY_LENGTH);
        let place = placement(origin, rotation, s);
        let nodes = REST_POSITIONS.map(&place);
        for shape in SHAPES {
            let skin = BodySkin::new(shape);
            let mesh = deformed(&skin, &nodes);
            assert_eq!(mesh.vertices.len(), skin.vertices.len());
            for (i, v) in skin.vertices.iter().enumerate() {
                let expected = place(v.position);
                let got = position(&mesh, i);
                assert!(
                    got.distance(expected) < 1e-4,
                    "{shape:?} vertex {i} at {}: {got} instead of {expected}",
                    v.position
                );
                let normal = Vec3::from(mesh.vertices[i].normal);
                assert!(
                    normal.distance(rotation * v.normal) < 1e-3,
                    "{shape:?} normal of {}: {normal} instead of {}",
                    v.position,
                    rotation * v.normal
                );
            }
            check_normals(&mesh);
        }
    }

    #[test]
    fn moving_only_the_tail_moves_the_tail_and_leaves_the_head() {
        let s = 0.01;
        let place = placement(Vec3::ZERO, Quat::IDENTITY, s);
        let rest = REST_POSITIONS.map(&place);
        let mut beat = rest;
        // Tail fin and last ring swing to the left.
        for i in [17, 18, 19, 20, 21, 22] {
            beat[i] += vec3(0.0, 2.5 * s, 0.0);
        }
        for shape in SHAPES {
            let skin = BodySkin::new(shape);
            let (before, after) = (deformed(&skin, &rest), deformed(&skin, &beat));
            let mut tail_moved = 0;
            for (i, v) in skin.vertices.iter().enumerate() {
                let moved = position(&before, i).distance(position(&after, i));
                if v.position.x > -14.9 {
                    assert!(moved < 1e-6, "{shape:?}: {} moved {moved}", v.position);
                }
                if v.position.x < -24.0 {
                    assert!(
                        moved > 1.5 * s,
                        "{shape:?}: {} only moved {moved}",
                        v.position
                    );
                    tail_moved += 1;
                }
            }
            assert!(tail_moved > 10, "{shape:?}: {tail_moved} tail vertices");
        }
    }

    #[test]
    fn a_bent_and_twisted_body_has_unit_normals_and_stays_near_its_nodes() {
        let s = 0.3 / PAPER_BODY_LENGTH;
        let place = placement(vec3(0.2, 1.0, 0.4), Quat::from_rotation_y(1.0), s);
        let body_length = PAPER_BODY_LENGTH * s;
        for shape in SHAPES {
            let skin = BodySkin::new(shape);
            for (radius, twist) in [(40.0, 0.0), (12.0, 0.0), (8.0, 0.03), (-10.0, -0.05)] {
                let nodes = bent(radius, twist, &place);
                let mesh = deformed(&skin, &nodes);
                check_normals(&mesh);
                for v in &mesh.vertices {
                    let p = Vec3::from(v.position);
                    let nearest = nodes.iter().map(|n| n.distance(p)).fold(f32::MAX, f32::min);
                    assert!(
                        nearest < 0.5 * body_length,
                        "{shape:?}: {p} is {nearest} m from the body"
                    );
                }
                // The tail fin goes where the tail nodes went: its centroid stays
                // about as far from their midpoint as at rest.
                let fin_mid = (nodes[21] + nodes[22]) * 0.5;
                let fin: Vec<usize> = (0..skin.vertices.len())
                    .filter(|&i| (-27.0..-24.0).contains(&skin.vertices[i].position.x))
                    .collect();
                let mean = |p: &dyn Fn(usize) -> Vec3| {
                    fin.iter().map(|&i| p(i)).sum::<Vec3>() / fin.len() as f32
                };
                let rest_offset =
                    mean(&|i| skin.vertices[i].position).distance(vec3(-26.0, 0.0, 0.0));
                let centroid = mean(&|i| position(&mesh, i));
                assert!(
                    centroid.distance(fin_mid) < (rest_offset + 1.0) * s,
                    "{shape:?}, radius {radius}: fin at {centroid}, nodes at {fin_mid}"
                );
                if radius.abs() >= 12.0 {
                    let area = 1e-4 * s * s;
                    assert_eq!(check_winding(&mesh, area), 0, "{shape:?}, radius {radius}");
                }
            }
        }
    }

    #[test]
    fn the_tail_root_of_the_profiles_is_ring_5() {
        let ring_5 = ring_nodes(RING_COUNT - 1).map(|i| REST_POSITIONS[i].x);
        assert!(ring_5.iter().all(|&x| x == TAIL_ROOT_X), "{ring_5:?}");
        const { assert!(TUBE_END_X < TAIL_ROOT_X) };
    }

    #[test]
    fn collapsed_or_broken_nodes_still_give_unit_normals_or_nothing() {
        let skin = BodySkin::new(BodyShape::Fish);
        let mesh = deformed(&skin, &[Vec3::ONE; NODE_COUNT]);
        check_normals(&mesh);
        let mut nodes = REST_POSITIONS;
        nodes[7] = Vec3::NAN;
        assert!(deformed(&skin, &nodes).vertices.is_empty());
    }

    #[test]
    fn within_budget_and_indices_in_range() {
        let nodes = REST_POSITIONS.map(placement(Vec3::ZERO, Quat::IDENTITY, 0.01));
        for shape in SHAPES {
            let skin = BodySkin::new(shape);
            println!(
                "{shape:?}: {} triangles, {} vertices, {} slices",
                skin.triangle_count(),
                skin.vertex_count(),
                skin.slices.len()
            );
            assert!(skin.triangle_count() <= 1_500);
            assert!(skin.vertex_count() <= 1_000);
            // Two fish in one mesh: the second indexes its own vertices.
            let mut mesh = Mesh::default();
            skin.append_deformed(&nodes, &look(), &mut mesh);
            skin.append_deformed(&nodes, &look(), &mut mesh);
            assert_eq!(mesh.vertices.len(), 2 * skin.vertex_count());
            assert_eq!(mesh.indices.len(), 6 * skin.triangle_count());
            let n = skin.vertex_count() as u32;
            let (first, second) = mesh.indices.split_at(3 * skin.triangle_count());
            assert!(first.iter().all(|&i| i < n));
            assert!(second.iter().all(|&i| (n..2 * n).contains(&i)));
            // No degenerate triangles, all wound with their normals.
            assert_eq!(check_winding(&mesh, 0.0), 0, "{shape:?}");
            for tri in skin.indices.chunks_exact(3) {
                let p = |k: usize| skin.vertices[tri[k] as usize].position;
                let area = 0.5 * (p(1) - p(0)).cross(p(2) - p(0)).length();
                assert!(area > 1e-4, "{shape:?}: sliver at {}", p(0));
            }
        }
    }

    /// Template vertices of one material, body frame (paper units).
    fn points(skin: &BodySkin, material: Material) -> Vec<Vec3> {
        skin.vertices
            .iter()
            .filter(|v| v.material & MATERIAL_MASK == material as u32)
            .map(|v| v.position)
            .collect()
    }

    #[test]
    fn the_fish_points_its_head_along_x_with_fins_and_eyes() {
        let skin = BodySkin::new(BodyShape::Fish);
        let body = points(&skin, Material::SkinFish);
        let fins = points(&skin, Material::SkinFin);
        let eyes = points(&skin, Material::FishEye);
        let max_x = body.iter().map(|p| p.x).fold(f32::MIN, f32::max);
        assert!(max_x.abs() < 1e-4, "snout at the head node: {max_x}");
        let min_x = fins.iter().map(|p| p.x).fold(f32::MAX, f32::min);
        assert!(min_x < -27.0, "tail fin past the tail-fin nodes: {min_x}");
        let height = body.iter().map(|p| p.z.abs()).fold(0.0, f32::max);
        let width = body.iter().map(|p| p.y.abs()).fold(0.0, f32::max);
        assert!(
            width < 0.6 * height,
            "laterally compressed: {width} vs {height}"
        );
        // Fins stand out above the back and below the belly; one each side.
        assert!(fins.iter().any(|p| p.z > height + 1.0 && p.x < -5.0));
        assert!(fins.iter().any(|p| p.z < -height && p.x < -10.0));
        assert!(fins.iter().any(|p| p.y > width + 1.0) && fins.iter().any(|p| p.y < -width - 1.0));
        // Eyes near the head, both sides, outside the body.
        for side in [1.0_f32, -1.0] {
            let eye: Vec<&Vec3> = eyes.iter().filter(|p| p.y * side > 0.0).collect();
            assert!(!eye.is_empty());
            assert!(eye.iter().all(|p| p.x > -4.0 && p.x < -1.0 && p.z > -0.5));
        }
    }

    #[test]
    fn the_shark_has_a_pointed_snout_a_tall_dorsal_and_a_heterocercal_tail() {
        let skin = BodySkin::new(BodyShape::Shark);
        let body = points(&skin, Material::SkinShark);
        let fins = points(&skin, Material::SkinSharkFin);
        let half_height_at = |x0: f32, x1: f32| {
            body.iter()
                .filter(|p| (x1..=x0).contains(&p.x))
                .map(|p| p.z.abs())
                .fold(0.0, f32::max)
        };
        let deepest = half_height_at(-5.0, -12.0);
        assert!(half_height_at(0.0, -0.8) < 0.35 * deepest, "pointed snout");
        // The tallest point is the first dorsal's apex, far above the back.
        let apex = fins
            .iter()
            .copied()
            .max_by(|a, b| a.z.total_cmp(&b.z))
            .unwrap();
        let back = body.iter().map(|p| p.z).fold(f32::MIN, f32::max);
        assert!(
            apex.z > back + 3.5 && (-12.0..-8.0).contains(&apex.x),
            "dorsal apex {apex}"
        );
        // Heterocercal: the upper lobe is longer and reaches further back.
        let tail: Vec<&Vec3> = fins.iter().filter(|p| p.x < -22.0).collect();
        let upper = tail.iter().max_by(|a, b| a.z.total_cmp(&b.z)).unwrap();
        let lower = tail.iter().min_by(|a, b| a.z.total_cmp(&b.z)).unwrap();
        let rearmost = tail.iter().map(|p| p.x).fold(f32::MAX, f32::min);
        assert!(
            upper.z > -2.0 * lower.z,
            "upper lobe {upper}, lower {lower}"
        );
        assert!(upper.x < lower.x - 1.5 && (upper.x - rearmost).abs() < 1e-4);
        // Pectorals reach well out to both sides.
        let width = body.iter().map(|p| p.y.abs()).fold(0.0, f32::max);
        assert!(fins.iter().any(|p| p.y > width + 3.0) && fins.iter().any(|p| p.y < -width - 3.0));
    }

    #[test]
    fn skin_coordinates_and_highlight_are_packed_in_the_material_word() {
        let skin = BodySkin::new(BodyShape::Shark);
        let nodes = REST_POSITIONS.map(placement(Vec3::ZERO, Quat::IDENTITY, 0.01));
        let mut mesh = Mesh::default();
        let look = BodyLook::shark(crate::render::fish_palette::shark_livery(0.5)).highlighted(1.0);
        skin.append_deformed(&nodes, &look, &mut mesh);
        for (v, out) in skin.vertices.iter().zip(&mesh.vertices) {
            let word = out.material;
            assert_eq!(word & MATERIAL_MASK, v.material & MATERIAL_MASK);
            assert_eq!((word >> HIGHLIGHT_SHIFT) & 7, HIGHLIGHT_LEVELS);
            let local = skin_local(v.position).to_array();
            for axis in 0..3 {
                let (lo, hi) = (SKIN_LOCAL_MIN[axis], SKIN_LOCAL_MAX[axis]);
                assert!(
                    (lo..=hi).contains(&local[axis]),
                    "{} outside the box",
                    v.position
                );
                let q = ((word >> (8 + 8 * axis)) & 255) as f32 / 255.0;
                assert!((lo + q * (hi - lo) - local[axis]).abs() <= 0.5 * (hi - lo) / 255.0 + 1e-6);
            }
            // Pattern strength in alpha.
            assert_eq!(out.color >> 24, (look.pattern * 255.0).round() as u32);
        }
        // Without a highlight the bits stay clear.
        let mut plain = Mesh::default();
        skin.append_deformed(&nodes, &look.highlighted(0.0), &mut plain);
        assert!(
            plain
                .vertices
                .iter()
                .all(|v| (v.material >> HIGHLIGHT_SHIFT) & 7 == 0)
        );
    }

    #[test]
    fn countershading_is_pale_below_and_dark_above() {
        let skin = BodySkin::new(BodyShape::Fish);
        let nodes = REST_POSITIONS.map(placement(Vec3::ZERO, Quat::IDENTITY, 0.01));
        let look = BodyLook::fish(crate::render::fish_palette::livery(0.3));
        let mut mesh = Mesh::default();
        skin.append_deformed(&nodes, &look, &mut mesh);
        let brightness = |c: u32| (c & 255) + ((c >> 8) & 255) + ((c >> 16) & 255);
        let extreme = |up: bool| {
            let i = (0..skin.vertices.len())
                .filter(|&i| skin.vertices[i].material & MATERIAL_MASK == Material::SkinFish as u32)
                .max_by(|&a, &b| {
                    let (za, zb) = (skin.vertices[a].position.z, skin.vertices[b].position.z);
                    if up {
                        za.total_cmp(&zb)
                    } else {
                        zb.total_cmp(&za)
                    }
                })
                .unwrap();
            brightness(mesh.vertices[i].color)
        };
        assert!(extreme(false) > extreme(true) + 60, "belly paler than back");
    }
}
