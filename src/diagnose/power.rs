//! `torsim diagnose MODEL --power`: what a campaign can detect and tell apart, before it
//! is run (issue 14, item 6). A linearised detectability analysis:
//!
//! 1. the observables of the plan, each with its σ ([`super::power_plan`]);
//! 2. each candidate effect's signature (the change of every observable) at sizes around
//!    its typical one, and the plain parameters' sensitivities ([`super::power_eval`]);
//! 3. the χ² non-centrality `λ(s)` of the signature after the best recalibration of the
//!    plain parameters (the Schur complement, [`super::power_fisher`]); the *detectable
//!    size* is the smallest with `λ ≥ 7.85` (a χ² test at 5 % with 80 % power, one
//!    degree of freedom), interpolated log–log between sizes a factor 2 apart;
//! 4. separation of every two effects ([`super::power_pairs`]) and what to add to the
//!    plan where two cannot be told apart or one is not detectable
//!    ([`super::power_add`]).

use super::DiagnoseError;
use super::candidates::{Candidate, candidates};
use super::holdout::held_out;
use super::power_eval::{Evaluator, in_time_domain};
use super::power_fisher::{LAMBDA_DETECT, projected_lambda};
use super::power_named::Rule;
use super::power_plan::{Bench, planned};
use super::power_size::{EffectSize, SizeLaw, effect_size};
use crate::campaign::Plan;
use crate::effects::Effect;
use crate::model::Model;
use serde::Serialize;

/// Sizes tried for a surrogate effect: its typical size times `2^k` for these `k`.
const SIZE_STEPS: std::ops::RangeInclusive<i32> = -7..=4;
/// Reference frequencies tried for the null of hysteretic damping, Hz (log grid).
const HYSTERETIC_GRID: usize = 24;

/// One candidate effect at one place.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EffectPower {
    /// `"gear_backlash"`.
    pub effect: String,
    /// `"gearbox"`, `"cylinder 3"`, … (empty when the effect has no place).
    pub place: String,
    /// Unit of the sizes.
    pub unit: String,
    /// The size it is compared at ([`super::power_size`]).
    pub typical_size: f64,
    /// The smallest size this campaign detects (`None`: not within the candidate's
    /// bounds).
    pub detectable_size: Option<f64>,
    /// The detectable size as the candidate's parameter (`backlash_deg = 0.0123`).
    pub detectable_parameter: String,
    /// The detectable size over the typical one.
    pub detectable_relative: Option<f64>,
    /// λ at the typical size, after the plain parameters' best recalibration.
    pub lambda_typical: f64,
    /// λ at the typical size before it (what the effect shows at all).
    pub lambda_typical_raw: f64,
    /// Detectable at its typical size (λ ≥ 7.85).
    pub detectable: bool,
    /// The smallest size the diagnosis' decision rule names it at on this campaign's
    /// held-out amplitudes ([`super::power_named`]); larger than the detectable size,
    /// since the verdict asks for a misfit above twice the noise and a margin over the
    /// plain recalibration (`None`: not within the candidate's bounds).
    pub named_size: Option<f64>,
    /// The named size over the typical one.
    pub named_relative: Option<f64>,
    /// `"surrogate"` or `"time domain"`.
    pub evaluated_by: String,
}

/// The analysis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PowerReport {
    /// `"torsim-power/1"`.
    pub format: &'static str,
    /// The λ of 80 % power at 5 % (one degree of freedom).
    pub lambda_detect: f64,
    /// Per planned run: label, kind, observables and their σ range.
    pub runs: Vec<super::power_add::RunSummary>,
    /// Observables in all.
    pub observables: usize,
    /// White noise per sample, rpm; jitter, ns; rate, Hz.
    pub noise_rpm: f64,
    /// Pulse jitter, ns.
    pub jitter_ns: f64,
    /// Sample rate, Hz.
    pub rate_hz: f64,
    /// Stations.
    pub stations: Vec<String>,
    /// Every candidate, most detectable (relative) first within each effect.
    pub effects: Vec<EffectPower>,
    /// Every two effects (their most detectable places).
    pub pairs: Vec<super::power_pairs::PairSeparation>,
    /// What to add, per inseparable pair or undetectable effect.
    pub additions: Vec<super::power_add::Addition>,
    /// Wall time, s.
    pub elapsed_s: f64,
}

