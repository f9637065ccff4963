//! Accepting a verdict: the user's model with what the diagnosis found put into it.
//!
//! | verdict | the accepted model |
//! |---|---|
//! | `none` | the user's model unchanged: nothing is missing |
//! | `parameter_error` | the named plain parameter times the verdict's `factor` |
//! | an effect | every plain parameter times its fitted `scale.<name>` of the verdict's candidate row, then the effect at its fitted value, built by [`Candidate::apply`] (the code the fit used) |
//! | `sensor_artifact` | the user's model unchanged: the artifact is in the measurement (a tape joint, an encoder's pitch error), not in the driveline, so there is nothing to add to the model |
//!
//! Every verdict but `none` also puts in the mesh dampings the diagnosis added to gears the
//! model left undamped (`mesh_damping.<gear>`, [`super::mesh_damping`]).

use super::candidates::Candidate;
use super::report::{ParameterValue, Report, Verdict};
use super::searched::{Campaign, searched};
use super::surrogate::{plain_parameters, scaled};
use crate::effects::Effect;
use crate::model::Model;

/// The user's `model` with `report`'s verdict applied (see the module docs).
///
/// `model` must be the model the diagnosis ran on: the verdict names its parameters and
/// places, and an error says which one this model lacks (edited since?). For
/// `parameter_error` only the parameter the verdict names changes, by its `factor`
/// (dimensionless); the joint fit's smaller corrections of the others are not taken over.
/// For an effect the plain factors come from the candidate row whose `effect` is the
/// verdict's (the first row of a report made by [`super::diagnose`]); a factor the row
/// does not give stays 1.
pub fn accepted_model(model: &Model, report: &Report) -> Result<Model, String> {
    let verdict = &report.verdict;
    let effect = Effect::parse(&verdict.effect).map_err(|e| e.to_string())?;
    // Mesh dampings the diagnosis added ([`super::mesh_damping`]) were in the model every
    // fit started from, whatever it named.
    let damped = super::mesh_damping::apply(model, &verdict.parameters)?;
    match effect {
        Effect::None => Ok(model.clone()),
        Effect::SensorArtifact => Ok(damped),
        Effect::ParameterError => parameter_error(&damped, verdict),
        _ => with_effect(&damped, report, effect),
    }
}

/// The number under `key`, if it is one.
fn number(
    parameters: &std::collections::BTreeMap<String, ParameterValue>,
    key: &str,
) -> Option<f64> {
    match parameters.get(key) {
        Some(ParameterValue::Number(x)) => Some(*x),
        _ => None,
    }
}

/// `parameter_error`: the named parameter times `factor`.
fn parameter_error(model: &Model, verdict: &Verdict) -> Result<Model, String> {
    let Some(ParameterValue::Text(name)) = verdict.parameters.get("parameter") else {
        return Err("verdict `parameter_error` names no `parameter`".into());
    };
    let factor = number(&verdict.parameters, "factor")
        .filter(|f| f.is_finite() && *f > 0.0)
        .ok_or("verdict `parameter_error` has no positive `factor`")?;
    let plain = plain_parameters(model);
    let index = plain.iter().position(|p| p.name == *name).ok_or_else(|| {
        format!("the model has no parameter `{name}` (edited since the diagnosis?)")
    })?;
    let mut factors = vec![1.0; plain.len()];
    factors[index] = factor;
    scaled(model, &plain, &factors)
}

