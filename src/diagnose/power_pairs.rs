//! Which two effects a campaign can tell apart (issue 14, item 6): the non-centrality of
//! effect A's signature at its detectable size after the best fit by effect B and the
//! plain parameters, and the other way round.
//!
//! The share of A's λ that B's best fit leaves, `ρ(A|B) = λ(A | plain, B) / λ(A | plain)`,
//! does not depend on A's size (the analysis is linear in it): at `c` times its
//! detectable size A still stands out from B with 80 % power when `c²·ρ ≥ 1`. Two
//! effects count as *separable* when each does at twice its detectable size (the size the
//! check of issue 14 diagnoses), that is `ρ ≥ 1/4` both ways; A is told from B at
//! `detectable size / √ρ`.

use super::power::Analysed;
use super::power_eval::Evaluator;
use super::power_fisher::{Column, projected_lambda};
use serde::Serialize;

/// Smallest share of its λ an effect must keep after another's best fit to count as
/// separable from it (module docs).
pub const SEPARABLE_SHARE: f64 = 0.25;

/// Two effects, each at its most detectable place.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairSeparation {
    /// Effect A (with its place).
    pub a: String,
    /// Effect B.
    pub b: String,
    /// λ of A at its reference size (detectable, else typical) after B's and the plain
    /// parameters' best fit.
    pub lambda_a_given_b: f64,
    /// The same of B after A's.
    pub lambda_b_given_a: f64,
    /// ρ(A|B): the share of A's λ that B leaves.
    pub share_a: f64,
    /// ρ(B|A).
    pub share_b: f64,
    /// ρ ≥ 1/4 both ways.
    pub separable: bool,
}

/// The name of an analysed candidate: `gear_backlash at gearbox`.
pub fn name(a: &Analysed) -> String {
    a.candidate.name()
}

/// `ρ(A|B)` and `λ(A | plain, B)` at A's reference size.
pub fn share(ev: &Evaluator, a: &Analysed, b: &Analysed) -> (f64, f64) {
    let s_a = a.reference_size();
    let d = a.signature_at(s_a);
    let s_b = b.reference_size();
    let column = Column {
        values: b.signature_at(s_b).iter().map(|x| x / s_b).collect(),
        prior: 0.0,
    };
    let mut cols = ev.plain_columns();
    let alone = projected_lambda(&d, &ev.weights, &cols);
    cols.push(&column);
    let with_b = projected_lambda(&d, &ev.weights, &cols);
    if alone <= 0.0 {
        return (0.0, 0.0);
    }
    (with_b / alone, with_b)
}

/// The most detectable place of each effect, in the order first seen.
pub fn representatives(all: &[Analysed]) -> Vec<&Analysed> {
    let mut out: Vec<&Analysed> = Vec::new();
    for a in all {
        let better = |x: &Analysed| {
            let key = |y: &Analysed| y.row.detectable_relative.unwrap_or(f64::INFINITY);
            key(x) < key(a) || (key(x) == key(a) && x.row.lambda_typical >= a.row.lambda_typical)
        };
        match out
            .iter()
            .position(|x| x.candidate.effect == a.candidate.effect)
        {
            Some(k) if !better(out[k]) => out[k] = a,
            Some(_) => {}
            None => out.push(a),
        }
    }
    out
}

/// Every two effects' separation.
pub fn pairs(ev: &Evaluator, all: &[Analysed]) -> Vec<PairSeparation> {
    let reps = representatives(all);
    let mut out = Vec::new();
    for (i, a) in reps.iter().enumerate() {
        for b in &reps[i + 1..] {
            let (share_a, lambda_a) = share(ev, a, b);
            let (share_b, lambda_b) = share(ev, b, a);
            out.push(PairSeparation {
                a: name(a),
                b: name(b),
                lambda_a_given_b: lambda_a,
                lambda_b_given_a: lambda_b,
                share_a,
                share_b,
                separable: share_a >= SEPARABLE_SHARE && share_b >= SEPARABLE_SHARE,
            });
        }
    }
    out
}

/// The size at which an effect is told from another: `detectable / √ρ` gives
/// [`super::power_fisher::LAMBDA_DETECT`] after the other's fit.
pub fn size_to_tell(a: &Analysed, share: f64) -> Option<f64> {
    (share > 0.0).then(|| a.reference_size() / share.sqrt())
}
