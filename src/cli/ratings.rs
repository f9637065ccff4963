//! The coupling ratings in `torsim response`, `simulate` and `compare` (issue 16): a table
//! of each rated stage's worst utilisation per limit, over every speed computed (the
//! sweep, the run, the regimes) and over the operating range, with a warning line for
//! every limit exceeded; in `response` also a note for every node whose IAS leaves the
//! linear model's range. And the same as JSON.

use super::error::CliError;
use super::format::{numbers, table};
use serde_json::{Value, json};
use torsim::model::Model;
use torsim::physics::System;
use torsim::ratings::{
    BeyondLinear, Check, LINEAR_IAS_SHARE, OutsideAmplitudeLaw, StageRating, beyond_amplitude_law,
    beyond_linear_range, check_ratings,
};
use torsim::response::Response;

/// The rating checks of one command's results.
pub struct Ratings {
    /// Each rated stage.
    pub stages: Vec<StageRating>,
    /// Where the linear response leaves its range.
    pub beyond: Vec<BeyondLinear>,
    /// Where a stage's twist leaves its amplitude law's measured range.
    pub outside_law: Vec<OutsideAmplitudeLaw>,
    /// The model's operating range, rpm.
    pub operating_rpm: Option<[f64; 2]>,
}

impl Ratings {
    /// Time-domain checks (`simulate`, `compare`): the run itself is the check of the
    /// linear range, so there is no linear-range note.
    pub fn of_runs(stages: Vec<StageRating>, model: &Model) -> Self {
        Self {
            stages,
            beyond: Vec::new(),
            outside_law: Vec::new(),
            operating_rpm: model.operation.operating_range_rpm,
        }
    }

    /// Checks every rated stage of the forced response and its linear range.
    pub fn new(model: &Model, system: &System, response: &Response) -> Self {
        Self {
            stages: check_ratings(model, system, response),
            beyond: beyond_linear_range(system, response),
            outside_law: beyond_amplitude_law(model, system, response),
            operating_rpm: model.operation.operating_range_rpm,
        }
    }
}

fn at(c: &Check) -> String {
    match c.order {
        Some(q) => format!("{:.0} rpm, order {q}", c.speed_rpm),
        None => format!("{:.0} rpm", c.speed_rpm),
    }
}

fn unit(c: &Check) -> &'static str {
    match c.kind {
        torsim::ratings::CheckKind::PowerLoss => "W",
        _ => "N·m",
    }
}

/// The human-readable part: a table and warning lines (empty without ratings and with
/// the whole response in the linear range).
pub fn text(r: &Ratings) -> String {
    let mut out = String::new();
    if !r.stages.is_empty() {
        out += "\nCoupling ratings (DIN 740-2; load counted with S_t, and with S_f for T_KW): worst utilisation\n";
        let header: Vec<String> = [
            "stage",
            "limit",
            "value",
            "worst: load at",
            "worst",
            "operating range",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        let mut rows = Vec::new();
        let mut warnings = Vec::new();
        for s in &r.stages {
            let inside = s.worst(r.operating_rpm);
            for w in s.worst(None) {
                let op = inside.iter().find(|c| c.kind == w.kind);
                rows.push(vec![
                    s.connection.clone(),
                    w.kind.limit_name().to_string(),
                    format!("{:.0} {}", w.limit, unit(&w)),
                    format!("{:.0} {} at {}", w.load, unit(&w), at(&w)),
                    format!("{:.0} %", 100.0 * w.utilisation),
                    op.map_or("—".into(), |c| {
                        format!("{:.0} % at {}", 100.0 * c.utilisation, at(c))
                    }),
                ]);
                if let Some(c) = op.filter(|c| c.utilisation > 1.0) {
                    warnings.push(format!(
                        "warning: {} exceeds {} in the operating range: {:.0} % at {}",
                        s.connection,
                        c.kind.limit_name(),
                        100.0 * c.utilisation,
                        at(c)
                    ));
                } else if w.utilisation > 1.0 {
                    warnings.push(format!(
                        "warning: {} exceeds {} at {} ({:.0} %), outside the operating range: \
                         pass it quickly, or at part load",
                        s.connection,
                        w.kind.limit_name(),
                        at(&w),
                        100.0 * w.utilisation
                    ));
                }
            }
        }
        out += &table(&header, &rows);
        for w in warnings {
            out += &w;
            out.push('\n');
        }
    }
    for b in &r.beyond {
        out += &format!(
            "note: at {} the IAS reaches {:.0} % of its mean speed ({:.0}–{:.0} rpm): beyond \
             the linear model's range (above {:.0} %); check it in the time domain\n",
            b.node,
            100.0 * b.worst_share,
            b.speeds_rpm[0],
            b.speeds_rpm[1],
            100.0 * LINEAR_IAS_SHARE
        );
    }
    for o in &r.outside_law {
        out += &format!("note: {o}\n");
    }
    out
}

/// One check; `order` only where there is one (T_KW): the JSON guard refuses null as a
/// number that could not be computed.
fn check_json(c: &Check) -> Value {
    let mut v = json!({
        "limit": c.kind.limit_name(),
        "speed_rpm": c.speed_rpm,
        "load": c.load,
        "limit_value": c.limit,
        "utilisation": c.utilisation,
    });
    if let (Some(order), Value::Object(map)) = (c.order, &mut v) {
        map.insert("order".into(), json!(order));
    }
    v
}

/// The JSON part: `ratings` (per stage: its limits, S_t, the worst check per limit over
/// the sweep and the operating range, and the utilisation per limit at every speed) and
/// `beyond_linear_range` (the nodes, then the stages outside their amplitude law's range
/// as `{connection, speeds_rpm, deformation_mm, range_mm}`).
pub fn json(r: &Ratings) -> Result<(Value, Value), CliError> {
    let mut stages = Vec::new();
    for s in &r.stages {
        let kinds: Vec<_> = s.worst(None).iter().map(|c| c.kind).collect();
        let mut by_limit = serde_json::Map::new();
        for kind in kinds {
            let series: Vec<f64> = s
                .by_speed
                .iter()
                .map(|checks| {
                    checks
                        .iter()
                        .find(|c| c.kind == kind)
                        .map_or(0.0, |c| c.utilisation)
                })
                .collect();
            by_limit.insert(kind.limit_name().into(), numbers(&series, "utilisation")?);
        }
        stages.push(json!({
            "connection": s.connection,
            "temperature_factor": s.temperature_factor,
            "worst": s.worst(None).iter().map(check_json).collect::<Vec<_>>(),
            "worst_in_operating_range": s.worst(r.operating_rpm).iter().map(check_json).collect::<Vec<_>>(),
            "utilisation_by_speed": Value::Object(by_limit),
        }));
    }
    let beyond: Vec<Value> = r
        .beyond
        .iter()
        .map(|b| json!({ "node": b.node, "speeds_rpm": b.speeds_rpm, "worst_ias_share": b.worst_share }))
        .chain(r.outside_law.iter().map(|o| {
            json!({
                "connection": o.connection,
                "speeds_rpm": o.speeds_rpm,
                "deformation_mm": o.deformation_mm,
                "range_mm": o.range_mm,
            })
        }))
        .collect();
    Ok((Value::Array(stages), Value::Array(beyond)))
}
