//! The plain parameters refitted with the best sensor artifact in place.
//!
//! A sensor artifact is fitted on the plain fit's time domain ([`super::rounds`]), which
//! is cheap (it only adds to the measured amplitudes) but leaves the plain parameters
//! where the plain fit put them; and where an artifact is in the recordings the plain fit
//! bends them to stand in for it (on benchtruth's development seed 10, an eccentric tape
//! at a geared station: the plain fit's held-out χ²/N is 75 against the user's model's
//! 42). So the artifact that fits best is also fitted from the user's values, and each of
//! the two starts gets the rounds of surrogate fit and time-domain run a verified effect
//! gets ([`super::verify::verify`]), which move the plain parameters and the artifact's
//! size together; the candidate keeps whichever scores best on the fitted data.

use super::DiagnoseError;
use super::context::{Context, Evaluated};
use super::screen::Screened;
use super::trial;
use super::verify::VERIFY_ROUNDS;
use crate::effects::Effect;

/// Refits the best screened sensor artifact of `screened` (by `score` on the fitted data,
/// and only when it beats `plain_score`) from its screening and from `baseline`.
/// A start that cannot be simulated is a rejected step; only cancelling is an error.
pub fn refine_best_artifact(
    cx: &Context,
    baseline: &Evaluated,
    screened: &mut [Screened],
    plain_score: f64,
    score: &dyn Fn(&Evaluated) -> f64,
) -> Result<(), DiagnoseError> {
    let best = (0..screened.len())
        .filter(|i| {
            let s = &screened[*i];
            s.candidate.effect == Effect::SensorArtifact && s.rejected.is_none()
        })
        .min_by(|a, b| score(&screened[*a].evaluated).total_cmp(&score(&screened[*b].evaluated)));
    let Some(i) = best else {
        return Ok(());
    };
    if score(&screened[i].evaluated) >= plain_score {
        return Ok(());
    }
    let c = screened[i].candidate.clone();
    let mut kept = screened[i].evaluated.clone();
    let mut steps = Vec::new();
    let from_user = cx.fit_artifact(baseline, &c);
    // The two starts' rounds run side by side ([`super::parallel`]), taken in order.
    let starts = [Ok(kept.clone()), from_user];
    let fits = super::parallel::map_reporting(
        starts.len(),
        cx.options.threads,
        &|k| {
            starts[k]
                .as_ref()
                .map(|s| cx.rounds(s.clone(), Some(&c), VERIFY_ROUNDS, None))
                .map_err(Clone::clone)
        },
        &mut |_, _| Ok(()),
    )?;
    for fit in fits {
        let stepped = match fit {
            Ok(stepped) => stepped,
            Err(e) if trial::is_fatal(&e) => return Err(e),
            Err(e) => {
                steps.push(trial::reason("start from the user's values", &e));
                continue;
            }
        };
        steps.extend(stepped.rejected);
        if score(&stepped.best) < score(&kept) {
            kept = stepped.best;
        }
    }
    let s = &mut screened[i];
    s.evaluated = kept;
    s.rejected_steps.extend(steps);
    s.note = format!(
        "{}; the plain parameters refitted with it, from the plain fit and from the \
         user's values",
        s.note
    );
    Ok(())
}
