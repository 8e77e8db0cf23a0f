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

use super::banded_cholesky::{BandedCholesky, sym3_outer};
use super::body_layout::{NODE_COUNT, TRIANGLES};

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
    for tri in TRIANGLES {
        let [a, b, c] = tri;
        let area_normal = 0.5 * (positions[b] - positions[a]).cross(positions[c] - positions[a]);
        let area = area_normal.length();
        let n = area_normal.normalize_or_zero();
        let v_rel = (velocities[a] + velocities[b] + velocities[c]) / 3.0 - water_velocity;
        let normal_speed = n.dot(v_rel);
        if normal_speed <= 0.0 {
            continue;
        }
        let f = -drag_coefficient * area * normal_speed * n;
        for node in tri {
            forces[node] += f / 3.0;
        }
        if let Some((matrix, dt)) = system.as_mut() {
            let k = *dt * f64::from(drag_coefficient * area) / 9.0;
            let block = sym3_outer([f64::from(n.x), f64::from(n.y), f64::from(n.z)], k, 0.0);
            matrix.add_triangle_block(tri, &block);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::body::body_layout::REST_POSITIONS;

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
