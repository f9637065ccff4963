//! A saturating amplitude law of a rubber stage (issue 14), the alternative to seed 000's
//! polynomial `amplitude_poly` (eq. 1): `α_x(x) = 1 + s·tanh((x/x_s)²)`, x the element's
//! radial deformation in mm as for the polynomial (`spec/model-format.md`, needs
//! `elements`).
//!
//! A progressive coupling stiffens as its elements are pressed into their housing, and
//! once they bear on it the stiffening stops growing: a quadratic law fitted to one load
//! overshoots the stiffening at another. This law is quadratic for small deformation
//! (`α_x ≈ 1 + s·(x/x_s)²`), and tends to `1 + s` beyond a few `x_s`. Its two
//! parameters are what a catalogue's progressive characteristic gives: how much stiffer
//! the stage ends (`s`) and the deformation it gets there over (`x_s`).
//!
//! Where seed 000's polynomial is the measured law of one coupling (valid over its
//! measured range, `amplitude_poly_range`), this is a form: no range is needed, and
//! every deformation has a finite, positive factor. Found on the independent bench
//! (`benchtruth`), whose progressive truths follow either a power of the twist or this
//! `tanh`: the diagnosis' quadratic and linear candidates missed five of the seven `tanh`
//! truths of development seeds 3000–3109.

/// `amplitude_saturation = { stiffening, deformation_mm }` of a rubber stage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AmplitudeSaturation {
    /// `s`: the secant stiffening the law tends to, relative (`α_x → 1 + s`), ≥ 0.
    pub stiffening: f64,
    /// `x_s`: the element deformation over which it saturates, mm (> 0); at `x_s` the
    /// stiffening is `s·tanh(1)`, 76 % of it.
    pub deformation_mm: f64,
}

impl AmplitudeSaturation {
    /// The secant factor `α_x(x)` at deformation `x_mm` (either sign).
    pub fn secant(&self, x_mm: f64) -> f64 {
        let u = (x_mm / self.deformation_mm).powi(2);
        1.0 + self.stiffening * u.tanh()
    }

    /// `d(α_x(x)·x)/dx`, the tangent factor at `x_mm ≥ 0`: `α_x + x·α_x'`, with
    /// `α_x' = s·sech²(u)·2x/x_s²`, `u = (x/x_s)²`.
    pub fn tangent(&self, x_mm: f64) -> f64 {
        let u = (x_mm / self.deformation_mm).powi(2);
        let sech2 = 1.0 / u.cosh().powi(2);
        self.secant(x_mm) + self.stiffening * sech2 * 2.0 * u
    }

    /// `None` when the law is usable, else the field at fault and why (for validation).
    pub fn problem(&self) -> Option<(&'static str, String)> {
        if !(self.stiffening.is_finite() && self.stiffening >= 0.0) {
            let why = format!("stiffening {} must be ≥ 0", self.stiffening);
            return Some(("stiffening", why));
        }
        if !(self.deformation_mm.is_finite() && self.deformation_mm > 0.0) {
            let why = format!("deformation_mm {} must be > 0", self.deformation_mm);
            return Some(("deformation_mm", why));
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LAW: AmplitudeSaturation = AmplitudeSaturation {
        stiffening: 0.4,
        deformation_mm: 0.5,
    };

    #[test]
    fn the_law_is_quadratic_when_small_and_saturates_when_large() {
        // tanh(u) = u − u³/3 + …: at x = x_s/100, u = 1e-4, the secant is 1 + s·u to 1e-12.
        let x = 0.005;
        assert!((LAW.secant(x) - (1.0 + 0.4 * 1e-4)).abs() < 1e-12);
        // At x_s: 1 + s·tanh(1).
        assert!((LAW.secant(0.5) - (1.0 + 0.4 * 1f64.tanh())).abs() < 1e-15);
        // Far beyond: 1 + s (tanh(400) is 1 in f64).
        assert_eq!(LAW.secant(10.0), 1.4);
        assert_eq!(LAW.secant(-0.5), LAW.secant(0.5));
    }

    #[test]
    fn the_tangent_is_the_derivative_of_the_carried_force() {
        // Central difference of α_x(x)·x, step 1e-6 mm: error O(h²·f''') ≈ 1e-11.
        let h = 1e-6;
        for x in [0.0, 0.1, 0.5, 0.8, 2.0] {
            let carried = |x: f64| LAW.secant(x) * x;
            let numeric = (carried(x + h) - carried(x - h)) / (2.0 * h);
            assert!((LAW.tangent(x) - numeric).abs() < 1e-8, "x = {x}");
        }
        // Saturated, the tangent is the secant: the stage is linear again.
        assert!((LAW.tangent(5.0) - 1.4).abs() < 1e-12);
    }

    #[test]
    fn a_law_without_a_positive_deformation_is_refused() {
        let bad = AmplitudeSaturation {
            stiffening: 0.4,
            deformation_mm: 0.0,
        };
        assert_eq!(bad.problem().expect("refused").0, "deformation_mm");
        let negative = AmplitudeSaturation {
            stiffening: -0.1,
            deformation_mm: 1.0,
        };
        assert!(
            negative
                .problem()
                .expect("refused")
                .1
                .contains("stiffening -0.1")
        );
        assert_eq!(LAW.problem(), None);
    }
}
