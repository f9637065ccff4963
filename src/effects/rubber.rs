//! Effects on a rubber coupling stage (seed 000): amplitude nonlinearity (eq. 1),
//! frequency dependence (eq. 9) and self-heating with temperature softening (eq. 10–11);
//! each takes `connection=<name>`, by default the first rubber stage. Hysteretic damping in
//! place of the user's viscous equivalent is in [`super::hysteretic`].

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::truth::{Applied, mode_frequencies_hz};
use crate::model::{
    AmplitudeForm, ConnectionKind, Model, Poly, RubberElements, RubberStage, RubberStiffness,
    Thermal,
};

/// Seed 000 eq. 1: α_x(x) = 0.0152 x² + 0.0033 x + 1, x in mm.
pub const SEED_AMPLITUDE_POLY: [f64; 3] = [0.0152, 0.0033, 1.0];
/// The pitch diameter, m, on which a stage given by its stiffness is written as elements
/// for the amplitude law: 0.2.
pub const DEFAULT_PITCH_DIAMETER_M: f64 = 0.2;
/// The largest `a2` of eq. 1 the amplitude effect takes, per mm²: 1e4, the stiffness
/// doubled at 0.01 mm of element deformation. A bound per mm² follows the element's size:
/// the seed's 0.0152 /mm² belongs to elements deforming by millimetres; a stiff coupling
/// whose elements deform by a tenth of that stiffens as much with a hundred times the
/// coefficient (issue 14), so the bound is set by the smallest deformation that means
/// anything, not by the seed's elements.
pub const A2_MAX_PER_MM2: f64 = 1.0e4;
/// The largest `a1` of the amplitude law, /mm: 100, for the same reason as
/// [`A2_MAX_PER_MM2`] (a progressive law linear in the deformation, `a2` = 0, stiffens a
/// stage whose elements deform by 0.01 mm by 100 % at that bound); as much softening
/// below zero.
pub const A1_MAX_PER_MM: f64 = 100.0;
/// Seed 000 eq. 9: α_f(f) = −0.000023 f² + 0.01519 f + 1, f in Hz (measured 50–300 Hz).
pub const SEED_FREQUENCY_POLY: [f64; 3] = [-0.000023, 0.01519, 1.0];
/// Seed 000 eq. 10: α_Tc(T), T in °C (measured 25–55 °C).
pub const SEED_TEMPERATURE_STIFFNESS_POLY: [f64; 3] = [0.000187, -0.02565, 1.530];
/// Seed 000 eq. 11: α_Tξ(T), T in °C (measured 25–55 °C).
pub const SEED_TEMPERATURE_DAMPING_POLY: [f64; 3] = [0.000063, -0.01275, 1.281];

/// Index of the rubber stage `connection` names (default: the first rubber stage).
pub(super) fn stage_index(model: &Model, p: &mut Params) -> Result<usize, EffectError> {
    let first = model
        .connections
        .iter()
        .find(|c| matches!(c.kind, ConnectionKind::Rubber(_)))
        .map(|c| c.name.clone());
    let name = p.text("connection", first)?;
    model
        .connections
        .iter()
        .position(|c| c.name == name && matches!(c.kind, ConnectionKind::Rubber(_)))
        .ok_or_else(|| {
            p.bad(
                "connection",
                format!("`{name}` is no rubber stage of the model"),
            )
        })
}

/// The rubber stage of connection `j` (found by [`stage_index`]).
pub(super) fn stage_mut(model: &mut Model, j: usize) -> Result<&mut RubberStage, EffectError> {
    let name = model.connections[j].name.clone();
    match &mut model.connections[j].kind {
        ConnectionKind::Rubber(r) => Ok(r),
        _ => Err(EffectError::Input(format!(
            "connection `{name}` is no rubber stage"
        ))),
    }
}

