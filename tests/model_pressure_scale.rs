//! The model-format extension `[engine] pressure_scale` (one factor per cylinder on its
//! gauge pressure; cylinder imbalance): read, validated with the key and line named,
//! written back, and used by the physics (mean torque, half orders) and the time domain.

use torsim::model::{parse_model, presets, to_toml_string};
use torsim::physics::{Excitation, OperatingPoint, System};
use torsim::recording::Run;
use torsim::transient::{RunOptions, simulate};

fn bench_with(line: &str) -> String {
    let text = presets::preset("diagnosis-bench").unwrap().text;
    text.replace(
        "reciprocating_mass = 0.6\n",
        &format!("reciprocating_mass = 0.6\n{line}\n"),
    )
}

#[test]
fn reads_validates_and_round_trips() {
    let text = bench_with("pressure_scale = [1.0, 1.0, 0.85, 1.0]");
    let m = parse_model(&text, "b.toml").unwrap();
    let e = m.engine.as_ref().unwrap();
    assert_eq!(e.pressure_scale, Some(vec![1.0, 1.0, 0.85, 1.0]));
    assert_eq!(e.pressure_scale_of(2), 0.85);
    assert_eq!(parse_model(&to_toml_string(&m), "w.toml").unwrap(), m);
    let plain = parse_model(presets::preset("diagnosis-bench").unwrap().text, "p").unwrap();
    assert_eq!(plain.engine.as_ref().unwrap().pressure_scale_of(2), 1.0);
    assert!(!to_toml_string(&plain).contains("pressure_scale"));

    let line_of = |text: &str| {
        text.lines()
            .position(|l| l.contains("pressure_scale"))
            .unwrap()
            + 1
    };
    let short = bench_with("pressure_scale = [1.0, 0.9]");
    let err = parse_model(&short, "b.toml").unwrap_err();
    assert_eq!(err.key, "engine.pressure_scale");
    assert_eq!(err.line, Some(line_of(&short)));
    assert!(err.message.contains("4 cylinders"), "{}", err.message);
    let negative = bench_with("pressure_scale = [1.0, 1.0, -0.1, 1.0]");
    let err = parse_model(&negative, "b.toml").unwrap_err();
    assert_eq!(err.key, "engine.pressure_scale[2]");
    let wrong = bench_with("pressure_scale = \"weak\"");
    assert!(parse_model(&wrong, "b.toml").is_err());
}

/// One cylinder dead of four: the mean torque is 3/4 and the half orders appear in the
/// forcing (identical cylinders cancel them exactly).
#[test]
fn physics_scales_the_mean_torque_and_excites_half_orders() {
    let equal = parse_model(&bench_with(""), "e").unwrap();
    let weak = parse_model(&bench_with("pressure_scale = [1.0, 1.0, 0.0, 1.0]"), "w").unwrap();
    let mean = |m: &torsim::model::Model| {
        let s = System::new(m, OperatingPoint::default()).unwrap();
        s.mean_torque_nm[2].unwrap()
    };
    assert!((mean(&weak) / mean(&equal) - 0.75).abs() < 1e-12);
    let half = |m: &torsim::model::Model| {
        let s = System::new(m, OperatingPoint::default()).unwrap();
        let x = Excitation::new(m, &s, 1.0, &[0.5, 2.0]);
        let mut f = vec![num_complex::Complex64::default(); s.dof_count()];
        x.forcing(0, 3000.0, &mut f);
        f[0].norm()
    };
    assert!(half(&equal) < 1e-9 * mean(&equal).abs());
    assert!(half(&weak) > 0.05 * mean(&equal).abs());
}

/// The time domain: a steady run with a weak cylinder has a crank order 0.5 where equal
/// cylinders have none, and the brake takes the lower mean torque (the run settles).
#[test]
fn time_domain_uses_the_factors() {
    let kind = Run::steady(4440.0, 0.5);
    let options = RunOptions {
        rate_hz: 4096.0,
        ..RunOptions::default()
    };
    let order_half = |text: &str| {
        let m = parse_model(text, "m").unwrap();
        let sim = simulate(&m, kind, options, &mut |_| true).unwrap();
        let rec = torsim::transient::to_recording(&sim, kind, 1.0, 4, "m");
        let a = torsim::signal::analyse(&rec).unwrap();
        assert!(sim.settling.converged);
        a.stations[0].orders[0].amplitude
    };
    let equal = order_half(&bench_with(""));
    let weak = order_half(&bench_with("pressure_scale = [1.0, 1.0, 0.9, 1.0]"));
    assert!(equal < 1e-3 && weak > 1.0, "equal {equal}, weak {weak}");
}
