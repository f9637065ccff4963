//! The commands of `spec/cli.md`: thin wrappers that parse options, call the library and
//! print a table or one JSON document.

mod analyse;
mod campbell;
mod check;
mod compare;
mod coupling;
mod diagnose;
mod diagnose_power;
pub mod error;
mod format;
mod input;
mod json_guard;
// Only the window opens a model by this name; a build without it has no caller.
#[cfg_attr(not(feature = "gui"), allow(unused_imports))]
mod modes;
mod progress;
pub mod ratings;
mod response;
mod simulate;
mod synth;
mod values;

use clap::{Parser, Subcommand};
use error::CliError;

/// Torsional vibration of engine drivelines with highly flexible rubber couplings.
///
/// MODEL is a model file (spec/model-format.md) or `preset:NAME` for a preset shipped in
/// the binary (cng-genset, genset-20dof, diagnosis-bench, two-inertia, three-inertia,
/// test-rig-45sh, test-rig-60sh, test-rig-70sh, test-rig-mod1, test-rig-mod2,
/// test-rig-mod3).
#[derive(Debug, Parser)]
#[command(name = "torsim", version, args_conflicts_with_subcommands = true)]
pub struct Cli {
    /// Model to open (default: the embedded cng-genset preset).
    pub model: Option<String>,
    /// The command; none opens the model.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Limits raised (or lowered) for this run.
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// The `--max-*` flags: each replaces one default of `torsim::limits::Limits` for this
/// run (issue 13: sizes are bounded by documented defaults that a flag can raise).
#[derive(Debug, Clone, Copy, clap::Args)]
pub struct LimitArgs {
    /// Most samples per channel of a simulated run or a recording (default 2^27).
    #[arg(long, global = true, value_name = "N")]
    pub max_samples: Option<usize>,
    /// Highest engine order analysed or swept (default 100).
    #[arg(long, global = true, value_name = "ORDER")]
    pub max_order: Option<f64>,
    /// Most cylinders of an engine (default 64).
    #[arg(long, global = true, value_name = "N")]
    pub max_cylinders: Option<usize>,
    /// Highest shaft speed, rpm (default 100000).
    #[arg(long, global = true, value_name = "RPM")]
    pub max_speed_rpm: Option<f64>,
    /// Most speeds, and speeds × orders, of a Campbell or response sweep (default 10^6).
    #[arg(long, global = true, value_name = "N")]
    pub max_sweep_points: Option<usize>,
}

impl LimitArgs {
    /// The limits in force with these flags over the defaults; refuses a limit that is
    /// not a finite number > 0.
    pub fn limits(&self) -> Result<torsim::limits::Limits, CliError> {
        let mut limits = torsim::limits::Limits::DEFAULT;
        for (flag, value) in [
            ("--max-order", self.max_order),
            ("--max-speed-rpm", self.max_speed_rpm),
        ] {
            if let Some(v) = value
                && !(v.is_finite() && v > 0.0)
            {
                return Err(CliError::input(anyhow::anyhow!(
                    "{flag} {v}: must be a finite number > 0"
                )));
            }
        }
        for (flag, value) in [
            ("--max-samples", self.max_samples),
            ("--max-cylinders", self.max_cylinders),
            ("--max-sweep-points", self.max_sweep_points),
        ] {
            if value == Some(0) {
                return Err(CliError::input(anyhow::anyhow!("{flag} 0: must be > 0")));
            }
        }
        limits.max_samples = self.max_samples.unwrap_or(limits.max_samples);
        limits.max_order = self.max_order.unwrap_or(limits.max_order);
        limits.max_cylinders = self.max_cylinders.unwrap_or(limits.max_cylinders);
        limits.max_speed_rpm = self.max_speed_rpm.unwrap_or(limits.max_speed_rpm);
        limits.max_sweep_points = self.max_sweep_points.unwrap_or(limits.max_sweep_points);
        Ok(limits)
    }
}

/// Headless commands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Undamped natural frequencies, damped frequencies, damping ratios and mode shapes.
    Modes {
        /// Model file or preset:NAME.
        model: String,
        /// Reference speed, rpm (the linear model's modes do not depend on it).
        #[arg(long)]
        speed_rpm: Option<f64>,
        /// Engine load 0..1: the mean torque that twists the rubber stages.
        #[arg(long, default_value_t = 1.0)]
        load: f64,
        /// Print one JSON document.
        #[arg(long)]
        json: bool,
    },
    /// Modes over speed, order lines and their crossings.
    Campbell {
        /// Model, speeds and load.
        #[command(flatten)]
        sweep: input::Sweep,
        /// Write the diagram as CSV.
        #[arg(long)]
        csv: Option<String>,
        /// Print one JSON document.
        #[arg(long)]
        json: bool,
    },
    /// Steady forced response order by order over a speed sweep.
    Response {
        /// Model, speeds and load.
        #[command(flatten)]
        sweep: input::Sweep,
        /// Orders, comma separated (default: [operation] orders).
        #[arg(long, value_delimiter = ',')]
        orders: Option<Vec<f64>>,
        /// Print one JSON document.
        #[arg(long)]
        json: bool,
    },
    /// Nonlinear time-domain simulation: a steady run or a speed ramp, with its order analysis.
    Simulate(simulate::SimulateArgs),
    /// Design variants side by side: IR per station and power loss per rubber stage at each regime.
    Compare(compare::CompareArgs),
    /// Bench-like recordings from a richer model (one effect, parameter errors, noise), the truth apart.
    Synth(synth::SynthArgs),
    /// Where the model and recordings disagree, the physics it left out, fitted and shown to improve on held-out data.
    Diagnose(diagnose::DiagnoseArgs),
    /// Runs the [expect] checks of presets (all of ./presets/ when none named).
    Check {
        /// Model files or preset:NAME.
        presets: Vec<String>,
        /// Print one JSON document.
        #[arg(long)]
        json: bool,
    },
    /// Order analysis of a recording: RMS, irregularity ratio, orders, STFT of run-ups.
    Analyse {
        /// The recording's CSV (its sidecar, same stem `.toml`, beside it).
        recording: String,
        /// Over-range or impossible samples: refuse (list them), interpolate (from their
        /// neighbours) or drop (keep the longest stretch without them).
        #[arg(long, default_value = "refuse", value_parser = analyse::parse_bad_samples)]
        bad_samples: torsim::recording::BadSamples,
        /// Print one JSON document.
        #[arg(long)]
        json: bool,
    },
    /// Each rubber stage's dynamic stiffness and damping by the seed 000 law.
    Coupling {
        /// Model file or preset:NAME.
        model: String,
        /// Vibration frequency, Hz (default: static, α_f = 1).
        #[arg(long)]
        frequency_hz: Option<f64>,
        /// Rubber temperature, °C (default: each stage's temperature_c).
        #[arg(long)]
        temperature_c: Option<f64>,
        /// Twist across the stage, degrees (default 0).
        #[arg(long, default_value_t = 0.0)]
        twist_deg: f64,
        /// Print one JSON document.
        #[arg(long)]
        json: bool,
    },
}

