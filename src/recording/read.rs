//! Reading recordings: the CSV of samples and its TOML sidecar (same stem, beside it),
//! with errors that name the file, the line, the column and the reason.
//!
//! Both files are read as bytes: a UTF-8 BOM (Excel's "CSV UTF-8") is stripped, and
//! bytes that are not UTF-8 are refused with the line and byte offset (issue 13). The
//! samples are then checked in this order: the clock ([`super::timing`]: gaps,
//! duplicates and time going backwards refused, jitter resampled onto the fitted grid),
//! bad samples ([`super::bad_samples`], handled as [`ReadOptions::bad_samples`] says),
//! the reference column and its two working cycles, and the sidecar's `speed_rpm`.

use std::path::Path;

use super::bad_samples::{self, BadSamples};
use super::error::{Reason, RecordingError};
use super::integrity::verify;
use super::sidecar::{key_line, parse_csv_check, parse_sidecar};
use super::table::{Table, parse_table};
use super::timing::{self, TimingFault};
use super::types::{Channel, Recording, RecordingMeta, RunKind, revolutions};

/// How far a steady run's mean reference speed may be from the sidecar's `speed_rpm`,
/// %: a bench holds its speed to 1–2 %, a different regime differs by 20 % or more.
pub const SPEED_TOLERANCE_PCT: f64 = 10.0;

/// Options of [`read_recording_with`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ReadOptions {
    /// What to do with over-range and impossible samples (default: refuse).
    pub bad_samples: BadSamples,
}

/// A recording as read, and what the reader did to it (interpolated or dropped bad
/// samples, resampled jittered time stamps), one sentence per note, for the user.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadOutcome {
    /// The recording, on a uniform time grid.
    pub recording: Recording,
    /// What was changed, empty when nothing was.
    pub notes: Vec<String>,
}

/// The sidecar path of a CSV: same stem, `.toml`.
pub fn sidecar_path(csv_path: &Path) -> std::path::PathBuf {
    csv_path.with_extension("toml")
}

/// Reads a recording with the default options (bad samples refused). See
/// [`read_recording_with`].
pub fn read_recording(
    csv_path: &Path,
    node_names: Option<&[String]>,
) -> Result<Recording, RecordingError> {
    read_recording_with(csv_path, node_names, &ReadOptions::default()).map(|r| r.recording)
}

/// Reads a recording: `csv_path` and the sidecar beside it (same stem, `.toml`).
///
/// With `node_names` (the model's nodes), every `<node>_rpm` and `<node>_rad` column must
/// name one of them. The reference shaft must turn through at least two working cycles
/// (`strokes` revolutions), and a steady run's mean reference speed must be within
/// [`SPEED_TOLERANCE_PCT`] of the sidecar's `speed_rpm`. When the sidecar records the
/// CSV's fingerprint (`csv_sha256`, `csv_rows`), a CSV that does not match it is refused,
/// naming both files.
pub fn read_recording_with(
    csv_path: &Path,
    node_names: Option<&[String]>,
    options: &ReadOptions,
) -> Result<ReadOutcome, RecordingError> {
    let csv_file = csv_path.display().to_string();
    let csv_text = read_text(csv_path, &csv_file, "cannot read")?;
    let toml_path = sidecar_path(csv_path);
    let toml_file = toml_path.display().to_string();
    let toml_text = read_text(&toml_path, &toml_file, "cannot read the sidecar")?;
    let meta = parse_sidecar(&toml_text, &toml_file)?;
    // Issue 13: a pair whose CSV is not the one its sidecar was written with is refused.
    // The fingerprint is of the text (torsim writes no BOM) or of the bytes as written
    // with a leading BOM (a logger that adds one and fingerprints its own file).
    if let Some(check) = parse_csv_check(&toml_text, &toml_file)? {
        let of_text = verify(&check, csv_text.as_bytes(), &csv_file, &toml_file);
        if of_text.is_err() {
            let with_bom = format!("\u{feff}{csv_text}");
            verify(&check, with_bom.as_bytes(), &csv_file, &toml_file).or(of_text)?;
        }
    }
    let outcome = parse_recording_with(&csv_text, &csv_file, meta, node_names, options)?;
    check_speed(&outcome.recording, &csv_file, &toml_file, &toml_text)?;
    Ok(outcome)
}

/// A file's text: BOM stripped, invalid UTF-8 refused with its line and byte offset.
fn read_text(path: &Path, file: &str, what: &str) -> Result<String, RecordingError> {
    let bytes = std::fs::read(path)
        .map_err(|e| RecordingError::new(file, Reason::Io(format!("{what}: {e}"))))?;
    let body = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&bytes);
    match std::str::from_utf8(body) {
        Ok(text) => Ok(text.to_string()),
        Err(e) => {
            let valid = &body[..e.valid_up_to()];
            let line = valid.iter().filter(|&&b| b == b'\n').count() + 1;
            let offset = e.valid_up_to() + (bytes.len() - body.len());
            Err(RecordingError::new(file, Reason::InvalidUtf8 { offset }).at_line(line))
        }
    }
}

