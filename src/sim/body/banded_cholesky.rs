//! Banded Cholesky (LLᵀ) factorisation and solve for the implicit Euler system of the
//! fish body, Tu & Terzopoulos 1994 §3.1 ("assembles the sparse stiffness matrix …
//! in skyline storage, then factorizes and solves … at every time step").
//!
//! Why by hand and why banded: the system has 23 × 3 = 69 unknowns. With nodes
//! numbered front to back, a spring or a surface triangle only couples nodes at most
//! [`NODE_BANDWIDTH`] = 8 apart (the tail-fin tips reach back to ring 4, see
//! `body_layout.rs`; every other node at most 7), so the matrix is a band of
//! half-width 3·8 + 2 = 26 scalars. Within it the factorisation only touches the envelope (the
//! paper's skyline): each ring node couples back to 3 of the 4 nodes of the ring in
//! front, so a row reaches back 4 to 7 nodes, not always 7, and Cholesky fills in
//! nothing outside the envelope. That is about 9 300 multiply-adds per
//! factorisation (the full band 14 700, a dense one n³/6 ≈ 55 000); no pivoting is
//! needed because the matrix is symmetric positive definite (mass + damping +
//! clamped stiffness, see `fish_body.rs`), and it lives in a fixed array, so a step
//! allocates nothing. A linear-algebra crate would add a dependency for a few hundred lines.
//!
//! Measured (`cargo run --release --bin shoal-census -- factorize-and-solve-cost`,
//! native release, a matrix with the fish's pattern, [`fish_like`]): about 3.2 µs per factorisation and 1.0 µs per solve; the layout
//! and loop structure behind those figures are described on [`BandedCholesky`].

/// Number of scalar unknowns: 23 nodes × 3 components.
pub const SYSTEM_SIZE: usize = 69;
/// Largest index difference between two coupled nodes (a tail-fin tip to ring 4).
pub const NODE_BANDWIDTH: usize = 8;
/// Scalar half-bandwidth (excluding the diagonal).
pub const HALF_BANDWIDTH: usize = 3 * NODE_BANDWIDTH + 2;
/// Stored length of a column: the band plus two zero entries, so that the three
/// columns of a node can be swept together up to the last row of the third.
const WIDTH: usize = HALF_BANDWIDTH + 3;

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
/// Layout (chosen for speed, see the module doc of `fish_body.rs` for the measured
/// cost): column j is the contiguous array `band[j]`, `band[j][p]` = entry (j + p, j),
/// padded with zeros. The factorisation is right-looking and goes one node (three
/// columns) at a time: once a node's columns are scaled by their pivots, every later
/// column k they touch is updated in one contiguous sweep (column k loses
/// L(k, j) column j, L(k, j+1) column j+1 and L(k, j+2) column j+2 at once), which
/// the compiler vectorises with no bounds checks in the loop. Each sweep stops at the last non-zero row of the
/// node's columns and columns with zero multipliers are skipped, so the work follows
/// the envelope. The solve goes a node at a time too and multiplies by stored
/// reciprocal pivots.
#[derive(Clone, Debug)]
pub struct BandedCholesky {
    /// `band[j][p]` holds entry (j + p, j); entries past the matrix stay zero.
    band: [[f64; WIDTH]; SYSTEM_SIZE],
    /// 1 / L(j, j), set by [`Self::factorize`].
    inverse_pivots: [f64; SYSTEM_SIZE],
    /// Last non-zero row of column j of L, relative to j (its envelope), set by
    /// [`Self::factorize`].
    extents: [usize; SYSTEM_SIZE],
    /// Pivots that had to be clamped in the last factorisation (0 for an SPD system).
    pub clamped_pivots: usize,
}