/// Runs the parsed command line.
pub fn run(cli: Cli) -> Result<(), CliError> {
    torsim::limits::set(cli.limits.limits()?);
    match cli.command {
        None => crate::gui::run(cli.model).map_err(|e| {
            if e.is_input() {
                CliError::input(e)
            } else {
                CliError::failed(e)
            }
        }),
        Some(Command::Modes {
            model,
            speed_rpm,
            load,
            json,
        }) => modes::run(&model, speed_rpm, load, json),
        Some(Command::Campbell { sweep, csv, json }) => campbell::run(&sweep, csv.as_deref(), json),
        Some(Command::Response {
            sweep,
            orders,
            json,
        }) => response::run(&sweep, orders, json),
        Some(Command::Check { presets, json }) => check::run(&presets, json),
        Some(Command::Analyse {
            recording,
            bad_samples,
            json,
        }) => analyse::run(&recording, bad_samples, json),
        Some(Command::Simulate(args)) => simulate::run(&args),
        Some(Command::Compare(args)) => compare::run(&args),
        Some(Command::Synth(args)) => synth::run(&args),
        Some(Command::Diagnose(args)) => diagnose::run(&args),
        Some(Command::Coupling {
            model,
            frequency_hz,
            temperature_c,
            twist_deg,
            json,
        }) => coupling::run(&model, frequency_hz, temperature_c, twist_deg, json),
    }
}
