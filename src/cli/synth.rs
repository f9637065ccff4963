//! `torsim synth MODEL --effect E [--param KEY=VALUE …] --out DIR`: bench-like recordings
//! from a richer model than MODEL (`spec/diagnosis.md`), the truth written apart.
//!
//! DIR gets `model.toml` (the user's model as given), one CSV and sidecar per planned run,
//! `truth.toml` (effect, parameters, parameter errors, seed, measurement, plan, this
//! command) and `truth-model.toml`. The diagnosis reads the first two kinds only.

use super::error::CliError;
use super::format::emit;
use super::input::{PRESET_PREFIX, load_model};
use super::progress::Progress;
use std::path::{Path, PathBuf};
use std::time::Instant;
use torsim::files::{OutputGuard, same_file, write_atomic};
use torsim::model::{presets, save_model_file};
use torsim::recording::write_recording;
use torsim::synth::{
    EffectSpec, Measurement, Plan, PlanDurations, SensorArtifact, Station, SynthError, TRUTH_FILE,
    TRUTH_MODEL_FILE, build_truth, generate, truth_toml,
};

/// Options of the command.
#[derive(Debug, clap::Args)]
pub struct SynthArgs {
    /// The user's model (file or preset:NAME): what the engineer has.
    pub model: String,
    /// The effect the truth adds: none, parameter_error, coupling_amplitude_nonlinearity,
    /// coupling_frequency_dependence, coupling_thermal_drift, hysteretic_damping,
    /// unmodelled_mode, crank_variable_inertia, gear_backlash, cylinder_imbalance,
    /// sensor_artifact.
    #[arg(long)]
    pub effect: String,
    /// An effect parameter, KEY=VALUE (repeatable; see the effect's docs for keys and
    /// defaults).
    #[arg(long = "param", value_name = "KEY=VALUE")]
    pub params: Vec<String>,
    /// Plain errors: every inertia and stiffness off by a seeded factor within ±P %.
    #[arg(long, default_value_t = 0.0, value_name = "P")]
    pub param_error_pct: f64,
    /// Seed of every random draw (errors, noise, jitter, wobble, tape positions).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The recordings to make (TOML, [[run]] tables); default: regimes A–F at full load,
    /// two at part load, one long steady run, one full-load run-up.
    #[arg(long, value_name = "PLAN.toml")]
    pub plan: Option<String>,
    /// Output sample rate, Hz (a plan's run may set its own).
    #[arg(long, default_value_t = 2048.0)]
    pub rate_hz: f64,
    /// A measured station NODE[:zebra|encoder[:LINES]] (repeatable); default: the crank
    /// with a 360-line encoder and the engine side of the first rubber stage with a
    /// 78-line zebra tape.
    #[arg(long = "station", value_name = "STATION")]
    pub stations: Vec<String>,
    /// White noise on every sample, rpm (standard deviation).
    #[arg(long, default_value_t = 0.1)]
    pub noise_rpm: f64,
    /// Timing jitter of every pulse, ns (standard deviation).
    #[arg(long, default_value_t = 20.0)]
    pub jitter_ns: f64,
    /// Slow wobble of the mean speed, % (bound).
    #[arg(long, default_value_t = 0.2)]
    pub wobble_pct: f64,
    /// Main period of the wobble, s.
    #[arg(long, default_value_t = 6.0)]
    pub wobble_period_s: f64,
    /// A sensor artifact besides the effect: tape_joint:NODE:FRACTION or
    /// pitch_error:NODE:DEG (repeatable).
    #[arg(long = "sensor-artifact", value_name = "ARTIFACT")]
    pub artifacts: Vec<String>,
    /// Resolution of the samples, rpm (0: full precision).
    #[arg(long, default_value_t = 0.01)]
    pub resolution_rpm: f64,
    /// Duration of each steady regime of the default plan, s.
    #[arg(long, default_value_t = 4.0)]
    pub regime_s: f64,
    /// Duration of the default plan's long steady run, s.
    #[arg(long, default_value_t = 30.0)]
    pub long_run_s: f64,
    /// Duration of the default plan's run-up, s.
    #[arg(long, default_value_t = 60.0)]
    pub run_up_s: f64,
    /// Output folder (created if missing; files of the same names are replaced).
    #[arg(long)]
    pub out: String,
}

/// Bad input is exit 2; a simulation or measurement that failed is exit 1.
fn cli_error(e: impl Into<SynthError>) -> CliError {
    let e: SynthError = e.into();
    match &e {
        SynthError::Input(_) => CliError::input(e),
        SynthError::Simulation { source, .. } => match source {
            torsim::transient::TransientError::Model(_)
            | torsim::transient::TransientError::Physics(_) => CliError::input(e),
            _ => CliError::failed(e),
        },
        SynthError::Run { .. } => CliError::failed(e),
    }
}

