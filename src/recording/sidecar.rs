//! The TOML sidecar of a recording: reading with errors that name the line and key, and
//! writing it back.

use std::collections::BTreeMap;

use toml_edit::{Document, Item, TableLike};

use super::error::{Reason, RecordingError};
use super::integrity::CsvCheck;
use super::types::{RecordingMeta, RunKind, Sensor};

const KEYS: [&str; 11] = [
    "format",
    "kind",
    "reference",
    "speed_rpm",
    "load",
    "temperature_c",
    "label",
    "strokes",
    "sensors",
    "csv_sha256",
    "csv_rows",
];
/// Absolute zero, °C: no temperature is below it (issue 13).
pub const ABSOLUTE_ZERO_C: f64 = -273.15;
/// Highest rubber temperature accepted, °C: natural, nitrile and silicone rubbers
/// decompose below 300 °C, so a higher value is a unit mistake (K or °F), not a bench
/// run (issue 13).
pub const MAX_TEMPERATURE_C: f64 = 300.0;

const SENSOR_KEYS: [&str; 2] = ["kind", "lines_per_rev"];

/// 1-based line of a byte offset in `text`.
fn line_of(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

struct Ctx<'a> {
    text: &'a str,
    file: &'a str,
}

impl Ctx<'_> {
    fn err(
        &self,
        key: &str,
        span: Option<std::ops::Range<usize>>,
        reason: Reason,
    ) -> RecordingError {
        let e = RecordingError::new(self.file, reason).at_key(key);
        match span {
            Some(s) => e.at_line(line_of(self.text, s.start)),
            None => e,
        }
    }

    /// The item at `key` of `table` (path `path`), with the line of its key.
    fn get<'t>(
        &self,
        table: &'t dyn TableLike,
        key: &str,
    ) -> Option<(&'t Item, Option<std::ops::Range<usize>>)> {
        table
            .get_key_value(key)
            .map(|(k, item)| (item, k.span().or_else(|| item.span())))
    }

    fn allow(
        &self,
        table: &dyn TableLike,
        path: &str,
        known: &[&str],
    ) -> Result<(), RecordingError> {
        for (key, _) in table.iter() {
            if !known.contains(&key) {
                let span = table.key(key).and_then(|k| k.span());
                let full = if path.is_empty() {
                    key.to_string()
                } else {
                    format!("{path}.{key}")
                };
                return Err(self.err(&full, span, Reason::UnknownKey(known.join(", "))));
            }
        }
        Ok(())
    }

    fn number(
        &self,
        table: &dyn TableLike,
        key: &str,
        path: &str,
    ) -> Result<Option<f64>, RecordingError> {
        let Some((item, span)) = self.get(table, key) else {
            return Ok(None);
        };
        let x = item
            .as_float()
            .or_else(|| item.as_integer().map(|i| i as f64));
        match x {
            Some(x) if x.is_finite() => Ok(Some(x)),
            _ => Err(self.err(
                path,
                span,
                Reason::BadValue("expected a finite number".into()),
            )),
        }
    }

    fn string(
        &self,
        table: &dyn TableLike,
        key: &str,
        path: &str,
    ) -> Result<Option<String>, RecordingError> {
        let Some((item, span)) = self.get(table, key) else {
            return Ok(None);
        };
        item.as_str()
            .map(|s| Some(s.to_string()))
            .ok_or_else(|| self.err(path, span, Reason::BadValue("expected a string".into())))
    }

    fn integer(
        &self,
        table: &dyn TableLike,
        key: &str,
        path: &str,
    ) -> Result<Option<i64>, RecordingError> {
        let Some((item, span)) = self.get(table, key) else {
            return Ok(None);
        };
        item.as_integer()
            .map(Some)
            .ok_or_else(|| self.err(path, span, Reason::BadValue("expected an integer".into())))
    }

    fn bad(&self, table: &dyn TableLike, key: &str, message: String) -> RecordingError {
        let span = self.get(table, key).and_then(|(_, s)| s);
        self.err(key, span, Reason::BadValue(message))
    }
}

