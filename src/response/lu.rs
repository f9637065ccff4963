//! An allocation-free complex LU solve with partial pivoting, in place on a reused
//! column-major n×n buffer, for the forced-response sweep (one small solve per speed and
//! order).
//!
//! It performs the same operations in the same order as nalgebra 0.35's `LU::new` +
//! `LU::solve` (pivot: the first largest `|re| + |im|` in the column; the column below the
//! pivot scaled by `1/pivot`; rank-one update column by column; then forward and back
//! substitution), so the sweep's results are unchanged — bit for bit, up to the sign of a
//! zero — while skipping nalgebra's per-solve allocations (matrix clone, permutation
//! sequence, right-hand side) and its generic view overhead. Updates by an exact zero
//! (a zero multiplier or pivot-row entry) only add ±0 and are skipped, so the banded and
//! tree-shaped matrices of drivelines cost far less than n³/3. `tests` below check it
//! against nalgebra.

use nalgebra::DMatrix;
use num_complex::Complex64;

/// Row swaps of one factorization, reused between solves.
#[derive(Debug, Default)]
pub(crate) struct LuWorkspace {
    /// `(i, pivot row)` for each column where rows were swapped, in elimination order.
    swaps: Vec<(usize, usize)>,
}

impl LuWorkspace {
    /// Factors the square `matrix` in place (L below the diagonal with unit diagonal, U on
    /// and above it) and solves `matrix · x = rhs`, writing `x` into `rhs`. Returns false
    /// when a pivot is exactly zero (singular matrix; `rhs` is then garbage), as
    /// nalgebra's `solve` returns `None`.
    pub(crate) fn factor_solve(
        &mut self,
        matrix: &mut DMatrix<Complex64>,
        rhs: &mut [Complex64],
    ) -> bool {
        let n = matrix.nrows();
        debug_assert_eq!(matrix.ncols(), n);
        debug_assert_eq!(rhs.len(), n);
        let a = matrix.as_mut_slice();
        self.swaps.clear();
        for i in 0..n {
            // Partial pivoting: first row of the largest norm1 in column i, rows i...
            let col = i * n;
            let mut piv = i;
            let mut the_max = norm1(a[col + i]);
            for r in i + 1..n {
                let v = norm1(a[col + r]);
                if v > the_max {
                    the_max = v;
                    piv = r;
                }
            }
            let diag = a[col + piv];
            if is_zero(diag) {
                continue;
            }
            if piv != i {
                self.swaps.push((i, piv));
                // Swap the whole rows: the L part (columns < i), the pivot column and U.
                for k in 0..n {
                    a.swap(k * n + i, k * n + piv);
                }
            }
            let inv_diag = Complex64::new(1.0, 0.0) / diag;
            // Rows below `last` hold exact zeros in this column: their updates would add
            // ±0 and are skipped (drivelines are chains and trees, so this is most rows).
            let last = (i + 1..n)
                .rev()
                .find(|&r| !is_zero(a[col + r]))
                .unwrap_or(i);
            for r in i + 1..=last {
                a[col + r] *= inv_diag;
            }
            for k in i + 1..n {
                let kc = k * n;
                let pivot_row = a[kc + i];
                if is_zero(pivot_row) {
                    continue;
                }
                let minus_pivot_row = -pivot_row;
                for r in i + 1..=last {
                    let update = minus_pivot_row * a[col + r];
                    a[kc + r] = update + a[kc + r];
                }
            }
        }
        for &(i, piv) in &self.swaps {
            rhs.swap(i, piv);
        }
        // Forward substitution with the unit lower triangle.
        for i in 0..n.saturating_sub(1) {
            let minus_coeff = -rhs[i];
            let col = i * n;
            for r in i + 1..n {
                let l = a[col + r];
                if !is_zero(l) {
                    rhs[r] = minus_coeff * l + rhs[r];
                }
            }
        }
        // Back substitution with the upper triangle.
        for i in (0..n).rev() {
            let col = i * n;
            let diag = a[col + i];
            if is_zero(diag) {
                return false;
            }
            let coeff = rhs[i] / diag;
            rhs[i] = coeff;
            let minus_coeff = -coeff;
            for r in 0..i {
                let u = a[col + r];
                if !is_zero(u) {
                    rhs[r] = minus_coeff * u + rhs[r];
                }
            }
        }
        true
    }
}

/// True for an exact zero (either sign).
fn is_zero(z: Complex64) -> bool {
    z.re == 0.0 && z.im == 0.0
}

/// `|re| + |im|`, nalgebra's pivot measure for complex numbers.
fn norm1(z: Complex64) -> f64 {
    z.re.abs() + z.im.abs()
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// Deterministic pseudo-random values in [-1, 1).
    fn values(seed: &mut u64, count: usize) -> Vec<f64> {
        (0..count)
            .map(|_| {
                *seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (*seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0
            })
            .collect()
    }

    /// On random complex systems — dense, tridiagonal (a chain) and with random exact
    /// zeros (a tree), pivoting exercised — the solution equals nalgebra's
    /// `lu().solve()` exactly: same operations in the same order, zero updates skipped.
    #[test]
    fn matches_nalgebra_bit_for_bit() {
        let mut seed = 7;
        let mut workspace = LuWorkspace::default();
        for n in [1usize, 2, 3, 5, 10, 17] {
            for trial in 0..60 {
                let re = values(&mut seed, n * n + n);
                let im = values(&mut seed, n * n + n);
                let keep = values(&mut seed, n * n);
                let z: Vec<Complex64> = re
                    .iter()
                    .zip(&im)
                    .map(|(&r, &i)| Complex64::new(r, i))
                    .collect();
                let mut matrix = DMatrix::from_column_slice(n, n, &z[..n * n]);
                for (index, entry) in matrix.iter_mut().enumerate() {
                    let (row, col) = (index % n, index / n);
                    let zero = match trial % 3 {
                        0 => false,
                        1 => row.abs_diff(col) > 1,
                        _ => row != col && keep[index] < 0.4,
                    };
                    if zero {
                        *entry = Complex64::default();
                    }
                }
                let b = DVector::from_column_slice(&z[n * n..]);
                let expected = matrix.clone().lu().solve(&b).expect("regular");
                let mut factored = matrix.clone();
                let mut x: Vec<Complex64> = b.iter().copied().collect();
                assert!(workspace.factor_solve(&mut factored, &mut x));
                for (a, e) in x.iter().zip(expected.iter()) {
                    assert_eq!(a.re.to_bits(), e.re.to_bits(), "n = {n}, trial {trial}");
                    assert_eq!(a.im.to_bits(), e.im.to_bits(), "n = {n}, trial {trial}");
                }
            }
        }
    }

    /// A singular matrix (a zero column) is reported, as nalgebra's solve returns `None`.
    #[test]
    fn singular_is_reported() {
        let mut m = DMatrix::<Complex64>::from_element(3, 3, Complex64::new(1.0, 0.5));
        m.column_mut(1).fill(Complex64::default());
        let mut b = vec![Complex64::new(1.0, 0.0); 3];
        assert!(
            m.clone()
                .lu()
                .solve(&DVector::from_column_slice(&b))
                .is_none()
        );
        assert!(!LuWorkspace::default().factor_solve(&mut m, &mut b));
    }
}
