//! Multi-start recalibration of the plain parameters (issue 14, item 5: "the
//! recalibration of plain parameters escapes local minima … because seed 12's case
//! already showed one").
//!
//! The plain fit is Levenberg–Marquardt on the linear surrogate ([`super::surrogate`]):
//! a local method, which from the user's values goes down into the nearest valley. Two
//! plain parameters that trade one natural frequency against another make valleys side by
//! side (a mode can be matched from either neighbour). So the fit starts from the user's
//! values *and* from a small deterministic design of scale factors within the plain
//! bounds (±30 %, [`super::context::PLAIN_BOUNDS`]): [`DESIGN_POINTS`] points of a Halton
//! sequence in `ln f` (prime bases 2, 3, 5, … one per parameter, from index 1; no
//! wall-clock seed, so a diagnosis is reproducible). The [`FITTED_STARTS`] design points
//! of lowest starting cost and the user's values are fitted on the surrogate, the lowest
//! fitted cost (data and prior, the fit's own objective) wins, and
//! the time-domain rounds go on from it ([`super::rounds`]). When the winner lies in
//! another valley than the single start's, both are run in the time domain once and the
//! better there is kept: the surrogate is exact only at the user's values, so a distant
//! valley must prove itself where the diagnosis scores.

use super::DiagnoseError;
use super::context::{
    Context, Evaluated, PLAIN_BOUNDS, PLAIN_PRIOR, SURROGATE_ITERATIONS, SURROGATE_TOLERANCE,
};
use super::fit::{Bounds, FitResult, levenberg_marquardt, parallel_map};
use super::rounds::Stepped;
use super::surrogate::scaled;

/// Design points besides the user's values. Each costs one surrogate fit (milliseconds
/// to a few tenths of a second); seven keep the plain fit within a second on two cores
/// for the issue-5 campaign's ~15 plain parameters.
pub const DESIGN_POINTS: usize = 7;
/// Design points fitted: the best by their starting cost (one surrogate evaluation each).
/// A full fit costs 30 iterations of `n + 1` evaluations; screening keeps the
/// multi-start within about twice the single fit's time on two cores.
pub const FITTED_STARTS: usize = 2;
/// Two fitted factor vectors closer than this (largest relative difference) are the same
/// minimum.
const SAME_MINIMUM: f64 = 2e-3;

/// The first primes, one Halton base per parameter (cycled beyond them).
const PRIMES: [u32; 24] = [
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89,
];

/// The radical inverse of `index` in `base`: the Halton coordinate, in (0, 1).
fn radical_inverse(mut index: u32, base: u32) -> f64 {
    let (mut value, mut scale) = (0.0, 1.0 / f64::from(base));
    while index > 0 {
        value += f64::from(index % base) * scale;
        index /= base;
        scale /= f64::from(base);
    }
    value
}

/// `points` start vectors of `n` factors within `bounds` (a bound with `log` spaced in
/// `ln f`): the Halton points 1..=points, parameter `j` in base `PRIMES[j % 24]`; beyond
/// 24 parameters the bases repeat with a shifted index, which keeps the coordinates
/// distinct.
pub fn design(n: usize, points: usize, bounds: &Bounds) -> Vec<Vec<f64>> {
    let (lo, hi) = if bounds.log {
        (bounds.lo.ln(), bounds.hi.ln())
    } else {
        (bounds.lo, bounds.hi)
    };
    (1..=points as u32)
        .map(|k| {
            (0..n)
                .map(|j| {
                    let shift = (j / PRIMES.len()) as u32 * 7;
                    let u = radical_inverse(k + shift, PRIMES[j % PRIMES.len()]);
                    let v = lo + u * (hi - lo);
                    if bounds.log { v.exp() } else { v }
                })
                .collect()
        })
        .collect()
}

/// Levenberg–Marquardt from `first` and from every point of `others`, each start on its
/// own thread (the fits themselves single-threaded). Returns every converged fit, best
/// (lowest cost) first; the fit from `first` is marked by index 0 of the second element.
pub fn multistart(
    first: &[f64],
    others: &[Vec<f64>],
    bounds: &[Bounds],
    iterations: usize,
    tolerance: f64,
    threads: usize,
    residuals: super::fit::Residuals,
) -> Vec<(FitResult, usize)> {
    let starts: Vec<&[f64]> = std::iter::once(first)
        .chain(others.iter().map(Vec::as_slice))
        .collect();
    let fits = parallel_map(starts.len(), threads, &|k| {
        levenberg_marquardt(starts[k], bounds, iterations, tolerance, 1, residuals)
            .filter(|f| f.cost.is_finite())
    });
    let mut out: Vec<(FitResult, usize)> = fits
        .into_iter()
        .enumerate()
        .filter_map(|(k, f)| f.map(|f| (f, k)))
        .collect();
    out.sort_by(|a, b| a.0.cost.total_cmp(&b.0.cost));
    out
}

