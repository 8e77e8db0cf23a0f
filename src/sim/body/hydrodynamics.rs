//! Water force on the body surface, Tu & Terzopoulos 1994 §3.2:
//! each surface triangle feels f = min[0, −A (n·v) n], A its area, n its outward unit
//! normal, v its velocity relative to the water (mean of its three nodes minus the
//! current); f/3 goes to each of its nodes.
//!
//! "min" is read as: water only pushes back on a face that moves *into* it
//! (n·v > 0); a face moving away feels nothing (no suction). This asymmetry is what
//! turns a beating tail into thrust (paper Fig. 4).
//!
//! For the implicit integrator the force is also differentiated with respect to the
//! node velocities: with the active set and the normals frozen over one step,
//! ∂f_a/∂v_b = −k A/9 · n nᵀ for every pair of nodes a, b of an active triangle. That
//! block is negative semi-definite, so moving it to the left-hand side keeps the
//! system positive definite and makes the water drag unconditionally stable even on
//! the light tail-fin nodes (m = 0.165).

use glam::Vec3;

use crate::sim::body::banded_cholesky::{BandedCholesky, sym3_outer};
use crate::sim::body::body_layout::{NODE_COUNT, TRIANGLE_COUNT, TRIANGLES};

/// Adds the water force of every triangle to `forces`, and, when `system` is given,
/// `dt · (−∂f/∂v)` to the implicit system matrix.
///
/// `drag_coefficient` (dimensionless, default 1.0 = the paper's formula) scales the
/// whole force; with the body scaling of `fish_body.rs` the force is in scaled force
/// units automatically (area × velocity ∝ length³).
pub fn add_water_forces(
    positions: &[Vec3; NODE_COUNT],
    velocities: &[Vec3; NODE_COUNT],
    water_velocity: Vec3,
    drag_coefficient: f32,
    forces: &mut [Vec3; NODE_COUNT],
    mut system: Option<(&mut BandedCholesky, f64)>,
) {
    // Gathered into arrays, the arithmetic as one loop over them (vectorised by the
    // compiler), then scattered to the nodes of the active triangles.
    let mut edge_b = [[0.0f32; TRIANGLE_COUNT]; 3];
    let mut edge_c = [[0.0f32; TRIANGLE_COUNT]; 3];
    let mut velocity = [[0.0f32; TRIANGLE_COUNT]; 3];
    for (t, &[a, b, c]) in TRIANGLES.iter().enumerate() {
        let (pa, pb, pc) = (positions[a], positions[b], positions[c]);
        [edge_b[0][t], edge_b[1][t], edge_b[2][t]] = (pb - pa).to_array();
        [edge_c[0][t], edge_c[1][t], edge_c[2][t]] = (pc - pa).to_array();
        let v_rel = (velocities[a] + velocities[b] + velocities[c]) / 3.0 - water_velocity;
        [velocity[0][t], velocity[1][t], velocity[2][t]] = v_rel.to_array();
    }
    let mut normal = [[0.0f32; TRIANGLE_COUNT]; 3];
    let mut area = [0.0f32; TRIANGLE_COUNT];
    let mut normal_speed = [0.0f32; TRIANGLE_COUNT];
    for t in 0..TRIANGLE_COUNT {
        let (bx, by, bz) = (edge_b[0][t], edge_b[1][t], edge_b[2][t]);
        let (cx, cy, cz) = (edge_c[0][t], edge_c[1][t], edge_c[2][t]);
        let nx = 0.5 * (by * cz - bz * cy);
        let ny = 0.5 * (bz * cx - bx * cz);
        let nz = 0.5 * (bx * cy - by * cx);
        let a = (nx * nx + ny * ny + nz * nz).sqrt();
        let inverse = 1.0 / a;
        // As `normalize_or_zero`: a degenerate triangle has no normal.
        let inverse = if inverse.is_finite() && inverse > 0.0 {
            inverse
        } else {
            0.0
        };
        let (nx, ny, nz) = (nx * inverse, ny * inverse, nz * inverse);
        normal[0][t] = nx;
        normal[1][t] = ny;
        normal[2][t] = nz;
        area[t] = a;
        normal_speed[t] = nx * velocity[0][t] + ny * velocity[1][t] + nz * velocity[2][t];
    }
    for (t, tri) in TRIANGLES.into_iter().enumerate() {
        if normal_speed[t] <= 0.0 {
            continue;
        }
        let n = Vec3::new(normal[0][t], normal[1][t], normal[2][t]);
        let f = -drag_coefficient * area[t] * normal_speed[t] * n;
        for node in tri {
            forces[node] += f / 3.0;
        }
        if let Some((matrix, dt)) = system.as_mut() {
            let k = *dt * f64::from(drag_coefficient * area[t]) / 9.0;
            let block = sym3_outer([f64::from(n.x), f64::from(n.y), f64::from(n.z)], k, 0.0);
            matrix.add_triangle_block(tri, &block);
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::body::body_layout::REST_POSITIONS;
    use crate::sim::body::hydrodynamics::*;

    #[test]
    fn water_only_resists_faces_moving_into_it() {
        // The whole rest body moving forward: the net force points backwards (drag),
        // and moving with the current gives no force at all.
        let v = [Vec3::X; NODE_COUNT];
        let mut f = [Vec3::ZERO; NODE_COUNT];
        add_water_forces(&REST_POSITIONS, &v, Vec3::ZERO, 1.0, &mut f, None);
        let total: Vec3 = f.iter().sum();
        assert!(total.x < 0.0 && total.y.abs() < 1e-4 && total.z.abs() < 1e-4);
        let mut g = [Vec3::ZERO; NODE_COUNT];
        add_water_forces(&REST_POSITIONS, &v, Vec3::X, 1.0, &mut g, None);
        assert!(g.iter().all(|x| *x == Vec3::ZERO));
        // Sideways motion is resisted far more than forward motion (flat sides).
        let mut s = [Vec3::ZERO; NODE_COUNT];
        add_water_forces(
            &REST_POSITIONS,
            &[Vec3::Y; NODE_COUNT],
            Vec3::ZERO,
            1.0,
            &mut s,
            None,
        );
        let side: Vec3 = s.iter().sum();
        assert!(side.y < 2.0 * total.x, "side {side} forward {total}");
    }
}
