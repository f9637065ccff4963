//! The size at which the diagnosis *names* an effect (issue 14, item 6: "check it with
//! full diagnoses").
//!
//! `λ ≥ 7.85` ([`super::power_fisher`]) says a χ² test on the whole campaign would see an
//! effect. The diagnosis asks more, on the held-out amplitudes only
//! ([`super::holdout`], [`super::decide`]):
//! 1. the user's model misfits them: `χ²/N_h > NONE_CHI2` (2);
//! 2. the effect's fit improves on the user's model by more than chance:
//!    `after < before·(1 − 2√(2/N_h))` ([`super::guard::improves`]);
//! 3. the effect's score beats the plain recalibration's by the margin:
//!    `score_e < (1 − EFFECT_MARGIN)·score_p` (40 % for a branch,
//!    [`super::branch::margin`]), scores being held-out χ²/N plus `k·ln n/n`.
//!
//! With a signature `d = t·d₀` (linear in the size), the expected held-out χ²/N of the
//! user's model is `1 + t²·A` with `A = Σ_h w d₀²/N_h`; that of the plain recalibration,
//! fitted on the other amplitudes with the diagnosis' prior, is `1 + t²·B` with `B` its
//! held-out residual `Σ_h w r₀²/N_h`; the effect's own fit leaves the noise, `1`. Each
//! condition is then a bound `t² > …`, and the named size is `s₀·t` at the largest.
//! Noise only adds scatter around these expectations (two scatters of χ²/N are within
//! condition 2), so a size a factor 2 above the named one is named and a third of it is
//! not, which `tests/diagnose_power.rs` checks with full diagnoses.

use super::decide::NONE_CHI2;
use super::power_fisher::Column;
use nalgebra::{DMatrix, DVector};

/// What the decision rule needs of a campaign.
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    /// `true` for the held-out observables.
    pub held: Vec<bool>,
    /// Plain parameters (the penalty's `k`).
    pub k_plain: usize,
    /// The effect's margin over the plain fit (0.15; 0.4 for a branch).
    pub effect_margin: f64,
}

impl Rule {
    fn n_held(&self) -> usize {
        self.held.iter().filter(|h| **h).count()
    }

    fn n_fitted(&self) -> usize {
        self.held.len() - self.n_held()
    }

    /// `(A, B)` of the module docs for the signature `d` under `weights` (`1/σ²`), the
    /// plain fit by `columns` on the fitted observables.
    pub fn coefficients(&self, d: &[f64], weights: &[f64], columns: &[&Column]) -> (f64, f64) {
        let clean = |x: f64| if x.is_finite() { x } else { 0.0 };
        let n = d.len().min(weights.len()).min(self.held.len());
        let k = columns.len();
        let col = |a: usize, i: usize| clean(columns[a].values.get(i).copied().unwrap_or(0.0));
        let mut m = DMatrix::<f64>::zeros(k, k);
        let mut b = DVector::<f64>::zeros(k);
        for i in (0..n).filter(|i| !self.held[*i]) {
            let w = clean(weights[i]);
            for a in 0..k {
                b[a] += w * col(a, i) * clean(d[i]);
                for c in 0..k {
                    m[(a, c)] += w * col(a, i) * col(c, i);
                }
            }
        }
        for a in 0..k {
            m[(a, a)] += columns[a].prior.max(0.0);
        }
        let scale = (0..k).map(|a| m[(a, a)]).fold(0.0, f64::max).max(1e-300);
        // No plain parameter: nothing absorbs (nalgebra's SVD refuses an empty matrix).
        let beta = if k == 0 {
            DVector::zeros(0)
        } else {
            m.pseudo_inverse(1e-12 * scale)
                .map_or_else(|_| DVector::zeros(k), |inv| inv * b)
        };
        let (mut a_sum, mut b_sum) = (0.0, 0.0);
        for i in (0..n).filter(|i| self.held[*i]) {
            let w = clean(weights[i]);
            let r = clean(d[i]) - (0..k).map(|a| col(a, i) * beta[a]).sum::<f64>();
            a_sum += w * clean(d[i]).powi(2);
            b_sum += w * r * r;
        }
        let nh = self.n_held().max(1) as f64;
        (a_sum / nh, b_sum / nh)
    }

