//! Natural frequencies and mode shapes ([`undamped`]), damped frequencies and damping
//! ratios ([`damped`]), the Campbell diagram and its crossings ([`campbell`]), where each
//! mode keeps its strain energy ([`energy`]), the exact frequencies of distributed shafts
//! ([`wittrick_williams`]), and how far each rubber stage's causal chain
//! departs from the nominal law at each mode ([`law_deviation`]).

pub mod campbell;
pub mod damped;
pub mod energy;
pub mod law_deviation;
pub mod undamped;
pub mod wittrick_williams;

pub use campbell::{Campbell, Crossing, campbell, critical_speed_rpm, speed_grid};
pub use damped::{DampedMode, damped_modes};
pub use energy::{shares_by_connection, strain_energy_j, strain_energy_shares};
pub use law_deviation::{LawDeviation, law_deviations};
pub use undamped::{Mode, modes};
