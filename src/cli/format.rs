//! Output helpers: order keys, JSON printing, fixed-width tables.

use super::error::CliError;
use serde_json::Value;

/// An order as a JSON key: `"0.5"`, `"1"`, `"1.5"` (`spec/cli.md`).
pub fn order_key(order: f64) -> String {
    format!("{order}")
}

/// Prints one JSON document on stdout; refuses non-finite numbers (JSON has none).
pub fn print_json(value: &Value) -> Result<(), CliError> {
    let text = serde_json::to_string_pretty(value).map_err(CliError::failed)?;
    println!("{text}");
    Ok(())
}

/// A finite number as JSON, or an error naming what it was.
pub fn number(value: f64, what: &str) -> Result<Value, CliError> {
    serde_json::Number::from_f64(value)
        .map(Value::Number)
        .ok_or_else(|| CliError::failed(anyhow::anyhow!("{what} is not finite ({value})")))
}

/// A list of finite numbers as JSON.
pub fn numbers(values: &[f64], what: &str) -> Result<Value, CliError> {
    values
        .iter()
        .map(|&v| number(v, what))
        .collect::<Result<Vec<_>, _>>()
        .map(Value::Array)
}

/// Prints a table: a header row and rows, columns padded to their widest cell.
pub fn print_table(header: &[String], rows: &[Vec<String>]) {
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
    println!("{}", line(header));
    for row in rows {
        println!("{}", line(row));
    }
}

/// Prints the library's warnings on stderr.
pub fn print_warnings(warnings: &[String]) {
    for w in warnings {
        eprintln!("warning: {w}");
    }
}
