//! Forced response against closed forms, and a geared model against its referred twin.

use std::f64::consts::TAU;
use torsim::model::parse_model;
use torsim::physics::{Excitation, OperatingPoint, System};
use torsim::response::{Response, forced_response};

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Order 1's forced response of the model in `text` (order 1 only, full load) at
/// `speeds_rpm`: the geared models and their hand-referred twins below.
fn order_one_response(text: &str, speeds_rpm: &[f64]) -> Response {
    let model = parse_model(text, "m.toml").unwrap();
    let system = System::new(&model, OperatingPoint::default()).unwrap();
    let excitation = Excitation::new(&model, &system, 1.0, &[1.0]);
    forced_response(&system, &excitation, speeds_rpm).unwrap()
}

/// One inertia on a shaft (k, c) to ground under T cos(qθ*): Θ = T/(k − ω²J + iωc).
/// IAS amplitude = ω|Θ|·60/2π, shaft torque = |(k + iωc)Θ|, viscous loss ½cω²|Θ|².
/// The same inertia on a rubber stage (k, ψ): Θ = T/(k(1 + iψ/2π) − ω²J), and DIN 740
/// loss ψ·½k|Θ|² per cycle. Tolerance 1e-12: one 1×1 complex division.
#[test]
fn single_dof_closed_form() {
    let (j, k, c, t, order) = (0.35, 2.2e4, 6.0, 40.0, 2.0);
    let text = format!(
        r#"format = 1
name = "1dof"
[[inertia]]
name = "a"
inertia = {j}
[[connection]]
kind = "shaft"
from = "a"
to = "ground"
stiffness = {k}
damping = {c}
[[harmonic]]
at = "a"
order = {order}
amplitude = {t}
phase_deg = 30.0
"#
    );
    let model = parse_model(&text, "1dof.toml").unwrap();
    let system = System::new(&model, OperatingPoint::default()).unwrap();
    let excitation = Excitation::new(&model, &system, 1.0, &[order]);
    let speeds: Vec<f64> = (1..=60).map(|i| 40.0 * i as f64).collect();
    let r = forced_response(&system, &excitation, &speeds).unwrap();
    for (s, &n) in speeds.iter().enumerate() {
        let w = order * n * TAU / 60.0;
        let theta = t / ((k - w * w * j).powi(2) + (w * c).powi(2)).sqrt();
        assert!(rel(r.ias_amplitude_rpm[0][0][s], w * theta * 60.0 / TAU) < 1e-12);
        assert!(
            rel(
                r.torque_amplitude_nm[0][0][s],
                (k * k + w * w * c * c).sqrt() * theta
            ) < 1e-12
        );
        assert!(rel(r.power_loss_w[0][s], 0.5 * c * w * w * theta * theta) < 1e-12);
        // One order around zero mean: the peak is the amplitude.
        assert!(
            rel(
                r.torque_peak_nm[0][s],
                (k * k + w * w * c * c).sqrt() * theta
            ) < 1e-3
        );
    }

    let psi = 0.9;
    let rubber = text
        .replace("kind = \"shaft\"", "kind = \"rubber\"")
        .replace(&format!("damping = {c}"), &format!("psi = {psi}"));
    let model = parse_model(&rubber, "1dof-rubber.toml").unwrap();
    // The closed form is the nominal law's, k(1 + iψ/2π).
    let system = System::nominal(&model, OperatingPoint::default()).unwrap();
    let excitation = Excitation::new(&model, &system, 1.0, &[order]);
    let r = forced_response(&system, &excitation, &speeds).unwrap();
    let xi = psi / TAU;
    for (s, &n) in speeds.iter().enumerate() {
        let w = order * n * TAU / 60.0;
        let theta = t / ((k - w * w * j).powi(2) + (k * xi).powi(2)).sqrt();
        assert!(rel(r.ias_amplitude_rpm[0][0][s], w * theta * 60.0 / TAU) < 1e-12);
        let loss = psi * 0.5 * k * theta * theta * w / TAU;
        assert!(
            rel(r.power_loss_w[0][s], loss) < 1e-12,
            "DIN 740 loss at {n} rpm"
        );
    }
}

const GEARED: &str = r#"format = 1
name = "geared"
[[inertia]]
name = "crank"
inertia = 0.3
[[inertia]]
name = "gear_out"
inertia = 0.05
[[inertia]]
name = "coupling"
inertia = 0.9
[[inertia]]
name = "brake"
inertia = 2.0
[[connection]]
kind = "gear"
from = "crank"
to = "gear_out"
ratio = 0.3333333333333333
[[connection]]
kind = "shaft"
name = "shaft"
from = "gear_out"
to = "coupling"
stiffness = 9.0e4
damping = 3.0
[[connection]]
kind = "rubber"
name = "rubber"
from = "coupling"
to = "brake"
stiffness = 4.5e3
psi = 1.0
[[harmonic]]
at = "crank"
order = 1.0
amplitude = 150.0
phase_deg = 0.0
[[harmonic]]
at = "brake"
order = 1.0
amplitude = 60.0
phase_deg = 90.0
"#;

