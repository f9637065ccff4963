//! Which node and connection names a model may use: only those every output format can
//! carry and torsim can read back (issue 13, "node names are restricted to what every
//! output format can carry").
//!
//! A node name becomes the CSV columns `<node>_rpm` and `<node>_rad`, a connection name
//! the column `torque_<connection>_nm` (`spec/recording-format.md`); both become JSON keys,
//! TOML keys of a sidecar (`[sensors.<node>]`, quoted when needed) and HTML text (escaped).
//! JSON, TOML and HTML carry any string; the CSV header does not:
//! - the recording reader splits the header on `,` and trims each name, so a comma or a
//!   leading or trailing space would not read back;
//! - a line break ends the header, and other control characters are invisible in every
//!   viewer;
//! - `"` starts a quoted field in every other CSV reader (spreadsheets, pandas);
//! - invisible format characters (a BOM, zero-width spaces, direction marks) make two
//!   names that look equal differ.
//!
//! Inside a name, plain spaces and any other printable Unicode are accepted.

use super::validate::{Check, fail};

/// Characters that print as nothing: BOM, zero-width spaces and joiners, direction marks
/// and embeddings, word joiner and invisible operators.
const INVISIBLE: [std::ops::RangeInclusive<char>; 4] = [
    '\u{200B}'..='\u{200F}',
    '\u{202A}'..='\u{202E}',
    '\u{2060}'..='\u{2064}',
    '\u{FEFF}'..='\u{FEFF}',
];

/// Why `name` cannot be carried by every output format, or `None` when it can.
pub fn name_problem(name: &str) -> Option<String> {
    if name.trim().is_empty() {
        return Some(if name.is_empty() {
            "is empty".into()
        } else {
            "has only spaces".into()
        });
    }
    if name.starts_with(char::is_whitespace) || name.ends_with(char::is_whitespace) {
        return Some("starts or ends with a space".into());
    }
    let bad = name.chars().find(|&c| {
        c == ','
            || c == '"'
            || c.is_control()
            || (c.is_whitespace() && c != ' ')
            || INVISIBLE.iter().any(|r| r.contains(&c))
    })?;
    Some(match bad {
        ',' => "contains a comma".into(),
        '"' => "contains a double quote".into(),
        c => format!(
            "contains the control or invisible character U+{:04X}",
            u32::from(c)
        ),
    })
}

/// `name` (a node or connection name, `what`) at `key` must be one every output format
/// can carry (see the module docs).
pub(crate) fn check_name(key: &str, what: &str, name: &str) -> Check {
    match name_problem(name) {
        None => Ok(()),
        Some(problem) => fail(
            key,
            format!(
                "{what} name {name:?} {problem}; {what} names must be non-empty, without \
                 commas, double quotes, control or invisible characters, or leading or \
                 trailing spaces, so that every output format (CSV columns, JSON, TOML, \
                 HTML) can carry them"
            ),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::name_problem;

    #[test]
    fn accepts_what_every_format_carries() {
        for ok in [
            "engine",
            "throw 1",
            "crank_12",
            "Kurbelwelle-Ü",
            "a.b(2)/c#3",
            "x_nm",
        ] {
            assert_eq!(name_problem(ok), None, "{ok}");
        }
    }

    #[test]
    fn refuses_what_a_csv_header_cannot_carry() {
        let cases = [
            ("", "is empty"),
            ("   ", "only spaces"),
            (" a", "starts or ends"),
            ("a ", "starts or ends"),
            ("a,b", "comma"),
            ("a\"b", "double quote"),
            ("a\nb", "U+000A"),
            ("a\rb", "U+000D"),
            ("a\tb", "U+0009"),
            ("a\u{FEFF}b", "U+FEFF"),
            ("a\u{200B}b", "U+200B"),
            ("a\u{2028}b", "U+2028"),
            ("a\u{A0}b", "U+00A0"),
        ];
        for (name, says) in cases {
            let problem = name_problem(name).unwrap_or_default();
            assert!(problem.contains(says), "{name:?}: {problem}");
        }
    }
}
