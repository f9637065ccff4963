//! `torsim compare PRESET… [--speeds-rpm A,B,…]`: design variants side by side — IR per
//! station and power loss per rubber stage at each regime (seed 001 Tables 9–13).

use super::error::CliError;
use super::format::{emit, numbers, outln, print_json, table};
use super::input::{check_load, load_model};
use super::progress::Progress;
use serde_json::{Map, Value, json};
use torsim::compare::{RegimePoint, compare_regimes, model_regimes};
use torsim::transient::RunOptions;

/// Options of the command.
#[derive(Debug, clap::Args)]
pub struct CompareArgs {
    /// Model files or preset:NAME, one per variant.
    #[arg(required = true)]
    pub presets: Vec<String>,
    /// Speeds to compare at, rpm (default: each model's [operation] regimes).
    #[arg(long, value_delimiter = ',')]
    pub speeds_rpm: Option<Vec<f64>>,
    /// Recorded duration of each steady run, s.
    #[arg(long, default_value_t = 1.0)]
    pub duration_s: f64,
    /// Engine load 0..1 when --speeds-rpm is given.
    #[arg(long, default_value_t = 1.0)]
    pub load: f64,
    /// Print one JSON document.
    #[arg(long)]
    pub json: bool,
}

/// Runs the command.
pub fn run(a: &CompareArgs) -> Result<(), CliError> {
    let load = check_load(a.load)?;
    let mut variants = Vec::new();
    let mut text = String::new();
    for file in &a.presets {
        let model = load_model(file)?;
        let regimes: Vec<RegimePoint> = match &a.speeds_rpm {
            Some(speeds) => speeds
                .iter()
                .map(|&s| RegimePoint {
                    label: format!("{s} rpm"),
                    speed_rpm: s,
                    load,
                })
                .collect(),
            None => model_regimes(&model),
        };
        if regimes.is_empty() {
            return Err(CliError::input(anyhow::anyhow!(
                "{file}: no regimes — give --speeds-rpm, or `regimes` in [operation]"
            )));
        }
        let progress = Progress::new(&format!("comparing {file}"));
        let result = compare_regimes(
            &model,
            &regimes,
            a.duration_s,
            RunOptions::default(),
            &mut |f| progress.set(f),
        );
        progress.finish();
        let r = result.map_err(CliError::failed)?;
        let labels: Vec<String> = r.regimes.iter().map(|x| x.label.clone()).collect();
        let mut ir = Map::new();
        let mut rms = Map::new();
        for (k, node) in r.nodes.iter().enumerate() {
            ir.insert(node.clone(), numbers(&r.irregularity_pct[k], "IR")?);
            rms.insert(node.clone(), numbers(&r.rms_rpm[k], "RMS")?);
        }
        let mut loss = Map::new();
        for (s, stage) in r.stages.iter().enumerate() {
            loss.insert(stage.clone(), numbers(&r.power_loss_w[s], "power loss")?);
        }
        let ratings = super::ratings::Ratings::of_runs(r.ratings.clone(), &model);
        let (rated, _) = super::ratings::json(&ratings)?;
        variants.push(json!({
            "ratings": rated,
            "file": file,
            "name": model.name,
            "regimes": labels,
            "speeds_rpm": numbers(&r.regimes.iter().map(|x| x.speed_rpm).collect::<Vec<_>>(), "speed")?,
            "irregularity_pct": Value::Object(ir),
            "rms_rpm": Value::Object(rms),
            "power_loss_w": Value::Object(loss),
        }));
        let mut header = vec![String::new()];
        header.extend(labels.iter().cloned());
        let mut rows: Vec<Vec<String>> = r
            .nodes
            .iter()
            .enumerate()
            .map(|(k, node)| {
                let mut row = vec![format!("IR {node} [%]")];
                row.extend(r.irregularity_pct[k].iter().map(|v| format!("{v:.2}")));
                row
            })
            .collect();
        for (s, stage) in r.stages.iter().enumerate() {
            let mut row = vec![format!("P {stage} [W]")];
            row.extend(r.power_loss_w[s].iter().map(|v| format!("{v:.2}")));
            rows.push(row);
        }
        outln!(text, "{file} — {}", model.name);
        text += &table(&header, &rows);
        text += &super::ratings::text(&ratings);
        outln!(text);
    }
    if a.json {
        return print_json(&json!({ "variants": variants }));
    }
    emit(&text)
}
