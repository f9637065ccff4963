//! A causal frequency law of a rubber stage (issue 14): the storage stiffness grows as a
//! power of frequency, `k'(f) = k·(f/f_ref)^n`, and the loss that Kramers–Kronig ties to
//! it comes with it. A complex stiffness `K*(ω) ∝ (iω)^n` (a spring-pot, the
//! fractional-derivative element of linear viscoelasticity) has the phase `nπ/2` at every
//! frequency, so its loss factor is `tan(nπ/2)`: an elastomer whose storage stiffness
//! rises by 10 % per decade (n ≈ 0.041) loses `η ≈ 0.065` however little its catalogue
//! says. Seed 000 eq. 9 (`frequency_poly`) changes only the storage stiffness and keeps
//! the catalogue's ψ, which no causal material does.
//!
//! The catalogue's ψ (DIN 740, measured at one frequency) is then the loss the stage
//! has at `f_ref`: the law's part, `tan(nπ/2)`, and a rate-independent remainder
//! (filler friction) `max(0, ψ/2π − tan(nπ/2))`, which is frequency-independent. Both
//! parts being constant in frequency, the loss factor is `max(ψ/2π, tan(nπ/2))` at
//! every frequency. Below [`PowerLaw::PLATEAU_HZ`] the stiffness is held at its value
//! there: the rubbery plateau, the stiffness the mean twist sees.

/// `frequency_power_law = { exponent, reference_hz }` of a rubber stage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLaw {
    /// Exponent `n` of the storage stiffness, `0 ≤ n < 1` (loss factor `tan(nπ/2)`).
    pub exponent: f64,
    /// Frequency where the storage stiffness is the stage's (static) stiffness, Hz (> 0).
    pub reference_hz: f64,
}

impl PowerLaw {
    /// Below this frequency, Hz, the storage stiffness is held (the rubbery plateau): 1 Hz,
    /// below every engine order of a running engine (order 0.5 at 120 rpm).
    pub const PLATEAU_HZ: f64 = 1.0;

    /// Storage stiffness relative to the stage's at `frequency_hz`: `(f/f_ref)^n`, with
    /// `f` held at [`Self::PLATEAU_HZ`] or above.
    pub fn storage(&self, frequency_hz: f64) -> f64 {
        (frequency_hz.max(Self::PLATEAU_HZ) / self.reference_hz).powf(self.exponent)
    }

    /// The law's own loss factor, `tan(nπ/2)`.
    pub fn own_loss_factor(&self) -> f64 {
        (self.exponent * std::f64::consts::FRAC_PI_2).tan()
    }

    /// The stage's loss factor when its catalogue gives `catalogue_loss_factor` (`ψ/2π`,
    /// with the temperature factor): `max(ψ/2π, tan(nπ/2))` (see the module doc).
    pub fn loss_factor(&self, catalogue_loss_factor: f64) -> f64 {
        catalogue_loss_factor.max(self.own_loss_factor())
    }

    /// `None` when the law is usable, else why not (for validation).
    pub fn problem(&self) -> Option<String> {
        if !(self.exponent.is_finite() && (0.0..1.0).contains(&self.exponent)) {
            return Some(format!(
                "exponent {} must be in [0, 1) (a loss factor tan(nπ/2) from 0 to infinity)",
                self.exponent
            ));
        }
        if !(self.reference_hz.is_finite() && self.reference_hz > 0.0) {
            return Some(format!("reference_hz {} must be > 0", self.reference_hz));
        }
        None
    }
}