/// The sidecar's TOML document; a syntax error names the file and its line.
fn parse_document<'t>(text: &'t str, file: &str) -> Result<Document<&'t str>, RecordingError> {
    Document::parse(text).map_err(|e| {
        let err = RecordingError::new(file, Reason::Toml(e.message().trim().to_string()));
        match e.span() {
            Some(s) => err.at_line(line_of(text, s.start)),
            None => err,
        }
    })
}

/// Parses a sidecar's text; `file` names it in errors.
pub fn parse_sidecar(text: &str, file: &str) -> Result<RecordingMeta, RecordingError> {
    let cx = Ctx { text, file };
    let doc = parse_document(text, file)?;
    let root = doc.as_table();
    cx.allow(root, "", &KEYS)?;
    let missing = |key: &str| RecordingError::new(file, Reason::MissingKey).at_key(key);
    match cx.integer(root, "format", "format")? {
        Some(1) => {}
        Some(n) => {
            return Err(cx.bad(
                root,
                "format",
                format!("recording format {n} is not supported (this reader knows format 1)"),
            ));
        }
        None => return Err(missing("format")),
    }
    let kind_text = cx
        .string(root, "kind", "kind")?
        .ok_or_else(|| missing("kind"))?;
    let kind = RunKind::parse(&kind_text).ok_or_else(|| {
        cx.bad(
            root,
            "kind",
            format!("`{kind_text}` is neither \"steady\" nor \"run-up\""),
        )
    })?;
    let reference = cx
        .string(root, "reference", "reference")?
        .ok_or_else(|| missing("reference"))?;
    let mut meta = RecordingMeta::new(kind, reference);
    meta.speed_rpm = cx.number(root, "speed_rpm", "speed_rpm")?;
    if let Some(n) = meta.speed_rpm.filter(|n| *n <= 0.0) {
        return Err(cx.bad(root, "speed_rpm", format!("{n} rpm: must be > 0")));
    }
    meta.load = cx.number(root, "load", "load")?.unwrap_or(1.0);
    if !(0.0..=1.0).contains(&meta.load) {
        return Err(cx.bad(root, "load", format!("{}: must be within 0 … 1", meta.load)));
    }
    meta.temperature_c = cx.number(root, "temperature_c", "temperature_c")?;
    if let Some(t) = meta
        .temperature_c
        .filter(|t| !(ABSOLUTE_ZERO_C..=MAX_TEMPERATURE_C).contains(t))
    {
        return Err(cx.bad(
            root,
            "temperature_c",
            format!(
                "{t} °C: must be within {ABSOLUTE_ZERO_C} … {MAX_TEMPERATURE_C} °C (absolute zero to \
                 above where any elastomer decomposes; a value outside is a unit mistake such as K or °F)"
            ),
        ));
    }
    meta.label = cx.string(root, "label", "label")?;
    match cx.integer(root, "strokes", "strokes")? {
        None => {}
        Some(s @ (2 | 4)) => meta.strokes = s as u32,
        Some(s) => return Err(cx.bad(root, "strokes", format!("{s}: must be 2 or 4"))),
    }
    if let Some((item, span)) = cx.get(root, "sensors") {
        // Inline tables are tables (issue 13): `sensors = { engine = { kind = … } }`.
        let table = item.as_table_like().ok_or_else(|| {
            cx.err(
                "sensors",
                span.clone(),
                Reason::BadValue("expected a table `[sensors.<node>]`".into()),
            )
        })?;
        meta.sensors = sensors(&cx, table)?;
    }
    Ok(meta)
}

/// The CSV's fingerprint recorded in a sidecar (`csv_sha256` and `csv_rows`, written
/// together by [`sidecar_text`]); `None` when the sidecar has neither (a bench's own).
/// Errors name the key and its line.
pub fn parse_csv_check(text: &str, file: &str) -> Result<Option<CsvCheck>, RecordingError> {
    let cx = Ctx { text, file };
    let doc = parse_document(text, file)?;
    let root = doc.as_table();
    let sha256 = cx.string(root, "csv_sha256", "csv_sha256")?;
    let rows = cx.integer(root, "csv_rows", "csv_rows")?;
    match (sha256, rows) {
        (None, None) => Ok(None),
        (Some(sha256), Some(rows)) => {
            if !CsvCheck::valid_hash(&sha256) {
                return Err(cx.bad(root, "csv_sha256", "expected 64 hex digits".into()));
            }
            let rows = u64::try_from(rows)
                .map_err(|_| cx.bad(root, "csv_rows", format!("{rows}: must be ≥ 0")))?;
            Ok(Some(CsvCheck { sha256, rows }))
        }
        (Some(_), None) => Err(RecordingError::new(file, Reason::MissingKey).at_key("csv_rows")),
        (None, Some(_)) => Err(RecordingError::new(file, Reason::MissingKey).at_key("csv_sha256")),
    }
}

