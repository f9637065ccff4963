//! The step matrices of the exact discretization ([`super::exact`]) and the products one
//! step takes with them.
//!
//! `(e^{hA}, h·φ1(hA)·E, h·φ2(hA)·E)` come from one exponential of the block matrix
//! `[[hA, hE, 0], [0, 0, I], [0, 0, 0]]`, whose top row of blocks is
//! `[e^{hA}, h·φ1·E, h·φ2·E]` (Al-Mohy & Higham 2011, Thm. 2.1; the Padé exponential of
//! `nalgebra`, scaling and squaring), E the unit columns of the remainder's rows.
//!
//! Written here rather than left to `nalgebra`'s dynamic `gemv`: the matrices are small
//! (a 3-DOF chain with two orders is 11 × 11), and a step runs once per output sample, so
//! the generic product's per-column dispatch was most of a step. The rows are taken in
//! blocks of [`LANES`] (the state padded with zeros to whole blocks), each block's part
//! of a matrix stored column after column, so a product runs each block of rows through
//! the columns in registers (the compiler turns the lanes into vector instructions),
//! adding column after column as `gemv` adds them: the results are `gemv`'s.

use nalgebra::DMatrix;

/// Rows handled at once.
const LANES: usize = 4;

/// One block of rows in one column.
type Lanes = [f64; LANES];

/// Length of an augmented state of `s` entries in the layout of the products: `s` rounded
/// up to whole [`LANES`] (the padding stays zero).
pub(super) fn padded_len(s: usize) -> usize {
    s.div_ceil(LANES) * LANES
}

/// The matrices of one step size, by blocks of rows.
#[derive(Debug, Clone)]
pub(super) struct StepMatrices {
    /// Augmented state length, `s`.
    size: usize,
    /// Remainder columns, `r`.
    columns: usize,
    /// First column of `e^{hA}` that reaches each block: 0 for the blocks that hold the
    /// plant's rows, `m` for those below (the constant and the oscillators evolve by
    /// themselves: the rest of their rows is zero in `A`, and kept zero here).
    first: Vec<usize>,
    /// `e^{hA}`: block `b`'s columns at `b·s ..`.
    phi: Vec<Lanes>,
    /// `h·φ1(hA)·E`: block `b`'s columns at `b·r ..`.
    gamma1: Vec<Lanes>,
    /// `h·φ2(hA)·E`, as `gamma1`.
    gamma2: Vec<Lanes>,
}

impl StepMatrices {
    /// The matrices of step `h` (s) for `ż = A·z + E·N`, `A` of size `s`, `plant` its first
    /// rows (the plant's state), `rows` the rows of E's unit columns.
    pub(super) fn new(a: &DMatrix<f64>, plant: usize, rows: &[usize], h: f64) -> Self {
        let (s, r) = (a.nrows(), rows.len());
        let mut w = DMatrix::<f64>::zeros(s + 2 * r, s + 2 * r);
        w.view_mut((0, 0), (s, s)).copy_from(&(a * h));
        for (c, row) in rows.iter().enumerate() {
            w[(*row, s + c)] = h;
            w[(s + c, s + r + c)] = 1.0;
        }
        let e = w.exp();
        let blocks = padded_len(s) / LANES;
        let by_blocks = |first_column: usize, width: usize, whole: bool| -> Vec<Lanes> {
            let mut out = vec![[0.0; LANES]; blocks * width];
            for (index, lanes) in out.iter_mut().enumerate() {
                let (b, j) = (index / width, index % width);
                for (k, entry) in lanes.iter_mut().enumerate() {
                    let i = b * LANES + k;
                    if i < s && (whole || i < plant || j >= plant) {
                        *entry = e[(i, first_column + j)];
                    }
                }
            }
            out
        };
        Self {
            size: s,
            columns: r,
            first: (0..blocks)
                .map(|b| if b * LANES < plant { 0 } else { plant })
                .collect(),
            phi: by_blocks(0, s, false),
            gamma1: by_blocks(s, r, true),
            gamma2: by_blocks(s + r, r, true),
        }
    }

    /// `out = e^{hA}·z + h·φ1(hA)·E·n`, the step's first stage (`n` the remainder at `z`,
    /// of length `r`); `z` and `out` of [`padded_len`].
    #[inline]
    pub(super) fn predict(&self, z: &[f64], n: &[f64], out: &mut [f64]) {
        match self.first.len() {
            1 => self.predict_fixed::<1>(z, n, out),
            2 => self.predict_fixed::<2>(z, n, out),
            3 => self.predict_fixed::<3>(z, n, out),
            4 => self.predict_fixed::<4>(z, n, out),
            _ => self.predict_any(z, n, out),
        }
    }