/// The geared model's response equals its hand-referred twin: inertias and stiffness
/// × r², the torque at the brake × r; own-shaft IAS = r × referred IAS, own-shaft torque =
/// referred torque / r. Tolerance 1e-11: two 3×3 complex LU solves.
#[test]
fn geared_response_equals_referred_twin() {
    let r: f64 = 1.0 / 3.0;
    let twin = format!(
        r#"format = 1
name = "twin"
[[inertia]]
name = "crank"
inertia = {}
[[inertia]]
name = "coupling"
inertia = {}
[[inertia]]
name = "brake"
inertia = {}
[[connection]]
kind = "shaft"
name = "shaft"
from = "crank"
to = "coupling"
stiffness = {}
damping = {}
[[connection]]
kind = "rubber"
name = "rubber"
from = "coupling"
to = "brake"
stiffness = {}
psi = 1.0
[[harmonic]]
at = "crank"
order = 1.0
amplitude = 150.0
phase_deg = 0.0
[[harmonic]]
at = "brake"
order = 1.0
amplitude = {}
phase_deg = 90.0
"#,
        0.3 + 0.05 * r * r,
        0.9 * r * r,
        2.0 * r * r,
        9.0e4 * r * r,
        3.0 * r * r,
        4.5e3 * r * r,
        60.0 * r
    );
    let speeds: Vec<f64> = (1..=100).map(|i| 20.0 * i as f64).collect();
    let (g, t) = (
        order_one_response(GEARED, &speeds),
        order_one_response(&twin, &speeds),
    );
    for s in 0..100 {
        assert!(
            rel(g.ias_amplitude_rpm[0][0][s], t.ias_amplitude_rpm[0][0][s]) < 1e-11,
            "crank"
        );
        assert!(
            rel(
                g.ias_amplitude_rpm[2][0][s],
                r * t.ias_amplitude_rpm[1][0][s]
            ) < 1e-11,
            "coupling"
        );
        assert!(
            rel(
                g.ias_amplitude_rpm[3][0][s],
                r * t.ias_amplitude_rpm[2][0][s]
            ) < 1e-11,
            "brake"
        );
        for c in 0..2 {
            assert!(
                rel(
                    g.torque_amplitude_nm[c][0][s],
                    t.torque_amplitude_nm[c][0][s] / r
                ) < 1e-11,
                "torque {c}"
            );
            assert!(
                rel(g.power_loss_w[c][s], t.power_loss_w[c][s]) < 1e-11,
                "power {c}"
            );
        }
    }
    // The resonance is really in the sweep: the response varies by more than 10×.
    let a = &g.ias_amplitude_rpm[2][0];
    let (lo, hi) = a
        .iter()
        .fold((f64::MAX, 0.0_f64), |(l, h), &v| (l.min(v), h.max(v)));
    assert!(hi > 10.0 * lo, "{lo} … {hi}");
}

/// A harmonic whose amplitude is a table over speed is interpolated linearly and held
/// beyond the ends: 10 N·m at 1000 rpm, 30 N·m at 2000 rpm → 20 N·m at 1500 rpm.
#[test]
fn harmonic_amplitude_table_over_speed() {
    let text = r#"format = 1
name = "tabled"
[[inertia]]
name = "a"
inertia = 0.5
[[connection]]
kind = "shaft"
from = "a"
to = "ground"
stiffness = 1.0e4
[[harmonic]]
at = "a"
order = 1.0
amplitude = { rpm = [1000.0, 2000.0], nm = [10.0, 30.0] }
phase_deg = 0.0
"#;
    let model = parse_model(text, "tabled.toml").unwrap();
    let system = System::new(&model, OperatingPoint::default()).unwrap();
    let excitation = Excitation::new(&model, &system, 1.0, &[1.0]);
    let speeds = [500.0, 1500.0, 2500.0];
    let r = forced_response(&system, &excitation, &speeds).unwrap();
    for (s, (&n, t)) in speeds.iter().zip([10.0, 20.0, 30.0]).enumerate() {
        let w = n * TAU / 60.0;
        let expected = (1.0e4 * t / (1.0e4 - w * w * 0.5)).abs();
        assert!(
            rel(r.torque_amplitude_nm[0][0][s], expected) < 1e-12,
            "{n} rpm"
        );
    }
}