fn sensors(cx: &Ctx, table: &dyn TableLike) -> Result<BTreeMap<String, Sensor>, RecordingError> {
    let mut out = BTreeMap::new();
    for (node, item) in table.iter() {
        let path = format!("sensors.{node}");
        let span = table.key(node).and_then(|k| k.span());
        let t = item.as_table_like().ok_or_else(|| {
            cx.err(
                &path,
                span.clone(),
                Reason::BadValue("expected a table".into()),
            )
        })?;
        cx.allow(t, &path, &SENSOR_KEYS)?;
        let kind = cx
            .string(t, "kind", &format!("{path}.kind"))?
            .ok_or_else(|| cx.err(&format!("{path}.kind"), span.clone(), Reason::MissingKey))?;
        let lines_path = format!("{path}.lines_per_rev");
        let lines_per_rev = match cx.integer(t, "lines_per_rev", &lines_path)? {
            None => None,
            Some(n) => Some(u32::try_from(n).ok().filter(|n| *n > 0).ok_or_else(|| {
                cx.err(
                    &lines_path,
                    span.clone(),
                    Reason::BadValue(format!("{n}: must be a positive integer")),
                )
            })?),
        };
        out.insert(
            node.to_string(),
            Sensor {
                kind,
                lines_per_rev,
            },
        );
    }
    Ok(out)
}

/// The sidecar as TOML text; keys equal to their defaults are left out, numbers in
/// Rust's shortest round-trip form.
pub fn sidecar_string(meta: &RecordingMeta) -> String {
    sidecar_text(meta, None)
}

/// The sidecar as TOML text with the CSV's fingerprint (`csv_sha256`, `csv_rows`) when
/// given; see [`sidecar_string`].
pub fn sidecar_text(meta: &RecordingMeta, check: Option<&CsvCheck>) -> String {
    let s = |x: &str| toml_edit::Value::from(x).to_string();
    let mut out = format!(
        "format = 1\nkind = {}\nreference = {}\n",
        s(meta.kind.as_str()),
        s(&meta.reference)
    );
    let num = |x: f64| {
        if x.fract() == 0.0 && x.abs() < 1e15 {
            format!("{x:.1}")
        } else {
            // `{:?}` keeps an exponent (`1e300`): `{}` would print 301 digits, which TOML
            // reads as an overflowing integer (found by the sidecar fuzz target).
            format!("{x:?}")
        }
    };
    if let Some(n) = meta.speed_rpm {
        out += &format!("speed_rpm = {}\n", num(n));
    }
    if meta.load != 1.0 {
        out += &format!("load = {}\n", num(meta.load));
    }
    if let Some(t) = meta.temperature_c {
        out += &format!("temperature_c = {}\n", num(t));
    }
    if let Some(label) = &meta.label {
        out += &format!("label = {}\n", s(label));
    }
    if meta.strokes != 4 {
        out += &format!("strokes = {}\n", meta.strokes);
    }
    if let Some(check) = check {
        out += &format!(
            "csv_sha256 = {}\ncsv_rows = {}\n",
            s(&check.sha256),
            check.rows
        );
    }
    for (node, sensor) in &meta.sensors {
        out += &format!(
            "\n[sensors.{}]\nkind = {}\n",
            toml_edit::Key::new(node.as_str()),
            s(&sensor.kind)
        );
        if let Some(n) = sensor.lines_per_rev {
            out += &format!("lines_per_rev = {n}\n");
        }
    }
    out
}

/// 1-based line of a top-level `key` in a sidecar's text, when it is there (for errors
/// found after parsing, such as a `speed_rpm` the data contradict).
pub fn key_line(text: &str, key: &str) -> Option<usize> {
    let doc = Document::parse(text).ok()?;
    let span = doc.as_table().key(key)?.span()?;
    Some(line_of(text, span.start))
}
