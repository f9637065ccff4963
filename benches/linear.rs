//! Benchmarks of the linear analyses: modes, Campbell diagram, forced response, and the
//! build of a system + excitation (what every GUI edit pays before the cheap results).
//!
//! Run with `cargo bench --bench linear`. Each job is measured for ~2 s with 30 samples so
//! the whole file runs in well under a minute. Targets (median): `modes/3dof` < 5 µs,
//! `modes/20dof` < 50 µs, `campbell/10dof_200_speeds` < 2 ms,
//! `response/10dof_200x24` < 5 ms.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use torsim::model::*;
use torsim::physics::{Excitation, OperatingPoint, System};

fn node(name: &str, inertia: f64, damping: f64) -> Inertia {
    Inertia {
        name: name.into(),
        inertia_kg_m2: inertia,
        damping_nm_s_per_rad: damping,
    }
}

fn shaft(from: &str, to: &str, k: f64, c: f64) -> Connection {
    Connection {
        name: Connection::default_name(from, to),
        from: from.into(),
        to: to.into(),
        kind: ConnectionKind::Shaft(Shaft::massless(k, c)),
    }
}

/// Seed 000's α_f(f) (eq. 9), held beyond its measured range [0, 300] Hz.
fn seed000_frequency_poly() -> Poly {
    Poly {
        coeffs: [-0.000023, 0.01519, 1.0],
        range: Some([0.0, 300.0]),
    }
}

fn rubber(from: &str, to: &str, k: f64, psi: f64, frequency_poly: Option<Poly>) -> Connection {
    Connection {
        name: Connection::default_name(from, to),
        from: from.into(),
        to: to.into(),
        kind: ConnectionKind::Rubber(RubberStage {
            stiffness: RubberStiffness::Direct(k),
            psi,
            temperature_c: 25.0,
            amplitude_poly: None,
            amplitude_saturation: None,
            amplitude_form: Default::default(),
            frequency_poly,
            frequency_power_law: None,
            frequency_zener: None,
            temperature_stiffness_poly: None,
            temperature_damping_poly: None,
            thermal: None,
            rating: None,
        }),
    }
}

fn model(inertias: Vec<Inertia>, connections: Vec<Connection>) -> Model {
    Model {
        name: "bench".into(),
        description: String::new(),
        inertias,
        connections,
        engine: None,
        harmonics: Vec::new(),
        load: None,
        modal_damping: None,
        operation: Operation::default(),
        expect: Expect::default(),
    }
}

fn system(model: &Model) -> System {
    System::new(model, OperatingPoint::default()).expect("bench model builds")
}

/// Seed 001's grounded 3-DOF form: engine 0.5, coupling 0.02, flange 0.01 kg·m²; shaft
/// 2e5, rubber 1e4, rubber 1e4 to ground; no frequency dependence. A 100 N·m first-order
/// harmonic on the engine.
fn three_dof() -> Model {
    let mut m = model(
        vec![
            node("engine", 0.5, 0.0),
            node("coupling", 0.02, 0.0),
            node("flange", 0.01, 0.0),
        ],
        vec![
            shaft("engine", "coupling", 2.0e5, 2.0),
            rubber("coupling", "flange", 1.0e4, 0.9, None),
            rubber("flange", GROUND, 1.0e4, 0.9, None),
        ],
    );
    m.harmonics.push(Harmonic {
        at: "engine".into(),
        order: 1.0,
        amplitude: HarmonicAmplitude::Constant(100.0),
        phase_deg: 0.0,
    });
    m
}

/// A free 20-DOF chain: a crank train of 9 throws, flywheel, a two-stage rubber coupling
/// (stages 9–10 and 10–11), a gearbox-and-generator shaft line of 9 nodes.
fn twenty_dof(frequency_poly: Option<Poly>) -> Model {
    let names: Vec<String> = (0..20).map(|i| format!("n{i}")).collect();
    let inertias = names
        .iter()
        .enumerate()
        .map(|(i, name)| node(name, 0.05 + 0.03 * ((i * 7) % 11) as f64, 0.0))
        .collect();
    let connections = (1..20)
        .map(|i| {
            let (a, b) = (&names[i - 1], &names[i]);
            match i {
                10 => rubber(a, b, 2.5e4, 1.0, frequency_poly.clone()),
                11 => rubber(a, b, 4.0e4, 1.0, frequency_poly.clone()),
                _ => shaft(a, b, 8.0e5 + 1.0e5 * (i % 4) as f64, 0.0),
            }
        })
        .collect();
    model(inertias, connections)
}

