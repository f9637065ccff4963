//! How a run is integrated: tolerances, settling, output rate and the integrator
//! ([`RunOptions`]), with the defaults every view of a model shares.

use super::stepper::Method;

/// How to run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunOptions {
    /// Engine load 0..1 (default 1).
    pub load: f64,
    /// Output rate, Hz (default 10240, seed 001's IAS rate).
    pub rate_hz: f64,
    /// Relative tolerance of the integrator (default 1e-5: a linear run then agrees with
    /// the frequency domain within 0.03 %).
    pub rtol: f64,
    /// Cycle-to-cycle change of the speeds, relative to their vibration amplitude, below
    /// which a run counts as settled (default 1e-4; never below 20 × `rtol`, the noise
    /// floor of the integration).
    pub settle_tolerance: f64,
    /// Longest settling time before recording anyway, s (default 60).
    pub max_settle_s: f64,
    /// Shortest settling time, s, whatever the cycle-to-cycle change says (default 0).
    /// The change compares whole states a cycle apart against the largest vibration, so
    /// a start transient of a lightly damped mode at a few 0.1 % of it passes the
    /// tolerance, yet leaks into the orders that an engine hardly excites, where a bench
    /// measures noise (see [`crate::diagnose`]'s forward model, which settles for the
    /// slowest mode's decay).
    pub min_settle_s: f64,
    /// Time the start speed is held after settling and before recording, s, with every
    /// state free, a self-heating rubber's temperature too (default 0). Settling holds
    /// the temperature; a bench holds a regime a while before it records, and a stage at
    /// a resonance warms and detunes meanwhile (benchtruth case 2050: a stage losing
    /// 1 kW at 1020 rpm). The recorded time starts after the hold.
    pub hold_s: f64,
    /// Integrator (default: explicit unless the model is stiff).
    pub method: Method,
    /// Steps per working cycle at the run's highest speed that the integrator must take
    /// at least (default 180: 4° of crank on a four-stroke engine).
    pub min_steps_per_cycle: f64,
    /// Rubber Maxwell arms that relax faster than this, Hz, run as their low-frequency
    /// limit, a dashpot ([`crate::rubber::MaxwellChain::take_fast_arms`]; default `None`:
    /// every arm is integrated). For runs of which only frequencies below a third of it
    /// matter: the fastest arms bound the explicit integrator's step.
    pub viscous_above_hz: Option<f64>,
    /// Step budget: by simulated time `t` the run may take at most this × `(t / h_max +
    /// 1000)` steps, `h_max` the largest step [`RunOptions::min_steps_per_cycle`] allows;
    /// a run beyond it stops with [`super::TransientError::StepBudget`], which names the element
    /// holding it back (default `None`: [`crate::limits::Limits::step_budget_factor`], 200;
    /// well-posed runs take 1–3×).
    pub step_budget_factor: Option<f64>,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            load: 1.0,
            rate_hz: 10240.0,
            rtol: 1e-5,
            settle_tolerance: 1e-4,
            max_settle_s: 60.0,
            min_settle_s: 0.0,
            hold_s: 0.0,
            method: Method::Auto,
            min_steps_per_cycle: 180.0,
            viscous_above_hz: None,
            step_budget_factor: None,
        }
    }
}
