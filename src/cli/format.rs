//! Output helpers: order keys, JSON printing, fixed-width tables.

use super::error::CliError;
use serde_json::Value;
use std::io::Write;

/// An order as a JSON key: `"0.5"`, `"1"`, `"1.5"` (`spec/cli.md`).
pub fn order_key(order: f64) -> String {
    format!("{order}")
}

/// Writes `text` to stdout at once. A reader that closed the pipe early (`| head`) is
/// not an error: the output is simply no longer wanted.
pub fn emit(text: &str) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(CliError::failed(e)),
        _ => Ok(()),
    }
}

/// Prints one JSON document on stdout; refuses non-finite numbers (JSON has none).
pub fn print_json(value: &Value) -> Result<(), CliError> {
    super::json_guard::check(value).map_err(|e| CliError::failed(anyhow::anyhow!(e)))?;
    let text = serde_json::to_string_pretty(value).map_err(CliError::failed)?;
    emit(&(text + "\n"))
}

/// A finite number as JSON, or an error naming what it was.
pub fn number(value: f64, what: &str) -> Result<Value, CliError> {
    serde_json::Number::from_f64(value)
        .map(Value::Number)
        .ok_or_else(|| {
            CliError::failed(anyhow::anyhow!(
                "{what} could not be computed (the result is {value}, which JSON cannot carry)"
            ))
        })
}

/// A list of finite numbers as JSON.
pub fn numbers(values: &[f64], what: &str) -> Result<Value, CliError> {
    values
        .iter()
        .map(|&v| number(v, what))
        .collect::<Result<Vec<_>, _>>()
        .map(Value::Array)
}

/// A table as text: a header row and rows, columns padded to their widest cell.
pub fn table(header: &[String], rows: &[Vec<String>]) -> String {
    let mut widths: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for row in rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let line = |cells: &[String]| {
        cells
            .iter()
            .zip(&widths)
            .map(|(c, w)| format!("{c:>w$}"))
            .collect::<Vec<_>>()
            .join("  ")
    };
    let mut text = line(header).trim_end().to_string() + "\n";
    for row in rows {
        text += line(row).trim_end();
        text.push('\n');
    }
    text
}

/// Prints the library's warnings on stderr.
pub fn print_warnings(warnings: &[String]) {
    for w in warnings {
        eprintln!("warning: {w}");
    }
}

/// Appends one formatted line to a `String` (writing to a `String` cannot fail).
macro_rules! outln {
    ($buf:expr) => {
        $buf.push('\n')
    };
    ($buf:expr, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = writeln!($buf, $($arg)*);
    }};
}
pub(crate) use outln;
