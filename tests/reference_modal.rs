//! Natural frequencies and shapes against cases with exact answers.

mod builders;
use builders::*;
use std::f64::consts::{PI, TAU};
use torsim::modal::{damped_modes, modes};
use torsim::physics::{OperatingPoint, System};

/// The modes of `m` with the nominal rubber law (the closed forms below are of it; with
/// no rubber stage, [`System::new`] is the same system).
fn freqs(m: &torsim::model::Model) -> Vec<f64> {
    let system = System::nominal(m, OperatingPoint::default()).unwrap();
    modes(&system)
        .unwrap()
        .iter()
        .map(|m| m.frequency_hz)
        .collect()
}

/// Free-free two inertias on a shaft: ω² = k(1/J1 + 1/J2); one rigid-body mode dropped.
/// Round-off in a 2×2 symmetric eigenproblem is ~1e-15; 1e-12 leaves room.
#[test]
fn free_free_two_dof() {
    let (j1, j2, k) = (1.8, 3.5, 2.88e4);
    let m = model(
        vec![node("a", j1), node("b", j2)],
        vec![shaft("a", "b", k, 0.0)],
    );
    let f = freqs(&m);
    assert_eq!(f.len(), 1);
    assert_rel(
        f[0],
        (k * (1.0 / j1 + 1.0 / j2)).sqrt() / TAU,
        1e-12,
        "2-DOF",
    );
}

/// A uniform free-free chain of N inertias J and N−1 springs k:
/// f_n = (1/π)·√(k/J)·sin(nπ/2N), n = 1 … N−1.
#[test]
fn uniform_chain() {
    let (n, j, k) = (12usize, 0.25, 4.0e5);
    let names: Vec<String> = (0..n).map(|i| format!("n{i}")).collect();
    let m = model(
        names.iter().map(|s| node(s, j)).collect(),
        (1..n)
            .map(|i| shaft(&names[i - 1], &names[i], k, 0.0))
            .collect(),
    );
    let f = freqs(&m);
    assert_eq!(f.len(), n - 1);
    for (i, fi) in f.iter().enumerate() {
        let mode = (i + 1) as f64;
        let exact = (k / j).sqrt() / PI * (mode * PI / (2.0 * n as f64)).sin();
        assert_rel(*fi, exact, 1e-11, &format!("chain mode {}", i + 1));
    }
}

/// Roots of det(K − λM) = 0 for a grounded 3-DOF chain by the trigonometric solution of
/// the cubic — computed without any eigen solver.
fn cubic_roots(j: [f64; 3], k: [f64; 3]) -> [f64; 3] {
    // Chain: ground –k0– J0 –k1– J1 –k2– J2. Characteristic polynomial of M⁻¹K.
    let a = [
        [(k[0] + k[1]) / j[0], -k[1] / j[0], 0.0],
        [-k[1] / j[1], (k[1] + k[2]) / j[1], -k[2] / j[1]],
        [0.0, -k[2] / j[2], k[2] / j[2]],
    ];
    let tr = a[0][0] + a[1][1] + a[2][2];
    let minors = a[0][0] * a[1][1] - a[0][1] * a[1][0] + a[0][0] * a[2][2] - a[0][2] * a[2][0]
        + a[1][1] * a[2][2]
        - a[1][2] * a[2][1];
    let det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]);
    // λ³ − tr λ² + minors λ − det = 0; depressed with λ = t + tr/3.
    let p = minors - tr * tr / 3.0;
    let q = -2.0 * tr.powi(3) / 27.0 + tr * minors / 3.0 - det;
    let r = 2.0 * (-p / 3.0).sqrt();
    let phi = ((3.0 * q / (p * r)).clamp(-1.0, 1.0)).acos() / 3.0;
    let mut roots = [0, 1, 2].map(|i| r * (phi - 2.0 * PI * i as f64 / 3.0).cos() + tr / 3.0);
    roots.sort_by(f64::total_cmp);
    roots
}

/// A grounded 3-DOF chain (seed 001 eq. 6 form) against the closed-form cubic.
/// Tolerance 1e-9: the trigonometric cubic loses a few digits to cancellation.
#[test]
fn grounded_three_dof_against_cubic() {
    let (j, k) = ([0.5, 0.02, 0.01], [2.0e5, 1.0e4, 1.0e4]);
    let m = model(
        vec![node("engine", j[0]), node("es", j[1]), node("mf", j[2])],
        vec![
            shaft("engine", "es", k[0], 0.0),
            rubber("es", "mf", k[1], 0.9),
            rubber("mf", "ground", k[2], 0.9),
        ],
    );
    // The cubic's chain order is ground–J2–J1–J0; map: J0=mf (k to ground), J1=es, J2=engine.
    let roots = cubic_roots([j[2], j[1], j[0]], [k[2], k[1], k[0]]);
    let f = freqs(&m);
    assert_eq!(f.len(), 3);
    for (fi, lambda) in f.iter().zip(roots) {
        assert_rel(*fi, lambda.sqrt() / TAU, 1e-9, "grounded 3-DOF");
    }
}

