//! The diagnosis benchmark (issue 14, item 4): draws cases, runs `torsim diagnose …
//! --json` on each, scores the verdict against the truth and tabulates a confusion
//! matrix, per-class accuracy, place right/wrong, false physics on controls, held-out fits
//! worse than the user's model, and the time per case.

use crate::effects::CLASSES;
use crate::redraw::write_case;
use crate::write::CaseFiles;
use serde_json::Value;
use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;
use std::time::Instant;

/// The score of one case.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    pub truth: String,
    pub verdict: String,
    /// The verdict counts as right (controls: `none` or `parameter_error`).
    pub right: bool,
    /// Where the effect sits, when the class has a place and the verdict is right.
    pub place: Option<Place>,
    pub fit_before: Option<f64>,
    pub fit_after: Option<f64>,
}

/// How the verdict's place compares with the truth's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// The named place is the truth's.
    Right,
    /// The named place is another, and the report does not list the truth's as
    /// indistinguishable from it.
    Wrong,
    /// The named place is another, but the report says the recordings cannot tell it from
    /// the truth's (`equivalent_places`). Recordings without an angle reference carry no
    /// phase, so e.g. every cylinder of an imbalance predicts the same amplitudes.
    Unresolvable,
}

impl Place {
    /// The word in `results.csv`.
    pub fn word(self) -> &'static str {
        match self {
            Place::Right => "right",
            Place::Wrong => "wrong",
            Place::Unresolvable => "unresolvable",
        }
    }
}

/// Whether `got` (a place as the report prints it) is one of `ok`.
fn is_place(ok: &[String], got: &str) -> bool {
    ok.iter().any(|o| {
        o == got || o.parse::<f64>().is_ok() && o.parse::<f64>().ok() == got.parse::<f64>().ok()
    })
}

/// Scores a `torsim diagnose --json` report against the truth of `case`.
pub fn score(case: &CaseFiles, report: &Value) -> Outcome {
    let verdict = report["verdict"]["effect"]
        .as_str()
        .unwrap_or("?")
        .to_string();
    let control = case.class == "none" || case.class == "parameter_error";
    let right = if control {
        verdict == "none" || verdict == "parameter_error"
    } else {
        verdict == case.class
    };
    let place = match (&case.place, right) {
        (Some((key, ok)), true) => {
            let p = &report["verdict"]["parameters"];
            let got = match &p[key.as_str()] {
                Value::String(s) => Some(s.clone()),
                Value::Number(n) => n.as_f64().map(|x| format!("{x}")),
                _ => p["node"].as_str().map(str::to_string),
            };
            let equivalent = report["verdict"]["equivalent_places"]
                .as_array()
                .map(|a| a.iter().filter_map(|v| v.as_str()).any(|g| is_place(ok, g)))
                .unwrap_or(false);
            Some(match got {
                Some(g) if is_place(ok, &g) => Place::Right,
                _ if equivalent => Place::Unresolvable,
                _ => Place::Wrong,
            })
        }
        _ => None,
    };
    Outcome {
        truth: case.class.clone(),
        verdict,
        right,
        place,
        fit_before: report["fit"]["before"].as_f64(),
        fit_after: report["fit"]["after"].as_f64(),
    }
}

/// One benchmark row.
#[derive(Debug, Clone)]
pub struct Row {
    pub seed: u64,
    pub form: String,
    pub outcome: Result<Outcome, String>,
    pub seconds: f64,
    /// What the campaign exercised of the effect ([`crate::exercise::Exercise::headline`]:
    /// the largest fraction of samples inside a gear's play, or the largest secant
    /// stiffening of an amplitude law); `None` for the classes not measured.
    pub exercised: Option<f64>,
    /// Which draw of the seed was diagnosed: 0, or a redraw after draws no bench could
    /// run ([`crate::redraw::MAX_DRAWS`]).
    pub draw: u64,
    /// How plainly the campaign shows the effect: the largest `z` of
    /// [`crate::visibility`]; `None` for a control or a failed draw.
    pub visible_z: Option<f64>,
}

