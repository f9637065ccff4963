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
//! damped at each ratio of [`RATIOS`] (c = 2ζ√(k·J) of its own mode,
//! [`crate::effects::backlash::mesh_mode_inertia_kg_m2`]) at the plain fit's factors, and
//! the damping that fits the fitted recordings best by at least [`MIN_GAIN`] becomes part
//! of the model every candidate is fitted from. It is a plain value the model format could
//! not give, not new physics: the report names it under [`KEY_PREFIX`]`<gear>` in every
//! candidate row (N·m·s/rad), and accepting any verdict puts it into the model ([`apply`]).

use super::DiagnoseError;
use super::context::{Context, Evaluated};
use super::fit::{parabola_vertex_offset, parallel_map};
use super::report::{ParameterValue, Verdict};
use super::surrogate::scaled;
use super::trial;
use crate::effects::backlash::{DEFAULT_MESH_DAMPING_RATIO, mesh_mode_inertia_kg_m2};
use crate::model::{ConnectionKind, Gear, Model};
use std::collections::BTreeMap;

/// The mesh damping ratios tried first: a log grid a factor √10 apart around the backlash
/// candidates' default, from 1 % to 32 % of critical ([`choose`] refines the best).
pub const RATIOS: [f64; 4] = [
    0.1 * DEFAULT_MESH_DAMPING_RATIO,
    0.316_227_766_016_837_94 * DEFAULT_MESH_DAMPING_RATIO,
    DEFAULT_MESH_DAMPING_RATIO,
    3.162_277_660_168_379 * DEFAULT_MESH_DAMPING_RATIO,
];
/// The ratio of neighbouring [`RATIOS`], √10.
const STEP: f64 = 3.162_277_660_168_379;
/// Bracket halvings of the best ratio after the grid: ζ to within a factor 10^(1/8) = 1.33.
const HALVINGS: usize = 2;
/// Relative drop of the fitted χ² a damping must bring to be taken: below it the
/// recordings do not tell the mesh's damping, and the model stays as the user wrote it.
pub const MIN_GAIN: f64 = 0.05;
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

/// The damping the recordings chose.
#[derive(Debug)]
pub struct Chosen {
    /// The user's model with its meshes damped: what every fit scales from now on.
    pub model: Model,
    /// What was added.
    pub added: Added,
    /// That model at the plain fit's factors, on every recording.
    pub at_plain: Evaluated,
    /// That model as it is (every factor 1), on every recording: where fits start "from
    /// the user's values".
    pub at_user: Evaluated,
    /// Dampings that could not be simulated, with the reason.
    pub rejected: Vec<String>,
}

