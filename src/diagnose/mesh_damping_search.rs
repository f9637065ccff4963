//! The search for the damping of the gear meshes the user's model leaves undamped
//! ([`super::mesh_damping`] says why and what becomes of it): a log grid of damping
//! ratios, each at the plain fit's factors and at the user's values, refined in ln ζ about
//! the best where it gains, kept on a [`MIN_GAIN`] drop of the fitted χ².
//!
//! Both starts, because the plain fit has already bent the plain parameters to mimic the
//! missing damping: on independent bench case 101904 (`benchtruth`, a plain control whose
//! mesh is damped at ζ ≈ 10 %) it had moved `mass6` by ×0.77 and `mass3` by ×1.12 (fitted
//! χ²/N 38.7 → 2.76). Damped at those factors the meshes gained under 5 %, and the
//! model stayed undamped, so a candidate damped the mesh mode instead and was named
//! (false physics). From the user's values the damping alone fits the same data at 1.49.

use super::DiagnoseError;
use super::context::{Context, Evaluated};
use super::fit::{parabola_vertex_offset, parallel_map};
use super::mesh_damping::{Added, damped};
use super::surrogate::scaled;
use super::trial;
use crate::effects::backlash::DEFAULT_MESH_DAMPING_RATIO;
use crate::model::Model;

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

/// The damping the recordings chose.
#[derive(Debug)]
pub struct Chosen {
    /// The user's model with its meshes damped: what every fit scales from now on.
    pub model: Model,
    /// What was added.
    pub added: Added,
    /// That model at the factors the damping was chosen at (the plain fit's or the
    /// user's values), on every recording: where the plain parameters are refitted from.
    pub at_start: Evaluated,
    /// That model as it is (every factor 1), on every recording: where fits start "from
    /// the user's values".
    pub at_user: Evaluated,
    /// Dampings that could not be simulated, with the reason.
    pub rejected: Vec<String>,
}

