//! Watching a run as it goes: [`simulate_observed`](super::simulate_observed) reports
//! [`Event`]s — the fraction done, and the recorded samples in [`Chunk`]s (every 0.5 % of
//! the recording, and the rest at the end) — so a front end can draw the traces while
//! they grow. Concatenated, the chunks are the final [`Simulation`] sample for sample.

use super::run::Simulation;

/// What an observed run reports.
#[derive(Debug, Clone, PartialEq)]
pub enum Event {
    /// Fraction done, 0–1 (settling is the first 10 %).
    Progress(f64),
    /// Samples recorded since the last chunk.
    Chunk(Chunk),
}

/// Consecutive samples of a run's outputs, in the layout of [`Simulation`].
#[derive(Debug, Clone, PartialEq)]
pub struct Chunk {
    /// Index of the first sample in the whole recording.
    pub first_sample: usize,
    /// Samples in the whole recording.
    pub total_samples: usize,
    /// Sample times from the start of recording, s.
    pub time_s: Vec<f64>,
    /// IAS of every node in its own shaft, rpm: `[node][sample]`, model order.
    pub speed_rpm: Vec<Vec<f64>>,
    /// Torque of every connection with an element, own shaft, N·m: `(connection, samples)`.
    pub torque_nm: Vec<(usize, Vec<f64>)>,
    /// Instantaneous power dissipated in every connection with an element, W:
    /// `(connection, samples)`. Their mean over the whole recording is
    /// [`Simulation::power_loss_w`].
    pub power_w: Vec<(usize, Vec<f64>)>,
    /// Temperature of every rubber stage with `thermal`, °C: `(connection, samples)`.
    pub temperature_c: Vec<(usize, Vec<f64>)>,
}

impl Chunk {
    /// Samples in this chunk.
    pub fn len(&self) -> usize {
        self.time_s.len()
    }

    /// True when the chunk holds no sample.
    pub fn is_empty(&self) -> bool {
        self.time_s.is_empty()
    }
}

/// Samples `from..to` of `sim`; `power` holds the instantaneous power of those samples
/// (per element, in the order of `sim.power_loss_w`) and is emptied.
pub(super) fn take_chunk(
    sim: &Simulation,
    from: usize,
    to: usize,
    power: &mut [Vec<f64>],
) -> Chunk {
    let per_connection = |series: &[(usize, Vec<f64>)]| -> Vec<(usize, Vec<f64>)> {
        series
            .iter()
            .map(|(c, v)| (*c, v[from..to].to_vec()))
            .collect()
    };
    Chunk {
        first_sample: from,
        total_samples: sim.time_s.len(),
        time_s: sim.time_s[from..to].to_vec(),
        speed_rpm: sim.speed_rpm.iter().map(|v| v[from..to].to_vec()).collect(),
        torque_nm: per_connection(&sim.torque_nm),
        power_w: sim
            .power_loss_w
            .iter()
            .zip(power.iter_mut())
            .map(|((c, _), p)| (*c, std::mem::take(p)))
            .collect(),
        temperature_c: per_connection(&sim.temperature_c),
    }
}
