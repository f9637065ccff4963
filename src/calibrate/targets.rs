//! What a calibration must reproduce, and its value for a model: natural frequencies
//! from [`modes`], irregularity ratios from the forced response's synthesized waveform
//! (`IR = 2·(half peak-to-peak IAS) / mean speed · 100 %` in the station's own shaft, the
//! frequency-domain twin of what `compare` measures in the time domain; seed 001 §3.5).

use crate::modal::modes;
use crate::model::Model;
use crate::physics::{Excitation, OperatingPoint, System};
use crate::response::forced_response;

/// What the calibrated model must reproduce.
#[derive(Debug, Clone, PartialEq)]
pub enum Target {
    /// Natural frequency of flexible mode `mode` (from 1), Hz, within `tolerance_pct`
    /// (one standard deviation of the residual, %).
    ModeHz {
        /// Mode number, from 1 (rigid-body modes not counted).
        mode: usize,
        /// Target, Hz.
        hz: f64,
        /// Relative tolerance, %.
        tolerance_pct: f64,
    },
    /// Irregularity ratio of `station` at regime `regime` (a label of `[operation]
    /// regimes`), %, within `tolerance_pct` of itself.
    Irregularity {
        /// Node name.
        station: String,
        /// Regime label.
        regime: String,
        /// Target IR, %.
        pct: f64,
        /// Relative tolerance, %.
        tolerance_pct: f64,
    },
}

impl Target {
    pub(super) fn tolerance_pct(&self) -> f64 {
        match self {
            Self::ModeHz { tolerance_pct, .. } | Self::Irregularity { tolerance_pct, .. } => {
                *tolerance_pct
            }
        }
    }

    pub(super) fn value(&self) -> f64 {
        match self {
            Self::ModeHz { hz, .. } => *hz,
            Self::Irregularity { pct, .. } => *pct,
        }
    }
}

/// The value of every target for `model`, in target order (Hz or %); `None` where the
/// model cannot be evaluated (a mode or a regime it does not have, a failed build).
pub fn evaluate(model: &Model, targets: &[Target]) -> Option<Vec<f64>> {
    let system = System::new(model, OperatingPoint::default()).ok()?;
    let needs_modes = targets.iter().any(|t| matches!(t, Target::ModeHz { .. }));
    let found = if needs_modes {
        modes(&system).ok()?
    } else {
        Vec::new()
    };
    let regimes = &model.operation.regimes;
    let speeds: Vec<f64> = regimes.iter().map(|r| r.speed_rpm).collect();
    let needs_ir = targets
        .iter()
        .any(|t| matches!(t, Target::Irregularity { .. }));
    let response = if needs_ir {
        let excitation = Excitation::new(model, &system, 1.0, &model.orders());
        Some(forced_response(&system, &excitation, &speeds).ok()?)
    } else {
        None
    };
    targets
        .iter()
        .map(|t| match t {
            Target::ModeHz { mode, .. } => found.get(mode.checked_sub(1)?).map(|m| m.frequency_hz),
            Target::Irregularity {
                station, regime, ..
            } => {
                let node = system.node_names.iter().position(|n| n == station)?;
                let s = regimes.iter().position(|r| &r.label == regime)?;
                let mean_rpm = (speeds[s] * system.speed_ratio[node]).abs();
                let half = response.as_ref()?.ias_half_peak_to_peak_rpm[node][s];
                Some(200.0 * half / mean_rpm)
            }
        })
        .collect()
}
