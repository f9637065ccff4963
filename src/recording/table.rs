//! The CSV of a recording as a table of numbers: the header's columns, the samples, the
//! file line of each row and the printed resolution of the time column.
//!
//! Parsed by hand (split on `,`, `str::parse::<f64>`): a 300 000-row, 3-column file
//! reads in a few tens of milliseconds. Non-finite samples are kept here (they are
//! judged with the other bad samples, [`super::bad_samples`]), except in `time_s`.

use super::error::{Reason, RecordingError};
use super::types::ChannelKind;

/// The parsed CSV.
pub struct Table {
    /// Column names of the header, `time_s` first.
    pub names: Vec<String>,
    /// Line of the header.
    pub header_line: usize,
    /// Kind of each column after `time_s`.
    pub kinds: Vec<ChannelKind>,
    /// Samples per column, `time_s` first.
    pub columns: Vec<Vec<f64>>,
    /// File line (1-based) of each data row.
    pub lines: Vec<usize>,
    /// Finest printed resolution of the time column, s (6 decimals: 1e-6).
    pub time_resolution_s: f64,
}

/// Parses the header and rows; `file` names the CSV in errors.
pub fn parse_table(
    text: &str,
    file: &str,
    node_names: Option<&[String]>,
) -> Result<Table, RecordingError> {
    let err = |line: usize, reason: Reason| RecordingError::new(file, reason).at_line(line);
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
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
    let names: Vec<String> = header.split(',').map(|s| s.trim().to_string()).collect();
    if names[0] != "time_s" {
        return Err(err(
            header_line,
            Reason::MissingTime(format!(", not `{}`", names[0].escape_debug())),
        )
        .at_key(&names[0]));
    }
    let kinds = kinds(&names, header_line, file, node_names)?;
    let width = names.len();
    let max_rows = crate::limits::current().max_samples;
    let rows_guess = (text.len() / (width * 8).max(1)).min(max_rows);
    let mut columns: Vec<Vec<f64>> = (0..width).map(|_| Vec::with_capacity(rows_guess)).collect();
    let mut row_lines = Vec::with_capacity(rows_guess);
    let mut time_resolution_s = f64::INFINITY;
    for (line, row) in lines {
        if row_lines.len() == max_rows {
            return Err(err(line, Reason::TooManySamples { limit: max_rows }));
        }
        row_lines.push(line);
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
                .map_err(|_| err(line, Reason::NotNumeric(field.into())).at_key(&names[k]))?;
            if k == 0 {
                if !value.is_finite() {
                    return Err(err(line, Reason::NotFinite(field.into())).at_key("time_s"));
                }
                time_resolution_s = time_resolution_s.min(printed_resolution(field));
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
    }
    Ok(Table {
        names,
        header_line,
        kinds,
        columns,
        lines: row_lines,
        time_resolution_s,
    })
}

/// The kind of each column after `time_s`, checked against the model's nodes.
fn kinds(
    names: &[String],
    header_line: usize,
    file: &str,
    node_names: Option<&[String]>,
) -> Result<Vec<ChannelKind>, RecordingError> {
    let mut kinds = Vec::with_capacity(names.len() - 1);
    for (i, name) in names.iter().enumerate().skip(1) {
        let at = |reason| {
            RecordingError::new(file, reason)
                .at_line(header_line)
                .at_key(name)
        };
        if names[..i].contains(name) {
            return Err(at(Reason::DuplicateColumn(name.clone())));
        }
        let kind =
            ChannelKind::from_column(name).ok_or_else(|| at(Reason::BadColumn(name.clone())))?;
        if let (Some(nodes), Some(node)) = (node_names, kind.node())
            && !nodes.iter().any(|n| n == node)
        {
            return Err(at(Reason::UnknownNode {
                column: name.clone(),
                nodes: nodes.join(", "),
            }));
        }
        kinds.push(kind);
    }
    Ok(kinds)
}

/// The resolution a number was printed with: `0.000098` → 1e-6, `1.5e-3` → 1e-4,
/// `12` → 1.
pub fn printed_resolution(field: &str) -> f64 {
    let (mantissa, exponent) = match field.find(['e', 'E']) {
        Some(i) => (&field[..i], field[i + 1..].parse::<i32>().unwrap_or(0)),
        None => (field, 0),
    };
    let decimals = mantissa.find('.').map_or(0, |i| {
        mantissa[i + 1..].bytes().filter(u8::is_ascii_digit).count()
    });
    10f64.powi(exponent.saturating_sub(decimals.min(400) as i32))
}

#[cfg(test)]
mod tests {
    use super::printed_resolution;

    #[test]
    fn resolution_counts_printed_decimals() {
        assert_eq!(printed_resolution("187.648112"), 1e-6);
        assert_eq!(printed_resolution("0.00010"), 1e-5);
        assert_eq!(printed_resolution("1.5e-3"), 1e-4);
        assert_eq!(printed_resolution("12"), 1.0);
    }
}
