//! Semantic checks of the excitation (`[engine]`, `[[harmonic]]`), `[operation]` and
//! `[expect]`; part of [`validate`](super::validate::validate).

use super::validate::{
    Check, all_finite, fail, finite, increasing, known_node, non_negative, positive, range,
};
use super::{Engine, HarmonicAmplitude, Model, Pressure, PressureCurve};

/// `[engine]`.
pub(crate) fn engine(model: &Model, e: &Engine) -> Check {
    if e.at.is_empty() {
        fail("engine.at", "needs a node name")?;
    }
    for (i, name) in e.at.iter().enumerate() {
        let key = if e.at.len() == 1 {
            "engine.at".to_string()
        } else {
            format!("engine.at[{i}]")
        };
        known_node(model, &key, name)?;
    }
    if e.cylinders < 1 {
        fail("engine.cylinders", "must be at least 1")?;
    }
    let max_cylinders = crate::limits::current().max_cylinders;
    if e.cylinders as usize > max_cylinders {
        fail(
            "engine.cylinders",
            format!(
                "{} cylinders is more than the limit of {max_cylinders} (issue 13: the \
                 time domain's cost grows with the cylinders; raise the limit with \
                 --max-cylinders)",
                e.cylinders
            ),
        )?;
    }
    if e.strokes != 2 && e.strokes != 4 {
        fail(
            "engine.strokes",
            format!("must be 2 or 4, found {}", e.strokes),
        )?;
    }
    let n = e.cylinders as usize;
    if e.at.len() != 1 && e.at.len() != n {
        fail(
            "engine.at",
            format!(
                "lists {} nodes; give one node or one per cylinder ({n})",
                e.at.len()
            ),
        )?;
    }
    if let Some(angles) = &e.firing_angles_deg {
        if angles.len() != n {
            fail(
                "engine.firing_angles_deg",
                format!(
                    "has {} angles but the engine has {n} cylinders",
                    angles.len()
                ),
            )?;
        }
        all_finite("engine.firing_angles_deg", angles)?;
    }
    positive("engine.bore", e.bore_m)?;
    positive("engine.crank_radius", e.crank_radius_m)?;
    positive("engine.conrod_length", e.conrod_length_m)?;
    if e.conrod_length_m <= e.crank_radius_m {
        fail(
            "engine.conrod_length",
            format!(
                "must be longer than crank_radius ({}), found {}",
                e.crank_radius_m, e.conrod_length_m
            ),
        )?;
    }
    if let Some(scale) = &e.pressure_scale {
        if scale.len() != n {
            fail(
                "engine.pressure_scale",
                format!(
                    "has {} factors but the engine has {n} cylinders",
                    scale.len()
                ),
            )?;
        }
        for (i, f) in scale.iter().enumerate() {
            non_negative(&format!("engine.pressure_scale[{i}]"), *f)?;
        }
    }
    non_negative("engine.reciprocating_mass", e.reciprocating_mass_kg)?;
    non_negative("engine.rod_inertia_correction", e.rod_inertia_correction_kg)?;
    let cycle = e.cycle_deg();
    match &e.pressure {
        Pressure::Single(c) => curve("engine.pressure", c, cycle),
        Pressure::ByLoad(curves) => {
            if curves.is_empty() {
                fail("engine.pressure_by_load", "needs at least one curve")?;
            }
            for (i, lp) in curves.iter().enumerate() {
                let key = format!("engine.pressure_by_load[{i}]");
                if !(0.0..=1.0).contains(&lp.load) {
                    fail(
                        format!("{key}.load"),
                        format!("must be in [0, 1], found {}", lp.load),
                    )?;
                }
                if i > 0 && lp.load <= curves[i - 1].load {
                    fail(
                        format!("{key}.load"),
                        format!(
                            "loads must be strictly increasing, but {} follows {}",
                            lp.load,
                            curves[i - 1].load
                        ),
                    )?;
                }
                curve(&key, &lp.curve, cycle)?;
            }
            Ok(())
        }
    }
}

/// One pressure curve at `key` (`engine.pressure` or `engine.pressure_by_load[i]`).
fn curve(key: &str, c: &PressureCurve, cycle_deg: f64) -> Check {
    let angles_key = format!("{key}.crank_angle_deg");
    let bar_key = format!("{key}.bar");
    let (angles, bar) = (&c.crank_angle_deg, &c.pressure_bar);
    if angles.len() != bar.len() {
        fail(
            &bar_key,
            format!(
                "has {} values but crank_angle_deg has {}",
                bar.len(),
                angles.len()
            ),
        )?;
    }
    if angles.len() < 2 {
        fail(
            &angles_key,
            format!("needs at least 2 points, found {}", angles.len()),
        )?;
    }
    all_finite(&angles_key, angles)?;
    all_finite(&bar_key, bar)?;
    increasing(&angles_key, angles)?;
    let span = angles[angles.len() - 1] - angles[0];
    let closed = span == cycle_deg && bar[0] == bar[bar.len() - 1];
    if span >= cycle_deg && !closed {
        fail(
            &angles_key,
            format!(
                "spans {span}°, more than one cycle ({cycle_deg}°); a span of exactly one \
                 cycle needs equal first and last pressures"
            ),
        )?;
    }
    Ok(())
}

