//! Non-negative least squares, `min ‖A x − b‖₂` subject to `x ≥ 0`, by the active-set
//! method of Lawson and Hanson (Solving Least Squares Problems, 1974, ch. 23). Used to
//! fit the stiffnesses of a generalized Maxwell chain, which must not be negative.

use nalgebra::{DMatrix, DVector};

/// Iterations allowed: Lawson–Hanson converges in at most a few times the column count.
const MAX_OUTER: usize = 200;

/// Solves the NNLS problem, returning `x ≥ 0` (zeros where the bound is active), started
/// from a guess of which entries are positive (`guess[j]`; ignored
/// unless it has one entry per column), e.g. the support of a neighbouring problem's
/// solution. The guess is first pruned to a feasible start — the least squares on it,
/// dropping the columns whose entry comes out non-positive, until all are positive —
/// from which Lawson and Hanson's loop goes on as from zero (its invariant is only that
/// `x` solves the least squares on its positive set). A diagnosis fits a nearly equal
/// chain for every model it builds, and from the last support the loop ends in one or
/// two solves instead of one per arm. The answer is the least squares on the final
/// positive set, solved afresh, so wherever the optimum's support is unique it is the
/// cold start's to the bit (`tests::a_warm_start_gives_the_cold_answer`).
pub fn nnls_from(a: &DMatrix<f64>, b: &DVector<f64>, guess: &[bool]) -> DVector<f64> {
    let n = a.ncols();
    // AᵀA and Aᵀb once (Bro & de Jong, J. Chemometrics 11, 1997): the gradient and the
    // passive sets' normal equations then cost no pass over A's rows.
    let normal = Normal {
        gram: a.tr_mul(a),
        atb: a.tr_mul(b),
    };
    let mut x = DVector::<f64>::zeros(n);
    let mut passive = vec![false; n];
    let scale = a.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(1e-300);
    let tolerance = 1e-12 * scale * b.norm().max(1e-300) * n as f64;
    if guess.len() == n && guess.iter().any(|g| *g) {
        passive.copy_from_slice(guess);
        while passive.iter().any(|p| *p) {
            let z = passive_solution(a, b, &normal, &passive);
            let mut feasible = true;
            for j in 0..n {
                if passive[j] && z[j] <= 0.0 {
                    passive[j] = false;
                    feasible = false;
                }
            }
            if feasible {
                x = z;
                break;
            }
        }
    }
    for _ in 0..MAX_OUTER {
        let gradient = &normal.atb - &normal.gram * &x;
        let candidate = (0..n)
            .filter(|&j| !passive[j])
            .max_by(|&i, &j| gradient[i].total_cmp(&gradient[j]));
        match candidate {
            Some(j) if gradient[j] > tolerance => passive[j] = true,
            _ => break,
        }
        // Inner loop: least squares on the passive set, stepping back to keep x ≥ 0.
        loop {
            let z = passive_solution(a, b, &normal, &passive);
            if (0..n).all(|j| !passive[j] || z[j] > 0.0) {
                x = z;
                break;
            }
            let mut alpha = 1.0_f64;
            for j in 0..n {
                if passive[j] && z[j] <= 0.0 {
                    alpha = alpha.min(x[j] / (x[j] - z[j]));
                }
            }
            for j in 0..n {
                x[j] += alpha * (z[j] - x[j]);
                if passive[j] && x[j] <= 1e-15 * scale {
                    passive[j] = false;
                    x[j] = 0.0;
                }
            }
        }
    }
    x
}

/// `AᵀA` and `Aᵀb` of the problem.
struct Normal {
    gram: DMatrix<f64>,
    atb: DVector<f64>,
}

/// Below this ratio of the smallest to the largest |diagonal| of R, the passive columns
/// count as dependent and the least squares is solved by SVD instead.
const QR_RANK_RATIO: f64 = 1e-10;

/// Below this ratio of the smallest to the largest diagonal of the passive Gram matrix's
/// Cholesky factor (about 1/κ of the passive columns), the normal equations would lose
/// more than ~κ²·ε ≈ 1e-8 of the solution: QR solves it instead.
const NORMAL_RANK_RATIO: f64 = 1e-4;

