//! Damped natural frequencies and damping ratios from the complex eigenproblem.
//!
//! For each undamped mode the quadratic eigenproblem `T(λ)x = (λ²M + λC + K)x = 0` is set
//! up with the rubber at that mode's frequency, its hysteretic damping as the equivalent
//! viscous `c = k·ξ_T/ω` at that frequency (seed 000 eq. 14, seed 001 eq. 2), and the
//! viscous damping of shafts, nodes and load. Its eigenvalue `λ = −ζω_n ± iω_d` gives the
//! damped frequency `ω_d/2π` and the damping ratio `ζ = −Re λ/|λ|`.
//!
//! The eigenvalue is found by Rayleigh-functional iteration started from the undamped
//! shape (`λ` from the scalar quadratic `xᵀT(λ)x = 0`, then `x ← T(λ)⁻¹T′(λ)x`), which
//! converges cubically for this complex-symmetric problem in three or four n×n solves.
//! When it does not converge, the eigenvalue of the 2n×2n state matrix
//! `[[0, I], [−M⁻¹K, −M⁻¹C]]` nearest the mode (by `|λ|`) is taken from a full Schur
//! decomposition instead — ~25 times the work, and what every mode cost before.
//!
//! A model with distributed shafts is solved on their lumped segments; its damping ratio
//! is that eigenvalue's and its damped frequency `f·√(1 − ζ²)` on the exact undamped `f`
//! ([`super::wittrick_williams`]), so the two tables never disagree by the lumping.

use super::undamped::Mode;
use crate::physics::{System, matrices};
use crate::response::lu::LuWorkspace;
use nalgebra::DMatrix;
use num_complex::Complex64;
use std::f64::consts::TAU;

/// Relative change of λ at which the iteration has converged.
const LAMBDA_TOLERANCE: f64 = 1e-13;
/// Iterations allowed before the Schur fallback.
const MAX_ITERATIONS: usize = 30;

/// Damped frequency and damping ratio of one mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampedMode {
    /// Damped natural frequency `ω_d/2π`, Hz (0 for an overdamped mode).
    pub frequency_hz: f64,
    /// Damping ratio ζ (fraction of critical).
    pub damping_ratio: f64,
}

/// The damped counterpart of each undamped mode, in the same order.
pub fn damped_modes(system: &System, modes: &[Mode]) -> Vec<DampedMode> {
    let mut lu = LuWorkspace::default();
    modes
        .iter()
        .map(|mode| {
            let f = mode.frequency_hz;
            let omega = (TAU * f).max(f64::MIN_POSITIVE);
            let k = matrices::stiffness_matrix(system, f);
            let mut c = matrices::damping_matrix(system);
            for e in &system.elements {
                let (stiffness, loss) = e.stiffness_at(f);
                matrices::add_spring(&mut c, e.from_dof, e.to_dof, stiffness * loss / omega);
            }
            let lambda = rayleigh_iteration(system, &k, &c, &mode.shape_dof, &mut lu)
                .or_else(|| nearest_state_eigenvalue(system, &k, &c, omega));
            match lambda {
                // Distributed shafts: ζ of the lumped segments, on the exact frequency.
                Some(l) if l.norm() > 0.0 && !system.distributed.is_empty() => {
                    let zeta = -l.re / l.norm();
                    DampedMode {
                        frequency_hz: f * (1.0 - zeta * zeta).max(0.0).sqrt(),
                        damping_ratio: zeta,
                    }
                }
                Some(l) if l.norm() > 0.0 => DampedMode {
                    frequency_hz: l.im / TAU,
                    damping_ratio: -l.re / l.norm(),
                },
                _ => DampedMode {
                    frequency_hz: f64::NAN,
                    damping_ratio: f64::NAN,
                },
            }
        })
        .collect()
}

/// `xᵀAx` for a real symmetric `a` and complex `x` (transpose, not conjugate).
fn quadratic_form(a: &DMatrix<f64>, x: &[Complex64]) -> Complex64 {
    let n = x.len();
    let mut sum = Complex64::default();
    for j in 0..n {
        let mut column = Complex64::default();
        for i in 0..n {
            column += x[i] * a[(i, j)];
        }
        sum += column * x[j];
    }
    sum
}

