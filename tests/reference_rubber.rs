//! The seed 000 rubber law against numbers worked by hand from its polynomials, and the
//! static twist of a stage under the engine's mean torque.

mod builders;
use builders::*;
use std::f64::consts::TAU;
use torsim::modal::modes;
use torsim::model::{ConnectionKind, RubberElements};
use torsim::physics::engine::mean_torque_per_cylinder_nm;
use torsim::physics::{OperatingPoint, System};

fn elements() -> RubberElements {
    RubberElements {
        count: 8,
        per_side: 4,
        pitch_diameter_m: 0.30,
        radial_stiffness_n_per_m: 6.4e5,
    }
}

/// eq. 12: c_Tstat = 6.4e5 · 0.15² · 4·4/8 = 28 800 N·m/rad.
/// At x = 5 mm (twist 5/150 rad), f = 100 Hz, T = 40 °C, by hand:
/// α_x = 0.0152·25 + 0.0033·5 + 1 = 1.3965 (eq. 1);
/// d(α_x x)/dx = 3·0.0152·25 + 2·0.0033·5 + 1 = 2.173;
/// α_f = −0.000023·10⁴ + 1.519 + 1 = 2.289 (eq. 9);
/// α_Tc = 0.000187·1600 − 0.02565·40 + 1.530 = 0.8032 (eq. 10);
/// α_Tξ = 0.000063·1600 − 0.01275·40 + 1.281 = 0.8718 (eq. 11);
/// k = 28 800 · 1.3965 · 2.289 · 0.8032 (eq. 13); ξ_T = ψ/2π · 0.8718 (eq. 15).
#[test]
fn law_against_hand_numbers() {
    let stage = seed000_stage(elements(), 1.0, 40.0);
    assert_rel(
        stage.static_stiffness_nm_per_rad(),
        28_800.0,
        1e-15,
        "eq. 12",
    );
    let s = stage.state(Some(100.0), 40.0, 5.0 / 150.0);
    assert_rel(s.alpha_x, 1.3965, 1e-14, "α_x");
    assert_rel(s.alpha_x_tangent, 2.173, 1e-14, "tangent");
    assert_rel(s.alpha_f, 2.289, 1e-14, "α_f");
    assert_rel(s.alpha_tc, 0.8032, 1e-13, "α_Tc");
    assert_rel(s.alpha_txi, 0.8718, 1e-13, "α_Tξ");
    assert_rel(
        s.stiffness_nm_per_rad,
        28_800.0 * 1.3965 * 2.289 * 0.8032,
        1e-13,
        "eq. 13",
    );
    assert_rel(s.loss_factor, 1.0 / TAU * 0.8718, 1e-13, "eq. 15");
    assert!(s.warnings.is_empty());
    // Beyond the measured 300 Hz, α_f is held at its end value and a warning is raised.
    let held = stage.state(Some(500.0), 40.0, 0.0);
    assert_rel(
        held.alpha_f,
        -0.000023 * 9.0e4 + 0.01519 * 300.0 + 1.0,
        1e-14,
        "held α_f",
    );
    assert_eq!(held.warnings.len(), 1);
}

/// The static twist carries the torque through the secant law, and the modes see the
/// tangent stiffness there: a free-free pair on one stage has
/// f = √(k_tan(1/J1 + 1/J2))/2π with k_tan = c_Tstat·α_Tc·d(α_x x)/dx at the twist.
#[test]
fn static_twist_and_tangent_stiffness_under_mean_torque() {
    let mut stage = seed000_stage(elements(), 1.0, 40.0);
    stage.frequency_poly = None;
    let (j1, j2) = (1.8, 3.5);
    let mut m = model(vec![node("crank", j1), node("generator", j2)], vec![]);
    m.connections.push(torsim::model::Connection {
        name: "coupling".into(),
        from: "crank".into(),
        to: "generator".into(),
        kind: ConnectionKind::Rubber(stage.clone()),
    });
    let text = format!(
        "{}\n[engine]\nat = \"crank\"\ncylinders = 6\nbore = 0.13\ncrank_radius = 0.075\nconrod_length = 0.25\npressure = {{ crank_angle_deg = [-360, -30, 0, 20, 60, 180, 360], bar = [0.0, 20.0, 80.0, 110.0, 40.0, 4.0, 0.0] }}\n",
        torsim::model::to_toml_string(&m)
    );
    let m = torsim::model::parse_model(&text, "pair.toml").unwrap();
    let engine = m.engine.as_ref().unwrap();
    let torque = 6.0 * mean_torque_per_cylinder_nm(engine, 1.0);
    assert!(torque > 500.0, "a real mean torque: {torque}");
    let system = System::new(&m, OperatingPoint::default()).unwrap();
    assert_rel(
        system.mean_torque_nm[0].unwrap(),
        torque,
        1e-12,
        "mean torque through the coupling",
    );
    let twist = system.static_twist_rad[0].unwrap();
    let s = stage.state(None, 40.0, twist);
    assert_rel(
        s.stiffness_nm_per_rad * twist,
        torque,
        1e-12,
        "secant law carries the torque",
    );
    let x = twist * 150.0;
    let k_tan = 28_800.0 * s.alpha_tc * (3.0 * 0.0152 * x * x + 2.0 * 0.0033 * x + 1.0);
    // reciprocating_mass is 0 here, so the crank keeps its own inertia.
    let exact = (k_tan * (1.0 / j1 + 1.0 / j2)).sqrt() / TAU;
    let nominal = System::nominal(&m, OperatingPoint::default()).unwrap();
    assert_rel(
        modes(&nominal).unwrap()[0].frequency_hz,
        exact,
        1e-12,
        "tangent mode",
    );
    // The causal chain (what every analysis uses) is the same tangent times a chain that
    // meets the flat law at this one mode to its fit (measured 1.3e-4 in frequency).
    assert_rel(
        modes(&system).unwrap()[0].frequency_hz,
        exact,
        3e-4,
        "tangent mode, causal",
    );
    assert!(
        k_tan > 1.5 * 28_800.0 * s.alpha_tc,
        "the twist stiffens the stage noticeably"
    );
}