/// Seed 000's α_f without a measured range turns negative above ~720 Hz: a sweep that
/// reaches there stops with an error naming the stage, rather than computing nonsense.
#[test]
fn negative_frequency_factor_is_an_error() {
    let text = r#"format = 1
name = "alpha_f"
[[inertia]]
name = "a"
inertia = 0.5
[[connection]]
kind = "rubber"
name = "coupling"
from = "a"
to = "ground"
stiffness = 1.0e4
psi = 1.0
frequency_poly = [-0.000023, 0.01519, 1.0]
[[harmonic]]
at = "a"
order = 24.0
amplitude = 10.0
phase_deg = 0.0
"#;
    let model = parse_model(text, "alpha.toml").unwrap();
    // The nominal law refuses at the first frequency the sweep reaches where α_f ≤ 0.
    let system = System::nominal(&model, OperatingPoint::default()).unwrap();
    let excitation = Excitation::new(&model, &system, 1.0, &[24.0]);
    let err = forced_response(&system, &excitation, &[1000.0, 2000.0]).unwrap_err();
    let message = err.to_string();
    assert!(
        message.contains("coupling") && message.contains("800.0 Hz"),
        "{message}"
    );
    // Every analysis refuses the model before its causal chain is fitted: α_f ≤ 0 inside
    // the model's band (to 1.5 × order 24 at 3000 rpm).
    let message = System::new(&model, OperatingPoint::default())
        .unwrap_err()
        .to_string();
    assert!(message.contains("coupling"), "{message}");
}

/// An elastic, damped gear mesh equals its hand-referred twin: the mesh (k_m, c_m at the
/// `to` side of a 1:3 reduction) is a shaft of k_m·r², c_m·r² referred to the crank, and
/// what lies beyond it J·r², k·r², c·r². Own-shaft IAS = r × referred IAS; the mesh's
/// own torque = referred torque / r; its viscous loss is the twin shaft's. Tolerance 1e-11:
/// two 3×3 complex LU solves. The mesh damping is large enough (ζ ≈ 2 % of the mesh
/// mode) that leaving it out moves the mesh loss from its value to 0.
#[test]
fn damped_mesh_equals_referred_shaft() {
    let r: f64 = 1.0 / 3.0;
    let (k_mesh, c_mesh) = (4.0e5, 30.0);
    let geared = format!(
        "format = 1\nname = \"damped mesh\"\n\
         [[inertia]]\nname = \"crank\"\ninertia = 0.3\n\
         [[inertia]]\nname = \"gear_out\"\ninertia = 0.05\n\
         [[inertia]]\nname = \"brake\"\ninertia = 2.0\n\
         [[connection]]\nkind = \"gear\"\nname = \"mesh\"\nfrom = \"crank\"\nto = \"gear_out\"\n\
         ratio = {r}\nmesh_stiffness = {k_mesh}\nmesh_damping = {c_mesh}\n\
         [[connection]]\nkind = \"shaft\"\nname = \"shaft\"\nfrom = \"gear_out\"\nto = \"brake\"\n\
         stiffness = 9.0e4\ndamping = 3.0\n\
         [[harmonic]]\nat = \"crank\"\norder = 1.0\namplitude = 150.0\nphase_deg = 0.0\n"
    );
    let twin = format!(
        "format = 1\nname = \"twin\"\n\
         [[inertia]]\nname = \"crank\"\ninertia = 0.3\n\
         [[inertia]]\nname = \"gear_out\"\ninertia = {}\n\
         [[inertia]]\nname = \"brake\"\ninertia = {}\n\
         [[connection]]\nkind = \"shaft\"\nname = \"mesh\"\nfrom = \"crank\"\nto = \"gear_out\"\n\
         stiffness = {}\ndamping = {}\n\
         [[connection]]\nkind = \"shaft\"\nname = \"shaft\"\nfrom = \"gear_out\"\nto = \"brake\"\n\
         stiffness = {}\ndamping = {}\n\
         [[harmonic]]\nat = \"crank\"\norder = 1.0\namplitude = 150.0\nphase_deg = 0.0\n",
        0.05 * r * r,
        2.0 * r * r,
        k_mesh * r * r,
        c_mesh * r * r,
        9.0e4 * r * r,
        3.0 * r * r,
    );
    let speeds: Vec<f64> = (1..=150).map(|i| 40.0 * i as f64).collect();
    let (g, t) = (
        order_one_response(&geared, &speeds),
        order_one_response(&twin, &speeds),
    );
    for s in 0..150 {
        let crank = rel(g.ias_amplitude_rpm[0][0][s], t.ias_amplitude_rpm[0][0][s]);
        assert!(crank < 1e-11, "crank at {s}: {crank}");
        for node in 1..3 {
            let own = r * t.ias_amplitude_rpm[node][0][s];
            assert!(
                rel(g.ias_amplitude_rpm[node][0][s], own) < 1e-11,
                "node {node}"
            );
        }
        let mesh = rel(
            g.torque_amplitude_nm[0][0][s],
            t.torque_amplitude_nm[0][0][s] / r,
        );
        assert!(mesh < 1e-11, "mesh torque at {s}: {mesh}");
        for c in 0..2 {
            let loss = rel(g.power_loss_w[c][s], t.power_loss_w[c][s]);
            assert!(loss < 1e-11, "loss {c} at {s}: {loss}");
        }
    }
    // The mesh loss is the damping's: it is there, and largest at the mesh mode.
    let peak = g.power_loss_w[0].iter().fold(0.0_f64, |m, &p| m.max(p));
    assert!(peak > 1.0, "mesh loss peak {peak} W");
}