/// Tries [`RATIOS`] on `gears` of `cx.user` at the plain fit `plain`'s factors, then,
/// where the grid gains half of [`MIN_GAIN`], [`HALVINGS`] bracket halvings about the best
/// in ln ζ with the parabola's vertex through the last three. `None` when there are no
/// gears, or no ratio lowers the fitted χ² by [`MIN_GAIN`]. A ratio that cannot be simulated is a
/// rejected step; only cancelling is an error.
pub fn choose(
    cx: &Context,
    gears: &[String],
    plain: &Evaluated,
) -> Result<Option<Chosen>, DiagnoseError> {
    if gears.is_empty() {
        return Ok(None);
    }
    // The search scores the fitted half only, so it simulates only the runs that have
    // fitted observations (the others keep the plain fit's amplitudes).
    let mut fitted_runs = vec![false; cx.observed.runs.len()];
    for (o, held) in cx.observed.observations.iter().zip(&cx.held_out) {
        if !held {
            fitted_runs[o.run] = true;
        }
    }
    let only = Some((fitted_runs.as_slice(), plain.simulated.as_slice()));
    let run = |zeta: f64| {
        let (m, added) = damped(cx.user, gears, zeta);
        let at = scaled(&m, &cx.plain, &plain.factors).map_err(DiagnoseError::Input)?;
        let simulated = trial::simulate(cx, None, &at, None, only)?;
        let cost = cx.fit_cost(&simulated);
        Ok::<_, DiagnoseError>(Tried {
            zeta,
            model: m,
            added,
            at,
            cost,
        })
    };
    // Each ratio of a batch side by side; one that cannot be simulated is a rejected
    // step, left out.
    let mut rejected = Vec::new();
    let mut try_all = |zetas: &[f64]| -> Result<Vec<Option<Tried>>, DiagnoseError> {
        let runs = parallel_map(zetas.len(), cx.options.threads, &|k| Some(run(zetas[k])));
        let mut out = Vec::with_capacity(zetas.len());
        for (zeta, t) in zetas.iter().zip(runs) {
            out.push(match t {
                Some(Ok(t)) => Some(t),
                Some(Err(e)) if trial::is_fatal(&e) => return Err(e),
                Some(Err(e)) => {
                    rejected.push(trial::reason(&format!("mesh damping ratio {zeta:.4}"), &e));
                    None
                }
                None => None,
            });
        }
        Ok(out)
    };
    let cost = |t: &Option<Tried>| t.as_ref().map_or(f64::INFINITY, |t| t.cost);
    let mut grid = try_all(&RATIOS)?;
    let Some(k) = (0..grid.len()).min_by(|a, b| cost(&grid[*a]).total_cmp(&cost(&grid[*b]))) else {
        return Ok(None);
    };
    let plain_cost = cx.fit_cost(&plain.simulated);
    let mut best = grid.swap_remove(k);
    let mut step = 0.5 * STEP.ln();
    // Refined only where the grid already gains half of MIN_GAIN: the grid's factor √10
    // moves the cost by more than its halvings can.
    let halvings = if cost(&best) < (1.0 - 0.5 * MIN_GAIN) * plain_cost {
        HALVINGS
    } else {
        0
    };
    for _ in 0..halvings {
        let Some(mid) = best.as_ref().map(|t| t.zeta) else {
            break;
        };
        let around = try_all(&[mid * (-step).exp(), mid * step.exp()])?;
        let (lower, middle, upper) = (cost(&around[0]), cost(&best), cost(&around[1]));
        let vertex = parabola_vertex_offset(lower, middle, upper, step)
            .filter(|d| d.abs() < step)
            .map(|d| mid * d.exp());
        // The vertex is tried from the second halving on, once the three are close.
        let at_vertex = match vertex.filter(|_| step < 0.5 * STEP.ln()) {
            Some(zeta) => try_all(&[zeta])?,
            None => Vec::new(),
        };
        for t in around.into_iter().chain(at_vertex).flatten() {
            if t.cost < cost(&best) {
                best = Some(t);
            }
        }
        step *= 0.5;
    }
    let Some(best) = best.filter(|t| t.cost < (1.0 - MIN_GAIN) * plain_cost) else {
        return Ok(None);
    };
    // The chosen damping on every recording, at the plain factors and at the user's.
    let ones = vec![1.0; cx.plain.len()];
    let both = [(best.at, plain.factors.clone()), (best.model.clone(), ones)];
    let full = parallel_map(2, cx.options.threads, &|i| {
        Some(trial::evaluate(
            cx,
            None,
            both[i].0.clone(),
            None,
            both[i].1.clone(),
            None,
        ))
    });
    let mut evaluated = Vec::with_capacity(2);
    for e in full.into_iter().flatten() {
        match e {
            Ok(e) => evaluated.push(e),
            Err(e) if trial::is_fatal(&e) => return Err(e),
            // The held-out runs cannot be simulated with it: the model stays undamped.
            Err(_) => return Ok(None),
        }
    }
    let (Some(at_user), Some(at_plain)) = (evaluated.pop(), evaluated.pop()) else {
        return Ok(None);
    };
    Ok(Some(Chosen {
        model: best.model,
        added: Added {
            ratio: best.zeta,
            dampings: best.added,
        },
        at_plain,
        at_user,
        rejected,
    }))
}

/// One damping ratio tried.
struct Tried {
    zeta: f64,
    model: Model,
    added: Vec<(String, f64)>,
    /// The damped model at the plain factors.
    at: Model,
    cost: f64,
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