/// The root of `m λ² + c λ + k = 0` with `Im λ ≥ 0` nearest `previous`.
fn quadratic_root(m: Complex64, c: Complex64, k: Complex64, previous: Complex64) -> Complex64 {
    let root = (c * c - 4.0 * m * k).sqrt();
    let (a, b) = ((-c + root) / (2.0 * m), (-c - root) / (2.0 * m));
    let score = |l: Complex64| (l.im < 0.0, (l - previous).norm_sqr());
    if score(a) <= score(b) { a } else { b }
}

/// Rayleigh-functional iteration from the undamped shape `shape`; `None` when it does not
/// converge (the caller falls back to the state matrix).
fn rayleigh_iteration(
    system: &System,
    k: &DMatrix<f64>,
    c: &DMatrix<f64>,
    shape: &[f64],
    lu: &mut LuWorkspace,
) -> Option<Complex64> {
    let n = shape.len();
    let m = &system.inertia_kg_m2;
    let mut x: Vec<Complex64> = shape.iter().map(|&v| Complex64::new(v, 0.0)).collect();
    let mass_form =
        |x: &[Complex64]| -> Complex64 { x.iter().zip(m).map(|(v, &j)| v * v * j).sum() };
    // The undamped eigenvalue iω_n picks the root of the first quadratic.
    let start = Complex64::new(
        0.0,
        (quadratic_form(k, &x) / mass_form(&x)).re.max(0.0).sqrt(),
    );
    let mut lambda = quadratic_root(
        mass_form(&x),
        quadratic_form(c, &x),
        quadratic_form(k, &x),
        start,
    );
    let mut t = DMatrix::<Complex64>::zeros(n, n);
    for _ in 0..MAX_ITERATIONS {
        // T(λ) and the right-hand side T′(λ)x = (2λM + C)x.
        let mut rhs = vec![Complex64::default(); n];
        for j in 0..n {
            for i in 0..n {
                t[(i, j)] = lambda * c[(i, j)] + k[(i, j)];
                rhs[i] += x[j] * c[(i, j)];
            }
            t[(j, j)] += lambda * lambda * m[j];
            rhs[j] += 2.0 * lambda * m[j] * x[j];
        }
        if !lu.factor_solve(&mut t, &mut rhs) || !rhs.iter().all(|v| v.is_finite()) {
            // λ is an eigenvalue to working precision.
            return Some(lambda);
        }
        let scale = rhs.iter().map(|v| v.norm_sqr()).fold(0.0, f64::max).sqrt();
        if scale == 0.0 {
            return None;
        }
        x = rhs.iter().map(|v| v / scale).collect();
        let next = quadratic_root(
            mass_form(&x),
            quadratic_form(c, &x),
            quadratic_form(k, &x),
            lambda,
        );
        let step = (next - lambda).norm();
        lambda = next;
        if step <= LAMBDA_TOLERANCE * lambda.norm() {
            return Some(lambda);
        }
    }
    None
}

