//! Each effect leaves its physical signature in the generated recordings, checked with
//! `torsim::signal::analyse` against the same campaign made from the user's model (effect
//! `none`), on a noiseless bench so that the differences are the effect's alone. The
//! thresholds sit well inside the measured values quoted in each test.

mod synth_support;

use synth_support::{
    bench, data_model, make, order, peak, perfect, rec, run_up, steady, track, truth,
};
use torsim::model::Model;
use torsim::recording::{Recording, RunKind};
use torsim::signal::analyse;
use torsim::synth::{Effect, EffectSpec, PlannedRun, SynthRecording};

/// Recordings of `runs` from the user's model and from the truth with `spec`.
fn pair(
    user: &Model,
    spec: &EffectSpec,
    runs: impl Fn() -> Vec<PlannedRun>,
) -> (Vec<SynthRecording>, Vec<SynthRecording>) {
    let none = make(
        &truth(user, &EffectSpec::new(Effect::None)),
        runs(),
        &perfect(),
    );
    let effect = make(&truth(user, spec), runs(), &perfect());
    (none, effect)
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-12)
}

/// One cylinder at 0.95 pressure: the half orders appear (identical cylinders give only
/// orders 2, 4, 6 …), strongest at Regime D where order 0.5 meets mode 1 (4315 rpm).
/// Measured: engine order 0.5 at D 3.6 rpm (none: below 1e-3), order 1.5 at A 0.46 rpm.
#[test]
fn cylinder_imbalance_raises_the_half_orders() {
    let spec = EffectSpec::new(Effect::CylinderImbalance)
        .with("cylinder", 3)
        .with("pressure_scale", 0.95);
    let runs = || vec![steady("a", 3000.0, 1.0, 1.0), steady("d", 4440.0, 1.0, 1.0)];
    let (none, eff) = pair(&bench(), &spec, runs);
    for file in ["a", "d"] {
        for q in [0.5, 1.0, 1.5] {
            let (n, e) = (
                order(rec(&none, file), "engine", q),
                order(rec(&eff, file), "engine", q),
            );
            assert!(
                n < 0.01 && e > 0.2,
                "{file} order {q}: none {n}, imbalance {e}"
            );
        }
        let (n, e) = (
            order(rec(&none, file), "engine", 2.0),
            order(rec(&eff, file), "engine", 2.0),
        );
        assert!(rel(e, n) < 0.1, "{file} order 2: {n} → {e}");
    }
    assert!(order(rec(&eff, "d"), "engine", 0.5) > 2.0);
}

/// 0.1° of backlash: the gear rattles at part load (mean torque 153 N·m at the output,
/// less than its vibratory torque near mode 2) and not at full load (510 N·m). Measured at
/// Regime C, coupling order 2: full load unchanged to 1e-4, part load +35 %.
#[test]
fn gear_backlash_shows_at_part_load_only() {
    let spec = EffectSpec::new(Effect::GearBacklash).with("backlash_deg", 0.1);
    let runs = || {
        vec![
            steady("full", 3960.0, 1.0, 1.0),
            steady("part", 3960.0, 0.3, 1.0),
        ]
    };
    let (none, eff) = pair(&bench(), &spec, runs);
    let d = |f: &str| {
        rel(
            order(rec(&eff, f), "coupling_es", 2.0),
            order(rec(&none, f), "coupling_es", 2.0),
        )
    };
    assert!(
        d("full") < 0.005 && d("part") > 0.1,
        "full {}, part {}",
        d("full"),
        d("part")
    );
}

/// Seed 000 eq. 1: the stage is stiffer at full load (static twist 0.46°, element
/// deformation 1 mm, tangent factor 1.05) than at 30 % load (1.02), so Regime C's
/// resonant coupling order changes with load where the user's model does not.
#[test]
fn amplitude_nonlinearity_depends_on_load() {
    let spec = EffectSpec::new(Effect::CouplingAmplitudeNonlinearity);
    let runs = || {
        vec![
            steady("full", 3960.0, 1.0, 1.0),
            steady("part", 3960.0, 0.3, 1.0),
        ]
    };
    let (none, eff) = pair(&bench(), &spec, runs);
    let d = |f: &str| {
        rel(
            order(rec(&eff, f), "coupling_es", 2.0),
            order(rec(&none, f), "coupling_es", 2.0),
        )
    };
    eprintln!("amplitude: full {}, part {}", d("full"), d("part"));
    assert!(d("full") > 0.05 && d("full") > 3.0 * d("part"));
}

