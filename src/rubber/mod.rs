//! The one causal representation of a rubber stage that every analysis of a model uses
//! (issue 15, `spec/model-format.md` `kind = "rubber"`): modes, damped modes, Campbell,
//! forced response, `compare`, the time domain, `synth` and the diagnosis.
//!
//! - [`chain`]: the generalized Maxwell chain and its fit to seed 000's law (α_f, ψ) at
//!   the model's modes and over its band;
//! - [`band`]: the band of excited frequencies a model's orders span over its speed range;
//! - `chain_cache`: fits remembered by what they depend on, bit for bit;
//! - `nnls`: the non-negative least squares the fit solves.

pub mod band;
pub mod chain;
mod chain_cache;
mod nnls;

pub use band::{DEFAULT_SPEED_RANGE_RPM, law_band_hz, law_speed_range_rpm};
pub use chain::{MaxwellChain, ModeTarget};
