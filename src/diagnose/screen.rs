//! Screening and verification of the candidates: the time domain is the costly part of a
//! diagnosis, so every candidate is first fitted cheaply — on the linear surrogate with
//! all plain parameters, or, for effects the linear model cannot represent, in the time
//! domain of only the runs that show them — and only the few whose screened score beats
//! the plain fit are run on the whole campaign in the time domain, where they are scored.
//! Only those can become the verdict.

use super::DiagnoseError;
use super::candidates::Candidate;
use super::context::{Context, Evaluated};
use super::drift::{DRIFT_CHI2, long_run_drift};
use super::observe::RunShape;
use super::reversal::{REVERSAL_FRACTION, torque_reversal_runs};
use super::trial;
use crate::effects::Effect;

/// A screened candidate must lower the plain fit's score on the fitted data by this
/// fraction to be verified in the time domain. Zero: any gain will do. The linear
/// model's first step undersells effects that show mostly in a swept resonance of the
/// run-up (on the shipped hysteretic and frequency-dependence cases it predicts 1–2 %
/// where the time domain then gains 5–50 %), so the ranking, not the size of the
/// screened gain, chooses what is verified.
const SCREEN_MARGIN: f64 = 0.0;
/// At most this many effects are verified: the best place of each of their forms. Each
/// form, not only the effect's best, because the linear screening ranks forms of one
/// effect unreliably: on development seed 80 the power-law form at the wrong coupling
/// screened first and crowded out seed 000 eq. 9 at the right one, which the time
/// domain then fits at χ²/N 2.8 against 39.9. An effect the linear model does not see
/// ([`linear_sees`]: thermal drift, backlash, the elastic amplitude law) was screened in
/// the time domain already,
/// so its ranking is no estimate: it is verified when it beats the plain fit, beside
/// these three and without taking their place. Validation case 1005 (thermal drift,
/// screened at fitted χ²/N 35.2, held out 17.8) was crowded out by three effects whose
/// optimistic linear screenings ranked above it and whose verified fits then came out at
/// 18–40 fitted, 191–230 held out.
const VERIFIED_EFFECTS: usize = 3;

/// The number of distinct effects in `effects`.
fn distinct(effects: &[Effect]) -> usize {
    let mut seen: Vec<Effect> = Vec::new();
    for e in effects {
        if !seen.contains(e) {
            seen.push(*e);
        }
    }
    seen.len()
}
/// Time-domain rounds of a verified candidate.
pub const VERIFY_ROUNDS: usize = 3;

/// A candidate after screening (and, if it got that far, verification).
#[derive(Debug, Clone)]
pub struct Screened {
    /// The candidate.
    pub candidate: Candidate,
    /// Its fit: time domain when `verified`, else the screening's estimate.
    pub evaluated: Evaluated,
    /// Scored in the time domain on the whole campaign.
    pub verified: bool,
    /// How it was screened, for the report.
    pub note: String,
    /// `evaluated` is a time-domain run on the whole campaign (a second start that was
    /// checked, [`super::restart`]), so verification goes on from it.
    pub in_time_domain: bool,
    /// Why the candidate was rejected: its screening, or its verification, could not be
    /// simulated ([`super::trial`]). A rejected candidate is never verified, so never the
    /// verdict; `evaluated` is then the last point it reached (the plain fit it started
    /// from when its screening failed).
    pub rejected: Option<String>,
    /// Steps of its fits that could not be simulated and were not taken.
    pub rejected_steps: Vec<String>,
}

impl Screened {
    /// A candidate whose screening failed with `why` at the plain fit `plain`.
    pub fn rejected_at(candidate: &Candidate, plain: &Evaluated, why: &DiagnoseError) -> Self {
        Self {
            candidate: candidate.clone(),
            evaluated: plain.clone(),
            verified: false,
            note: "its screening could not be simulated".to_string(),
            in_time_domain: false,
            rejected: Some(trial::reason("screening", why)),
            rejected_steps: Vec::new(),
        }
    }
}

/// Does the linear model represent this candidate (so the surrogate can fit it)? Not
/// thermal drift, backlash, a tape joint, nor the elastic amplitude law: the linear model
/// takes a rubber's tangent at the static twist, and a bench's coupling twists by 1.7–22
/// times its static twist (issue 14's independent bench), so the stiffening the
/// recordings see is set by the vibration. Screened on the linear model, the law was
/// pushed to its bound on every development case of that bench (2004–2081, `a2` =
/// 0.5 /mm²) and never named right. The seed form (seed 000 eq. 13–15, the damping
/// scaled with the stiffness) stays on the linear model, where torsim's own cases of it
/// are named right.
pub fn linear_sees(c: &Candidate) -> bool {
    match c.effect {
        Effect::CouplingThermalDrift | Effect::GearBacklash | Effect::SensorArtifact => false,
        Effect::CouplingAmplitudeNonlinearity => !super::candidates_amplitude::is_elastic(c),
        _ => true,
    }
}