/// Draws and diagnoses the case of `seed` in `dir`.
pub fn run_case(torsim: &Path, seed: u64, dir: &Path) -> Row {
    let files = match write_case(seed, None, dir) {
        Ok(f) => f,
        Err(e) => {
            return Row {
                seed,
                form: "?".into(),
                outcome: Err(format!("draw: {e}")),
                seconds: 0.0,
                exercised: None,
                draw: 0,
                visible_z: None,
            };
        }
    };
    let start = Instant::now();
    let out = Command::new(torsim)
        .arg("diagnose")
        .arg(&files.model)
        .args(&files.recordings)
        .arg("--json")
        .output();
    let seconds = start.elapsed().as_secs_f64();
    let outcome = match out {
        Err(e) => Err(format!("cannot run {}: {e}", torsim.display())),
        Ok(o) if !o.status.success() => Err(String::from_utf8_lossy(&o.stderr)
            .lines()
            .last()
            .unwrap_or("failed")
            .to_string()),
        Ok(o) => {
            // Kept beside the case for a later look at what was confused with what.
            let _ = std::fs::write(dir.join("report.json"), &o.stdout);
            serde_json::from_slice::<Value>(&o.stdout)
                .map_err(|e| format!("report is not JSON: {e}"))
                .map(|v| score(&files, &v))
        }
    };
    let all: Vec<_> = files.exercise.iter().map(|(_, e)| *e).collect();
    Row {
        seed,
        form: files.form,
        outcome,
        seconds,
        exercised: crate::exercise::Exercise::headline(&all),
        draw: files.draw,
        visible_z: files.visibility.as_ref().map(|v| v.z_max),
    }
}

/// The README-ready markdown summary of `rows`.
pub fn summary(rows: &[Row], first: u64, last: u64) -> String {
    let mut verdicts: Vec<String> = CLASSES.iter().map(|s| s.to_string()).collect();
    verdicts.push("error".into());
    let mut s = format!(
        "Seeds {first}–{last}, {} cases.\n\n| truth \\ verdict |",
        rows.len()
    );
    for v in &verdicts {
        let _ = write!(s, " {} |", abbreviate(v));
    }
    s.push_str(" right | place right/wrong/unresolvable |\n|---|");
    for _ in 0..verdicts.len() + 2 {
        s.push_str("---|");
    }
    s.push('\n');
    let (mut right_all, mut false_physics, mut worse, mut errors) = (0, 0, 0, 0);
    for class in CLASSES {
        let mine: Vec<&Row> = rows.iter().filter(|r| class_of_row(r) == class).collect();
        if mine.is_empty() {
            continue;
        }
        let _ = write!(s, "| {class} |");
        for v in &verdicts {
            let n = mine.iter().filter(|r| verdict_of(r) == *v).count();
            let _ = write!(
                s,
                " {} |",
                if n == 0 { String::new() } else { n.to_string() }
            );
        }
        let right = mine
            .iter()
            .filter(|r| r.outcome.as_ref().is_ok_and(|o| o.right))
            .count();
        right_all += right;
        let places = |want: Place| {
            mine.iter()
                .filter(|r| r.outcome.as_ref().is_ok_and(|o| o.place == Some(want)))
                .count()
        };
        let (pr, pw, pu) = (
            places(Place::Right),
            places(Place::Wrong),
            places(Place::Unresolvable),
        );
        let _ = writeln!(s, " {right}/{} | {pr}/{pw}/{pu} |", mine.len());
        for r in &mine {
            match &r.outcome {
                Ok(o) => {
                    if (class == "none" || class == "parameter_error") && !o.right {
                        false_physics += 1;
                    }
                    if let (Some(b), Some(a)) = (o.fit_before, o.fit_after)
                        && a > b
                    {
                        worse += 1;
                    }
                }
                Err(_) => errors += 1,
            }
        }
    }
    let mut times: Vec<f64> = rows.iter().map(|r| r.seconds).collect();
    times.sort_by(f64::total_cmp);
    let median = times.get(times.len() / 2).copied().unwrap_or(0.0);
    let max = times.last().copied().unwrap_or(0.0);
    let redrawn = rows.iter().filter(|r| r.draw > 0).count();
    let _ = writeln!(
        s,
        "\nOverall right: {right_all}/{} ({:.0} %). False physics on controls: {false_physics}. Held-out fit worse than the user's model: {worse}. Errors: {errors}. Seeds drawn again because no bench could run the first draw: {redrawn}. Diagnosis time per case: median {median:.1} s, max {max:.1} s.",
        rows.len(),
        100.0 * right_all as f64 / rows.len().max(1) as f64
    );
    s
}

