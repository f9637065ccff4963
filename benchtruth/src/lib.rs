//! benchtruth: an independent test bench for torsim's diagnosis (issue 14, items 3–4).
//!
//! It draws a driveline, a concealed effect and a measurement campaign from a seed,
//! integrates the truth with its own RK4 integrator and its own effect laws, and writes
//! what a test engineer hands over: the user's nominal model (model-format.md) and the
//! recordings (recording-format.md), plus `truth.toml` that only the scorer reads. It
//! reaches torsim only through files and the `torsim diagnose` command; it does not
//! depend on the torsim crate (checked by `tests/independence.rs`).

pub mod bench;
pub mod campaign;
pub mod draw;
pub mod driveline;
pub mod effects;
pub mod engine;
pub mod exercise;
pub mod fitpoints;
pub mod integrate;
pub mod model_file;
pub mod nnls;
pub mod order_meter;
pub mod plant;
pub mod redraw;
pub mod rng;
pub mod sim;
pub mod sizing;
pub mod truth_file;
pub mod twin;
pub mod visco;
pub mod visibility;
pub mod write;

pub use bench::{Outcome, score};
pub use redraw::write_case;
pub use write::{CaseFiles, WriteError};
