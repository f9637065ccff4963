//! Effects on the structure and the engine: a missing degree of freedom (seed 001's local
//! coupling mode), the reciprocating masses (crank-angle-dependent inertia, seed 001 eq.
//! 3–4), and one cylinder firing weaker or stronger. Gear backlash is [`super::backlash`].

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::truth::Applied;
use crate::model::{ConnectionKind, GROUND, Inertia, Model, RubberStiffness};
use crate::physics::engine;
use std::f64::consts::TAU;

/// `unmodelled_mode`: connection `connection` (default the first rubber stage; a shaft or
/// rubber stage) is really two in series, `<name>_a` and `<name>_b`, with stiffnesses
/// `k/split` and `k/(1 − split)` (same series stiffness) around a middle node `node`
/// (default `<name>_middle`) of inertia `inertia_kg_m2` (default a quarter of the lighter
/// end), which the user had lumped into the ends: it is taken from them (`take_from`:
/// `both`, half each, the default; or `from` or `to`, one end; ground gives none), so the
/// total inertia is unchanged. The local mode of the middle node against held ends is
/// `√((k_a + k_b)/J)/2π`.
///
/// `form` (default `split`) chooses this middle flange; `form = branch` is a local mode
/// hanging on a node instead ([`super::branch::branch_mode`], its own keys).
pub(crate) fn unmodelled_mode(
    model: &mut Model,
    spec: &EffectSpec,
) -> Result<Applied, EffectError> {
    if spec.params.get("form").map(String::as_str) == Some("branch") {
        return super::branch::branch_mode(model, spec);
    }
    let mut p = Params::new(
        spec,
        &[
            "connection",
            "inertia_kg_m2",
            "split",
            "node",
            "take_from",
            "form",
        ],
    )?;
    // Resolved only when given, so that a split's parameters read as they always did.
    if spec.params.contains_key("form") {
        let form = p.text("form", None)?;
        if form != "split" {
            return Err(p.bad("form", format!("`{form}`: expected split or branch")));
        }
    }
    let first = model
        .connections
        .iter()
        .find(|c| matches!(c.kind, ConnectionKind::Rubber(_)))
        .map(|c| c.name.clone());
    let name = p.text("connection", first)?;
    let Some(j) = model.connections.iter().position(|c| c.name == name) else {
        return Err(p.bad("connection", format!("no connection `{name}`")));
    };
    let conn = model.connections[j].clone();
    if let ConnectionKind::Gear(_) = conn.kind {
        return Err(p.bad(
            "connection",
            format!("`{name}` is a gear: split a shaft or rubber stage"),
        ));
    }
    let all_ends: Vec<usize> = [&conn.from, &conn.to]
        .iter()
        .filter(|n| n.as_str() != GROUND)
        .filter_map(|n| model.node_index(n))
        .collect();
    let lightest = all_ends
        .iter()
        .map(|&i| model.inertias[i].inertia_kg_m2)
        .fold(f64::INFINITY, f64::min);
    let j_m = p.number("inertia_kg_m2", 0.25 * lightest, 1e-9, 1e9)?;
    let split = p.number("split", 0.5, 0.1, 0.9)?;
    let node = p.text("node", Some(format!("{name}_middle")))?;
    let take_from = p.text("take_from", Some("both".into()))?;
    let ends: Vec<usize> = match take_from.as_str() {
        "both" => all_ends.clone(),
        "from" | "to" => {
            let end = if take_from == "from" {
                &conn.from
            } else {
                &conn.to
            };
            model.node_index(end).into_iter().collect()
        }
        other => {
            return Err(p.bad("take_from", format!("`{other}`: expected both, from or to")));
        }
    };
    if ends.is_empty() {
        return Err(p.bad("take_from", "that end is ground"));
    }
    if model.node_index(&node).is_some() || node == GROUND {
        return Err(p.bad("node", format!("`{node}` is already a node")));
    }
    let end_names: Vec<String> = ends
        .iter()
        .map(|&i| format!("`{}`", model.inertias[i].name))
        .collect();
    let share = j_m / ends.len() as f64;
    for &i in &ends {
        let end = &mut model.inertias[i];
        if end.inertia_kg_m2 - share < 0.1 * end.inertia_kg_m2 {
            return Err(p.bad(
                "inertia_kg_m2",
                format!(
                    "{j_m} kg·m² would leave `{}` less than 10 % of its {} kg·m²",
                    end.name, end.inertia_kg_m2
                ),
            ));
        }
        end.inertia_kg_m2 -= share;
    }
    let at = model.node_index(&conn.from).map_or(0, |i| i + 1);
    model.inertias.insert(
        at,
        Inertia {
            name: node.clone(),
            inertia_kg_m2: j_m,
            damping_nm_s_per_rad: 0.0,
        },
    );
    let part = |fraction: f64, suffix: &str, from: &str, to: &str| {
        let mut c = conn.clone();
        c.name = format!("{name}_{suffix}");
        c.from = from.to_string();
        c.to = to.to_string();
        match &mut c.kind {
            ConnectionKind::Shaft(s) => {
                s.stiffness_nm_per_rad /= fraction;
                s.damping_nm_s_per_rad /= fraction;
            }
            ConnectionKind::Rubber(r) => match &mut r.stiffness {
                RubberStiffness::Direct(k) => *k /= fraction,
                RubberStiffness::Elements(e) => e.radial_stiffness_n_per_m /= fraction,
            },
            ConnectionKind::Gear(_) => {}
        }
        c
    };
    let a = part(split, "a", &conn.from, &node);
    let b = part(1.0 - split, "b", &node, &conn.to);
    let stiffness = |c: &crate::model::Connection| match &c.kind {
        ConnectionKind::Shaft(s) => s.stiffness_nm_per_rad,
        ConnectionKind::Rubber(r) => r.static_stiffness_nm_per_rad(),
        ConnectionKind::Gear(_) => 0.0,
    };
    let f_local = ((stiffness(&a) + stiffness(&b)) / j_m).sqrt() / TAU;
    model.connections.splice(j..=j, [a, b]);
    let summary = format!(
        "`{name}` is two stages in series around a middle node `{node}` of {j_m} kg·m² \
         (taken from {}); its local mode against held ends is at {f_local:.1} Hz (static \
         stiffnesses)",
        end_names.join(" and ")
    );
    Ok((p.resolved, summary))
}

