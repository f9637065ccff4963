//! Screening of the candidates: the time domain is the costly part of a diagnosis, so
//! every candidate is first fitted cheaply — on the linear surrogate with all plain
//! parameters, or, for effects the linear model cannot represent, in the time domain of
//! only the runs that show them. Only the few whose screened score beats the plain fit
//! are then run on the whole campaign in the time domain ([`super::verify`]), where they
//! are scored; only those can become the verdict.

use super::DiagnoseError;
use super::candidates::Candidate;
use super::context::{Context, Evaluated};
use super::drift::{DRIFT_CHI2, long_run_drift};
use super::observe::RunShape;
use super::reversal::{REVERSAL_FRACTION, torque_reversal_runs};
use super::trial;
use crate::effects::Effect;
use crate::effects::backlash::DEFAULT_MESH_DAMPING_RATIO;

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
    /// Why the verified fit is no evidence of the effect although it gains: what else the
    /// candidate brings made the gain ([`super::own_gain`]).
    /// Such a candidate is never the verdict.
    pub unsupported: Option<String>,
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
            unsupported: None,
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
    // The candidate as screened: a backlash candidate may come out with another mesh
    // damping.
    let mut candidate = c.clone();
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
            let (e, verified, note) = in_two_starts(
                "screened in the time domain of the recordings where its torque can reverse",
                &runs,
            )?;
            // The mesh damping the recordings prefer ([`super::backlash_damping`]).
            match super::backlash_damping::rechoose(cx, c, &e, &runs)? {
                Some(r) => {
                    rejected_steps.extend(r.rejected);
                    in_time_domain = false;
                    let ratio = super::candidates_backlash::mesh_damping_ratio(&r.candidate);
                    let note = format!(
                        "{note}; its mesh damping ratio {} fits them better than {}",
                        ratio.unwrap_or("?"),
                        DEFAULT_MESH_DAMPING_RATIO
                    );
                    candidate = r.candidate;
                    (r.evaluated, verified, note)
                }
                None => (e, verified, note),
            }
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
            // A rubber stage warms up most in the long runs and run-ups (a steady regime
            // only in its hold, `forward.rs`'s `warm_hold_s`, a few seconds). The long run
            // alone leaves its heat capacity loose (4700 J/K for 300 on the reference
            // campaign). Searched from
            // the plain fit and from the user's values: the plain fit has taken the
            // warm stage's mean softening into its stiffness, and warming added on top of
            // that only harms (development case 2149: from the plain fit the search ended
            // at 2700 J/K, where the stage hardly warms, held out 3.55 as the plain fit;
            // from the user's values at 0.31 J/K, 1.75, named right).
            let long = runs_where(cx, |r| !matches!(r, RunShape::Steady { .. }));
            in_two_starts(
                "screened in the time domain of the long run and the run-up",
                &long,
            )?
        }
        _ => {
            debug_assert!(linear_sees(c));
            let all: Vec<usize> = (0..cx.plain.len()).collect();
            let e = cx.propose(plain, Some(c), &all)?;
            // A local mode's damping, chosen by the recordings ([`super::branch_damping`]).
            match super::branch_damping::rechoose(cx, c, &e)? {
                Some((rechosen, better)) => {
                    let note = format!(
                        "screened on the linear model; its damping ratio {} fits better than {}",
                        rechosen
                            .fixed_value(super::branch_damping::KEY)
                            .unwrap_or("?"),
                        crate::effects::branch::DEFAULT_DAMPING_RATIO
                    );
                    candidate = rechosen;
                    (better, false, note)
                }
                None => (e, false, "screened on the linear model".to_string()),
            }
        }
    };
    Ok(Screened {
        candidate,
        evaluated,
        verified,
        note,
        in_time_domain,
        rejected: None,
        rejected_steps,
        unsupported: None,
    })
}
