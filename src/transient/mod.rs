//! Time domain: the nonlinear driveline integrated in time (seed 001 eq. 3–6 with the
//! rubber law of seed 000), steady runs and run-ups.
//!
//! - [`plant`]: the state layout and constants of a run; [`forces`]: the equations of
//!   motion — crank-angle-dependent engine inertia, secant rubber stiffness with a causal
//!   Maxwell chain ([`crate::rubber`]) and self-heating, gear backlash (hard or softened contact:
//!   `dead_zone`), a speed governor on the rigid-body motion of a free driveline;
//! - [`dopri`]: Dormand–Prince 5(4) with error control and dense output;
//! - [`run`]: settling cycle by cycle (`settle`), then recording a steady run or a ramp
//!   ([`speed`]); [`observe`]: the run reported in chunks while it goes;
//! - [`validate`]: what a run may ask for, checked against [`crate::limits`] before
//!   anything is allocated; [`budget`]: the step budget that stops a run which would not
//!   end, the state check that stops one which diverges, and the element named when a
//!   step collapses or the budget runs out.

pub mod budget;
mod crank_angle;
mod crank_remainder;
pub mod dopri;
mod error;
pub mod exact;
mod exact_step;
mod export;
pub mod forces;
pub mod measured_speed;
pub mod observe;
mod periodic_start;
pub mod plant;
mod pressure;
mod record;
pub mod ros2;
pub mod run;
mod run_options;
mod settle;
pub mod speed;
mod start;
pub mod stepper;
pub mod validate;

pub use error::TransientError;
pub use export::to_recording;
pub use measured_speed::MeasuredSpeed;
pub use observe::{Chunk, Event};
pub use run::{
    RunOptions, Simulation, simulate, simulate_along, simulate_observed, simulate_observed_along,
};
pub use settle::Settling;
pub use speed::SpeedProfile;
pub use stepper::Method;
