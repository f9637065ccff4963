//! An effect's *size* for the detectability analysis (issue 14, item 6): a number that is
//! 0 where the effect is absent and grows with it, in the effect's own unit, mapped to the
//! candidate's fitted parameter ([`super::candidates`]), and the typical size each is
//! compared at — the candidate's start value, which is `torsim synth`'s default.
//!
//! | effect | size | unit | typical |
//! |---|---|---|---|
//! | `coupling_amplitude_nonlinearity` | `a2` | 1/mm² | 0.0152 |
//! | `coupling_frequency_dependence` | `scale` | 1 | 0.1 |
//! | `coupling_thermal_drift` | `1/capacity_j_per_k` | K/J | 1/300 |
//! | `hysteretic_damping` | `|ln(reference_hz/f₀)|` | 1 (ln) | `|ln(50 Hz/f₀)|`, ≥ ln 2 |
//! | `unmodelled_mode` | `inertia_kg_m2` | kg·m² | ¼ of the lightest node |
//! | `crank_variable_inertia` | `mass_kg` | kg | 1100 kg/m³·bore³ |
//! | `gear_backlash` | `backlash_deg` | ° | 0.05 |
//! | `cylinder_imbalance` | `1 − pressure_scale` | 1 | 0.05 |
//! | `sensor_artifact` | `joint_fraction` | pitch | 0.02 |
//! | `sensor_artifact` (pitch error) | `error_deg` | ° | 0.05 |
//!
//! `f₀` of hysteretic damping is the reference frequency at which the hysteretic damper
//! changes the campaign's amplitudes least (found by [`super::power`]): there the user's
//! viscous damper already stands in for it.

use super::candidates::Candidate;
use crate::effects::Effect;

/// How a size maps to the candidate's parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SizeLaw {
    /// `value = null + sign·size`.
    Offset {
        /// The parameter where the effect is absent.
        null: f64,
        /// +1 or −1.
        sign: f64,
    },
    /// `value = 1/size` (a heat capacity: the smaller, the more drift).
    Inverse,
    /// `value = null·exp(sign·size)`.
    LogRatio {
        /// The parameter where the effect changes least.
        null: f64,
        /// +1 or −1.
        sign: f64,
    },
}

/// The size of one candidate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EffectSize {
    /// Size to parameter.
    pub law: SizeLaw,
    /// The size it is compared at.
    pub typical: f64,
    /// Largest size the candidate's bounds allow.
    pub max: f64,
    /// Unit of the size, for a person.
    pub unit: &'static str,
}

impl EffectSize {
    /// The candidate's parameter at `size`.
    pub fn value(&self, size: f64) -> f64 {
        match self.law {
            SizeLaw::Offset { null, sign } => null + sign * size,
            SizeLaw::Inverse => 1.0 / size.max(1e-300),
            SizeLaw::LogRatio { null, sign } => null * (sign * size).exp(),
        }
    }

    /// The parameter where the effect is absent, if one exists.
    pub fn null_value(&self) -> Option<f64> {
        match self.law {
            SizeLaw::Offset { null, .. } | SizeLaw::LogRatio { null, .. } => Some(null),
            SizeLaw::Inverse => None,
        }
    }
}

/// The size of candidate `c`; `hysteretic_null_hz`: `f₀` (module docs), for hysteretic
/// damping only.
pub fn effect_size(c: &Candidate, hysteretic_null_hz: f64) -> EffectSize {
    let p = &c.param;
    let offset = |null: f64, sign: f64, typical: f64, unit| EffectSize {
        law: SizeLaw::Offset { null, sign },
        typical,
        max: if sign > 0.0 { p.hi - null } else { null - p.lo },
        unit,
    };
    match c.effect {
        Effect::CouplingAmplitudeNonlinearity => offset(0.0, 1.0, p.start, "1/mm²"),
        Effect::CouplingFrequencyDependence => offset(0.0, 1.0, p.start, "1"),
        Effect::CouplingThermalDrift => EffectSize {
            law: SizeLaw::Inverse,
            typical: 1.0 / p.start,
            max: 1.0 / p.lo,
            unit: "K/J",
        },
        Effect::HystereticDamping => {
            let f0 = hysteretic_null_hz.clamp(p.lo, p.hi);
            let ratio = (p.start / f0).ln();
            let sign = if ratio < 0.0 { -1.0 } else { 1.0 };
            EffectSize {
                law: SizeLaw::LogRatio { null: f0, sign },
                typical: ratio.abs().max(std::f64::consts::LN_2),
                max: if sign > 0.0 {
                    (p.hi / f0).ln()
                } else {
                    (f0 / p.lo).ln()
                },
                unit: "ln",
            }
        }
        Effect::UnmodelledMode => offset(0.0, 1.0, p.start, "kg·m²"),
        Effect::CrankVariableInertia => offset(0.0, 1.0, p.start, "kg"),
        Effect::GearBacklash => offset(0.0, 1.0, p.start, "°"),
        Effect::CylinderImbalance => offset(1.0, -1.0, 1.0 - p.start, "1"),
        Effect::SensorArtifact if p.key == "error_deg" => offset(0.0, 1.0, p.start, "°"),
        Effect::SensorArtifact => offset(0.0, 1.0, p.start, "pitch"),
        Effect::None | Effect::ParameterError => offset(0.0, 1.0, 1.0, "1"),
    }
}

/// The size as the candidate's own parameter, for a person: `backlash_deg = 0.012`,
/// `capacity_j_per_k = 1.2e4`.
pub fn as_parameter(c: &Candidate, size: &EffectSize, s: f64) -> String {
    format!("{} = {:.4}", c.param.key, size.value(s))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::param::Param;

    fn candidate(effect: Effect, start: f64, lo: f64, hi: f64) -> Candidate {
        Candidate {
            effect,
            fixed: Vec::new(),
            param: Param::new("x", start, lo, hi, false),
            artifact_gains: None,
        }
    }

    #[test]
    fn sizes_map_to_parameters() {
        let c = candidate(Effect::CylinderImbalance, 0.95, 0.3, 1.5);
        let s = effect_size(&c, 0.0);
        assert!((s.typical - 0.05).abs() < 1e-12);
        assert!((s.value(0.1) - 0.9).abs() < 1e-12);
        assert!((s.max - 0.7).abs() < 1e-12);
        let t = effect_size(
            &candidate(Effect::CouplingThermalDrift, 300.0, 10.0, 1e5),
            0.0,
        );
        assert!((t.value(t.typical) - 300.0).abs() < 1e-9);
        let h = effect_size(
            &candidate(Effect::HystereticDamping, 50.0, 1.0, 2000.0),
            25.0,
        );
        assert!((h.value(h.typical) - 50.0).abs() < 1e-9);
        assert_eq!(h.null_value(), Some(25.0));
    }
}
