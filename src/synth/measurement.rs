//! How the bench measures: stations and their sensors, the output rate, noise, jitter,
//! wobble, artifacts and resolution ([`Measurement`]), checked against the model and plan
//! before anything is simulated; the time stamps of the samples ([`time_stamps`]).

use super::SynthError;
use super::plan::Plan;
use super::station::Station;
use crate::effects::SensorArtifact;
use crate::effects::Truth;
use crate::model::graph;

/// How the bench measures (defaults: [`Measurement::default`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    /// Measured stations; the reference node (crank) must be one.
    pub stations: Vec<Station>,
    /// Output sample rate, Hz (default 2048), unless a planned run gives its own.
    pub rate_hz: f64,
    /// White noise added to every sample (electronics), rpm standard deviation (default
    /// 0.1).
    pub noise_rpm: f64,
    /// Timing jitter of every pulse edge, ns standard deviation (default 20).
    pub jitter_ns: f64,
    /// Wobble of the mean speed, % (default 0.2).
    pub wobble_pct: f64,
    /// Main period of the wobble, s (default 6).
    pub wobble_period_s: f64,
    /// Sensor artifacts (a station may have several).
    pub artifacts: Vec<SensorArtifact>,
    /// Samples are rounded to this, rpm (default 0.01; 0: not rounded).
    pub resolution_rpm: f64,
}

impl Default for Measurement {
    fn default() -> Self {
        Self {
            stations: Vec::new(),
            rate_hz: 2048.0,
            noise_rpm: 0.1,
            jitter_ns: 20.0,
            wobble_pct: 0.2,
            wobble_period_s: 6.0,
            artifacts: Vec::new(),
            resolution_rpm: 0.01,
        }
    }
}

impl Measurement {
    /// A perfect bench: no noise, jitter, wobble, artifacts or rounding.
    pub fn perfect(stations: Vec<Station>, rate_hz: f64) -> Self {
        Self {
            stations,
            rate_hz,
            noise_rpm: 0.0,
            jitter_ns: 0.0,
            wobble_pct: 0.0,
            wobble_period_s: 6.0,
            artifacts: Vec::new(),
            resolution_rpm: 0.0,
        }
    }
}

/// Checks the measurement against the model; returns the reference node's name.
pub(crate) fn check(m: &Measurement, truth: &Truth, plan: &Plan) -> Result<String, SynthError> {
    let model = &truth.model;
    let reference = graph::reference_node(model)
        .map(|r| model.inertias[r].name.clone())
        .ok_or_else(|| SynthError::Input("the model has no reference node".into()))?;
    for s in &m.stations {
        if model.node_index(&s.node).is_none() {
            return Err(SynthError::Input(format!(
                "station `{}` is no node of the model",
                s.node
            )));
        }
    }
    if m.stations.iter().all(|s| s.node != reference) {
        return Err(SynthError::Input(format!(
            "the reference node `{reference}` must be a station (recordings define orders by it)"
        )));
    }
    let artifacts = m.artifacts.iter().chain(&truth.artifact);
    for a in artifacts {
        if m.stations.iter().all(|s| s.node != a.station()) {
            return Err(SynthError::Input(format!(
                "sensor artifact at `{}`, which is not a station",
                a.station()
            )));
        }
    }
    let checks = [
        ("--rate-hz", m.rate_hz, 100.0, 1.0e5),
        ("--noise-rpm", m.noise_rpm, 0.0, 1.0e3),
        ("--jitter-ns", m.jitter_ns, 0.0, 1.0e6),
        ("--wobble-pct", m.wobble_pct, 0.0, 5.0),
        ("--wobble-period-s", m.wobble_period_s, 0.1, 1.0e4),
        ("resolution", m.resolution_rpm, 0.0, 10.0),
    ];
    for (name, v, lo, hi) in checks {
        if !(v.is_finite() && (lo..=hi).contains(&v)) {
            return Err(SynthError::Input(format!(
                "{name} {v}: must be within {lo} … {hi}"
            )));
        }
    }
    for r in &plan.runs {
        if let Some(rate) = r.rate_hz
            && !(100.0..=1.0e5).contains(&rate)
        {
            return Err(SynthError::Input(format!(
                "run `{}`: rate {rate} Hz must be within 100 … 100000",
                r.file
            )));
        }
    }
    Ok(reference)
}

/// `i / rate` for every sample, rounded to the fewest decimals (at most 9) that keep every
/// stamp within 2e-4 of a sample interval of its exact value (order analysis accepts 1e-3).
pub fn time_stamps(samples: usize, rate_hz: f64) -> Vec<f64> {
    let exact: Vec<f64> = (0..samples).map(|i| i as f64 / rate_hz).collect();
    let tolerance = 2e-4 / rate_hz;
    for decimals in 0..=9 {
        let scale = 10f64.powi(decimals);
        let rounded: Vec<f64> = exact.iter().map(|t| (t * scale).round() / scale).collect();
        if rounded
            .iter()
            .zip(&exact)
            .all(|(r, e)| (r - e).abs() <= tolerance)
        {
            return rounded;
        }
    }
    exact
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_stamps_use_few_decimals() {
        let t = time_stamps(5000, 2000.0);
        assert_eq!(t[3], 0.0015);
        assert_eq!(format!("{}", t[4999]), "2.4995");
        let t = time_stamps(5000, 2048.0);
        assert!((t[1] - 1.0 / 2048.0).abs() <= 2e-4 / 2048.0);
        assert_eq!(format!("{}", t[1]), "0.0004883");
    }
}
