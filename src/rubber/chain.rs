//! The causal representation of a rubber stage that every view of a model uses: a
//! generalized Maxwell chain fitted to seed 000's law where the model's modes and excited
//! orders lie (`spec/model-format.md`, `kind = "rubber"`; issue 15).
//!
//! The torque (per unit static stiffness `c_Tstat`, before the amplitude and temperature
//! factors) of vibration `φ` about the static twist is `k∞·φ + Σ_j k_j (φ − q_j)` with
//! `q̇_j = (φ − q_j)/τ_j`; its complex stiffness is `K*(ω) = k∞ + Σ_j k_j·iωτ_j/(1 + iωτ_j)`.
//! The static twist itself is held by the static stiffness `κ0 = α_f(0)` (a causal power
//! law's plateau below the band), so the mean twist under the mean torque is the spec's.
//!
//! The target is seed 000's law `α_f(f)·(1 + iξ0)`, `ξ0 = ψ/2π·α_Tξ(T0)` at the stage's
//! `temperature_c` (eq. 9, 11, 13–15), or a causal power law
//! `(f/f_ref)^n·(1 + i·max(ξ0, tan(nπ/2)))` ([`crate::model::frequency_law`]), or a
//! fractional Zener law, whose loss factor varies with frequency
//! ([`crate::model::frequency_zener`]).
//! Rows of the non-negative least squares, all as relative errors:
//! - the band, [`SAMPLES_PER_DECADE`] frequencies per decade; storage rows weigh
//!   [`STIFFNESS_WEIGHT`] × the loss rows (storage places the resonances);
//! - each of the model's modes inside `[lo/3, 1.5·hi]`, weighted [`MODE_WEIGHT`] × the
//!   stage's share of that mode's strain energy: where the stage matters, the chain meets
//!   the law there;
//! - one static row, [`STATIC_WEIGHT`], holding `k∞` softly at `κ0`.
//!
//! Unknowns: `k∞ ≥ 0` and arm stiffnesses `k_j ≥ 0` at relaxation times spaced
//! [`ARMS_PER_DECADE`] per decade from `min(lo, lowest mode)/1.5` to `1.5·hi`.
//!
//! A frequency-independent loss factor is not causal (Kramers–Kronig): a causal material
//! with a nearly constant loss must stiffen with frequency, by about `(2/π)·ξ·ln(f2/f1)`
//! between two frequencies. The fit therefore meets ψ and α_f exactly at one mode, closely
//! at modes near each other, and only approximately over a wide band;
//! [`MaxwellChain::stiffness_error`] and [`MaxwellChain::loss_error`] give its worst
//! relative errors over the band, and [`crate::modal::law_deviations`] its deviation at
//! each mode.

use super::nnls::nnls_from;
use crate::model::RubberStage;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use std::cell::RefCell;
use std::f64::consts::TAU;

/// Relaxation times per decade of frequency.
pub const ARMS_PER_DECADE: f64 = 4.0;
/// Fit frequencies per decade of the band.
pub const SAMPLES_PER_DECADE: f64 = 12.0;
/// Weight of the stiffness rows against the loss rows: stiffness places the resonances,
/// so it is matched first where the two cannot both be met.
pub const STIFFNESS_WEIGHT: f64 = 2.0;
/// Weight of a mode's rows per unit strain-energy share of the stage in that mode: a
/// mode the stage dominates outweighs the ~40 band rows together by 2.5×, so the chain
/// meets the law at it (to 0.1 % for one such mode, measured in the tests below).
pub const MODE_WEIGHT: f64 = 100.0;
/// Weight of the static row `k∞ = κ0`: soft, so that `k∞` may give way where the band's
/// Kramers–Kronig stiffening asks for it, yet stays near the static stiffness.
pub const STATIC_WEIGHT: f64 = 0.3;
/// A causal power law's static stiffness is the law's value this factor below the slowest
/// arm: the law's relaxation goes on below the band, and the loss it gives at the band's
/// lower end needs arms below it.
const PLATEAU_BELOW_ARMS: f64 = 4.0;

/// A mode the chain is fitted at: its frequency and the stage's share of its strain energy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeTarget {
    /// Natural frequency, Hz.
    pub frequency_hz: f64,
    /// The stage's share of the mode's strain energy, 0…1.
    pub energy_share: f64,
}

