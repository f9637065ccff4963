//! The rubber coupling law of seed 000: static stiffness from elements (eq. 12), the
//! amplitude, frequency and temperature corrections (eq. 1–2, 8–11), the dynamic stiffness
//! (eq. 13) and the relative damping (eq. 14–15).

use super::types::{Poly, RubberStage, RubberStiffness};

/// Rubber temperatures the seed 000 law is taken to hold for, °C: `[−100, 300]`.
///
/// The temperature polynomials (eq. 10–11) are fitted over a few tens of degrees around
/// room temperature and held at their end values beyond; what they cannot describe is
/// rubber that is no longer rubber. Below about −100 °C every elastomer is glassy (natural
/// rubber's glass transition is near −70 °C, silicone's near −125 °C but it is not used
/// in these couplings), and above about 300 °C it decomposes. A temperature outside this
/// range (−300 °C, below absolute zero, was accepted before issue 13) is refused rather
/// than turned into a stiffness.
pub const TEMPERATURE_RANGE_C: [f64; 2] = [-100.0, 300.0];

/// `None` when `temperature_c` lies in [`TEMPERATURE_RANGE_C`], else why not.
pub fn temperature_problem(temperature_c: f64) -> Option<String> {
    let [lo, hi] = TEMPERATURE_RANGE_C;
    if temperature_c.is_finite() && (lo..=hi).contains(&temperature_c) {
        None
    } else {
        Some(format!(
            "{temperature_c} °C is outside the rubber law's range {lo} … {hi} °C (below \
             it rubber is glassy, above it, it decomposes; absolute zero is −273.15 °C)"
        ))
    }
}

/// Which correction factor a warning is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Factor {
    /// α_x (amplitude, seed 000 eq. 1).
    Amplitude,
    /// α_f (frequency, eq. 9).
    Frequency,
    /// α_Tc (temperature, stiffness, eq. 10).
    TemperatureStiffness,
    /// α_Tξ (temperature, damping, eq. 11).
    TemperatureDamping,
}

impl Factor {
    /// The model-file key of the polynomial.
    pub fn key(self) -> &'static str {
        match self {
            Factor::Amplitude => "amplitude_poly",
            Factor::Frequency => "frequency_poly",
            Factor::TemperatureStiffness => "temperature_stiffness_poly",
            Factor::TemperatureDamping => "temperature_damping_poly",
        }
    }
}

/// A polynomial evaluated outside its measured range (the end value was used).
#[derive(Debug, Clone, PartialEq)]
pub struct RangeWarning {
    /// Which polynomial.
    pub factor: Factor,
    /// The argument asked for (mm, Hz or °C).
    pub argument: f64,
    /// The measured range.
    pub range: [f64; 2],
}

impl Poly {
    /// Value at `x` (`a2·x² + a1·x + a0`), with `x` held inside `range` when one is given.
    pub fn eval(&self, x: f64) -> f64 {
        let x = self.clamp(x);
        let [a2, a1, a0] = self.coeffs;
        (a2 * x + a1) * x + a0
    }

    /// Derivative at `x`; zero outside the range (the factor is held there).
    pub fn derivative(&self, x: f64) -> f64 {
        if self.clamp(x) != x {
            return 0.0;
        }
        let [a2, a1, _] = self.coeffs;
        2.0 * a2 * x + a1
    }

    /// `x` held inside the measured range.
    pub fn clamp(&self, x: f64) -> f64 {
        match self.range {
            Some([lo, hi]) => x.clamp(lo, hi),
            None => x,
        }
    }

    /// The smallest value over `[lo, hi]` and where it is: `(x, value)`. The factor is
    /// held beyond the measured range, so the search is over the range's part of the
    /// interval; a quadratic's minimum is at an end or at its vertex.
    pub fn min_over(&self, [lo, hi]: [f64; 2]) -> (f64, f64) {
        let (lo, hi) = (self.clamp(lo), self.clamp(hi));
        let [a2, a1, _] = self.coeffs;
        let vertex = (a2 > 0.0)
            .then(|| -a1 / (2.0 * a2))
            .filter(|x| (lo..=hi).contains(x));
        [Some(lo), Some(hi), vertex]
            .into_iter()
            .flatten()
            .map(|x| (x, self.eval(x)))
            .fold((lo, f64::INFINITY), |best, (x, v)| {
                // A NaN value counts as the smallest: it must be refused too.
                if v < best.1 || v.is_nan() {
                    (x, v)
                } else {
                    best
                }
            })
    }

    /// True when `x` lies outside the measured range.
    pub fn is_outside(&self, x: f64) -> bool {
        self.range.is_some_and(|[lo, hi]| x < lo || x > hi)
    }
}