/// `coupling_amplitude_nonlinearity`: α_x(x) = a2·x² + a1·x + 1 (default seed 000 eq. 1),
/// on the whole stage (`form = whole`, default: the damping scales with it, eq. 13–15) or
/// on its elastic spring only (`form = elastic`, [`AmplitudeForm::Elastic`]).
/// A stage given by `stiffness` is first written as 8 elements, 4 per side, on pitch
/// diameter `pitch_diameter_m` (default 0.2 m) with the same static stiffness. `a2` is
/// taken up to [`A2_MAX_PER_MM2`], `a1` within ±[`A1_MAX_PER_MM`].
pub(crate) fn amplitude(model: &mut Model, spec: &EffectSpec) -> Result<Applied, EffectError> {
    let mut p = Params::new(
        spec,
        &["connection", "a2", "a1", "pitch_diameter_m", "form"],
    )?;
    let j = stage_index(model, &mut p)?;
    // Read only when given, so the seed form resolves to the same keys as before.
    let form = match spec.params.contains_key("form") {
        false => AmplitudeForm::Whole,
        true => {
            let key = p.text("form", None)?;
            AmplitudeForm::from_key(&key)
                .ok_or_else(|| p.bad("form", format!("`{key}`: expected whole or elastic")))?
        }
    };
    let a2 = p.number("a2", SEED_AMPLITUDE_POLY[0], 0.0, A2_MAX_PER_MM2)?;
    let a1 = p.number("a1", SEED_AMPLITUDE_POLY[1], -A1_MAX_PER_MM, A1_MAX_PER_MM)?;
    let direct = match &stage_mut(model, j)?.stiffness {
        RubberStiffness::Direct(k) => Some(*k),
        RubberStiffness::Elements(_) => None,
    };
    if direct.is_none() && spec.params.contains_key("pitch_diameter_m") {
        return Err(p.bad("pitch_diameter_m", "the stage already has elements"));
    }
    if let Some(k) = direct {
        let d = p.number("pitch_diameter_m", DEFAULT_PITCH_DIAMETER_M, 0.02, 5.0)?;
        let mut e = RubberElements {
            count: 8,
            per_side: 4,
            pitch_diameter_m: d,
            radial_stiffness_n_per_m: 1.0,
        };
        e.radial_stiffness_n_per_m = k / e.torsional_stiffness_nm_per_rad();
        stage_mut(model, j)?.stiffness = RubberStiffness::Elements(e);
    }
    let stage = stage_mut(model, j)?;
    if stage.amplitude_poly.is_some() {
        return Err(p.bad("connection", "the stage already has amplitude_poly"));
    }
    stage.amplitude_poly = Some(Poly {
        coeffs: [a2, a1, 1.0],
        range: None,
    });
    stage.amplitude_form = form;
    let name = &model.connections[j].name;
    let what = match form {
        AmplitudeForm::Whole => "stiffness and damping",
        AmplitudeForm::Elastic => "elastic stiffness only, damping the user's",
    };
    let summary = format!(
        "rubber stage `{name}` stiffens with the element deformation x (mm): \
         α_x = {a2}·x² + {a1}·x + 1 (seed 000 eq. 1 form) on its {what}"
    );
    Ok((p.resolved, summary))
}

/// `coupling_frequency_dependence`: the truth's α_f is seed 000 eq. 9 scaled by `scale`
/// (default 0.1) about `reference_hz`, where it equals the user's stiffness (default: the
/// user model's first mode, the frequency a user would have tuned the stiffness to):
/// `α_f(f) = 1 + scale·(g(f) − g(f_ref))`, g eq. 9, held beyond its measured 300 Hz.
/// `form` is `poly` (this, the default) or `power_law` ([`super::rubber_power`]).
pub(crate) fn frequency(
    model: &mut Model,
    user: &Model,
    spec: &EffectSpec,
) -> Result<Applied, EffectError> {
    if spec.params.contains_key("form") {
        let form = spec.params.get("form").map(String::as_str);
        if form == Some(super::rubber_power::FORM) {
            return super::rubber_power::power_law(model, user, spec);
        }
        if form != Some("poly") {
            return Err(EffectError::Input(format!(
                "effect `coupling_frequency_dependence`, parameter `form`: `{}`: expected \
                 poly or power_law",
                form.unwrap_or_default()
            )));
        }
    }
    let mut p = Params::new(spec, &["connection", "form", "scale", "reference_hz"])?;
    if spec.params.contains_key("form") {
        p.text("form", None)?;
    }
    let j = stage_index(model, &mut p)?;
    let scale = p.number("scale", 0.1, 0.0, 1.0)?;
    let first_mode = mode_frequencies_hz(user)?.first().copied().unwrap_or(50.0);
    let f_ref = p.number("reference_hz", first_mode.min(300.0), 0.0, 300.0)?;
    let [b2, b1, b0] = SEED_FREQUENCY_POLY;
    let g_ref = (b2 * f_ref + b1) * f_ref + b0;
    let coeffs = [scale * b2, scale * b1, 1.0 + scale * (b0 - g_ref)];
    if coeffs[2] <= 0.0 {
        return Err(p.bad("scale", "makes the static stiffness ≤ 0"));
    }
    let stage = stage_mut(model, j)?;
    if stage.frequency_poly.is_some() {
        return Err(p.bad("connection", "the stage already has frequency_poly"));
    }
    stage.frequency_poly = Some(Poly {
        coeffs,
        range: Some([0.0, 300.0]),
    });
    let at = |f: f64| (coeffs[0] * f + coeffs[1]) * f + coeffs[2];
    let summary = format!(
        "rubber stage `{}` stiffens with frequency: α_f = {:.4} at 0 Hz, 1 at {f_ref:.1} Hz, \
         {:.4} at 100 Hz, {:.4} from 300 Hz (seed 000 eq. 9 × {scale})",
        model.connections[j].name,
        at(0.0),
        at(100.0),
        at(300.0)
    );
    Ok((p.resolved, summary))
}