/// A candidate with its size, reference and signatures, as the analysis holds it.
pub struct Analysed {
    /// The candidate.
    pub candidate: Candidate,
    /// Its size law.
    pub size: EffectSize,
    /// Sizes evaluated and their signatures.
    pub signatures: Vec<(f64, Vec<f64>)>,
    /// Its row.
    pub row: EffectPower,
}

impl Analysed {
    /// The signature at size `s`: the nearest evaluated one, scaled linearly.
    pub fn signature_at(&self, s: f64) -> Vec<f64> {
        let near = self
            .signatures
            .iter()
            .min_by(|a, b| (a.0 / s).ln().abs().total_cmp(&(b.0 / s).ln().abs()));
        match near {
            Some((at, d)) => d.iter().map(|x| x * s / at).collect(),
            None => Vec::new(),
        }
    }

    /// Its reference size: detectable where it is, else the typical one.
    pub fn reference_size(&self) -> f64 {
        self.row.detectable_size.unwrap_or(self.row.typical_size)
    }
}

/// The place of a candidate for a person.
fn place(c: &Candidate) -> String {
    match c.fixed.first() {
        Some(("cylinder", v)) => format!("cylinder {v}"),
        Some(("drop_harmonics", _)) | None => String::new(),
        Some((_, v)) => v.clone(),
    }
}

/// The smallest size with `λ ≥` [`LAMBDA_DETECT`] from `(size, λ)` ascending.
fn detectable_size(points: &[(f64, f64)]) -> Option<f64> {
    let k = points.iter().position(|(_, l)| *l >= LAMBDA_DETECT)?;
    let (s1, l1) = points[k];
    if k == 0 {
        return Some(s1 * (LAMBDA_DETECT / l1).sqrt());
    }
    let (s0, l0) = points[k - 1];
    if l0 <= 0.0 {
        return Some(s1 * (LAMBDA_DETECT / l1).sqrt());
    }
    let t = (LAMBDA_DETECT / l0).ln() / (l1 / l0).ln();
    Some(s0 * (s1 / s0).powf(t))
}

