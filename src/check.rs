//! The `[expect]` checks of a model (`spec/model-format.md`): natural frequencies in a
//! band, critical speeds of an order in a band, orders free of resonance in the operating
//! range, and (an extension, issue 16) rated couplings within their ratings. Evaluated at
//! the default operating point (full load, each stage's temperature).

use crate::modal::{critical_speed_rpm, modes};
use crate::model::Model;
use crate::physics::{OperatingPoint, PhysicsError, System};

/// One check and its outcome.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckOutcome {
    /// `mode_hz`, `critical_rpm`, `no_resonance_in_operating_range` or `within_ratings`.
    pub kind: &'static str,
    /// What was expected, for a person.
    pub expected: String,
    /// What was computed, for a person.
    pub computed: String,
    /// The computed number the check is about (Hz or rpm), when there is one.
    pub value: Option<f64>,
    /// True when the expectation holds.
    pub passed: bool,
}

/// Runs every `[expect]` check of `model`.
pub fn run_checks(model: &Model) -> Result<Vec<CheckOutcome>, PhysicsError> {
    let system = System::new(model, OperatingPoint::default())?;
    let modes = modes(&system)?;
    let freqs: Vec<f64> = modes.iter().map(|m| m.frequency_hz).collect();
    let mut out = Vec::new();
    for e in &model.expect.mode_hz {
        let f = freqs.get(e.mode as usize - 1).copied();
        out.push(CheckOutcome {
            kind: "mode_hz",
            expected: format!("mode {} in {} … {} Hz", e.mode, e.min_hz, e.max_hz),
            computed: match f {
                Some(f) => format!("mode {} at {f:.3} Hz", e.mode),
                None => format!("the model has only {} flexible modes", freqs.len()),
            },
            value: f,
            passed: f.is_some_and(|f| f >= e.min_hz && f <= e.max_hz),
        });
    }
    for e in &model.expect.critical_rpm {
        let speeds: Vec<(usize, f64)> = freqs
            .iter()
            .enumerate()
            .map(|(i, &f)| (i + 1, critical_speed_rpm(e.order, f)))
            .collect();
        let hit = speeds
            .iter()
            .find(|(_, n)| *n >= e.min_rpm && *n <= e.max_rpm);
        let nearest = speeds.iter().min_by(|a, b| {
            let d = |n: f64| (n - e.min_rpm).abs().min((n - e.max_rpm).abs());
            d(a.1).total_cmp(&d(b.1))
        });
        let shown = hit.or(nearest);
        out.push(CheckOutcome {
            kind: "critical_rpm",
            expected: format!(
                "order {} crosses a mode in {} … {} rpm",
                e.order, e.min_rpm, e.max_rpm
            ),
            computed: match shown {
                Some((m, n)) => format!(
                    "order {} crosses mode {m} at {n:.1} rpm{}",
                    e.order,
                    if hit.is_some() {
                        ""
                    } else {
                        " (nearest; none in the band)"
                    }
                ),
                None => "the model has no flexible modes".into(),
            },
            value: shown.map(|s| s.1),
            passed: hit.is_some(),
        });
    }
    if let Some([lo, hi]) = model.operation.operating_range_rpm {
        for &order in &model.expect.no_resonance_in_operating_range {
            let inside: Vec<String> = freqs
                .iter()
                .enumerate()
                .map(|(i, &f)| (i + 1, critical_speed_rpm(order, f)))
                .filter(|(_, n)| *n >= lo && *n <= hi)
                .map(|(m, n)| format!("mode {m} at {n:.1} rpm"))
                .collect();
            out.push(CheckOutcome {
                kind: "no_resonance_in_operating_range",
                expected: format!("order {order} crosses no mode in {lo} … {hi} rpm"),
                computed: if inside.is_empty() {
                    format!("order {order}: no crossing in the operating range")
                } else {
                    format!("order {order} crosses {}", inside.join(", "))
                },
                value: None,
                passed: inside.is_empty(),
            });
        }
    }
    out.extend(rating_checks(model, &system)?);
    Ok(out)
}

/// `within_ratings`: each named stage's worst utilisation of every rating over the
/// operating range (else the speed range), from the forced response at full load over
/// 201 speeds.
fn rating_checks(model: &Model, system: &System) -> Result<Vec<CheckOutcome>, PhysicsError> {
    if model.expect.within_ratings.is_empty() {
        return Ok(Vec::new());
    }
    let [lo, hi] = model
        .operation
        .operating_range_rpm
        .or(model.operation.speed_range_rpm)
        .unwrap_or([100.0, 3000.0]);
    let speeds = crate::modal::speed_grid(lo, hi, (hi - lo) / 200.0);
    let orders = model.orders();
    let excitation = crate::physics::Excitation::new(model, system, 1.0, &orders);
    let response = crate::response::forced_response(system, &excitation, &speeds)?;
    let stages = crate::ratings::check_ratings(model, system, &response);
    let mut out = Vec::new();
    for name in &model.expect.within_ratings {
        let Some(stage) = stages.iter().find(|s| s.connection == *name) else {
            continue;
        };
        for w in stage.worst(None) {
            let at = match w.order {
                Some(q) => format!("order {q} at {:.0} rpm", w.speed_rpm),
                None => format!("{:.0} rpm", w.speed_rpm),
            };
            out.push(CheckOutcome {
                kind: "within_ratings",
                expected: format!(
                    "{name}: {} within its limit in {lo} … {hi} rpm",
                    w.kind.limit_name()
                ),
                computed: format!(
                    "{name}: {:.0} % of {} ({:.0}) at {at}, with S_t and S_f",
                    100.0 * w.utilisation,
                    w.kind.limit_name(),
                    w.limit
                ),
                value: Some(w.utilisation),
                passed: w.utilisation <= 1.0,
            });
        }
    }
    Ok(out)
}