/// Unconstrained least squares on the passive columns (others zero): by the normal
/// equations of those columns (a Cholesky factor of at most the column count squared)
/// while they are well conditioned ([`NORMAL_RANK_RATIO`]), else by Householder QR,
/// `R·z = Qᵀ·b`, as Lawson and Hanson solve it (ch. 23), and by SVD when R says the
/// columns are dependent ([`QR_RANK_RATIO`]). The SVD alone was a third of a diagnosis'
/// time: each model it builds fits its rubber stages' chains.
fn passive_solution(
    a: &DMatrix<f64>,
    b: &DVector<f64>,
    normal: &Normal,
    passive: &[bool],
) -> DVector<f64> {
    let columns: Vec<usize> = (0..a.ncols()).filter(|&j| passive[j]).collect();
    let mut z = DVector::<f64>::zeros(a.ncols());
    if columns.is_empty() {
        return z;
    }
    let solved = normal_solution(normal, &columns).unwrap_or_else(|| {
        let sub = DMatrix::from_fn(a.nrows(), columns.len(), |i, k| a[(i, columns[k])]);
        qr_solution(&sub, b).unwrap_or_else(|| {
            sub.svd(true, true)
                .solve(b, 1e-14)
                .unwrap_or_else(|_| DVector::zeros(columns.len()))
        })
    });
    for (k, &j) in columns.iter().enumerate() {
        z[j] = solved[k];
    }
    z
}

/// The normal equations of `columns`, `G_PP·z = (Aᵀb)_P`, by Cholesky; `None` when their
/// factor is not positive or says they are ill conditioned.
fn normal_solution(normal: &Normal, columns: &[usize]) -> Option<DVector<f64>> {
    let k = columns.len();
    let g = DMatrix::from_fn(k, k, |i, j| normal.gram[(columns[i], columns[j])]);
    let rhs = DVector::from_fn(k, |i, _| normal.atb[columns[i]]);
    let cholesky = g.cholesky()?;
    let diagonal = cholesky.l_dirty().diagonal();
    let (smallest, largest) = (diagonal.min(), diagonal.max());
    if !largest.is_finite() || smallest.is_nan() || smallest <= NORMAL_RANK_RATIO * largest {
        return None;
    }
    Some(cholesky.solve(&rhs))
}

