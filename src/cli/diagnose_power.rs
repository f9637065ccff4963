//! `torsim diagnose MODEL --power [--plan PLAN.toml] [--noise-rpm X] [--jitter-ns J]
//! [--json]`: what a campaign can detect and tell apart, before it is run (issue 14,
//! item 6). No recordings: the plan defaults to `torsim synth`'s default campaign, the
//! bench to its default stations, 2048 Hz, 0.1 rpm white noise and 20 ns pulse jitter.

use super::diagnose::DiagnoseArgs;
use super::error::CliError;
use super::format::{emit, outln, print_json, table};
use super::input::load_model;
use super::progress::Progress;
use torsim::diagnose::power::PowerReport;
use torsim::diagnose::power_plan::Bench;
use torsim::diagnose::power_run::power;
use torsim::synth::{Plan, PlanDurations};

/// Runs `diagnose --power`.
pub fn run(a: &DiagnoseArgs, threads: usize, max_order: f64) -> Result<(), CliError> {
    let model = load_model(&a.model)?;
    let plan = match &a.plan {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .map_err(|e| CliError::input(anyhow::anyhow!("{path}: cannot read: {e}")))?;
            Plan::parse(&text, path).map_err(CliError::input)?
        }
        None => Plan::default_for(&model, PlanDurations::default()).map_err(CliError::input)?,
    };
    let mut bench = Bench::default_for(&model);
    bench.max_order = max_order;
    for (name, v, slot) in [
        ("--noise-rpm", a.noise_rpm, &mut bench.noise_rpm),
        ("--jitter-ns", a.jitter_ns, &mut bench.jitter_ns),
    ] {
        if let Some(v) = v {
            if !(v.is_finite() && (0.0..=1.0e3).contains(&v)) {
                return Err(CliError::input(anyhow::anyhow!(
                    "{name} {v}: must be within 0 … 1000"
                )));
            }
            *slot = v;
        }
    }
    if bench.noise_rpm == 0.0 && bench.jitter_ns == 0.0 {
        return Err(CliError::input(anyhow::anyhow!(
            "--noise-rpm 0 with --jitter-ns 0: a campaign without noise detects everything"
        )));
    }
    let progress = Progress::new("power");
    let result = power(&model, &plan, &bench, threads, &mut |f, stage| {
        progress.message(&format!("power: {stage}"));
        progress.set(f)
    });
    progress.finish();
    let report = result.map_err(|e| CliError::failed(anyhow::anyhow!(e)))?;
    if a.json {
        let doc = serde_json::to_value(&report).map_err(CliError::failed)?;
        return print_json(&doc);
    }
    emit(&summary(&report, &model.name))
}

/// A number with 3 significant digits.
fn sig(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let digits = (2 - v.abs().log10().floor() as i32).max(0) as usize;
    if v.abs() >= 1e5 || v.abs() < 1e-3 {
        format!("{v:.2e}")
    } else {
        format!("{v:.digits$}")
    }
}

/// The tables for a person.
fn summary(r: &PowerReport, model_name: &str) -> String {
    let mut text = String::new();
    outln!(
        text,
        "{model_name}: {} planned runs, {} observables, stations {}; noise {} rpm + {} ns \
         jitter at {} Hz; {:.1} s",
        r.runs.len(),
        r.observables,
        r.stations.join(", "),
        r.noise_rpm,
        r.jitter_ns,
        r.rate_hz,
        r.elapsed_s
    );
    outln!(
        text,
        "detectable: χ² test at 5 % with 80 % power (λ ≥ {:.2}) after the best recalibration \
         of the plain parameters\nnamed from: the size the diagnosis names it at (held-out \
         χ²/N above 2, two scatters better than the user's model, the margin over the plain \
         fit)\n",
        r.lambda_detect
    );
    let header: Vec<String> = [
        "effect",
        "place",
        "detectable size",
        "unit",
        "× typical",
        "λ at typical",
        "detectable",
        "named from",
        "as parameter",
    ]
    .map(String::from)
    .to_vec();
    let rows: Vec<Vec<String>> = r
        .effects
        .iter()
        .map(|e| {
            vec![
                e.effect.clone(),
                e.place.clone(),
                e.detectable_size.map_or("—".into(), sig),
                e.unit.clone(),
                e.detectable_relative.map_or("—".into(), sig),
                sig(e.lambda_typical),
                if e.detectable { "yes" } else { "no" }.into(),
                e.named_size.map_or("—".into(), sig),
                e.detectable_parameter.clone(),
            ]
        })
        .collect();
    text += &table(&header, &rows);
    let bad: Vec<_> = r.pairs.iter().filter(|p| !p.separable).collect();
    outln!(
        text,
        "\ncannot be told apart (ρ = share of an effect's λ another's best fit leaves; < 0.25):"
    );
    if bad.is_empty() {
        outln!(
            text,
            "  none: every two effects separate at twice their detectable size"
        );
    }
    for p in bad {
        outln!(
            text,
            "  {} / {}: ρ = {} / {}",
            p.a,
            p.b,
            sig(p.share_a),
            sig(p.share_b)
        );
    }
    if !r.additions.is_empty() {
        outln!(
            text,
            "\nwhat to add (measure: λ after the other's fit, or λ at typical size):"
        );
    }
    for a in &r.additions {
        outln!(
            text,
            "  {}: add {} (λ {} → {})",
            a.target,
            a.add,
            sig(a.before),
            sig(a.after)
        );
    }
    text
}