/// A 10-DOF CNG-genset-like driveline (seed 000): damper, six crank throws, flywheel, a
/// two-stage rubber coupling with seed 000's α_f, generator; a 6-cylinder 4-stroke engine
/// firing 1-5-3-6-2-4 with a pressure table; load damping on the generator.
fn cng_like() -> Model {
    let mut inertias = vec![node("damper", 0.35, 40.0)];
    for i in 1..=6 {
        inertias.push(node(&format!("cyl{i}"), 0.12, 0.5));
    }
    inertias.push(node("flywheel", 2.8, 0.0));
    inertias.push(node("coupling_mid", 0.25, 0.0));
    inertias.push(node("generator", 6.5, 0.0));
    let mut connections = vec![shaft("damper", "cyl1", 2.2e6, 20.0)];
    for i in 1..6 {
        connections.push(shaft(
            &format!("cyl{i}"),
            &format!("cyl{}", i + 1),
            3.0e6,
            5.0,
        ));
    }
    connections.push(shaft("cyl6", "flywheel", 4.0e6, 5.0));
    let poly = Some(seed000_frequency_poly());
    connections.push(rubber("flywheel", "coupling_mid", 1.0e5, 1.1, poly.clone()));
    connections.push(rubber("coupling_mid", "generator", 1.0e5, 1.1, poly));
    let mut m = model(inertias, connections);
    // Cylinder gauge pressure over the 720° cycle from firing TDC, bar.
    let crank_angle_deg = vec![
        0.0, 10.0, 20.0, 40.0, 60.0, 90.0, 120.0, 180.0, 360.0, 540.0, 600.0, 660.0, 690.0, 710.0,
    ];
    let pressure_bar = vec![
        95.0, 110.0, 90.0, 55.0, 35.0, 20.0, 12.0, 4.0, 0.0, 0.5, 2.0, 8.0, 25.0, 60.0,
    ];
    m.engine = Some(Engine {
        at: (1..=6).map(|i| format!("cyl{i}")).collect(),
        cylinders: 6,
        strokes: 4,
        firing_angles_deg: Some(vec![0.0, 480.0, 240.0, 600.0, 120.0, 360.0]),
        bore_m: 0.128,
        crank_radius_m: 0.075,
        conrod_length_m: 0.26,
        reciprocating_mass_kg: 3.2,
        rod_inertia_correction_kg: 0.4,
        pressure: Pressure::Single(PressureCurve {
            crank_angle_deg,
            pressure_bar,
        }),
        pressure_scale: None,
    });
    m.load = Some(Load {
        at: Some("generator".into()),
        damping_nm_s_per_rad: 15.0,
    });
    m
}

/// Orders 0.5, 1, …, 12.
fn half_orders() -> Vec<f64> {
    (1..=24).map(|i| 0.5 * i as f64).collect()
}

/// `count` speeds evenly from `from_rpm` to `to_rpm`.
fn speeds(from_rpm: f64, to_rpm: f64, count: usize) -> Vec<f64> {
    (0..count)
        .map(|i| from_rpm + (to_rpm - from_rpm) * i as f64 / (count - 1) as f64)
        .collect()
}

fn modes_group(c: &mut Criterion) {
    let mut g = c.benchmark_group("modes");
    let s3 = system(&three_dof());
    g.bench_function("3dof", |b| {
        b.iter(|| torsim::modal::modes(black_box(&s3)).expect("modes"))
    });
    let s20 = system(&twenty_dof(None));
    g.bench_function("20dof", |b| {
        b.iter(|| torsim::modal::modes(black_box(&s20)).expect("modes"))
    });
    let s20f = system(&twenty_dof(Some(seed000_frequency_poly())));
    g.bench_function("20dof_frequency_dependent", |b| {
        b.iter(|| torsim::modal::modes(black_box(&s20f)).expect("modes"))
    });
    g.finish();
}

fn campbell_group(c: &mut Criterion) {
    let mut g = c.benchmark_group("campbell");
    let s = system(&cng_like());
    let speeds = speeds(300.0, 2200.0, 200);
    let orders = half_orders();
    g.bench_function("10dof_200_speeds", |b| {
        b.iter(|| {
            torsim::modal::campbell(black_box(&s), black_box(&speeds), black_box(&orders))
                .expect("campbell")
        })
    });
    g.finish();
}