/// A fitted generalized Maxwell chain (stiffnesses relative to `c_Tstat`).
#[derive(Debug, Clone, PartialEq)]
pub struct MaxwellChain {
    /// Equilibrium stiffness `k∞` of vibration about the static twist, relative.
    pub equilibrium: f64,
    /// Static stiffness `κ0` that holds the static twist, relative: α_f(0), or a power
    /// law's plateau.
    pub static_stiffness: f64,
    /// Arms `(k_j, τ_j)`: relative stiffness and relaxation time in s; arms the fit gave
    /// zero stiffness are dropped.
    pub arms: Vec<(f64, f64)>,
    /// The band fitted, Hz.
    pub band_hz: [f64; 2],
    /// Worst relative error of the real part (stiffness) over the band.
    pub stiffness_error: f64,
    /// Worst relative error of the imaginary part (loss) over the band.
    pub loss_error: f64,
}

thread_local! {
    /// Which arms (and the equilibrium spring) came out positive in the last chain this
    /// thread fitted: the next fit starts from it ([`nnls_from`], which gives the same
    /// chain from any start).
    static LAST_SUPPORT: RefCell<Vec<bool>> = const { RefCell::new(Vec::new()) };
}

impl MaxwellChain {
    /// Fits the chain to `stage`'s α_f and ψ over `band_hz = [lo, hi]` (lo > 0) and at
    /// `modes`; what [`MaxwellChain::fit_at_modes`] does when it has not seen the stage,
    /// band and modes before.
    pub(super) fn fit_uncached(
        stage: &RubberStage,
        band_hz: [f64; 2],
        modes: &[ModeTarget],
    ) -> Self {
        let [lo, hi] = [band_hz[0].max(1e-3), band_hz[1].max(band_hz[0] * 1.01)];
        // The nominal loss factor at the stage's own temperature, ξ_T = ψ/2π·α_Tξ(T0)
        // (eq. 11, 15; a power law's tan(nπ/2) if larger): the chain meets the law there,
        // and its arms scale by α_Tξ(T)/α_Tξ(T0) at other temperatures.
        // A Zener law's loss varies with frequency ([`crate::model::frequency_zener`]);
        // every other law's is the same at every frequency.
        let state = stage.state(None, stage.temperature_c, 0.0);
        let catalogue = stage.catalogue_loss_factor(state.alpha_txi);
        let xi_at = |f: f64| stage.loss_factor_at(Some(f), catalogue);
        let alpha_f = |f: f64| stage.frequency_factor(f);
        let modes: Vec<ModeTarget> = modes
            .iter()
            .copied()
            .filter(|m| {
                m.frequency_hz >= lo / 3.0 && m.frequency_hz <= 1.5 * hi && m.energy_share > 0.0
            })
            .collect();
        let lowest = modes.iter().map(|m| m.frequency_hz).fold(lo, f64::min);
        let (arm_lo, arm_hi) = (lowest / 1.5, hi * 1.5);
        let static_stiffness = match stage.frequency_power_law {
            Some(law) if stage.frequency_zener.is_none() => {
                law.storage(arm_lo / PLATEAU_BELOW_ARMS)
            }
            _ => alpha_f(0.0),
        };
        let n_arms = ((arm_hi / arm_lo).log10() * ARMS_PER_DECADE).ceil() as usize + 1;
        let taus: Vec<f64> = log_space(arm_lo, arm_hi, n_arms)
            .iter()
            .map(|f| 1.0 / (TAU * f))
            .collect();
        let n_samples = (((hi / lo).log10() * SAMPLES_PER_DECADE).ceil() as usize + 1).max(8);
        // Rows: (frequency, weight).
        let rows: Vec<(f64, f64)> = log_space(lo, hi, n_samples)
            .into_iter()
            .map(|f| (f, 1.0))
            .chain(
                modes
                    .iter()
                    .map(|m| (m.frequency_hz, MODE_WEIGHT * m.energy_share)),
            )
            .collect();
        let n_cols = n_arms + 1;
        let mut a = DMatrix::<f64>::zeros(2 * rows.len() + 1, n_cols);
        let mut b = DVector::<f64>::zeros(2 * rows.len() + 1);
        for (s, &(f, weight)) in rows.iter().enumerate() {
            let target = alpha_f(f);
            let xi0 = xi_at(f);
            let (ws, wl) = (weight * STIFFNESS_WEIGHT / target, weight / (target * xi0));
            a[(2 * s, 0)] = ws;
            for (j, &tau) in taus.iter().enumerate() {
                let arm = arm_response(TAU * f, tau);
                a[(2 * s, j + 1)] = ws * arm.re;
                a[(2 * s + 1, j + 1)] = wl * arm.im;
            }
            b[2 * s] = ws * target;
            b[2 * s + 1] = wl * target * xi0;
        }
        let last = 2 * rows.len();
        a[(last, 0)] = STATIC_WEIGHT / static_stiffness;
        b[last] = STATIC_WEIGHT;
        // From the support of this thread's last fit: a fit's neighbours share it.
        let k = LAST_SUPPORT.with(|last| {
            let k = nnls_from(&a, &b, &last.borrow());
            *last.borrow_mut() = k.iter().map(|v| *v > 0.0).collect();
            k
        });
        let arms: Vec<(f64, f64)> = k
            .iter()
            .skip(1)
            .zip(&taus)
            .filter(|(k, _)| **k > 0.0)
            .map(|(k, t)| (*k, *t))
            .collect();
        let mut chain = MaxwellChain {
            equilibrium: k[0],
            static_stiffness,
            arms,
            band_hz: [lo, hi],
            stiffness_error: 0.0,
            loss_error: 0.0,
        };
        for f in log_space(lo, hi, 4 * n_samples) {
            let k = chain.complex_stiffness(f);
            let target = alpha_f(f);
            let xi0 = xi_at(f);
            chain.stiffness_error = chain.stiffness_error.max((k.re - target).abs() / target);
            chain.loss_error = chain
                .loss_error
                .max((k.im - target * xi0).abs() / (target * xi0));
        }
        chain
    }