/// A steady run's `speed_rpm` against the data's mean reference speed.
fn check_speed(
    recording: &Recording,
    csv_file: &str,
    toml_file: &str,
    toml_text: &str,
) -> Result<(), RecordingError> {
    let meta = &recording.meta;
    let (RunKind::Steady, Some(sidecar_rpm)) = (meta.kind, meta.speed_rpm) else {
        return Ok(());
    };
    let Some(speed) = recording.speed_rpm(&meta.reference) else {
        return Ok(());
    };
    let data_rpm = speed.iter().sum::<f64>() / speed.len().max(1) as f64;
    if ((data_rpm - sidecar_rpm) / sidecar_rpm).abs() * 100.0 <= SPEED_TOLERANCE_PCT {
        return Ok(());
    }
    let e = RecordingError::new(
        toml_file,
        Reason::SpeedMismatch {
            sidecar_rpm,
            data_rpm,
            csv: csv_file.to_string(),
            tolerance_pct: SPEED_TOLERANCE_PCT,
        },
    )
    .at_key("speed_rpm");
    Err(match key_line(toml_text, "speed_rpm") {
        Some(line) => e.at_line(line),
        None => e,
    })
}

/// Parses a recording's CSV text with its sidecar already read, default options; `file`
/// names the CSV in errors. See [`read_recording_with`].
pub fn parse_recording(
    text: &str,
    file: &str,
    meta: RecordingMeta,
    node_names: Option<&[String]>,
) -> Result<Recording, RecordingError> {
    parse_recording_with(text, file, meta, node_names, &ReadOptions::default()).map(|r| r.recording)
}

/// Parses a recording's CSV text with its sidecar already read. See
/// [`read_recording_with`].
pub fn parse_recording_with(
    text: &str,
    file: &str,
    meta: RecordingMeta,
    node_names: Option<&[String]>,
    options: &ReadOptions,
) -> Result<ReadOutcome, RecordingError> {
    let mut table = parse_table(text, file, node_names)?;
    let mut notes = Vec::new();
    let timing = judge(&table, file)?;
    let mut time_s = std::mem::take(&mut table.columns[0]);
    let mut channels: Vec<Channel> = table.names[1..]
        .iter()
        .zip(std::mem::take(&mut table.kinds))
        .zip(table.columns.drain(1..))
        .map(|((name, kind), values)| Channel {
            column: name.clone(),
            kind,
            values,
        })
        .collect();
    let bad = bad_samples::find(&channels, timing.dt_s);
    if !bad.is_empty() {
        let list = bad_samples::describe(&bad, &channels, &table.lines);
        let first = bad.iter().min_by_key(|b| b.row).map(|b| (b.row, b.channel));
        let what = format!(
            "{} bad sample{} (not finite, below 0 rpm, or above {}× the running median over \
             a revolution): {list}",
            bad.len(),
            if bad.len() == 1 { "" } else { "s" },
            bad_samples::MEDIAN_FACTOR
        );
        match options.bad_samples {
            BadSamples::Refuse => {
                let (row, c) = first.unwrap_or_default();
                let e = RecordingError::new(
                    file,
                    Reason::BadSamples(format!(
                        "{what}; `--bad-samples interpolate` or `drop` reads it anyway"
                    )),
                );
                return Err(e.at_line(table.lines[row]).at_key(&channels[c].column));
            }
            BadSamples::Interpolate => {
                let (run, c) = bad_samples::interpolate(&mut channels, &bad);
                let rev = 60.0 / (timing.dt_s * typical_rpm(&channels, c));
                if run as f64 > rev.max(bad_samples::MIN_BLOCK as f64) {
                    let e = RecordingError::new(
                        file,
                        Reason::BadSamples(format!(
                            "{what}; `{}` has a run of {run} bad samples, more than a \
                             revolution: interpolating it would invent data (use `drop`)",
                            channels[c].column
                        )),
                    );
                    return Err(e.at_key(&channels[c].column));
                }
                notes.push(format!("{file}: interpolated {what}"));
            }
            BadSamples::Drop => {
                let (start, end) = bad_samples::longest_clean_stretch(time_s.len(), &bad);
                time_s = time_s[start..end].to_vec();
                for c in &mut channels {
                    c.values = c.values[start..end].to_vec();
                }
                let kept = if end > start {
                    format!("lines {} … {}", table.lines[start], table.lines[end - 1])
                } else {
                    "no rows".to_string()
                };
                notes.push(format!(
                    "{file}: dropped {what}; kept {kept}, the longest stretch without them"
                ));
                table.lines = table.lines[start..end].to_vec();
            }
        }
    }
    let timing = if time_s.len() < 2 {
        timing
    } else {
        judge_times(&time_s, &table, file)?
    };
    if !timing.is_uniform() {
        let mut columns: Vec<&mut Vec<f64>> = channels.iter_mut().map(|c| &mut c.values).collect();
        let grid = timing::regularize(&time_s, &timing, &mut columns);
        // The cubic through a sample far off its neighbours (a dropout to 34 rpm amid
        // 4430 rpm, which the bad-sample rule lets pass) can overshoot below 0 rpm between
        // them: what the reader returns must pass the same check as what it read (the
        // recording fuzzer's crash 2ac8a006: −184 rpm written, refused on reading back).
        let overshoot = bad_samples::find(&channels, timing.dt_s);
        if let Some(b) = overshoot.iter().min_by_key(|b| b.row) {
            let column = channels[b.channel].column.clone();
            let e = RecordingError::new(
                file,
                Reason::BadSamples(format!(
                    "resampling the jittered time stamps onto a uniform grid gives `{column}`                      = {:.1} rpm near this line: a sample here is far off its neighbours;                      correct or remove it",
                    b.value
                )),
            );
            let line = table.lines.get(b.row).copied().unwrap_or(table.header_line);
            return Err(e.at_line(line).at_key(&column));
        }
        notes.push(format!(
            "{file}: time stamps scatter by up to {:.3} µs ({:.1} % of a step, beyond the \
             printed resolution): resampled onto the uniform {:.3} µs grid (cubic)",
            timing.max_residual_s * 1e6,
            100.0 * timing.max_residual_s / timing.dt_s,
            timing.dt_s * 1e6
        ));
        time_s = grid;
    } else if timing.max_residual_s > timing::IN_MEMORY_TOLERANCE_STEPS * timing.dt_s {
        // Uniform, but printed coarser than the analysis' 0.1 % of a step: the fitted
        // grid is the clock. Finer time stamps are kept as written (round trips are
        // bit-exact).
        time_s = (0..time_s.len())
            .map(|k| timing.t0_s + k as f64 * timing.dt_s)
            .collect();
    }
    let recording = Recording {
        time_s,
        channels,
        meta,
    };
    let last_line = table.lines.last().copied().unwrap_or(table.header_line);
    check_reference(&recording, file, table.header_line, last_line)?;
    Ok(ReadOutcome { recording, notes })
}

