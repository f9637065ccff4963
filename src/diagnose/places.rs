//! Places the recordings cannot tell apart.
//!
//! An effect fitted at one place may predict exactly the same amplitudes at another: a
//! weak cylinder of an in-line four with even firing intervals changes every order's
//! amplitude the same way whichever cylinder it is (its half and odd orders are that
//! cylinder's own, phase-shifted, and the even ones are in phase for all four), and order
//! amplitudes carry no phase. The verdict then names the place the fit happened to
//! settle on, and says which others fit as well, rather than claim a place the data
//! cannot support.

use super::candidates::Candidate;
use super::context::{Context, Evaluated};
use super::residual::z_scores;
use super::screen::linear_sees;
use super::surrogate::{linear_predict, scaled};

/// Two places are the same to the recordings when the linear model's amplitudes differ by
/// less than this many noise standard deviations at every observation.
pub const SAME_Z: f64 = 0.01;

/// The places of `chosen`'s effect (other than its own) where the same fitted value, on
/// `at`'s plain parameters, predicts the same amplitudes within [`SAME_Z`]. Only effects
/// the linear model represents are compared (it is blind to backlash, thermal drift and
/// tape joints, so every place of those would look alike).
pub fn equivalent_places<'a>(
    cx: &Context,
    all: impl IntoIterator<Item = &'a Candidate>,
    chosen: &Candidate,
    at: &Evaluated,
) -> Vec<String> {
    let (Some(value), true) = (at.value, linear_sees(chosen)) else {
        return Vec::new();
    };
    let Ok(base) = scaled(cx.user, &cx.plain, &at.factors) else {
        return Vec::new();
    };
    let z_at = |c: &Candidate| -> Option<Vec<f64>> {
        let (m, joint) = c.apply(&base, value).ok()?;
        let predicted = linear_predict(&m, &cx.observed, joint.as_ref())?;
        Some(z_scores(&cx.observed, &predicted))
    };
    let Some(reference) = z_at(chosen) else {
        return Vec::new();
    };
    let place = |c: &Candidate| c.fixed.first().map(|(_, v)| v.clone());
    all.into_iter()
        // The same form of the effect (its parameter is the same quantity).
        .filter(|c| c.effect == chosen.effect && c.param.key == chosen.param.key)
        .filter(|c| place(c) != place(chosen))
        .filter(|c| {
            z_at(c).is_some_and(|z| {
                z.iter()
                    .zip(&reference)
                    .all(|(a, b)| (a - b).abs() < SAME_Z)
            })
        })
        .filter_map(place)
        .collect()
}
