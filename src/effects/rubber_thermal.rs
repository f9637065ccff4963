//! `coupling_thermal_drift` (seed 000 eq. 10–11): a rubber stage warms by its own loss
//! into a lumped heat capacity and softens with its temperature. Takes
//! `connection=<name>`, by default the first rubber stage.
//!
//! A stage without temperature laws of its own gets seed 000's, in one of two forms
//! (`softening`):
//! - `seed` (the default): eq. 10–11 as measured, a quadratic over 25–55 °C moved to the
//!   stage's start temperature ([`shifted_law`]), held beyond ±15 K of it;
//! - `linear`: their slopes at the start, −1.33 %/K in stiffness and −0.88 %/K in damping,
//!   on to [`LINEAR_FLOOR`] ([`linear_law`]). The diagnosis' thermal candidate takes this
//!   one: a stage at a resonance warms far past 15 K, and a law held there leaves it
//!   heating without end where a real rubber softens, detunes and stops.

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::rubber::{stage_index, stage_mut};
use super::truth::Applied;
use crate::model::{Model, Poly, Thermal};

/// Seed 000 eq. 10: α_Tc(T), T in °C (measured 25–55 °C).
pub const SEED_TEMPERATURE_STIFFNESS_POLY: [f64; 3] = [0.000187, -0.02565, 1.530];
/// Seed 000 eq. 11: α_Tξ(T), T in °C (measured 25–55 °C).
pub const SEED_TEMPERATURE_DAMPING_POLY: [f64; 3] = [0.000063, -0.01275, 1.281];
/// The `softening` the diagnosis' thermal candidate fixes.
pub const LINEAR_SOFTENING: &str = "linear";
/// Stiffness factor at which the `linear` law stops softening, 53 K above the start: a
/// stage that soft is far past any rubber's service temperature (natural-rubber couplings
/// are rated to 80–90 °C), so the floor only keeps the law a spring. The independent
/// bench softens its linear stages to the same floor. Held earlier, as the `seed` form
/// is at +15 K, a stage on a resonance heats without end: benchtruth case 2050's coupling
/// at 1020 rpm lost 3.6 kW and reached 590 °C in 6 s, where the bench's own, softening
/// on, detuned within a second to 30 W.
pub const LINEAR_FLOOR: f64 = 0.3;

/// A seed 000 temperature law's value at 40 °C (the middle of its measured 25–55 °C) and
/// its slope there over that value, 1/K.
fn at_40(seed: [f64; 3]) -> (f64, f64) {
    let [a2, a1, a0] = seed;
    let value = (a2 * 40.0 + a1) * 40.0 + a0;
    (value, (2.0 * a2 * 40.0 + a1) / value)
}

/// A seed 000 temperature law moved so that `t0_c` sits where 40 °C (the middle of the
/// measured 25–55 °C) sits in the seed's, normalised to 1 there, valid ±15 K around it.
fn shifted_law(seed: [f64; 3], t0_c: f64) -> Poly {
    let [a2, a1, a0] = seed;
    let d = t0_c - 40.0;
    let (at40, _) = at_40(seed);
    Poly {
        coeffs: [
            a2 / at40,
            (a1 - 2.0 * a2 * d) / at40,
            (a2 * d * d - a1 * d + a0) / at40,
        ],
        range: Some([t0_c - 15.0, t0_c + 15.0]),
    }
}

/// Seed 000's law `seed` at its slope at 40 °C over its value there (the middle of the
/// measured 25–55 °C), as a straight line through 1 at `t0_c`, held from `hot_k` above it
/// (and 15 K below it).
fn linear_law(seed: [f64; 3], t0_c: f64, hot_k: f64) -> Poly {
    let (_, slope_per_k) = at_40(seed);
    Poly {
        coeffs: [0.0, slope_per_k, 1.0 - slope_per_k * t0_c],
        range: Some([t0_c - 15.0, t0_c + hot_k]),
    }
}

/// Warming above the start at which the `linear` stiffness law reaches [`LINEAR_FLOOR`], K
/// (52.6 K at −1.331 %/K); the damping law is held from there too.
fn linear_hot_k() -> f64 {
    let (_, slope_per_k) = at_40(SEED_TEMPERATURE_STIFFNESS_POLY);
    (1.0 - LINEAR_FLOOR) / -slope_per_k
}

