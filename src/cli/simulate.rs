//! `torsim simulate MODEL --speed-rpm N [--duration-s T] [--rate-hz R] [--csv FILE]` and
//! `torsim simulate MODEL --run-up A:B --duration-s T`: the nonlinear time domain, with
//! the order analysis of the result (the same as `analyse` of its CSV).

use super::analyse::{print_analysis, to_json};
use super::error::CliError;
use super::format::{number, print_warnings};
use super::input::PRESET_PREFIX;
use super::input::{check_load, load_model};
use super::progress::Progress;
use serde_json::{Map, Value, json};
use std::path::Path;
use torsim::files::{OutputGuard, PreparedPair};
use torsim::ratings::{check_run_up_peaks, check_simulated};
use torsim::recording::Run;
use torsim::recording::prepare_recording;
use torsim::signal::{AnalysisOptions, analyse_with};
use torsim::transient::{Method, RunOptions, simulate, to_recording};

/// Options of the command.
#[derive(Debug, clap::Args)]
pub struct SimulateArgs {
    /// Model file or preset:NAME.
    pub model: String,
    /// Steady mean speed of the reference (crank), rpm.
    #[arg(long, conflicts_with = "run_up", required_unless_present = "run_up")]
    pub speed_rpm: Option<f64>,
    /// A linear ramp FROM:TO rpm over --duration-s (run-up, or run-down if TO < FROM).
    #[arg(long, value_name = "FROM:TO")]
    pub run_up: Option<String>,
    /// Recorded duration, s (default 2 for a steady run; required for a ramp).
    #[arg(long)]
    pub duration_s: Option<f64>,
    /// Output sample rate, Hz.
    #[arg(long, default_value_t = 10240.0)]
    pub rate_hz: f64,
    /// Engine load 0..1: picks the pressure curve.
    #[arg(long, default_value_t = 1.0)]
    pub load: f64,
    /// Relative tolerance of the integrator.
    #[arg(long, default_value_t = 1e-5)]
    pub rtol: f64,
    /// Time the start speed is held after settling and before recording, s: a
    /// self-heating rubber stage warms meanwhile (settling holds its temperature).
    #[arg(long, default_value_t = 0.0)]
    pub hold_s: f64,
    /// Integrator: auto (exact for steady runs of linear models, else Dormand–Prince unless
    /// the model is stiff), explicit, implicit (ROS2) or exact.
    #[arg(long, value_enum, default_value_t = MethodArg::Auto)]
    pub method: MethodArg,
    /// Write the run as a recording (CSV and its .toml sidecar).
    #[arg(long)]
    pub csv: Option<String>,
    /// Print one JSON document.
    #[arg(long)]
    pub json: bool,
}

/// `--method`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MethodArg {
    /// Dormand–Prince unless the model is stiff.
    Auto,
    /// Dormand–Prince 5(4).
    Explicit,
    /// ROS2, linearly implicit.
    Implicit,
    /// Exact discretization (steady runs of linear models without an engine).
    Exact,
}

/// What to run, from the options.
fn run_kind(a: &SimulateArgs) -> Result<Run, CliError> {
    let bad = |m: String| CliError::input(anyhow::anyhow!(m));
    match (&a.run_up, a.speed_rpm) {
        (Some(spec), _) => {
            let (from, to) = spec
                .split_once(':')
                .and_then(|(f, t)| {
                    Some((f.trim().parse::<f64>().ok()?, t.trim().parse::<f64>().ok()?))
                })
                .ok_or_else(|| {
                    bad(format!(
                        "--run-up {spec}: expected FROM:TO in rpm, e.g. 400:2000"
                    ))
                })?;
            let duration_s = a
                .duration_s
                .ok_or_else(|| bad("--run-up needs --duration-s".into()))?;
            Ok(Run::ramp(from, to, duration_s))
        }
        (None, Some(speed_rpm)) => Ok(Run::steady(speed_rpm, a.duration_s.unwrap_or(2.0))),
        (None, None) => Err(bad("give --speed-rpm N or --run-up FROM:TO".into())),
    }
}

