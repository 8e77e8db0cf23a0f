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

/// A symmetric 3×3 block by its lower triangle, column by column:
/// (0,0), (1,0), (2,0), (1,1), (2,1), (2,2).
pub type Sym3 = [f64; 6];

/// The lower triangle of `scale · n nᵀ + diagonal · I`.
#[inline]
pub fn sym3_outer(n: [f64; 3], scale: f64, diagonal: f64) -> Sym3 {
    let [x, y, z] = n;
    let (sx, sy, sz) = (scale * x, scale * y, scale * z);
    [
        sx * x + diagonal,
        sy * x,
        sz * x,
        sy * y + diagonal,
        sz * y,
        sz * z + diagonal,
    ]
}

/// Smallest pivot accepted; a smaller one (never expected for an SPD system) is
/// replaced by this so the solve stays finite.
const MIN_PIVOT: f64 = 1e-30;

/// A symmetric banded matrix stored by its lower band, column by column, factorised
/// in place.
///
/// Layout (chosen for speed, see `fish_body.rs` for the measured cost): column j is
/// the contiguous array `band[j]`, `band[j][p]` = entry (j + p, j). The
/// factorisation is right-looking: once column j is scaled by its pivot, every later
/// column k it touches is updated by one contiguous `axpy` (column k −= L(k,j) ·
/// column j), which the compiler vectorises and which needs no bounds checks in the
/// inner loop. Only the actual extent of column j (its last non-zero row) is
/// swept and columns with L(k,j) = 0 are skipped, so the work follows the matrix's
/// envelope (about 60 % of the full band for the fish: a ring node couples back 4
/// to 7 nodes, not always 7). The subtractions happen in the same order as in the
/// textbook row-by-row (left-looking) form, so the result is bit for bit the same.
#[derive(Clone, Debug)]
pub struct BandedCholesky {
    /// `band[j][p]` holds entry (j + p, j); entries past the matrix stay zero.
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
        for column in &mut self.band {
            *column = [0.0; WIDTH];
        }
    }

    /// Adds `m` to the 3×3 block (node a, node b) and `mᵀ` to (b, a). For `a == b`, `m`
    /// must be symmetric (only its lower triangle is read). Couplings outside the band
    /// are ignored (debug-asserted).
    pub fn add_block(&mut self, a: usize, b: usize, m: [[f64; 3]; 3]) {
        debug_assert!(
            a.abs_diff(b) <= NODE_BANDWIDTH,
            "nodes {a},{b} outside band"
        );
        let (hi, lo, m) = if a >= b {
            (a, b, m)
        } else {
            (b, a, transpose(&m))
        };
        let offset = 3 * (hi - lo);
        let j = 3 * lo;
        if let Some(columns) = self.band.get_mut(j..j + 3) {
            for (c, column) in columns.iter_mut().enumerate() {
                for (r, row) in m.iter().enumerate() {
                    if hi == lo && r < c {
                        continue;
                    }
                    if let Some(slot) = column.get_mut(offset + r - c) {
                        *slot += row[c];
                    }
                }
            }
        }
    }

    /// Adds the symmetric block `s` to the diagonal blocks of nodes `a` and `b` and
    /// subtracts it from their coupling: the Jacobian pattern of a spring from a to b.
    #[inline]
    pub fn add_spring_block(&mut self, a: usize, b: usize, s: &Sym3) {
        self.add_diagonal_block(a, s);
        self.add_diagonal_block(b, s);
        let negative = s.map(|x| -x);
        if a > b {
            self.add_coupling_block(a, b, &negative);
        } else if b > a {
            self.add_coupling_block(b, a, &negative);
        }
    }

    /// Adds the symmetric block `s` to all nine blocks (p, q) of the three distinct
    /// nodes of `triangle`: the Jacobian pattern of a force that depends on the mean
    /// velocity of the triangle's nodes.
    #[inline]
    pub fn add_triangle_block(&mut self, triangle: [usize; 3], s: &Sym3) {
        for (i, &p) in triangle.iter().enumerate() {
            self.add_diagonal_block(p, s);
            for &q in &triangle[i + 1..] {
                if p > q {
                    self.add_coupling_block(p, q, s);
                } else if q > p {
                    self.add_coupling_block(q, p, s);
                }
            }
        }
    }

    /// Adds the lower triangle `s` to the diagonal block of `node`.
    #[inline]
    fn add_diagonal_block(&mut self, node: usize, s: &Sym3) {
        let j = 3 * node;
        if let Some([c0, c1, c2]) = self.band.get_mut(j..j + 3) {
            let [xx, yx, zx, yy, zy, zz] = *s;
            c0[0] += xx;
            c0[1] += yx;
            c0[2] += zx;
            c1[0] += yy;
            c1[1] += zy;
            c2[0] += zz;
        }
    }

    /// Adds the symmetric `s` to the block (row node `hi`, column node `lo`),
    /// `hi > lo`, of the lower triangle. Ignored outside the band (debug-asserted).
    #[inline]
    fn add_coupling_block(&mut self, hi: usize, lo: usize, s: &Sym3) {
        debug_assert!(hi > lo && hi - lo <= NODE_BANDWIDTH, "nodes {hi},{lo}");
        let o = 3 * (hi - lo);
        let j = 3 * lo;
        if o < 3 || o + 2 >= WIDTH {
            return;
        }
        if let Some([c0, c1, c2]) = self.band.get_mut(j..j + 3) {
            let [xx, yx, zx, yy, zy, zz] = *s;
            c0[o] += xx;
            c0[o + 1] += yx;
            c0[o + 2] += zx;
            c1[o - 1] += yx;
            c1[o] += yy;
            c1[o + 1] += zy;
            c2[o - 2] += zx;
            c2[o - 1] += zy;
            c2[o] += zz;
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
            let (done, rest) = self.band.split_at_mut(j + 1);
            let column = &mut done[j];
            let mut d = column[0];
            if d.is_nan() || d <= MIN_PIVOT {
                d = MIN_PIVOT;
                self.clamped_pivots += 1;
            }
            let d = d.sqrt();
            column[0] = d;
            // Last non-zero row of this column (the envelope), 0 if none below.
            let len = column.iter().rposition(|&x| x != 0.0).unwrap_or(0);
            for x in &mut column[1..=len] {
                *x /= d;
            }
            let column = &*column;
            for (off, target) in (1..=len).zip(rest.iter_mut()) {
                let l = column[off];
                if l == 0.0 {
                    continue;
                }
                for (t, &c) in target[..=len - off].iter_mut().zip(&column[off..=len]) {
                    *t -= l * c;
                }
            }
        }
    }

    /// Solves L Lᵀ x = rhs in place (call [`Self::factorize`] first).
    pub fn solve(&self, rhs: &mut [f64; SYSTEM_SIZE]) {
        // L y = rhs, column by column.
        for (j, column) in self.band.iter().enumerate() {
            let (done, rest) = rhs.split_at_mut(j + 1);
            let y = done[j] / column[0];
            done[j] = y;
            for (r, &l) in rest.iter_mut().zip(&column[1..]) {
                *r -= l * y;
            }
        }
        // Lᵀ x = y, from the last unknown back.
        for (i, column) in self.band.iter().enumerate().rev() {
            let (done, rest) = rhs.split_at_mut(i + 1);
            let mut s = done[i];
            for (&l, &x) in column[1..].iter().zip(rest.iter()) {
                s -= l * x;
            }
            done[i] = s / column[0];
        }
    }
}

fn transpose(m: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| m[c][r]))
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
