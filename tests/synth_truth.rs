//! `torsim synth`'s truth: each effect's truth model differs from the user's model exactly
//! in that effect (undoing it gives the user's model back, field for field), parameter
//! errors stay within their bound and repeat for a seed, and bad input is refused with a
//! message that names it.

mod synth_support;

use std::f64::consts::TAU;
use synth_support::{bench, data_model, truth};
use torsim::model::{ConnectionKind, Model, RubberStage, RubberStiffness, Shaft};
use torsim::physics::{OperatingPoint, System, engine};
use torsim::synth::{Effect, EffectSpec, SensorArtifact, build_truth};

fn stage_mut<'a>(m: &'a mut Model, name: &str) -> &'a mut RubberStage {
    match &mut m
        .connections
        .iter_mut()
        .find(|c| c.name == name)
        .expect("connection")
        .kind
    {
        ConnectionKind::Rubber(r) => r,
        other => panic!("not rubber: {other:?}"),
    }
}

fn modes_hz(m: &Model) -> Vec<f64> {
    let s = System::new(m, OperatingPoint::default()).unwrap();
    torsim::modal::modes(&s)
        .unwrap()
        .iter()
        .map(|m| m.frequency_hz)
        .collect()
}

#[test]
fn none_and_sensor_artifact_leave_the_driveline_alone() {
    let user = bench();
    let t = truth(&user, &EffectSpec::new(Effect::None));
    assert_eq!(t.model, user);
    assert!(t.parameter_errors.is_empty() && t.artifact.is_none());
    let t = truth(&user, &EffectSpec::new(Effect::SensorArtifact));
    assert_eq!(t.model, user);
    assert_eq!(
        t.artifact,
        Some(SensorArtifact::TapeJoint {
            station: "coupling_es".into(),
            joint_fraction: 0.2
        })
    );
}

#[test]
fn parameter_error_changes_one_value() {
    let user = bench();
    let t = truth(&user, &EffectSpec::new(Effect::ParameterError));
    assert_eq!(t.parameter_errors.len(), 1);
    let e = &t.parameter_errors[0];
    assert_eq!(e.parameter, "connection.coupling.elements.radial_stiffness");
    assert!((e.factor() - 0.88).abs() < 1e-15);
    let mut back = t.model.clone();
    if let RubberStiffness::Elements(el) = &mut stage_mut(&mut back, "coupling").stiffness {
        el.radial_stiffness_n_per_m = e.user_value;
    }
    assert_eq!(back, user);
}

#[test]
fn rubber_effects_add_their_law_only() {
    let user = bench();
    // Amplitude: seed 000 eq. 1.
    let mut t = truth(
        &user,
        &EffectSpec::new(Effect::CouplingAmplitudeNonlinearity),
    )
    .model;
    let s = stage_mut(&mut t, "coupling");
    assert_eq!(
        s.amplitude_poly.as_ref().unwrap().coeffs,
        [0.0152, 0.0033, 1.0]
    );
    s.amplitude_poly = None;
    assert_eq!(t, user);
    // Frequency: 1 at the reference (the user's first mode), seed 000 eq. 9 × 0.1 around it.
    let spec = EffectSpec::new(Effect::CouplingFrequencyDependence).with("reference_hz", 40.0);
    let mut t = truth(&user, &spec).model;
    let s = stage_mut(&mut t, "coupling");
    let p = s.frequency_poly.clone().unwrap();
    assert!((p.eval(40.0) - 1.0).abs() < 1e-14);
    let g = |f: f64| -0.000023 * f * f + 0.01519 * f + 1.0;
    assert!((p.eval(140.0) - 1.0 - 0.1 * (g(140.0) - g(40.0))).abs() < 1e-12);
    assert_eq!(
        p.eval(400.0),
        p.eval(300.0),
        "held beyond its measured range"
    );
    s.frequency_poly = None;
    assert_eq!(t, user);
    // Thermal: a heat capacity and the seed's temperature laws, 1 at the start.
    let mut t = truth(&user, &EffectSpec::new(Effect::CouplingThermalDrift)).model;
    let s = stage_mut(&mut t, "coupling");
    let th = s.thermal.clone().unwrap();
    assert_eq!(
        (th.capacity_j_per_k, th.conductance_w_per_k, th.ambient_c),
        (300.0, 1.5, 60.0)
    );
    let k = s.temperature_stiffness_poly.clone().unwrap();
    let d = s.temperature_damping_poly.clone().unwrap();
    assert!((k.eval(60.0) - 1.0).abs() < 1e-12 && (d.eval(60.0) - 1.0).abs() < 1e-12);
    assert!(
        k.eval(65.0) < 0.95 && d.eval(65.0) < 0.96,
        "softens as it warms"
    );
    (
        s.thermal,
        s.temperature_stiffness_poly,
        s.temperature_damping_poly,
    ) = (None, None, None);
    assert_eq!(t, user);
}

