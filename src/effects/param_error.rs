//! Plain parameter errors: the truth's inertias and stiffnesses differ from the user's by
//! factors, seeded and uniform within ±P %, or one named parameter by a given factor.
//!
//! Parameters are named by their place in the model file: `inertia.<node>` (kg·m²),
//! `connection.<name>.stiffness` (a shaft's, or a rubber stage's given directly, N·m/rad),
//! `connection.<name>.elements.radial_stiffness` (a rubber stage from elements, N/m: the
//! stage's torsional stiffness scales with it, seed 000 eq. 12) and
//! `connection.<name>.mesh_stiffness` (a gear's, N·m/rad). Damping, ψ and rigid gears are
//! left alone.

use super::EffectError;
use super::rng::Rng;
use crate::model::{ConnectionKind, Model, RubberStiffness};

/// One parameter the truth has off the user's value.
#[derive(Debug, Clone, PartialEq)]
pub struct ParameterError {
    /// Its place in the model file, e.g. `inertia.engine`.
    pub parameter: String,
    /// The user's value (SI unit of the key).
    pub user_value: f64,
    /// The truth's value.
    pub truth_value: f64,
}

impl ParameterError {
    /// `truth / user`.
    pub fn factor(&self) -> f64 {
        self.truth_value / self.user_value
    }
}

/// A mutable reference to every inertia and stiffness of `model`, with its name.
fn parameters(model: &mut Model) -> Vec<(String, &mut f64)> {
    let mut out: Vec<(String, &mut f64)> = model
        .inertias
        .iter_mut()
        .map(|n| (format!("inertia.{}", n.name), &mut n.inertia_kg_m2))
        .collect();
    for c in &mut model.connections {
        let base = format!("connection.{}", c.name);
        match &mut c.kind {
            ConnectionKind::Shaft(s) => {
                out.push((format!("{base}.stiffness"), &mut s.stiffness_nm_per_rad));
            }
            ConnectionKind::Rubber(r) => match &mut r.stiffness {
                RubberStiffness::Direct(k) => out.push((format!("{base}.stiffness"), k)),
                RubberStiffness::Elements(e) => out.push((
                    format!("{base}.elements.radial_stiffness"),
                    &mut e.radial_stiffness_n_per_m,
                )),
            },
            ConnectionKind::Gear(g) => {
                if let Some(k) = &mut g.mesh_stiffness_nm_per_rad {
                    out.push((format!("{base}.mesh_stiffness"), k));
                }
            }
        }
    }
    out
}

/// The names of every parameter [`apply_random_errors`] may change, in model order.
pub fn parameter_names(model: &Model) -> Vec<String> {
    let mut copy = model.clone();
    parameters(&mut copy).into_iter().map(|(n, _)| n).collect()
}

/// Multiplies every inertia and stiffness of `model` by its own factor, uniform in
/// `[1 − pct/100, 1 + pct/100]`, drawn from stream `"parameter_errors"` of `seed` in model
/// order. `pct` is within 0 … 50; 0 changes nothing and returns no errors.
pub fn apply_random_errors(
    model: &mut Model,
    pct: f64,
    seed: u64,
) -> Result<Vec<ParameterError>, EffectError> {
    if !(pct.is_finite() && (0.0..=50.0).contains(&pct)) {
        return Err(EffectError::Input(format!(
            "--param-error-pct {pct}: must be within 0 … 50"
        )));
    }
    if pct == 0.0 {
        return Ok(Vec::new());
    }
    let mut rng = Rng::stream(seed, "parameter_errors", 0);
    let p = pct / 100.0;
    Ok(parameters(model)
        .into_iter()
        .map(|(parameter, value)| {
            let user_value = *value;
            *value *= rng.uniform_in(1.0 - p, 1.0 + p);
            ParameterError {
                parameter,
                user_value,
                truth_value: *value,
            }
        })
        .collect())
}

/// Multiplies the parameter of `target` by `factor`: the inertia of a node of that name,
/// else the stiffness of a connection of that name (shaft, rubber stage, or a gear with
/// mesh stiffness).
pub fn scale_parameter(
    model: &mut Model,
    target: &str,
    factor: f64,
) -> Result<ParameterError, EffectError> {
    let node = format!("inertia.{target}");
    let conn = format!("connection.{target}.");
    let known = parameter_names(model);
    let found = parameters(model)
        .into_iter()
        .find(|(name, _)| *name == node || name.starts_with(&conn));
    let Some((parameter, value)) = found else {
        return Err(EffectError::Input(format!(
            "effect `parameter_error`: `{target}` names no node and no connection with a \
             stiffness; parameters: {}",
            known.join(", ")
        )));
    };
    let user_value = *value;
    *value *= factor;
    Ok(ParameterError {
        parameter,
        user_value,
        truth_value: *value,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{parse_model, presets};

    fn rig() -> Model {
        let p = presets::preset("test-rig-70sh").expect("shipped");
        parse_model(p.text, "rig").expect("parses")
    }

    #[test]
    fn random_errors_stay_within_bounds_and_repeat() {
        let user = rig();
        let names = parameter_names(&user);
        assert_eq!(
            names,
            [
                "inertia.engine",
                "inertia.gearbox_out",
                "inertia.coupling_es",
                "inertia.middle_flange",
                "connection.a.stiffness",
                "connection.b.stiffness",
                "connection.c.stiffness"
            ]
        );
        let mut a = user.clone();
        let errors = apply_random_errors(&mut a, 10.0, 5).unwrap();
        assert_eq!(errors.len(), names.len());
        for e in &errors {
            assert!((e.factor() - 1.0).abs() <= 0.1 + 1e-12, "{e:?}");
            assert!(e.factor() != 1.0);
        }
        let mut b = user.clone();
        assert_eq!(apply_random_errors(&mut b, 10.0, 5).unwrap(), errors);
        assert_eq!(a, b);
        let mut c = user.clone();
        assert!(apply_random_errors(&mut c, 0.0, 5).unwrap().is_empty());
        assert_eq!(c, user);
        assert!(apply_random_errors(&mut c, -1.0, 5).is_err());
    }

    #[test]
    fn one_named_parameter() {
        let mut m = rig();
        let e = scale_parameter(&mut m, "b", 0.9).unwrap();
        assert_eq!(e.parameter, "connection.b.stiffness");
        assert!((e.factor() - 0.9).abs() < 1e-15);
        let e = scale_parameter(&mut m, "engine", 1.05).unwrap();
        assert_eq!(e.parameter, "inertia.engine");
        let msg = scale_parameter(&mut m, "gearbox", 1.1)
            .unwrap_err()
            .to_string();
        assert!(msg.contains("`gearbox`"), "{msg}");
    }
}