/// The power law of the first rubber stage of `model` that has one (for tests).
#[cfg(test)]
pub(crate) fn first_power_law(model: &super::Model) -> Option<PowerLaw> {
    model.connections.iter().find_map(|c| match &c.kind {
        super::ConnectionKind::Rubber(r) => r.frequency_power_law,
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_complex::Complex64;
    use std::f64::consts::TAU;

    /// The storage and loss are those of the spring-pot `k·(iω/ω_ref)^n / cos(nπ/2)`
    /// (normalised so that its real part is k at f_ref), to rounding.
    #[test]
    fn is_the_spring_pot() {
        let law = PowerLaw {
            exponent: 0.12,
            reference_hz: 40.0,
        };
        let norm = (law.exponent * std::f64::consts::FRAC_PI_2).cos();
        for f in [5.0, 40.0, 300.0] {
            let i_omega = Complex64::new(0.0, TAU * f / (TAU * law.reference_hz));
            let pot = i_omega.powf(law.exponent) / norm;
            assert!((pot.re - law.storage(f)).abs() < 1e-12, "{f} Hz");
            assert!(
                (pot.im / pot.re - law.own_loss_factor()).abs() < 1e-12,
                "{f} Hz"
            );
        }
        assert_eq!(law.storage(40.0), 1.0);
        // The catalogue's loss where it is larger, the law's where that is.
        assert_eq!(law.loss_factor(0.5), 0.5);
        assert!((law.loss_factor(0.01) - 0.190_76).abs() < 1e-5);
        // Held on the plateau.
        assert_eq!(law.storage(0.0), law.storage(PowerLaw::PLATEAU_HZ));
    }

    #[test]
    fn refuses_what_is_no_law() {
        let ok = PowerLaw {
            exponent: 0.1,
            reference_hz: 30.0,
        };
        assert!(ok.problem().is_none());
        for (n, f) in [(-0.1, 30.0), (1.0, 30.0), (f64::NAN, 30.0), (0.1, 0.0)] {
            let law = PowerLaw {
                exponent: n,
                reference_hz: f,
            };
            assert!(law.problem().is_some(), "{n} {f}");
        }
    }

    /// The model file's key reads, writes back the same, reaches the linear model's
    /// element, and is refused beside `frequency_poly` or out of range.
    #[test]
    fn reads_writes_and_refuses() {
        use crate::model::{parse_model, presets, to_toml_string};
        use crate::physics::{OperatingPoint, System};
        let base = presets::preset("diagnosis-bench").expect("shipped").text;
        let at = "psi = 1.0\n";
        assert!(base.contains(at));
        let with = |extra: &str| base.replacen(at, &format!("{at}{extra}\n"), 1);
        let text = with("frequency_power_law = { exponent = 0.12, reference_hz = 30.0 }");
        let model = parse_model(&text, "m.toml").unwrap();
        let law = first_power_law(&model).unwrap();
        assert_eq!(
            law,
            PowerLaw {
                exponent: 0.12,
                reference_hz: 30.0
            }
        );
        let again = parse_model(&to_toml_string(&model), "again.toml").unwrap();
        assert_eq!(again, model);
        // The nominal linear model sees the storage and the law's loss (ψ = 1 is ξ = 0.159,
        // below tan(0.12·π/2) = 0.191).
        let point = OperatingPoint {
            load: 0.0,
            temperature_c: None,
        };
        let system = System::nominal(&model, point).unwrap();
        let e = system
            .elements
            .iter()
            .find(|e| e.is_frequency_dependent())
            .unwrap();
        let (k30, eta) = e.stiffness_at(30.0);
        let (k300, _) = e.stiffness_at(300.0);
        assert!((k300 / k30 - 10f64.powf(0.12)).abs() < 1e-12);
        assert!((eta - law.own_loss_factor()).abs() < 1e-12);
        for bad in [
            "frequency_power_law = { exponent = 1.2, reference_hz = 30.0 }",
            "frequency_power_law = { exponent = 0.1 }",
            "frequency_power_law = { exponent = 0.1, reference_hz = 30.0 }\nfrequency_poly = [0, 0.01, 1]",
        ] {
            assert!(parse_model(&with(bad), "bad.toml").is_err(), "{bad}");
        }
    }
}