/// The `keep` points of `points` with the lowest cost `Σ r²` (those that cannot be
/// evaluated dropped), evaluated on up to `threads` threads.
pub fn best_starts(
    points: Vec<Vec<f64>>,
    keep: usize,
    threads: usize,
    residuals: super::fit::Residuals,
) -> Vec<Vec<f64>> {
    let costs = parallel_map(points.len(), threads, &|k| {
        residuals(&points[k])
            .map(|r| r.iter().map(|v| v * v).sum::<f64>())
            .filter(|c| c.is_finite())
    });
    let mut ranked: Vec<(f64, Vec<f64>)> = costs
        .into_iter()
        .zip(points)
        .filter_map(|(c, p)| c.map(|c| (c, p)))
        .collect();
    ranked.sort_by(|a, b| a.0.total_cmp(&b.0));
    ranked.into_iter().take(keep).map(|(_, p)| p).collect()
}

/// Do two factor vectors name the same minimum ([`SAME_MINIMUM`])?
fn same(a: &[f64], b: &[f64]) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (x / y - 1.0).abs() < SAME_MINIMUM)
}

impl Context<'_> {
    /// The plain fit's surrogate proposals around `at`, from the user's values and the
    /// design ([`DESIGN_POINTS`]): the best, and the single start's when it found another
    /// minimum. Each with the surrogate's prediction in `simulated`.
    pub fn plain_proposals(&self, at: &Evaluated) -> Result<Vec<Evaluated>, DiagnoseError> {
        let n = self.plain.len();
        let around = self.around(at);
        let predict = |x: &[f64]| -> Option<Vec<f64>> {
            let m = scaled(self.user, &self.plain, x).ok()?;
            around.searched(&m, &self.observed, at.joint.as_ref())
        };
        let residuals = |x: &[f64]| -> Option<Vec<f64>> {
            let mut r = self.fit_z(&predict(x)?);
            r.extend(x.iter().map(|f| self.prior_weight * f.ln() / PLAIN_PRIOR));
            Some(r)
        };
        let bounds = vec![PLAIN_BOUNDS; n];
        let starts = best_starts(
            design(n, DESIGN_POINTS, &PLAIN_BOUNDS),
            FITTED_STARTS,
            self.options.threads,
            &residuals,
        );
        let fits = multistart(
            &at.factors,
            &starts,
            &bounds,
            SURROGATE_ITERATIONS,
            SURROGATE_TOLERANCE,
            self.options.threads,
            &residuals,
        );
        let mut chosen: Vec<Vec<f64>> = Vec::new();
        if let Some((best, _)) = fits.first() {
            chosen.push(best.x.clone());
        }
        if let Some((single, _)) = fits.iter().find(|(_, k)| *k == 0)
            && !chosen.iter().any(|c| same(c, &single.x))
        {
            chosen.push(single.x.clone());
        }
        if chosen.is_empty() {
            chosen.push(at.factors.clone());
        }
        chosen
            .into_iter()
            .map(|x| {
                let bad = || DiagnoseError::Input("bad plain fit".into());
                let m = scaled(self.user, &self.plain, &x).map_err(DiagnoseError::Input)?;
                let simulated = around
                    .at(&m, &self.observed, at.joint.as_ref())
                    .ok_or_else(bad)?;
                Ok(self.scored(m, at.joint.clone(), simulated, x, None))
            })
            .collect()
    }

    /// The plain fit: [`Self::plain_proposals`] from `baseline`, the better proposal in
    /// the time domain (when there are two), then up to `max` rounds in all.
    pub fn plain_fit(&self, baseline: &Evaluated, max: usize) -> Result<Stepped, DiagnoseError> {
        let mut proposals = self.plain_proposals(baseline)?;
        if proposals.len() == 1 {
            return Ok(self.rounds(baseline.clone(), None, max, proposals.pop()));
        }
        let mut best = baseline.clone();
        let mut rejected = Vec::new();
        for (k, p) in proposals.into_iter().enumerate() {
            // A start that cannot be simulated is a rejected step (issue 14, item 2).
            match self.evaluate(p.model, p.joint, p.factors, p.value) {
                Ok(e) if self.chi2(&e, false) < self.chi2(&best, false) => best = e,
                Ok(_) => {}
                Err(DiagnoseError::Cancelled) => return Err(DiagnoseError::Cancelled),
                Err(why) => rejected.push(format!("start {}: {why}", k + 1)),
            }
        }
        let mut stepped = self.rounds(best, None, max.saturating_sub(1), None);
        rejected.append(&mut stepped.rejected);
        stepped.rejected = rejected;
        Ok(stepped)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BOUNDS: Bounds = PLAIN_BOUNDS;

    /// A scale factor's two valleys: `r = [s·(u − a)(u − b), c·(u − b)]` in `u = ln f`,
    /// local minimum near `u = a = −0.15` (cost ≈ c²(a − b)² = 0.001225), global at
    /// `u = b = 0.2` (cost 0). From `u = 0` the quartic's slope, 2s²·ab(a + b)·… = +0.3,
    /// outweighs the tilt's −0.004: the descent goes left, into the wrong valley.
    fn two_valleys(x: &[f64]) -> Option<Vec<f64>> {
        let (a, b, s, c) = (-0.15, 0.2, 10.0, 0.1);
        let u = x[0].ln();
        Some(vec![s * (u - a) * (u - b), c * (u - b)])
    }

    /// The single start lands in the local minimum; the multi-start finds the global one.
    #[test]
    fn multistart_escapes_a_local_minimum() {
        let single = levenberg_marquardt(&[1.0], &[BOUNDS], 50, 1e-10, 1, &two_valleys).unwrap();
        // The local valley is at u ≈ a (the tilt moves it by < 0.01).
        assert!(
            (single.x[0].ln() + 0.15).abs() < 0.01,
            "single start: {:?}",
            single.x
        );
        let fits = multistart(
            &[1.0],
            &design(1, DESIGN_POINTS, &BOUNDS),
            &[BOUNDS],
            50,
            1e-10,
            2,
            &two_valleys,
        );
        let (best, _) = &fits[0];
        // The global minimum, to the fit's tolerance (cost 0 there: LM converges
        // quadratically, 1e-6 in u is far coarser than what it reaches).
        assert!((best.x[0].ln() - 0.2).abs() < 1e-6, "best: {:?}", best.x);
        assert!(best.cost < single.cost / 1e3);
        // Screening the design by starting cost keeps a start in the global valley.
        let kept = best_starts(
            design(1, DESIGN_POINTS, &BOUNDS),
            FITTED_STARTS,
            1,
            &two_valleys,
        );
        let fits2 = multistart(&[1.0], &kept, &[BOUNDS], 50, 1e-10, 2, &two_valleys);
        assert!((fits2[0].0.x[0].ln() - 0.2).abs() < 1e-6, "{kept:?}");
        // The single start's fit is among them, marked 0.
        assert!(
            fits.iter()
                .any(|(f, k)| *k == 0 && (f.x[0] - single.x[0]).abs() < 1e-9)
        );
    }

    /// The design is deterministic, within the bounds, and spreads each parameter over
    /// them (a Halton coordinate's first 7 points are the odd eighths and the quarters in base 2).
    #[test]
    fn design_is_deterministic_and_bounded() {
        let a = design(30, DESIGN_POINTS, &BOUNDS);
        assert_eq!(a, design(30, DESIGN_POINTS, &BOUNDS));
        assert_eq!(a.len(), DESIGN_POINTS);
        for p in &a {
            assert!(p.iter().all(|f| (0.7..=1.3).contains(f)), "{p:?}");
        }
        let first: Vec<f64> = a.iter().map(|p| p[0]).collect();
        let (lo, hi) = first
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(l, h), v| (l.min(*v), h.max(*v)));
        // Base 2 reaches 1/8 and 7/8 of [ln 0.7, ln 1.3]: 0.756 and 1.203.
        assert!(lo < 0.76 && hi > 1.2, "{first:?}");
        // Parameters 0 and 24 share base 2 but not their coordinates.
        assert!(a.iter().any(|p| (p[0] - p[24]).abs() > 1e-3));
    }
}
