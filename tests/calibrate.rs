//! `torsim::calibrate` against exact answers: targets computed from a known model are met
//! again, and the knobs found, from a start 20–40 % off; bad knobs and targets are refused
//! with their names.

use torsim::calibrate::{
    CalibrateError, Knob, Target, calibrate, evaluate, parameter_value, set_parameter,
};
use torsim::model::{Model, parse_model, presets};

fn rig() -> Model {
    let p = presets::preset("test-rig-70sh").expect("preset");
    parse_model(p.text, "test-rig-70sh.toml").expect("model")
}

fn knob(parameter: &str, lo: f64, hi: f64) -> Knob {
    Knob {
        parameter: parameter.into(),
        lo,
        hi,
    }
}

/// Mode and IR targets of `truth`: three modes, and IR at two stations and three regimes.
fn targets_of(truth: &Model) -> Vec<Target> {
    let mut targets: Vec<Target> = (1..=3)
        .map(|mode| Target::ModeHz {
            mode,
            hz: 1.0,
            tolerance_pct: 1.0,
        })
        .collect();
    for station in ["engine", "middle_flange"] {
        for regime in ["A", "C", "F"] {
            targets.push(Target::Irregularity {
                station: station.into(),
                regime: regime.into(),
                pct: 1.0,
                tolerance_pct: 10.0,
            });
        }
    }
    let values = evaluate(truth, &targets).expect("truth evaluates");
    targets
        .into_iter()
        .zip(values)
        .map(|(t, v)| match t {
            Target::ModeHz {
                mode,
                tolerance_pct,
                ..
            } => Target::ModeHz {
                mode,
                hz: v,
                tolerance_pct,
            },
            Target::Irregularity {
                station,
                regime,
                tolerance_pct,
                ..
            } => Target::Irregularity {
                station,
                regime,
                pct: v,
                tolerance_pct,
            },
        })
        .collect()
}

#[test]
fn a_perturbed_rig_is_calibrated_back_to_its_truth() {
    let truth = rig();
    let targets = targets_of(&truth);
    let knobs = [
        knob("inertia.middle_flange", 0.01, 1.0),
        knob("connection.c.stiffness", 1e3, 1e5),
        knob("connection.b.psi,connection.c.psi", 0.2, 3.0),
        knob("harmonic.2.amplitude", 0.1, 200.0),
    ];
    let true_values: Vec<f64> = knobs
        .iter()
        .map(|k| parameter_value(&truth, &k.parameter).expect("value"))
        .collect();
    let factors = [1.3, 0.75, 1.4, 0.6];
    let mut start = truth.clone();
    for ((k, v), f) in knobs.iter().zip(&true_values).zip(factors) {
        set_parameter(&mut start, &truth, &k.parameter, v * f).expect("knob");
    }
    let c = calibrate(&start, &knobs, &targets, 80, 0, 2).expect("calibration");
    // The truth meets every target exactly, so the fit must reach a cost at rounding level
    // and the knobs the truth's values: the nine targets constrain the four knobs.
    assert!(c.cost < 1e-8, "cost {}", c.cost);
    for ((k, v), want) in knobs.iter().zip(&c.values).zip(&true_values) {
        assert!(
            (v / want - 1.0).abs() < 1e-3,
            "{}: {v} against {want}",
            k.parameter
        );
    }
    for (t, a) in targets.iter().zip(&c.achieved) {
        let want = match t {
            Target::ModeHz { hz, .. } => *hz,
            Target::Irregularity { pct, .. } => *pct,
        };
        assert!((a / want - 1.0).abs() < 1e-4, "{t:?}: {a}");
    }
}

#[test]
fn the_regime_speed_factor_scales_every_regime_of_the_base() {
    let base = rig();
    let mut m = base.clone();
    set_parameter(&mut m, &base, "operation.regime_speed_factor", 1.1).expect("knob");
    set_parameter(&mut m, &base, "operation.regime_speed_factor", 1.1).expect("knob");
    for (a, b) in m.operation.regimes.iter().zip(&base.operation.regimes) {
        assert!((a.speed_rpm - 1.1 * b.speed_rpm).abs() < 1e-9);
    }
}

#[test]
fn unknown_knobs_and_bad_targets_are_refused_by_name() {
    let base = rig();
    let modes = [Target::ModeHz {
        mode: 1,
        hz: 9.0,
        tolerance_pct: 1.0,
    }];
    for (name, words) in [
        ("inertia.flywheel", "inertia.flywheel"),
        (
            "connection.gearbox.stiffness",
            "connection.gearbox.stiffness",
        ),
        ("harmonic.9.amplitude", "harmonic.9.amplitude"),
        ("connection.b.psi,connection.x.psi", "connection.x.psi"),
    ] {
        let err = calibrate(&base, &[knob(name, 0.1, 1.0)], &modes, 5, 0, 1).unwrap_err();
        assert!(
            matches!(&err, CalibrateError::Input(m) if m.contains(words)),
            "{name}: {err}"
        );
    }
    let err = calibrate(&base, &[knob("inertia.engine", 0.0, 1.0)], &modes, 5, 0, 1).unwrap_err();
    assert!(err.to_string().contains("0 < lo < hi"), "{err}");
    let missing = [Target::Irregularity {
        station: "engine".into(),
        regime: "Z".into(),
        pct: 2.0,
        tolerance_pct: 10.0,
    }];
    let err = calibrate(
        &base,
        &[knob("inertia.engine", 0.1, 1.0)],
        &missing,
        5,
        0,
        1,
    )
    .unwrap_err();
    assert!(matches!(err, CalibrateError::Start(_)), "{err}");
}
