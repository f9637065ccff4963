//! What a candidate's effect gains by itself, at its own fit.
//!
//! A candidate is fitted together with the plain parameters, and the pair may beat the
//! plain fit for a reason that is not the effect: the candidate's fit took its plain
//! parameters along another path to a better recalibration, or the candidate brings
//! something fixed besides its parameter (a backlash candidate damps an undamped mesh,
//! [`crate::effects::backlash`]). Either way the recordings show no effect, and naming
//! one would name physics that is not there. So a candidate that could be the verdict is
//! run once more on the whole campaign with its effect closed: its parameter at the
//! effect's absence ([`Param::absent_at`]), its plain parameters and fixed keys as
//! fitted. When that scores within [`EFFECT_MARGIN`] of the candidate, the effect gained
//! too little of its own, and the candidate is set aside with the numbers
//! ([`super::screen::Screened::unsupported`]).
//!
//! Why, measured on the seventh published run (seeds 100660–100769):
//! - control 100672 (`none`; the bench damps its meshes, as every real mesh is, and the
//!   spec's model format has no key for it): the softened backlash candidate at 0.006°
//!   of play, the bottom of its search, held out χ²/N 3.76 against the plain fit's 50.3
//!   and was the verdict;
//! - control 100662 (`parameter_error`): the elastic amplitude law at a2 = 0.005 /mm²
//!   held out 1.58 against 2.89, and the frequency law at exponent 0, its absence, 1.57:
//!   the candidates' fits had found better plain parameters than the plain fit.
//!
//! Effects without an absence (thermal drift's heat capacity, a local mode's frequency)
//! are not checked here.
//!
//! [`Param::absent_at`]: super::param::Param::absent_at

use super::DiagnoseError;
use super::candidates::Candidate;
use super::context::{Context, Evaluated};
use super::decide::{EFFECT_MARGIN, score};
use super::surrogate::scaled;
use super::trial;

/// Whether a verified candidate at `verified` could be the verdict: its score beats the
/// plain fit `plain`'s by [`EFFECT_MARGIN`] ([`super::decide`]'s first rule). Only those
/// are checked, as the check costs a run of the whole campaign.
pub fn could_be_named(cx: &Context, plain: &Evaluated, verified: &Evaluated) -> bool {
    let k = cx.plain.len();
    score(cx, verified, k + 1) < (1.0 - EFFECT_MARGIN) * score(cx, plain, k)
}

/// A candidate's fit with its effect closed: the user's model with the candidate's
/// plain factors, and its fixed keys where they stay (a backlash's mesh damping);
/// `None` when the effect has no absence or the closed model cannot be simulated.
pub fn closed(
    cx: &Context,
    c: &Candidate,
    verified: &Evaluated,
) -> Result<Option<Evaluated>, DiagnoseError> {
    let Some(null) = c.param.absent_at else {
        return Ok(None);
    };
    let Ok(base) = scaled(cx.user, &cx.plain, &verified.factors) else {
        return Ok(None);
    };
    // An effect that refuses its own absence (a cylinder's `pressure_scale` of 1
    // "changes nothing") is the plain model there.
    let (model, joint) = c.apply(&base, null).unwrap_or((base, None));
    match trial::evaluate(cx, None, model, joint, verified.factors.clone(), None) {
        Ok(e) => Ok(Some(e)),
        Err(e) if trial::is_fatal(&e) => Err(e),
        Err(_) => Ok(None),
    }
}

/// Whether `closed` is a plain recalibration: the user's model with its plain factors
/// and nothing else (a backlash's closed fit keeps the mesh damping it brings, so is
/// not one).
pub fn is_recalibration(cx: &Context, closed: &Evaluated) -> bool {
    closed.joint.is_none()
        && scaled(cx.user, &cx.plain, &closed.factors).is_ok_and(|m| m == closed.model)
}

/// Why candidate `c`, verified at `verified`, gained too little by its own effect
/// against `closed`, its fit with the effect closed ([`closed`]), or `None` when it
/// gained enough. Both are scored as the verdict is ([`score`]: held out, the closed one
/// with one parameter fewer).
pub fn unsupported(
    cx: &Context,
    c: &Candidate,
    verified: &Evaluated,
    closed: &Evaluated,
) -> Option<String> {
    let null = c.param.absent_at?;
    let k = cx.plain.len();
    let (with, without) = (score(cx, verified, k + 1), score(cx, closed, k));
    if with <= (1.0 - EFFECT_MARGIN) * without {
        return None;
    }
    let kept = match super::candidates_backlash::mesh_damping_ratio(c) {
        Some(z) => format!(" and the mesh damping it brings (ζ = {z})"),
        None => String::new(),
    };
    Some(format!(
        "gains too little by its own effect: with {} = {null} (its absence), the same plain \
         parameters{kept}, it scores {without:.2} against {with:.2}, and the effect must \
         gain {:.0} %",
        c.param.key,
        100.0 * EFFECT_MARGIN
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::DiagnoseOptions;
    use crate::diagnose::candidates::candidates;
    use crate::diagnose::observe::observe;
    use crate::diagnose::tests_guard::{bench, recordings};
    use crate::effects::Effect;

    /// On recordings that are exactly the effect's simulation the effect gains all by
    /// itself; on recordings that are exactly the closed model's, the same fit gains
    /// nothing of its own and is set aside, with the scores in the reason.
    #[test]
    fn an_effect_must_gain_by_itself() {
        let model = bench();
        let options = DiagnoseOptions::default();
        let observed = observe(&recordings(), 8.0).expect("observed");
        let mut cx = Context::new(&model, &options, observed);
        let list = candidates(&model, &["engine".to_string()], false);
        let c = list
            .iter()
            .find(|c| c.effect == Effect::CylinderImbalance)
            .expect("a cylinder candidate");
        let factors = vec![1.0; cx.plain.len()];
        let run = |cx: &Context, value: f64| {
            let (m, j) = c.apply(&model, value).expect("applies");
            cx.evaluate(m, j, factors.clone(), Some(value))
                .expect("simulates")
        };
        // A cylinder's `pressure_scale` of 1 is refused as changing nothing: closed, the
        // candidate is the user's model.
        assert_eq!(c.param.absent_at, Some(1.0));
        assert!(c.apply(&model, 1.0).is_err());
        let with = run(&cx, 0.5);
        let closed_run = cx
            .evaluate(model.clone(), None, factors.clone(), None)
            .expect("simulates");
        // The recordings are the effect's own: closing it loses the fit.
        for (o, s) in cx.observed.observations.iter_mut().zip(&with.simulated) {
            o.measured_rpm = *s;
        }
        let with = cx.scored(with.model, None, with.simulated, factors.clone(), Some(0.5));
        let shut = closed(&cx, c, &with).expect("runs").expect("closes");
        assert_eq!(shut.simulated, closed_run.simulated);
        assert_eq!(unsupported(&cx, c, &with, &shut), None);
        // The recordings are the closed model's: the effect only harms.
        for (o, s) in cx
            .observed
            .observations
            .iter_mut()
            .zip(&closed_run.simulated)
        {
            o.measured_rpm = *s;
        }
        let with = cx.scored(with.model, None, with.simulated, factors.clone(), Some(0.5));
        let shut = closed(&cx, c, &with).expect("runs").expect("closes");
        let why = unsupported(&cx, c, &with, &shut).expect("set aside");
        assert!(
            why.contains("pressure_scale = 1 (its absence)") && why.contains("15 %"),
            "{why}"
        );
    }
}
