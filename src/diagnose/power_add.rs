//! What to add to a campaign (issue 14, item 6): for every two effects the plan cannot
//! tell apart and every effect it cannot detect at its typical size, a small menu of
//! additions — a steady regime at another speed (full load) or at part load, a long run,
//! a run-up over the speed range (twice as slow when the plan has one), another station
//! — each analysed again, and the one that raises the measure most.
//!
//! The measure: for a pair, the smaller of `λ(A | plain, B)` and `λ(B | plain, A)` at the
//! sizes of the plan as given; for an effect, `λ` at its typical size after the plain
//! parameters' fit. Both are compared before and after on the same sizes.

use super::power::{Analysed, analyse_candidate};
use super::power_eval::Evaluator;
use super::power_pairs::{PairSeparation, share};
use super::power_plan::{Bench, planned};
use crate::campaign::{Plan, PlannedRun, Station};
use crate::model::Model;
use crate::recording::RunShape;
use serde::Serialize;

/// One recommendation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Addition {
    /// The pair (`A / B`) or effect it is for.
    pub target: String,
    /// The best addition, for a person (`steady 2400 rpm, load 1, 4 s`).
    pub add: String,
    /// The measure with the plan as given.
    pub before: f64,
    /// The measure with the addition.
    pub after: f64,
}

/// One planned run for the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunSummary {
    /// Label.
    pub label: String,
    /// `"steady"`, `"long run"` or `"run-up"`.
    pub kind: String,
    /// Observables.
    pub observables: usize,
    /// Smallest and largest σ, rpm.
    pub sigma_rpm: [f64; 2],
}

/// An addition to the plan or the bench.
#[derive(Debug, Clone)]
enum Extra {
    Run(PlannedRun),
    Station(Station),
}

impl Extra {
    fn describe(&self) -> String {
        match self {
            Extra::Run(r) => match r.shape {
                RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => format!(
                    "steady regime {speed_rpm:.0} rpm, load {}, {} s",
                    r.load, r.duration_s
                ),
                RunShape::Ramp { from_rpm, to_rpm } => format!(
                    "run-up {from_rpm:.0} → {to_rpm:.0} rpm, load {}, {} s",
                    r.load, r.duration_s
                ),
            },
            Extra::Station(s) => format!("station at {} ({} lines)", s.node, s.lines_per_rev),
        }
    }
}

/// The menu for `plan` on `model`.
fn menu(model: &Model, plan: &Plan, bench: &Bench) -> Vec<Extra> {
    let steady: Vec<f64> = plan
        .runs
        .iter()
        .filter(|r| !r.shape.is_ramp())
        .map(|r| r.shape.speeds_rpm()[0])
        .collect();
    let range = model
        .operation
        .speed_range_rpm
        .or(model.operation.operating_range_rpm)
        .or_else(|| {
            let lo = steady.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = steady.iter().copied().fold(0.0, f64::max);
            (lo.is_finite() && hi > lo).then_some([lo, hi])
        });
    let run = |label: String, shape, duration_s, load| {
        Extra::Run(PlannedRun {
            file: crate::campaign::plan::stem(&label),
            label,
            shape,
            duration_s,
            load,
            rate_hz: None,
        })
    };
    let mut out = Vec::new();
    if let Some([lo, hi]) = range {
        for f in [0.15, 0.4, 0.6, 0.85] {
            let v = (lo + (hi - lo) * f).round();
            if steady.iter().all(|s| (s - v).abs() > 0.05 * v) {
                out.push(run(
                    format!("Added {v} rpm"),
                    RunShape::steady(v, 4.0),
                    4.0,
                    1.0,
                ));
            }
        }
        let mid = (0.5 * (lo + hi)).round();
        out.push(run(
            format!("Added {mid} rpm part load"),
            RunShape::steady(mid, 4.0),
            4.0,
            0.3,
        ));
        if plan
            .runs
            .iter()
            .all(|r| !matches!(r.shape, RunShape::LongRun { .. }))
        {
            out.push(run(
                "Added long run".into(),
                RunShape::steady(mid, 30.0),
                30.0,
                1.0,
            ));
        }
        let slow = plan.runs.iter().any(|r| r.shape.is_ramp());
        let d = if slow { 120.0 } else { 60.0 };
        out.push(run(
            "Added run-up".into(),
            RunShape::Ramp {
                from_rpm: lo.max(1.0),
                to_rpm: hi,
            },
            d,
            1.0,
        ));
    }
    for node in &model.inertias {
        if bench.stations.iter().all(|s| s.node != node.name) {
            out.push(Extra::Station(Station {
                node: node.name.clone(),
                kind: "encoder".into(),
                lines_per_rev: 360,
            }));
        }
    }
    out
}

