//! Design variants side by side (seed 001 §3.6, Tables 9–13): for each steady regime, the
//! irregularity ratio of every station and the power loss of every rubber stage, from a
//! nonlinear steady run and its order analysis; and every rated stage's coupling ratings
//! at each regime ([`crate::ratings::check_simulated`]).

use crate::model::{ConnectionKind, Model};
use crate::ratings::{StageRating, check_simulated, merge_points};
use crate::recording::Run;
use crate::signal::{AnalysisOptions, SignalError, analyse_with};
use crate::transient::{RunOptions, TransientError, simulate, to_recording};

/// A steady operating point to compare at.
#[derive(Debug, Clone, PartialEq)]
pub struct RegimePoint {
    /// Name shown in tables (e.g. `A`, or the speed).
    pub label: String,
    /// Mean speed of the reference node, rpm.
    pub speed_rpm: f64,
    /// Engine load 0..1.
    pub load: f64,
}

/// The model's own `[operation] regimes`, as points to compare at.
pub fn model_regimes(model: &Model) -> Vec<RegimePoint> {
    model
        .operation
        .regimes
        .iter()
        .map(|r| RegimePoint {
            label: r.label.clone(),
            speed_rpm: r.speed_rpm,
            load: r.load,
        })
        .collect()
}

/// One variant's results over the regimes.
#[derive(Debug, Clone, PartialEq)]
pub struct VariantResult {
    /// The regimes, in order.
    pub regimes: Vec<RegimePoint>,
    /// Node names.
    pub nodes: Vec<String>,
    /// `irregularity_pct[node][regime]`: peak-to-peak IAS of the averaged cycle over the
    /// mean speed, % (seed 001's IR).
    pub irregularity_pct: Vec<Vec<f64>>,
    /// `rms_rpm[node][regime]`: RMS of the IAS about its mean, rpm.
    pub rms_rpm: Vec<Vec<f64>>,
    /// Rubber stage names.
    pub stages: Vec<String>,
    /// `power_loss_w[stage][regime]`: mean power dissipated in the stage, W.
    pub power_loss_w: Vec<Vec<f64>>,
    /// The rated stages' checks, one point per regime (empty without ratings).
    pub ratings: Vec<StageRating>,
}

/// Why a comparison could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CompareError {
    /// A run failed.
    #[error("regime {label}: {source}")]
    Run {
        /// Regime label.
        label: String,
        /// The error.
        source: TransientError,
    },
    /// The analysis of a run failed.
    #[error("regime {label}: {source}")]
    Analysis {
        /// Regime label.
        label: String,
        /// The error.
        source: SignalError,
    },
}

/// Runs `model` at every regime for `duration_s` each; `progress` gets the fraction done.
pub fn compare_regimes(
    model: &Model,
    regimes: &[RegimePoint],
    duration_s: f64,
    options: RunOptions,
    progress: &mut dyn FnMut(f64) -> bool,
) -> Result<VariantResult, CompareError> {
    let stage_connections: Vec<usize> = model
        .connections
        .iter()
        .enumerate()
        .filter(|(_, c)| matches!(c.kind, ConnectionKind::Rubber(_)))
        .map(|(j, _)| j)
        .collect();
    let nodes: Vec<String> = model.inertias.iter().map(|n| n.name.clone()).collect();
    let mut result = VariantResult {
        regimes: regimes.to_vec(),
        irregularity_pct: vec![Vec::new(); nodes.len()],
        rms_rpm: vec![Vec::new(); nodes.len()],
        stages: stage_connections
            .iter()
            .map(|&j| model.connections[j].name.clone())
            .collect(),
        power_loss_w: vec![Vec::new(); stage_connections.len()],
        ratings: Vec::new(),
        nodes,
    };
    let mut rated = Vec::new();
    let count = regimes.len().max(1) as f64;
    for (i, regime) in regimes.iter().enumerate() {
        let kind = Run::steady(regime.speed_rpm, duration_s);
        let run_options = RunOptions {
            load: regime.load,
            ..options
        };
        let mut inner = |f: f64| progress((i as f64 + f) / count);
        let sim =
            simulate(model, kind, run_options, &mut inner).map_err(|source| CompareError::Run {
                label: regime.label.clone(),
                source,
            })?;
        let recording = to_recording(&sim, kind, regime.load, model.strokes(), &model.name);
        let analysis = analyse_with(&recording, &AnalysisOptions::default()).map_err(|source| {
            CompareError::Analysis {
                label: regime.label.clone(),
                source,
            }
        })?;
        for (k, node) in result.nodes.iter().enumerate() {
            let station = analysis.stations.iter().find(|s| &s.name == node);
            result.irregularity_pct[k].push(station.map_or(f64::NAN, |s| s.irregularity_pct));
            result.rms_rpm[k].push(station.map_or(f64::NAN, |s| s.rms_rpm));
        }
        for (s, &j) in stage_connections.iter().enumerate() {
            let w = sim
                .power_loss_w
                .iter()
                .find(|(c, _)| *c == j)
                .map_or(0.0, |(_, w)| *w);
            result.power_loss_w[s].push(w);
        }
        rated.push(
            check_simulated(model, &sim, regime.speed_rpm).map_err(|source| {
                CompareError::Analysis {
                    label: regime.label.clone(),
                    source,
                }
            })?,
        );
    }
    result.ratings = merge_points(rated);
    Ok(result)
}