/// Everything the seed 000 law gives for one stage at one operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct RubberState {
    /// Static torsional stiffness at 25 °C, N·m/rad (eq. 12 or as given).
    pub static_stiffness_nm_per_rad: f64,
    /// α_x at the twist: secant ratio (eq. 1–2).
    pub alpha_x: f64,
    /// d(α_x·x)/dx at the twist: tangent ratio.
    pub alpha_x_tangent: f64,
    /// α_f at the frequency (eq. 9).
    pub alpha_f: f64,
    /// α_Tc at the temperature (eq. 10).
    pub alpha_tc: f64,
    /// α_Tξ at the temperature (eq. 11).
    pub alpha_txi: f64,
    /// Dynamic (secant) stiffness `c_Tstat·α_x·α_f·α_Tc`, N·m/rad (eq. 13).
    pub stiffness_nm_per_rad: f64,
    /// Tangent stiffness `c_Tstat·d(α_x x)/dx·α_f·α_Tc`, N·m/rad: what small vibration
    /// about the twist sees.
    pub tangent_stiffness_nm_per_rad: f64,
    /// Loss factor `ξ_T = ψ/2π · α_Tξ` (eq. 15); with a `frequency_power_law`, at least
    /// its `tan(nπ/2)` ([`super::frequency_law`]); with a `frequency_zener`, its loss at
    /// the frequency (at its reference when static, [`super::frequency_zener`]).
    pub loss_factor: f64,
    /// Relative damping at the temperature, `ψ_T = 2π·ξ_T`.
    pub psi: f64,
    /// Polynomials evaluated outside their measured range.
    pub warnings: Vec<RangeWarning>,
}

impl RubberState {
    /// The first correction factor that is not finite and > 0 at this operating point
    /// (α_x secant and tangent, α_f, α_Tc, α_Tξ), with its value: a stiffness or damping
    /// from it would be negative or zero, which no rubber has (issue 13).
    pub fn non_positive_factor(&self) -> Option<(Factor, f64)> {
        [
            (Factor::Amplitude, self.alpha_x),
            (Factor::Amplitude, self.alpha_x_tangent),
            (Factor::Frequency, self.alpha_f),
            (Factor::TemperatureStiffness, self.alpha_tc),
            (Factor::TemperatureDamping, self.alpha_txi),
        ]
        .into_iter()
        .find(|(_, v)| !(v.is_finite() && *v > 0.0))
    }
}

/// Evaluates an optional correction polynomial (a missing one is the factor 1),
/// recording a warning when the argument is outside its range.
fn factor(poly: Option<&Poly>, which: Factor, x: f64, warnings: &mut Vec<RangeWarning>) -> f64 {
    match poly {
        None => 1.0,
        Some(p) => {
            if let (true, Some(range)) = (p.is_outside(x), p.range) {
                warnings.push(RangeWarning {
                    factor: which,
                    argument: x,
                    range,
                });
            }
            p.eval(x)
        }
    }
}

impl RubberStage {
    /// The stiffness factor at vibration frequency `frequency_hz`: the causal power law's
    /// or Zener law's storage ratio when the stage has one, else α_f (seed 000 eq. 9),
    /// else 1.
    pub fn frequency_factor(&self, frequency_hz: f64) -> f64 {
        if let Some(law) = &self.frequency_zener {
            return law.storage(frequency_hz);
        }
        match (&self.frequency_power_law, &self.frequency_poly) {
            (Some(law), _) => law.storage(frequency_hz),
            (None, Some(p)) => p.eval(frequency_hz),
            (None, None) => 1.0,
        }
    }

    /// The catalogue's loss factor `ψ/2π·α_Tξ` (eq. 15) at the temperature factor
    /// `alpha_txi`, before any frequency law.
    pub fn catalogue_loss_factor(&self, alpha_txi: f64) -> f64 {
        self.psi / std::f64::consts::TAU * alpha_txi
    }

    /// The loss factor at vibration frequency `frequency_hz` (`None`: at the law's
    /// reference) when the catalogue's, with its temperature factor, is
    /// `catalogue_loss_factor`: at least a power law's `tan(nπ/2)`, with a Zener law's own
    /// loss added ([`super::frequency_law`], [`super::frequency_zener`]), else the
    /// catalogue's.
    pub fn loss_factor_at(&self, frequency_hz: Option<f64>, catalogue_loss_factor: f64) -> f64 {
        if let Some(law) = &self.frequency_zener {
            let f = frequency_hz.unwrap_or(law.reference_hz);
            return law.loss_factor(f, catalogue_loss_factor);
        }
        self.frequency_power_law.map_or(catalogue_loss_factor, |l| {
            l.loss_factor(catalogue_loss_factor)
        })
    }

    /// Static torsional stiffness at 25 °C, N·m/rad (given, or seed 000 eq. 12).
    pub fn static_stiffness_nm_per_rad(&self) -> f64 {
        match &self.stiffness {
            RubberStiffness::Direct(k) => *k,
            RubberStiffness::Elements(e) => e.torsional_stiffness_nm_per_rad(),
        }
    }

