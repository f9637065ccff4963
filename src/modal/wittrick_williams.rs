//! Exact natural frequencies of a driveline with distributed shafts, by the
//! Wittrick–Williams count (Wittrick & Williams, *A general algorithm for computing
//! natural frequencies of elastic structures*, Q. J. Mech. Appl. Math. 24, 1971).
//!
//! With exact elements the dynamic stiffness `D(ω)` is transcendental in ω, and a shaft
//! has more modes than its end DOFs. The number of natural frequencies strictly below ω is
//!
//! ```text
//! J(ω) = J0(ω) + s{D(ω)}
//! ```
//!
//! with `s` the number of negative eigenvalues of `D(ω)` on the node DOFs (the negative
//! pivots of its LDLᵀ, Sylvester's law of inertia) and `J0` the frequencies of every
//! shaft with both ends clamped (β = π, 2π, …, [`distributed::clamped_below`]). Mode `i`
//! is where `J` steps from `i` to `i + 1`, found by bisection on `J`; bisection cannot
//! miss a root or take a neighbour's, even where `D` has a pole.
//!
//! `D(ω)` here is the node DOFs' dynamic stiffness without damping: every element other
//! than the distributed shafts at its stiffness at ω (rubber's storage, as the undamped
//! modes use), `−ω²` times the nodes' own inertia, and each distributed shaft as one exact
//! element. Its internal DOFs (the time domain's segments) do not enter.
//!
//! Written here: the count is a few lines over torsim's own assembly, and no crate has it.

use crate::physics::{System, distributed, matrices};
use nalgebra::DMatrix;
use num_complex::Complex64;
use std::f64::consts::TAU;

/// Bisection stops at this relative bracket width.
const RELATIVE_TOLERANCE: f64 = 1.0e-13;
/// Bisection steps allowed (each halves the bracket).
const MAX_STEPS: usize = 200;

/// Natural frequencies (Hz) of `system`'s exact elements with indices `first..first +
/// count` over all modes, rigid-body ones included (index 0 is the lowest), each started
/// from `guess_hz[i]` (the lumped chain's, which lies below the exact one).
pub fn exact_frequencies_hz(system: &System, first: usize, guess_hz: &[f64]) -> Vec<f64> {
    let counter = Counter::new(system);
    guess_hz
        .iter()
        .enumerate()
        .map(|(i, &guess)| counter.root_hz(first + i, guess))
        .collect()
}

/// What the count needs of a system, built once.
struct Counter<'a> {
    system: &'a System,
    /// Number of node DOFs (internal DOFs of distributed shafts follow them).
    n: usize,
    /// The nodes' own inertia: the system's less the segments' lumped halves, kg·m².
    node_inertia_kg_m2: Vec<f64>,
    /// Elements that are not segments of a distributed shaft.
    others: Vec<usize>,
}

impl<'a> Counter<'a> {
    fn new(system: &'a System) -> Self {
        let n = system.dof_of_node.iter().max().map_or(0, |m| m + 1);
        let node_inertia_kg_m2 = system.inertia_kg_m2[..n]
            .iter()
            .zip(system.segment_inertia_kg_m2())
            .map(|(j, segments)| j - segments)
            .collect();
        let mut segment = vec![false; system.elements.len()];
        for d in &system.distributed {
            for e in d.elements.clone() {
                segment[e] = true;
            }
        }
        let others = (0..system.elements.len())
            .filter(|&e| !segment[e])
            .collect();
        Self {
            system,
            n,
            node_inertia_kg_m2,
            others,
        }
    }

    /// Natural frequencies strictly below `omega_rad_s`.
    fn count(&self, omega_rad_s: f64) -> usize {
        let frequency_hz = omega_rad_s / TAU;
        let mut d = DMatrix::<f64>::zeros(self.n, self.n);
        for (i, j) in self.node_inertia_kg_m2.iter().enumerate() {
            d[(i, i)] -= omega_rad_s * omega_rad_s * j;
        }
        for &e in &self.others {
            let e = &self.system.elements[e];
            matrices::add_spring(&mut d, e.from_dof, e.to_dof, e.stiffness_at(frequency_hz).0);
        }
        let mut j0 = 0;
        for s in &self.system.distributed {
            let (k, j) = (s.stiffness_nm_per_rad, s.inertia_kg_m2);
            j0 += distributed::clamped_below(k, j, omega_rad_s);
            let (aa, ab) = distributed::exact_ends(Complex64::new(k, 0.0), j, omega_rad_s);
            matrices::add_two_port(&mut d, s.from_dof, s.to_dof, aa.re, ab.re);
        }
        j0 + negative_pivots(d)
    }

    /// The frequency (Hz) where the count steps past `index`, from `guess_hz`.
    fn root_hz(&self, index: usize, guess_hz: f64) -> f64 {
        let guess = (TAU * guess_hz).max(1e-9);
        let (mut lo, mut hi) = (0.5 * guess, 1.5 * guess);
        for _ in 0..MAX_STEPS {
            if self.count(lo) <= index {
                break;
            }
            lo *= 0.5;
        }
        for _ in 0..MAX_STEPS {
            if self.count(hi) > index {
                break;
            }
            hi *= 1.5;
        }
        for _ in 0..MAX_STEPS {
            if hi - lo <= RELATIVE_TOLERANCE * hi {
                break;
            }
            let mid = 0.5 * (lo + hi);
            if self.count(mid) > index {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        0.5 * (lo + hi) / TAU
    }
}

/// Negative eigenvalues of a real symmetric matrix: the negative pivots of its LDLᵀ
/// (Gaussian elimination without pivoting keeps the inertia). A pivot of exactly zero is
/// taken as positive (the count then belongs to the frequency just above).
fn negative_pivots(mut a: DMatrix<f64>) -> usize {
    let n = a.nrows();
    let mut negatives = 0;
    for k in 0..n {
        let mut pivot = a[(k, k)];
        if pivot == 0.0 || !pivot.is_finite() {
            pivot = f64::MIN_POSITIVE;
        }
        if pivot < 0.0 {
            negatives += 1;
        }
        for i in k + 1..n {
            let l = a[(i, k)] / pivot;
            if l == 0.0 {
                continue;
            }
            for j in k + 1..n {
                a[(i, j)] -= l * a[(k, j)];
            }
        }
    }
    negatives
}

#[cfg(test)]
mod tests {
    use super::negative_pivots;
    use nalgebra::DMatrix;

    #[test]
    fn pivots_count_the_negative_eigenvalues() {
        let a = DMatrix::from_row_slice(3, 3, &[2.0, -1.0, 0.0, -1.0, -3.0, 1.0, 0.0, 1.0, 0.5]);
        let negatives = a
            .clone()
            .symmetric_eigenvalues()
            .iter()
            .filter(|v| **v < 0.0)
            .count();
        assert_eq!(negative_pivots(a), negatives);
    }
}