/// `[[harmonic]]`.
pub(crate) fn harmonics(model: &Model) -> Check {
    for (i, h) in model.harmonics.iter().enumerate() {
        let key = |sub: &str| format!("harmonic[{i}].{sub}");
        known_node(model, &key("at"), &h.at)?;
        order(&key("order"), h.order)?;
        finite(&key("phase_deg"), h.phase_deg)?;
        match &h.amplitude {
            HarmonicAmplitude::Constant(a) => non_negative(&key("amplitude"), *a)?,
            HarmonicAmplitude::BySpeed {
                speed_rpm,
                amplitude_nm,
            } => {
                if speed_rpm.len() != amplitude_nm.len() {
                    fail(
                        key("amplitude.nm"),
                        format!(
                            "has {} values but rpm has {}",
                            amplitude_nm.len(),
                            speed_rpm.len()
                        ),
                    )?;
                }
                if speed_rpm.is_empty() {
                    fail(key("amplitude.rpm"), "needs at least one point")?;
                }
                all_finite(&key("amplitude.rpm"), speed_rpm)?;
                for (j, a) in amplitude_nm.iter().enumerate() {
                    non_negative(&format!("{}[{j}]", key("amplitude.nm")), *a)?;
                }
                increasing(&key("amplitude.rpm"), speed_rpm)?;
            }
        }
    }
    Ok(())
}

/// `[operation]` and `[expect]`.
pub(crate) fn operation_and_expect(model: &Model) -> Check {
    let op = &model.operation;
    if let Some(r) = op.speed_range_rpm {
        range("operation.speed_range_rpm", r)?;
    }
    if let Some(r) = op.operating_range_rpm {
        range("operation.operating_range_rpm", r)?;
    }
    if op.orders.as_ref().is_some_and(Vec::is_empty) {
        fail(
            "operation.orders",
            "is empty: a response with no orders shows nothing; list at least one order, \
             or leave `orders` out for every multiple of 0.5 (1 for a 2-stroke) up to 12",
        )?;
    }
    for (i, q) in op.orders.iter().flatten().enumerate() {
        order(&format!("operation.orders[{i}]"), *q)?;
    }
    for (i, r) in op.regimes.iter().enumerate() {
        positive(&format!("operation.regimes[{i}].speed_rpm"), r.speed_rpm)?;
        if !(0.0..=1.0).contains(&r.load) {
            fail(
                format!("operation.regimes[{i}].load"),
                "must be within 0 … 1",
            )?;
        }
    }
    let ex = &model.expect;
    for (i, m) in ex.mode_hz.iter().enumerate() {
        let key = format!("expect.mode_hz[{i}]");
        if m.mode < 1 {
            fail(format!("{key}.mode"), "modes are counted from 1")?;
        }
        bounds(&key, m.min_hz, m.max_hz)?;
    }
    for (i, c) in ex.critical_rpm.iter().enumerate() {
        let key = format!("expect.critical_rpm[{i}]");
        positive(&format!("{key}.order"), c.order)?;
        bounds(&key, c.min_rpm, c.max_rpm)?;
    }
    let key = "expect.no_resonance_in_operating_range";
    for (i, q) in ex.no_resonance_in_operating_range.iter().enumerate() {
        positive(&format!("{key}[{i}]"), *q)?;
    }
    if !ex.no_resonance_in_operating_range.is_empty() && op.operating_range_rpm.is_none() {
        fail(key, "needs `operating_range_rpm` in [operation]")?;
    }
    for (i, name) in ex.within_ratings.iter().enumerate() {
        let rated = model.connections.iter().any(|c| {
            c.name == *name
                && matches!(&c.kind, crate::model::ConnectionKind::Rubber(r) if r.rating.is_some())
        });
        if !rated {
            fail(
                format!("expect.within_ratings[{i}]"),
                format!("`{name}` is no rubber stage with a `rating`"),
            )?;
        }
    }
    Ok(())
}

/// An engine order: finite, > 0 and at most `limits::current().max_order` (issue 13).
fn order(key: &str, q: f64) -> Check {
    positive(key, q)?;
    let max_order = crate::limits::current().max_order;
    if q > max_order {
        fail(
            key,
            format!(
                "order {q} is above the limit max_order = {max_order} (issue 13: orders \
                 allocate and loop in sweeps; a front end may raise the limit)"
            ),
        )?;
    }
    Ok(())
}

/// `min ≤ max`, both finite.
fn bounds(key: &str, min: f64, max: f64) -> Check {
    finite(&format!("{key}.min"), min)?;
    finite(&format!("{key}.max"), max)?;
    if min > max {
        fail(
            format!("{key}.max"),
            format!("max ({max}) is below min ({min})"),
        )?;
    }
    Ok(())
}