    /// Pitch radius of the elements, m, when the stage is built from elements.
    pub fn pitch_radius_m(&self) -> Option<f64> {
        match &self.stiffness {
            RubberStiffness::Elements(e) => Some(e.pitch_diameter_m / 2.0),
            RubberStiffness::Direct(_) => None,
        }
    }

    /// Whether the stage stiffens with its deformation: `amplitude_poly` or
    /// `amplitude_saturation` given.
    pub fn has_amplitude_law(&self) -> bool {
        self.amplitude_poly.is_some() || self.amplitude_saturation.is_some()
    }

    /// Radial deformation of an element in mm for a twist across the stage in rad:
    /// `x = |Δθ| · D/2 · 1000`. Zero when the stage has no elements.
    pub fn radial_deformation_mm(&self, twist_rad: f64) -> f64 {
        self.pitch_radius_m()
            .map_or(0.0, |r| twist_rad.abs() * r * 1000.0)
    }

    /// The law at vibration frequency `frequency_hz` (`None`: static, α_f = 1),
    /// rubber temperature `temperature_c` and twist `twist_rad` across the stage.
    pub fn state(
        &self,
        frequency_hz: Option<f64>,
        temperature_c: f64,
        twist_rad: f64,
    ) -> RubberState {
        let mut warnings = Vec::new();
        let x_mm = self.radial_deformation_mm(twist_rad);
        let law = (&self.amplitude_poly, &self.amplitude_saturation);
        let (alpha_x, alpha_x_tangent) = match (law, self.pitch_radius_m()) {
            ((Some(p), _), Some(_)) => {
                let secant = factor(Some(p), Factor::Amplitude, x_mm, &mut warnings);
                // d(α_x(x)·x)/dx = α_x(x) + x·α_x'(x); held α_x outside the range.
                (secant, secant + x_mm * p.derivative(x_mm))
            }
            ((None, Some(s)), Some(_)) => (s.secant(x_mm), s.tangent(x_mm)),
            _ => (1.0, 1.0),
        };
        let alpha_f = match (frequency_hz, &self.frequency_power_law) {
            (Some(f), _) if self.frequency_zener.is_some() => self.frequency_factor(f),
            (Some(f), Some(law)) => law.storage(f),
            (Some(f), None) => factor(
                self.frequency_poly.as_ref(),
                Factor::Frequency,
                f,
                &mut warnings,
            ),
            (None, _) => 1.0,
        };
        let alpha_tc = factor(
            self.temperature_stiffness_poly.as_ref(),
            Factor::TemperatureStiffness,
            temperature_c,
            &mut warnings,
        );
        let alpha_txi = factor(
            self.temperature_damping_poly.as_ref(),
            Factor::TemperatureDamping,
            temperature_c,
            &mut warnings,
        );
        let k0 = self.static_stiffness_nm_per_rad();
        let catalogue = self.catalogue_loss_factor(alpha_txi);
        let loss_factor = self.loss_factor_at(frequency_hz, catalogue);
        RubberState {
            static_stiffness_nm_per_rad: k0,
            alpha_x,
            alpha_x_tangent,
            alpha_f,
            alpha_tc,
            alpha_txi,
            stiffness_nm_per_rad: k0 * alpha_x * alpha_f * alpha_tc,
            tangent_stiffness_nm_per_rad: k0 * alpha_x_tangent * alpha_f * alpha_tc,
            loss_factor,
            psi: 2.0 * std::f64::consts::PI * loss_factor,
            warnings,
        }
    }

    /// Static twist in rad that a static torque `torque_nm` (in the stage's own shaft)
    /// puts on the stage at `temperature_c`: solves `c_Tstat·α_Tc·α_x(x)·Δθ = T` (seed 000
    /// eq. 2, 13 with α_f = 1), the sign of Δθ following the torque.
    ///
    /// `α_x(x)·x` must increase with x for a unique answer; where it stops increasing the
    /// twist found is the smallest that carries the torque, or the end of a bracket of
    /// 10 rad. Returns `None` when no twist up to 10 rad carries the torque.
    pub fn static_twist_rad(&self, torque_nm: f64, temperature_c: f64) -> Option<f64> {
        let k_lin = self.state(None, temperature_c, 0.0).stiffness_nm_per_rad;
        if torque_nm == 0.0 {
            return Some(0.0);
        }
        if !self.has_amplitude_law() || self.pitch_radius_m().is_none() {
            return Some(torque_nm / k_lin);
        }
        let target = torque_nm.abs();
        let carried =
            |twist: f64| self.state(None, temperature_c, twist).stiffness_nm_per_rad * twist;
        // Bracket: grow the upper end until it carries the torque.
        let mut lo = 0.0;
        let mut hi = (target / k_lin).min(10.0);
        while carried(hi) < target {
            lo = hi;
            hi *= 2.0;
            if hi > 10.0 {
                return None;
            }
        }
        // Bisection: 60 halvings reach f64 resolution of the bracket.
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if carried(mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(0.5 * (lo + hi) * torque_nm.signum())
    }
}
