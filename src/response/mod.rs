//! Frequency domain: steady forced response order by order over a speed sweep
//! ([`sweep`]) and the synthesized peak torque over a cycle ([`peak`]).

pub(crate) mod lu;
pub mod peak;
pub mod sweep;
mod tree;

pub use sweep::{Response, forced_response, forced_response_orders};

#[cfg(test)]
mod tests;
