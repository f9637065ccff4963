//! The verdict in words (issue 16): one physical sentence per effect, with its place and
//! size, for a person who knows drivelines but not torsim's effect keys ("the coupling's
//! rubber softens as it warms", not `coupling_thermal_drift`). The report keeps the keys
//! (`spec/diagnosis.md`); the explanation, the CLI, the HTML page and the window say this.

use super::report::ParameterValue;
use std::collections::BTreeMap;

fn number(p: &BTreeMap<String, ParameterValue>, key: &str) -> Option<f64> {
    match p.get(key)? {
        ParameterValue::Number(x) => Some(*x),
        ParameterValue::Text(t) => t.parse().ok(),
    }
}

fn text<'a>(p: &'a BTreeMap<String, ParameterValue>, key: &str) -> Option<&'a str> {
    match p.get(key)? {
        ParameterValue::Text(t) => Some(t),
        ParameterValue::Number(_) => None,
    }
}

/// Four significant digits, without trailing zeros' noise.
fn sig(x: f64) -> String {
    let a = x.abs();
    if a != 0.0 && !(1e-3..1e5).contains(&a) {
        format!("{x:.3e}")
    } else if a >= 100.0 {
        format!("{x:.0}")
    } else if a >= 10.0 {
        format!("{x:.1}")
    } else if a >= 1.0 {
        format!("{x:.2}")
    } else {
        format!("{x:.3}")
    }
}

/// `the coupling stage `c``, or `a rubber stage` when the place is not given.
fn stage(p: &BTreeMap<String, ParameterValue>) -> String {
    text(p, "connection").map_or("a rubber stage".into(), |c| format!("rubber stage `{c}`"))
}

