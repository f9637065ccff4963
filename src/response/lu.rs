//! An allocation-free LU solve with partial pivoting, in place on a reused column-major
//! n×n buffer, real or complex: the forced-response sweep (one small complex solve per
//! speed and order) and ROS2's `I − γhJ` (one real factorization reused for many steps,
//! two solves per step, [`crate::transient::ros2`]).
//!
//! It performs the same operations in the same order as nalgebra 0.35's `LU::new` +
//! `LU::solve` (pivot: the first largest `norm1` in the column, `|re| + |im|` for a complex
//! number; the column below the pivot scaled by `1/pivot`; rank-one update column by
//! column; then forward and back substitution), so the results are unchanged — bit for bit,
//! up to the sign of a zero — while skipping nalgebra's per-solve allocations (matrix clone,
//! permutation sequence, right-hand side) and its generic view overhead. Updates by an
//! exact zero (a zero pivot-row entry, the zero multipliers at the end of a column, a zero
//! coefficient of a substitution) only add ±0 and are skipped, so the banded and
//! tree-shaped matrices of drivelines cost far less than n³/3; the remaining inner loops
//! are branch-free axpys over slices, which the compiler vectorizes. `tests` below
//! check it against nalgebra. Written by hand because nalgebra's LU allocates per solve and
//! cannot skip the structural zeros; measured on benchtruth case 2016's diagnosis, its
//! `LU::new` and `LU::solve` were 33 % of the time.

use nalgebra::{ComplexField, DMatrix};

/// Row swaps of one factorization, reused between solves.
#[derive(Debug, Default)]
pub(crate) struct LuWorkspace {
    /// `(i, pivot row)` for each column where rows were swapped, in elimination order.
    swaps: Vec<(usize, usize)>,
}

impl LuWorkspace {
    /// Factors the square `matrix` in place and solves `matrix · x = rhs`, writing `x` into
    /// `rhs`. Returns false when a pivot is exactly zero (singular matrix; `rhs` is then
    /// garbage), as nalgebra's `solve` returns `None`.
    pub(crate) fn factor_solve<T: ComplexField + Copy>(
        &mut self,
        matrix: &mut DMatrix<T>,
        rhs: &mut [T],
    ) -> bool {
        self.factor(matrix);
        self.solve(matrix, rhs)
    }

    /// Factors the square `matrix` in place: L below the diagonal with unit diagonal, U on
    /// and above it, the row swaps kept here for [`Self::solve`]. A column without a
    /// nonzero pivot is left as it is (the solve then reports the matrix singular).
    pub(crate) fn factor<T: ComplexField + Copy>(&mut self, matrix: &mut DMatrix<T>) {
        let n = matrix.nrows();
        debug_assert_eq!(matrix.ncols(), n);
        let a = matrix.as_mut_slice();
        self.swaps.clear();
        for i in 0..n {
            // Partial pivoting: first row of the largest norm1 in column i, rows i...
            let col = i * n;
            let mut piv = i;
            let mut the_max = a[col + i].norm1();
            for r in i + 1..n {
                let v = a[col + r].norm1();
                if v > the_max {
                    the_max = v;
                    piv = r;
                }
            }
            let diag = a[col + piv];
            if diag.is_zero() {
                continue;
            }
            if piv != i {
                self.swaps.push((i, piv));
                // Swap the whole rows: the L part (columns < i), the pivot column and U.
                for k in 0..n {
                    a.swap(k * n + i, k * n + piv);
                }
            }
            let inv_diag = T::one() / diag;
            // Rows below `last` hold exact zeros in this column: their updates would add
            // ±0 and are skipped (drivelines are chains and trees, so this is most rows).
            let last = (i + 1..n)
                .rev()
                .find(|&r| !a[col + r].is_zero())
                .unwrap_or(i);
            for v in &mut a[col + i + 1..=col + last] {
                *v *= inv_diag;
            }
            for k in i + 1..n {
                let kc = k * n;
                // Column k lies after column i: split so that the update is a plain axpy
                // over two slices, which the compiler vectorizes.
                let (left, right) = a.split_at_mut(kc);
                let pivot_row = right[i];
                if pivot_row.is_zero() {
                    continue;
                }
                let minus_pivot_row = -pivot_row;
                let multipliers = &left[col + i + 1..=col + last];
                for (target, &m) in right[i + 1..=last].iter_mut().zip(multipliers) {
                    let update = minus_pivot_row * m;
                    *target = update + *target;
                }
            }
        }
    }

