//! Errors from reading and writing recordings: they name the file, the line, the column
//! or key, and the reason (`spec/recording-format.md`, "Errors").

use std::fmt;

/// Why a recording cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Reason {
    /// The file could not be read or written.
    #[error("{0}")]
    Io(String),
    /// The CSV has no header line, or its first column is not `time_s`.
    #[error("the first column must be `time_s`{0}")]
    MissingTime(String),
    /// A column name is not `<node>_rpm`, `<node>_rad` or `torque_<connection>_nm`.
    #[error("column `{0}` is not `<node>_rpm`, `<node>_rad` or `torque_<connection>_nm`")]
    BadColumn(String),
    /// A station column names no node of the model.
    #[error("column `{column}` names no node of the model (nodes: {nodes})")]
    UnknownNode {
        /// The column.
        column: String,
        /// The model's nodes, comma separated.
        nodes: String,
    },
    /// The same column twice.
    #[error("column `{0}` appears twice")]
    DuplicateColumn(String),
    /// A data row with the wrong number of fields.
    #[error("{found} fields, the header has {expected}")]
    FieldCount {
        /// Fields in the header.
        expected: usize,
        /// Fields in the row.
        found: usize,
    },
    /// A sample that is not a number.
    #[error("`{0}` is not a number")]
    NotNumeric(String),
    /// A sample that is NaN or infinite.
    #[error("sample `{0}` is not finite")]
    NotFinite(String),
    /// A time stamp not after the one before.
    #[error("time {time_s} s is not after the previous {previous_s} s (time must increase)")]
    TimeNotIncreasing {
        /// This row's time, s.
        time_s: f64,
        /// The previous row's time, s.
        previous_s: f64,
    },
    /// The reference shaft turns through fewer than two working cycles.
    #[error(
        "the reference shaft turns {revolutions:.3} revolutions: fewer than two working cycles ({needed} revolutions)"
    )]
    TooShort {
        /// Revolutions of the reference shaft over the recording.
        revolutions: f64,
        /// Revolutions needed (two cycles).
        needed: f64,
    },
    /// Bytes that are not UTF-8.
    #[error(
        "invalid UTF-8 at byte {offset} (the file must be UTF-8 text; a leading BOM is allowed)"
    )]
    InvalidUtf8 {
        /// 0-based byte offset of the first invalid byte in the file.
        offset: usize,
    },
    /// More data rows than [`crate::limits::Limits::max_samples`].
    #[error("more than {limit} samples per channel (the limit `max_samples` of torsim::limits)")]
    TooManySamples {
        /// The limit.
        limit: usize,
    },
    /// Sampling that is not uniform: a gap, or scatter of the time stamps beyond jitter
    /// (see [`crate::recording::timing`]).
    #[error("{0}")]
    Timing(String),
    /// Over-range or impossible samples, refused (`--bad-samples refuse`, the default).
    #[error("{0}")]
    BadSamples(String),
    /// The sidecar's `speed_rpm` contradicts the data.
    #[error(
        "speed_rpm = {sidecar_rpm} but the reference's mean speed in {csv} is {data_rpm:.1} rpm: \
         they differ by more than {tolerance_pct} % (fix the sidecar or pick the right CSV)"
    )]
    SpeedMismatch {
        /// The sidecar's speed, rpm.
        sidecar_rpm: f64,
        /// The data's mean reference speed, rpm.
        data_rpm: f64,
        /// The CSV.
        csv: String,
        /// The tolerance, %.
        tolerance_pct: f64,
    },
    /// The sidecar is not valid TOML.
    #[error("TOML syntax error: {0}")]
    Toml(String),
    /// A sidecar key this format does not have.
    #[error("unknown key (known: {0})")]
    UnknownKey(String),
    /// A required sidecar key is absent.
    #[error("missing required key")]
    MissingKey,
    /// A sidecar value of the wrong type or out of range.
    #[error("{0}")]
    BadValue(String),
    /// The reference node has no `<reference>_rpm` column in the CSV.
    #[error("the reference `{reference}` has no column `{reference}_rpm` in the CSV")]
    MissingReference {
        /// The sidecar's `reference`.
        reference: String,
    },
    /// Channels of different lengths, or no samples (when writing).
    #[error("{0}")]
    Inconsistent(String),
}

/// A recording that cannot be used, with where and why.
///
/// `Display` gives `file:line: column `x`: reason`, leaving out what is unknown.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct RecordingError {
    /// The file (CSV or sidecar) as given.
    pub file: String,
    /// 1-based line in that file, when known.
    pub line: Option<usize>,
    /// The CSV column or sidecar key, when it applies.
    pub key: Option<String>,
    /// What is wrong.
    pub reason: Reason,
}

impl RecordingError {
    /// An error in `file` with no line or key yet.
    pub fn new(file: impl Into<String>, reason: Reason) -> Self {
        Self {
            file: file.into(),
            line: None,
            key: None,
            reason,
        }
    }

    /// The same error at a 1-based line.
    pub fn at_line(mut self, line: usize) -> Self {
        self.line = Some(line);
        self
    }

    /// The same error at a column or key.
    pub fn at_key(mut self, key: impl Into<String>) -> Self {
        self.key = Some(key.into());
        self
    }
}

impl fmt::Display for RecordingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        if let Some(key) = &self.key {
            write!(f, ": `{key}`")?;
        }
        write!(f, ": {}", self.reason)
    }
}
