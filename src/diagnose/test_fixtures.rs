//! Hand-made analysed recordings for the diagnosis' unit tests: one [`Run`] and one
//! [`Observation`] with every field a test does not care about at a plain value, so that
//! a test names only what it is about (struct update syntax for the rest).

use super::observe::{Observation, Run, RunShape};

/// A run `label` of shape `regime` at full load, measured at `station` (also its
/// reference), 1 s at 2048 Hz, without STFT windows or cycle speeds.
pub fn run(label: &str, regime: RunShape, station: &str) -> Run {
    Run {
        label: label.into(),
        regime,
        load: 1.0,
        duration_s: 1.0,
        rate_hz: 2048.0,
        reference: station.into(),
        stations: vec![station.into()],
        window_speeds_rpm: Vec::new(),
        window_times_s: Vec::new(),
        lines_per_rev: vec![None],
        cycle_speeds_rpm: Vec::new(),
    }
}

/// Order `order` of run `run`'s part `part` at `station`: 1 rpm measured at 1000 rpm and
/// 0.5 s, with σ = 0.1 rpm for noise and bias.
pub fn observation(run: usize, part: usize, station: &str, order: f64) -> Observation {
    Observation {
        run,
        part,
        station: station.into(),
        order,
        speed_rpm: 1000.0,
        time_s: 0.5,
        measured_rpm: 1.0,
        sigma_rpm: 0.1,
        bias_sigma_rpm: 0.1,
    }
}