    /// Solves `matrix · x = rhs` with the `factored` matrix of the last [`Self::factor`],
    /// writing `x` into `rhs`. Returns false when a pivot is exactly zero.
    pub(crate) fn solve<T: ComplexField + Copy>(
        &self,
        factored: &DMatrix<T>,
        rhs: &mut [T],
    ) -> bool {
        let n = factored.nrows();
        debug_assert_eq!(rhs.len(), n);
        let a = factored.as_slice();
        for &(i, piv) in &self.swaps {
            rhs.swap(i, piv);
        }
        // Forward substitution with the unit lower triangle; a column is skipped whole when
        // its coefficient is an exact zero (its updates would add ±0).
        for i in 0..n.saturating_sub(1) {
            let (done, rest) = rhs.split_at_mut(i + 1);
            if done[i].is_zero() {
                continue;
            }
            let minus_coeff = -done[i];
            let col = i * n;
            for (target, &l) in rest.iter_mut().zip(&a[col + i + 1..col + n]) {
                *target = minus_coeff * l + *target;
            }
        }
        // Back substitution with the upper triangle.
        for i in (0..n).rev() {
            let col = i * n;
            let diag = a[col + i];
            if diag.is_zero() {
                return false;
            }
            let coeff = rhs[i] / diag;
            rhs[i] = coeff;
            if coeff.is_zero() {
                continue;
            }
            let minus_coeff = -coeff;
            for (target, &u) in rhs[..i].iter_mut().zip(&a[col..col + i]) {
                *target = minus_coeff * u + *target;
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;
    use num_complex::Complex64;

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

    /// Sets entries of `matrix` to exact zeros by `trial`'s pattern: none (dense), all but
    /// the tridiagonal band (a chain), or off-diagonal ones where `keep` < `share` (a tree).
    fn sparsify<T: ComplexField + Copy>(
        matrix: &mut DMatrix<T>,
        trial: usize,
        keep: &[f64],
        share: f64,
    ) {
        let n = matrix.nrows();
        for (index, entry) in matrix.iter_mut().enumerate() {
            let (row, col) = (index % n, index / n);
            let zero = match trial % 3 {
                0 => false,
                1 => row.abs_diff(col) > 1,
                _ => row != col && keep[index] < share,
            };
            if zero {
                *entry = T::zero();
            }
        }
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
                sparsify(&mut matrix, trial, &keep, 0.4);
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

    /// Real systems, as ROS2 factors `I − γhJ` once and solves with it twice: each
    /// solution equals nalgebra's exactly, on dense, banded and sparse matrices.
    #[test]
    fn real_factor_once_solve_twice_matches_nalgebra_bit_for_bit() {
        let mut seed = 11;
        let mut workspace = LuWorkspace::default();
        for n in [1usize, 2, 4, 9, 23, 40] {
            for trial in 0..30 {
                let v = values(&mut seed, n * n + 2 * n);
                let keep = values(&mut seed, n * n);
                let mut matrix = DMatrix::from_column_slice(n, n, &v[..n * n]);
                sparsify(&mut matrix, trial, &keep, 0.6);
                let nalgebra_lu = matrix.clone().lu();
                let mut factored = matrix.clone();
                workspace.factor(&mut factored);
                for b in [&v[n * n..n * n + n], &v[n * n + n..]] {
                    let expected = nalgebra_lu
                        .solve(&DVector::from_column_slice(b))
                        .expect("regular");
                    let mut x = b.to_vec();
                    assert!(workspace.solve(&factored, &mut x));
                    for (a, e) in x.iter().zip(expected.iter()) {
                        assert_eq!(a.to_bits(), e.to_bits(), "n = {n}, trial {trial}");
                    }
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
