//! The χ² non-centrality of a signature after the best fit by other directions
//! (issue 14, item 6): the Schur complement of the Fisher information.
//!
//! With whitened residuals (`W = Σ⁻¹ = diag(1/σᵢ²)`), a signature `d` and the
//! sensitivities `C` of the parameters that may absorb it (the plain parameters, with
//! the diagnosis' prior precision `P`, and perhaps another effect, with none):
//! `λ = dᵀWd − (CᵀWd)ᵀ (CᵀWC + P)⁻¹ (CᵀWd)`, which for `d = s·J_e` is `s²·F_eff` with
//! `F_eff = F_ee − F_ep (F_pp + P)⁻¹ F_pe`, the Schur complement.

use nalgebra::{DMatrix, DVector};

/// Non-centrality for 80 % power of a χ² test at 5 % with one degree of freedom:
/// `(z₀.₉₇₅ + z₀.₈₀)² = (1.95996 + 0.84162)² = 7.849`.
pub const LAMBDA_DETECT: f64 = 7.849;

/// A column that may absorb a signature: its sensitivities (same length as the
/// signature) and its prior precision (0: free).
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// ∂(amplitudes)/∂(parameter), rpm per unit.
    pub values: Vec<f64>,
    /// Prior precision, 1/unit².
    pub prior: f64,
}

/// `λ` of `d` after the best fit by `columns` (module docs); `weights`: `1/σᵢ²`.
/// Non-finite entries count as 0; the result is ≥ 0 and finite.
pub fn projected_lambda(d: &[f64], weights: &[f64], columns: &[&Column]) -> f64 {
    let clean = |x: f64| if x.is_finite() { x } else { 0.0 };
    let n = d.len().min(weights.len());
    let total: f64 = (0..n)
        .map(|i| clean(weights[i]) * clean(d[i]).powi(2))
        .sum();
    let k = columns.len();
    if k == 0 {
        return total.max(0.0);
    }
    let mut m = DMatrix::<f64>::zeros(k, k);
    let mut b = DVector::<f64>::zeros(k);
    for (a, ca) in columns.iter().enumerate() {
        for i in 0..n {
            b[a] +=
                clean(weights[i]) * clean(ca.values.get(i).copied().unwrap_or(0.0)) * clean(d[i]);
        }
        for (c, cc) in columns.iter().enumerate().skip(a) {
            let v: f64 = (0..n)
                .map(|i| {
                    clean(weights[i])
                        * clean(ca.values.get(i).copied().unwrap_or(0.0))
                        * clean(cc.values.get(i).copied().unwrap_or(0.0))
                })
                .sum();
            m[(a, c)] = v;
            m[(c, a)] = v;
        }
        m[(a, a)] += ca.prior.max(0.0);
    }
    // Directions the data and priors cannot fix absorb nothing: pseudo-inverse.
    let scale = (0..k).map(|a| m[(a, a)]).fold(0.0, f64::max).max(1e-300);
    let explained = match m.clone().pseudo_inverse(1e-12 * scale) {
        Ok(inv) => (b.transpose() * inv * &b)[(0, 0)],
        Err(_) => 0.0,
    };
    let out = total - explained;
    if out.is_finite() { out.max(0.0) } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A signature along a free column is absorbed completely; one orthogonal to it not
    /// at all; one at 45° loses half (cos² = 1/2).
    #[test]
    fn projects_out_free_columns() {
        let w = [1.0, 1.0, 4.0];
        let col = Column {
            values: vec![1.0, 0.0, 0.0],
            prior: 0.0,
        };
        assert!(projected_lambda(&[2.0, 0.0, 0.0], &w, &[&col]) < 1e-12);
        assert!((projected_lambda(&[0.0, 3.0, 0.0], &w, &[&col]) - 9.0).abs() < 1e-12);
        assert!((projected_lambda(&[1.0, 1.0, 0.0], &w, &[&col]) - 1.0).abs() < 1e-12);
        // Weight 4 on the third entry: λ = 4·0.5² = 1.
        assert!((projected_lambda(&[0.0, 0.0, 0.5], &w, &[]) - 1.0).abs() < 1e-12);
    }

    /// A prior keeps a column from absorbing everything: one observation, weight 1,
    /// column 1, prior 1: λ = d² − d²/2.
    #[test]
    fn a_prior_limits_what_a_column_absorbs() {
        let col = Column {
            values: vec![1.0],
            prior: 1.0,
        };
        assert!((projected_lambda(&[2.0], &[1.0], &[&col]) - 2.0).abs() < 1e-12);
        // Two identical columns: the pseudo-inverse handles the singular matrix.
        let free = Column {
            values: vec![1.0, 1.0],
            prior: 0.0,
        };
        assert!(projected_lambda(&[1.0, 1.0], &[1.0, 1.0], &[&free, &free]) < 1e-9);
        assert_eq!(projected_lambda(&[f64::NAN], &[1.0], &[]), 0.0);
    }
}