/// The eigenvalue of the state matrix nearest `omega` in magnitude, upper half-plane.
fn nearest_state_eigenvalue(
    system: &System,
    k: &DMatrix<f64>,
    c: &DMatrix<f64>,
    omega: f64,
) -> Option<Complex64> {
    let n = system.dof_count();
    let mut a = DMatrix::<f64>::zeros(2 * n, 2 * n);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        let inv_j = 1.0 / system.inertia_kg_m2[i];
        for j in 0..n {
            a[(n + i, j)] = -k[(i, j)] * inv_j;
            a[(n + i, n + j)] = -c[(i, j)] * inv_j;
        }
    }
    a.complex_eigenvalues()
        .iter()
        .filter(|l| l.im >= 0.0)
        .min_by(|x, y| {
            (x.norm() - omega)
                .abs()
                .total_cmp(&(y.norm() - omega).abs())
        })
        .copied()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::modal::modes;
    use crate::model::{parse_model, presets};
    use crate::physics::OperatingPoint;

    /// On every mode of every preset, the iteration's eigenvalue is the one the full
    /// state-matrix decomposition picks, to 5e-8 relative. The Schur decomposition is the
    /// less accurate of the two here: its error is ~ε‖A‖ times the eigenvalue's condition,
    /// and ‖A‖ = max k/J of a crank train or a stiff gear mesh on a light pinion is 1e3–1e4
    /// times a low mode's |λ|². Measured: the cng-genset coupling mode differs by 1.2e-9,
    /// genset-20dof's 232 Hz mode (coupling and gearbox, its stages' loss far from
    /// proportional) by 1.2e-8. T(λ) at the iteration's λ is checked to be singular to
    /// 1e-13 (σ_min/σ_max), and more so than at Schur's (seen: 0 vs 5e-15–2e-10), so the
    /// gap is Schur's.
    #[test]
    fn equals_the_state_matrix_eigenvalue_on_every_preset_mode() {
        let mut lu = LuWorkspace::default();
        let mut checked = 0;
        for preset in presets::PRESETS {
            let model = parse_model(preset.text, preset.name).expect("preset");
            let system = System::new(&model, OperatingPoint::default()).expect("system");
            for mode in modes(&system).expect("modes") {
                let f = mode.frequency_hz;
                let omega = TAU * f;
                let k = matrices::stiffness_matrix(&system, f);
                let mut c = matrices::damping_matrix(&system);
                for e in &system.elements {
                    let (stiffness, loss) = e.stiffness_at(f);
                    matrices::add_spring(&mut c, e.from_dof, e.to_dof, stiffness * loss / omega);
                }
                let fast = rayleigh_iteration(&system, &k, &c, &mode.shape_dof, &mut lu)
                    .expect("converges");
                let full = nearest_state_eigenvalue(&system, &k, &c, omega).expect("eigenvalue");
                assert!(
                    (fast - full).norm() <= 5e-8 * full.norm(),
                    "{} mode at {f:.3} Hz: {fast} vs {full}",
                    preset.name
                );
                checked += 1;
                // T(λ) must be singular to working precision, at least as much as at Schur's λ.
                let n = system.dof_count();
                let t = |l: Complex64| {
                    DMatrix::<Complex64>::from_fn(n, n, |i, j| {
                        let mass = if i == j { system.inertia_kg_m2[i] } else { 0.0 };
                        l * l * mass + l * c[(i, j)] + k[(i, j)]
                    })
                };
                // How singular T(λ) is: σ_min/σ_max, zero at an exact eigenvalue.
                let residual = |l: Complex64| {
                    let sv = t(l).singular_values();
                    sv.min() / sv.max()
                };
                let (residual, schur_residual) = (residual(fast), residual(full));
                eprintln!(
                    "{} {f:.2} Hz: {residual:e} vs Schur {schur_residual:e}",
                    preset.name
                );
                assert!(
                    residual <= schur_residual && residual <= 1e-13,
                    "{}: residual {residual:e}, Schur's {schur_residual:e}",
                    preset.name
                );
            }
        }
        assert!(checked >= 20, "{checked} modes checked");
    }

    /// A critically damped 1-DOF oscillator (ζ = 1) still gives ζ = 1 (λ is a double real
    /// root: the iteration stops on a singular T(λ) or converges onto it).
    #[test]
    fn a_heavily_damped_mode_keeps_its_damping_ratio() {
        let text = "format = 1\nname = \"one\"\n[[inertia]]\nname = \"a\"\ninertia = 2.0\n\
            [[connection]]\nkind = \"shaft\"\nfrom = \"a\"\nto = \"ground\"\nstiffness = 800.0\n\
            damping = 48.0\n";
        let model = parse_model(text, "one.toml").expect("model");
        let system = System::new(&model, OperatingPoint::default()).expect("system");
        let modes = modes(&system).expect("modes");
        // ω_n = 20 rad/s, c_crit = 2·J·ω_n = 80: ζ = 0.6, ω_d = 16 rad/s.
        let d = damped_modes(&system, &modes)[0];
        assert!((d.damping_ratio - 0.6).abs() < 1e-12, "{d:?}");
        assert!((d.frequency_hz - 16.0 / TAU).abs() < 1e-12, "{d:?}");
    }
}
