//! `[load]`, `[operation]` and `[expect]` as written in a model file.

/// `[load]`: what holds the mean speed.
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    /// Node that takes the mean torque; `None`: the last node.
    pub at: Option<String>,
    /// Extra damping on vibration of that node, N·m·s/rad (default 0).
    pub damping_nm_s_per_rad: f64,
}

/// `[operation]`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Operation {
    /// `[min, max]` for sweeps and Campbell diagrams, rpm of the reference node.
    pub speed_range_rpm: Option<[f64; 2]>,
    /// `[min, max]` band where resonances are not allowed, rpm.
    pub operating_range_rpm: Option<[f64; 2]>,
    /// Orders to draw and sum; `None`: all multiples of 0.5 up to 12 (4-stroke) or of 1
    /// up to 12 (2-stroke).
    pub orders: Option<Vec<f64>>,
    /// Named steady regimes (extension key `regimes`), e.g. seed 001's A–F: what
    /// `torsim compare` runs by default.
    pub regimes: Vec<Regime>,
}

/// A named steady operating point, `{ label = "A", speed_rpm = 3000, load = 1 }`.
#[derive(Debug, Clone, PartialEq)]
pub struct Regime {
    /// Name, e.g. `A` or `Regime A`.
    pub label: String,
    /// Mean speed of the reference node, rpm.
    pub speed_rpm: f64,
    /// Engine load 0..1 (default 1).
    pub load: f64,
}

/// `[expect]`: checks for `torsim check`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Expect {
    /// Mode k (from 1, rigid-body modes not counted) lies in `[min, max]` Hz.
    pub mode_hz: Vec<ModeExpectation>,
    /// The q-th order line crosses some mode in `[min, max]` rpm.
    pub critical_rpm: Vec<CriticalExpectation>,
    /// Orders that must cross no mode inside `operating_range_rpm`.
    pub no_resonance_in_operating_range: Vec<f64>,
    /// Rated rubber stages (connection names) that must stay within every rating over
    /// the operating range, else the speed range, at full load (issue 16,
    /// [`crate::ratings`]).
    pub within_ratings: Vec<String>,
}

impl Expect {
    /// True when the model has no checks at all.
    pub fn is_empty(&self) -> bool {
        self.mode_hz.is_empty()
            && self.critical_rpm.is_empty()
            && self.no_resonance_in_operating_range.is_empty()
            && self.within_ratings.is_empty()
    }
}

/// `{ mode = k, min = a, max = b }` in `[expect] mode_hz`.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeExpectation {
    /// Mode number, from 1.
    pub mode: u32,
    /// Lower bound, Hz.
    pub min_hz: f64,
    /// Upper bound, Hz.
    pub max_hz: f64,
}

/// `{ order = q, min = a, max = b }` in `[expect] critical_rpm`.
#[derive(Debug, Clone, PartialEq)]
pub struct CriticalExpectation {
    /// Engine order.
    pub order: f64,
    /// Lower bound, rpm.
    pub min_rpm: f64,
    /// Upper bound, rpm.
    pub max_rpm: f64,
}