    /// The smallest factor `t` on the signature `d` (at size `s₀`) at which the rule
    /// names the effect: the named size is `s₀·t`. `None` when the plain fit absorbs
    /// the signature entirely (`B = 0`) or nothing is held out.
    pub fn factor(&self, d: &[f64], weights: &[f64], columns: &[&Column]) -> Option<f64> {
        let (nh, nf) = (self.n_held(), self.n_fitted());
        if nh == 0 || nf == 0 {
            return None;
        }
        let (a, b) = self.coefficients(d, weights, columns);
        if !(a > 0.0 && b > 0.0) {
            return None;
        }
        let per = (nf as f64).ln() / nf as f64;
        let k = self.k_plain as f64;
        // 1. the user's model misfits;
        let misfits = (NONE_CHI2 - 1.0) / a;
        // 2. the fit improves on it by more than chance;
        let improve = super::guard::margin(nh);
        let improves = if improve < 1.0 {
            (1.0 / (1.0 - improve) - 1.0) / a
        } else {
            return None;
        };
        // 3. the effect beats the plain recalibration by the margin.
        let score_e = 1.0 + (k + 1.0) * per;
        let beats = (score_e / (1.0 - self.effect_margin) - 1.0 - k * per) / b;
        let t2 = misfits.max(improves).max(beats).max(0.0);
        Some(t2.sqrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two held-out and two fitted observables of weight 1, no plain parameters: A = B
    /// = mean held-out d²; with d₀ = (1, 1) held out, A = 1, so the misfit condition
    /// (χ²/N > 2) needs t = 1 exactly when it is the largest bound.
    #[test]
    fn the_misfit_condition_alone_gives_the_closed_form() {
        let rule = Rule {
            held: vec![false, true, false, true],
            k_plain: 0,
            effect_margin: 0.15,
        };
        let d = [0.0, 1.0, 0.0, 1.0];
        let (a, b) = rule.coefficients(&d, &[1.0; 4], &[]);
        assert!((a - 1.0).abs() < 1e-15 && (b - 1.0).abs() < 1e-15);
        // Bounds: misfit 1; improve (1/(1−2·√(2/2)) invalid → margin ≥ 1 → None.
        assert_eq!(rule.factor(&d, &[1.0; 4], &[]), None);
        // 200 held-out amplitudes: improve margin 0.2, bound 0.25; beats: score_e =
        // 1 + ln200/200, bound (score_e/0.85 − 1) = 0.2046…; misfit 1 is the largest.
        let mut held = vec![false; 400];
        for h in held.iter_mut().skip(1).step_by(2) {
            *h = true;
        }
        let rule = Rule {
            held,
            k_plain: 0,
            effect_margin: 0.15,
        };
        let d: Vec<f64> = (0..400).map(|i| (i % 2) as f64).collect();
        let t = rule.factor(&d, &[1.0; 400], &[]).expect("named");
        assert!((t - 1.0).abs() < 1e-12, "{t}");
    }

    /// A plain column equal to the signature on the fitted set and the held-out set
    /// absorbs it: B = 0, never named; a column seen only on the fitted set leaves the
    /// held-out part whole: B = A.
    #[test]
    fn the_plain_fit_is_made_on_the_fitted_amplitudes_only() {
        let rule = Rule {
            held: vec![false, true],
            k_plain: 1,
            effect_margin: 0.15,
        };
        let along = Column {
            values: vec![1.0, 1.0],
            prior: 0.0,
        };
        let (_, b) = rule.coefficients(&[1.0, 1.0], &[1.0, 1.0], &[&along]);
        assert!(b < 1e-20, "{b}");
        let fitted_only = Column {
            values: vec![1.0, 0.0],
            prior: 0.0,
        };
        let (a, b) = rule.coefficients(&[1.0, 1.0], &[1.0, 1.0], &[&fitted_only]);
        assert!((a - 1.0).abs() < 1e-15 && (b - 1.0).abs() < 1e-15);
    }
}
