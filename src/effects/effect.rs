//! The effects of `spec/diagnosis.md` by their exact identifiers, and the `key=value`
//! parameters that size one.

use super::EffectError;
use std::collections::BTreeMap;

/// One effect the truth model adds to the user's model (`spec/diagnosis.md`, table).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Effect {
    /// Nothing is missing.
    None,
    /// No physics is missing; one parameter value is off.
    ParameterError,
    /// Rubber stiffness depends on deflection (seed 000 eq. 1).
    CouplingAmplitudeNonlinearity,
    /// Rubber stiffness depends on vibration frequency (seed 000 eq. 8–9).
    CouplingFrequencyDependence,
    /// Rubber warms by its own power loss and softens (seed 000 eq. 10–11).
    CouplingThermalDrift,
    /// Rubber damping is hysteretic, the user's is viscous (seed 001 eq. 2).
    HystereticDamping,
    /// A degree of freedom is missing (seed 001's local coupling mode).
    UnmodelledMode,
    /// Reciprocating masses make the engine inertia vary with crank angle.
    CrankVariableInertia,
    /// Free play in a gear stage.
    GearBacklash,
    /// One cylinder fires weaker or stronger than the others.
    CylinderImbalance,
    /// The measurement, not the driveline: a zebra-tape joint or encoder pitch error.
    SensorArtifact,
}

impl Effect {
    /// Every effect, in the order of the spec's table.
    pub const ALL: [Effect; 11] = [
        Effect::None,
        Effect::ParameterError,
        Effect::CouplingAmplitudeNonlinearity,
        Effect::CouplingFrequencyDependence,
        Effect::CouplingThermalDrift,
        Effect::HystereticDamping,
        Effect::UnmodelledMode,
        Effect::CrankVariableInertia,
        Effect::GearBacklash,
        Effect::CylinderImbalance,
        Effect::SensorArtifact,
    ];

    /// The identifier of `spec/diagnosis.md`, e.g. `"gear_backlash"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Effect::None => "none",
            Effect::ParameterError => "parameter_error",
            Effect::CouplingAmplitudeNonlinearity => "coupling_amplitude_nonlinearity",
            Effect::CouplingFrequencyDependence => "coupling_frequency_dependence",
            Effect::CouplingThermalDrift => "coupling_thermal_drift",
            Effect::HystereticDamping => "hysteretic_damping",
            Effect::UnmodelledMode => "unmodelled_mode",
            Effect::CrankVariableInertia => "crank_variable_inertia",
            Effect::GearBacklash => "gear_backlash",
            Effect::CylinderImbalance => "cylinder_imbalance",
            Effect::SensorArtifact => "sensor_artifact",
        }
    }

    /// Parses an identifier; the error lists the known ones.
    pub fn parse(name: &str) -> Result<Self, EffectError> {
        Self::ALL
            .into_iter()
            .find(|e| e.as_str() == name)
            .ok_or_else(|| {
                let known: Vec<&str> = Self::ALL.iter().map(|e| e.as_str()).collect();
                EffectError::Input(format!(
                    "unknown effect `{name}`; effects: {}",
                    known.join(", ")
                ))
            })
    }
}

impl std::fmt::Display for Effect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A resolved parameter value: a number or a name (a node, a connection, a kind).
#[derive(Debug, Clone, PartialEq)]
pub enum ParamValue {
    /// A number in the unit its key names.
    Number(f64),
    /// A name.
    Text(String),
}

impl std::fmt::Display for ParamValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParamValue::Number(x) => write!(f, "{x}"),
            ParamValue::Text(s) => f.write_str(s),
        }
    }
}

/// An effect and the `key=value` parameters given for it (as typed; each effect
/// resolves them with its defaults, and an unknown key is an error).
#[derive(Debug, Clone, PartialEq)]
pub struct EffectSpec {
    /// The effect.
    pub effect: Effect,
    /// Parameters as given, by key.
    pub params: BTreeMap<String, String>,
}

impl EffectSpec {
    /// An effect with no parameters given (all defaults).
    pub fn new(effect: Effect) -> Self {
        Self {
            effect,
            params: BTreeMap::new(),
        }
    }

    /// Adds `key=value` (builder style).
    pub fn with(mut self, key: &str, value: impl ToString) -> Self {
        self.params.insert(key.to_string(), value.to_string());
        self
    }

