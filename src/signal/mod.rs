//! Order analysis of recordings (seed 001 §2.3): resampling each station's IAS to the
//! reference shaft's angle ([`resample`], band-limited), removing the slow trend of the
//! mean speed and averaging per working cycle ([`orders`]), order amplitudes by FFT, RMS
//! and irregularity ratio ([`stats`]), the relative speed across a coupling, and the STFT
//! of run-ups with order tracks ([`stft`]). [`analyse`] does it all for a recording.

pub mod analysis;
pub mod kernel;
pub mod orders;
pub mod resample;
pub mod stats;
pub mod stft;

pub use analysis::{
    Analysis, AnalysisOptions, RunUpStft, StationAnalysis, StationStft, analyse, analyse_with,
};
pub use orders::{OrderAmplitude, OrderSpectrum};
pub use resample::{AngleGrid, Interpolation, SAMPLES_PER_REV, angle_grid, resample};

/// Why an analysis could not run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SignalError {
    /// The reference node has no speed column.
    #[error("the reference `{0}` has no `{0}_rpm` column")]
    MissingReference(String),
    /// Sampling is not uniform (order tracking needs uniform samples).
    #[error(
        "sampling is not uniform: the sample at {time_s} s is off the {dt_s} s grid by more than 0.1 % of a step"
    )]
    NonUniform {
        /// Time of the first sample off the grid, s.
        time_s: f64,
        /// Mean sampling interval, s.
        dt_s: f64,
    },
    /// The reference speed is zero or negative (its angle cannot define orders).
    #[error("the reference speed is not > 0 at {time_s} s")]
    NonPositiveSpeed {
        /// Time of the first such sample, s.
        time_s: f64,
    },
    /// Not a whole working cycle away from the recording's ends.
    #[error(
        "only {cycles:.2} working cycles of the reference shaft: need at least 1 away from the ends"
    )]
    TooShort {
        /// Working cycles available.
        cycles: f64,
    },
    /// An analysis option out of range.
    #[error("{0}")]
    BadOption(String),
    /// The FFT failed (wrong buffer sizes: a bug).
    #[error("FFT: {0}")]
    Fft(String),
}