/// The command line as typed, quoted where a shell would need it.
fn command_line() -> String {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let quote = |a: &str| {
        let plain = !a.is_empty()
            && a.chars()
                .all(|c| c.is_ascii_alphanumeric() || "-_./:=,+".contains(c));
        if plain {
            a.to_string()
        } else {
            format!("'{}'", a.replace('\'', r"'\''"))
        }
    };
    std::iter::once("torsim".to_string())
        .chain(args.iter().map(|a| quote(a)))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The user's model text as given (a preset's, or the file's).
fn model_text(arg: &str) -> Result<String, CliError> {
    match arg.strip_prefix(PRESET_PREFIX) {
        Some(name) => presets::preset(name)
            .map(|p| p.text.to_string())
            .ok_or_else(|| CliError::input(anyhow::anyhow!("no preset `{name}`"))),
        None => std::fs::read_to_string(arg)
            .map_err(|e| CliError::input(anyhow::anyhow!("{arg}: cannot read: {e}"))),
    }
}

/// Runs the command.
pub fn run(a: &SynthArgs) -> Result<(), CliError> {
    let started = Instant::now();
    let user = load_model(&a.model)?;
    let text = model_text(&a.model)?;
    let spec = EffectSpec::parse(&a.effect, &a.params).map_err(cli_error)?;
    let plan = match &a.plan {
        Some(path) => {
            let plan_text = std::fs::read_to_string(path)
                .map_err(|e| CliError::input(anyhow::anyhow!("{path}: cannot read: {e}")))?;
            Plan::parse(&plan_text, path).map_err(cli_error)?
        }
        None => {
            let d = PlanDurations {
                regime_s: a.regime_s,
                long_run_s: a.long_run_s,
                run_up_s: a.run_up_s,
            };
            Plan::default_for(&user, d).map_err(cli_error)?
        }
    };
    let stations = if a.stations.is_empty() {
        Station::defaults(&user)
    } else {
        a.stations
            .iter()
            .map(|s| Station::parse(s))
            .collect::<Result<_, _>>()
            .map_err(cli_error)?
    };
    let measurement = Measurement {
        stations,
        rate_hz: a.rate_hz,
        noise_rpm: a.noise_rpm,
        jitter_ns: a.jitter_ns,
        wobble_pct: a.wobble_pct,
        wobble_period_s: a.wobble_period_s,
        artifacts: a
            .artifacts
            .iter()
            .map(|s| SensorArtifact::parse(s))
            .collect::<Result<_, _>>()
            .map_err(cli_error)?,
        resolution_rpm: a.resolution_rpm,
    };
    let truth = build_truth(&user, &spec, a.param_error_pct, a.seed).map_err(cli_error)?;
    let out = PathBuf::from(&a.out);
    let copy_model = guard_outputs(a, &plan, &out)?;
    let progress = Progress::new("synth");
    let result = generate(&truth, &plan, &measurement, &mut |f| progress.set(f));
    progress.finish();
    let recordings = result.map_err(cli_error)?;

    std::fs::create_dir_all(&out)
        .map_err(|e| CliError::input(anyhow::anyhow!("{}: cannot create: {e}", a.out)))?;
    let model_path = out.join(MODEL_FILE);
    if copy_model {
        write_file(&model_path, &text)?;
    }
    let mut bytes = 0;
    let mut lines = String::new();
    for r in &recordings {
        let csv = out.join(format!("{}.csv", r.file));
        write_recording(&r.recording, &csv).map_err(CliError::input)?;
        bytes += file_size(&csv) + file_size(&csv.with_extension("toml"));
        let run = plan.runs.iter().find(|p| p.file == r.file);
        let what = run.map_or(String::new(), |p| p.shape.describe());
        let n = r.recording.time_s.len();
        let rate = n as f64 / run.map_or(1.0, |p| p.duration_s);
        lines += &format!(
            "  {:<24} {:<34} {what}, load {}, {n} samples at {rate:.0} Hz\n",
            format!("{}.csv", r.file),
            r.recording.meta.label.clone().unwrap_or_default(),
            r.recording.meta.load
        );
    }
    let truth_text = truth_toml(
        &truth,
        &plan,
        &measurement,
        a.param_error_pct,
        &command_line(),
    );
    let truth_path = out.join(TRUTH_FILE);
    write_file(&truth_path, &truth_text)?;
    save_model_file(&truth.model, &out.join(TRUTH_MODEL_FILE))?;
    emit(&format!(
        "wrote {} recordings to {} ({:.2} MB of CSV and sidecars) in {:.1} s:\n{lines}\
         truth: {} and {} (effect `{}`; a diagnosis must not read them)\n",
        recordings.len(),
        out.display(),
        bytes as f64 / 1.0e6,
        started.elapsed().as_secs_f64(),
        truth_path.display(),
        out.join(TRUTH_MODEL_FILE).display(),
        truth.effect.effect,
    ))
}

/// The copy of the user's model in `--out`.
const MODEL_FILE: &str = "model.toml";

/// Issue 13: no file `--out` gets may replace an input (the model, the plan) or another
/// output. Returns whether the model is to be copied: not when `--out`'s `model.toml` is
/// the model itself (it would be rewritten with its own text).
fn guard_outputs(a: &SynthArgs, plan: &Plan, out: &Path) -> Result<bool, CliError> {
    let mut guard = OutputGuard::new();
    let mut copy_model = true;
    if !a.model.starts_with(PRESET_PREFIX) {
        guard.input("the model", Path::new(&a.model));
        copy_model = !same_file(Path::new(&a.model), &out.join(MODEL_FILE));
    }
    if let Some(path) = &a.plan {
        guard.input("the plan", Path::new(path));
    }
    let refuse = CliError::input;
    if copy_model {
        guard
            .output("--out", &out.join(MODEL_FILE))
            .map_err(refuse)?;
    }
    for run in &plan.runs {
        let csv = out.join(format!("{}.csv", run.file));
        guard.recording_output("--out", &csv).map_err(refuse)?;
    }
    for name in [TRUTH_FILE, TRUTH_MODEL_FILE] {
        guard.output("--out", &out.join(name)).map_err(refuse)?;
    }
    Ok(copy_model)
}

/// Writes `text` to `path` atomically.
fn write_file(path: &Path, text: &str) -> Result<(), CliError> {
    write_atomic(path, text)
        .map_err(|e| CliError::input(anyhow::anyhow!("{}: cannot write: {e}", path.display())))
}

fn file_size(path: &Path) -> u64 {
    std::fs::metadata(path).map_or(0, |m| m.len())
}
