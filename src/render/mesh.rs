//! Triangle meshes built on the CPU once: the fish body, rocks, pillars, the sand
//! floor and the tank frame.
//!
//! Everything here is plain geometry (no GPU types), so it is tested natively: normals
//! are unit length, the fish points along +x, rocks are closed.

use bytemuck::{Pod, Zeroable};
use glam::{Vec3, vec3};

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
    /// Fish eye: near black with a glint.
    FishEye = 5,
}

/// One vertex of a static or fish mesh. 32 bytes.
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C)]
pub struct Vertex {
    pub position: [f32; 3],
    pub material: u32,
    pub normal: [f32; 3],
    /// Packed RGBA8 colour (rocks, pillars); unused for fish.
    pub color: u32,
}

/// An indexed triangle list.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

/// Packs a linear-ish RGB colour into RGBA8.
pub fn pack_rgb(rgb: [f32; 3]) -> u32 {
    let c = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u32;
    c(rgb[0]) | (c(rgb[1]) << 8) | (c(rgb[2]) << 16) | (255 << 24)
}

impl Mesh {
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

/// Half height and half width of the fish body at `x` ∈ [−0.5, 0.5] (tail root to
/// snout), in body lengths. A streamlined, laterally compressed profile: deepest a
/// third of the way back from the snout, a narrow caudal peduncle.
fn fish_profile(x: f32) -> (f32, f32) {
    let t = (0.5 - x).clamp(0.0, 1.0); // 0 at the snout, 1 at the tail root
    let nose = (t / 0.28).min(1.0);
    let rounded_nose = (1.0 - (1.0 - nose).powi(2)).sqrt();
    let taper = 1.0 - ((t - 0.28).max(0.0) / 0.72).powf(1.3) * 0.86;
    let half_height = 0.15 * rounded_nose * taper + 0.012;
    let half_width = half_height * 0.55;
    (half_height, half_width)
}

/// The fish mesh, one body length long, snout at +x = 0.5, tail fin to x ≈ −0.74,
/// back up (+y). The vertex shader bends it with the tail beat.
pub fn fish() -> Mesh {
    const RINGS: usize = 18;
    const SEGMENTS: usize = 14;
    let mut mesh = Mesh::default();
    let xs: Vec<f32> = (0..=RINGS)
        .map(|i| 0.5 - (i as f32 / RINGS as f32).powf(1.15))
        .collect();
    let ring_point = |x: f32, angle: f32| {
        let (h, w) = fish_profile(x);
        vec3(x, h * angle.sin() - 0.01, w * angle.cos())
    };
    // Body rings. Normals from finite differences of the surface.
    let snout = mesh.push(vec3(0.5, -0.01, 0.0), Vec3::X, Material::FishBody, 0);
    let mut ring_starts = Vec::new();
    for &x in &xs[1..] {
        ring_starts.push(mesh.vertices.len() as u32);
        for s in 0..SEGMENTS {
            let angle = s as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
            let p = ring_point(x, angle);
            let dx = 0.01;
            let da = 0.01;
            let along = ring_point(x - dx, angle) - ring_point(x + dx, angle);
            let around = ring_point(x, angle + da) - ring_point(x, angle - da);
            let normal = around.cross(along);
            mesh.push(p, normal, Material::FishBody, 0);
        }
    }
    let seg = SEGMENTS as u32;
    for s in 0..seg {
        mesh.triangle(snout, ring_starts[0] + (s + 1) % seg, ring_starts[0] + s);
    }
    for pair in ring_starts.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        for s in 0..seg {
            let s1 = (s + 1) % seg;
            mesh.triangle(a + s, a + s1, b + s);
            mesh.triangle(a + s1, b + s1, b + s);
        }
    }
    // Close the tail root with a fan.
    let tail_x = xs[RINGS];
    let tail_center = mesh.push(vec3(tail_x, -0.01, 0.0), -Vec3::X, Material::FishBody, 0);
    let last = *ring_starts.last().unwrap_or(&0);
    for s in 0..seg {
        mesh.triangle(tail_center, last + s, last + (s + 1) % seg);
    }

    // Forked caudal (tail) fin, in the vertical plane.
    let root = tail_x + 0.03;
    for (tip, notch) in [
        (vec3(-0.74, 0.17, 0.0), vec3(-0.62, 0.02, 0.0)),
        (vec3(-0.74, -0.17, 0.0), vec3(-0.62, -0.02, 0.0)),
    ] {
        let root_edge = vec3(root, tip.y.signum() * 0.035, 0.0);
        mesh.fin_triangle(vec3(root, 0.0, 0.0), root_edge, tip, Material::FishFin);
        mesh.fin_triangle(vec3(root, 0.0, 0.0), tip, notch, Material::FishFin);
    }
    // Dorsal fin.
    let (h_dorsal, _) = fish_profile(0.05);
    mesh.fin_triangle(
        vec3(0.12, h_dorsal - 0.02, 0.0),
        vec3(-0.2, h_dorsal * 0.8 - 0.02, 0.0),
        vec3(-0.12, h_dorsal + 0.11, 0.0),
        Material::FishFin,
    );
    // Anal fin.
    mesh.fin_triangle(
        vec3(-0.12, -0.09, 0.0),
        vec3(-0.3, -0.05, 0.0),
        vec3(-0.27, -0.14, 0.0),
        Material::FishFin,
    );
    // Pectoral fins, angled out and back from behind the gills.
    for side in [-1.0_f32, 1.0] {
        let (_, w) = fish_profile(0.22);
        mesh.fin_triangle(
            vec3(0.24, -0.05, side * w * 0.9),
            vec3(0.16, -0.06, side * w * 0.9),
            vec3(0.08, -0.1, side * (w + 0.09)),
            Material::FishFin,
        );
    }
    // Eyes: small domes on each side of the head.
    for side in [-1.0_f32, 1.0] {
        let (h, w) = fish_profile(0.38);
        let center = vec3(0.38, h * 0.35, side * w * 0.92);
        let radius = 0.028;
        let ring = 8;
        let apex = mesh.push(
            center + vec3(0.0, 0.0, side * radius),
            vec3(0.0, 0.0, side),
            Material::FishEye,
            0,
        );
        let first = mesh.vertices.len() as u32;
        for k in 0..ring {
            let a = k as f32 / ring as f32 * std::f32::consts::TAU;
            let offset = vec3(a.cos() * radius, a.sin() * radius, 0.0);
            mesh.push(
                center + offset,
                offset.normalize_or_zero() + vec3(0.0, 0.0, side * 0.6),
                Material::FishEye,
                0,
            );
        }
        for k in 0..ring {
            let (a, b) = (first + k, first + (k + 1) % ring);
            if side > 0.0 {
                mesh.triangle(apex, a, b);
            } else {
                mesh.triangle(apex, b, a);
            }
        }
    }
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
    if crate::sim::obstacle::signed_area_m2(&corners) < 0.0 {
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