/// What `effect` with its fitted `parameters` means physically, in one sentence.
pub fn effect_sentence(effect: &str, p: &BTreeMap<String, ParameterValue>) -> String {
    match effect {
        "none" => "Nothing is missing that torsim can fit.".into(),
        "parameter_error" => {
            let which = text(p, "parameter").unwrap_or("a plain parameter");
            match number(p, "factor") {
                Some(f) => format!(
                    "No physics is missing, but a plain value is off: {which} is {} the \
                     user's value ({:+.1} %).",
                    sig(f),
                    100.0 * (f - 1.0)
                ),
                None => format!("No physics is missing, but a plain value is off: {which}."),
            }
        }
        "coupling_amplitude_nonlinearity" => {
            // The elastic form fitted in `a1` has `a2` = 0: α_x = a1·x + 1; the saturating
            // form has `stiffening` and `saturation_mm`.
            let law = match (number(p, "a1"), number(p, "a2")) {
                _ if number(p, "stiffening").is_some() => format!(
                    "1 + {}·tanh((x/{})²) (saturating)",
                    number(p, "stiffening").map_or("s".into(), sig),
                    number(p, "saturation_mm").map_or("x_s".into(), sig)
                ),
                (Some(a1), Some(0.0)) => format!("{}·x + 1", sig(a1)),
                (_, a2) => format!("{}·x² + 1", a2.map_or("a₂".into(), sig)),
            };
            format!(
                "The rubber of {} stiffens as it twists further (progressive elements): \
                 α_x = {law} with x the element deformation in mm.",
                stage(p)
            )
        }
        "coupling_frequency_dependence" => match (number(p, "exponent"), number(p, "delta")) {
            (_, Some(d)) => format!(
                "The rubber of {} relaxes with vibration frequency: it stiffens by {} % from \
                 rest to high frequency across an S-curve about {} Hz, and loses most there.",
                stage(p),
                sig(100.0 * d),
                number(p, "relax_hz").map_or("?".into(), sig)
            ),
            (Some(n), None) => format!(
                "The rubber of {} is stiffer at higher vibration frequencies than its \
                 catalogue value says: stiffness grows as f^{} (and its loss with it).",
                stage(p),
                sig(n)
            ),
            (None, None) => format!(
                "The rubber of {} is stiffer at higher vibration frequencies than its \
                 catalogue value says.",
                stage(p)
            ),
        },
        "coupling_thermal_drift" => format!(
            "The rubber of {} warms with its own damping loss and softens as it warms \
             (heat capacity {} J/K).",
            stage(p),
            number(p, "capacity_j_per_k").map_or("?".into(), sig)
        ),
        "hysteretic_damping" => format!(
            "{} damps by hysteresis (the same energy lost per cycle at every frequency), \
             not like the viscous damper the model has{}.",
            text(p, "connection").map_or("A connection".into(), |c| format!("`{c}`")),
            number(p, "reference_hz").map_or(String::new(), |f| format!(
                " (equal to it at {} Hz)",
                sig(f)
            ))
        ),
        "unmodelled_mode" => {
            let place = text(p, "node")
                .map(|n| format!("at `{n}`"))
                .or_else(|| text(p, "connection").map(|c| format!("inside `{c}`")))
                .unwrap_or_else(|| "in the driveline".into());
            let size = number(p, "inertia_kg_m2")
                .map_or(String::new(), |j| format!(" of {} kg·m²", sig(j)));
            let frequency = number(p, "frequency_hz").map_or(String::new(), |f| {
                format!(", a local mode near {} Hz", sig(f))
            });
            format!(
                "A flexible part the model lacks: an inertia{size} on its own spring \
                 {place}{frequency} (a flexible flange, hub or accessory)."
            )
        }
        "crank_variable_inertia" => format!(
            "The engine's inertia varies with crank angle: reciprocating masses of {} kg \
             per cylinder that the model lumps into a constant inertia.",
            number(p, "mass_kg").map_or("?".into(), sig)
        ),
        "gear_backlash" => format!(
            "The gear {} has play: {}° of backlash, and its teeth separate where the \
             vibratory torque exceeds the mean.",
            text(p, "connection").map_or(String::new(), |c| format!("`{c}`")),
            number(p, "backlash_deg").map_or("?".into(), sig)
        ),
        "cylinder_imbalance" => {
            let cylinder = text(p, "cylinder")
                .map(str::to_string)
                .or_else(|| number(p, "cylinder").map(|c| format!("{c:.0}")))
                .unwrap_or_else(|| "one cylinder".into());
            match number(p, "pressure_scale") {
                Some(s) => format!(
                    "Cylinder {cylinder} fires with {:.0} % of the others' pressure ({:+.0} %): \
                     the engine's half orders grow.",
                    100.0 * s,
                    100.0 * (s - 1.0)
                ),
                None => format!("Cylinder {cylinder} fires unlike the others."),
            }
        }
        "sensor_artifact" => {
            let station = text(p, "station").map_or("a station".into(), |s| format!("`{s}`"));
            match text(p, "kind") {
                Some("pitch_error") => format!(
                    "The measurement, not the driveline: the tape or encoder at {station} \
                     runs eccentric or is pitched unevenly ({}°), which reads as a \
                     once-per-revolution speed swing.",
                    number(p, "error_deg").map_or("?".into(), sig)
                ),
                _ => {
                    let f = number(p, "joint_fraction").unwrap_or(0.0);
                    let how = if f >= 0.0 { "wider" } else { "narrower" };
                    format!(
                        "The measurement, not the driveline: the zebra tape at {station} \
                         has a butt joint {:.0} % of a stripe pitch {how} than the other \
                         stripes, which reads as a speed dip once per revolution.",
                        100.0 * f.abs()
                    )
                }
            }
        }
        other => format!("The model misses `{other}`."),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(pairs: &[(&str, ParameterValue)]) -> BTreeMap<String, ParameterValue> {
        pairs
            .iter()
            .map(|(k, v)| (k.to_string(), v.clone()))
            .collect()
    }

    #[test]
    fn each_effect_is_said_with_its_place_and_size() {
        let t = |s: &str| ParameterValue::Text(s.into());
        let n = ParameterValue::Number;
        let s = effect_sentence(
            "coupling_thermal_drift",
            &params(&[
                ("connection", t("coupling")),
                ("capacity_j_per_k", n(227.4)),
            ]),
        );
        assert!(
            s.contains("`coupling`") && s.contains("227 J/K") && s.contains("softens"),
            "{s}"
        );
        let s = effect_sentence(
            "sensor_artifact",
            &params(&[
                ("kind", t("tape_joint")),
                ("station", t("crank")),
                ("joint_fraction", n(-0.19)),
            ]),
        );
        assert!(s.contains("19 % of a stripe pitch narrower"), "{s}");
        assert!(!s.contains('-'), "no negative fraction shown: {s}");
        let s = effect_sentence(
            "unmodelled_mode",
            &params(&[
                ("node", t("mass3")),
                ("inertia_kg_m2", n(0.00915)),
                ("frequency_hz", n(749.2)),
            ]),
        );
        assert!(
            s.contains("at `mass3`") && s.contains("749 Hz") && s.contains("0.009"),
            "{s}"
        );
        let s = effect_sentence(
            "cylinder_imbalance",
            &params(&[("cylinder", t("4")), ("pressure_scale", n(0.95))]),
        );
        assert!(
            s.contains("Cylinder 4 fires with 95 %") && s.contains("-5 %"),
            "{s}"
        );
    }
}