/// `crank_variable_inertia`: the truth has `mass_kg` of reciprocating mass per cylinder
/// (default `1100 kg/m³ · bore³`, about 0.6 kg for an 82 mm bore) where the user has none;
/// each cylinder's node loses the cycle mean `m·r²·(1/2 + λ²/8)` that the user had lumped
/// into it, so the mean inertia is unchanged and only its variation with crank angle and
/// the oscillating-mass torque are new. `drop_harmonics` (orders, comma separated,
/// default `none`) removes the user's `[[harmonic]]` stand-ins for that torque.
pub(crate) fn crank_inertia(model: &mut Model, spec: &EffectSpec) -> Result<Applied, EffectError> {
    let mut p = Params::new(spec, &["mass_kg", "drop_harmonics"])?;
    let Some(engine) = model.engine.clone() else {
        return Err(p.bad("mass_kg", "the model has no [engine]"));
    };
    if engine.reciprocating_mass_kg != 0.0 || engine.rod_inertia_correction_kg != 0.0 {
        return Err(p.bad(
            "mass_kg",
            "the user's engine already has reciprocating_mass (the effect is modelled)",
        ));
    }
    let default = (1100.0 * engine.bore_m.powi(3) * 100.0).round() / 100.0;
    let mass = p.number("mass_kg", default, 1e-3, 1e3)?;
    let drop = p.text("drop_harmonics", Some("none".into()))?;
    let orders: Vec<f64> = if drop == "none" {
        Vec::new()
    } else {
        drop.split(',')
            .map(|s| s.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| p.bad("drop_harmonics", format!("`{drop}`: orders, e.g. 2 or 2,4")))?
    };
    for q in &orders {
        let before = model.harmonics.len();
        model
            .harmonics
            .retain(|h| !((h.order - q).abs() < 1e-9 && engine.at.contains(&h.at)));
        if model.harmonics.len() == before {
            return Err(p.bad(
                "drop_harmonics",
                format!("no [[harmonic]] of order {q} acts on an engine node"),
            ));
        }
    }
    let mut e = engine.clone();
    e.reciprocating_mass_kg = mass;
    let mean = engine::mean_reciprocating_inertia_kg_m2(&e);
    for c in 0..e.cylinders as usize {
        let name = e.node_of_cylinder(c).to_string();
        let Some(i) = model.node_index(&name) else {
            continue;
        };
        let node = &mut model.inertias[i];
        if node.inertia_kg_m2 - mean <= 0.1 * node.inertia_kg_m2 {
            return Err(p.bad(
                "mass_kg",
                format!(
                    "node `{name}` ({} kg·m²) cannot give up the cycle-mean {mean:.5} kg·m²",
                    node.inertia_kg_m2
                ),
            ));
        }
        node.inertia_kg_m2 -= mean;
    }
    model.engine = Some(e);
    let dropped = if orders.is_empty() {
        String::new()
    } else {
        format!("; the user's [[harmonic]] stand-ins of order {drop} are removed")
    };
    let summary = format!(
        "the engine has {mass} kg reciprocating mass per cylinder: its inertia varies with \
         crank angle about the same mean ({mean:.5} kg·m² per cylinder, taken from the \
         crank nodes) and adds the oscillating-mass torque of seed 001 eq. 3{dropped}"
    );
    Ok((p.resolved, summary))
}

/// `cylinder_imbalance`: cylinder `cylinder` (from 1, default 1) has its gauge pressure
/// scaled by `pressure_scale` (default 0.85), through `[engine] pressure_scale`.
pub(crate) fn imbalance(model: &mut Model, spec: &EffectSpec) -> Result<Applied, EffectError> {
    let mut p = Params::new(spec, &["cylinder", "pressure_scale"])?;
    let Some(e) = model.engine.as_mut() else {
        return Err(p.bad("cylinder", "the model has no [engine]"));
    };
    let n = e.cylinders as usize;
    let cylinder = p.number("cylinder", 1.0, 1.0, n as f64)?;
    if cylinder.fract() != 0.0 {
        return Err(p.bad("cylinder", "must be a whole number"));
    }
    let factor = p.number("pressure_scale", 0.85, 0.0, 2.0)?;
    if factor == 1.0 {
        return Err(p.bad("pressure_scale", "1 changes nothing"));
    }
    let mut scale = e.pressure_scale.clone().unwrap_or_else(|| vec![1.0; n]);
    let i = cylinder as usize - 1;
    scale[i] *= factor;
    e.pressure_scale = Some(scale);
    let summary = format!(
        "cylinder {cylinder} fires with {factor} × the gauge pressure of the others \
         ([engine] pressure_scale)"
    );
    Ok((p.resolved, summary))
}
