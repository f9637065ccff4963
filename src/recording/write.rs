//! Writing recordings: the CSV and its sidecar, each atomically (a temporary file in the
//! same directory, renamed over the target once complete), the pair in stages
//! ([`prepare_recording`]). Numbers are written in Rust's
//! shortest round-trip form, so [`read_recording`](super::read_recording) reads them back
//! bit-identical; non-finite samples are refused (an output file never holds NaN).

use std::path::Path;

use super::error::{Reason, RecordingError};
use super::integrity::CsvCheck;
use super::read::sidecar_path;
use super::sidecar::sidecar_text;
use super::types::Recording;
use crate::files::pair::{PairError, PreparedPair};

/// Checks that every channel has one finite sample per time stamp and that time
/// increases; the error names the column and the 1-based CSV line (header = line 1).
pub fn check_recording(recording: &Recording, file: &str) -> Result<(), RecordingError> {
    let n = recording.time_s.len();
    let bad = |reason| RecordingError::new(file, reason);
    if n == 0 {
        return Err(bad(Reason::Inconsistent("no samples".into())));
    }
    let columns = std::iter::once(("time_s", &recording.time_s)).chain(
        recording
            .channels
            .iter()
            .map(|c| (c.column.as_str(), &c.values)),
    );
    for (name, values) in columns {
        if values.len() != n {
            let message = format!("{} samples, `time_s` has {n}", values.len());
            return Err(bad(Reason::Inconsistent(message)).at_key(name));
        }
        if let Some(i) = values.iter().position(|v| !v.is_finite()) {
            return Err(bad(Reason::NotFinite(format!("{}", values[i])))
                .at_line(i + 2)
                .at_key(name));
        }
    }
    if let Some(i) = recording.time_s.windows(2).position(|w| w[1] <= w[0]) {
        let t = &recording.time_s;
        let reason = Reason::TimeNotIncreasing {
            time_s: t[i + 1],
            previous_s: t[i],
        };
        return Err(bad(reason).at_line(i + 3).at_key("time_s"));
    }
    Ok(())
}

/// The CSV text of a recording (header `time_s,<columns>`, one row per sample).
pub fn csv_string(recording: &Recording) -> String {
    use std::fmt::Write as _;
    let width = 1 + recording.channels.len();
    let mut out = String::with_capacity(recording.time_s.len() * width * 20);
    out.push_str("time_s");
    for c in &recording.channels {
        out.push(',');
        out.push_str(&c.column);
    }
    out.push('\n');
    for (i, t) in recording.time_s.iter().enumerate() {
        let _ = write!(out, "{t}");
        for c in &recording.channels {
            let _ = write!(out, ",{}", c.values[i]);
        }
        out.push('\n');
    }
    out
}

/// Checks the recording and writes the temporaries of its CSV and sidecar (same stem,
/// `.toml`) without touching either target: the first stage of [`write_recording`]. The
/// sidecar records the CSV's SHA-256 and row count (`csv_sha256`, `csv_rows`), so a pair
/// left half-renamed is refused by [`read_recording`](super::read_recording). Commit with
/// [`PreparedPair::commit`] (or its two stages); dropping it removes both temporaries.
pub fn prepare_recording(
    recording: &Recording,
    csv_path: &Path,
) -> Result<PreparedPair, RecordingError> {
    check_recording(recording, &csv_path.display().to_string())?;
    let csv = csv_string(recording);
    let check = CsvCheck::of(csv.as_bytes());
    let sidecar = sidecar_text(&recording.meta, Some(&check));
    PreparedPair::prepare(
        csv_path,
        csv.as_bytes(),
        &sidecar_path(csv_path),
        sidecar.as_bytes(),
    )
    .map_err(pair_error)
}

fn pair_error(e: PairError) -> RecordingError {
    RecordingError::new(
        e.path.display().to_string(),
        Reason::Io(format!("cannot write: {}", e.source)),
    )
}

/// Writes the recording to `csv_path` and its sidecar beside it (same stem, `.toml`).
/// Refuses channels of the wrong length, non-finite samples and time that does not
/// increase, before writing anything. Both files go to temporaries first; if either
/// cannot be written neither target is touched. Then the CSV is renamed, then the sidecar
/// (issue 13).
pub fn write_recording(recording: &Recording, csv_path: &Path) -> Result<(), RecordingError> {
    prepare_recording(recording, csv_path)?
        .commit()
        .map_err(pair_error)
}
