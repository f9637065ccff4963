//! Shared inputs and assertions for the model error tests.
#![allow(dead_code)]

use torsim::model::{ModelError, parse_model};

/// Two nodes joined by a shaft (16 lines).
pub const BASE: &str = r#"format = 1
name = "t"

[[inertia]]
name = "a"
inertia = 1.0

[[inertia]]
name = "b"
inertia = 2.0

[[connection]]
kind = "shaft"
from = "a"
to = "b"
stiffness = 1000.0
"#;

/// A minimal engine section to append to [`BASE`].
pub const ENGINE: &str = r#"
[engine]
at = "a"
cylinders = 2
bore = 0.1
crank_radius = 0.05
conrod_length = 0.2
pressure = { crank_angle_deg = [0, 90, 180], bar = [50, 10, 0] }
"#;

/// A rubber stage from elements between a and b, to append to [`BASE`].
pub const RUBBER: &str = r#"
[[connection]]
kind = "rubber"
name = "r"
from = "a"
to = "b"
elements = { count = 8, per_side = 4, pitch_diameter = 0.3, radial_stiffness = 6.4e5 }
psi = 1.0
"#;

pub fn error(text: &str) -> ModelError {
    match parse_model(text, "test.toml") {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e,
    }
}

/// 1-based line of the only line containing `needle`.
pub fn line_of(text: &str, needle: &str) -> usize {
    let hits: Vec<usize> = text
        .lines()
        .enumerate()
        .filter(|(_, l)| l.contains(needle))
        .map(|(i, _)| i + 1)
        .collect();
    assert_eq!(hits.len(), 1, "`{needle}` must be on exactly one line");
    hits[0]
}

/// The error names `key`, `line` and a message containing `says`.
pub fn fails_at(text: &str, key: &str, line: usize, says: &str) {
    let e = error(text);
    assert_eq!(e.file.as_deref(), Some("test.toml"), "{e}");
    assert_eq!(e.key, key, "{e}");
    assert_eq!(e.line, Some(line), "{e}");
    assert!(
        e.message.contains(says),
        "message `{}` lacks `{says}`",
        e.message
    );
}

/// As [`fails_at`], the line being the one containing `needle`.
pub fn fails(text: &str, key: &str, needle: &str, says: &str) {
    fails_at(text, key, line_of(text, needle), says);
}

pub fn with(extra: &str) -> String {
    format!("{BASE}{extra}")
}

pub fn replaced(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "`{from}` not in the text");
    text.replacen(from, to, 1)
}
