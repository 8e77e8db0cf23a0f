//! Banded Cholesky (LLᵀ) factorisation and solve for the implicit Euler system of the
//! fish body, Tu & Terzopoulos 1994 §3.1 ("assembles the sparse stiffness matrix …
//! in skyline storage, then factorizes and solves … at every time step").
//!
//! Why by hand and why banded: the system has 23 × 3 = 69 unknowns. With nodes
//! numbered front to back, a spring or a surface triangle only couples nodes at most
//! [`NODE_BANDWIDTH`] = 7 apart, so the matrix is a band of half-width
//! 3·7 + 2 = 23 scalars — the paper's skyline profile is this band. A banded LLᵀ costs
//! about n·w²/2 ≈ 18 000 multiply-adds (a dense one n³/6 ≈ 55 000), needs no
//! pivoting because the matrix is symmetric positive definite (mass + damping +
//! clamped stiffness, see `fish_body.rs`), and lives in a fixed array, so a step
//! allocates nothing. A linear-algebra crate would add a dependency for 60 lines.

/// Number of scalar unknowns: 23 nodes × 3 components.
pub const SYSTEM_SIZE: usize = 69;
/// Largest index difference between two coupled nodes (ring k to ring k+1).
pub const NODE_BANDWIDTH: usize = 7;
/// Scalar half-bandwidth (excluding the diagonal).
pub const HALF_BANDWIDTH: usize = 3 * NODE_BANDWIDTH + 2;
const WIDTH: usize = HALF_BANDWIDTH + 1;

/// Smallest pivot accepted; a smaller one (never expected for an SPD system) is
/// replaced by this so the solve stays finite.
const MIN_PIVOT: f64 = 1e-30;

/// A symmetric banded matrix stored by its lower band, factorised in place.
#[derive(Clone, Debug)]
pub struct BandedCholesky {
    /// `band[i][k]` holds entry (i, i − k).
    band: [[f64; WIDTH]; SYSTEM_SIZE],
    /// Pivots that had to be clamped in the last factorisation (0 for an SPD system).
    pub clamped_pivots: usize,
}

impl Default for BandedCholesky {
    fn default() -> Self {
        Self {
            band: [[0.0; WIDTH]; SYSTEM_SIZE],
            clamped_pivots: 0,
        }
    }
}

impl BandedCholesky {
    /// Sets every entry to zero.
    pub fn clear(&mut self) {
        for row in &mut self.band {
            *row = [0.0; WIDTH];
        }
    }

    /// Adds `m` to the 3×3 block (node a, node b) and `mᵀ` to (b, a). For `a == b`, `m`
    /// must be symmetric. Couplings outside the band are ignored (debug-asserted).
    pub fn add_block(&mut self, a: usize, b: usize, m: [[f64; 3]; 3]) {
        debug_assert!(
            a.abs_diff(b) <= NODE_BANDWIDTH,
            "nodes {a},{b} outside band"
        );
        for (r, row) in m.iter().enumerate() {
            for (c, v) in row.iter().enumerate() {
                let (i, j) = (3 * a + r, 3 * b + c);
                if a == b && j > i {
                    continue;
                }
                let (i, j) = if i >= j { (i, j) } else { (j, i) };
                if let Some(slot) = self.band[i].get_mut(i - j) {
                    *slot += v;
                }
            }
        }
    }

    /// Adds `v` to the diagonal entry (i, i).
    pub fn add_diagonal(&mut self, i: usize, v: f64) {
        self.band[i][0] += v;
    }

    /// Factorises A = L Lᵀ in place.
    pub fn factorize(&mut self) {
        self.clamped_pivots = 0;
        for j in 0..SYSTEM_SIZE {
            let lo = j.saturating_sub(HALF_BANDWIDTH);
            let mut d = self.band[j][0];
            for k in lo..j {
                let l = self.band[j][j - k];
                d -= l * l;
            }
            if d.is_nan() || d <= MIN_PIVOT {
                d = MIN_PIVOT;
                self.clamped_pivots += 1;
            }
            let d = d.sqrt();
            self.band[j][0] = d;
            let hi = (j + HALF_BANDWIDTH).min(SYSTEM_SIZE - 1);
            for i in j + 1..=hi {
                let lo = i.saturating_sub(HALF_BANDWIDTH);
                let mut s = self.band[i][i - j];
                for k in lo..j {
                    s -= self.band[i][i - k] * self.band[j][j - k];
                }
                self.band[i][i - j] = s / d;
            }
        }
    }

    /// Solves L Lᵀ x = rhs in place (call [`Self::factorize`] first).
    #[allow(clippy::needless_range_loop)] // band index arithmetic reads better as loops
    pub fn solve(&self, rhs: &mut [f64; SYSTEM_SIZE]) {
        for i in 0..SYSTEM_SIZE {
            let lo = i.saturating_sub(HALF_BANDWIDTH);
            let mut s = rhs[i];
            for k in lo..i {
                s -= self.band[i][i - k] * rhs[k];
            }
            rhs[i] = s / self.band[i][0];
        }
        for i in (0..SYSTEM_SIZE).rev() {
            let hi = (i + HALF_BANDWIDTH).min(SYSTEM_SIZE - 1);
            let mut s = rhs[i];
            for k in i + 1..=hi {
                s -= self.band[k][k - i] * rhs[k];
            }
            rhs[i] = s / self.band[i][0];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_banded_spd_system_exactly() {
        // A 1-D chain of springs between neighbouring nodes plus a mass term, built by
        // blocks; compare A·x with the right-hand side.
        let mut m = BandedCholesky::default();
        let mut dense = vec![[0.0f64; SYSTEM_SIZE]; SYSTEM_SIZE];
        for node in 0..23 {
            let d = [
                [3.0 + node as f64, 0.5, 0.0],
                [0.5, 4.0, 0.2],
                [0.0, 0.2, 5.0],
            ];
            m.add_block(node, node, d);
            for r in 0..3 {
                for c in 0..3 {
                    dense[3 * node + r][3 * node + c] += d[r][c];
                }
            }
            for other in (node + 1)..(node + 8).min(23) {
                let o = [[-0.1, 0.02, 0.0], [0.0, -0.1, 0.03], [0.01, 0.0, -0.1]];
                m.add_block(node, other, o);
                for r in 0..3 {
                    for c in 0..3 {
                        dense[3 * node + r][3 * other + c] += o[r][c];
                        dense[3 * other + c][3 * node + r] += o[r][c];
                    }
                }
            }
        }
        let x_true: Vec<f64> = (0..SYSTEM_SIZE).map(|i| (i as f64 * 0.37).sin()).collect();
        let mut rhs = [0.0; SYSTEM_SIZE];
        for i in 0..SYSTEM_SIZE {
            rhs[i] = (0..SYSTEM_SIZE).map(|j| dense[i][j] * x_true[j]).sum();
        }
        m.factorize();
        m.solve(&mut rhs);
        assert_eq!(m.clamped_pivots, 0);
        for i in 0..SYSTEM_SIZE {
            assert!((rhs[i] - x_true[i]).abs() < 1e-10, "{i}");
        }
    }
}