/// Runs the command.
pub fn run(a: &SimulateArgs) -> Result<(), CliError> {
    let model = load_model(&a.model)?;
    // Issue 13: refuse an output that would replace the model before running anything.
    if let Some(path) = &a.csv {
        let mut guard = OutputGuard::new();
        if !a.model.starts_with(PRESET_PREFIX) {
            guard.input("the model", Path::new(&a.model));
        }
        guard
            .recording_output("--csv", Path::new(path))
            .map_err(CliError::input)?;
    }
    let kind = run_kind(a)?;
    let method = match a.method {
        MethodArg::Auto => Method::Auto,
        MethodArg::Explicit => Method::Explicit,
        MethodArg::Implicit => Method::Implicit,
        MethodArg::Exact => Method::Exact,
    };
    let options = RunOptions {
        load: check_load(a.load)?,
        rate_hz: a.rate_hz,
        rtol: a.rtol,
        hold_s: a.hold_s,
        method,
        ..RunOptions::default()
    };
    if !(a.rtol > 0.0 && a.rtol < 0.1) {
        return Err(CliError::input(anyhow::anyhow!(
            "--rtol {}: must be within 0 … 0.1",
            a.rtol
        )));
    }
    let progress = Progress::new("simulating");
    let result = simulate(&model, kind, options, &mut |f| progress.set(f));
    progress.finish();
    let sim = result.map_err(|e| match e {
        torsim::transient::TransientError::Model(_)
        | torsim::transient::TransientError::Limit(_)
        | torsim::transient::TransientError::Physics(_) => CliError::input(e),
        _ => CliError::failed(e),
    })?;
    let mut warnings = sim.warnings.clone();
    if !sim.settling.converged {
        warnings.push(format!(
            "the run did not settle within {} s (cycle-to-cycle change {:.2e}); recorded anyway",
            options.max_settle_s, sim.settling.change
        ));
    }
    for (c, chain) in &sim.chains {
        warnings.push(format!(
            "rubber stage `{}`: causal Maxwell chain fitted over {:.1} … {:.0} Hz with {} arms; worst error {:.1} % in stiffness, {:.1} % in loss against seed 000's law",
            sim.connection_names[*c],
            chain.band_hz[0],
            chain.band_hz[1],
            chain.arms.len(),
            100.0 * chain.stiffness_error,
            100.0 * chain.loss_error
        ));
    }
    print_warnings(&warnings);
    let recording = to_recording(&sim, kind, options.load, model.strokes(), &model.name);
    // The temporaries are written now (a recording with NaN is refused before any file),
    // renamed only once the analysis below succeeded (issue 13).
    let pending = match &a.csv {
        Some(path) => {
            Some(prepare_recording(&recording, Path::new(path)).map_err(CliError::input)?)
        }
        None => None,
    };
    let mut analysis_options = AnalysisOptions::default();
    for (node, ratio) in sim.node_names.iter().zip(&sim.speed_ratio) {
        analysis_options
            .shaft_ratio
            .insert(node.clone(), ratio.abs());
    }
    // The relative speed across each rubber stage (seed 001's n_rel = n_es − n_bs).
    analysis_options.pairs = Some(
        model
            .connections
            .iter()
            .filter(|c| matches!(c.kind, torsim::model::ConnectionKind::Rubber(_)))
            .filter(|c| c.from != torsim::model::GROUND && c.to != torsim::model::GROUND)
            .map(|c| (c.from.clone(), c.to.clone()))
            .collect(),
    );
    let analysis = analyse_with(&recording, &analysis_options).map_err(CliError::failed)?;
    let rated = if kind.is_ramp() {
        check_run_up_peaks(&model, &sim)
    } else {
        check_simulated(&model, &sim, kind.speeds_rpm()[0]).map_err(CliError::failed)?
    };
    let ratings = super::ratings::Ratings::of_runs(rated, &model);
    // The files are renamed once everything that can fail has succeeded; dropping
    // `pending` on an early return removes its temporaries.
    let commit = |pending: Option<PreparedPair>| match pending {
        Some(p) => p.commit().map_err(CliError::input),
        None => Ok(()),
    };
    if a.json {
        let mut doc = to_json(&analysis)?;
        if let Value::Object(map) = &mut doc {
            let mut power = Map::new();
            for (c, w) in &sim.power_loss_w {
                power.insert(sim.connection_names[*c].clone(), number(*w, "power loss")?);
            }
            map.insert("power_loss_w".into(), Value::Object(power));
            let mut temperatures = Map::new();
            for (c, t) in &sim.temperature_c {
                temperatures.insert(sim.connection_names[*c].clone(), json!(t.last()));
            }
            map.insert("final_temperature_c".into(), Value::Object(temperatures));
            map.insert(
                "settling".into(),
                json!({"cycles": sim.settling.cycles, "time_s": sim.settling.time_s, "converged": sim.settling.converged}),
            );
            map.insert(
                "steps".into(),
                json!({"accepted": sim.steps.0, "rejected": sim.steps.1}),
            );
            map.insert("ratings".into(), super::ratings::json(&ratings)?.0);
        }
        commit(pending)?;
        return super::format::print_json(&doc);
    }
    let [from_rpm, to_rpm] = kind.speeds_rpm();
    let duration_s = kind.duration_s;
    let label = if kind.is_ramp() {
        format!(
            "{}: ramp {from_rpm} → {to_rpm} rpm in {duration_s} s",
            model.name
        )
    } else {
        format!("{}: steady {from_rpm} rpm, {duration_s} s", model.name)
    };
    let mut extra = String::new();
    for (c, w) in &sim.power_loss_w {
        if *w > 0.0 {
            extra += &format!("power loss `{}`: {w:.3} W\n", sim.connection_names[*c]);
        }
    }
    extra += &super::ratings::text(&ratings);
    commit(pending)?;
    print_analysis(&label, &analysis, &extra)
}