/// An effect: the candidate row's plain factors, then the effect at its fitted value.
fn with_effect(model: &Model, report: &Report, effect: Effect) -> Result<Model, String> {
    let verdict = &report.verdict;
    let row = report
        .candidates
        .iter()
        .find(|c| c.effect == verdict.effect)
        .ok_or_else(|| format!("the report has no candidate row for `{}`", verdict.effect))?;
    let plain = plain_parameters(model);
    for key in row.parameters.keys() {
        if let Some(name) = key.strip_prefix("scale.")
            && !plain.iter().any(|p| p.name == name)
        {
            return Err(format!(
                "the model has no parameter `{name}` (edited since the diagnosis?)"
            ));
        }
    }
    let factors: Vec<f64> = plain
        .iter()
        .map(|p| number(&row.parameters, &format!("scale.{}", p.name)).unwrap_or(1.0))
        .collect();
    if let Some(bad) = factors.iter().find(|f| !(f.is_finite() && **f > 0.0)) {
        return Err(format!("the candidate row has a scale factor of {bad}"));
    }
    let candidate = place(model, verdict, effect)?;
    let value = number(&verdict.parameters, candidate.param.key).ok_or_else(|| {
        format!(
            "verdict `{}` gives no value of `{}`",
            verdict.effect, candidate.param.key
        )
    })?;
    let base = scaled(model, &plain, &factors)?;
    candidate.apply(&base, value).map(|(m, _)| m)
}

/// Fixed keys a diagnosis reads off its recordings, whatever value the candidate starts
/// from: a backlash's mesh damping ([`super::backlash_damping`]), a local mode's
/// ([`super::branch_damping`]) and a warming stage's heat time constant
/// ([`super::drift::long_run_time_constant`]).
const RECHOSEN: [&str; 3] = [
    super::candidates_backlash::MESH_DAMPING_KEY,
    super::branch_damping::KEY,
    super::drift::TIME_CONSTANT_KEY,
];

