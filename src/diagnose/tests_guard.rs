//! The verdict never worsens the held-out fit (issue 14): hand-made evaluations of a
//! small steady campaign through [`super::decide::report`].

use super::LabelledRecording;
use super::candidates::candidates;
use super::context::{Context, Evaluated};
use super::observe::observe;
use super::report::Report;
use super::screen::Screened;
use super::tests::steady;
use super::{DiagnoseError, DiagnoseOptions, decide, guard};
use crate::model::{Model, parse_model};

pub(super) fn bench() -> Model {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/presets/diagnosis-bench.toml");
    let text = std::fs::read_to_string(path).expect("the preset");
    parse_model(&text, "diagnosis-bench.toml").expect("the preset parses")
}

/// Four steady regimes of the crank: 3000 and 4000 rpm fitted, 3500 and 4500 held out.
pub(super) fn recordings() -> Vec<LabelledRecording> {
    [3000.0, 3500.0, 4000.0, 4500.0]
        .iter()
        .enumerate()
        .map(|(i, s)| steady(&format!("R{i}"), *s, 5.0, 2.0, 0.3, 40 + i as u64))
        .collect()
}

/// A model's amplitudes: the measured ones × (1 + `fitted`) on the fitted observations
/// and × (1 + `held`) on the held-out ones.
fn evaluated(cx: &Context, fitted: f64, held: f64, value: Option<f64>) -> Evaluated {
    let simulated = cx
        .observed
        .observations
        .iter()
        .zip(&cx.held_out)
        .map(|(o, h)| o.measured_rpm * (1.0 + if *h { held } else { fitted }))
        .collect();
    let factors = vec![1.0; cx.plain.len()];
    cx.scored(cx.user.clone(), None, simulated, factors, value)
}

fn decided(cx: &Context, baseline: &Evaluated, plain: &Evaluated, s: &[Screened]) -> Report {
    decide::report(cx, baseline, plain, s, &[], &[], None, 0.0)
}

fn with_context(check: impl Fn(&Context)) {
    let model = bench();
    let options = DiagnoseOptions::default();
    let observed = observe(&recordings(), 8.0).expect("observed");
    check(&Context::new(&model, &options, observed));
}

/// A recalibration that makes the held-out data worse (the control: 5.00 →
/// 5.31) is not `parameter_error`: the verdict is `none`, its fit is the user's model's,
/// and the explanation says the model misfits and names the worst mismatches.
#[test]
fn a_recalibration_that_worsens_held_out_data_is_none() {
    with_context(|cx| {
        let baseline = evaluated(cx, 0.05, 0.05, None);
        let plain = evaluated(cx, 0.0, 0.06, None);
        let (before, after) = (cx.chi2(&baseline, true), cx.chi2(&plain, true));
        // The case is what the test means: a misfit the recalibration worsens held out.
        assert!(
            before > decide::NONE_CHI2 && after > before,
            "{before} {after}"
        );
        let r = decided(cx, &baseline, &plain, &[]);
        assert_eq!(r.verdict.effect, "none");
        assert_eq!(r.fit.after, r.fit.before);
        let text = &r.verdict.explanation;
        assert!(
            text.contains("misfits") && text.contains("Worst mismatches"),
            "{text}"
        );
        assert!(
            text.contains("order 2"),
            "the worst mismatch is order 2: {text}"
        );
        // The same recalibration improving the held-out data is named.
        let plain = evaluated(cx, 0.0, 0.0, None);
        assert!(guard::improves(
            before,
            cx.chi2(&plain, true),
            guard::n_held(cx)
        ));
        let r = decided(cx, &baseline, &plain, &[]);
        assert_eq!(r.verdict.effect, "parameter_error");
        assert!(r.fit.after < r.fit.before, "{:?}", r.fit);
    });
}

/// An effect that beats a still worse plain fit by far more than the 15 % margin, but
/// worsens the user's held-out χ²/N (the 55 → 370), is not the verdict; a
/// rejected candidate is listed last with its reason and never named.
#[test]
fn an_effect_that_worsens_held_out_data_is_not_named() {
    with_context(|cx| {
        let list = candidates(cx.user, &["engine".to_string()], false);
        let c = list.first().expect("a candidate").clone();
        let baseline = evaluated(cx, 0.05, 0.05, None);
        let plain = evaluated(cx, 0.0, 0.12, None);
        let effect = evaluated(cx, 0.0, 0.07, Some(c.param.start));
        let screened = |e: Evaluated, rejected: Option<String>| Screened {
            candidate: c.clone(),
            evaluated: e,
            verified: rejected.is_none(),
            note: String::new(),
            in_time_domain: true,
            rejected,
            rejected_steps: Vec::new(),
            unsupported: None,
        };
        let why = DiagnoseError::Simulation {
            label: "Run-up".into(),
            message: "the reference speed is not > 0 at 0.34 s".into(),
        };
        let list = [
            screened(effect.clone(), None),
            Screened::rejected_at(&list[1], &plain, &why),
        ];
        let (before, with_effect) = (cx.chi2(&baseline, true), cx.chi2(&effect, true));
        assert!(with_effect > before, "{before} {with_effect}");
        let r = decided(cx, &baseline, &plain, &list);
        let row = r
            .candidates
            .iter()
            .find(|r| r.effect == c.effect.to_string());
        let row = row.expect("the effect's row");
        assert!(
            row.score
                < 0.85
                    * r.candidates
                        .iter()
                        .find(|r| r.effect == "parameter_error")
                        .unwrap()
                        .score
        );
        assert_eq!(r.verdict.effect, "none");
        assert!(r.fit.after <= r.fit.before);
        let last = r.candidates.last().expect("rows");
        assert_eq!(
            last.rejected.as_deref(),
            Some("screening: simulating `Run-up`: the reference speed is not > 0 at 0.34 s")
        );
        assert!(!last.verified);
        // The same effect improving the held-out data is named.
        let effect = evaluated(cx, 0.0, 0.0, Some(c.param.start));
        let r = decided(cx, &baseline, &plain, &[screened(effect.clone(), None)]);
        assert_eq!(r.verdict.effect, c.effect.to_string());
        assert!(r.fit.after < r.fit.before);
        // Unless something else it brings made the gain (its plain parameters' path, a
        // backlash's mesh damping): then it is set aside with that reason, and the
        // verdict is the one without it (`none`: the recalibration worsens the held-out
        // data).
        let why = "gains too little by its own effect";
        let mut unsupported = screened(effect, None);
        unsupported.unsupported = Some(why.to_string());
        let r = decided(cx, &baseline, &plain, &[unsupported]);
        assert_eq!(r.verdict.effect, "none");
        assert_eq!(r.fit.after, r.fit.before);
        let row = r
            .candidates
            .iter()
            .find(|r| r.effect == c.effect.to_string());
        assert_eq!(row.and_then(|r| r.set_aside.as_deref()), Some(why));
    });
}
