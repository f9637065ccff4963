//! The commands of `spec/cli.md`: thin wrappers that parse options, call the library and
//! print a table or one JSON document.

mod analyse;
mod campbell;
mod check;
mod compare;
mod coupling;
mod diagnose;
pub mod error;
mod format;
mod input;
// Only the window opens a model by this name; a build without it has no caller.
#[cfg_attr(not(feature = "gui"), allow(unused_imports))]
pub use input::load_model;
mod modes;
mod progress;
mod response;
mod simulate;
mod synth;

use clap::{Parser, Subcommand};
use error::CliError;

/// Torsional vibration of engine drivelines with highly flexible rubber couplings.
///
/// MODEL is a model file (spec/model-format.md) or `preset:NAME` for a preset shipped in
/// the binary (cng-genset, diagnosis-bench, test-rig-45sh, test-rig-60sh, test-rig-70sh,
/// test-rig-mod1, test-rig-mod2, test-rig-mod3).
#[derive(Debug, Parser)]
#[command(name = "torsim", version, args_conflicts_with_subcommands = true)]
pub struct Cli {
    /// Model to open (default: the embedded cng-genset preset).
    pub model: Option<String>,
    /// The command; none opens the model.
    #[command(subcommand)]
    pub command: Option<Command>,
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
    match cli.command {
        None => crate::gui::run(cli.model),
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
        Some(Command::Analyse { recording, json }) => analyse::run(&recording, json),
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
