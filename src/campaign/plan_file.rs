//! Plan files for `torsim synth --plan`: TOML `[[run]]` tables, read with errors that
//! name the file, the line and the key:
//!
//! ```toml
//! [[run]]
//! file = "regime-a"      # stem of the CSV and its sidecar
//! label = "Regime A"     # the sidecar's label (default: the file stem)
//! kind = "steady"        # or "run-up"
//! speed_rpm = 3000       # steady: mean speed of the reference (crank)
//! duration_s = 4
//! load = 1.0             # default 1
//! rate_hz = 2000         # default: the command's --rate-hz
//!
//! [[run]]
//! file = "run-up"
//! kind = "run-up"
//! from_rpm = 1000
//! to_rpm = 6000
//! duration_s = 60
//! ```

use super::CampaignError;
use super::plan::{Plan, PlannedRun};
use crate::recording::RunShape;
use toml_edit::{Document, Item, Table};

impl Plan {
    /// Reads a plan file's text; errors name `file`, the line and the key.
    pub fn parse(text: &str, file: &str) -> Result<Self, CampaignError> {
        let line_of = |span: Option<std::ops::Range<usize>>| {
            span.map_or(String::new(), |s| {
                format!(
                    ":{}",
                    text[..s.start.min(text.len())].matches('\n').count() + 1
                )
            })
        };
        let doc = Document::parse(text).map_err(|e| {
            CampaignError::Input(format!(
                "{file}{}: {}",
                line_of(e.span()),
                e.message().trim()
            ))
        })?;
        let root = doc.as_table();
        if let Some((k, _)) = root.iter().find(|(k, _)| *k != "run") {
            let span = root.key(k).and_then(|k| k.span());
            return Err(CampaignError::Input(format!(
                "{file}{}: unknown key `{k}` (a plan has [[run]] tables)",
                line_of(span)
            )));
        }
        let Some(runs) = root.get("run").and_then(Item::as_array_of_tables) else {
            return Err(CampaignError::Input(format!("{file}: no [[run]] tables")));
        };
        let mut out = Vec::new();
        for (i, t) in runs.iter().enumerate() {
            out.push(run(t, i, file, &line_of)?);
        }
        let mut seen = std::collections::HashSet::new();
        for r in &out {
            if !seen.insert(r.file.clone()) {
                return Err(CampaignError::Input(format!(
                    "{file}: two runs write `{}`",
                    r.file
                )));
            }
        }
        Ok(Self { runs: out })
    }
}

const RUN_KEYS: [&str; 10] = [
    "file",
    "label",
    "kind",
    "speed_rpm",
    "from_rpm",
    "to_rpm",
    "duration_s",
    "load",
    "rate_hz",
    "comment",
];

/// One `[[run]]` table.
fn run(
    t: &Table,
    i: usize,
    file: &str,
    line_of: &dyn Fn(Option<std::ops::Range<usize>>) -> String,
) -> Result<PlannedRun, CampaignError> {
    let at = |key: &str| {
        let span = t.key(key).and_then(|k| k.span()).or_else(|| t.span());
        format!("{file}{}: run[{i}].{key}", line_of(span))
    };
    if let Some((k, _)) = t.iter().find(|(k, _)| !RUN_KEYS.contains(k)) {
        return Err(CampaignError::Input(format!(
            "{}: unknown key (known: {})",
            at(k),
            RUN_KEYS.join(", ")
        )));
    }
    let number = |key: &str| -> Result<Option<f64>, CampaignError> {
        match t.get(key) {
            None => Ok(None),
            Some(item) => item
                .as_float()
                .or_else(|| item.as_integer().map(|v| v as f64))
                .filter(|v| v.is_finite() && *v > 0.0)
                .map(Some)
                .ok_or_else(|| CampaignError::Input(format!("{}: expected a number > 0", at(key)))),
        }
    };
    let string = |key: &str| -> Result<Option<String>, CampaignError> {
        match t.get(key) {
            None => Ok(None),
            Some(item) => item
                .as_str()
                .map(|s| Some(s.to_string()))
                .ok_or_else(|| CampaignError::Input(format!("{}: expected a string", at(key)))),
        }
    };
    let required = |key: &str| {
        number(key)?.ok_or_else(|| CampaignError::Input(format!("{}: missing", at(key))))
    };
    let file_stem =
        string("file")?.ok_or_else(|| CampaignError::Input(format!("{}: missing", at("file"))))?;
    if file_stem.is_empty()
        || !file_stem
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
    {
        return Err(CampaignError::Input(format!(
            "{}: `{file_stem}` must be letters, digits, - and _",
            at("file")
        )));
    }
    let duration_s = required("duration_s")?;
    let shape = match string("kind")?.as_deref() {
        Some("steady") => RunShape::steady(required("speed_rpm")?, duration_s),
        Some("run-up") => RunShape::Ramp {
            from_rpm: required("from_rpm")?,
            to_rpm: required("to_rpm")?,
        },
        other => {
            return Err(CampaignError::Input(format!(
                "{}: {} (expected \"steady\" or \"run-up\")",
                at("kind"),
                other.map_or("missing".to_string(), |k| format!("`{k}`"))
            )));
        }
    };
    let load = match t.get("load") {
        None => 1.0,
        Some(item) => item
            .as_float()
            .or_else(|| item.as_integer().map(|v| v as f64))
            .filter(|v| (0.0..=1.0).contains(v))
            .ok_or_else(|| CampaignError::Input(format!("{}: expected 0 … 1", at("load"))))?,
    };
    Ok(PlannedRun {
        label: string("label")?.unwrap_or_else(|| file_stem.clone()),
        file: file_stem,
        shape,
        duration_s,
        load,
        rate_hz: number("rate_hz")?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_names_errors() {
        let text = "[[run]]\nfile = \"a\"\nkind = \"steady\"\nspeed_rpm = 3000\nduration_s = 2\n\n\
                    [[run]]\nfile = \"up\"\nkind = \"run-up\"\nfrom_rpm = 1000\nto_rpm = 6000\n\
                    duration_s = 20\nrate_hz = 1000\nload = 0.5\n";
        let plan = Plan::parse(text, "p.toml").unwrap();
        assert_eq!(plan.runs.len(), 2);
        assert_eq!(plan.runs[0].label, "a");
        assert_eq!(plan.runs[1].rate_hz, Some(1000.0));
        assert_eq!(plan.runs[1].load, 0.5);
        let bad = text.replace("speed_rpm = 3000", "speed = 3000");
        let e = Plan::parse(&bad, "p.toml").unwrap_err().to_string();
        assert!(e.contains("p.toml:4: run[0].speed"), "{e}");
        let bad = text.replace("\"run-up\"", "\"ramp\"");
        let e = Plan::parse(&bad, "p.toml").unwrap_err().to_string();
        assert!(e.contains("run[1].kind") && e.contains("`ramp`"), "{e}");
        assert!(Plan::parse("x = 1", "p").is_err());
    }
}
