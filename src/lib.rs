//! # torsim — torsional vibration of engine drivelines with rubber couplings
//!
//! The library computes; it has no GUI and prints nothing. The `torsim` binary (its CLI,
//! later its GUI) is a thin front end on these calls, so every number it shows can be
//! reproduced here and checked by a test.
//!
//! ## A tour
//!
//! - [`model`] — the driveline as the user writes it (`spec/model-format.md`): inertias,
//!   shafts, rubber stages, gears, the engine, prescribed harmonics, load, operation and
//!   expectations; reading with errors that name file, line and key; writing back; the
//!   rubber coupling law of seed 000 ([`model::rubber`]: eq. 1–2, 8–15); the presets
//!   shipped in the binary ([`model::presets`]).
//! - [`physics`] — the linear driveline at an operating point ([`physics::System`]):
//!   inertias and stiffnesses referred to the engine shaft through the gear tree, rubber
//!   stages linearized at the static twist of the mean torque, the engine's cycle-mean
//!   reciprocating inertia; the cylinder torque of seed 001 eq. 3–5
//!   ([`physics::engine`]) and its harmonics per order ([`physics::Excitation`]).
//! - [`modal`] — undamped modes (rubber at each mode's own frequency), damped frequencies
//!   and damping ratios, the Campbell diagram and its crossings.
//! - [`response`] — steady forced response order by order over a speed sweep: IAS per
//!   node, torque per connection, peak torque over a cycle, DIN 740 power loss.
//! - [`recording`] — bench and simulated recordings (`spec/recording-format.md`): a CSV
//!   of IAS per station in time and its TOML sidecar; reading with errors that name file,
//!   line and column; atomic writing.
//! - [`signal`] — order analysis of a recording: resampling to the reference shaft's
//!   angle (band-limited), synchronous averaging per working cycle, order spectrum, RMS,
//!   irregularity ratio, relative speed between stations, STFT of run-ups.
//! - [`rubber`] — the one causal representation of each rubber stage (a Maxwell chain
//!   fitted to seed 000's law at the model's modes and over its band) that every analysis
//!   reads.
//! - [`transient`] — the nonlinear time domain: crank-angle-dependent engine inertia,
//!   secant rubber stiffness with its causal Maxwell chain and self-heating, gear backlash;
//!   Dormand–Prince integration; steady runs settled cycle by cycle, and run-ups.
//! - [`compare`] — design variants regime by regime: IR per station, power loss per
//!   rubber stage (seed 001 Tables 9–13).
//! - [`diagnose`] — where a model and bench recordings disagree, the physics the model
//!   left out (`spec/diagnosis.md`), fitted and validated on held-out recordings.
//! - [`effects`] — the effects of `spec/diagnosis.md` as model extensions (rubber laws,
//!   structure, backlash, hysteresis, sensor artefacts, plain parameter errors): the
//!   diagnosis's candidates and the synthetic bench's truths.
//! - [`campaign`] — a bench campaign as planned (runs and speed stations), for `synth` and
//!   for the detectability analysis `diagnose --power`.
//! - [`check`] — the `[expect]` checks that `torsim check` runs on presets.
//! - [`synth`] — synthetic bench recordings for the diagnosis: the user's model made
//!   richer by one effect of `spec/diagnosis.md` and plain parameter errors, simulated
//!   over a campaign (regimes, long run, run-up) and measured like a bench (zebra-tape
//!   pulses, jitter, wobble, anti-aliasing, noise), with the truth written apart.
//!
//! ## Example
//!
//! ```
//! use torsim::model::{parse_model, presets};
//! use torsim::physics::{OperatingPoint, System};
//!
//! let preset = presets::preset("test-rig-70sh").expect("shipped");
//! let model = parse_model(preset.text, "test-rig-70sh.toml")?;
//! let system = System::new(&model, OperatingPoint::default())?;
//! let modes = torsim::modal::modes(&system)?;
//! assert_eq!(modes.len(), 3); // seed 001's 3-DOF model, brake side as frame
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Units are SI unless a name says otherwise (`_rpm`, `_hz`, `_deg`, `_c`, `_bar`, `_mm`).

#![warn(missing_docs)]

pub mod calibrate;
pub mod campaign;
pub mod check;
pub mod compare;
pub mod diagnose;
pub mod effects;
pub mod files;
pub mod limits;
pub mod modal;
pub mod model;
pub mod physics;
pub mod ratings;
pub mod recording;
pub mod response;
pub mod rubber;
pub mod signal;
pub mod synth;
pub mod transient;
