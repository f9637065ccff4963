//! Coupling ratings checked against the forced response (issue 16; DIN 740-2, the
//! catalogue values of [`crate::model::rating`]). At each speed of a sweep, for each
//! rubber stage with a `rating`:
//!
//! - mean torque: |T_N|·S_t against T_KN;
//! - largest torque over a cycle (mean plus every order with its phase): T_max·S_t
//!   against T_Kmax;
//! - vibratory torque, order by order: T̂_q·S_t·S_f(f_q) against T_KW, f_q = q·n/60 the
//!   order's frequency, S_f = √(f/10 Hz) above 10 Hz; the decisive order is kept;
//! - power loss, all orders: P against P_KV derated to the stage's ambient.
//!
//! Each check is a utilisation, actual over permissible: above 1 the limit is exceeded.
//! Beside them, [`beyond_linear_range`] says where the linear response itself should not
//! be trusted: IAS above 10 % of a node's mean speed.
//!
//! The checks are one rule ([`checks_at`]) on one operating point's loads
//! ([`StageLoads`]), whichever view computed them: the forced response
//! ([`check_ratings`], `response` and the window) or a steady time-domain run
//! ([`check_simulated`], `simulate` and `compare`), so both views judge alike.

mod linear_range;
mod response;
mod simulated;

pub use linear_range::{
    BeyondLinear, LINEAR_IAS_SHARE, OutsideAmplitudeLaw, beyond_amplitude_law, beyond_linear_range,
};
pub use response::check_ratings;
pub use simulated::{check_run_up_peaks, check_simulated, merge_points};

use crate::model::{ConnectionKind, CouplingRating, Model, RubberStage};

/// What a check compares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CheckKind {
    /// Mean torque against T_KN.
    MeanTorque,
    /// Largest torque over a cycle against T_Kmax.
    MaxTorque,
    /// The decisive order's vibratory torque against T_KW.
    VibratoryTorque,
    /// Power loss against P_KV at the ambient.
    PowerLoss,
}

impl CheckKind {
    /// A short name for tables: `T_KN`, `T_Kmax`, `T_KW`, `P_KV`.
    pub fn limit_name(self) -> &'static str {
        match self {
            Self::MeanTorque => "T_KN",
            Self::MaxTorque => "T_Kmax",
            Self::VibratoryTorque => "T_KW",
            Self::PowerLoss => "P_KV",
        }
    }
}

/// One check at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    /// What is checked.
    pub kind: CheckKind,
    /// Engine speed, rpm.
    pub speed_rpm: f64,
    /// The decisive order (vibratory torque only).
    pub order: Option<f64>,
    /// The load as the limit counts it (with S_t and S_f), N·m or W.
    pub load: f64,
    /// The limit, N·m or W.
    pub limit: f64,
    /// `load / limit`: above 1 the limit is exceeded.
    pub utilisation: f64,
}

/// The checks of one rated stage over a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct StageRating {
    /// The connection's name.
    pub connection: String,
    /// Its index in the model's connections.
    pub connection_index: usize,
    /// The rating checked.
    pub rating: CouplingRating,
    /// S_t at the stage's temperature.
    pub temperature_factor: f64,
    /// Per speed of the sweep, every check the rating allows.
    pub by_speed: Vec<Vec<Check>>,
}

impl StageRating {
    /// The highest utilisation of each kind within `range_rpm` (all speeds when `None`).
    pub fn worst(&self, range_rpm: Option<[f64; 2]>) -> Vec<Check> {
        let inside =
            |c: &&Check| range_rpm.is_none_or(|[a, b]| c.speed_rpm >= a && c.speed_rpm <= b);
        let mut out: Vec<Check> = Vec::new();
        for c in self.by_speed.iter().flatten().filter(inside) {
            match out.iter_mut().find(|w| w.kind == c.kind) {
                Some(w) if c.utilisation > w.utilisation => *w = *c,
                Some(_) => {}
                None => out.push(*c),
            }
        }
        out
    }
}

/// What one rated stage carries at one operating point, from whichever view computed it.
#[derive(Debug, Clone, PartialEq)]
pub struct StageLoads {
    /// Engine (reference) speed, rpm.
    pub speed_rpm: f64,
    /// Mean torque, N·m (its magnitude is checked).
    pub mean_nm: f64,
    /// Largest torque magnitude over a cycle, N·m.
    pub peak_nm: f64,
    /// Vibratory torque by engine order: `(order, zero-to-peak amplitude in N·m)`.
    pub orders_nm: Vec<(f64, f64)>,
    /// Mean power dissipated in the stage, W.
    pub power_loss_w: f64,
}

fn check(kind: CheckKind, speed_rpm: f64, order: Option<f64>, load: f64, limit: f64) -> Check {
    Check {
        kind,
        speed_rpm,
        order,
        load,
        limit,
        utilisation: load / limit,
    }
}

/// Every check `rating` allows on `loads`, torques counted with the temperature factor
/// `s_t` (and the frequency factor S_f for T_KW).
pub fn checks_at(rating: &CouplingRating, s_t: f64, loads: &StageLoads) -> Vec<Check> {
    let n = loads.speed_rpm;
    let mean_nm = loads.mean_nm.abs();
    let mut checks = vec![check(
        CheckKind::MeanTorque,
        n,
        None,
        mean_nm * s_t,
        rating.rated_torque_nm,
    )];
    if let Some(t_max) = rating.max_torque_nm {
        let peak = loads.peak_nm.abs().max(mean_nm);
        checks.push(check(CheckKind::MaxTorque, n, None, peak * s_t, t_max));
    }
    if let Some(t_kw) = rating.permissible_vibratory_torque_nm {
        let decisive = loads
            .orders_nm
            .iter()
            .map(|&(order, amplitude_nm)| {
                let f_hz = order * n / 60.0;
                (
                    order,
                    amplitude_nm * s_t * CouplingRating::frequency_factor(f_hz),
                )
            })
            .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((order, counted)) = decisive {
            checks.push(check(
                CheckKind::VibratoryTorque,
                n,
                Some(order),
                counted,
                t_kw,
            ));
        }
    }
    if let Some(p_kv) = rating.permissible_power_loss_at_ambient_w() {
        checks.push(check(
            CheckKind::PowerLoss,
            n,
            None,
            loads.power_loss_w,
            p_kv,
        ));
    }
    checks
}

/// The rated rubber stages of `model`: `(connection index, stage, rating)`.
fn rated_stages(model: &Model) -> impl Iterator<Item = (usize, &RubberStage, &CouplingRating)> {
    model
        .connections
        .iter()
        .enumerate()
        .filter_map(|(j, c)| match &c.kind {
            ConnectionKind::Rubber(stage) => stage.rating.as_ref().map(|r| (j, stage, r)),
            _ => None,
        })
}