/// Analysis of the samples of `r` from `t0` to `t1` (s).
fn window(r: &Recording, t0: f64, t1: f64) -> Recording {
    let keep: Vec<usize> = (0..r.time_s.len())
        .filter(|&i| r.time_s[i] >= t0 && r.time_s[i] < t1)
        .collect();
    let mut out = r.clone();
    out.time_s = keep.iter().map(|&i| r.time_s[i] - t0).collect();
    for (c, src) in out.channels.iter_mut().zip(&r.channels) {
        c.values = keep.iter().map(|&i| src.values[i]).collect();
    }
    out
}

/// The rubber warms by its own loss and softens (seed 000 eq. 10): over 12 s at Regime C
/// the resonant coupling order drifts, while the user's model stays put. Measured: +1.6 %
/// from the first 3 s to the last 3 s (none: below 0.01 %).
#[test]
fn thermal_drift_shows_within_the_long_run() {
    let spec = EffectSpec::new(Effect::CouplingThermalDrift);
    let runs = || vec![steady("long", 3960.0, 1.0, 12.0)];
    let (none, eff) = pair(&bench(), &spec, runs);
    let drift = |recs: &[SynthRecording]| {
        let r = rec(recs, "long");
        let first = order(&window(r, 0.0, 3.0), "coupling_es", 2.0);
        let last = order(&window(r, 9.0, 12.0), "coupling_es", 2.0);
        (last - first) / first
    };
    let (n, e) = (drift(&none), drift(&eff));
    eprintln!("thermal drift: none {n}, truth {e}");
    assert!(n.abs() < 1e-3 && e.abs() > 0.008, "none {n}, thermal {e}");
}

/// The stiffness rises with frequency about the user's first mode: the run-up's mode-2
/// peak (order 2 near 4200 rpm) moves up several times more than the mode-1 peak (order 2
/// near 1200 rpm), which a stiffness error would move alike. Seed 000 eq. 9 × 0.3 here
/// (the shipped case has × 0.1, too small for the STFT's 0.1 s windows to place the
/// peaks this sharply). Measured: mode 1 −0.3 %, mode 2 +1.2 % (the causal chain and
/// the stiff shaft beside the coupling in mode 2 take most of α_f's +35 % at 140 Hz).
#[test]
fn frequency_dependence_moves_the_higher_mode() {
    let spec = EffectSpec::new(Effect::CouplingFrequencyDependence).with("scale", 0.3);
    let runs = || vec![run_up(1000.0, 6000.0, 15.0)];
    let (none, eff) = pair(&bench(), &spec, runs);
    let peaks = |recs: &[SynthRecording]| {
        let r = rec(recs, "run-up");
        (
            peak(&track(r, "engine", 2.0), 1000.0, 1700.0).0,
            peak(&track(r, "coupling_es", 2.0), 3500.0, 5000.0).0,
        )
    };
    let ((n1, n2), (e1, e2)) = (peaks(&none), peaks(&eff));
    eprintln!("frequency: mode 1 {n1} → {e1}, mode 2 {n2} → {e2}");
    let (s1, s2) = (e1 / n1 - 1.0, e2 / n2 - 1.0);
    assert!(
        s2 > 0.008 && s2 > 3.0 * s1.abs(),
        "mode 1 {s1}, mode 2 {s2}"
    );
}