    /// Takes out the arms that relax faster than `above_hz` (`1/(2πτ_j) > above_hz`) and
    /// returns their low-frequency limit, a dashpot `Σ k_j·τ_j` (relative stiffness × s)
    /// that stands in for them. At a frequency `f` the dashpot differs from an arm by
    /// `k_j·(2πfτ_j)²/(1 + (2πfτ_j)²)` in stiffness and `k_j·(2πfτ_j)³/(1 + (2πfτ_j)²)` in
    /// loss, so below `above_hz / 3` by at most 10 % and 3.4 % of the arms taken out. Those
    /// arms' stiffness is what bounds an explicit integrator's step (its stability limit,
    /// `h/τ_j ≲ 3.3` for Dormand–Prince), so a run that compares only frequencies well
    /// below `above_hz` can step several times further with them as a dashpot.
    pub fn take_fast_arms(&mut self, above_hz: f64) -> f64 {
        let fast = |tau: f64| 1.0 / (TAU * tau) > above_hz;
        let viscous_s = self
            .arms
            .iter()
            .filter(|(_, tau)| fast(*tau))
            .map(|(k, tau)| k * tau)
            .sum();
        self.arms.retain(|(_, tau)| !fast(*tau));
        viscous_s
    }

    /// `K*(f)` relative to `c_Tstat`.
    pub fn complex_stiffness(&self, frequency_hz: f64) -> Complex64 {
        let omega = TAU * frequency_hz;
        self.arms
            .iter()
            .fold(Complex64::new(self.equilibrium, 0.0), |acc, &(k, tau)| {
                acc + k * arm_response(omega, tau)
            })
    }
}

/// `iωτ/(1 + iωτ)`: one Maxwell arm of unit stiffness.
fn arm_response(omega: f64, tau: f64) -> Complex64 {
    let x = omega * tau;
    Complex64::new(x * x, x) / (1.0 + x * x)
}