/// `min ‖sub·z − b‖₂` by QR, or `None` when `sub` has fewer rows than columns or R's
/// diagonal says its columns are dependent.
fn qr_solution(sub: &DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    if sub.nrows() < sub.ncols() {
        return None;
    }
    let k = sub.ncols();
    let qr = sub.clone().qr();
    let r = qr.r();
    let diagonal = r.diagonal().map(f64::abs);
    let largest = diagonal.max();
    if largest.is_nan() || largest <= 0.0 || diagonal.min() < QR_RANK_RATIO * largest {
        return None;
    }
    // Qᵀ·b by the Householder reflections themselves (forming Q cost as much as the QR).
    let mut qtb = b.clone();
    qr.q_tr_mul(&mut qtb);
    r.solve_upper_triangular(&qtb.rows(0, k).into_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The storage and loss rows of 12 Maxwell arms, 4 per decade, at 60 frequencies over
    /// the same three decades (120 × 12).
    fn chain_like() -> DMatrix<f64> {
        DMatrix::from_fn(120, 12, |i, j| {
            let w = 10f64.powf(0.05 * (i / 2) as f64 - 0.25 * j as f64);
            if i % 2 == 0 {
                w * w / (1.0 + w * w)
            } else {
                w / (1.0 + w * w)
            }
        })
    }

    /// From no guess: Lawson and Hanson's cold start.
    fn nnls(a: &DMatrix<f64>, b: &DVector<f64>) -> DVector<f64> {
        nnls_from(a, b, &[])
    }

    /// A problem whose unconstrained solution has a negative entry: NNLS must clamp it to
    /// zero and re-solve the rest. Exact answer worked by hand: with x2 = 0, minimising
    /// (x1 − 1)² + (x1 − 3)² gives x1 = 2.
    #[test]
    fn clamps_negative_component() {
        let a = DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 2.0]);
        let b = DVector::from_row_slice(&[1.0, 3.0]);
        // Unconstrained: x = (−1, 2) fits exactly; with x ≥ 0 the optimum is on x1 = 0?
        // Check all candidate faces by hand: x1 = 0 → x2 = (1 + 6)/5 = 1.4, residual 0.2;
        // x2 = 0 → x1 = 2, residual 2. The first wins.
        let x = nnls(&a, &b);
        assert!(
            (x[0] - 0.0).abs() < 1e-12 && (x[1] - 1.4).abs() < 1e-12,
            "{x}"
        );
    }

    /// Normal equations, QR and SVD give the same least squares on a chain-like problem: the storage and
    /// loss rows of 12 Maxwell arms, 4 per decade, at 60 frequencies over the same three
    /// decades (120 × 12). Their residual norms agree to 1e-12 relative (both are the
    /// minimum) and their solutions to 1e-9 (QR: the problem's condition number times the
    /// rounding) and 1e-8 (normal equations: its square); dependent columns go to SVD.
    #[test]
    fn qr_and_svd_agree() {
        let a = chain_like();
        let b = DVector::from_fn(120, |i, _| 1.0 + 0.3 * ((i / 2) as f64).sqrt());
        let qr = qr_solution(&a, &b).expect("independent columns");
        let normal = Normal {
            gram: a.tr_mul(&a),
            atb: a.tr_mul(&b),
        };
        let all: Vec<usize> = (0..12).collect();
        let by_normal = normal_solution(&normal, &all).expect("well conditioned");
        let svd = a.clone().svd(true, true).solve(&b, 1e-14).unwrap();
        let residual = |x: &DVector<f64>| (&a * x - &b).norm();
        assert!((residual(&qr) - residual(&svd)).abs() < 1e-12 * residual(&svd));
        assert!((&qr - &svd).norm() < 1e-9 * svd.norm(), "{qr} {svd}");
        assert!((residual(&by_normal) - residual(&svd)).abs() < 1e-12 * residual(&svd));
        let gap = (&by_normal - &svd).norm() / svd.norm();
        assert!(gap < 1e-8, "normal equations off by {gap:e}");
        let mut dependent = a.clone();
        let first = a.column(0).clone_owned();
        dependent.set_column(3, &first);
        assert!(qr_solution(&dependent, &b).is_none());
        let normal = Normal {
            gram: dependent.tr_mul(&dependent),
            atb: dependent.tr_mul(&b),
        };
        assert!(normal_solution(&normal, &all).is_none());
    }

    /// A problem whose solution is interior is solved exactly.
    #[test]
    fn interior_solution_is_exact() {
        let a = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
        let b = DVector::from_row_slice(&[1.0, 2.0, 3.0]);
        let x = nnls(&a, &b);
        assert!(
            (x[0] - 1.0).abs() < 1e-12 && (x[1] - 2.0).abs() < 1e-12,
            "{x}"
        );
    }

    /// From a right guess, a wrong one (a column too many, a column missing) or an empty
    /// one, the chain-like problem of `qr_and_svd_agree` with a bound that binds comes out
    /// the same to the bit: the answer is the least squares on the final support.
    #[test]
    fn a_warm_start_gives_the_cold_answer() {
        let a = chain_like();
        let b = DVector::from_fn(120, |i, _| 1.0 + 0.8 * ((i / 2) as f64 * 0.3).sin());
        let cold = nnls(&a, &b);
        let support: Vec<bool> = cold.iter().map(|v| *v > 0.0).collect();
        assert!(support.iter().any(|p| !*p), "a bound must bind: {cold}");
        assert!(support.iter().filter(|p| **p).count() >= 2, "{cold}");
        let mut too_many = support.clone();
        let off = support.iter().position(|p| !*p).expect("a zero");
        too_many[off] = true;
        let mut missing = support.clone();
        let on = support.iter().position(|p| *p).expect("a positive");
        missing[on] = false;
        for guess in [support.clone(), too_many, missing, vec![true; 12], vec![]] {
            assert_eq!(nnls_from(&a, &b, &guess), cold, "from {guess:?}");
        }
    }
}
