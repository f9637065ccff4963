//! The excitation as written in a model file: `[engine]` (seed 001 eq. 3–5) and
//! `[[harmonic]]` (`spec/model-format.md`), with one extension key: `[engine]
//! pressure_scale = [f1, f2, …]`, a factor per cylinder on its gauge pressure (cylinder
//! imbalance; default all 1).

/// A cylinder pressure curve over one working cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct PressureCurve {
    /// Crank angle from that cylinder's firing TDC, degrees, strictly increasing.
    pub crank_angle_deg: Vec<f64>,
    /// Gauge pressure at each angle, bar.
    pub pressure_bar: Vec<f64>,
}

/// A pressure curve measured at one engine load.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadPressure {
    /// Engine load 0..1.
    pub load: f64,
    /// The curve at that load.
    pub curve: PressureCurve,
}

/// Where the cylinder pressure comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Pressure {
    /// `pressure = {...}`: one curve for every load.
    Single(PressureCurve),
    /// `pressure_by_load = [...]`: curves by load, interpolated in load (sorted by load).
    ByLoad(Vec<LoadPressure>),
}

/// `[engine]`: reciprocating engine excitation (seed 001 eq. 3–5).
#[derive(Debug, Clone, PartialEq)]
pub struct Engine {
    /// One node (all cylinders act on it) or one node per cylinder (crank throws).
    pub at: Vec<String>,
    /// Number of cylinders (≥ 1).
    pub cylinders: u32,
    /// 2 or 4 (default 4).
    pub strokes: u32,
    /// Firing TDC of each cylinder after cylinder 1's, degrees; `None`: evenly spaced.
    pub firing_angles_deg: Option<Vec<f64>>,
    /// Bore `d`, m.
    pub bore_m: f64,
    /// Crank radius `r` (half the stroke), m.
    pub crank_radius_m: f64,
    /// Connecting rod length `l`, centre to centre, m.
    pub conrod_length_m: f64,
    /// `m_p + m_A` of seed 001 eq. 3–4, kg per cylinder (default 0).
    pub reciprocating_mass_kg: f64,
    /// `J0/l²` of seed 001 eq. 3–4, kg (default 0).
    pub rod_inertia_correction_kg: f64,
    /// Cylinder gauge pressure.
    pub pressure: Pressure,
    /// Extension key `pressure_scale`: one factor per cylinder (in cylinder order) on that
    /// cylinder's whole gauge-pressure curve, e.g. `[1, 1, 0.85, 1]` for a third cylinder
    /// firing weaker (cylinder imbalance); `None`: every cylinder 1. Each factor ≥ 0. A
    /// factor scales compression as well as combustion, so a low factor is only a rough
    /// stand-in for a misfire (which still compresses).
    pub pressure_scale: Option<Vec<f64>>,
}

impl Engine {
    /// Crank angle of one working cycle, degrees: 720 for 4-stroke, 360 for 2-stroke.
    pub fn cycle_deg(&self) -> f64 {
        if self.strokes == 2 { 360.0 } else { 720.0 }
    }

    /// Firing angles actually used: the given ones, or evenly spaced over the cycle in
    /// cylinder order (`i · cycle / cylinders`).
    pub fn firing_angles_or_even_deg(&self) -> Vec<f64> {
        match &self.firing_angles_deg {
            Some(angles) => angles.clone(),
            None => {
                let step = self.cycle_deg() / f64::from(self.cylinders);
                (0..self.cylinders).map(|i| f64::from(i) * step).collect()
            }
        }
    }

    /// The pressure factor of cylinder `cylinder` (0-based): `pressure_scale[cylinder]`,
    /// or 1 when the model gives none.
    pub fn pressure_scale_of(&self, cylinder: usize) -> f64 {
        self.pressure_scale
            .as_ref()
            .and_then(|s| s.get(cylinder).copied())
            .unwrap_or(1.0)
    }

    /// The node each cylinder acts on (length `cylinders`).
    pub fn node_of_cylinder(&self, cylinder: usize) -> &str {
        if self.at.len() == 1 {
            &self.at[0]
        } else {
            &self.at[cylinder]
        }
    }
}

/// Amplitude of a prescribed harmonic.
#[derive(Debug, Clone, PartialEq)]
pub enum HarmonicAmplitude {
    /// A constant amplitude, N·m.
    Constant(f64),
    /// Amplitude varying with reference speed: linear interpolation, held at the ends.
    BySpeed {
        /// Reference speeds, rpm, strictly increasing.
        speed_rpm: Vec<f64>,
        /// Amplitudes at those speeds, N·m.
        amplitude_nm: Vec<f64>,
    },
}

/// `[[harmonic]]`: `T = amplitude · cos(order · θ* + phase)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Harmonic {
    /// Node it acts on.
    pub at: String,
    /// Multiple of the reference speed (> 0).
    pub order: f64,
    /// Zero-to-peak amplitude in the node's own shaft.
    pub amplitude: HarmonicAmplitude,
    /// Phase, degrees (default 0).
    pub phase_deg: f64,
}