/// The runs of `cx` whose regime passes `keep`.
fn runs_where(cx: &Context, keep: impl Fn(&RunShape) -> bool) -> Vec<bool> {
    cx.observed.runs.iter().map(|r| keep(&r.regime)).collect()
}

/// Screens one candidate around the plain fit `plain` (a backlash or an elastic amplitude
/// law also from `baseline`, the user's model: [`super::restart::second_start_in_time`]); an error when it is not
/// plausible (its signature is absent: [`DiagnoseError::Input`] says why) or cannot be
/// fitted (a [`DiagnoseError::Simulation`]: the caller rejects it,
/// [`Screened::rejected_at`]).
pub fn screen_one(
    cx: &Context,
    plain: &Evaluated,
    baseline: &Evaluated,
    c: &Candidate,
) -> Result<Screened, DiagnoseError> {
    let mut in_time_domain = false;
    let mut rejected_steps = Vec::new();
    // A time-domain search from the plain fit and from the user's values
    // ([`super::restart::search_in_time`]), noted with where it ended.
    let mut in_two_starts = |note: &str, runs: &[bool]| {
        let (e, whole, why) = super::restart::search_in_time(cx, plain, baseline, c, runs)?;
        rejected_steps.extend(why);
        in_time_domain = whole;
        let note = if whole {
            format!("{note}, from the user's values")
        } else {
            note.to_string()
        };
        Ok::<_, DiagnoseError>((e, false, note))
    };
    let (evaluated, verified, note) = match c.effect {
        Effect::SensorArtifact => (
            cx.fit_artifact(plain, c)?,
            true,
            "fitted on the plain fit's time domain (a sensor artifact adds in power)".to_string(),
        ),
        Effect::GearBacklash => {
            let gear = c.fixed.first().map_or("", |(_, v)| v.as_str());
            let mut runs = torque_reversal_runs(cx, plain, gear);
            // The steady regimes that show it are enough to screen on, and cheap; a
            // run-up (backlash slows its simulation several times) only without them.
            let steady = runs_where(cx, |r| !matches!(r, RunShape::Ramp { .. }));
            if runs.iter().zip(&steady).any(|(a, b)| *a && *b) {
                runs.iter_mut().zip(&steady).for_each(|(a, b)| *a &= *b);
            }
            if !runs.contains(&true) {
                return Err(DiagnoseError::Input(format!(
                    "not plausible: in no recording does the torque in `{gear}` reverse (its \
                     vibratory torque stays below {:.0} % of the mean), so free play never \
                     opens",
                    100.0 * REVERSAL_FRACTION
                )));
            }
            in_two_starts(
                "screened in the time domain of the recordings where its torque can reverse",
                &runs,
            )?
        }
        Effect::CouplingAmplitudeNonlinearity if !linear_sees(c) => {
            // Its stiffening is set by the vibration, which the linear model's tangent at
            // the static twist cannot see (README, issue 14): its coefficient (`a2` or
            // `a1`) is searched in the time domain of the steady recordings (a run-up, several times longer,
            // only in verification).
            let runs = runs_where(cx, |r| !matches!(r, RunShape::Ramp { .. }));
            in_two_starts(
                "screened in the time domain of the steady recordings",
                &runs,
            )?
        }
        Effect::CouplingThermalDrift => {
            let drift = long_run_drift(&cx.observed).unwrap_or(0.0);
            if drift <= DRIFT_CHI2 {
                return Err(DiagnoseError::Input(format!(
                    "not plausible: the long run's order amplitudes do not drift (mean \
                     square of their slopes over its noise {drift:.2}, at most {DRIFT_CHI2} \
                     without drift), so the coupling does not warm enough to matter"
                )));
            }
            // A rubber stage warms up in the long runs and run-ups (the steady regimes are
            // simulated for a few cycles only). The long run alone leaves its heat
            // capacity loose (4700 J/K for 300 on the reference campaign).
            let long = runs_where(cx, |r| !matches!(r, RunShape::Steady { .. }));
            (
                {
                    let stepped = cx.fit_time_domain(plain, c, &long)?;
                    rejected_steps.extend(stepped.rejected);
                    stepped.best
                },
                false,
                "screened in the time domain of the long run and the run-up".to_string(),
            )
        }
        _ => {
            debug_assert!(linear_sees(c));
            let all: Vec<usize> = (0..cx.plain.len()).collect();
            (
                cx.propose(plain, Some(c), &all)?,
                false,
                "screened on the linear model".to_string(),
            )
        }
    };
    Ok(Screened {
        candidate: c.clone(),
        evaluated,
        verified,
        note,
        in_time_domain,
        rejected: None,
        rejected_steps,
    })
}

