//! Builders for models used by the reference tests (no model file needed).
#![allow(dead_code)]

use torsim::model::*;

pub fn node(name: &str, inertia: f64) -> Inertia {
    Inertia {
        name: name.into(),
        inertia_kg_m2: inertia,
        damping_nm_s_per_rad: 0.0,
    }
}

pub fn shaft(from: &str, to: &str, k: f64, c: f64) -> Connection {
    Connection {
        name: Connection::default_name(from, to),
        from: from.into(),
        to: to.into(),
        kind: ConnectionKind::Shaft(Shaft::massless(k, c)),
    }
}

pub fn gear(from: &str, to: &str, ratio: f64, mesh: Option<f64>) -> Connection {
    Connection {
        name: Connection::default_name(from, to),
        from: from.into(),
        to: to.into(),
        kind: ConnectionKind::Gear(Gear {
            ratio,
            mesh_stiffness_nm_per_rad: mesh,
            mesh_damping_nm_s_per_rad: 0.0,
            backlash_deg: 0.0,
            backlash_softening_deg: 0.0,
            contact_exponent: 1.0,
            contact_reference_deg: 0.0,
        }),
    }
}

pub fn rubber(from: &str, to: &str, k: f64, psi: f64) -> Connection {
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
            frequency_poly: None,
            frequency_power_law: None,
            frequency_zener: None,
            temperature_stiffness_poly: None,
            temperature_damping_poly: None,
            thermal: None,
            rating: None,
        }),
    }
}

pub fn model(inertias: Vec<Inertia>, connections: Vec<Connection>) -> Model {
    Model {
        name: "test".into(),
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

/// Seed 000's polynomials (eq. 1, 9, 10, 11).
pub fn seed000_stage(elements: RubberElements, psi: f64, temperature_c: f64) -> RubberStage {
    RubberStage {
        stiffness: RubberStiffness::Elements(elements),
        psi,
        temperature_c,
        amplitude_poly: Some(Poly {
            coeffs: [0.0152, 0.0033, 1.0],
            range: None,
        }),
        amplitude_saturation: None,
        amplitude_form: Default::default(),
        frequency_poly: Some(Poly {
            coeffs: [-0.000023, 0.01519, 1.0],
            range: Some([0.0, 300.0]),
        }),
        frequency_power_law: None,
        frequency_zener: None,
        temperature_stiffness_poly: Some(Poly {
            coeffs: [0.000187, -0.02565, 1.530],
            range: None,
        }),
        temperature_damping_poly: Some(Poly {
            coeffs: [0.000063, -0.01275, 1.281],
            range: None,
        }),
        thermal: None,
        rating: None,
    }
}

pub fn assert_rel(actual: f64, expected: f64, tol: f64, what: &str) {
    let err = (actual - expected).abs() / expected.abs().max(f64::MIN_POSITIVE);
    assert!(
        err <= tol,
        "{what}: {actual} vs {expected} (relative error {err:e} > {tol:e})"
    );
}
