//! Non-negative least squares, `min ‖A·x − b‖` subject to `x ≥ 0`, by Lawson and
//! Hanson's active-set method (Solving Least Squares Problems, 1974, ch. 23): it adds the
//! column with the largest positive gradient to the free set, solves the least squares on
//! the free set, and steps back to the boundary where a coefficient would turn negative.
//! It ends at the exact solution (the KKT conditions) in finitely many steps, which the
//! bench needs: a rubber bank's mode rows outweigh its band rows 100-fold, and an
//! iterative solver's residual there would move the fitted modes.

use nalgebra::{DMatrix, DVector};

/// Relative tolerance on the gradient for a column to enter the free set.
const GRADIENT_TOL: f64 = 1e-12;

/// Solves the least squares on the columns `free` of `a` (others held at zero).
fn solve_free(a: &DMatrix<f64>, b: &DVector<f64>, free: &[usize]) -> Option<DVector<f64>> {
    let sub = DMatrix::from_fn(a.nrows(), free.len(), |r, c| a[(r, free[c])]);
    sub.svd(true, true).solve(b, 1e-14).ok()
}

/// The non-negative least-squares solution of `a·x ≈ b` (columns scaled to unit norm
/// inside, so the tolerances are scale-free).
pub fn nnls(a: &DMatrix<f64>, b: &DVector<f64>) -> Vec<f64> {
    let n = a.ncols();
    let norms: Vec<f64> = (0..n).map(|j| a.column(j).norm().max(1e-300)).collect();
    let an = DMatrix::from_fn(a.nrows(), n, |r, c| a[(r, c)] / norms[c]);
    let scale = b.norm().max(1e-300);
    let mut x = DVector::<f64>::zeros(n);
    let mut free = vec![false; n];
    for _ in 0..(3 * n + 10) {
        let w = an.transpose() * (b - &an * &x);
        let enter = (0..n)
            .filter(|&j| !free[j] && w[j] > GRADIENT_TOL * scale)
            .max_by(|&i, &j| w[i].total_cmp(&w[j]));
        let Some(t) = enter else {
            break;
        };
        free[t] = true;
        loop {
            let idx: Vec<usize> = (0..n).filter(|&j| free[j]).collect();
            let Some(z) = solve_free(&an, b, &idx) else {
                free[t] = false;
                break;
            };
            if z.iter().all(|&v| v > 0.0) {
                for (k, &j) in idx.iter().enumerate() {
                    x[j] = z[k];
                }
                break;
            }
            // Step from x towards z until the first free coefficient reaches zero.
            let alpha = idx
                .iter()
                .enumerate()
                .filter(|&(k, _)| z[k] <= 0.0)
                .map(|(k, &j)| x[j] / (x[j] - z[k]))
                .fold(1.0f64, f64::min);
            for (k, &j) in idx.iter().enumerate() {
                x[j] += alpha * (z[k] - x[j]);
                if x[j] <= 1e-15 * scale {
                    x[j] = 0.0;
                    free[j] = false;
                }
            }
            if idx.iter().all(|&j| !free[j]) {
                break;
            }
        }
    }
    x.iter().zip(&norms).map(|(x, s)| x / s).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meets_the_kkt_conditions() {
        // b lies outside the cone: the second column's coefficient is held at zero.
        let a = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
        let b = DVector::from_row_slice(&[2.0, -1.0, 1.0]);
        let x = nnls(&a, &b);
        assert!(x[1] == 0.0 && (x[0] - 1.5).abs() < 1e-12, "{x:?}");
        // An interior solution is the plain least squares.
        let b = DVector::from_row_slice(&[1.0, 2.0, 3.0]);
        let x = nnls(&a, &b);
        assert!(
            (x[0] - 1.0).abs() < 1e-12 && (x[1] - 2.0).abs() < 1e-12,
            "{x:?}"
        );
    }
}
