//! Order analysis of recordings (seed 001 §2.3): resampling each station's IAS to the
//! reference shaft's angle ([`resample`], band-limited), removing the slow trend of the
//! mean speed and averaging per working cycle ([`orders`]), order amplitudes by FFT, RMS
//! and irregularity ratio ([`stats`]), the relative speed across a coupling, and the STFT
//! of run-ups with order tracks ([`stft`]). [`analyse`] does it all for a recording.

pub mod analysis;
pub mod antialias;
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
    /// Sampling is not uniform (order tracking needs uniform samples): a gap, a
    /// duplicate, time going backwards, or jitter not yet resampled
    /// ([`crate::recording::timing`]).
    #[error("sampling is not uniform: {0}")]
    NonUniform(String),
    /// The reference speed is zero, negative or not finite (its angle cannot define
    /// orders).
    #[error("the reference speed is not > 0 at {time_s:.6} s")]
    NonPositiveSpeed {
        /// Time of the first such sample, s.
        time_s: f64,
    },
    /// Fewer samples than the resampling kernel needs.
    #[error(
        "only {samples} samples: the resampling kernel needs {needed} ({margin} at each end \
         and two between)"
    )]
    TooFewSamples {
        /// Samples in the recording.
        samples: usize,
        /// Samples needed.
        needed: usize,
        /// Kernel margin at each end, samples.
        margin: usize,
    },
    /// No whole working cycle between the resampling kernel's margins at the ends.
    #[error(
        "only {cycles:.2} working cycles of the reference shaft lie between the \
         {margin}-sample margins the resampling kernel needs at each end, and whole cycles \
         are counted from the first sample's angle: {needed:.2} cycles are needed there \
         to hold one whole cycle"
    )]
    TooShort {
        /// Working cycles between the margins.
        cycles: f64,
        /// Working cycles needed between the margins (one, plus the part of a cycle
        /// before the first whole one starts).
        needed: f64,
        /// Kernel margin at each end, samples.
        margin: usize,
    },
    /// The angle grid would exceed [`crate::limits::Limits::max_grid_points`].
    #[error(
        "the angle grid would have {points:.3e} points, more than the limit max_grid_points = \
         {limit} (the reference turns {revolutions:.3e} revolutions at {samples_per_rev} \
         points each: is a speed sample an over-range marker?)"
    )]
    GridTooLarge {
        /// Points the grid would have.
        points: f64,
        /// The limit.
        limit: usize,
        /// Revolutions of the reference.
        revolutions: f64,
        /// Points per revolution.
        samples_per_rev: usize,
    },
    /// A speed station whose mean speed is zero: its irregularity ratio (peak-to-peak
    /// over the mean) is undefined.
    #[error("station `{0}` has a mean speed of 0 rpm: its irregularity ratio is undefined")]
    StandingStation(String),
    /// An analysis option out of range.
    #[error("{0}")]
    BadOption(String),
    /// The FFT failed (wrong buffer sizes: a bug).
    #[error("FFT: {0}")]
    Fft(String),
}