impl Default for BandedCholesky {
    fn default() -> Self {
        Self {
            band: [[0.0; WIDTH]; SYSTEM_SIZE],
            inverse_pivots: [1.0; SYSTEM_SIZE],
            extents: [0; SYSTEM_SIZE],
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
                    let p = offset + r - c;
                    if let Some(slot) = column.get_mut(p).filter(|_| p <= HALF_BANDWIDTH) {
                        *slot += row[c];
                    }
                }
            }
        }
    }

    /// Adds the symmetric block `s` to the diagonal blocks of nodes `a` and `b` and
    /// subtracts it from their coupling: the Jacobian pattern of a spring from a to b.
    #[inline(always)]
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
    #[inline(always)]
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
    #[inline(always)]
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
    #[inline(always)]
    fn add_coupling_block(&mut self, hi: usize, lo: usize, s: &Sym3) {
        debug_assert!(hi > lo && hi - lo <= NODE_BANDWIDTH, "nodes {hi},{lo}");
        let o = 3 * (hi - lo);
        let j = 3 * lo;
        if o < 3 || o + 2 > HALF_BANDWIDTH {
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
        for j0 in (0..SYSTEM_SIZE).step_by(3) {
            let (done, rest) = self.band.split_at_mut(j0 + 3);
            let Some([c0, c1, c2]) = done.get_mut(j0..) else {
                continue;
            };
            // The node's own three columns, each with the updates of the previous
            // nodes already applied.
            let (d0, clamped) = pivot(c0[0]);
            self.clamped_pivots += clamped;
            let len0 = scale_column(c0, d0);
            axpy(c1, c0[1], sweep(c0, 1, len0));
            axpy(c2, c0[2], sweep(c0, 2, len0));
            let (d1, clamped) = pivot(c1[0]);
            self.clamped_pivots += clamped;
            let len1 = scale_column(c1, d1);
            axpy(c2, c1[1], sweep(c1, 1, len1));
            let (d2, clamped) = pivot(c2[0]);
            self.clamped_pivots += clamped;
            let len2 = scale_column(c2, d2);
            self.inverse_pivots[j0..j0 + 3].copy_from_slice(&[1.0 / d0, 1.0 / d1, 1.0 / d2]);
            self.extents[j0..j0 + 3].copy_from_slice(&[len0, len1, len2]);
            // Every later column k the node touches: column k −= L(k, j0) column j0 +
            // L(k, j0+1) column j0+1 + L(k, j0+2) column j0+2, one sweep.
            let last = (len0).max(len1 + 1).max(len2 + 2);
            let (c0, c1, c2) = (&*c0, &*c1, &*c2);
            for (q0, target) in (3..=last).zip(rest.iter_mut()) {
                let (l0, l1, l2) = (c0[q0], c1[q0 - 1], c2[q0 - 2]);
                if l0 == 0.0 && l1 == 0.0 && l2 == 0.0 {
                    continue;
                }
                let n = last + 1 - q0;
                let sources = c0[q0..q0 + n]
                    .iter()
                    .zip(&c1[q0 - 1..q0 - 1 + n])
                    .zip(&c2[q0 - 2..q0 - 2 + n]);
                for (t, ((&a, &b), &c)) in target[..n].iter_mut().zip(sources) {
                    *t -= l0 * a + l1 * b + l2 * c;
                }
            }
        }
    }

    /// Solves L Lᵀ x = rhs in place (call [`Self::factorize`] first).
    pub fn solve(&self, rhs: &mut [f64; SYSTEM_SIZE]) {
        // L y = rhs, three columns (one node) at a time.
        for j0 in (0..SYSTEM_SIZE).step_by(3) {
            let [c0, c1, c2] = [&self.band[j0], &self.band[j0 + 1], &self.band[j0 + 2]];
            let [i0, i1, i2] = [
                self.inverse_pivots[j0],
                self.inverse_pivots[j0 + 1],
                self.inverse_pivots[j0 + 2],
            ];
            let (done, rest) = rhs.split_at_mut(j0 + 3);
            let y0 = done[j0] * i0;
            let y1 = (done[j0 + 1] - c0[1] * y0) * i1;
            let y2 = (done[j0 + 2] - c0[2] * y0 - c1[1] * y1) * i2;
            done[j0..].copy_from_slice(&[y0, y1, y2]);
            let last = self.block_extent(j0);
            let n = (last + 1).saturating_sub(3).min(rest.len());
            let sources = c0[3..3 + n].iter().zip(&c1[2..2 + n]).zip(&c2[1..1 + n]);
            for (r, ((&a, &b), &c)) in rest[..n].iter_mut().zip(sources) {
                *r -= a * y0 + b * y1 + c * y2;
            }
        }
        // Lᵀ x = y, from the last node back.
        for j0 in (0..SYSTEM_SIZE).step_by(3).rev() {
            let [c0, c1, c2] = [&self.band[j0], &self.band[j0 + 1], &self.band[j0 + 2]];
            let (done, rest) = rhs.split_at_mut(j0 + 3);
            let last = self.block_extent(j0);
            let n = (last + 1).saturating_sub(3).min(rest.len());
            let (mut s0, mut s1, mut s2) = (0.0, 0.0, 0.0);
            let sources = c0[3..3 + n].iter().zip(&c1[2..2 + n]).zip(&c2[1..1 + n]);
            for (&x, ((&a, &b), &c)) in rest[..n].iter().zip(sources) {
                s0 += a * x;
                s1 += b * x;
                s2 += c * x;
            }
            let x2 = (done[j0 + 2] - s2) * self.inverse_pivots[j0 + 2];
            let x1 = (done[j0 + 1] - s1 - c1[1] * x2) * self.inverse_pivots[j0 + 1];
            let x0 = (done[j0] - s0 - c0[1] * x1 - c0[2] * x2) * self.inverse_pivots[j0];
            done[j0..].copy_from_slice(&[x0, x1, x2]);
        }
    }

    /// Last row touched by the three columns from `j0` on, relative to `j0`.
    fn block_extent(&self, j0: usize) -> usize {
        let e = &self.extents[j0..j0 + 3];
        e[0].max(e[1] + 1).max(e[2] + 2)
    }
}

