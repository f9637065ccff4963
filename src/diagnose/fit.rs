//! Levenberg–Marquardt on a few bounded parameters, with a forward-difference Jacobian.
//!
//! The residual function is a simulation (seconds) or the linear model (milliseconds), so
//! the fitter counts evaluations: each iteration costs one evaluation per parameter for the
//! Jacobian and one per trial step. Parameters live in an unbounded internal coordinate:
//! `ln x` for scale-like ones, and a clamp to the bounds otherwise.

use nalgebra::{DMatrix, DVector};

/// One parameter's bounds and scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
    /// Fitted as `ln x` (requires `lo > 0`).
    pub log: bool,
}

/// How a fit went.
#[derive(Debug, Clone, PartialEq)]
pub struct FitResult {
    /// The parameters found.
    pub x: Vec<f64>,
    /// Σ r² there.
    pub cost: f64,
    /// Residual evaluations used.
    pub evaluations: usize,
}

fn to_internal(x: f64, b: &Bounds) -> f64 {
    let x = x.clamp(b.lo, b.hi);
    if b.log { x.ln() } else { x }
}

fn to_external(u: f64, b: &Bounds) -> f64 {
    let x = if b.log { u.exp() } else { u };
    x.clamp(b.lo, b.hi)
}

/// A residual function: `None` where the model cannot be evaluated.
pub type Residuals<'a> = &'a (dyn Fn(&[f64]) -> Option<Vec<f64>> + Sync);

/// The offset from the middle of three equally spaced points, `step` apart, to the vertex
/// of the parabola through their values `before`, `middle` and `after`; `None` when the
/// parabola has no minimum (curvature ≤ 0 or not finite). In units of the abscissa.
pub fn parabola_vertex_offset(before: f64, middle: f64, after: f64, step: f64) -> Option<f64> {
    let curvature = before - 2.0 * middle + after;
    (curvature > 0.0 && curvature.is_finite()).then(|| 0.5 * step * (before - after) / curvature)
}

/// Minimizes `Σ r(x)²` from `start` within `bounds` in at most `max_iterations`
/// Levenberg–Marquardt steps, stopping when a step gains less than `tolerance` of the
/// cost. `residuals` returns `None` where the model cannot be evaluated (the step is then
/// refused, as one that does not improve). The Jacobian's columns are evaluated on up to
/// `threads` threads.
pub fn levenberg_marquardt(
    start: &[f64],
    bounds: &[Bounds],
    max_iterations: usize,
    tolerance: f64,
    threads: usize,
    residuals: Residuals,
) -> Option<FitResult> {
    let n = start.len();
    let mut u: Vec<f64> = start
        .iter()
        .zip(bounds)
        .map(|(x, b)| to_internal(*x, b))
        .collect();
    let external = |u: &[f64]| -> Vec<f64> {
        u.iter()
            .zip(bounds)
            .map(|(v, b)| to_external(*v, b))
            .collect()
    };
    let mut evaluations = 1;
    let mut r = residuals(&external(&u))?;
    let mut cost: f64 = r.iter().map(|v| v * v).sum();
    let mut lambda = 1e-2;
    for _ in 0..max_iterations {
        // Forward differences: a relative step in the internal coordinate, backward from
        // the upper bound (a step past a bound is clamped back, and the parameter would
        // look inert there and never leave it).
        let mut jac = DMatrix::<f64>::zeros(r.len(), n);
        let steps: Vec<f64> = (0..n)
            .map(|j| {
                let h = 1e-3 * u[j].abs().max(if bounds[j].log { 1.0 } else { 1e-2 });
                if to_external(u[j] + h, &bounds[j]) < bounds[j].hi {
                    h
                } else {
                    -h
                }
            })
            .collect();
        let column = |j: usize| {
            let mut up = u.clone();
            up[j] += steps[j];
            residuals(&external(&up))
        };
        evaluations += n;
        // A column that could not be evaluated (or panicked) is skipped.
        for (j, rj) in parallel_map(n, threads, &column).into_iter().enumerate() {
            let Some(rj) = rj else { continue };
            for (i, (a, b)) in rj.iter().zip(&r).enumerate() {
                jac[(i, j)] = (a - b) / steps[j];
            }
        }
        let jt = jac.transpose();
        let jtj = &jt * &jac;
        let g = &jt * DVector::from_vec(r.clone());
        let mut improved = false;
        for _ in 0..6 {
            let mut a = jtj.clone();
            for k in 0..n {
                a[(k, k)] += lambda * jtj[(k, k)].max(1e-12);
            }
            let Some(step) = a.lu().solve(&(-&g)) else {
                lambda *= 10.0;
                continue;
            };
            let trial: Vec<f64> = u.iter().zip(step.iter()).map(|(a, s)| a + s).collect();
            // Clamp into the bounds in the internal coordinate.
            let trial: Vec<f64> = trial
                .iter()
                .zip(bounds)
                .map(|(v, b)| to_internal(to_external(*v, b), b))
                .collect();
            evaluations += 1;
            if let Some(rt) = residuals(&external(&trial)) {
                let c: f64 = rt.iter().map(|v| v * v).sum();
                if c < cost {
                    let gain = (cost - c) / cost.max(1e-300);
                    u = trial;
                    r = rt;
                    cost = c;
                    lambda = (lambda / 3.0).max(1e-7);
                    improved = gain > tolerance;
                    break;
                }
            }
            lambda *= 8.0;
        }
        if !improved {
            break;
        }
    }
    Some(FitResult {
        x: external(&u),
        cost,
        evaluations,
    })
}

