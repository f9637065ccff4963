//! Natural frequencies and mode shapes ([`undamped`]), damped frequencies and damping
//! ratios ([`damped`]), the Campbell diagram and its crossings ([`campbell`]).

pub mod campbell;
pub mod damped;
pub mod undamped;

pub use campbell::{Campbell, Crossing, campbell, critical_speed_rpm, speed_grid};
pub use damped::{DampedMode, damped_modes};
pub use undamped::{Mode, modes};
