//! The ratings on a steady time-domain run (issue 16: "checks everywhere a torque or loss
//! is computed": `simulate` and `compare`). The loads of [`StageLoads`] are read off the
//! run as a bench would read them off a torque transducer: the mean torque and the
//! largest torque magnitude over the recorded samples, the orders of the synchronously
//! averaged cycle (the torque resampled in the reference angle, as
//! [`crate::signal::analyse_with`] does for speeds), and the stage's dissipated power.
//! For a linear model these are the forced response's loads, with the run's own rubber
//! law (`tests/ratings.rs` checks the two views agree).

use super::{StageLoads, StageRating, checks_at, rated_stages};
use crate::model::{CouplingRating, Model};
use crate::signal::orders::{cycle_orders, synchronous_average};
use crate::signal::{
    AnalysisOptions, Interpolation, SAMPLES_PER_REV, SignalError, angle_grid, resample,
};
use crate::transient::Simulation;

/// The rating checks of every rated rubber stage of `model` on `sim`, a steady run of
/// `model` at the mean reference speed `speed_rpm`: one operating point per stage.
pub fn check_simulated(
    model: &Model,
    sim: &Simulation,
    speed_rpm: f64,
) -> Result<Vec<StageRating>, SignalError> {
    let mut out = Vec::new();
    let stages: Vec<_> = rated_stages(model).collect();
    if stages.is_empty() {
        return Ok(out);
    }
    let cycle_rev = f64::from(model.strokes()) / 2.0;
    let reference = &sim.speed_rpm[sim.reference_node];
    let grid = angle_grid(&sim.time_s, reference, SAMPLES_PER_REV, cycle_rev)?;
    let max_order = AnalysisOptions::default().max_order;
    for (j, stage, rating) in stages {
        let Some((_, torque_nm)) = sim.torque_nm.iter().find(|(c, _)| *c == j) else {
            continue;
        };
        let on_grid = resample(&grid, torque_nm, Interpolation::BandLimited);
        let cycle = synchronous_average(&on_grid, grid.samples_per_cycle);
        let orders_nm = cycle_orders(&cycle, cycle_rev, max_order)?
            .iter()
            .map(|o| (o.order, o.amplitude))
            .collect();
        let mean_nm = cycle.iter().sum::<f64>() / cycle.len().max(1) as f64;
        let peak_nm = torque_nm.iter().fold(0.0_f64, |m, t| m.max(t.abs()));
        let power_loss_w = sim
            .power_loss_w
            .iter()
            .find(|(c, _)| *c == j)
            .map_or(0.0, |(_, w)| *w);
        let loads = StageLoads {
            speed_rpm,
            mean_nm,
            peak_nm,
            orders_nm,
            power_loss_w,
        };
        let s_t = CouplingRating::temperature_factor(stage.temperature_c);
        out.push(StageRating {
            connection: model.connections[j].name.clone(),
            connection_index: j,
            rating: rating.clone(),
            temperature_factor: s_t,
            by_speed: vec![checks_at(rating, s_t, &loads)],
        });
    }
    Ok(out)
}

/// The T_Kmax check of every rated stage (with a maximum torque) on a run-up `sim` of
/// `model`: the largest torque magnitude of the run, at the reference speed where it
/// occurred. DIN 740-2 allows T_Kmax for passing through a resonance; the steady limits
/// (T_KN, T_KW, P_KV) are not judged on a passage.
pub fn check_run_up_peaks(model: &Model, sim: &Simulation) -> Vec<StageRating> {
    let reference = &sim.speed_rpm[sim.reference_node];
    let mut out = Vec::new();
    for (j, stage, rating) in rated_stages(model) {
        let (Some(t_max), Some((_, torque_nm))) = (
            rating.max_torque_nm,
            sim.torque_nm.iter().find(|(c, _)| *c == j),
        ) else {
            continue;
        };
        let Some((k, peak_nm)) = torque_nm
            .iter()
            .map(|t| t.abs())
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))
        else {
            continue;
        };
        let s_t = CouplingRating::temperature_factor(stage.temperature_c);
        let load = peak_nm * s_t;
        out.push(StageRating {
            connection: model.connections[j].name.clone(),
            connection_index: j,
            rating: rating.clone(),
            temperature_factor: s_t,
            by_speed: vec![vec![super::check(
                super::CheckKind::MaxTorque,
                reference.get(k).copied().unwrap_or(0.0),
                None,
                load,
                t_max,
            )]],
        });
    }
    out
}

/// The ratings of several operating points (one [`check_simulated`] per regime) as one
/// sweep per stage, points in the order given.
pub fn merge_points(points: Vec<Vec<StageRating>>) -> Vec<StageRating> {
    let mut out: Vec<StageRating> = Vec::new();
    for stage in points.into_iter().flatten() {
        match out
            .iter_mut()
            .find(|s| s.connection_index == stage.connection_index)
        {
            Some(s) => s.by_speed.extend(stage.by_speed),
            None => out.push(stage),
        }
    }
    out
}