/// The candidate of `model` the verdict names: the same effect at the same place (the
/// verdict's text parameters are the candidate's fixed keys, a [`RECHOSEN`] one at the
/// verdict's value).
fn place(model: &Model, verdict: &Verdict, effect: Effect) -> Result<Candidate, String> {
    let fixed: Vec<(&str, &str)> = verdict
        .parameters
        .iter()
        .filter_map(|(k, v)| match v {
            ParameterValue::Text(t) => Some((k.as_str(), t.as_str())),
            ParameterValue::Number(_) => None,
        })
        .collect();
    // Every place and form a diagnosis searches ([`super::searched`]).
    searched(model, &Campaign::any())
        .into_iter()
        .find(|c| {
            c.effect == effect
                && c.fixed.len() == fixed.len()
                && c.fixed.iter().all(|(k, v)| {
                    fixed
                        .iter()
                        .any(|(fk, fv)| fk == k && (fv == v || RECHOSEN.contains(k)))
                })
        })
        .map(|mut c| {
            // A damping the diagnosis chose by the recordings is the verdict's.
            for (k, v) in c.fixed.iter_mut() {
                if let Some((_, fv)) = fixed.iter().find(|(fk, _)| fk == k) {
                    *v = fv.to_string();
                }
            }
            c
        })
        .ok_or_else(|| {
            let at: Vec<String> = fixed.iter().map(|(k, v)| format!("{k} `{v}`")).collect();
            format!(
                "the model has no place for `{effect}` at {} (edited since the diagnosis?)",
                if at.is_empty() {
                    "its engine".to_string()
                } else {
                    at.join(", ")
                }
            )
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::report::{Candidate as Row, Fit, REPORT_FORMAT};
    use crate::modal::modes;
    use crate::model::{ConnectionKind, parse_model, presets};
    use crate::physics::{OperatingPoint, System};
    use std::collections::BTreeMap;

    fn bench() -> Model {
        let p = presets::preset("diagnosis-bench").expect("shipped");
        parse_model(p.text, "bench").expect("parses")
    }

    fn report(
        effect: &str,
        verdict: &[(&str, ParameterValue)],
        row: &[(&str, ParameterValue)],
    ) -> Report {
        let map = |pairs: &[(&str, ParameterValue)]| -> BTreeMap<String, ParameterValue> {
            pairs
                .iter()
                .map(|(k, v)| (k.to_string(), v.clone()))
                .collect()
        };
        Report {
            format: REPORT_FORMAT,
            verdict: Verdict {
                effect: effect.into(),
                confidence: 0.5,
                parameters: map(verdict),
                explanation: String::new(),
                equivalent_places: Vec::new(),
            },
            mismatches: vec![],
            candidates: vec![Row {
                effect: effect.into(),
                parameters: map(row),
                score: 1.0,
                residual_before: 2.0,
                residual_after: 1.0,
                residual_fitted: 1.0,
                parameter_count: 1,
                signature: String::new(),
                verified: true,
                rejected: None,
                rejected_steps: Vec::new(),
                set_aside: None,
            }],
            fit: Fit {
                metric: String::new(),
                before: 2.0,
                after: 1.0,
                validated_on: vec![],
                swapped_because: None,
            },
            mismatch_map: vec![],
            unexplained_resonances: vec![],
            overlays: vec![],
            recordings: vec![],
            not_fitted: vec![],
            noise_rpm: 0.01,
            elapsed_s: 1.0,
        }
    }

    fn frequencies_hz(model: &Model) -> Vec<f64> {
        let system = System::new(model, OperatingPoint::default()).expect("system");
        modes(&system)
            .expect("modes")
            .iter()
            .map(|m| m.frequency_hz)
            .collect()
    }

    fn text(s: &str) -> ParameterValue {
        ParameterValue::Text(s.into())
    }

    fn num(x: f64) -> ParameterValue {
        ParameterValue::Number(x)
    }

    /// The coupling 10 % softer: the accepted model is the library's scaled model, and
    /// its first mode (engine against brake across the coupling) falls by less than
    /// √0.9 (the shaft in series stays as stiff).
    #[test]
    fn a_parameter_error_scales_the_named_parameter() {
        let user = bench();
        let name = "connection.coupling.elements.radial_stiffness";
        let r = report(
            "parameter_error",
            &[("parameter", text(name)), ("factor", num(0.9))],
            &[],
        );
        let accepted = accepted_model(&user, &r).expect("accepted");
        let plain = plain_parameters(&user);
        let factors: Vec<f64> = plain
            .iter()
            .map(|p| if p.name == name { 0.9 } else { 1.0 })
            .collect();
        let library = scaled(&user, &plain, &factors).expect("scaled");
        assert_eq!(accepted, library);
        let (before, after) = (frequencies_hz(&user), frequencies_hz(&accepted));
        assert_eq!(after, frequencies_hz(&library));
        let ratio = after[0] / before[0];
        assert!(ratio < 1.0 && ratio > 0.9f64.sqrt(), "mode 1 × {ratio}");
        let r = report(
            "parameter_error",
            &[("parameter", text("inertia.nowhere")), ("factor", num(0.9))],
            &[],
        );
        let e = accepted_model(&user, &r).unwrap_err();
        assert!(e.contains("inertia.nowhere"), "{e}");
    }

    /// Backlash at the gearbox (hard contact, the undamped mesh damped at ζ = 0.1): the
    /// gear gets the fitted free play and that damping, and the row's plain factor (mesh
    /// stiffness × 1.1) comes with it; nothing else changes.
    #[test]
    fn an_effect_adds_the_fitted_physics_with_the_plain_factors() {
        let user = bench();
        let r = report(
            "gear_backlash",
            &[
                ("connection", text("gearbox")),
                ("mesh_damping_ratio", text("0.1")),
                ("backlash_deg", num(0.1)),
            ],
            &[
                ("connection", text("gearbox")),
                ("mesh_damping_ratio", text("0.1")),
                ("backlash_deg", num(0.1)),
                ("scale.connection.gearbox.mesh_stiffness", num(1.1)),
                ("scale.inertia.brake", num(1.0)),
            ],
        );
        let accepted = accepted_model(&user, &r).expect("accepted");
        let gear = |m: &Model| match &m.connections[0].kind {
            ConnectionKind::Gear(g) => g.clone(),
            other => panic!("{other:?}"),
        };
        assert_eq!(gear(&accepted).backlash_deg, 0.1);
        let k = gear(&user).mesh_stiffness_nm_per_rad.expect("mesh");
        assert_eq!(gear(&accepted).mesh_stiffness_nm_per_rad, Some(k * 1.1));
        let j = crate::effects::backlash::mesh_mode_inertia_kg_m2(&user, "gearbox").expect("J");
        let mut expected = user.clone();
        if let ConnectionKind::Gear(g) = &mut expected.connections[0].kind {
            g.backlash_deg = 0.1;
            g.mesh_stiffness_nm_per_rad = Some(k * 1.1);
            g.mesh_damping_nm_s_per_rad = 2.0 * 0.1 * (k * 1.1 * j).sqrt();
        }
        assert_eq!(accepted, expected);
        let mut nowhere = r.clone();
        nowhere
            .verdict
            .parameters
            .insert("connection".into(), text("shaft"));
        let e = accepted_model(&user, &nowhere).unwrap_err();
        assert!(e.contains("gear_backlash") && e.contains("`shaft`"), "{e}");
    }

    /// A local mode's branch at the brake with the damping the recordings chose (4 %):
    /// the accepted model is the branch effect applied with that damping.
    #[test]
    fn a_branch_verdict_keeps_its_chosen_damping() {
        let user = bench();
        let fixed = [
            ("node", text("brake")),
            ("form", text("branch")),
            ("inertia_ratio", text("0.15")),
            ("damping_ratio", text("0.04")),
            ("frequency_hz", num(80.0)),
        ];
        let r = report("unmodelled_mode", &fixed, &fixed);
        let accepted = accepted_model(&user, &r).expect("accepted");
        let spec = crate::effects::EffectSpec::new(Effect::UnmodelledMode)
            .with("node", "brake")
            .with("form", "branch")
            .with("inertia_ratio", "0.15")
            .with("damping_ratio", "0.04")
            .with("frequency_hz", 80.0);
        let expected = crate::effects::build_truth(&user, &spec, 0.0, 0).expect("applies");
        assert_eq!(accepted, expected.model);
        let spring = |m: &Model| match &m.connections.last().expect("spring").kind {
            ConnectionKind::Shaft(s) => s.damping_nm_s_per_rad,
            other => panic!("{other:?}"),
        };
        let mut at_two = r.clone();
        at_two
            .verdict
            .parameters
            .insert("damping_ratio".into(), text("0.02"));
        let two = accepted_model(&user, &at_two).expect("accepted");
        assert!((spring(&accepted) / spring(&two) - 2.0).abs() < 1e-12);
    }

    /// Thermal drift in its second form, the heat time constant read off the long runs
    /// (93 s here): the accepted model is the effect applied with that time constant, so
    /// its stage's conductance is the fitted capacity over it.
    #[test]
    fn a_thermal_verdict_keeps_its_time_constant() {
        let user = bench();
        let fixed = [
            ("connection", text("coupling")),
            ("softening", text("linear")),
            ("time_constant_s", text("9.3000e1")),
            ("capacity_j_per_k", num(40.0)),
        ];
        let r = report("coupling_thermal_drift", &fixed, &fixed);
        let accepted = accepted_model(&user, &r).expect("accepted");
        let spec = crate::effects::EffectSpec::new(Effect::CouplingThermalDrift)
            .with("connection", "coupling")
            .with("softening", "linear")
            .with("time_constant_s", "9.3000e1")
            .with("capacity_j_per_k", 40.0);
        let expected = crate::effects::build_truth(&user, &spec, 0.0, 0).expect("applies");
        assert_eq!(accepted, expected.model);
        let other = crate::effects::build_truth(&user, &spec.with("time_constant_s", 31.0), 0.0, 0)
            .expect("applies");
        assert_ne!(accepted, other.model);
    }

    /// `none` and a sensor artifact leave the driveline as it is.
    #[test]
    fn none_and_a_sensor_artifact_change_nothing() {
        let user = bench();
        let none = report("none", &[], &[]);
        assert_eq!(accepted_model(&user, &none).expect("none"), user);
        let sensor = report(
            "sensor_artifact",
            &[
                ("station", text("coupling_es")),
                ("joint_fraction", num(0.1)),
            ],
            &[("scale.inertia.brake", num(1.2))],
        );
        assert_eq!(accepted_model(&user, &sensor).expect("sensor"), user);
        let e = accepted_model(&user, &report("warp_drive", &[], &[])).unwrap_err();
        assert!(e.contains("warp_drive"), "{e}");
    }
}
