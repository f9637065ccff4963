//! A trial: one time-domain run of a model that a fit or a candidate proposes, and what
//! its failure means (issue 14, "Never abort, never get worse").
//!
//! A diagnosis runs the user's model once as given (the baseline) and then many models
//! that it made itself: fit steps of the plain parameters, candidates at trial values,
//! second starts, verifications. Only a failure of the baseline (or of the inputs) is the
//! user's problem and an error. A model the diagnosis proposed may fail to simulate (a
//! run-up whose reference speed turns negative, a divergence, a step-size collapse): that
//! is a *rejected step* (the fit keeps its previous point) or a *rejected candidate* (it
//! stays in the report with the reason and can never be the verdict), never the end of
//! the diagnosis. Only [`DiagnoseError::Cancelled`] always propagates.
//!
//! Every proposed model goes through [`evaluate`] / [`simulate`] here, so that the tests
//! can make one candidate's simulation fail ([`inject_failure`]) and check the rest.

use super::DiagnoseError;
use super::candidates::Candidate;
use super::context::{Context, Evaluated};
use super::sensor::TapeJoint;
use crate::model::Model;

/// Runs a proposed model (`candidate`: the effect it carries, if any) in the time domain:
/// [`Context::evaluate`].
pub fn evaluate(
    cx: &Context,
    candidate: Option<&Candidate>,
    model: Model,
    joint: Option<TapeJoint>,
    factors: Vec<f64>,
    value: Option<f64>,
) -> Result<Evaluated, DiagnoseError> {
    injected(candidate)?;
    cx.evaluate(model, joint, factors, value)
}

/// The amplitudes of a proposed model: [`Context::simulate`].
pub fn simulate(
    cx: &Context,
    candidate: Option<&Candidate>,
    model: &Model,
    joint: Option<&TapeJoint>,
    only: Option<(&[bool], &[f64])>,
) -> Result<Vec<f64>, DiagnoseError> {
    injected(candidate)?;
    cx.simulate(model, joint, only)
}

/// Whether an error ends the diagnosis even when a proposed model caused it.
pub fn is_fatal(e: &DiagnoseError) -> bool {
    matches!(e, DiagnoseError::Cancelled)
}

/// The reason of a rejected step or candidate, for the report: `"what: why"`.
pub fn reason(what: &str, e: &DiagnoseError) -> String {
    format!("{what}: {e}")
}

#[cfg(test)]
static INJECTED: std::sync::Mutex<Vec<(crate::effects::Effect, DiagnoseError)>> =
    std::sync::Mutex::new(Vec::new());

/// Test seam: every simulation of a candidate of `effect` fails with `error` from now on
/// (no test but the one that sets it runs a whole diagnosis in the library's tests).
#[cfg(test)]
pub fn inject_failure(effect: crate::effects::Effect, error: DiagnoseError) {
    if let Ok(mut v) = INJECTED.lock() {
        v.push((effect, error));
    }
}

#[cfg(test)]
fn injected(candidate: Option<&Candidate>) -> Result<(), DiagnoseError> {
    let Some(c) = candidate else { return Ok(()) };
    let Ok(v) = INJECTED.lock() else {
        return Ok(());
    };
    match v.iter().find(|(e, _)| *e == c.effect) {
        Some((_, error)) => Err(error.clone()),
        None => Ok(()),
    }
}

#[cfg(not(test))]
#[inline]
fn injected(_: Option<&Candidate>) -> Result<(), DiagnoseError> {
    Ok(())
}