/// Tries [`RATIOS`] on `gears` of `cx.user`, each at the plain fit `plain`'s factors and
/// at the user's values (every factor 1), then, where the grid gains half of [`MIN_GAIN`],
/// [`HALVINGS`] bracket halvings about the best in ln ζ at the best's factors, with the
/// parabola's vertex through the last three. `None` when there are no gears, or no ratio
/// lowers the fitted χ² by [`MIN_GAIN`]. A ratio that cannot be simulated is a rejected
/// step; only cancelling is an error.
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
    let ones = vec![1.0; cx.plain.len()];
    let starts = [plain.factors.as_slice(), ones.as_slice()];
    let run = |zeta: f64, start: usize| {
        let (m, added) = damped(cx.user, gears, zeta);
        let at = scaled(&m, &cx.plain, starts[start]).map_err(DiagnoseError::Input)?;
        let simulated = trial::simulate(cx, None, &at, None, only)?;
        let cost = cx.fit_cost(&simulated);
        Ok::<_, DiagnoseError>(Tried {
            zeta,
            start,
            model: m,
            added,
            at,
            cost,
        })
    };
    // Each ratio of a batch side by side; one that cannot be simulated is a rejected
    // step, left out.
    let mut rejected = Vec::new();
    let mut try_all = |tries: &[(f64, usize)]| -> Result<Vec<Option<Tried>>, DiagnoseError> {
        let runs = parallel_map(tries.len(), cx.options.threads, &|k| {
            Some(run(tries[k].0, tries[k].1))
        });
        let mut out = Vec::with_capacity(tries.len());
        for ((zeta, _), t) in tries.iter().zip(runs) {
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
    let grid_tries: Vec<(f64, usize)> = (0..starts.len())
        .flat_map(|start| RATIOS.iter().map(move |z| (*z, start)))
        .collect();
    let mut grid = try_all(&grid_tries)?;
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
        let Some((mid, start)) = best.as_ref().map(|t| (t.zeta, t.start)) else {
            break;
        };
        let around = try_all(&[(mid * (-step).exp(), start), (mid * step.exp(), start)])?;
        let (lower, middle, upper) = (cost(&around[0]), cost(&best), cost(&around[1]));
        let vertex = parabola_vertex_offset(lower, middle, upper, step)
            .filter(|d| d.abs() < step)
            .map(|d| (mid * d.exp(), start));
        // The vertex is tried from the second halving on, once the three are close.
        let at_vertex = match vertex.filter(|_| step < 0.5 * STEP.ln()) {
            Some(tried) => try_all(&[tried])?,
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
    // The chosen damping on every recording, at its start's factors and at the user's.
    let both = [
        (best.at, starts[best.start].to_vec()),
        (best.model.clone(), ones.clone()),
    ];
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
    let (Some(at_user), Some(at_start)) = (evaluated.pop(), evaluated.pop()) else {
        return Ok(None);
    };
    Ok(Some(Chosen {
        model: best.model,
        added: Added {
            ratio: best.zeta,
            dampings: best.added,
        },
        at_start,
        at_user,
        rejected,
    }))
}

/// One damping ratio tried.
struct Tried {
    zeta: f64,
    /// The index of the start the plain parameters were at: 0 the plain fit, 1 the user's.
    start: usize,
    model: Model,
    added: Vec<(String, f64)>,
    /// The damped model at the start's factors.
    at: Model,
    cost: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::DiagnoseOptions;
    use crate::diagnose::mesh_damping::undamped;
    use crate::diagnose::observe::observe;
    use crate::diagnose::residual::expected;
    use crate::diagnose::tests_guard::{bench, recordings};

    /// The pattern of bench case 101904, by hand on the diagnosis bench: recordings made
    /// by its mesh damped at ζ = 0.1 (a ratio of the grid) with the plain parameters as
    /// the user wrote them, and a plain fit that bent the engine's inertia by ×0.77. The
    /// damping is found from the user's values (cost zero there, where at the bent
    /// factors no damping can reach it), at the truth's ratio, and the refit starts there.
    #[test]
    fn the_damping_is_also_tried_from_the_users_values() {
        let model = bench();
        let options = DiagnoseOptions::default();
        let observed = observe(&recordings(), 8.0).expect("observed");
        let mut cx = Context::new(&model, &options, observed);
        let gears = undamped(&model);
        let ones = vec![1.0; cx.plain.len()];
        let (truth, _) = damped(&model, &gears, 0.1);
        let at_truth = trial::evaluate(&cx, None, truth, None, ones.clone(), None).expect("runs");
        for (o, s) in cx.observed.observations.iter_mut().zip(&at_truth.simulated) {
            o.measured_rpm = expected(*s, o.bias_sigma_rpm);
        }
        let mut bent = ones.clone();
        let crank = cx.plain.iter().position(|p| p.name == "inertia.engine");
        bent[crank.expect("the engine's inertia is a plain parameter")] = 0.77;
        let plain_model = scaled(&model, &cx.plain, &bent).expect("scales");
        let plain = trial::evaluate(&cx, None, plain_model, None, bent, None).expect("runs");
        assert!(cx.fit_cost(&plain.simulated) > 1.0, "the bent fit misfits");
        let chosen = choose(&cx, &gears, &plain)
            .expect("no cancelling")
            .expect("a damping is chosen");
        assert_eq!(
            chosen.at_start.factors, ones,
            "started from the user's values"
        );
        assert_eq!(chosen.added.ratio, 0.1);
        assert!(cx.fit_cost(&chosen.at_start.simulated) < 1e-9);
        assert_eq!(chosen.model, damped(&model, &gears, 0.1).0);
    }

    /// The grid is a factor √10 apart and centred (in ln ζ) on the backlash default.
    #[test]
    fn the_ratios_are_a_log_grid_about_the_backlash_default() {
        for w in RATIOS.windows(2) {
            assert!((w[1] / w[0] - STEP).abs() < 1e-12);
        }
        assert!((STEP * STEP - 10.0).abs() < 1e-12);
        assert_eq!(RATIOS[2], DEFAULT_MESH_DAMPING_RATIO);
    }
}
