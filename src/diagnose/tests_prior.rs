//! The plain prior weighed against the model floor ([`Context::prior_weight`]): where the
//! data cannot be fitted to their noise, a heavier prior keeps the plain fit near the
//! user's values instead of letting it buy the misfit with large changes.

use super::DiagnoseOptions;
use super::context::Context;
use super::observe::observe;
use super::tests_guard::{bench, recordings};

/// The norm √Σ(ln f)² of the plain fit's best proposal and its fitted χ²/N, with the
/// prior weighed by `w`, from a model whose amplitudes are the measured ones 40 % too high
/// and too low by turns (a misfit of the model's form, which no plain parameter removes:
/// moving them buys little of it).
fn plain_change(w: f64) -> (f64, f64) {
    let model = bench();
    let options = DiagnoseOptions {
        threads: 1,
        ..DiagnoseOptions::default()
    };
    let observed = observe(&recordings(), 8.0).expect("observed");
    let mut cx = Context::new(&model, &options, observed);
    cx.prior_weight = w;
    let simulated = cx
        .observed
        .observations
        .iter()
        .enumerate()
        .map(|(i, o)| o.measured_rpm * if i % 2 == 0 { 1.4 } else { 0.6 })
        .collect();
    let factors = vec![1.0; cx.plain.len()];
    let at = cx.scored(cx.user.clone(), None, simulated, factors, None);
    let proposals = cx.plain_proposals(&at).expect("a proposal");
    let best = &proposals[0];
    let squares: f64 = best.factors.iter().map(|f| f.ln().powi(2)).sum();
    (squares.sqrt(), cx.chi2(best, false))
}

/// With weight 1 the fit moves the factors by √Σ(ln f)² > 0.1 and still misfits
/// (χ²/N ≫ 1); with the weight that floor sets, as a diagnosis weighs it (√F), they move
/// less than half as far (measured: 0.75 → 0.35 at F = 66). A heavier prior can never
/// move them farther at the minimum (the regularisation path is monotone); "half" says
/// the floor's weight matters.
#[test]
fn a_heavier_prior_keeps_the_plain_fit_near_the_users_values() {
    let (free, floor) = plain_change(1.0);
    assert!(free > 0.1, "weight 1: √Σ(ln f)² = {free}");
    assert!(floor > 10.0, "weight 1: fitted χ²/N {floor}");
    let (held, _) = plain_change(floor.sqrt());
    assert!(
        held < 0.5 * free,
        "weight √{floor:.0}: {held} against {free}"
    );
}