/// `n` points from `lo` to `hi`, evenly spaced in log.
fn log_space(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n < 2 {
        return vec![lo];
    }
    let step = (hi / lo).ln() / (n - 1) as f64;
    (0..n).map(|i| lo * (step * i as f64).exp()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Poly, RubberStiffness};

    #[test]
    fn fast_arms_become_their_dashpot() {
        let full = MaxwellChain::fit(&stage(None), [62.5, 3600.0]);
        let mut reduced = full.clone();
        let above_hz = 2400.0;
        let viscous_s = reduced.take_fast_arms(above_hz);
        let removed: Vec<(f64, f64)> = full
            .arms
            .iter()
            .filter(|(_, tau)| 1.0 / (TAU * tau) > above_hz)
            .copied()
            .collect();
        assert!(!removed.is_empty() && reduced.arms.len() + removed.len() == full.arms.len());
        let removed_k: f64 = removed.iter().map(|(k, _)| k).sum();
        for f in [1.0, 36.0, 134.0, 400.0, 800.0] {
            let omega = TAU * f;
            let stand_in = reduced.complex_stiffness(f) + Complex64::new(0.0, omega * viscous_s);
            let exact = full.complex_stiffness(f);
            // The dashpot's errors, summed over the arms it replaces (see the doc).
            let (mut re, mut im) = (0.0, 0.0);
            for (k, tau) in &removed {
                let x = omega * tau;
                re += k * x * x / (1.0 + x * x);
                im += k * x * x * x / (1.0 + x * x);
            }
            assert!((exact.re - stand_in.re - re).abs() < 1e-12, "{f} Hz");
            assert!((stand_in.im - exact.im - im).abs() < 1e-12, "{f} Hz");
            // Below a third of the limit, within 10 % (stiffness) and 3.4 % (loss) of the
            // stiffness taken out.
            assert!(re <= 0.10 * removed_k && im <= 0.034 * removed_k, "{f} Hz");
        }
    }

    fn stage(frequency_poly: Option<Poly>) -> RubberStage {
        RubberStage {
            stiffness: RubberStiffness::Direct(1.0e4),
            psi: 1.0,
            temperature_c: 25.0,
            amplitude_poly: None,
            amplitude_saturation: None,
            amplitude_form: Default::default(),
            frequency_poly,
            frequency_power_law: None,
            frequency_zener: None,
            temperature_stiffness_poly: None,
            temperature_damping_poly: None,
            thermal: None,
            rating: None,
        }
    }

    /// A nearly causal target — constant stiffness with a small loss (ψ = 0.2, ξ = 0.032)
    /// over one decade. Kramers–Kronig asks ~(2/π)·ξ·ln 10 ≈ 5 % stiffening across it;
    /// with `k∞` free the fit centres that on the band: k∞ = 0.941, worst errors 2.5 % in
    /// storage and 0.36 % in loss (measured; with k∞ pinned at 1 they were 7.1 % and
    /// 10.4 %). The bounds leave a little room.
    #[test]
    fn fits_a_nearly_causal_law() {
        let mut s = stage(None);
        s.psi = 0.2;
        let chain = MaxwellChain::fit(&s, [20.0, 200.0]);
        assert_eq!(chain.static_stiffness, 1.0);
        assert!(
            (chain.equilibrium - 1.0).abs() < 0.07,
            "{}",
            chain.equilibrium
        );
        assert!(
            chain.stiffness_error < 0.03,
            "stiffness error {}",
            chain.stiffness_error
        );
        assert!(chain.loss_error < 0.01, "loss error {}", chain.loss_error);
        assert!(chain.arms.iter().all(|(k, t)| *k > 0.0 && *t > 0.0));
    }

    /// A causal power law is what a Maxwell chain can be: its storage `(f/f_ref)^n` and
    /// its loss factor `tan(nπ/2)` (Kramers–Kronig) come out of the fit together, which
    /// seed 000's eq. 9 with a constant ψ cannot (the test below). Band 2–600 Hz (an
    /// engine from 1000 to 4000 rpm to order 6); measured worst errors printed on failure.
    #[test]
    fn fits_a_causal_power_law_with_its_loss() {
        let mut s = stage(None);
        s.psi = 0.3; // ξ0 = 0.048, below tan(0.12·π/2) = 0.191: the law's loss rules
        s.frequency_power_law = Some(crate::model::PowerLaw {
            exponent: 0.12,
            reference_hz: 40.0,
        });
        let law = s.frequency_power_law.unwrap();
        let chain = MaxwellChain::fit(&s, [2.0, 600.0]);
        let eta = (0.12 * std::f64::consts::FRAC_PI_2).tan();
        // Held on the plateau below the band.
        let plateau = law.storage(2.0 / 1.5 / PLATEAU_BELOW_ARMS);
        assert!((chain.static_stiffness - plateau).abs() < 1e-15);
        // Measured: 2.0 % in storage, 17 % in loss (at the band's lower end, where the
        // arms below it are missing).
        assert!(chain.stiffness_error < 0.025, "{}", chain.stiffness_error);
        assert!(chain.loss_error < 0.2, "{}", chain.loss_error);
        // Over the inner band (two thirds of an octave in from the lower end, a third from
        // the upper) the loss factor is
        // tan(nπ/2) within 5 % and the storage the power law within 2.5 % (measured: 4.4 %
        // and 2.0 %).
        for f in log_space(3.2, 480.0, 20) {
            let k = chain.complex_stiffness(f);
            let storage = (f / 40.0).powf(0.12);
            assert!(
                (k.re / storage - 1.0).abs() < 0.025,
                "{f} Hz: {}",
                k.re / storage
            );
            assert!(
                (k.im / k.re / eta - 1.0).abs() < 0.05,
                "{f} Hz: {}",
                k.im / k.re / eta
            );
        }
    }

    /// Seed 000's α_f (×3 from 0 to 300 Hz) with ψ = 1 is not causal: a causal chain that
    /// stiffens that much loses far more than ψ. The fit reports its errors honestly and
    /// they are large; the values pin the documented compromise (band 10–400 Hz).
    #[test]
    fn reports_the_error_of_seed_000_law() {
        let poly = Poly {
            coeffs: [-0.000023, 0.01519, 1.0],
            range: Some([0.0, 300.0]),
        };
        let chain = MaxwellChain::fit(&stage(Some(poly)), [10.0, 400.0]);
        // Measured: k∞ = 1.36, worst errors 34 % (storage) and 21 % (loss).
        assert_eq!(chain.static_stiffness, 1.0);
        assert!(
            chain.stiffness_error > 0.1 && chain.stiffness_error < 0.45,
            "{}",
            chain.stiffness_error
        );
        assert!(
            chain.loss_error > 0.1 && chain.loss_error < 1.0,
            "{}",
            chain.loss_error
        );
        // Stiffness still rises monotonically across the band, as α_f does.
        let re: Vec<f64> = [10.0, 30.0, 100.0, 300.0]
            .iter()
            .map(|&f| chain.complex_stiffness(f).re)
            .collect();
        assert!(re.windows(2).all(|w| w[1] > w[0]), "{re:?}");
    }

    /// Two modes a decade and a half apart (15 and 226 Hz, the spec's three-DOF example),
    /// each with half the stage's energy, on a flat law with ψ = 0.9: Kramers–Kronig asks
    /// ≈ 25 % stiffening between them to keep the loss at both, so the fit shares the
    /// difference (measured: −1.2 % / +0.9 % at 15 Hz, +4.9 % / −5.5 % at 226 Hz in storage
    /// and loss factor). A mode alone is met closely (measured −0.015 % and +0.002 %).
    #[test]
    fn meets_the_law_at_its_modes() {
        let mut s = stage(None);
        s.psi = 0.9;
        let xi = 0.9 / TAU;
        let one = [ModeTarget {
            frequency_hz: 15.0,
            energy_share: 1.0,
        }];
        let chain = MaxwellChain::fit_at_modes(&s, [1.25, 750.0], &one);
        let k = chain.complex_stiffness(15.0);
        assert!((k.re - 1.0).abs() < 1e-3, "{k}");
        assert!((k.im / k.re / xi - 1.0).abs() < 1e-2, "{k}");
        let two = [
            one[0],
            ModeTarget {
                frequency_hz: 226.0,
                energy_share: 0.5,
            },
        ];
        let chain = MaxwellChain::fit_at_modes(&s, [1.25, 750.0], &two);
        for f in [15.0, 226.0] {
            let k = chain.complex_stiffness(f);
            assert!((k.re - 1.0).abs() < 0.06, "{f} Hz: {k}");
            assert!((k.im / k.re / xi - 1.0).abs() < 0.08, "{f} Hz: {k}");
        }
    }
}