/// Hysteretic loss is the same per cycle at every frequency; the user's viscous damper,
/// tuned at 140 Hz, has 36/140 of it at mode 1 (36 Hz: 2.0 % modal damping against 6.1 %):
/// the run-up's mode-1 peak (crank order 2 near 1200 rpm) is lower in the truth, while
/// the steady regime beside mode 2 (D) barely differs. A run-up sweeps through the sharp
/// resonance too fast to build it up fully, so the peak drops by less than the damping
/// ratio. Measured: peak 349 → 249 rpm (−29 %), Regime D coupling order 2 +0.3 %.
#[test]
fn hysteretic_damping_shows_in_the_run_up() {
    let user = data_model("model-viscous.toml");
    let spec = EffectSpec::new(Effect::HystereticDamping).with("reference_hz", 140.0);
    let runs = || vec![run_up(1000.0, 6000.0, 15.0), steady("d", 4440.0, 1.0, 1.0)];
    let (none, eff) = pair(&user, &spec, runs);
    let p = |recs: &[SynthRecording]| {
        peak(&track(rec(recs, "run-up"), "engine", 2.0), 1000.0, 1700.0).1
    };
    let (n, e) = (p(&none), p(&eff));
    let d = rel(
        order(rec(&eff, "d"), "coupling_es", 2.0),
        order(rec(&none, "d"), "coupling_es", 2.0),
    );
    assert!(e < 0.85 * n && d < 0.02, "peak {n} → {e}, D {d}");
}

/// A middle flange (0.1 kg·m²) splits the coupling: a local mode near 300 Hz appears that
/// no mode of the model explains; order 4 at the coupling crosses it near Regime D.
#[test]
fn unmodelled_mode_adds_a_resonance() {
    let spec = EffectSpec::new(Effect::UnmodelledMode).with("inertia_kg_m2", 0.1);
    let runs = || vec![run_up(1000.0, 6000.0, 15.0)];
    let (none, eff) = pair(&bench(), &spec, runs);
    let p = |recs: &[SynthRecording]| {
        peak(
            &track(rec(recs, "run-up"), "coupling_es", 4.0),
            4200.0,
            4900.0,
        )
        .1
    };
    let (n, e) = (p(&none), p(&eff));
    eprintln!("unmodelled: order 4 near D {n} → {e}");
    assert!(e > 1.4 * n, "{n} → {e}");
}

/// The order `q` phasor (rpm, complex) at `station`.
fn phasor(recording: &Recording, station: &str, q: f64) -> num_complex::Complex64 {
    let a = analyse(recording).unwrap();
    let s = a.stations.iter().find(|s| s.name == station).unwrap();
    let o = s
        .orders
        .iter()
        .find(|o| (o.order - q).abs() < 1e-9)
        .unwrap();
    num_complex::Complex64::from_polar(o.amplitude, o.phase_rad)
}

/// The reciprocating masses' variable inertia and their 4th-order torque (the user's
/// order-2 stand-in covers the 2nd): the engine's order 4 gains a part driven by a torque
/// ∝ ω², which above the modes (order 4 at 200–376 Hz) the crank answers with an IAS ∝
/// ω — so the difference grows with speed, where a speed-independent torque's would fall
/// as 1/ω. Order 2 stays. Measured: order-4 phasor difference 0.41 rpm at A, 0.89 rpm at
/// F (× 2.2 for a speed × 1.88); order 2 within 0.6 %.
#[test]
fn crank_variable_inertia_grows_with_speed() {
    let user = data_model("model-norecip.toml");
    let spec = EffectSpec::new(Effect::CrankVariableInertia)
        .with("mass_kg", 0.6)
        .with("drop_harmonics", "2");
    let runs = || vec![steady("a", 3000.0, 1.0, 1.0), steady("f", 5640.0, 1.0, 1.0)];
    let (none, eff) = pair(&user, &spec, runs);
    let d4 = |f: &str| {
        (phasor(rec(&eff, f), "engine", 4.0) - phasor(rec(&none, f), "engine", 4.0)).norm()
    };
    let d2 = |f: &str| {
        rel(
            order(rec(&eff, f), "engine", 2.0),
            order(rec(&none, f), "engine", 2.0),
        )
    };
    eprintln!(
        "crank: order 4 A {} F {}; order 2 A {} F {}",
        d4("a"),
        d4("f"),
        d2("a"),
        d2("f")
    );
    assert!(d4("a") > 0.1 && d4("f") > 1.5 * d4("a"));
    assert!(d2("a") < 0.02 && d2("f") < 0.02);
}