/// The measure of a target on `ev` with the candidates `a` (and `b`, for a pair) at the
/// sizes `sizes` (module docs).
fn measure(ev: &Evaluator, a: &Analysed, b: Option<&Analysed>) -> f64 {
    match b {
        Some(b) => share(ev, a, b).1.min(share(ev, b, a).1),
        None => a.row.lambda_typical,
    }
}

/// `a` analysed again on `ev`, at the reference size of the plan as given.
fn again(ev: &Evaluator, a: &Analysed) -> Option<Analysed> {
    let mut out = analyse_candidate(ev, &a.candidate)?;
    out.row.detectable_size = Some(a.reference_size());
    Some(out)
}

/// The best addition for every inseparable pair and every effect not detectable at its
/// typical size (`reps`: the effects' most detectable places).
pub fn recommend(
    model: &Model,
    plan: &Plan,
    bench: &Bench,
    base: &Evaluator,
    reps: &[&Analysed],
    pairs: &[PairSeparation],
    threads: usize,
) -> Vec<Addition> {
    let find = |name: &str| reps.iter().find(|r| r.candidate.name() == name).copied();
    let mut targets: Vec<(String, &Analysed, Option<&Analysed>)> = Vec::new();
    for p in pairs.iter().filter(|p| !p.separable) {
        if let (Some(a), Some(b)) = (find(&p.a), find(&p.b)) {
            targets.push((format!("{} / {}", p.a, p.b), a, Some(b)));
        }
    }
    for r in reps.iter().filter(|r| !r.row.detectable) {
        targets.push((r.candidate.name(), r, None));
    }
    if targets.is_empty() {
        return Vec::new();
    }
    let extras = menu(model, plan, bench);
    // Per extra: its evaluator and the involved candidates analysed on it.
    let mut tried: Vec<(String, Vec<Option<f64>>)> = Vec::new();
    for extra in &extras {
        let (mut p2, mut b2) = (plan.clone(), bench.clone());
        match extra {
            Extra::Run(r) => p2.runs.push(r.clone()),
            Extra::Station(s) => b2.stations.push(s.clone()),
        }
        let Some(ev) = planned(model, &p2, &b2)
            .and_then(|o| Evaluator::new(model, o, bench.max_order, threads))
        else {
            continue;
        };
        let values = targets
            .iter()
            .map(|(_, a, b)| {
                let a2 = again(&ev, a)?;
                match b {
                    Some(b) => Some(measure(&ev, &a2, Some(&again(&ev, b)?))),
                    None => Some(measure(&ev, &a2, None)),
                }
            })
            .collect();
        tried.push((extra.describe(), values));
    }
    targets
        .iter()
        .enumerate()
        .filter_map(|(k, (target, a, b))| {
            let before = measure(base, a, *b);
            let (add, after) = tried
                .iter()
                .filter_map(|(d, v)| Some((d.clone(), v.get(k).copied().flatten()?)))
                .max_by(|x, y| x.1.total_cmp(&y.1))?;
            Some(Addition {
                target: target.clone(),
                add,
                before,
                after,
            })
        })
        .collect()
}