/// A 1-DOF rubber stage whose α_f = 1 − 0.02·f falls to 0 at 50 Hz (issue 13: `coupling`
/// printed a negative stiffness, `simulate` fitted a chain with a 3974 % error).
const FALLING_ALPHA_F: &str = r#"format = 1
name = "falling alpha_f"
[[inertia]]
name = "a"
inertia = 0.1
[[connection]]
kind = "rubber"
name = "r"
from = "a"
to = "ground"
stiffness = 1.0e4
psi = 1.0
frequency_poly = [0.0, -0.02, 1.0]
[[harmonic]]
at = "a"
order = 1.0
amplitude = 20.0
phase_deg = 0.0
"#;

#[test]
fn frequency_factor_at_or_below_zero_is_found_and_refused() {
    use torsim::model::Poly;
    use torsim::model::rubber::Factor;
    use torsim::physics::PhysicsError;
    use torsim::recording::Run;
    use torsim::transient::{RunOptions, TransientError, simulate};
    let model = torsim::model::parse_model(FALLING_ALPHA_F, "f.toml").expect("valid model");
    let ConnectionKind::Rubber(stage) = &model.connections[0].kind else {
        panic!("rubber")
    };
    // At 100 Hz α_f = 1 − 2 = −1: the state says which factor is not positive.
    let s = stage.state(Some(100.0), 25.0, 0.0);
    assert_eq!(s.non_positive_factor(), Some((Factor::Frequency, -1.0)));
    assert_eq!(
        stage.state(Some(10.0), 25.0, 0.0).non_positive_factor(),
        None
    );
    // The minimum of a quadratic over a band: an end, or the vertex (1 − 0.02 f + 1e-4 f²
    // has its vertex at 100 Hz, value 0), held beyond the measured range.
    let p = stage.frequency_poly.clone().unwrap();
    assert_eq!(p.min_over([0.0, 200.0]), (200.0, -3.0));
    let bowl = Poly {
        coeffs: [1e-4, -0.02, 1.0],
        range: None,
    };
    assert_eq!(bowl.min_over([0.0, 300.0]), (100.0, 0.0));
    let held = Poly {
        range: Some([0.0, 40.0]),
        ..p
    };
    assert_eq!(held.min_over([0.0, 1000.0]), (40.0, 1.0 - 0.02 * 40.0));
    // The time domain refuses before fitting: 1500 rpm excites up to 24 × 25 = 600 Hz.
    let run = simulate(
        &model,
        Run::steady(1500.0, 0.1),
        RunOptions::default(),
        &mut |_| true,
    );
    match run {
        Err(TransientError::Physics(PhysicsError::FrequencyFactor {
            connection,
            frequency_hz,
            value,
        })) => {
            assert_eq!(connection, "r");
            assert!(
                frequency_hz > 50.0 && value <= 0.0,
                "{frequency_hz} Hz: {value}"
            );
        }
        other => panic!("expected a refusal, got {:?}", other.map(|_| ())),
    }
}

/// Modes refuse α_f ≤ 0 at a mode's frequency (issue 13: a negative stiffness gave a mode
/// at 30.5 Hz with a −3.5 % damping ratio, exit 0).
#[test]
fn modes_refuse_a_frequency_factor_at_or_below_zero() {
    use torsim::physics::PhysicsError;
    let text = torsim::model::presets::preset("test-rig-mod1")
        .unwrap()
        .text
        .replacen(
            "psi = 0.3257",
            "psi = 0.3257\nfrequency_poly = [0, -0.5, 1]",
            1,
        );
    let model = torsim::model::parse_model(&text, "rig.toml").expect("valid");
    // The causal system refuses it before fitting its chain (α_f ≤ 0 in the band) …
    match System::new(&model, OperatingPoint::default()) {
        Err(PhysicsError::FrequencyFactor {
            connection, value, ..
        }) => {
            assert_eq!(connection, "b");
            assert!(value <= 0.0, "{value}");
        }
        other => panic!("expected a refusal, got {:?}", other.map(|_| ())),
    }
    // … and the nominal law's modes at the mode's frequency.
    let system = System::nominal(&model, OperatingPoint::default()).unwrap();
    match modes(&system) {
        Err(PhysicsError::FrequencyFactor {
            connection, value, ..
        }) => {
            assert_eq!(connection, "b");
            assert!(value <= 0.0, "{value}");
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}
