//! The honest decision and the report.
//!
//! Score of a model (lower is better): its χ² per amplitude on the held-out observations
//! (from [`NOISE_CHI2`] up: below it everything fits to the noise), plus the BIC-like
//! penalty `k·ln(n)/n` of its `k` fitted parameters on `n` fitted
//! amplitudes. Then:
//! - `none` when the user's model already fits the held-out data within the noise
//!   (χ²/N ≤ [`NONE_CHI2`]);
//! - an effect (one verified in the time domain, [`super::screen`], and not rejected,
//!   [`super::trial`]) when its score beats the plain-parameter fit's by [`EFFECT_MARGIN`]
//!   (relative) — new physics must earn its place on data the fit did not see — and its
//!   held-out χ²/N improves on the user's model's ([`guard::improves`]), unless it was
//!   fitted to its own absence ([`super::param::Param::is_absent`]);
//! - otherwise `parameter_error`, naming the plain parameter the fit moved most, when the
//!   recalibration improves on the user's model's held-out χ²/N the same way;
//! - otherwise `none` (issue 14: a verdict never has a held-out fit worse than the user's
//!   model), saying that the model misfits but that nothing tried improves the held-out
//!   data, with the worst mismatches ([`guard::misfit_none`]).

use super::context::{Context, Evaluated};
use super::guard;
use super::holdout::{held_out_labels, roles};
use super::places::{SAME_Z, equivalent_places};
use super::report::*;
use super::screen::Screened;
use std::collections::BTreeMap;

/// Held-out χ²/N under which the user's model is taken to fit.
pub const NONE_CHI2: f64 = 2.0;
/// An effect must lower the plain fit's score by this fraction. On the shipped
/// `parameter_error` control the best effect gains 0.3 %; the weakest real effect named
/// right gains 35 % (the frequency law; README, shipped cases).
pub const EFFECT_MARGIN: f64 = 0.15;

fn number(x: f64) -> ParameterValue {
    ParameterValue::Number(x)
}

/// The χ²/N of a model that fits its data to their noise: below it, no two models can be
/// told apart, so a score counts χ²/N from there ([`score`]). Published control 100717
/// (seventh run, a `parameter_error`): the plain fit held out 0.79, hysteretic damping in
/// a shaft 0.55, a 27 % gain that is all inside the noise, and it was named.
pub const NOISE_CHI2: f64 = 1.0;

/// The score of `e` with `k` fitted parameters: held-out χ²/N, but not below
/// [`NOISE_CHI2`], + `k·ln(n)/n`.
pub fn score(cx: &Context, e: &Evaluated, k: usize) -> f64 {
    let n = cx.n_fitted() as f64;
    cx.chi2(e, true).max(NOISE_CHI2) + k as f64 * n.ln() / n
}

/// The same on the fitted observations: what a screening may rank by (the held-out ones
/// are kept for the verdict).
pub fn fitted_score(cx: &Context, e: &Evaluated, k: usize) -> f64 {
    let n = cx.n_fitted() as f64;
    cx.chi2(e, false) + k as f64 * n.ln() / n
}

