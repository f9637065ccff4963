//! Loading the model a command names, and the speed grid it sweeps.

use super::error::CliError;
use torsim::model::Model;
pub use torsim::model::PRESET_PREFIX;

/// Reads the model `arg` names: a file path, or `preset:NAME` for a shipped preset
/// ([`torsim::model::load_model`]).
pub fn load_model(arg: &str) -> Result<Model, CliError> {
    Ok(torsim::model::load_model(arg)?.model)
}

/// What a sweep command sweeps: the model, the speeds and the engine load.
#[derive(Debug, Clone, clap::Args)]
pub struct Sweep {
    /// Model file or preset:NAME.
    pub model: String,
    /// First speed, rpm (default: [operation] speed_range_rpm).
    #[arg(long)]
    pub from_rpm: Option<f64>,
    /// Last speed, rpm.
    #[arg(long)]
    pub to_rpm: Option<f64>,
    /// Speed step, rpm (default: 1/200 of the range).
    #[arg(long)]
    pub step_rpm: Option<f64>,
    /// Engine load 0..1: picks the pressure curve and so the mean torque.
    #[arg(long, default_value_t = 1.0)]
    pub load: f64,
}

impl Sweep {
    /// Loads the model and works out the speed grid and the load.
    pub fn resolve(&self) -> Result<(Model, Vec<f64>, f64), CliError> {
        let model = load_model(&self.model)?;
        let speeds = speed_grid(&model, self.from_rpm, self.to_rpm, self.step_rpm)?;
        Ok((model, speeds, check_load(self.load)?))
    }
}

/// The speed grid of a sweep: the options, else `[operation] speed_range_rpm`; the step
/// defaults to 1/200 of the range.
pub fn speed_grid(
    model: &Model,
    from_rpm: Option<f64>,
    to_rpm: Option<f64>,
    step_rpm: Option<f64>,
) -> Result<Vec<f64>, CliError> {
    let range = model.operation.speed_range_rpm;
    let from = from_rpm.or(range.map(|r| r[0]));
    let to = to_rpm.or(range.map(|r| r[1]));
    let (Some(from), Some(to)) = (from, to) else {
        return Err(CliError::input(anyhow::anyhow!(
            "no speed range: give --from-rpm and --to-rpm, or `speed_range_rpm` in [operation]"
        )));
    };
    if !(from.is_finite() && to.is_finite() && from >= 0.0 && to > from) {
        return Err(CliError::input(anyhow::anyhow!(
            "speed range {from} … {to} rpm: need 0 ≤ from < to"
        )));
    }
    let step = step_rpm.unwrap_or((to - from) / 200.0);
    if !(step.is_finite() && step > 0.0) {
        return Err(CliError::input(anyhow::anyhow!(
            "--step-rpm {step}: must be > 0"
        )));
    }
    let limits = torsim::limits::current();
    torsim::limits::check_value(
        "--to-rpm",
        to,
        limits.max_speed_rpm,
        Some("--max-speed-rpm"),
    )
    .map_err(CliError::input)?;
    torsim::limits::check_count(
        "speeds of the sweep (--from-rpm … --to-rpm by --step-rpm)",
        (to - from) / step + 1.0,
        limits.max_sweep_points,
        Some("--max-sweep-points"),
    )
    .map_err(CliError::input)?;
    Ok(torsim::modal::speed_grid(from, to, step))
}

/// Checks a `--load` value.
pub fn check_load(load: f64) -> Result<f64, CliError> {
    if (0.0..=1.0).contains(&load) {
        Ok(load)
    } else {
        Err(CliError::input(anyhow::anyhow!(
            "--load {load}: must be within 0 … 1"
        )))
    }
}
