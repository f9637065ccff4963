//! The Campbell diagram: every mode's frequency over speed, the order lines `f = q·n/60`
//! and their crossings.
//!
//! The linear model's stiffness depends on the operating point (load, temperature) and on
//! the vibration frequency, not on speed, so each mode is a horizontal line found once;
//! crossings are located by the sign change of `f_mode(n) − q·n/60` between grid speeds
//! and interpolated linearly in rpm (exact for horizontal lines).

use super::energy::strain_energy_shares;
use super::undamped::{Mode, modes};
use crate::physics::{PhysicsError, System};

/// A crossing of an order line with a mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// Engine order q.
    pub order: f64,
    /// Mode number, from 1.
    pub mode: usize,
    /// Reference speed of the crossing, rpm.
    pub speed_rpm: f64,
    /// Frequency at the crossing, Hz.
    pub frequency_hz: f64,
}

/// A Campbell diagram over a speed grid.
#[derive(Debug, Clone, PartialEq)]
pub struct Campbell {
    /// Reference speeds, rpm.
    pub speeds_rpm: Vec<f64>,
    /// Orders drawn.
    pub orders: Vec<f64>,
    /// `frequency_hz[mode][speed]`, Hz.
    pub frequency_hz: Vec<Vec<f64>>,
    /// The modes (shapes at their own frequency).
    pub modes: Vec<Mode>,
    /// `strain_energy_share[mode][element]`: share of each mode's strain energy in each
    /// element of the system (element order; see [`super::energy`]), 0…1.
    pub strain_energy_share: Vec<Vec<f64>>,
    /// Every crossing inside the speed grid, sorted by speed.
    pub crossings: Vec<Crossing>,
}

/// Speeds from `from_rpm` to `to_rpm` in steps of `step_rpm` (the last one included).
pub fn speed_grid(from_rpm: f64, to_rpm: f64, step_rpm: f64) -> Vec<f64> {
    let valid = step_rpm > 0.0 && to_rpm >= from_rpm;
    if !valid {
        return vec![from_rpm];
    }
    let count = ((to_rpm - from_rpm) / step_rpm + 1e-9).floor() as usize;
    let mut grid: Vec<f64> = (0..=count)
        .map(|i| from_rpm + i as f64 * step_rpm)
        .collect();
    if to_rpm - grid[grid.len() - 1] > 1e-9 * step_rpm.max(1.0) {
        grid.push(to_rpm);
    }
    grid
}

/// The Campbell diagram of `system` over `speeds_rpm` for `orders`.
pub fn campbell(
    system: &System,
    speeds_rpm: &[f64],
    orders: &[f64],
) -> Result<Campbell, PhysicsError> {
    let modes = modes(system)?;
    let frequency_hz: Vec<Vec<f64>> = modes
        .iter()
        .map(|m| vec![m.frequency_hz; speeds_rpm.len()])
        .collect();
    let mut crossings = Vec::new();
    for &order in orders {
        for (m, line) in frequency_hz.iter().enumerate() {
            let gap = |i: usize| line[i] - order * speeds_rpm[i] / 60.0;
            for i in 0..speeds_rpm.len() {
                let g0 = gap(i);
                let hit = if g0 == 0.0 {
                    Some(speeds_rpm[i])
                } else if i + 1 < speeds_rpm.len() && g0 * gap(i + 1) < 0.0 {
                    let g1 = gap(i + 1);
                    let t = g0 / (g0 - g1);
                    Some(speeds_rpm[i] + t * (speeds_rpm[i + 1] - speeds_rpm[i]))
                } else {
                    None
                };
                if let Some(rpm) = hit {
                    crossings.push(Crossing {
                        order,
                        mode: m + 1,
                        speed_rpm: rpm,
                        frequency_hz: order * rpm / 60.0,
                    });
                }
            }
        }
    }
    crossings.sort_by(|a, b| a.speed_rpm.total_cmp(&b.speed_rpm));
    let strain_energy_share = modes
        .iter()
        .map(|m| strain_energy_shares(system, m))
        .collect();
    Ok(Campbell {
        speeds_rpm: speeds_rpm.to_vec(),
        orders: orders.to_vec(),
        frequency_hz,
        modes,
        strain_energy_share,
        crossings,
    })
}

/// Speed at which order `order` excites a mode of frequency `frequency_hz`, rpm.
pub fn critical_speed_rpm(order: f64, frequency_hz: f64) -> f64 {
    60.0 * frequency_hz / order
}