    /// Parses `key=value` strings (the CLI's `--param`); a key given twice is an error.
    pub fn parse(effect: &str, pairs: &[String]) -> Result<Self, EffectError> {
        let mut spec = Self::new(Effect::parse(effect)?);
        for pair in pairs {
            let (k, v) = pair.split_once('=').ok_or_else(|| {
                EffectError::Input(format!("--param `{pair}`: expected KEY=VALUE"))
            })?;
            let (k, v) = (k.trim(), v.trim());
            if k.is_empty() || v.is_empty() {
                return Err(EffectError::Input(format!(
                    "--param `{pair}`: expected KEY=VALUE"
                )));
            }
            if spec.params.insert(k.to_string(), v.to_string()).is_some() {
                return Err(EffectError::Input(format!("--param `{k}` given twice")));
            }
        }
        Ok(spec)
    }
}

/// Reads an effect's parameters against its known keys, recording the resolved values
/// (given or default) in order.
pub(crate) struct Params<'a> {
    effect: Effect,
    given: &'a BTreeMap<String, String>,
    /// Resolved `(key, value)` in the order read.
    pub resolved: Vec<(String, ParamValue)>,
}

impl<'a> Params<'a> {
    /// Checks that every given key is one of `known`.
    pub fn new(spec: &'a EffectSpec, known: &[&str]) -> Result<Self, EffectError> {
        if let Some(k) = spec.params.keys().find(|k| !known.contains(&k.as_str())) {
            let list = if known.is_empty() {
                "it takes none".to_string()
            } else {
                format!("known: {}", known.join(", "))
            };
            return Err(EffectError::Input(format!(
                "effect `{}` has no parameter `{k}` ({list})",
                spec.effect
            )));
        }
        Ok(Self {
            effect: spec.effect,
            given: &spec.params,
            resolved: Vec::new(),
        })
    }

    /// An error about parameter `key`.
    pub fn bad(&self, key: &str, message: impl std::fmt::Display) -> EffectError {
        EffectError::Input(format!(
            "effect `{}`, parameter `{key}`: {message}",
            self.effect
        ))
    }

    /// A number within `[lo, hi]`, or `default`.
    pub fn number(
        &mut self,
        key: &str,
        default: f64,
        lo: f64,
        hi: f64,
    ) -> Result<f64, EffectError> {
        let x = match self.given.get(key) {
            None => default,
            Some(text) => text
                .parse::<f64>()
                .map_err(|_| self.bad(key, format!("`{text}` is not a number")))?,
        };
        if !(x.is_finite() && (lo..=hi).contains(&x)) {
            return Err(self.bad(key, format!("{x} is outside {lo} … {hi}")));
        }
        self.resolved.push((key.into(), ParamValue::Number(x)));
        Ok(x)
    }

    /// A number within `[lo, hi]` when `key` is given (and then recorded), else `None`:
    /// a refinement whose absence leaves the effect as it was.
    pub fn optional_number(
        &mut self,
        key: &str,
        lo: f64,
        hi: f64,
    ) -> Result<Option<f64>, EffectError> {
        if self.given.contains_key(key) {
            self.number(key, lo, lo, hi).map(Some)
        } else {
            Ok(None)
        }
    }

    /// A name, or `default` (`None`: required unless the caller has one).
    pub fn text(&mut self, key: &str, default: Option<String>) -> Result<String, EffectError> {
        let value = match (self.given.get(key), default) {
            (Some(v), _) => v.clone(),
            (None, Some(d)) => d,
            (None, None) => return Err(self.bad(key, "is required")),
        };
        self.resolved
            .push((key.into(), ParamValue::Text(value.clone())));
        Ok(value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_errors_list_them() {
        for e in Effect::ALL {
            assert_eq!(Effect::parse(e.as_str()).unwrap(), e);
        }
        let msg = Effect::parse("backlash").unwrap_err().to_string();
        assert!(
            msg.contains("gear_backlash") && msg.contains("`backlash`"),
            "{msg}"
        );
    }

    #[test]
    fn params_parse_and_check() {
        let spec = EffectSpec::parse(
            "gear_backlash",
            &["backlash_deg=0.2".into(), "connection = gearbox".into()],
        )
        .unwrap();
        let mut p = Params::new(&spec, &["backlash_deg", "connection"]).unwrap();
        assert_eq!(p.number("backlash_deg", 0.1, 0.0, 5.0).unwrap(), 0.2);
        assert_eq!(p.text("connection", None).unwrap(), "gearbox");
        assert!(p.number("backlash_deg", 0.1, 0.0, 0.1).is_err());
        let e = Params::new(&spec, &["backlash_deg"])
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains("no parameter `connection`"), "{e}");
        assert!(EffectSpec::parse("none", &["x".into()]).is_err());
        assert!(EffectSpec::parse("none", &["x=1".into(), "x=2".into()]).is_err());
    }
}
