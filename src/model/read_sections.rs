//! The model reader's sections after the connections: `[engine]`, `[[harmonic]]`,
//! `[load]`, `[operation]` and `[expect]` (part of [`read`](super::read)).

use super::error::ModelError;
use super::spanned::{Tab, wrong_type};
use super::{
    CriticalExpectation, Engine, Expect, Harmonic, HarmonicAmplitude, Load, LoadPressure,
    ModeExpectation, Operation, Pressure, PressureCurve, Regime,
};

pub(super) fn engine(t: &Tab) -> Result<Engine, ModelError> {
    t.allow(&[
        "at",
        "cylinders",
        "strokes",
        "firing_angles_deg",
        "bore",
        "crank_radius",
        "conrod_length",
        "reciprocating_mass",
        "rod_inertia_correction",
        "pressure",
        "pressure_by_load",
        "pressure_scale",
    ])?;
    let at_item = t.req("at")?;
    let at = match (at_item.as_str(), at_item.as_array()) {
        (Some(name), _) => vec![name.to_string()],
        (None, Some(names)) => names
            .iter()
            .enumerate()
            .map(|(i, v)| {
                v.as_str().map(str::to_string).ok_or_else(|| {
                    ModelError::at(format!("{}[{i}]", t.key("at")), "expected a node name")
                })
            })
            .collect::<Result<_, _>>()?,
        _ => {
            let message = "a node name or a list of node names";
            return Err(wrong_type(&t.key("at"), message, at_item));
        }
    };
    let pressure = match (t.opt_table("pressure")?, t.get("pressure_by_load")) {
        (Some(p), None) => Pressure::Single(curve(&p, &[])?),
        (None, Some(_)) => Pressure::ByLoad(
            t.list("pressure_by_load")?
                .iter()
                .map(|p| {
                    Ok(LoadPressure {
                        load: p.f64("load")?,
                        curve: curve(p, &["load"])?,
                    })
                })
                .collect::<Result<_, ModelError>>()?,
        ),
        (Some(_), Some(_)) => {
            let message = "give either `pressure` or `pressure_by_load`, not both";
            return Err(ModelError::at(t.key("pressure_by_load"), message));
        }
        (None, None) => {
            let message = "missing required key `pressure` (or `pressure_by_load`)";
            return Err(ModelError::at(t.key("pressure"), message));
        }
    };
    Ok(Engine {
        at,
        cylinders: t.u32("cylinders")?,
        strokes: t.opt_u32("strokes")?.unwrap_or(4),
        firing_angles_deg: t.opt_f64s("firing_angles_deg")?,
        bore_m: t.f64("bore")?,
        crank_radius_m: t.f64("crank_radius")?,
        conrod_length_m: t.f64("conrod_length")?,
        reciprocating_mass_kg: t.f64_or("reciprocating_mass", 0.0)?,
        rod_inertia_correction_kg: t.f64_or("rod_inertia_correction", 0.0)?,
        pressure,
        pressure_scale: t.opt_f64s("pressure_scale")?,
    })
}

/// `{ crank_angle_deg = [...], bar = [...] }`, plus the `extra` keys the caller reads.
fn curve(t: &Tab, extra: &[&str]) -> Result<PressureCurve, ModelError> {
    t.allow(&[&["crank_angle_deg", "bar"][..], extra].concat())?;
    Ok(PressureCurve {
        crank_angle_deg: t.f64s("crank_angle_deg")?,
        pressure_bar: t.f64s("bar")?,
    })
}

pub(super) fn harmonic(t: &Tab) -> Result<Harmonic, ModelError> {
    t.allow(&["at", "order", "amplitude", "phase_deg"])?;
    let amplitude = if t.req("amplitude")?.is_table_like() {
        let a = t.opt_table("amplitude")?.ok_or_else(|| {
            ModelError::at(t.key("amplitude"), "missing required key `amplitude`")
        })?;
        a.allow(&["rpm", "nm"])?;
        HarmonicAmplitude::BySpeed {
            speed_rpm: a.f64s("rpm")?,
            amplitude_nm: a.f64s("nm")?,
        }
    } else {
        HarmonicAmplitude::Constant(t.f64("amplitude")?)
    };
    Ok(Harmonic {
        at: t.str("at")?,
        order: t.f64("order")?,
        amplitude,
        // Required: `spec/model-format.md` gives no default (issue 13).
        phase_deg: t.f64("phase_deg")?,
    })
}

pub(super) fn load(t: &Tab) -> Result<Load, ModelError> {
    t.allow(&["at", "damping"])?;
    Ok(Load {
        at: t.opt_str("at")?,
        damping_nm_s_per_rad: t.f64_or("damping", 0.0)?,
    })
}

pub(super) fn operation(t: &Tab) -> Result<Operation, ModelError> {
    t.allow(&[
        "speed_range_rpm",
        "operating_range_rpm",
        "orders",
        "regimes",
    ])?;
    let regimes = t
        .list("regimes")?
        .iter()
        .map(|r| {
            r.allow(&["label", "speed_rpm", "load"])?;
            Ok(Regime {
                label: r.str("label")?,
                speed_rpm: r.f64("speed_rpm")?,
                load: r.opt_f64("load")?.unwrap_or(1.0),
            })
        })
        .collect::<Result<Vec<_>, ModelError>>()?;
    Ok(Operation {
        speed_range_rpm: t.opt_array::<2>("speed_range_rpm")?,
        operating_range_rpm: t.opt_array::<2>("operating_range_rpm")?,
        orders: t.opt_f64s("orders")?,
        regimes,
    })
}

pub(super) fn expect(t: &Tab) -> Result<Expect, ModelError> {
    t.allow(&[
        "mode_hz",
        "critical_rpm",
        "no_resonance_in_operating_range",
        "within_ratings",
    ])?;
    let within_ratings = match t.get("within_ratings") {
        None => Vec::new(),
        Some(item) => item
            .as_array()
            .ok_or_else(|| {
                wrong_type(&t.key("within_ratings"), "a list of connection names", item)
            })?
            .iter()
            .enumerate()
            .map(|(i, v)| {
                v.as_str().map(str::to_string).ok_or_else(|| {
                    ModelError::at(
                        format!("{}[{i}]", t.key("within_ratings")),
                        "expected a connection name",
                    )
                })
            })
            .collect::<Result<_, _>>()?,
    };
    let mode_list = t.list("mode_hz")?;
    let critical_list = t.list("critical_rpm")?;
    let mode_hz = mode_list.iter().map(|m| {
        m.allow(&["mode", "min", "max"])?;
        Ok(ModeExpectation {
            mode: m.u32("mode")?,
            min_hz: m.f64("min")?,
            max_hz: m.f64("max")?,
        })
    });
    let critical_rpm = critical_list.iter().map(|c| {
        c.allow(&["order", "min", "max"])?;
        Ok(CriticalExpectation {
            order: c.f64("order")?,
            min_rpm: c.f64("min")?,
            max_rpm: c.f64("max")?,
        })
    });
    Ok(Expect {
        mode_hz: mode_hz.collect::<Result<_, ModelError>>()?,
        critical_rpm: critical_rpm.collect::<Result<_, ModelError>>()?,
        no_resonance_in_operating_range: t
            .opt_f64s("no_resonance_in_operating_range")?
            .unwrap_or_default(),
        within_ratings,
    })
}