/// The report of a finished diagnosis: `screened` are the candidates fitted (only the
/// verified, not rejected ones can be the verdict), `not_fitted` those left out and why,
/// `plain_rejected` the steps of the plain fit that could not be simulated.
#[allow(clippy::too_many_arguments)]
pub fn report(
    cx: &Context,
    baseline: &Evaluated,
    plain: &Evaluated,
    screened: &[Screened],
    not_fitted: &[(String, String)],
    plain_rejected: &[String],
    single: Option<(usize, f64, f64)>,
    elapsed_s: f64,
) -> Report {
    let k_plain = cx.plain.len();
    let before = cx.chi2(baseline, true);
    let plain_score = score(cx, plain, k_plain);
    let mut candidates: Vec<Candidate_> = Vec::new();
    let mut plain_params: BTreeMap<String, ParameterValue> = cx
        .plain
        .iter()
        .zip(&plain.factors)
        .map(|(p, f)| (format!("scale.{}", p.name), number(*f)))
        .collect();
    plain_params.extend(super::mesh_damping::keys(cx.mesh_damping.as_ref()));
    for s in screened {
        let (c, e) = (&s.candidate, &s.evaluated);
        let mut parameters = plain_params.clone();
        for (k, v) in &c.fixed {
            parameters.insert((*k).to_string(), ParameterValue::Text(v.clone()));
        }
        if let Some(v) = e.value {
            parameters.insert(c.param.key.to_string(), number(v));
        }
        if let Some(j) = super::branch::branch_inertia_kg_m2(c, &e.model) {
            parameters.insert("inertia_kg_m2".into(), number(j));
        }
        // A Zener form's relaxation frequency in Hz, which its `relax_ratio` only names
        // as a multiple of the first mode (the explanation gives it).
        if c.form() == Some(crate::effects::rubber_zener::FORM)
            && let Some(hz) = c
                .fixed_value("connection")
                .and_then(|k| crate::effects::rubber_zener::relax_hz(&e.model, k))
        {
            parameters.insert("relax_hz".into(), number(hz));
        }
        for (p, f) in cx.plain.iter().zip(&e.factors) {
            parameters.insert(format!("scale.{}", p.name), number(*f));
        }
        candidates.push(Candidate_ {
            name: c.name(),
            out: super::report::Candidate {
                effect: c.effect.to_string(),
                parameters,
                score: score(cx, e, k_plain + 1),
                residual_before: before,
                residual_after: cx.chi2(e, true),
                residual_fitted: cx.chi2(e, false),
                parameter_count: k_plain + 1,
                signature: format!("{}: {}", c.name(), s.note),
                verified: s.verified && s.rejected.is_none(),
                rejected: s.rejected.clone(),
                rejected_steps: s.rejected_steps.clone(),
                set_aside: None,
            },
            evaluated: e,
            candidate: c,
            unsupported: s.unsupported.as_deref(),
        });
    }
    // Keep the best place of each effect, a verified one before any only screened, and
    // every rejected one (last, each with its reason). Two scores tie exactly when both
    // fit the held-out data inside the noise ([`NOISE_CHI2`]) with as many parameters;
    // the lower held-out χ²/N then ranks first, where before the order of the search
    // did (development case 2171: thermal drift held out 0.55, the frequency
    // law 0.82, both scored 1.089 and the frequency law was named).
    let rank = |a: &super::report::Candidate, b: &super::report::Candidate| {
        (a.rejected.is_some())
            .cmp(&b.rejected.is_some())
            .then(b.verified.cmp(&a.verified))
            .then(a.score.total_cmp(&b.score))
            .then(a.residual_after.total_cmp(&b.residual_after))
    };
    candidates.sort_by(|a, b| rank(&a.out, &b.out));
    let mut seen = Vec::new();
    candidates.retain(|c| {
        let new = c.out.rejected.is_some() || !seen.contains(&c.out.effect);
        seen.push(c.out.effect.clone());
        new
    });
    let plain_row = super::report::Candidate {
        effect: "parameter_error".into(),
        parameters: plain_params.clone(),
        score: plain_score,
        residual_before: before,
        residual_after: cx.chi2(plain, true),
        residual_fitted: cx.chi2(plain, false),
        parameter_count: k_plain,
        signature: "plain parameters only".into(),
        verified: true,
        rejected: None,
        rejected_steps: plain_rejected.to_vec(),
        set_aside: None,
    };
    let none_row = super::report::Candidate {
        effect: "none".into(),
        parameters: BTreeMap::new(),
        score: before,
        residual_before: before,
        residual_after: before,
        residual_fitted: cx.chi2(baseline, false),
        parameter_count: 0,
        signature: "the user's model as it is".into(),
        verified: true,
        rejected: None,
        rejected_steps: Vec::new(),
        set_aside: None,
    };
    // A branch must clear its own, larger margin ([`super::branch::BRANCH_MARGIN`]); one
    // short of it (or tuned to the band's edge) is no evidence against the effects behind
    // it, so it is set aside and the next candidate judged. Validation case 1006: a branch
    // (2.37) and hysteretic damping (2.40) both beat the plain fit (3.21) by 25 %, and the
    // branch's shortfall named `parameter_error`.
    let clears_own_margin = |c: &Candidate_| {
        super::branch::clears_margin(c.candidate, c.out.score, plain_score)
            && super::branch::inside(c.candidate, c.evaluated.value)
    };
    // A sensor artifact whose mismatch the other stations see too is set aside as well
    // ([`super::sensor_local`]).
    // So is an effect fitted to its own absence ([`super::param::Param::is_absent`]).
    // And a candidate whose gain something else it brings made
    // ([`Screened::unsupported`]).
    let eligible = |c: &Candidate_| {
        (!super::branch::is_branch(c.candidate) || clears_own_margin(c))
            && c.unsupported.is_none()
            && !c.candidate.param.is_absent(c.evaluated.value)
            && super::sensor_local::local(cx, c.candidate, plain, c.evaluated)
    };
    let n_held = guard::n_held(cx);
    let best_index = candidates.iter().position(eligible);
    // A held-out tie with the next candidate that could be named goes to the better fit
    // of the fitted half ([`super::tie`]).
    let nameable = |c: &Candidate_| {
        eligible(c) && c.out.verified && c.out.rejected.is_none() && clears_own_margin(c)
    };
    let fits = |c: &Candidate_| super::tie::Fits {
        held: c.out.residual_after,
        fitted: c.out.residual_fitted,
    };
    // The effect that lost a tie, and why.
    let tie_loser: Option<(String, String)> = best_index
        .filter(|&i| nameable(&candidates[i]))
        .and_then(|i| super::tie::break_tie(&mut candidates, i, nameable, fits, n_held))
        .map(|(lost, why)| (lost.out.effect.clone(), why));
    let best = best_index
        .and_then(|i| candidates.get(i))
        .filter(|c| c.out.verified && c.out.rejected.is_none());
    let plain_after = cx.chi2(plain, true);
    let (verdict, after_model): (Verdict, &Evaluated) = if before <= NONE_CHI2 {
        (
            Verdict {
                effect: "none".into(),
                confidence: (1.0 - before / NONE_CHI2).clamp(0.0, 1.0),
                parameters: BTreeMap::new(),
                explanation: format!(
                    "The model fits the held-out recordings within their noise (χ²/N = {before:.2}); \
                     nothing is missing and no parameter needs changing."
                ),
                equivalent_places: Vec::new(),
            },
            baseline,
        )
    } else if let Some(b) = best
        .filter(|b| clears_own_margin(b) && guard::improves(before, b.out.residual_after, n_held))
    {
        let mut parameters = BTreeMap::new();
        for (k, v) in &b.out.parameters {
            if !k.starts_with("scale.") {
                parameters.insert(k.clone(), v.clone());
            }
        }
        let all = screened.iter().map(|s| &s.candidate);
        let equivalent = equivalent_places(cx, all, b.candidate, b.evaluated);
        let also = if equivalent.is_empty() {
            String::new()
        } else {
            format!(
                " At {} {} it would predict the same amplitudes (within {SAME_Z} σ): the \
                 recordings cannot tell these places apart, and the place named is only \
                 where the fit settled.",
                b.candidate.fixed.first().map_or("", |(k, _)| *k),
                equivalent.join(", ")
            )
        };
        let sentence = super::words::effect_sentence(&b.out.effect, &parameters);
        // The best candidate other than the verdict (the first, unless a branch or a
        // sensor artifact was set aside before it).
        let other = if best_index == Some(0) { 1 } else { 0 };
        let runner_up = candidates
            .get(other)
            .filter(|c| c.out.verified)
            .map_or(plain_score, |c| c.out.score.min(plain_score));
        (
            Verdict {
                effect: b.out.effect.clone(),
                confidence: (1.0 - b.out.score / runner_up).clamp(0.0, 1.0),
                parameters,
                explanation: format!(
                    "{} With it ({}), fitted together with the plain parameters, the \
                     held-out χ²/N falls from {before:.2} to {:.2}, against {:.2} for the \
                     plain parameters alone.{also}",
                    sentence,
                    b.name,
                    b.out.residual_after,
                    cx.chi2(plain, true)
                ),
                equivalent_places: equivalent,
            },
            b.evaluated,
        )
    } else if !guard::improves(before, plain_after, n_held) {
        let tried = best.map(|b| (b.name.as_str(), b.out.residual_after));
        (
            guard::misfit_none(cx, baseline, before, NONE_CHI2, plain_after, tried),
            baseline,
        )
    } else {
        // Name the parameter that alone explains the most (fitted by itself); its value
        // from the joint fit of all plain parameters when that one failed.
        let (i, f) = match single {
            Some((i, f, _)) => (i, f),
            None => plain
                .factors
                .iter()
                .enumerate()
                .max_by(|a, b| a.1.ln().abs().total_cmp(&b.1.ln().abs()))
                .map_or((0, 1.0), |(i, f)| (i, *f)),
        };
        let name = cx.plain.get(i).map_or(String::new(), |p| p.name.clone());
        let user_value = super::surrogate::value_of(cx.user, &name);
        let mut parameters = BTreeMap::new();
        parameters.insert("parameter".into(), ParameterValue::Text(name.clone()));
        parameters.insert("factor".into(), number(f));
        if let Some(v) = user_value {
            parameters.insert("user_value".into(), number(v));
            parameters.insert("fitted_value".into(), number(v * f));
        }
        let second = candidates
            .first()
            .filter(|c| c.out.verified)
            .map_or(f64::INFINITY, |c| c.out.score);
        (
            Verdict {
                effect: "parameter_error".into(),
                confidence: (1.0 - plain_score / second).clamp(0.0, 1.0),
                parameters,
                explanation: format!(
                    "No physics is missing: recalibrating the plain parameters brings the \
                     held-out χ²/N from {before:.2} to {:.2}, and no effect does clearly \
                     better. The parameter that alone explains most is {name}: × {f:.3} of \
                     the user's value.",
                    cx.chi2(plain, true)
                ),
                equivalent_places: Vec::new(),
            },
            plain,
        )
    };
    let verdict = super::mesh_damping::marked(verdict, cx.mesh_damping.as_ref());
    let against = super::aside::Against {
        plain,
        plain_score,
        before,
    };
    let mut rows: Vec<super::report::Candidate> = candidates
        .iter()
        .map(|c| {
            let mut out = c.out.clone();
            if out.rejected.is_none() && out.effect != verdict.effect {
                out.set_aside = super::aside::reason(cx, c.candidate, c.evaluated, &out, &against)
                    .or_else(|| c.unsupported.map(str::to_string))
                    .or_else(|| {
                        tie_loser
                            .as_ref()
                            .filter(|(effect, _)| *effect == out.effect)
                            .map(|(_, why)| why.clone())
                    });
            }
            out
        })
        .collect();
    rows.push(plain_row);
    rows.push(none_row);
    rows.sort_by(rank);
    if let Some(i) = rows.iter().position(|r| r.effect == verdict.effect) {
        let r = rows.remove(i);
        rows.insert(0, r);
    }
    let after = cx.chi2(after_model, true);
    super::report_parts::assemble(
        cx,
        baseline,
        after_model,
        verdict,
        rows,
        before,
        after,
        not_fitted
            .iter()
            .map(|(candidate, reason)| NotFitted {
                candidate: candidate.clone(),
                reason: reason.clone(),
            })
            .collect(),
        elapsed_s,
    )
}

/// A candidate row with its name and evaluation.
struct Candidate_<'a> {
    name: String,
    out: super::report::Candidate,
    evaluated: &'a Evaluated,
    candidate: &'a super::candidates::Candidate,
    /// Why its gain is no evidence of its effect ([`Screened::unsupported`]).
    unsupported: Option<&'a str>,
}

/// Held-out labels (re-exported for the report parts).
pub fn validated_on(cx: &Context) -> Vec<String> {
    held_out_labels(&cx.observed, &cx.held_out)
}

/// Roles of the runs.
pub fn run_roles(cx: &Context) -> Vec<String> {
    roles(&cx.observed, &cx.held_out)
}
