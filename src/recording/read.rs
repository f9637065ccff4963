//! Reading recordings: the CSV of samples and its TOML sidecar (same stem, beside it),
//! with errors that name the file, the line, the column and the reason.
//!
//! The CSV is parsed by hand (split on `,`, `str::parse::<f64>`): a 300 000-row,
//! 3-column file reads in a few tens of milliseconds in a release build.

use std::path::Path;

use super::error::{Reason, RecordingError};
use super::integrity::verify;
use super::sidecar::{parse_csv_check, parse_sidecar};
use super::types::{Channel, ChannelKind, Recording, RecordingMeta, revolutions};

/// The sidecar path of a CSV: same stem, `.toml`.
pub fn sidecar_path(csv_path: &Path) -> std::path::PathBuf {
    csv_path.with_extension("toml")
}

/// Reads a recording: `csv_path` and the sidecar beside it (same stem, `.toml`).
///
/// With `node_names` (the model's nodes), every `<node>_rpm` and `<node>_rad` column must
/// name one of them. The reference shaft must turn through at least two working cycles
/// (`strokes` revolutions). When the sidecar records the CSV's fingerprint (`csv_sha256`,
/// `csv_rows`), a CSV that does not match it is refused, naming both files.
pub fn read_recording(
    csv_path: &Path,
    node_names: Option<&[String]>,
) -> Result<Recording, RecordingError> {
    let toml_path = sidecar_path(csv_path);
    let toml_file = toml_path.display().to_string();
    let toml_text = std::fs::read_to_string(&toml_path).map_err(|e| {
        RecordingError::new(
            &toml_file,
            Reason::Io(format!("cannot read the sidecar: {e}")),
        )
    })?;
    let meta = parse_sidecar(&toml_text, &toml_file)?;
    let check = parse_csv_check(&toml_text, &toml_file)?;
    let csv_file = csv_path.display().to_string();
    let csv_text = std::fs::read_to_string(csv_path)
        .map_err(|e| RecordingError::new(&csv_file, Reason::Io(format!("cannot read: {e}"))))?;
    // Issue 13: a pair whose CSV is not the one its sidecar was written with is refused.
    if let Some(check) = &check {
        verify(check, csv_text.as_bytes(), &csv_file, &toml_file)?;
    }
    parse_recording(&csv_text, &csv_file, meta, node_names)
}

/// Parses a recording's CSV text with its sidecar already read; `file` names the CSV in
/// errors. See [`read_recording`].
pub fn parse_recording(
    text: &str,
    file: &str,
    meta: RecordingMeta,
    node_names: Option<&[String]>,
) -> Result<Recording, RecordingError> {
    let err = |line: usize, reason: Reason| RecordingError::new(file, reason).at_line(line);
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l))
        .filter(|(_, l)| !l.starts_with('#') && !l.trim().is_empty());
    let Some((header_line, header)) = lines.next() else {
        return Err(RecordingError::new(
            file,
            Reason::MissingTime(": the file has no header".into()),
        ));
    };
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    if names[0] != "time_s" {
        return Err(err(
            header_line,
            Reason::MissingTime(format!(", not `{}`", names[0])),
        )
        .at_key(names[0]));
    }
    let mut kinds = Vec::with_capacity(names.len() - 1);
    for (i, &name) in names.iter().enumerate().skip(1) {
        let at = |reason| err(header_line, reason).at_key(name);
        if names[..i].contains(&name) {
            return Err(at(Reason::DuplicateColumn(name.into())));
        }
        let kind =
            ChannelKind::from_column(name).ok_or_else(|| at(Reason::BadColumn(name.into())))?;
        if let (Some(nodes), Some(node)) = (node_names, kind.node())
            && !nodes.iter().any(|n| n == node)
        {
            return Err(at(Reason::UnknownNode {
                column: name.into(),
                nodes: nodes.join(", "),
            }));
        }
        kinds.push(kind);
    }
    let width = names.len();
    let rows_guess = text.len() / (width * 8).max(1);
    let mut columns: Vec<Vec<f64>> = (0..width).map(|_| Vec::with_capacity(rows_guess)).collect();
    let mut last_line = header_line;
    for (line, row) in lines {
        last_line = line;
        let mut fields = row.split(',');
        for (k, column) in columns.iter_mut().enumerate() {
            let Some(field) = fields.next() else {
                return Err(err(
                    line,
                    Reason::FieldCount {
                        expected: width,
                        found: k,
                    },
                ));
            };
            let field = field.trim();
            let value: f64 = field
                .parse()
                .map_err(|_| err(line, Reason::NotNumeric(field.into())).at_key(names[k]))?;
            if !value.is_finite() {
                return Err(err(line, Reason::NotFinite(field.into())).at_key(names[k]));
            }
            column.push(value);
        }
        let extra = fields.count();
        if extra > 0 {
            return Err(err(
                line,
                Reason::FieldCount {
                    expected: width,
                    found: width + extra,
                },
            ));
        }
        let t = &columns[0];
        if t.len() >= 2 && t[t.len() - 1] <= t[t.len() - 2] {
            let reason = Reason::TimeNotIncreasing {
                time_s: t[t.len() - 1],
                previous_s: t[t.len() - 2],
            };
            return Err(err(line, reason).at_key("time_s"));
        }
    }
    let mut columns = columns.into_iter();
    let time_s = columns.next().unwrap_or_default();
    let channels: Vec<Channel> = names[1..]
        .iter()
        .zip(kinds)
        .zip(columns)
        .map(|((name, kind), values)| Channel {
            column: (*name).to_string(),
            kind,
            values,
        })
        .collect();
    let recording = Recording {
        time_s,
        channels,
        meta,
    };
    let reference = &recording.meta.reference;
    let Some(n_ref) = recording.speed_rpm(reference) else {
        return Err(err(
            header_line,
            Reason::MissingReference {
                reference: reference.clone(),
            },
        ));
    };
    let revs = revolutions(&recording.time_s, n_ref);
    let needed = 2.0 * recording.meta.cycle_rev();
    if revs < needed || revs.is_nan() {
        let reason = Reason::TooShort {
            revolutions: revs,
            needed,
        };
        return Err(err(last_line, reason).at_key(format!("{reference}_rpm")));
    }
    Ok(recording)
}