fn abbreviate(v: &str) -> String {
    v.split('_')
        .map(|w| w.chars().next().unwrap_or('?'))
        .collect::<String>()
}

fn class_of_row(r: &Row) -> String {
    match &r.outcome {
        Ok(o) => o.truth.clone(),
        Err(_) => crate::draw::class_of(r.seed).to_string(),
    }
}

fn verdict_of(r: &Row) -> String {
    match &r.outcome {
        Ok(o) => o.verdict.clone(),
        Err(_) => "error".into(),
    }
}

/// `results.csv`: one row per case. `exercised` is [`Row::exercised`] and `visible_z`
/// [`Row::visible_z`], empty where not measured.
pub fn results_csv(rows: &[Row]) -> String {
    let mut s = String::from(
        "seed,truth,form,verdict,right,place,fit_before,fit_after,seconds,error,exercised,draw,visible_z\n",
    );
    for r in rows {
        let num = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v}"));
        let exercised = r.exercised.map_or(String::new(), |v| format!("{v:.4}"));
        let visible = r.visible_z.map_or(String::new(), |v| format!("{v:.2}"));
        match &r.outcome {
            Ok(o) => {
                let place = o.place.map_or("", Place::word);
                let _ = writeln!(
                    s,
                    "{},{},{},{},{},{place},{},{},{:.2},,{exercised},{},{visible}",
                    r.seed,
                    o.truth,
                    r.form,
                    o.verdict,
                    o.right,
                    num(o.fit_before),
                    num(o.fit_after),
                    r.seconds,
                    r.draw
                );
            }
            Err(e) => {
                let _ = writeln!(
                    s,
                    "{},{},{},error,false,,,,{:.2},\"{}\",{exercised},{},{visible}",
                    r.seed,
                    class_of_row(r),
                    r.form,
                    r.seconds,
                    e.replace('"', "'"),
                    r.draw
                );
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn imbalance_case() -> CaseFiles {
        CaseFiles {
            model: "m.toml".into(),
            recordings: Vec::new(),
            truth: "truth.toml".into(),
            class: "cylinder_imbalance".into(),
            form: "pressure_scale".into(),
            place: Some(("cylinder".into(), vec!["6".into()])),
            exercise: Vec::new(),
            draw: 0,
            visibility: None,
        }
    }

    fn report(effect: &str, cylinder: &str, equivalent: &[&str]) -> Value {
        serde_json::json!({
            "verdict": {
                "effect": effect,
                "parameters": { "cylinder": cylinder, "pressure_scale": 1.19 },
                "equivalent_places": equivalent,
            },
            "fit": { "before": 100.0, "after": 2.0 },
        })
    }

    #[test]
    fn place_is_right_wrong_or_unresolvable() {
        let case = imbalance_case();
        let right = score(&case, &report("cylinder_imbalance", "6", &[]));
        assert_eq!(right.place, Some(Place::Right));
        // Another cylinder that the report says it cannot tell from the truth's.
        let unresolved = score(&case, &report("cylinder_imbalance", "4", &["1", "6"]));
        assert_eq!(unresolved.place, Some(Place::Unresolvable));
        // Another cylinder, and the truth's not among the equivalent ones.
        let wrong = score(&case, &report("cylinder_imbalance", "4", &["1", "2"]));
        assert_eq!(wrong.place, Some(Place::Wrong));
        // A wrong verdict has no place to score.
        let other = score(&case, &report("sensor_artifact", "6", &[]));
        assert!(!other.right && other.place.is_none());
        assert_eq!(other.fit_after, Some(2.0));
    }
}
