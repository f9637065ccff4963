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
//! the columns in registers (the compiler turns the lanes into vector instructions). Only
//! the plant's rows are taken so; the constant's and the oscillators' rows below them
//! are rotated by their few nonzeros. Up to four blocks of plant rows (a plant state of
//! up to 16 entries) the even and odd columns go to two accumulators, so the sums differ
//! from `gemv`'s by rounding only; beyond that, column after column as `gemv` adds them.

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

/// The matrices of one step size: the plant's rows by blocks, the rows below (the
/// constant and the oscillators) by their few nonzeros.
#[derive(Debug, Clone)]
pub(super) struct StepMatrices {
    /// Augmented state length, `s`.
    size: usize,
    /// Remainder columns, `r`.
    columns: usize,
    /// Blocks of rows that hold the plant's rows, `⌈m / LANES⌉`.
    blocks: usize,
    /// `e^{hA}` in the plant's blocks: block `b`'s columns at `b·s ..` (entries of rows
    /// past the plant's in its last block kept only in their own columns, `j ≥ m`).
    phi: Vec<Lanes>,
    /// `h·φ1(hA)·E` in the plant's blocks: block `b`'s columns at `b·r ..`.
    gamma1: Vec<Lanes>,
    /// `h·φ2(hA)·E`, as `gamma1`.
    gamma2: Vec<Lanes>,
    /// `(row, column, value, first of its row)`: the nonzeros of `e^{hA}` in the rows
    /// below the plant's blocks, row by row. The constant and each oscillator evolve by
    /// themselves (the rest of their rows is zero in `A`, and their `φ·E` rows are zero),
    /// so a row holds one or two (at least its diagonal or its rotation's sine).
    below: Vec<(usize, usize, f64, bool)>,
}

impl StepMatrices {
    /// The matrices of step `h` (s) for `ż = A·z + E·N`, `A` of size `s`, `plant` its first
    /// rows (the plant's state), `rows` the rows of E's unit columns (all within `plant`).
    pub(super) fn new(a: &DMatrix<f64>, plant: usize, rows: &[usize], h: f64) -> Self {
        let (s, r) = (a.nrows(), rows.len());
        let e = block_exponential(a, rows, h);
        let blocks = plant.div_ceil(LANES);
        let by_blocks = |first_column: usize, width: usize| -> Vec<Lanes> {
            let mut out = vec![[0.0; LANES]; blocks * width];
            for (index, lanes) in out.iter_mut().enumerate() {
                let (b, j) = (index / width, index % width);
                for (k, entry) in lanes.iter_mut().enumerate() {
                    let i = b * LANES + k;
                    if i < plant || (i < s && first_column == 0 && j >= plant) {
                        *entry = e[(i, first_column + j)];
                    }
                }
            }
            out
        };
        let below = (blocks * LANES..s)
            .flat_map(|i| (plant..s).map(move |j| (i, j)))
            .map(|(i, j)| (i, j, e[(i, j)]))
            .filter(|(_, _, v)| *v != 0.0)
            .scan(None, |row, (i, j, v)| {
                let starts_row = *row != Some(i);
                *row = Some(i);
                Some((i, j, v, starts_row))
            })
            .collect();
        Self {
            size: s,
            columns: r,
            blocks,
            phi: by_blocks(0, s),
            gamma1: by_blocks(s, r),
            gamma2: by_blocks(s + r, r),
            below,
        }
    }

    /// `out = e^{hA}·z + h·φ1(hA)·E·n`, the step's first stage (`n` the remainder at `z`,
    /// of length `r`); `z` and `out` of [`padded_len`].
    #[inline]
    pub(super) fn predict(&self, z: &[f64], n: &[f64], out: &mut [f64]) {
        match self.blocks {
            1 => self.predict_fixed::<1>(z, n, out),
            2 => self.predict_fixed::<2>(z, n, out),
            3 => self.predict_fixed::<3>(z, n, out),
            4 => self.predict_fixed::<4>(z, n, out),
            _ => self.predict_any(z, n, out),
        }
        for &(i, j, v, starts_row) in &self.below {
            if starts_row {
                out[i] = v * z[j];
            } else {
                out[i] += v * z[j];
            }
        }
    }

    /// [`Self::predict`]'s plant rows for `B` blocks, all in registers at once.
    #[inline(always)]
    fn predict_fixed<const B: usize>(&self, z: &[f64], n: &[f64], out: &mut [f64]) {
        let (s, r) = (self.size, self.columns);
        let phi: [&[Lanes]; B] = std::array::from_fn(|b| &self.phi[b * s..(b + 1) * s]);
        let gamma: [&[Lanes]; B] = std::array::from_fn(|b| &self.gamma1[b * r..(b + 1) * r]);
        // Even and odd columns in two accumulators: one chain of additions through all
        // `s` columns was the step's latency; two halve it.
        let mut even = [[0.0; LANES]; B];
        let mut odd = [[0.0; LANES]; B];
        let (pairs, last) = z[..s].as_chunks::<2>();
        for (i, &[z0, z1]) in pairs.iter().enumerate() {
            for b in 0..B {
                let (c0, c1) = (&phi[b][2 * i], &phi[b][2 * i + 1]);
                for k in 0..LANES {
                    even[b][k] += c0[k] * z0;
                    odd[b][k] += c1[k] * z1;
                }
            }
        }
        if let [zl] = last {
            for b in 0..B {
                for k in 0..LANES {
                    even[b][k] += phi[b][s - 1][k] * zl;
                }
            }
        }
        for (j, &nj) in n[..r].iter().enumerate() {
            for b in 0..B {
                for k in 0..LANES {
                    odd[b][k] += gamma[b][j][k] * nj;
                }
            }
        }
        let (out, _) = out.as_chunks_mut::<LANES>();
        for ((o, e), d) in out.iter_mut().zip(even).zip(odd) {
            for k in 0..LANES {
                o[k] = e[k] + d[k];
            }
        }
    }