/// sqrt of a pivot, clamped to [`MIN_PIVOT`] (second value 1 if it was clamped).
#[inline]
fn pivot(d: f64) -> (f64, usize) {
    if d.is_nan() || d <= MIN_PIVOT {
        (MIN_PIVOT.sqrt(), 1)
    } else {
        (d.sqrt(), 0)
    }
}

/// Sets the column's diagonal to `d`, divides the rest of it by `d`; returns its
/// extent (last non-zero entry).
#[inline]
fn scale_column(column: &mut [f64; WIDTH], d: f64) -> usize {
    column[0] = d;
    let len = column.iter().rposition(|&x| x != 0.0).unwrap_or(0);
    let inverse = 1.0 / d;
    for x in &mut column[1..=len] {
        *x *= inverse;
    }
    len
}

/// Entries `from..=len` of a column (empty if `from > len`).
#[inline]
fn sweep(column: &[f64; WIDTH], from: usize, len: usize) -> &[f64] {
    column.get(from..=len).unwrap_or(&[])
}

/// target −= l · source, over the shorter of the two.
#[inline]
fn axpy(target: &mut [f64], l: f64, source: &[f64]) {
    if l != 0.0 {
        for (t, &s) in target.iter_mut().zip(source) {
            *t -= l * s;
        }
    }
}

fn transpose(m: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| m[c][r]))
}

/// A matrix with the fish's pattern and magnitudes: node masses + h·damping on
/// the diagonal, an h²K-sized block of a pseudo-random direction per spring and
/// a water-sized block per triangle. The solver's tests solve it and its cost
/// script (`factorize-and-solve-cost`, `body/census.rs`) times it.
#[cfg(not(target_arch = "wasm32"))]
pub fn fish_like(seed: u64) -> BandedCholesky {
    use crate::sim::body::body_layout::{MASSES, SPRINGS, TRIANGLES};
    let mut state = seed;
    let mut random = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let mut m = BandedCholesky::default();
    for (i, mass) in MASSES.iter().enumerate() {
        m.add_diagonal_block(i, &sym3_outer([0.0; 3], 0.0, f64::from(*mass) + 0.01));
    }
    let mut unit = || {
        let v = [random(), random(), random()];
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt().max(1e-9);
        v.map(|x| x / l)
    };
    for sp in SPRINGS {
        let block = sym3_outer(unit(), 2.3, 0.4);
        m.add_spring_block(sp.a, sp.b, &block);
    }
    for (k, tri) in TRIANGLES.into_iter().enumerate() {
        if k % 2 == 0 {
            m.add_triangle_block(tri, &sym3_outer(unit(), 0.3, 0.0));
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use crate::sim::body::banded_cholesky::*;
    use crate::sim::common::fmath;

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
        let x_true: Vec<f64> = (0..SYSTEM_SIZE)
            .map(|i| fmath::sin_f64(i as f64 * 0.37))
            .collect();
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

    #[test]
    fn solves_a_fish_shaped_system_like_a_dense_solver() {
        let m = fish_like(7);
        let dense: Vec<Vec<f64>> = (0..SYSTEM_SIZE)
            .map(|i| {
                (0..SYSTEM_SIZE)
                    .map(|j| {
                        let (hi, lo) = (i.max(j), i.min(j));
                        m.band[lo].get(hi - lo).copied().unwrap_or(0.0)
                    })
                    .collect()
            })
            .collect();
        let x_true: Vec<f64> = (0..SYSTEM_SIZE)
            .map(|i| fmath::cos_f64(i as f64 * 0.61))
            .collect();
        let mut rhs = [0.0; SYSTEM_SIZE];
        for i in 0..SYSTEM_SIZE {
            rhs[i] = (0..SYSTEM_SIZE).map(|j| dense[i][j] * x_true[j]).sum();
        }
        let mut f = m.clone();
        f.factorize();
        f.solve(&mut rhs);
        assert_eq!(f.clamped_pivots, 0);
        for i in 0..SYSTEM_SIZE {
            assert!((rhs[i] - x_true[i]).abs() < 1e-10, "{i}: {}", rhs[i]);
        }
    }
}