fn response_group(c: &mut Criterion) {
    let mut g = c.benchmark_group("response");
    // 30 samples of a ~5 ms job need a little more than the default 2 s.
    g.measurement_time(Duration::from_secs(3));
    let m = cng_like();
    let s = system(&m);
    let excitation = Excitation::new(&m, &s, 1.0, &half_orders());
    let sweep = speeds(300.0, 2200.0, 200);
    g.bench_function("10dof_200x24", |b| {
        b.iter(|| {
            torsim::response::forced_response(
                black_box(&s),
                black_box(&excitation),
                black_box(&sweep),
            )
            .expect("response")
        })
    });
    g.bench_function("10dof_200x24_orders_only", |b| {
        b.iter(|| {
            torsim::response::forced_response_orders(
                black_box(&s),
                black_box(&excitation),
                black_box(&sweep),
            )
            .expect("response")
        })
    });
    // The diagnosis' surrogate: the IAS amplitudes alone (`response::amplitudes`).
    g.bench_function("10dof_200x24_amplitudes_only", |b| {
        b.iter(|| {
            torsim::response::order_amplitudes(
                black_box(&s),
                black_box(&excitation),
                black_box(&sweep),
            )
            .expect("amplitudes")
        })
    });
    let m3 = three_dof();
    let s3 = system(&m3);
    let excitation3 = Excitation::new(&m3, &s3, 1.0, &[1.0]);
    let sweep3 = speeds(300.0, 3000.0, 200);
    g.bench_function("3dof_1order_200", |b| {
        b.iter(|| {
            torsim::response::forced_response(
                black_box(&s3),
                black_box(&excitation3),
                black_box(&sweep3),
            )
            .expect("response")
        })
    });
    g.finish();
}

fn system_group(c: &mut Criterion) {
    let mut g = c.benchmark_group("system");
    let m = cng_like();
    let orders = half_orders();
    g.bench_function("build_cng_like", |b| {
        b.iter(|| {
            let s = System::new(black_box(&m), OperatingPoint::default()).expect("system");
            let e = Excitation::new(black_box(&m), &s, 1.0, black_box(&orders));
            (s, e)
        })
    });
    g.finish();
}

/// What the GUI's simulation thread computes after every edit before the time run: the
/// system, modes and Campbell diagram over 201 speeds, damped modes, the excitation and the
/// forced response over the same speeds and the model's orders (target < 16 ms, a frame).
fn cheap_results(model: &Model) {
    let system = System::new(model, OperatingPoint::default()).expect("system");
    let [from, to] = model.operation.speed_range_rpm.unwrap_or([100.0, 3000.0]);
    let grid = torsim::modal::speed_grid(from, to, (to - from) / 200.0);
    let orders = model.orders();
    let diagram = torsim::modal::campbell(&system, &grid, &orders).expect("campbell");
    black_box(torsim::modal::damped_modes(&system, &diagram.modes));
    let excitation = Excitation::new(model, &system, 1.0, &orders);
    black_box(torsim::response::forced_response(&system, &excitation, &grid).expect("response"));
}

fn edit_group(c: &mut Criterion) {
    let mut group = c.benchmark_group("edit_to_cheap_results");
    let presets: Vec<(String, Model)> = ["cng-genset", "test-rig-70sh", "genset-20dof"]
        .iter()
        .map(|name| {
            let p = torsim::model::presets::preset(name).expect("preset");
            (
                name.to_string(),
                torsim::model::parse_model(p.text, name).expect("model"),
            )
        })
        .collect();
    for (name, model) in &presets {
        group.bench_function(name.as_str(), |b| {
            b.iter(|| cheap_results(black_box(model)))
        });
    }
    let mut chain = twenty_dof(Some(seed000_frequency_poly()));
    chain.operation.speed_range_rpm = Some([300.0, 3000.0]);
    group.bench_function("20dof_frequency_dependent", |b| {
        b.iter(|| cheap_results(black_box(&chain)))
    });
    group.finish();
}

fn config() -> Criterion {
    Criterion::default()
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .sample_size(30)
}

criterion_group! {
    name = linear;
    config = config();
    targets = modes_group, campbell_group, response_group, system_group, edit_group
}
criterion_main!(linear);
