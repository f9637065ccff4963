//! Where a rubber bank (`visco.rs`) is fitted: the band of the model's excitation and the
//! modes of the nominal system with each rubber stage's share of their strain energy
//! (model-format.md `kind = "rubber"`: the causal representation belongs to the model,
//! "fitted to reproduce [the law] where the model's modes and excited orders lie").
//!
//! The band is the model's, the same for every recording: from a quarter of the lowest
//! order at the lowest speed of `[operation] speed_range_rpm` to 1.5 × the highest order
//! at the highest speed. The bench writes no `orders`, regimes or harmonics into its model
//! files, so the orders are the default ones of a four-stroke engine, 0.5 … 12.
//! The modes are those of the stage's own driveline at the recording's load, each rubber
//! stage at its tangent stiffness at the static twist times its frequency factor at the
//! mode's own frequency (found by fixed-point iteration, mode by mode).

use crate::campaign::Campaign;
use crate::driveline::{Driveline, Kind};
use crate::plant::Band;

/// Lowest order of the model's default excitation (four-stroke half orders).
const ORDER_MIN: f64 = 0.5;
/// Highest order of the model's default excitation.
const ORDER_MAX: f64 = 12.0;
/// Lowest band edge, Hz.
const MIN_BAND_HZ: f64 = 0.1;
/// Fixed-point iterations on a mode's frequency when the stiffness depends on it.
const FIXED_POINT_ITERATIONS: usize = 100;

/// The speed range the model file declares, rpm: every recording's speeds taken in
/// (what `write.rs` writes as `[operation] speed_range_rpm`).
pub fn speed_range_rpm(campaign: &Campaign) -> (f64, f64) {
    campaign
        .recordings
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), r| {
            (
                lo.min(r.from_rpm.min(r.to_rpm)),
                hi.max(r.from_rpm.max(r.to_rpm)),
            )
        })
}

/// The model's band over `[lo_rpm, hi_rpm]`, Hz: `lo = max(¼·q_min·n_min/60, 0.1)`,
/// `hi = max(1.5·q_max·n_max/60, 4·lo)`.
pub fn model_band(lo_rpm: f64, hi_rpm: f64) -> Band {
    let lo_hz = (0.25 * ORDER_MIN * lo_rpm / 60.0).max(MIN_BAND_HZ);
    Band {
        lo_hz,
        hi_hz: (1.5 * ORDER_MAX * hi_rpm / 60.0).max(4.0 * lo_hz),
    }
}

/// A mode a bank is fitted at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeShare {
    /// Natural frequency, Hz.
    pub f_hz: f64,
    /// The stage's share of the mode's strain energy, 0…1.
    pub share: f64,
}

/// Strain energy of each connection in mode `m` of `d` with connection stiffnesses
/// scaled by `scale`, J per unit modal amplitude (mass-normalised shapes).
fn strain_energies(d: &Driveline, shape: &[f64], scale: &dyn Fn(usize) -> f64) -> Vec<f64> {
    d.connections
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let twist = c.lever() * shape[c.from] - shape[c.to];
            0.5 * c.stiffness() * scale(i) * twist * twist
        })
        .collect()
}

/// Every mode of `d` with every connection's share of its strain energy:
/// `result[mode] = (f_hz, shares by connection)`. `scale(i, f)` is connection `i`'s
/// stiffness factor at `f` Hz (1 for shafts and gears; for a rubber stage its tangent
/// factor at the static twist times its frequency factor); each mode's frequency is the
/// fixed point of its own stiffness.
pub fn modes_with_shares(d: &Driveline, scale: &dyn Fn(usize, f64) -> f64) -> Vec<(f64, Vec<f64>)> {
    let base = d.modes();
    let count = base.freq_hz.len();
    (0..count)
        .map(|m| {
            let mut f = base.freq_hz[m];
            let mut modes = d.modes_scaled(|i| scale(i, f));
            for _ in 0..FIXED_POINT_ITERATIONS {
                let next = modes.freq_hz.get(m).copied().unwrap_or(f);
                let done = (next - f).abs() <= 1e-12 * f.abs().max(1e-300);
                f = next;
                if done {
                    break;
                }
                modes = d.modes_scaled(|i| scale(i, f));
            }
            let shape: Vec<f64> = modes.shapes.column(m).iter().copied().collect();
            let energies = strain_energies(d, &shape, &|i| scale(i, f));
            let total: f64 = energies.iter().sum();
            let shares = if total > 0.0 {
                energies.iter().map(|e| e / total).collect()
            } else {
                vec![0.0; energies.len()]
            };
            (f, shares)
        })
        .collect()
}

/// The modes of `all` (from [`modes_with_shares`]) as connection `conn` sees them.
pub fn for_connection(all: &[(f64, Vec<f64>)], conn: usize) -> Vec<ModeShare> {
    all.iter()
        .map(|(f, s)| ModeShare {
            f_hz: *f,
            share: s.get(conn).copied().unwrap_or(0.0),
        })
        .collect()
}

/// The mean torque each connection carries under the engine's mean torque `t_mean` (N·m,
/// at the connection's `to` side), the load node held: the linear static solution, whose
/// torques on the bench's tree-shaped drivelines do not depend on the stiffnesses.
pub fn static_torques(d: &Driveline, t_mean: f64) -> Vec<f64> {
    let x = d.static_angles(t_mean);
    d.connections
        .iter()
        .map(|c| c.stiffness() * (c.lever() * x[c.from] - x[c.to]))
        .collect()
}

/// Whether connection `i` of `d` is a rubber stage.
pub fn is_rubber(d: &Driveline, i: usize) -> bool {
    matches!(d.connections[i].kind, Kind::Rubber { .. })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_band_is_the_models_default_orders_over_its_speed_range() {
        // ¼·0.5·600/60 = 1.25 Hz; 1.5·12·2400/60 = 720 Hz.
        let b = model_band(600.0, 2400.0);
        assert!((b.lo_hz - 1.25).abs() < 1e-12 && (b.hi_hz - 720.0).abs() < 1e-12);
        // the floor of 0.1 Hz and hi ≥ 4·lo
        let b = model_band(10.0, 10.0);
        assert!((b.lo_hz - 0.1).abs() < 1e-12 && (b.hi_hz - 3.0).abs() < 1e-12);
    }

    #[test]
    fn shares_sum_to_one_and_follow_a_frequency_dependent_stiffness() {
        let case = crate::draw::draw_case(0, Some("none")).expect("case");
        let d = &case.truth;
        let all = modes_with_shares(d, &|_, _| 1.0);
        assert_eq!(all.len(), d.nodes.len() - 1);
        for (f, s) in &all {
            assert!(*f > 0.0);
            assert!((s.iter().sum::<f64>() - 1.0).abs() < 1e-9);
        }
        // A rubber twice as stiff at every frequency above 0 raises the modes it holds.
        let stiffer = modes_with_shares(d, &|i, f| {
            if is_rubber(d, i) && f > 0.0 { 2.0 } else { 1.0 }
        });
        assert!(stiffer[0].0 > all[0].0 * 1.01);
    }
}
