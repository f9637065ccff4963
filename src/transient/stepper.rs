//! The integrator a run uses: the exact discretization for linear models in steady runs
//! ([`super::exact`]), Dormand–Prince for ordinary models, ROS2 for stiff ones.

use super::TransientError;
use super::dopri::Dopri5;
use super::exact::Exact;
use super::ros2::Ros2;

/// Which integrator to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// The exact discretization where it applies (a steady run of a model without an
    /// engine whose equations are affine, [`super::exact`]); else Dormand–Prince 5(4)
    /// unless the model is stiff (see [`is_stiff`]).
    #[default]
    Auto,
    /// The exact discretization ([`super::exact`]); a run it does not apply to is refused.
    Exact,
    /// Dormand–Prince 5(4).
    Explicit,
    /// ROS2, linearly implicit, L-stable.
    Implicit,
}

/// True when ROS2 would take fewer steps than Dormand–Prince: the fastest eigenvalue
/// `λ_max` (rad/s) times the largest step the excitation allows, `h_max`, exceeds
/// `90·(10⁻⁴/rtol)^{1/3}` (90 at the diagnosis' rtol 10⁻⁴, 194 at the CLI's 10⁻⁵).
///
/// Dormand–Prince is stable to `λh ≈ 3.3`; held there by its error control it steps
/// `h ≈ 1.75/λ` with its rejections (measured: benchtruth case 2016's hysteretic candidate,
/// λ = 67 350 rad/s, 1.13 M steps over 29.3 s and its settling). ROS2 is stable at any
/// step but of order 2, so its accuracy holds it to about `h_max/50` at rtol 10⁻⁴ (3.0 M
/// steps on the same run), and `h ∝ rtol^{1/3}` below it; a ROS2 step costs about what a
/// Dormand–Prince step does (3 right-hand sides and 2 solves against 6 right-hand sides).
/// Until 2026-12-04 the threshold was `λh_max > 20`, where stability alone would hold
/// Dormand–Prince back. Forced on every shipped preset at 1500 rpm, ROS2 takes 6–66× the
/// steps of Dormand–Prince; under that rule `genset-20dof` (λh_max = 25) ran on ROS2, 12×
/// slower, and the diagnosis of case 2016 spent 53 % of its time in ROS2 (35.0 s → 20.6 s).
pub fn is_stiff(lambda_max_rad_s: f64, h_max_s: f64, rtol: f64) -> bool {
    let threshold = 90.0 * (1e-4 / rtol.max(1e-14)).cbrt();
    lambda_max_rad_s * h_max_s > threshold
}

/// An integrator in use.
pub enum Stepper {
    /// Dormand–Prince.
    Explicit(Dopri5),
    /// ROS2.
    Implicit(Ros2),
    /// Exact discretization of a linear plant.
    Exact(Box<Exact>),
}

impl Stepper {
    /// Current time, s.
    pub fn t(&self) -> f64 {
        match self {
            Stepper::Explicit(s) => s.t,
            Stepper::Implicit(s) => s.t,
            Stepper::Exact(s) => s.t,
        }
    }

    /// Current state.
    pub fn y(&self) -> &[f64] {
        match self {
            Stepper::Explicit(s) => &s.y,
            Stepper::Implicit(s) => &s.y,
            Stepper::Exact(s) => s.y(),
        }
    }

    /// Accepted and rejected steps.
    pub fn steps(&self) -> (u64, u64) {
        match self {
            Stepper::Explicit(s) => s.steps,
            Stepper::Implicit(s) => s.steps,
            Stepper::Exact(s) => s.steps,
        }
    }

    /// The step size it would try next, s.
    pub fn h(&self) -> f64 {
        match self {
            Stepper::Explicit(s) => s.h,
            Stepper::Implicit(s) => s.h,
            Stepper::Exact(s) => s.h,
        }
    }

    /// The state whose error held the step back last ([`Dopri5::worst_state`]).
    pub fn worst_state(&self) -> usize {
        match self {
            Stepper::Explicit(s) => s.worst_state,
            Stepper::Implicit(s) => s.worst_state,
            Stepper::Exact(_) => 0,
        }
    }

    /// True when it chooses its step by an error estimate (and so can take more steps
    /// than a run's budget allows); the exact integrator steps a fixed `h`.
    pub fn adapts_step(&self) -> bool {
        !matches!(self, Stepper::Exact(_))
    }

    /// True for the explicit method.
    pub fn is_explicit(&self) -> bool {
        matches!(self, Stepper::Explicit(_))
    }

    /// One accepted step, not beyond `t_end`.
    pub fn step<F: FnMut(f64, &[f64], &mut [f64])>(
        &mut self,
        t_end: f64,
        rhs: &mut F,
    ) -> Result<(), TransientError> {
        match self {
            Stepper::Explicit(s) => s.step(t_end, rhs),
            Stepper::Implicit(s) => s.step(t_end, rhs),
            Stepper::Exact(s) => s.step(t_end),
        }
    }

    /// The state at `t` within the last step: the integrator's own state when `t` is the
    /// exact integrator's step end (where all its samples fall: no copy), else the dense
    /// output written into `scratch`.
    pub fn state_at<'a>(&'a self, t: f64, scratch: &'a mut [f64]) -> &'a [f64] {
        match self {
            Stepper::Exact(s) if s.is_at_end(t) => s.y(),
            _ => {
                self.interpolate(t, scratch);
                scratch
            }
        }
    }

    /// Dense output at `t` within the last step.
    pub fn interpolate(&self, t: f64, out: &mut [f64]) {
        match self {
            Stepper::Explicit(s) => s.interpolate(t, out),
            Stepper::Implicit(s) => s.interpolate(t, out),
            Stepper::Exact(s) => s.interpolate(t, out),
        }
    }
}