/// A geared model equals its hand-referred twin: J·r², k·r² on the far side of a
/// ratio-1/3 gear (rigid), and the mesh spring k_m·r² for an elastic gear. Own-shaft
/// shapes are r times the referred ones.
#[test]
fn geared_equals_hand_referred_twin() {
    let r: f64 = 1.0 / 3.0;
    let geared = model(
        vec![
            node("crank", 0.3),
            node("gear_out", 0.05),
            node("coupling", 0.9),
            node("brake", 2.0),
        ],
        vec![
            gear("crank", "gear_out", r, None),
            shaft("gear_out", "coupling", 9.0e4, 0.0),
            rubber("coupling", "brake", 4.5e3, 1.0),
        ],
    );
    let twin = model(
        vec![
            node("crank", 0.3 + 0.05 * r * r),
            node("coupling", 0.9 * r * r),
            node("brake", 2.0 * r * r),
        ],
        vec![
            shaft("crank", "coupling", 9.0e4 * r * r, 0.0),
            rubber("coupling", "brake", 4.5e3 * r * r, 1.0),
        ],
    );
    let (fg, ft) = (freqs(&geared), freqs(&twin));
    assert_eq!(fg.len(), ft.len());
    for (a, b) in fg.iter().zip(&ft) {
        assert_rel(*a, *b, 1e-12, "rigid gear twin");
    }
    let system = System::new(&geared, OperatingPoint::default()).unwrap();
    let shape = modes(&system).unwrap()[0].shape_by_node(&system);
    let twin_system = System::new(&twin, OperatingPoint::default()).unwrap();
    let twin_shape = modes(&twin_system).unwrap()[0].shape_by_node(&twin_system);
    // Node order: crank, gear_out, coupling, brake vs crank, coupling, brake.
    let scale = shape[0] / twin_shape[0];
    assert_rel(
        shape[2],
        r * twin_shape[1] * scale,
        1e-10,
        "own-shaft shape",
    );
    assert_rel(
        shape[1],
        r * twin_shape[0] * scale,
        1e-10,
        "gear output turns r times the crank",
    );

    let k_mesh = 2.0e6;
    let elastic = model(
        vec![
            node("crank", 0.3),
            node("gear_out", 0.05),
            node("coupling", 0.9),
        ],
        vec![
            gear("crank", "gear_out", r, Some(k_mesh)),
            shaft("gear_out", "coupling", 9.0e4, 0.0),
        ],
    );
    let elastic_twin = model(
        vec![
            node("crank", 0.3),
            node("gear_out", 0.05 * r * r),
            node("coupling", 0.9 * r * r),
        ],
        vec![
            shaft("crank", "gear_out", k_mesh * r * r, 0.0),
            shaft("gear_out", "coupling", 9.0e4 * r * r, 0.0),
        ],
    );
    for (a, b) in freqs(&elastic).iter().zip(&freqs(&elastic_twin)) {
        assert_rel(*a, *b, 1e-12, "elastic gear twin");
    }
}

/// One inertia on a viscous shaft to ground: ζ = c/(2√(kJ)), f_d = f_n√(1 − ζ²).
#[test]
fn damped_single_dof() {
    let (j, k, c) = (0.4, 1.6e4, 12.0);
    let m = model(vec![node("a", j)], vec![shaft("a", "ground", k, c)]);
    let system = System::new(&m, OperatingPoint::default()).unwrap();
    let modes = modes(&system).unwrap();
    let d = damped_modes(&system, &modes)[0];
    let zeta = c / (2.0 * (k * j).sqrt());
    let fn_hz = (k / j).sqrt() / TAU;
    assert_rel(modes[0].frequency_hz, fn_hz, 1e-12, "f_n");
    assert_rel(d.damping_ratio, zeta, 1e-9, "ζ");
    assert_rel(
        d.frequency_hz,
        fn_hz * (1.0 - zeta * zeta).sqrt(),
        1e-9,
        "f_d",
    );
}

/// Hysteretic rubber: the equivalent viscous c = kξ/ω at the mode frequency gives
/// ζ = ξ/2 exactly for one DOF (ζ = c/(2Jω) = kξ/(2Jω²)).
#[test]
fn hysteretic_damping_ratio_is_half_the_loss_factor() {
    let psi = 1.1;
    let m = model(
        vec![node("a", 0.2)],
        vec![rubber("a", "ground", 5.0e3, psi)],
    );
    // The nominal law k(1 + iξ) (its closed form); the causal chain meets it at the one
    // mode within its fit (`law_deviation` tests).
    let system = System::nominal(&m, OperatingPoint::default()).unwrap();
    let modes = modes(&system).unwrap();
    let d = damped_modes(&system, &modes)[0];
    assert_rel(d.damping_ratio, psi / (2.0 * TAU), 1e-9, "ζ = ψ/4π");
}
