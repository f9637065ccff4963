//! # torsim — torsional vibration of engine drivelines with rubber couplings
//!
//! The library has no GUI and prints nothing; the `torsim` binary (CLI and GUI) is a thin
//! front end on it.
//!
//! - [`model`]: the driveline as the user writes it, model files, validation, the rubber
//!   coupling law of seed 000.
//! - [`physics`]: the linear system at an operating point — M, K(f), C referred to the
//!   engine shaft through the gear tree — and the engine excitation of seed 001 eq. 3–5.
//! - [`modal`]: natural frequencies, mode shapes, damped modes, the Campbell diagram.
//! - [`response`]: steady forced response order by order over a speed sweep.
//! - [`check`]: the `[expect]` checks of presets.

#![warn(missing_docs)]

pub mod check;
pub mod modal;
pub mod model;
pub mod physics;
pub mod response;