    /// [`Self::predict`]'s plant rows for any number of blocks, one block after the other,
    /// column after column.
    fn predict_any(&self, z: &[f64], n: &[f64], out: &mut [f64]) {
        let (s, r) = (self.size, self.columns);
        let (z, n) = (&z[..s], &n[..r]);
        let (out, _) = out.as_chunks_mut::<LANES>();
        for (b, (o, phi)) in out.iter_mut().zip(self.phi.chunks_exact(s)).enumerate() {
            let own = add_columns([0.0; LANES], phi, z);
            *o = add_columns(own, &self.gamma1[b * r..(b + 1) * r], n);
        }
    }

    /// `out += h·φ2(hA)·E·n`, the step's correction (`n` the remainder's change over the
    /// step, of length `r`; it reaches the plant's rows only); `out` of [`padded_len`].
    #[inline]
    pub(super) fn correct(&self, n: &[f64], out: &mut [f64]) {
        let r = self.columns;
        let n = &n[..r];
        let (out, _) = out.as_chunks_mut::<LANES>();
        for (b, o) in out.iter_mut().take(self.blocks).enumerate() {
            *o = add_columns(*o, &self.gamma2[b * r..(b + 1) * r], n);
        }
    }
}

/// The exponential of `[[hA, hE, 0], [0, 0, I], [0, 0, 0]]`, whose top row of blocks is
/// `[e^{hA}, h·φ1(hA)·E, h·φ2(hA)·E]`.
fn block_exponential(a: &DMatrix<f64>, rows: &[usize], h: f64) -> DMatrix<f64> {
    let (s, r) = (a.nrows(), rows.len());
    let mut w = DMatrix::<f64>::zeros(s + 2 * r, s + 2 * r);
    w.view_mut((0, 0), (s, s)).copy_from(&(a * h));
    for (c, row) in rows.iter().enumerate() {
        w[(*row, s + c)] = h;
        w[(s + c, s + r + c)] = 1.0;
    }
    w.exp()
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

    /// The hand-written products against `gemv` on the block exponential itself, for a
    /// dense random-ish plant block with two remainder columns and, below it, the
    /// constant and two oscillators: one, two and five blocks of plant rows (the
    /// fixed-size paths, which sum in another order: within the bound of rounding,
    /// `(s + 4)·ε` times the sum of the terms' magnitudes; and the general one, to the
    /// bit).
    #[test]
    fn products_match_gemv() {
        for m in [3, 6, 18] {
            products_match_gemv_at(m);
        }
    }

    fn products_match_gemv_at(m: usize) {
        let s = m + 5;
        let mut a = DMatrix::<f64>::from_fn(s, s, |i, j| {
            if i >= m {
                0.0
            } else {
                ((i * 7 + j * 3) % 11) as f64 * 0.37 - 1.5
            }
        });
        for (c, q) in [(m + 1, 3.0), (m + 3, 5.0)] {
            a[(c, c + 1)] = -q;
            a[(c + 1, c)] = q;
        }
        let rows = [m - 2, m - 1];
        let h = 0.01;
        let mats = StepMatrices::new(&a, m, &rows, h);
        let e = block_exponential(&a, &rows, h);
        let z = DVector::<f64>::from_fn(s, |i, _| (i as f64 * 0.7).sin());
        let n = DVector::<f64>::from_vec(vec![0.3, -1.1]);
        let phi = e.view((0, 0), (s, s));
        let (g1, g2) = (e.view((0, s), (s, 2)), e.view((0, s + 2), (s, 2)));
        let mut expected = DVector::<f64>::zeros(s);
        expected.rows_mut(0, m).gemv(1.0, &phi.rows(0, m), &z, 0.0);
        expected.rows_mut(m, s - m).gemv(
            1.0,
            &phi.view((m, m), (s - m, s - m)),
            &z.rows(m, s - m),
            0.0,
        );
        expected.rows_mut(0, m).gemv(1.0, &g1.rows(0, m), &n, 1.0);
        expected.rows_mut(0, m).gemv(1.0, &g2.rows(0, m), &n, 1.0);
        let p = padded_len(s);
        let mut zp = vec![0.0; p];
        zp[..s].copy_from_slice(z.as_slice());
        let mut out = vec![0.0; p];
        mats.predict(&zp, n.as_slice(), &mut out);
        mats.correct(n.as_slice(), &mut out);
        assert!(out[s..].iter().all(|v| *v == 0.0));
        let out = &out[..s];
        if mats.blocks > 4 {
            assert_eq!(&out[..m], &expected.as_slice()[..m]);
        }
        let magnitude = phi.abs() * z.abs() + (g1.abs() + g2.abs()) * n.abs();
        let bound = (s + 4) as f64 * f64::EPSILON;
        for i in 0..s {
            let error = (out[i] - expected[i]).abs();
            assert!(error <= bound * magnitude[i], "m {m}, row {i}: {error:e}");
        }
    }
}
