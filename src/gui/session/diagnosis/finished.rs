//! A finished diagnosis: the model it ran on, the report, the model with the verdict
//! applied (`torsim::diagnose::accept::accepted_model`) and, for a person, what
//! accepting changes. Built on the diagnosis thread.

use std::sync::Arc;
use torsim::diagnose::Report;
use torsim::diagnose::accept::accepted_model;
use torsim::diagnose::report::ParameterValue;
use torsim::diagnose::surrogate::{plain_parameters, value_of};
use torsim::model::Model;

/// A finished diagnosis.
#[derive(Debug, Clone)]
pub struct Finished {
    /// The model the diagnosis ran on.
    pub model: Model,
    /// The report.
    pub report: Arc<Report>,
    /// The model with the verdict applied, or why it cannot be built.
    pub accepted: Result<Model, String>,
    /// What accepting changes, one line each (empty: nothing).
    pub changes: Vec<String>,
}

impl Finished {
    /// The report of a diagnosis of `model`, with its accepted model.
    pub fn new(model: Model, report: Report) -> Self {
        let accepted = accepted_model(&model, &report);
        let changes = match &accepted {
            Ok(after) => changes(&model, after, &report),
            Err(_) => Vec::new(),
        };
        Self {
            model,
            report: Arc::new(report),
            accepted,
            changes,
        }
    }

    /// The accepted model when it differs from the diagnosed one.
    pub fn change(&self) -> Option<&Model> {
        self.accepted.as_ref().ok().filter(|m| **m != self.model)
    }
}

/// A value with four significant digits.
pub fn sig4(v: f64) -> String {
    crate::gui::views::plots::fmt(v)
}

/// A parameter's value for a person.
pub fn value_text(v: &ParameterValue) -> String {
    match v {
        ParameterValue::Number(x) => sig4(*x),
        ParameterValue::Text(t) => t.clone(),
    }
}

/// What `after` changes from `before`: the effect added with its parameters
/// (`gear_backlash with backlash_deg = 0.1, connection = gearbox`), then every plain
/// parameter that moved (`inertia.brake: 1.5 to 1.53 (× 1.020)`).
pub fn changes(before: &Model, after: &Model, report: &Report) -> Vec<String> {
    let mut out = Vec::new();
    let v = &report.verdict;
    if after == before {
        return out;
    }
    if v.effect != "parameter_error" {
        let parameters: Vec<String> = v
            .parameters
            .iter()
            .map(|(k, x)| format!("{k} = {}", value_text(x)))
            .collect();
        out.push(format!("{} with {}", v.effect, parameters.join(", ")));
    }
    for p in plain_parameters(before) {
        if let (Some(a), Some(b)) = (value_of(before, &p.name), value_of(after, &p.name))
            && a != b
        {
            out.push(format!(
                "{}: {} to {} (× {:.3})",
                p.name,
                sig4(a),
                sig4(b),
                b / a
            ));
        }
    }
    out
}