/// The reference frequency at which hysteretic damping changes the observables least.
fn hysteretic_null(ev: &Evaluator, c: &Candidate) -> Option<f64> {
    let base: Vec<f64> = ev
        .observed
        .observations
        .iter()
        .map(|o| o.measured_rpm)
        .collect();
    let (lo, hi) = (c.param.lo.max(1.0), c.param.hi);
    let plain = ev.plain_columns();
    (0..HYSTERETIC_GRID)
        .filter_map(|k| {
            let f = lo * (hi / lo).powf(k as f64 / (HYSTERETIC_GRID - 1) as f64);
            let (m, _) = c.apply(ev.model, f).ok()?;
            let v = super::power_eval::expected_all(
                &ev.observed,
                super::surrogate::linear_predict(&m, &ev.observed, None)?,
            );
            let d: Vec<f64> = v.iter().zip(&base).map(|(a, b)| a - b).collect();
            Some((f, projected_lambda(&d, &ev.weights, &plain)))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(f, _)| f)
}

/// Analyses one candidate: signatures at its sizes, λ, the detectable size.
pub fn analyse_candidate(ev: &Evaluator, c: &Candidate) -> Option<Analysed> {
    let f0 = match c.effect {
        Effect::HystereticDamping => hysteretic_null(ev, c)?,
        _ => f64::NAN,
    };
    let size = effect_size(c, f0);
    let reference = ev.reference(c, &size)?;
    let sizes: Vec<f64> = if in_time_domain(c.effect) {
        vec![size.typical]
    } else {
        SIZE_STEPS
            .map(|k| size.typical * 2f64.powi(k))
            .filter(|s| *s <= size.max * (1.0 + 1e-9))
            .collect()
    };
    let plain = ev.plain_columns();
    let mut signatures = Vec::new();
    let mut points = Vec::new();
    for s in sizes {
        if let Some(d) = ev.signature(c, &size, s, &reference) {
            points.push((s, projected_lambda(&d, &ev.weights, &plain)));
            signatures.push((s, d));
        }
    }
    let (_, typical) = signatures
        .iter()
        .min_by(|a, b| {
            (a.0 / size.typical)
                .ln()
                .abs()
                .total_cmp(&(b.0 / size.typical).ln().abs())
        })?
        .clone();
    let lambda_typical = projected_lambda(&typical, &ev.weights, &plain);
    let lambda_raw = projected_lambda(&typical, &ev.weights, &[]);
    let detectable = detectable_size(&points).filter(|s| *s <= size.max * (1.0 + 1e-9));
    let named =
        named_size(ev, c, &signatures, size.typical).filter(|s| *s <= size.max * (1.0 + 1e-9));
    let parameter = detectable.map_or_else(
        || {
            format!(
                "not within {} ≤ {}",
                c.param.key,
                fmt_param(&size, size.max)
            )
        },
        |s| format!("{} = {}", c.param.key, fmt_param(&size, s)),
    );
    let row = EffectPower {
        effect: c.effect.to_string(),
        place: place(c),
        unit: size.unit.to_string(),
        typical_size: size.typical,
        detectable_size: detectable,
        detectable_parameter: parameter,
        detectable_relative: detectable.map(|s| s / size.typical),
        lambda_typical,
        lambda_typical_raw: lambda_raw,
        detectable: lambda_typical >= LAMBDA_DETECT,
        named_size: named,
        named_relative: named.map(|s| s / size.typical),
        evaluated_by: if in_time_domain(c.effect) {
            "time domain"
        } else {
            "surrogate"
        }
        .into(),
    };
    Some(Analysed {
        candidate: c.clone(),
        size,
        signatures,
        row,
    })
}

/// The smallest size the decision rule names `c` at ([`super::power_named`]): solved
/// from the signature evaluated nearest to it (signatures are nearly linear in the size
/// between grid points a factor 2 apart), from the typical size on.
fn named_size(
    ev: &Evaluator,
    c: &Candidate,
    signatures: &[(f64, Vec<f64>)],
    typical: f64,
) -> Option<f64> {
    let rule = Rule {
        held: held_out(&ev.observed),
        k_plain: ev.plain.len(),
        effect_margin: super::branch::margin(c),
    };
    let plain = ev.plain_columns();
    let solve = |(s0, d): &(f64, Vec<f64>)| rule.factor(d, &ev.weights, &plain).map(|t| s0 * t);
    let nearest = |s: f64| {
        signatures
            .iter()
            .min_by(|a, b| (a.0 / s).ln().abs().total_cmp(&(b.0 / s).ln().abs()))
    };
    let mut s = solve(nearest(typical)?)?;
    // Two refinements on the evaluated grid (the grid is a factor 2; a third changes
    // nothing where the signature is smooth).
    for _ in 0..2 {
        s = solve(nearest(s)?)?;
    }
    Some(s)
}

/// The candidate's parameter at size `s`, 4 significant digits.
fn fmt_param(size: &EffectSize, s: f64) -> String {
    let v = size.value(s);
    match size.law {
        SizeLaw::Inverse if v > 1e4 => format!("{v:.3e}"),
        _ => format!("{v:.4}"),
    }
}

/// Every candidate of `model` for the campaign `observed` describes: the first form of
/// each ([`super::candidates::candidates`]); the forms a diagnosis adds from the campaign
/// ([`super::searched`]) are not sized.
pub fn candidate_list(model: &Model, ev: &Evaluator) -> Vec<Candidate> {
    let campaign = super::searched::Campaign::of(&ev.observed);
    candidates(model, &campaign.stations, campaign.long_run)
}

/// Analyses every candidate of `model` on the observables of `plan` measured by
/// `bench`; `progress(fraction, stage)` returns `false` to cancel.
pub fn analyse_all<'a>(
    model: &'a Model,
    plan: &Plan,
    bench: &Bench,
    threads: usize,
    progress: &mut dyn FnMut(f64, &str) -> bool,
) -> Result<(Evaluator<'a>, Vec<Analysed>), DiagnoseError> {
    let observed = planned(model, plan, bench)
        .ok_or_else(|| DiagnoseError::Input("the model has no reference node".into()))?;
    let ev = Evaluator::new(model, observed, bench.max_order, threads).ok_or_else(|| {
        DiagnoseError::Input("the linear model of the user's model cannot be built".into())
    })?;
    let list = candidate_list(model, &ev);
    let mut out = Vec::with_capacity(list.len());
    for (k, c) in list.iter().enumerate() {
        if !progress(0.05 + 0.75 * k as f64 / list.len().max(1) as f64, &c.name()) {
            return Err(DiagnoseError::Cancelled);
        }
        if let Some(a) = analyse_candidate(&ev, c) {
            out.push(a);
        }
    }
    Ok((ev, out))
}
