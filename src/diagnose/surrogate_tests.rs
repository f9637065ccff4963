//! The campaign's linear prediction against one made run by run, the way it was made
//! before the runs shared their sweeps ([`super::super::sweeps`]), and the surrogate
//! around a point ([`super::Around`]).

use super::*;
use crate::diagnose::DiagnoseOptions;
use crate::diagnose::context::Context;
use crate::diagnose::observe::observe;
use crate::diagnose::spread::run_orders;
use crate::diagnose::tests_guard::{bench, recordings};
use crate::physics::Excitation;
use crate::response::forced_response;

/// The diagnosis bench's steady campaign with a wobble of ±0.4 % in every run's cycle
/// speeds (the hand-made recordings have none) and its second run at half load, so that
/// the runs fall into two sweeps.
fn campaign() -> (Model, Observed) {
    let model = bench();
    let mut observed = observe(&recordings(), 8.0).expect("observed");
    for (r, run) in observed.runs.iter_mut().enumerate() {
        let RunShape::Steady { speed_rpm } = run.regime else {
            panic!("a steady run");
        };
        run.cycle_speeds_rpm = vec![
            (0..60)
                .map(|k| speed_rpm * (1.0 + 0.004 * (0.37 * k as f64 + r as f64).sin()))
                .collect(),
        ];
    }
    observed.runs[1].load = 0.5;
    (model, observed)
}

/// Run by run: its own system and excitation, the full sweep at its speed, the wobble's
/// factor from 24 quantiles of its cycle speeds, then the sensors.
fn run_by_run(model: &Model, observed: &Observed) -> Vec<f64> {
    let mut out = vec![0.0; observed.observations.len()];
    for (r, run) in observed.runs.iter().enumerate() {
        let point = OperatingPoint {
            load: run.load,
            temperature_c: None,
        };
        let system = System::new(model, point).expect("system");
        let orders = run_orders(observed, r);
        let excitation = Excitation::new(model, &system, run.load, &orders);
        let RunShape::Steady { speed_rpm } = run.regime else {
            panic!("a steady run");
        };
        let mut cycles = run.cycle_speeds_rpm[0].clone();
        cycles.sort_by(f64::total_cmp);
        let mut speeds = vec![speed_rpm];
        speeds.extend((0..24).map(|k| cycles[((k as f64 + 0.5) / 24.0 * 60.0) as usize]));
        let response = forced_response(&system, &excitation, &speeds).expect("sweep");
        for (i, o) in observed.observations.iter().enumerate() {
            if o.run != r {
                continue;
            }
            let node = system.node_names.iter().position(|n| *n == o.station);
            let q = orders.iter().position(|x| *x == o.order);
            let a = &response.ias_amplitude_rpm[node.expect("node")][q.expect("order")];
            let spread = a[1..].iter().sum::<f64>() / 24.0;
            // An amplitude that is rounding (an order that does not reach the station)
            // keeps its factor of 1.
            let largest = a.iter().fold(0.0_f64, |m, x| m.max(*x));
            let factor = if a[0] > 1e-6 * largest && a[0] > 1e-9 {
                (spread / a[0]).clamp(1.0 / 1.5, 1.5)
            } else {
                1.0
            };
            out[i] = a[0] * factor;
        }
    }
    sensor::measure(observed, &ratios(model), None, &mut out);
    out
}

#[test]
fn the_shared_sweeps_predict_what_each_run_alone_does() {
    let (model, observed) = campaign();
    let shared = linear_predict(&model, &observed, None).expect("predicts");
    let alone = run_by_run(&model, &observed);
    assert_eq!(shared, alone);
    // The wobble and the load matter: the prediction is not the one without them.
    let (_, mut plain) = campaign();
    for run in &mut plain.runs {
        run.cycle_speeds_rpm.clear();
        run.load = 1.0;
    }
    let without = linear_predict(&model, &plain, None).expect("predicts");
    assert!(shared.iter().zip(&without).any(|(a, b)| a != b));
}

/// At its own point the surrogate is the time domain it was given; away from it the
/// search holds the point's wobble factors, so its prediction over the scored one is
/// exactly the ratio of the two points' factors, and the factors do move.
#[test]
fn the_surrogate_holds_its_points_wobble_during_a_search() {
    let (model, observed) = campaign();
    let options = DiagnoseOptions::default();
    let cx = Context::new(&model, &options, observed.clone());
    let linear = linear_predict(&model, &observed, None).expect("predicts");
    // A stand-in for the time domain at θ_k: 3 % above the linear model.
    let simulated: Vec<f64> = linear.iter().map(|v| 1.03 * v).collect();
    let around = Around::new(&model, &simulated, &observed, None);
    for got in [
        around.at(&model, &observed, None).expect("at"),
        around.searched(&model, &observed, None).expect("searched"),
    ] {
        for (g, t) in got.iter().zip(&simulated) {
            assert!((g - t).abs() <= 1e-14 * t, "{g} against {t}");
        }
    }
    let mut factors = vec![1.0; cx.plain.len()];
    factors[0] = 1.3;
    let moved = scaled(&model, &cx.plain, &factors).expect("scales");
    let searched = around.searched(&moved, &observed, None).expect("searched");
    let scored = around.at(&moved, &observed, None).expect("at");
    let (k, m) = (
        super::super::spread::spread_factors(&model, &observed),
        super::super::spread::spread_factors(&moved, &observed),
    );
    assert!(k.iter().zip(&m).any(|(a, b)| (a / b - 1.0).abs() > 1e-6));
    for i in 0..searched.len() {
        let c = around.correction[i];
        let ratio = (searched[i] - c) / (scored[i] - c);
        assert!(
            (ratio - k[i] / m[i]).abs() < 1e-12,
            "{i}: {ratio} against {}",
            k[i] / m[i]
        );
    }
}
