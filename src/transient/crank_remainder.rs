//! The crank-angle remainder of the exact discretization ([`super::exact`]): what the
//! `[[harmonic]]`s add because they act at the *vibrating* crank angle `qΩt + q·θ_ref`
//! and not at the mean one that the augmented linear system generates exactly,
//! `N = T·[cos a·(cos δ − 1) − sin a·sin δ]`, `a = qΩt + φ`, `δ = q·θ_ref`.
//!
//! `cos a`, `sin a` are read off the oscillator states of the augmented state, so a step
//! takes no trigonometry; `(sin δ, cos δ − 1)` come from their series, written here
//! because the library's `cos δ − 1` cancels to nothing at the ~1e-3 rad a crank vibrates.

/// One harmonic as the remainder sees it.
#[derive(Debug, Clone)]
pub(super) struct Term {
    /// Index of its order's oscillator's cos state in the augmented state (sin is the
    /// next).
    pub(super) cos_state: usize,
    /// Column of the remainder it adds to.
    pub(super) column: usize,
    /// True for the first term of its column (terms are kept column by column): it sets
    /// the column rather than adding to it, so no pass clears the columns first (a
    /// `fill` of a few entries is a call to `memset`, most of a step's remainder).
    pub(super) starts_column: bool,
    /// Acceleration amplitude `ratio·T/J`, rad/s².
    pub(super) coefficient: f64,
    /// `(cos φ, sin φ)` of its phase.
    pub(super) phase: (f64, f64),
    /// Order q.
    pub(super) order: f64,
}

/// The remainder of `terms` per column into `out` (rad/s²; no allocation: it runs twice
/// per step) at augmented state `z`, `reference_dof` the index of the reference's
/// vibration angle in it; the terms, kept column by column ([`mark_columns`]), added in
/// their order.
#[inline]
pub(super) fn remainder_into(terms: &[Term], reference_dof: usize, z: &[f64], out: &mut [f64]) {
    let theta = z[reference_dof];
    for t in terms {
        let value = t.value(z, theta);
        if t.starts_column {
            out[t.column] = value;
        } else {
            out[t.column] += value;
        }
    }
}

/// Sorts `terms` column by column (stably: a column's terms keep their order) and marks
/// the first of each column; every column of `0..columns` must have a term.
pub(super) fn mark_columns(terms: &mut [Term]) {
    terms.sort_by_key(|t| t.column);
    let mut previous = None;
    for t in terms.iter_mut() {
        t.starts_column = previous != Some(t.column);
        previous = Some(t.column);
    }
}

impl Term {
    /// Its remainder at augmented state `z` with the reference's vibration angle `theta`
    /// (rad), rad/s².
    #[inline(always)]
    fn value(&self, z: &[f64], theta: f64) -> f64 {
        let (c, s) = (z[self.cos_state], z[self.cos_state + 1]);
        let cos_a = self.phase.0 * c - self.phase.1 * s;
        let sin_a = self.phase.1 * c + self.phase.0 * s;
        let (sin_d, cos_d_minus_one) = sin_and_cos_minus_one(self.order * theta);
        self.coefficient * (cos_a * cos_d_minus_one - sin_a * sin_d)
    }
}

/// Below this |δ|, rad, the series; above, the library.
const SERIES_BELOW_RAD: f64 = 0.05;

/// `(sin δ, cos δ − 1)` without cancellation: below [`SERIES_BELOW_RAD`] their Taylor
/// series to δ⁷ and δ⁸ (truncation below 1e-16 relative there), summed by Estrin's scheme
/// (short dependency chains: this is on the step's critical path), with one branch (the
/// angle would cross any smaller threshold every cycle, and mispredict); above it
/// `−2·sin²(δ/2)`.
#[inline(always)]
fn sin_and_cos_minus_one(delta: f64) -> (f64, f64) {
    if delta.abs() < SERIES_BELOW_RAD {
        const S3: f64 = -1.0 / 6.0;
        const S5: f64 = 1.0 / 120.0;
        const S7: f64 = -1.0 / 5040.0;
        const C2: f64 = -1.0 / 2.0;
        const C4: f64 = 1.0 / 24.0;
        const C6: f64 = -1.0 / 720.0;
        const C8: f64 = 1.0 / 40320.0;
        let d2 = delta * delta;
        let d4 = d2 * d2;
        let sin = delta * ((1.0 + S3 * d2) + d4 * (S5 + S7 * d2));
        let cos_m1 = d2 * ((C2 + C4 * d2) + d4 * (C6 + C8 * d2));
        return (sin, cos_m1);
    }
    let half = (0.5 * delta).sin();
    (delta.sin(), -2.0 * half * half)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series against the library's `sin δ` and the cancellation-free `−2·sin²(δ/2)`
    /// over ±0.2 rad, across the switch: within 4 ulp of each (rounding of a few
    /// operations; the truncation is below 1e-16 relative).
    #[test]
    fn the_series_is_the_library_to_rounding() {
        for i in -2000..=2000 {
            let delta = i as f64 * 1e-4 + 3.3e-6;
            let (sin, cos_m1) = sin_and_cos_minus_one(delta);
            let half = (0.5 * delta).sin();
            let (sin_ref, cos_ref) = (delta.sin(), -2.0 * half * half);
            assert!(
                (sin - sin_ref).abs() <= 4.0 * f64::EPSILON * sin_ref.abs(),
                "{delta}"
            );
            assert!(
                (cos_m1 - cos_ref).abs() <= 4.0 * f64::EPSILON * cos_ref.abs(),
                "{delta}"
            );
        }
    }

    /// A term at the mean crank angle (δ = 0) adds nothing, and at δ its value is the
    /// harmonic at the vibrating angle less the one at the mean angle.
    #[test]
    fn a_term_is_the_difference_of_the_two_angles() {
        let (q, phi, a, coefficient): (f64, f64, f64, f64) = (2.0, 0.7, 1.3, 5.0);
        let term = Term {
            cos_state: 1,
            column: 0,
            starts_column: true,
            coefficient,
            phase: (phi.cos(), phi.sin()),
            order: q,
        };
        let z = [0.0, (q * a).cos(), (q * a).sin()];
        let mut out = [1.0];
        remainder_into(std::slice::from_ref(&term), 0, &z, &mut out);
        assert_eq!(out[0], 0.0);
        let theta = 3e-3;
        let z = [theta, (q * a).cos(), (q * a).sin()];
        remainder_into(std::slice::from_ref(&term), 0, &z, &mut out);
        let expected = coefficient * ((q * a + phi + q * theta).cos() - (q * a + phi).cos());
        assert!(
            (out[0] - expected).abs() < 1e-12 * coefficient,
            "{} {expected}",
            out[0]
        );
    }
}