/// `recording` seen from station `node` as its own reference: orders of that shaft.
fn own_shaft(recording: &Recording, node: &str) -> Recording {
    let mut r = recording.clone();
    r.channels.retain(|c| c.kind.node() == Some(node));
    r.meta.reference = node.into();
    r.meta.kind = RunKind::Steady;
    r
}

fn shaft_order(r: &Recording, q: f64) -> f64 {
    let a = analyse(r).unwrap();
    a.stations[0]
        .orders
        .iter()
        .find(|o| (o.order - q).abs() < 1e-9)
        .map_or(0.0, |o| o.amplitude)
}

/// A zebra-tape joint is the measurement's: the other station's samples are identical to
/// the user model's, and at its own station it adds every integer order of that shaft
/// (engine orders k/3) with an amplitude proportional to the speed.
#[test]
fn sensor_artifact_is_at_one_station_in_shaft_orders_proportional_to_speed() {
    let spec = EffectSpec::new(Effect::SensorArtifact)
        .with("station", "coupling_es")
        .with("joint_fraction", 0.03);
    let runs = || vec![steady("a", 3000.0, 1.0, 1.0), steady("f", 5640.0, 1.0, 1.0)];
    let (none, eff) = pair(&bench(), &spec, runs);
    for f in ["a", "f"] {
        assert_eq!(rec(&none, f).channels[0], rec(&eff, f).channels[0]);
    }
    for q in [1.0, 2.0, 4.0, 5.0] {
        let amp = |f: &str| {
            shaft_order(&own_shaft(rec(&eff, f), "coupling_es"), q)
                - shaft_order(&own_shaft(rec(&none, f), "coupling_es"), q)
        };
        let (a, f) = (amp("a"), amp("f"));
        eprintln!("sensor: shaft order {q}: A {a}, F {f}");
        assert!(a > 0.1, "shaft order {q} at A: {a}");
        assert!(
            rel(f / a, 5640.0 / 3000.0) < 0.05,
            "shaft order {q}: {a} → {f}"
        );
        let half = shaft_order(&own_shaft(rec(&eff, "a"), "coupling_es"), q - 0.5);
        assert!(half < 0.05 * a, "half shaft order {}: {half}", q - 0.5);
    }
}

/// A stiffness 10 % low moves the coupling mode down (≈ √0.9) and adds no order content.
#[test]
fn parameter_error_moves_a_mode_without_new_orders() {
    let spec = EffectSpec::new(Effect::ParameterError)
        .with("target", "coupling")
        .with("factor", 0.9);
    let runs = || vec![run_up(1000.0, 6000.0, 15.0)];
    let (none, eff) = pair(&bench(), &spec, runs);
    let p = |recs: &[SynthRecording]| {
        peak(&track(rec(recs, "run-up"), "engine", 2.0), 1000.0, 1700.0).0
    };
    let (n, e) = (p(&none), p(&eff));
    eprintln!("parameter error: mode-1 peak {n} → {e}");
    assert!(e < 0.985 * n && e > 0.92 * n, "{n} → {e}");
    // A run-up's order analysis leaks the swept resonances into the half orders (up to
    // 0.042 rpm at the crank without the effect); the error adds to that leakage no more
    // than 0.03 rpm, a tenth of the smallest half order a real imbalance makes here (0.3
    // rpm, tests/data/diagnosis/README.md). Measured: at most 0.014 rpm.
    let halves = |recs: &[SynthRecording]| -> Vec<(f64, f64)> {
        analyse(rec(recs, "run-up"))
            .unwrap()
            .stations
            .iter()
            .flat_map(|s| s.orders.iter())
            .filter(|o| o.order.fract() != 0.0)
            .map(|o| (o.order, o.amplitude))
            .collect()
    };
    let (without, with) = (halves(&none), halves(&eff));
    assert_eq!(without.len(), with.len());
    for ((q, a), (_, b)) in without.iter().zip(&with) {
        assert!((b - a).abs() < 0.03, "half order {q}: {a} → {b} rpm");
    }
}