/// The truth's rubber stage is calibrated so that its causal chain (the one every view of
/// the truth model reads, fitted at its modes and over its band) has the user's loss
/// factor c·ω/k and stiffness k at the reference frequency.
#[test]
fn hysteretic_damping_replaces_the_viscous_shaft() {
    let user = data_model("model-viscous.toml");
    let spec = EffectSpec::new(Effect::HystereticDamping).with("reference_hz", 140.0);
    let mut t = truth(&user, &spec).model;
    let (k, c) = (63360.0, 5.4);
    let s = stage_mut(&mut t, "coupling").clone();
    // The truth model's own chain, as every view of it reads it.
    let system = System::new(&t, OperatingPoint::default()).unwrap();
    let j = t
        .connections
        .iter()
        .position(|c| c.name == "coupling")
        .unwrap();
    let z = system.chains[j].as_ref().unwrap().complex_stiffness(140.0);
    assert!((z.im / z.re - c * TAU * 140.0 / k).abs() < 1e-9);
    assert!((s.static_stiffness_nm_per_rad() * z.re - k).abs() < 1e-6 * k);
    // One law (issue 15): the chain meets ψ/2π within 5 % at the modes (mode 2 is at
    // 134 Hz), so ψ is 2π·c·ω/k within that (measured 0.482 against 0.471, +2.3 %).
    let psi_nominal = TAU * c * TAU * 140.0 / k;
    assert!(
        (s.psi / psi_nominal - 1.0).abs() < 0.05,
        "ψ {} vs {psi_nominal}",
        s.psi
    );
    let conn = t
        .connections
        .iter_mut()
        .find(|c| c.name == "coupling")
        .unwrap();
    conn.kind = ConnectionKind::Shaft(Shaft::massless(k, c));
    assert_eq!(t, user);
    // A damper the chain cannot match is refused with the most it can do: 65 N·m·s/rad
    // asks a loss factor 0.90 at 140 Hz, beyond ψ = 5 (ψ/2π = 0.80), the calibration's
    // largest.
    let mut heavy = user.clone();
    if let ConnectionKind::Shaft(s) = &mut heavy.connections[2].kind {
        s.damping_nm_s_per_rad = 65.0;
    }
    let msg = build_truth(&heavy, &spec, 0.0, 1).unwrap_err().to_string();
    assert!(msg.contains("reaches at most"), "{msg}");
}

/// The middle node takes its inertia from the ends (total unchanged) and the two halves
/// keep the series stiffness.
#[test]
fn unmodelled_mode_splits_the_coupling() {
    let user = bench();
    let spec = EffectSpec::new(Effect::UnmodelledMode).with("inertia_kg_m2", 0.1);
    let t = truth(&user, &spec).model;
    let total = |m: &Model| m.inertias.iter().map(|n| n.inertia_kg_m2).sum::<f64>();
    assert!((total(&t) - total(&user)).abs() < 1e-12);
    let j = |m: &Model, n: &str| m.inertias[m.node_index(n).unwrap()].inertia_kg_m2;
    assert!((j(&t, "coupling_es") - 0.25).abs() < 1e-12 && (j(&t, "brake") - 1.45).abs() < 1e-12);
    assert_eq!(j(&t, "coupling_middle"), 0.1);
    let k = |m: &Model, n: &str| match &m.connections.iter().find(|c| c.name == n).unwrap().kind {
        ConnectionKind::Rubber(r) => r.static_stiffness_nm_per_rad(),
        _ => panic!("rubber"),
    };
    let series = 1.0 / (1.0 / k(&t, "coupling_a") + 1.0 / k(&t, "coupling_b"));
    assert!((series - k(&user, "coupling")).abs() < 1e-9 * series);
    assert_eq!(t.connections.len(), user.connections.len() + 1);
    let others = |m: &Model| {
        m.connections
            .iter()
            .filter(|c| !c.name.starts_with("coupling"))
            .cloned()
            .collect::<Vec<_>>()
    };
    assert_eq!(others(&t), others(&user));
}

/// Same cycle-mean inertia, so the linear modes are unchanged; only the variation and the
/// oscillating-mass torque are new (the order-2 stand-in goes).
#[test]
fn crank_variable_inertia_keeps_the_mean_inertia() {
    let user = data_model("model-norecip.toml");
    let spec = EffectSpec::new(Effect::CrankVariableInertia)
        .with("mass_kg", 0.6)
        .with("drop_harmonics", "2");
    let t = truth(&user, &spec).model;
    let e = t.engine.clone().unwrap();
    assert_eq!(e.reciprocating_mass_kg, 0.6);
    assert!(t.harmonics.is_empty());
    for (a, b) in modes_hz(&t).iter().zip(modes_hz(&user)) {
        assert!((a - b).abs() < 1e-9 * b, "{a} vs {b}");
    }
    let mut back = t.clone();
    back.engine.as_mut().unwrap().reciprocating_mass_kg = 0.0;
    back.inertias[0].inertia_kg_m2 += 4.0 * engine::mean_reciprocating_inertia_kg_m2(&e);
    back.harmonics = user.harmonics.clone();
    assert!((back.inertias[0].inertia_kg_m2 - user.inertias[0].inertia_kg_m2).abs() < 1e-15);
    back.inertias[0].inertia_kg_m2 = user.inertias[0].inertia_kg_m2;
    assert_eq!(back, user);
}

