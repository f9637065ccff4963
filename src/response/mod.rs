//! Frequency domain: steady forced response order by order over a speed sweep
//! ([`sweep`]), the amplitudes alone for the diagnosis' surrogate ([`amplitudes`]), and
//! the synthesized peak torque over a cycle ([`peak`]).

pub mod amplitudes;
pub(crate) mod lu;
pub mod peak;
mod point;
pub mod sweep;
mod tree;

pub use amplitudes::{OrderAmplitudes, order_amplitudes};
pub use sweep::{Response, forced_response, forced_response_orders};

#[cfg(test)]
mod tests;
