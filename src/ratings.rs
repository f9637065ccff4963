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

use crate::model::{ConnectionKind, CouplingRating, Model};
use crate::physics::System;
use crate::response::Response;

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

/// The rating checks of every rated rubber stage of `model` over `response` (of `system`,
/// built from `model`). Stages without a rating, or not in the response, are left out.
pub fn check_ratings(model: &Model, system: &System, response: &Response) -> Vec<StageRating> {
    let mut out = Vec::new();
    for (entry, &j) in response.connections.iter().enumerate() {
        let Some(c) = model.connections.get(j) else {
            continue;
        };
        let ConnectionKind::Rubber(stage) = &c.kind else {
            continue;
        };
        let Some(rating) = &stage.rating else {
            continue;
        };
        let s_t = CouplingRating::temperature_factor(stage.temperature_c);
        let mean_nm = system
            .mean_torque_nm
            .get(j)
            .copied()
            .flatten()
            .unwrap_or(0.0)
            .abs();
        let power_limit = rating.permissible_power_loss_at_ambient_w();
        let by_speed = response
            .speeds_rpm
            .iter()
            .enumerate()
            .map(|(s, &n)| {
                let mut checks = vec![check(
                    CheckKind::MeanTorque,
                    n,
                    None,
                    mean_nm * s_t,
                    rating.rated_torque_nm,
                )];
                if let Some(t_max) = rating.max_torque_nm {
                    let peak = response.torque_peak_nm[entry][s].abs().max(mean_nm);
                    checks.push(check(CheckKind::MaxTorque, n, None, peak * s_t, t_max));
                }
                if let Some(t_kw) = rating.permissible_vibratory_torque_nm {
                    let decisive = response
                        .orders
                        .iter()
                        .enumerate()
                        .map(|(q, &order)| {
                            let f_hz = order * n / 60.0;
                            let counted = response.torque_amplitude_nm[entry][q][s]
                                * s_t
                                * CouplingRating::frequency_factor(f_hz);
                            (order, counted)
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
                if let Some(p_kv) = power_limit {
                    let p = response.power_loss_w[entry][s];
                    checks.push(check(CheckKind::PowerLoss, n, None, p, p_kv));
                }
                checks
            })
            .collect();
        out.push(StageRating {
            connection: c.name.clone(),
            connection_index: j,
            rating: rating.clone(),
            temperature_factor: s_t,
            by_speed,
        });
    }
    out
}

/// IAS above this share of a node's mean speed is beyond what the linear response
/// describes: 0.1 (issue 16).
pub const LINEAR_IAS_SHARE: f64 = 0.1;

/// Where the linear response goes beyond its range: a node whose half peak-to-peak IAS
/// exceeds [`LINEAR_IAS_SHARE`] of its own mean speed.
#[derive(Debug, Clone, PartialEq)]
pub struct BeyondLinear {
    /// The node.
    pub node: String,
    /// The speed range where it happens, rpm (engine speed).
    pub speeds_rpm: [f64; 2],
    /// The largest IAS there over the node's mean speed.
    pub worst_share: f64,
}

/// The nodes and speed ranges where the linear response is beyond its range.
pub fn beyond_linear_range(system: &System, response: &Response) -> Vec<BeyondLinear> {
    let mut out = Vec::new();
    for (k, ias) in response.ias_half_peak_to_peak_rpm.iter().enumerate() {
        let ratio = system.speed_ratio.get(k).copied().unwrap_or(1.0).abs();
        let mut found: Option<BeyondLinear> = None;
        for (s, &n) in response.speeds_rpm.iter().enumerate() {
            let share = ias[s] / (n * ratio).max(f64::MIN_POSITIVE);
            if share <= LINEAR_IAS_SHARE {
                continue;
            }
            let b = found.get_or_insert(BeyondLinear {
                node: system.node_names.get(k).cloned().unwrap_or_default(),
                speeds_rpm: [n, n],
                worst_share: share,
            });
            b.speeds_rpm[1] = n;
            b.worst_share = b.worst_share.max(share);
        }
        out.extend(found);
    }
    out
}