/// A seed 000 temperature law moved so that `t0_c` sits where 40 °C (the middle of the
/// measured 25–55 °C) sits in the seed's, normalised to 1 there, valid ±15 K around it.
fn shifted_law(seed: [f64; 3], t0_c: f64) -> Poly {
    let [a2, a1, a0] = seed;
    let d = t0_c - 40.0;
    let at40 = (a2 * 40.0 + a1) * 40.0 + a0;
    Poly {
        coeffs: [
            a2 / at40,
            (a1 - 2.0 * a2 * d) / at40,
            (a2 * d * d - a1 * d + a0) / at40,
        ],
        range: Some([t0_c - 15.0, t0_c + 15.0]),
    }
}

/// `coupling_thermal_drift`: the stage warms by its own loss into a lumped heat capacity
/// (`capacity_j_per_k`, default 300 J/K: about 0.17 kg of loaded rubber; at least
/// 0.01 J/K, for a small loss that warms visibly) and cools to `ambient_c` (default its
/// start temperature) through `conductance_w_per_k` (default 1.5 W/K; time constant
/// 200 s), or with the conductance that gives `time_constant_s` (capacity over
/// conductance, s; the diagnosis reads it off a long run's drift, [`crate::diagnose`]'s
/// thermal candidate). A stage without temperature laws gets seed
/// 000 eq. 10–11 by [`shifted_law`]: −1.33 %/K in stiffness and −0.88 %/K in damping at
/// the start.
pub(crate) fn thermal(model: &mut Model, spec: &EffectSpec) -> Result<Applied, EffectError> {
    let mut p = Params::new(
        spec,
        &[
            "connection",
            "capacity_j_per_k",
            "conductance_w_per_k",
            "time_constant_s",
            "ambient_c",
        ],
    )?;
    let j = stage_index(model, &mut p)?;
    let capacity = p.number("capacity_j_per_k", 300.0, 0.01, 1.0e7)?;
    let conductance = match p.optional_number("time_constant_s", 1e-2, 1e7)? {
        Some(tau_s) => {
            if spec.params.contains_key("conductance_w_per_k") {
                return Err(p.bad(
                    "time_constant_s",
                    "give the conductance or the time constant, not both",
                ));
            }
            capacity / tau_s
        }
        None => p.number("conductance_w_per_k", 1.5, 1.0e-3, 1.0e5)?,
    };
    let t0 = stage_mut(model, j)?.temperature_c;
    let ambient = p.number("ambient_c", t0, -40.0, 200.0)?;
    let stage = stage_mut(model, j)?;
    if stage.thermal.is_some() {
        return Err(p.bad("connection", "the stage already has thermal"));
    }
    stage.thermal = Some(Thermal {
        capacity_j_per_k: capacity,
        conductance_w_per_k: conductance,
        ambient_c: ambient,
    });
    let mut added = Vec::new();
    if stage.temperature_stiffness_poly.is_none() {
        stage.temperature_stiffness_poly = Some(shifted_law(SEED_TEMPERATURE_STIFFNESS_POLY, t0));
        added.push("α_Tc");
    }
    if stage.temperature_damping_poly.is_none() {
        stage.temperature_damping_poly = Some(shifted_law(SEED_TEMPERATURE_DAMPING_POLY, t0));
        added.push("α_Tξ");
    }
    let laws = if added.is_empty() {
        "its own temperature laws".to_string()
    } else {
        format!(
            "{} of seed 000 eq. 10–11 centred on {t0} °C",
            added.join(" and ")
        )
    };
    let summary = format!(
        "rubber stage `{}` warms by its power loss (heat capacity {capacity} J/K, \
         {conductance} W/K to {ambient} °C, time constant {:.0} s) from {t0} °C and softens \
         by {laws}",
        model.connections[j].name,
        capacity / conductance
    );
    Ok((p.resolved, summary))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shifted_law_is_one_at_the_start_and_keeps_the_slope() {
        let law = shifted_law(SEED_TEMPERATURE_STIFFNESS_POLY, 60.0);
        assert!((law.eval(60.0) - 1.0).abs() < 1e-12);
        // The seed's slope at 40 °C over its value there: −1.331 %/K.
        let slope = law.derivative(60.0);
        assert!((slope + 0.013_31).abs() < 1e-4, "{slope}");
        let [a2, a1, a0] = SEED_TEMPERATURE_STIFFNESS_POLY;
        let seed = |t: f64| (a2 * t + a1) * t + a0;
        assert!((law.eval(70.0) - seed(50.0) / seed(40.0)).abs() < 1e-12);
        assert_eq!(law.range, Some([45.0, 75.0]));
    }

    /// A time constant gives the conductance as capacity over it (600 J/K over 40 s:
    /// 15 W/K); given beside a conductance it is refused, naming the key.
    #[test]
    fn a_time_constant_sets_the_conductance() {
        use crate::effects::{Effect, EffectSpec, build_truth};
        use crate::model::{parse_model, presets};
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        let user = parse_model(text, "bench.toml").unwrap();
        let spec = EffectSpec::new(Effect::CouplingThermalDrift)
            .with("capacity_j_per_k", 600.0)
            .with("time_constant_s", 40.0);
        let truth = build_truth(&user, &spec, 0.0, 0).unwrap();
        let thermal = truth
            .model
            .connections
            .iter()
            .find_map(|c| match &c.kind {
                crate::model::ConnectionKind::Rubber(r) => r.thermal.clone(),
                _ => None,
            })
            .expect("a warming stage");
        assert_eq!(thermal.capacity_j_per_k, 600.0);
        assert_eq!(thermal.conductance_w_per_k, 15.0);
        assert!(
            truth.effect.summary.contains("time constant 40 s"),
            "{}",
            truth.effect.summary
        );
        let both = spec.with("conductance_w_per_k", 2.0);
        let message = build_truth(&user, &both, 0.0, 0).unwrap_err().to_string();
        assert!(message.contains("time_constant_s"), "{message}");
    }

    /// A capacity down to 0.01 J/K is accepted (the diagnosis fits 0.3 J/K on development
    /// case 2149); below it, it is refused, naming the key.
    #[test]
    fn a_small_heat_capacity_is_accepted_down_to_its_bound() {
        use crate::effects::{Effect, EffectSpec, build_truth};
        use crate::model::{parse_model, presets};
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        let user = parse_model(text, "bench.toml").unwrap();
        let spec =
            |c: f64| EffectSpec::new(Effect::CouplingThermalDrift).with("capacity_j_per_k", c);
        let truth = build_truth(&user, &spec(0.01), 0.0, 0).expect("at the bound");
        let capacity = truth.model.connections.iter().find_map(|c| match &c.kind {
            crate::model::ConnectionKind::Rubber(r) => {
                r.thermal.as_ref().map(|t| t.capacity_j_per_k)
            }
            _ => None,
        });
        assert_eq!(capacity, Some(0.01));
        let message = build_truth(&user, &spec(0.009), 0.0, 0)
            .unwrap_err()
            .to_string();
        assert!(message.contains("capacity_j_per_k"), "{message}");
    }
}