/// `coupling_thermal_drift`: the stage warms by its own loss into a lumped heat capacity
/// (`capacity_j_per_k`, default 300 J/K: about 0.17 kg of loaded rubber; at least
/// 0.01 J/K, for a small loss that warms visibly) and cools to `ambient_c` (default its
/// start temperature) through `conductance_w_per_k` (default 1.5 W/K; time constant
/// 200 s), or with the conductance that gives `time_constant_s` (capacity over
/// conductance, s; the diagnosis reads it off a long run's drift, [`crate::diagnose`]'s
/// thermal candidate). A stage without temperature laws gets seed
/// 000 eq. 10–11 by [`shifted_law`] (`softening = "seed"`, the default) or by
/// [`linear_law`] (`softening = "linear"`): −1.33 %/K in stiffness and −0.88 %/K in damping
/// at the start.
pub(crate) fn thermal(model: &mut Model, spec: &EffectSpec) -> Result<Applied, EffectError> {
    let mut p = Params::new(
        spec,
        &[
            "connection",
            "capacity_j_per_k",
            "conductance_w_per_k",
            "time_constant_s",
            "ambient_c",
            "softening",
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
    let softening = p.text("softening", Some("seed".into()))?;
    let linear = match softening.as_str() {
        LINEAR_SOFTENING => true,
        "seed" => false,
        other => return Err(p.bad("softening", format!("`{other}`: expected seed or linear"))),
    };
    let law = |seed: [f64; 3], t0: f64| {
        if linear {
            linear_law(seed, t0, linear_hot_k())
        } else {
            shifted_law(seed, t0)
        }
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
        stage.temperature_stiffness_poly = Some(law(SEED_TEMPERATURE_STIFFNESS_POLY, t0));
        added.push("α_Tc");
    }
    if stage.temperature_damping_poly.is_none() {
        stage.temperature_damping_poly = Some(law(SEED_TEMPERATURE_DAMPING_POLY, t0));
        added.push("α_Tξ");
    }
    let laws = match (added.is_empty(), softening.as_str()) {
        (true, _) => "its own temperature laws".to_string(),
        (false, LINEAR_SOFTENING) => format!(
            "{} of seed 000 eq. 10–11 at their slopes, linear from {t0} °C down to {:.0} % \
             of its stiffness",
            added.join(" and "),
            100.0 * LINEAR_FLOOR
        ),
        (false, _) => format!(
            "{} of seed 000 eq. 10–11 centred on {t0} °C",
            added.join(" and ")
        ),
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

    /// The linear form: 1 at the start, the seed's slopes there, held at the floor.
    #[test]
    fn the_linear_law_keeps_the_slopes_down_to_its_floor() {
        use crate::effects::{Effect, EffectSpec, build_truth};
        use crate::model::{ConnectionKind, parse_model, presets};
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        let user = parse_model(text, "bench.toml").unwrap();
        let spec = EffectSpec::new(Effect::CouplingThermalDrift).with("softening", "linear");
        let truth = build_truth(&user, &spec, 0.0, 0).unwrap();
        let stage = truth
            .model
            .connections
            .iter()
            .find_map(|c| match &c.kind {
                ConnectionKind::Rubber(r) if r.thermal.is_some() => Some(r.clone()),
                _ => None,
            })
            .expect("a warming stage");
        let t0 = stage.temperature_c;
        let k = stage.temperature_stiffness_poly.expect("a stiffness law");
        let d = stage.temperature_damping_poly.expect("a damping law");
        assert!((k.eval(t0) - 1.0).abs() < 1e-12 && (d.eval(t0) - 1.0).abs() < 1e-12);
        // −1.331 %/K and −0.877 %/K: the seed's slopes at 40 °C over its values there.
        assert!(
            (k.eval(t0 + 10.0) - (1.0 - 0.1331)).abs() < 1e-3,
            "{}",
            k.eval(t0 + 10.0)
        );
        assert!(
            (d.eval(t0 + 10.0) - (1.0 - 0.0877)).abs() < 1e-3,
            "{}",
            d.eval(t0 + 10.0)
        );
        // Held at the floor 52.6 K up, and far beyond.
        assert!((k.eval(t0 + 500.0) - LINEAR_FLOOR).abs() < 1e-9);
        assert!((k.eval(t0 + 52.0) - LINEAR_FLOOR) > 0.0);
        let bad = EffectSpec::new(Effect::CouplingThermalDrift).with("softening", "cubic");
        let message = build_truth(&user, &bad, 0.0, 0).unwrap_err().to_string();
        assert!(message.contains("softening"), "{message}");
    }
}
