//! A gear mesh the user's model leaves undamped, damped as the recordings say.
//!
//! The model format's gear (`spec/model-format.md`) has a mesh stiffness but no mesh
//! damping; `mesh_damping` is torsim's extension (README, *Gear mesh damping*). A geared
//! model written to the spec therefore has undamped meshes, while a real mesh loses a few
//! to about 15 % of critical in its own mode (the range gear-pair models assume,
//! [`crate::effects::backlash::DEFAULT_MESH_DAMPING_RATIO`]). An undamped mesh mode rings
//! at its resonance far above what a bench records, and a diagnosis that cannot damp it
//! names whatever damps it best: independent bench case 3048 (`benchtruth`, a plain
//! stiffness error, its mesh damped at c = 7.0 N·m·s/rad and written without it) was named
//! `unmodelled_mode`, a branch at the 751 Hz mesh mode (held-out χ²/N 5.1, the plain
//! parameters 43.9). With that damping in its model it holds out 0.35 on the plain
//! parameters alone.
//!
//! So when the user's model misfits and has an undamped elastic mesh, every such mesh is
//! damped at each ratio of [`RATIOS`](super::mesh_damping_search::RATIOS) (c = 2ζ√(k·J) of
//! its own mode, [`crate::effects::backlash::mesh_mode_inertia_kg_m2`]), at the plain fit's
//! factors and at the user's values, and the damping that fits the fitted recordings better
//! than the plain fit by at least [`MIN_GAIN`](super::mesh_damping_search::MIN_GAIN)
//! becomes part of the model every candidate is fitted from. It is a plain value the model
//! format could not give, not new physics: the report names it under [`KEY_PREFIX`]`<gear>`
//! in every candidate row (N·m·s/rad), and accepting any verdict puts it into the model
//! ([`apply`]).

use super::report::{ParameterValue, Verdict};
use crate::effects::backlash::mesh_mode_inertia_kg_m2;
use crate::model::{ConnectionKind, Gear, Model};
use std::collections::BTreeMap;

/// The report's key of a mesh damping the diagnosis added, followed by the gear's name.
pub const KEY_PREFIX: &str = "mesh_damping.";

/// The gears of `model` with a mesh stiffness and no mesh damping.
pub fn undamped(model: &Model) -> Vec<String> {
    model
        .connections
        .iter()
        .filter(|c| {
            matches!(&c.kind, ConnectionKind::Gear(g)
                if g.mesh_stiffness_nm_per_rad.is_some() && g.mesh_damping_nm_s_per_rad == 0.0)
        })
        .map(|c| c.name.clone())
        .collect()
}

/// Gear `name` of `model` when it has a mesh stiffness.
fn elastic_gear<'m>(model: &'m mut Model, name: &str) -> Option<&'m mut Gear> {
    model
        .connections
        .iter_mut()
        .find_map(|c| match &mut c.kind {
            ConnectionKind::Gear(g) if c.name == name && g.mesh_stiffness_nm_per_rad.is_some() => {
                Some(g)
            }
            _ => None,
        })
}

/// `model` with each of `gears` damped at ratio `zeta` of its mesh mode; the dampings
/// given, N·m·s/rad, by gear.
pub fn damped(model: &Model, gears: &[String], zeta: f64) -> (Model, Vec<(String, f64)>) {
    let mut m = model.clone();
    let mut added = Vec::new();
    for name in gears {
        let j = mesh_mode_inertia_kg_m2(model, name);
        if let (Some(j), Some(g)) = (j, elastic_gear(&mut m, name))
            && let Some(k) = g.mesh_stiffness_nm_per_rad
        {
            let damping = 2.0 * zeta * (k * j).sqrt();
            g.mesh_damping_nm_s_per_rad = damping;
            added.push((name.clone(), damping));
        }
    }
    (m, added)
}

/// Mesh dampings the diagnosis added to the user's model.
#[derive(Debug, Clone, PartialEq)]
pub struct Added {
    /// The damping ratio ζ of the meshes' own modes.
    pub ratio: f64,
    /// The dampings, N·m·s/rad at each gear's `to` side, by gear.
    pub dampings: Vec<(String, f64)>,
}

/// `model` with gear `name`'s mesh damping taken out (unchanged without that elastic
/// gear; a rigid gear has no mesh damping).
pub fn without(model: &Model, name: &str) -> Model {
    let mut m = model.clone();
    if let Some(g) = elastic_gear(&mut m, name) {
        g.mesh_damping_nm_s_per_rad = 0.0;
    }
    m
}

/// The report keys of `added` ([`KEY_PREFIX`]`<gear>`, N·m·s/rad); none without it.
pub fn keys(added: Option<&Added>) -> Vec<(String, ParameterValue)> {
    added.map_or(Vec::new(), |a| {
        a.dampings
            .iter()
            .map(|(g, c)| (format!("{KEY_PREFIX}{g}"), ParameterValue::Number(*c)))
            .collect()
    })
}

/// `verdict` with the mesh dampings `added` among its parameters and said in its
/// explanation; unchanged without them, or when it is `none` (the user's model as given).
pub fn marked(mut verdict: Verdict, added: Option<&Added>) -> Verdict {
    let Some(a) = added.filter(|_| verdict.effect != "none") else {
        return verdict;
    };
    verdict.parameters.extend(keys(Some(a)));
    let gears: Vec<String> = a
        .dampings
        .iter()
        .map(|(g, c)| format!("`{g}` {c:.3} N·m·s/rad"))
        .collect();
    verdict.explanation.push_str(&format!(
        " The model's undamped gear meshes were damped at ζ = {:.3} of their own modes ({}), \
         as the recordings chose: the model format's gear carries no mesh damping, and every \
         fit above started from the damped model.",
        a.ratio,
        gears.join(", ")
    ));
    verdict
}

/// `model` with every mesh damping a report row names under [`KEY_PREFIX`] put in.
pub fn apply(
    model: &Model,
    parameters: &BTreeMap<String, ParameterValue>,
) -> Result<Model, String> {
    let mut m = model.clone();
    for (key, value) in parameters {
        let Some(name) = key.strip_prefix(KEY_PREFIX) else {
            continue;
        };
        let ParameterValue::Number(c) = value else {
            return Err(format!("`{key}` is no number"));
        };
        if !(c.is_finite() && *c >= 0.0) {
            return Err(format!("`{key}` = {c} is no damping"));
        }
        let Some(g) = elastic_gear(&mut m, name) else {
            return Err(format!(
                "the model has no elastic gear `{name}` (edited since the diagnosis?)"
            ));
        };
        g.mesh_damping_nm_s_per_rad = *c;
    }
    Ok(m)
}

#[cfg(test)]
#[path = "mesh_damping_tests.rs"]
mod tests;