    /// [`Self::predict`] for `B` blocks of rows, all in registers at once: every column is
    /// added to every block (the zeros below the plant's rows add nothing).
    #[inline(always)]
    fn predict_fixed<const B: usize>(&self, z: &[f64], n: &[f64], out: &mut [f64]) {
        let (s, r) = (self.size, self.columns);
        let phi: [&[Lanes]; B] = std::array::from_fn(|b| &self.phi[b * s..(b + 1) * s]);
        let gamma: [&[Lanes]; B] = std::array::from_fn(|b| &self.gamma1[b * r..(b + 1) * r]);
        let mut acc = [[0.0; LANES]; B];
        for (j, &zj) in z[..s].iter().enumerate() {
            for b in 0..B {
                for k in 0..LANES {
                    acc[b][k] += phi[b][j][k] * zj;
                }
            }
        }
        for (j, &nj) in n[..r].iter().enumerate() {
            for b in 0..B {
                for k in 0..LANES {
                    acc[b][k] += gamma[b][j][k] * nj;
                }
            }
        }
        let (out, _) = out.as_chunks_mut::<LANES>();
        for (o, a) in out.iter_mut().zip(acc) {
            *o = a;
        }
    }

    /// [`Self::predict`] for any number of blocks, one block after the other.
    fn predict_any(&self, z: &[f64], n: &[f64], out: &mut [f64]) {
        let (s, r) = (self.size, self.columns);
        let (z, n) = (&z[..s], &n[..r]);
        let (out, _) = out.as_chunks_mut::<LANES>();
        let blocks = self.phi.chunks_exact(s).zip(&self.first);
        for (b, (o, (phi, &first))) in out.iter_mut().zip(blocks).enumerate() {
            let own = add_columns([0.0; LANES], &phi[first..], &z[first..]);
            *o = add_columns(own, &self.gamma1[b * r..(b + 1) * r], n);
        }
    }

    /// `out += h·φ2(hA)·E·n`, the step's correction (`n` the remainder's change over the
    /// step, of length `r`); `out` of [`padded_len`].
    #[inline]
    pub(super) fn correct(&self, n: &[f64], out: &mut [f64]) {
        let r = self.columns;
        let n = &n[..r];
        let (out, _) = out.as_chunks_mut::<LANES>();
        for (b, o) in out.iter_mut().enumerate() {
            *o = add_columns(*o, &self.gamma2[b * r..(b + 1) * r], n);
        }
    }
}

/// `acc + Σ_j columns[j]·x[j]`, column after column.
#[inline]
fn add_columns(mut acc: Lanes, columns: &[Lanes], x: &[f64]) -> Lanes {
    for (c, &xj) in columns.iter().zip(x) {
        for k in 0..LANES {
            acc[k] += c[k] * xj;
        }
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// The hand-written products give `gemv`'s results to the bit on a dense random-ish
    /// matrix with two remainder columns: two blocks of rows (the fixed-size path) and
    /// five (the general one).
    #[test]
    fn products_match_gemv_to_the_bit() {
        for (m, s) in [(4, 7), (12, 19)] {
            products_match_gemv(m, s);
        }
    }

    fn products_match_gemv(m: usize, s: usize) {
        let a = DMatrix::<f64>::from_fn(s, s, |i, j| {
            if i >= m && j < m {
                0.0
            } else {
                ((i * 7 + j * 3) % 11) as f64 * 0.37 - 1.5
            }
        });
        let rows = [m - 2, m - 1];
        let mats = StepMatrices::new(&a, m, &rows, 0.01);
        let z = DVector::<f64>::from_fn(s, |i, _| (i as f64 * 0.7).sin());
        let n = DVector::<f64>::from_vec(vec![0.3, -1.1]);
        let p = padded_len(s);
        let dense = |v: &[Lanes], width: usize| {
            DMatrix::from_fn(s, width, |i, j| v[(i / LANES) * width + j][i % LANES])
        };
        let phi = dense(&mats.phi, s);
        let (g1, g2) = (dense(&mats.gamma1, 2), dense(&mats.gamma2, 2));
        // The oscillator rows of Φ keep only their block.
        assert!((0..m).all(|j| (m..s).all(|i| phi[(i, j)] == 0.0)));
        let mut expected = DVector::<f64>::zeros(s);
        expected.rows_mut(0, m).gemv(1.0, &phi.rows(0, m), &z, 0.0);
        expected.rows_mut(m, s - m).gemv(
            1.0,
            &phi.view((m, m), (s - m, s - m)),
            &z.rows(m, s - m),
            0.0,
        );
        expected.gemv(1.0, &g1, &n, 1.0);
        expected.gemv(1.0, &g2, &n, 1.0);
        let mut zp = vec![0.0; p];
        zp[..s].copy_from_slice(z.as_slice());
        let mut out = vec![0.0; p];
        mats.predict(&zp, n.as_slice(), &mut out);
        mats.correct(n.as_slice(), &mut out);
        assert!(out[s..].iter().all(|v| *v == 0.0));
        let out = &out[..s];
        assert_eq!(out, expected.as_slice());
    }
}