/// The clock of the whole table, with a located error.
fn judge(table: &Table, file: &str) -> Result<timing::Timing, RecordingError> {
    judge_times(&table.columns[0], table, file)
}

/// The clock of `time_s` (rows of `table`, `table.lines` aligned with them).
fn judge_times(
    time_s: &[f64],
    table: &Table,
    file: &str,
) -> Result<timing::Timing, RecordingError> {
    timing::judge(time_s, Some(table.time_resolution_s)).map_err(|fault| {
        let index = fault.index();
        let reason = match fault {
            TimingFault::NotIncreasing {
                time_s, previous_s, ..
            } => Reason::TimeNotIncreasing { time_s, previous_s },
            TimingFault::TooFew => Reason::Inconsistent(
                "fewer than two samples: no sampling interval, no working cycle".into(),
            ),
            other => Reason::Timing(other.to_string()),
        };
        let e = RecordingError::new(file, reason).at_key("time_s");
        match index.and_then(|i| table.lines.get(i)) {
            Some(&line) => e.at_line(line),
            None => e,
        }
    })
}

/// The median speed of channel `c`, rpm (for "a revolution" in samples).
fn typical_rpm(channels: &[Channel], c: usize) -> f64 {
    let mut v: Vec<f64> = channels[c].values.clone();
    if v.is_empty() {
        return bad_samples::MEDIAN_FLOOR_RPM;
    }
    let mid = v.len() / 2;
    let (_, m, _) = v.select_nth_unstable_by(mid, f64::total_cmp);
    m.max(bad_samples::MEDIAN_FLOOR_RPM)
}

/// The reference column exists and turns through two working cycles.
fn check_reference(
    recording: &Recording,
    file: &str,
    header_line: usize,
    last_line: usize,
) -> Result<(), RecordingError> {
    let reference = &recording.meta.reference;
    let Some(n_ref) = recording.speed_rpm(reference) else {
        return Err(RecordingError::new(
            file,
            Reason::MissingReference {
                reference: reference.clone(),
            },
        )
        .at_line(header_line));
    };
    let revs = revolutions(&recording.time_s, n_ref);
    let needed = 2.0 * recording.meta.cycle_rev();
    if revs < needed || revs.is_nan() {
        let reason = Reason::TooShort {
            revolutions: revs,
            needed,
        };
        return Err(RecordingError::new(file, reason)
            .at_line(last_line)
            .at_key(format!("{reference}_rpm")));
    }
    Ok(())
}