/// `each(k)` for `k` in `0..n`, on up to `threads` threads, in order. A panicking call
/// leaves its slot `None`, like one that returns `None`.
pub fn parallel_map<T: Send>(
    n: usize,
    threads: usize,
    each: &(dyn Fn(usize) -> Option<T> + Sync),
) -> Vec<Option<T>> {
    let threads = threads.clamp(1, n.max(1));
    if threads == 1 {
        return (0..n).map(each).collect();
    }
    let mut out: Vec<Option<T>> = (0..n).map(|_| None).collect();
    std::thread::scope(|scope| {
        let chunks: Vec<_> = out
            .chunks_mut(n.div_ceil(threads))
            .enumerate()
            .map(|(c, chunk)| {
                let first = c * n.div_ceil(threads);
                scope.spawn(move || {
                    for (k, slot) in chunk.iter_mut().enumerate() {
                        *slot = each(first + k);
                    }
                })
            })
            .collect();
        for c in chunks {
            let _ = c.join();
        }
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An exponential decay `a·exp(−t/τ)` is found from a far start, within its bounds.
    #[test]
    fn fits_an_exponential() {
        let t: Vec<f64> = (0..20).map(|k| k as f64 * 0.1).collect();
        let y: Vec<f64> = t.iter().map(|t| 3.0 * (-t / 0.7_f64).exp()).collect();
        let bounds = [
            Bounds {
                lo: 0.1,
                hi: 10.0,
                log: true,
            },
            Bounds {
                lo: 0.01,
                hi: 5.0,
                log: true,
            },
        ];
        let fit = levenberg_marquardt(&[1.0, 2.0], &bounds, 50, 1e-4, 2, &|x| {
            Some(
                t.iter()
                    .zip(&y)
                    .map(|(t, y)| x[0] * (-t / x[1]).exp() - y)
                    .collect(),
            )
        })
        .unwrap();
        assert!((fit.x[0] - 3.0).abs() < 1e-6, "{:?}", fit.x);
        assert!((fit.x[1] - 0.7).abs() < 1e-6, "{:?}", fit.x);
        // A bound that excludes the answer holds.
        let tight = [
            bounds[0],
            Bounds {
                lo: 1.0,
                hi: 5.0,
                log: false,
            },
        ];
        let fit = levenberg_marquardt(&[1.0, 2.0], &tight, 50, 1e-4, 1, &|x| {
            Some(
                t.iter()
                    .zip(&y)
                    .map(|(t, y)| x[0] * (-t / x[1]).exp() - y)
                    .collect(),
            )
        })
        .unwrap();
        assert!(fit.x[1] >= 1.0);
    }

    /// A parameter started at its upper bound comes back when the minimum is inside (a
    /// forward difference there is clamped to zero and would keep it at the bound).
    #[test]
    fn leaves_an_upper_bound() {
        let bounds = [Bounds {
            lo: 0.7,
            hi: 1.3,
            log: true,
        }];
        let fit = levenberg_marquardt(&[1.3], &bounds, 50, 1e-10, 1, &|x| {
            Some(vec![x[0] - 1.1, 2.0 * (x[0] - 1.1)])
        })
        .unwrap();
        assert!((fit.x[0] - 1.1).abs() < 1e-6, "{:?}", fit.x);
    }

    /// The vertex of a parabola sampled at three points is exact, and a maximum or a
    /// straight line has none.
    #[test]
    fn finds_a_parabolas_vertex() {
        let f = |x: f64| 2.0 * (x - 0.37).powi(2) + 5.0;
        let (x0, h) = (0.5, 0.25);
        let offset = parabola_vertex_offset(f(x0 - h), f(x0), f(x0 + h), h).unwrap();
        assert!((x0 + offset - 0.37).abs() < 1e-12, "{offset}");
        assert_eq!(parabola_vertex_offset(1.0, 2.0, 1.0, h), None);
        assert_eq!(parabola_vertex_offset(1.0, 2.0, 3.0, h), None);
        assert_eq!(parabola_vertex_offset(f64::INFINITY, 2.0, 3.0, h), None);
    }
}
