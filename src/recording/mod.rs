//! Recordings (`spec/recording-format.md`): IAS per station sampled in time, in a CSV
//! with a TOML sidecar of the same stem. [`read_recording`] reads and checks one, with
//! errors that name the file, the line, the column and the reason ([`RecordingError`]);
//! [`write_recording`] writes one atomically (the simulator's `--csv`).

pub mod bad_samples;
pub mod error;
pub mod integrity;
pub mod read;
pub mod run;
pub mod shape;
pub mod sidecar;
pub mod table;
pub mod timing;
pub mod types;
pub mod write;

pub use bad_samples::BadSamples;
pub use error::{Reason, RecordingError};
pub use integrity::CsvCheck;
pub use read::{
    ReadOptions, ReadOutcome, parse_recording, parse_recording_with, read_recording,
    read_recording_with, sidecar_path,
};
pub use run::Run;
pub use shape::{LONG_RUN_S, RunShape, classify, duration_s};
pub use sidecar::{parse_csv_check, parse_sidecar, sidecar_string, sidecar_text};
pub use types::*;
pub use write::{check_recording, csv_string, prepare_recording, write_recording};