#[test]
fn backlash_and_imbalance_set_one_key() {
    let user = bench();
    let mut t = truth(&user, &EffectSpec::new(Effect::GearBacklash)).model;
    match &mut t.connections[0].kind {
        ConnectionKind::Gear(g) => {
            assert_eq!(g.backlash_deg, 0.2);
            g.backlash_deg = 0.0;
        }
        _ => panic!("gear first"),
    }
    assert_eq!(t, user);
    // A softened contact: ε is the given share of the half play (0.3 × 0.1°).
    let spec = EffectSpec::new(Effect::GearBacklash)
        .with("backlash_deg", 0.2)
        .with("softening", 0.3);
    match &truth(&user, &spec).model.connections[0].kind {
        ConnectionKind::Gear(g) => {
            assert_eq!(g.backlash_deg, 0.2);
            assert!((g.backlash_softening_deg - 0.03).abs() < 1e-15);
        }
        _ => panic!("gear first"),
    }
    let spec = EffectSpec::new(Effect::CylinderImbalance)
        .with("cylinder", 3)
        .with("pressure_scale", 0.95);
    let mut t = truth(&user, &spec).model;
    let e = t.engine.as_mut().unwrap();
    assert_eq!(e.pressure_scale, Some(vec![1.0, 1.0, 0.95, 1.0]));
    e.pressure_scale = None;
    assert_eq!(t, user);
}

#[test]
fn parameter_errors_are_bounded_and_seeded() {
    let user = bench();
    let spec = EffectSpec::new(Effect::GearBacklash);
    let a = build_truth(&user, &spec, 10.0, 5).unwrap();
    let b = build_truth(&user, &spec, 10.0, 5).unwrap();
    let c = build_truth(&user, &spec, 10.0, 6).unwrap();
    assert_eq!(a, b);
    assert_ne!(a.parameter_errors, c.parameter_errors);
    assert_eq!(a.parameter_errors.len(), 7);
    assert!(
        a.parameter_errors
            .iter()
            .all(|e| (e.factor() - 1.0).abs() <= 0.1)
    );
    // The effect acts on the erroneous values: undoing both gives the user's model.
    let t = &a.model;
    let gear = match &t.connections[0].kind {
        ConnectionKind::Gear(g) => g.backlash_deg,
        _ => panic!("gear"),
    };
    assert_eq!(gear, 0.2);
}

fn error(user: &Model, spec: EffectSpec, pct: f64) -> String {
    build_truth(user, &spec, pct, 1).unwrap_err().to_string()
}

#[test]
fn bad_input_is_named() {
    let b = bench();
    let cases: Vec<(EffectSpec, f64, &str)> = vec![
        (EffectSpec::new(Effect::None), 5.0, "parameter_error"),
        (
            EffectSpec::new(Effect::GearBacklash).with("slack", 1),
            0.0,
            "no parameter `slack`",
        ),
        (
            EffectSpec::new(Effect::GearBacklash).with("backlash_deg", 30),
            0.0,
            "outside",
        ),
        (
            EffectSpec::new(Effect::HystereticDamping).with("connection", "coupling"),
            0.0,
            "is no viscous `shaft`",
        ),
        (
            EffectSpec::new(Effect::CrankVariableInertia),
            0.0,
            "already has reciprocating_mass",
        ),
        (
            EffectSpec::new(Effect::UnmodelledMode).with("inertia_kg_m2", 0.6),
            0.0,
            "less than 10 %",
        ),
        (
            EffectSpec::new(Effect::CylinderImbalance).with("cylinder", 5),
            0.0,
            "`cylinder`",
        ),
        (
            EffectSpec::new(Effect::ParameterError).with("target", "nowhere"),
            0.0,
            "`nowhere`",
        ),
        (
            EffectSpec::new(Effect::GearBacklash),
            60.0,
            "--param-error-pct",
        ),
    ];
    for (spec, pct, needle) in cases {
        let msg = error(&b, spec.clone(), pct);
        assert!(msg.contains(needle), "{spec:?}: {msg}");
    }
    let rig = torsim::model::parse_model(
        torsim::model::presets::preset("test-rig-70sh")
            .unwrap()
            .text,
        "rig",
    )
    .unwrap();
    let spec = EffectSpec::new(Effect::GearBacklash).with("connection", "gearbox");
    let msg = error(&rig, spec, 0.0);
    assert!(msg.contains("rigid"), "{msg}");
}
