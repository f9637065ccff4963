//! The last guard before a JSON document leaves the command line: serde_json writes a
//! NaN or an infinity as `null`, so a number that could not be computed would reach the
//! user as a silent `null` (issue 13: "a column of 1e308 gives 83 nulls in the report").
//! Every document is walked before it is printed; a `null` anywhere refuses the whole
//! document with the JSON paths that could not be computed, and nothing is printed.
//!
//! Absent values are left out of a document (`skip_serializing_if`), never written as
//! `null`, so a `null` here always means a number that was not finite.

use serde_json::Value;

/// The paths (`fit.before_chi2`, `modes[2].frequency_hz`) of every `null` in `value`.
pub fn null_paths(value: &Value) -> Vec<String> {
    let mut out = Vec::new();
    walk(value, &mut String::new(), &mut out);
    out
}

fn walk(value: &Value, path: &mut String, out: &mut Vec<String>) {
    match value {
        Value::Null => out.push(if path.is_empty() {
            "(the document)".into()
        } else {
            path.clone()
        }),
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                let len = path.len();
                path.push_str(&format!("[{i}]"));
                walk(item, path, out);
                path.truncate(len);
            }
        }
        Value::Object(map) => {
            for (key, item) in map {
                let len = path.len();
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(key);
                walk(item, path, out);
                path.truncate(len);
            }
        }
        Value::Bool(_) | Value::Number(_) | Value::String(_) => {}
    }
}

/// A located error for a document with `null`s, naming at most the first five paths.
pub fn check(value: &Value) -> Result<(), String> {
    let paths = null_paths(value);
    if paths.is_empty() {
        return Ok(());
    }
    let shown: Vec<&str> = paths.iter().take(5).map(String::as_str).collect();
    let more = match paths.len() {
        n if n > 5 => format!(" and {} more", n - 5),
        _ => String::new(),
    };
    Err(format!(
        "could not compute {}{more} (not a finite number); nothing was printed",
        shown.join(", ")
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn every_null_is_found_by_its_path() {
        let doc = json!({
            "fit": {"before_chi2": f64::NAN, "after_chi2": 1.5},
            "modes": [{"frequency_hz": 9.0}, {"frequency_hz": f64::INFINITY}],
        });
        assert_eq!(
            null_paths(&doc),
            vec![
                "fit.before_chi2".to_string(),
                "modes[1].frequency_hz".to_string()
            ]
        );
        let e = check(&doc).unwrap_err();
        assert!(
            e.starts_with("could not compute fit.before_chi2, modes[1]"),
            "{e}"
        );
        assert!(check(&json!({"a": [1, 2.5, "x", true]})).is_ok());
    }
}