/// Verifies the most promising screened candidates in the time domain: the best place of
/// each form of each effect, ranked by `score` on the fitted observations (the held-out ones must not
/// choose what gets verified), while it beats the plain fit's `plain_score` by
/// [`SCREEN_MARGIN`], of at most [`VERIFIED_EFFECTS`] effects the linear model screened
/// (and every effect screened in the time domain). `progress` is told each one's name.
pub fn verify(
    cx: &Context,
    plain: &Evaluated,
    screened: &mut [Screened],
    plain_score: f64,
    score: &dyn Fn(&Evaluated) -> f64,
    progress: &mut dyn FnMut(usize, usize, &str) -> Result<(), DiagnoseError>,
) -> Result<(), DiagnoseError> {
    let mut order: Vec<usize> = (0..screened.len())
        .filter(|i| !screened[*i].verified && screened[*i].rejected.is_none())
        .collect();
    order.sort_by(|a, b| score(&screened[*a].evaluated).total_cmp(&score(&screened[*b].evaluated)));
    let mut chosen: Vec<usize> = Vec::new();
    for i in order {
        let s = &screened[i];
        let c = &s.candidate;
        if score(&s.evaluated) >= (1.0 - SCREEN_MARGIN) * plain_score && !verified_anyway(s) {
            continue;
        }
        let chosen_effect = |k: &usize| screened[*k].candidate.effect == c.effect;
        if chosen
            .iter()
            .any(|k| chosen_effect(k) && screened[*k].candidate.form() == c.form())
        {
            continue;
        }
        let estimated = |k: &usize| linear_sees(&screened[*k].candidate);
        let effects: Vec<Effect> = chosen
            .iter()
            .filter(|k| estimated(k))
            .map(|k| screened[*k].candidate.effect)
            .collect();
        if estimated(&i)
            && !chosen.iter().any(chosen_effect)
            && distinct(&effects) >= VERIFIED_EFFECTS
        {
            continue;
        }
        chosen.push(i);
    }
    // Each chosen candidate is verified on its own, side by side ([`super::parallel`]).
    let results = super::parallel::map_reporting(
        chosen.len(),
        cx.options.threads,
        &|k| verify_one(cx, plain, &screened[chosen[k]]),
        &mut |k, finished| {
            progress(
                finished,
                chosen.len(),
                &screened[chosen[k]].candidate.name(),
            )
        },
    )?;
    for (i, result) in chosen.iter().zip(results) {
        let s = &mut screened[*i];
        match result {
            Err(e) if trial::is_fatal(&e) => return Err(e),
            Err(e) => s.rejected = Some(trial::reason("verification", &e)),
            // Every round rejected, the first (which adds the effect) too: the effect
            // was never run on the whole campaign.
            Ok(stepped) if stepped.best.value.is_none() => {
                s.rejected = Some(format!("verification: {}", stepped.rejected.join("; ")));
                s.rejected_steps.extend(stepped.rejected);
            }
            Ok(stepped) => {
                s.evaluated = stepped.best;
                s.rejected_steps.extend(stepped.rejected);
                s.verified = true;
                s.note = format!("{}; verified in the time domain", s.note);
            }
        }
    }
    Ok(())
}

/// Candidates verified whatever their screening scored, because the screening held the
/// plain parameters at the plain fit, which had already taken the effect's mean into a
/// stiffness, so its score on the fitted runs is no fair gate:
/// - a plausible thermal drift. It was screened on the long runs and run-ups alone (the
///   only runs where a rubber warms) and is plausible only where a long run drifts
///   ([`DRIFT_CHI2`]), which no other candidate explains. On development case 2039 (a
///   70 s heat time constant, 24 s long run) it predicted the held-out runs at χ²/N 5.7
///   against the plain fit's 24.2, yet its fitted 5.7 against 4.6 kept it from
///   verification;
/// - an elastic amplitude law the screening found present (not at its absence). Screened
///   on the steady runs with the plain fit's coupling stiffness, which had stiffened to
///   the mean twist of the fitted regimes. On development case 2059 (a power law, p = 1)
///   it screened at fitted χ²/N 603 against the plain fit's 388, so it was never run on
///   the whole campaign. Verified, it fits the fitted runs at 559 and the held-out runs
///   at 1.5e3 against the plain fit's 8.8e3, and is named right.
pub(super) fn verified_anyway(s: &Screened) -> bool {
    let c = &s.candidate;
    c.effect == Effect::CouplingThermalDrift
        || (super::candidates_amplitude::is_elastic(c) && !c.param.is_absent(s.evaluated.value))
}

/// The time-domain rounds of one screened candidate `s` ([`verify`]).
fn verify_one(
    cx: &Context,
    plain: &Evaluated,
    s: &Screened,
) -> Result<super::rounds::Stepped, DiagnoseError> {
    let c = &s.candidate;
    if s.in_time_domain {
        Ok(cx.rounds(s.evaluated.clone(), Some(c), VERIFY_ROUNDS - 1, None))
    } else if linear_sees(c) {
        Ok(cx.rounds(
            plain.clone(),
            Some(c),
            VERIFY_ROUNDS,
            Some(s.evaluated.clone()),
        ))
    } else {
        // The effect's value from the screening, on the whole campaign, then the
        // plain parameters refitted with it in place.
        let e = &s.evaluated;
        trial::evaluate(
            cx,
            Some(c),
            e.model.clone(),
            e.joint.clone(),
            e.factors.clone(),
            e.value,
        )
        .map(|e| cx.rounds(e, Some(c), VERIFY_ROUNDS - 1, None))
    }
}
