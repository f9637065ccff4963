//! Why a candidate is not the verdict, in the words of the rule that passed it over
//! (issue 14: the report says what the campaign can tell apart). The candidates table is
//! ranked by score, and a candidate above the verdict, or one that beats the plain fit,
//! would otherwise read as a mistake: validation case 1040 listed a local mode with
//! held-out χ²/N 4.9 under a verdict of 12.7 and gave no reason (the mode was tuned to the
//! edge of the excited band).
//!
//! The rules are [`super::decide`]'s: verified in the time domain, the margin over the
//! plain fit ([`super::decide::EFFECT_MARGIN`], a branch's own
//! [`super::branch::BRANCH_MARGIN`]), a branch inside the excited band
//! ([`super::branch::inside`]), a sensor artifact's locality ([`super::sensor_local`]) and
//! the held-out guard ([`super::guard`]), and an effect fitted to its own absence
//! ([`super::param::Param::is_absent`]). The margin is checked before the band and the
//! locality: a candidate that gains nothing is named for that, not for where it settled.

use super::branch;
use super::candidates::Candidate;
use super::context::{Context, Evaluated};
use super::guard;
use super::report;

/// The plain fit and the user's model, as the rules compare against them.
pub struct Against<'a> {
    /// The plain recalibration.
    pub plain: &'a Evaluated,
    /// Its score.
    pub plain_score: f64,
    /// The user's model's held-out χ²/N.
    pub before: f64,
}

/// The first rule that candidate `c`, fitted to `evaluated` and reported as `row`, fails,
/// as a sentence; `None` when it passes them all (it may still have lost on score to a
/// better candidate).
pub fn reason(
    cx: &Context,
    c: &Candidate,
    evaluated: &Evaluated,
    row: &report::Candidate,
    against: &Against,
) -> Option<String> {
    if !row.verified {
        return Some(
            "only screened on the linear model: not checked in the time domain".to_string(),
        );
    }
    if !branch::clears_margin(c, row.score, against.plain_score) {
        let margin = branch::margin(c);
        let gain = 1.0 - row.score / against.plain_score;
        let what = if branch::is_branch(c) {
            "a local mode searched at every node"
        } else {
            "new physics"
        };
        return Some(if gain > 0.0 {
            format!(
                "beats the plain parameters' score by {:.0} %, short of the {:.0} % {what} \
                 must show on held-out data",
                100.0 * gain,
                100.0 * margin
            )
        } else {
            "scores no better than the plain parameters alone".to_string()
        });
    }
    if c.param.is_absent(evaluated.value) {
        return Some(format!(
            "fitted to no effect ({} = {:.4}, where the effect is absent): what it gains \
             over the plain parameters is the path its fit took, not the effect",
            c.param.key,
            evaluated.value.unwrap_or(f64::NAN)
        ));
    }
    if !branch::inside(c, evaluated.value) {
        let v = evaluated.value.unwrap_or(f64::NAN);
        return Some(format!(
            "tuned to the edge of the excited band ({v:.1} Hz of {:.1}–{:.1} Hz): no \
             resonance inside the band, only inertia or stiffness, which the plain \
             parameters already fit",
            c.param.lo, c.param.hi
        ));
    }
    if !super::sensor_local::local(cx, c, against.plain, evaluated) {
        return Some(
            "the other stations see the same mismatch in the same runs and orders: a \
             sensor shows its fault at its own station only"
                .to_string(),
        );
    }
    if !guard::improves(against.before, row.residual_after, guard::n_held(cx)) {
        return Some(format!(
            "its held-out χ²/N ({:.2}) does not improve on the user's model's ({:.2}) by \
             more than chance",
            row.residual_after, against.before
        ));
    }
    None
}
