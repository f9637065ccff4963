//! Broken models, one per kind of key path `validate` produces, for the test that each key
//! is shown at the widget that edits it.

use torsim::model::{
    ConnectionKind, GROUND, HarmonicAmplitude, Inertia, Model, Poly, Pressure, Regime,
    RubberStiffness, Thermal, parse_model, presets,
};

/// A change that makes a valid model invalid.
pub type Breaker = Box<dyn Fn(&mut Model)>;

fn preset(name: &str) -> Model {
    let p = presets::preset(name).expect("preset");
    parse_model(p.text, name).expect("model")
}

fn rubber(m: &mut Model, j: usize) -> &mut torsim::model::RubberStage {
    match &mut m.connections[j].kind {
        ConnectionKind::Rubber(r) => r,
        _ => panic!("connection {j} is not rubber"),
    }
}

fn gear(m: &mut Model, j: usize) -> &mut torsim::model::Gear {
    match &mut m.connections[j].kind {
        ConnectionKind::Gear(g) => g,
        _ => panic!("connection {j} is not a gear"),
    }
}

fn shaft(m: &mut Model, j: usize) -> &mut torsim::model::Shaft {
    match &mut m.connections[j].kind {
        ConnectionKind::Shaft(s) => s,
        _ => panic!("connection {j} is not a shaft"),
    }
}

fn elements(m: &mut Model) -> &mut torsim::model::RubberElements {
    match &mut rubber(m, 7).stiffness {
        RubberStiffness::Elements(e) => e,
        RubberStiffness::Direct(_) => panic!("cng coupling has elements"),
    }
}

fn engine(m: &mut Model) -> &mut torsim::model::Engine {
    m.engine.as_mut().expect("engine")
}

fn thermal(m: &mut Model) -> &mut Thermal {
    rubber(m, 7).thermal.get_or_insert(Thermal {
        capacity_j_per_k: 3400.0,
        conductance_w_per_k: 10.0,
        ambient_c: 25.0,
    })
}

fn saturation(deformation_mm: f64) -> torsim::model::AmplitudeSaturation {
    torsim::model::AmplitudeSaturation {
        stiffening: 0.3,
        deformation_mm,
    }
}

fn rating(m: &mut Model) -> &mut torsim::model::CouplingRating {
    rubber(m, 7)
        .rating
        .as_mut()
        .expect("cng-genset's coupling is rated")
}

/// (valid model, how to break it): cng-genset (elements, polynomials, pressure by load,
/// load, expectations) and test-rig-45sh (gear, direct rubber, ground, one pressure curve,
/// harmonics, orders, regimes).
pub fn cases() -> Vec<(Model, Breaker)> {
    let cng: Vec<Breaker> = vec![
        Box::new(|m| m.inertias[1].name = "damper".into()),
        Box::new(|m| m.inertias[0].name = GROUND.into()),
        Box::new(|m| m.inertias[2].inertia_kg_m2 = -1.0),
        Box::new(|m| m.inertias[2].damping_nm_s_per_rad = -1.0),
        Box::new(|m| {
            m.inertias.push(Inertia {
                name: "spare".into(),
                inertia_kg_m2: 1.0,
                damping_nm_s_per_rad: 0.0,
            })
        }),
        Box::new(|m| m.connections[1].name = "crank_nose".into()),
        Box::new(|m| m.connections[1].from = "nowhere".into()),
        Box::new(|m| m.connections[1].to = "throw1".into()),
        Box::new(|m| shaft(m, 1).stiffness_nm_per_rad = 0.0),
        Box::new(|m| shaft(m, 1).damping_nm_s_per_rad = -1.0),
        Box::new(|m| elements(m).count = 1),
        Box::new(|m| elements(m).per_side = 8),
        Box::new(|m| elements(m).pitch_diameter_m = 0.0),
        Box::new(|m| elements(m).radial_stiffness_n_per_m = -1.0),
        Box::new(|m| rubber(m, 7).psi = 0.0),
        Box::new(|m| rubber(m, 7).temperature_c = f64::NAN),
        Box::new(|m| {
            if let Some(p) = &mut rubber(m, 7).frequency_poly {
                p.coeffs[1] = f64::NAN;
            }
        }),
        Box::new(|m| {
            if let Some(p) = &mut rubber(m, 7).frequency_poly {
                p.range = Some([300.0, 0.0]);
            }
        }),
        Box::new(|m| {
            rubber(m, 7).temperature_stiffness_poly = Some(Poly {
                coeffs: [0.0, 0.0, -1.0],
                range: None,
            })
        }),
        // cng-genset's coupling has an amplitude_poly: a saturating law beside it is
        // refused at the table, a zero deformation at its field.
        Box::new(|m| rubber(m, 7).amplitude_saturation = Some(saturation(1.0))),
        Box::new(|m| {
            rubber(m, 7).amplitude_poly = None;
            rubber(m, 7).amplitude_saturation = Some(saturation(0.0));
        }),
        Box::new(|m| thermal(m).capacity_j_per_k = 0.0),
        Box::new(|m| thermal(m).conductance_w_per_k = 0.0),
        Box::new(|m| thermal(m).ambient_c = f64::NAN),
        // cng-genset's coupling is rated (issue 16).
        Box::new(|m| rating(m).max_torque_nm = Some(1000.0)),
        Box::new(|m| rating(m).permissible_vibratory_torque_nm = Some(-1.0)),
        Box::new(|m| rating(m).ambient_c = 95.0),
        Box::new(|m| engine(m).at.truncate(2)),
        Box::new(|m| engine(m).at[3] = "nowhere".into()),
        Box::new(|m| engine(m).cylinders = 0),
        Box::new(|m| engine(m).strokes = 3),
        Box::new(|m| engine(m).firing_angles_deg = Some(vec![0.0; 5])),
        Box::new(|m| {
            if let Some(a) = &mut engine(m).firing_angles_deg {
                a[2] = f64::NAN;
            }
        }),
        Box::new(|m| engine(m).bore_m = 0.0),
        Box::new(|m| engine(m).crank_radius_m = 0.0),
        Box::new(|m| engine(m).conrod_length_m = 0.05),
        Box::new(|m| engine(m).reciprocating_mass_kg = -1.0),
        Box::new(|m| engine(m).rod_inertia_correction_kg = -1.0),
        Box::new(|m| {
            if let Pressure::ByLoad(c) = &mut engine(m).pressure {
                c[1].load = 0.2;
            }
        }),
        Box::new(|m| {
            if let Pressure::ByLoad(c) = &mut engine(m).pressure {
                c[0].curve.pressure_bar[3] = f64::NAN;
            }
        }),
        Box::new(|m| engine(m).at.clear()),
        Box::new(|m| m.load.as_mut().expect("load").at = Some("nowhere".into())),
        Box::new(|m| m.load.as_mut().expect("load").damping_nm_s_per_rad = -1.0),
        Box::new(|m| m.operation.speed_range_rpm = Some([2000.0, 400.0])),
        Box::new(|m| m.operation.operating_range_rpm = Some([2000.0, 1000.0])),
        Box::new(|m| m.operation.orders = Some(vec![3.0, -1.0])),
        Box::new(|m| {
            m.operation.regimes.push(Regime {
                label: "A".into(),
                speed_rpm: -1.0,
                load: 1.0,
            })
        }),
        Box::new(|m| {
            m.operation.regimes.push(Regime {
                label: "A".into(),
                speed_rpm: 900.0,
                load: 2.0,
            })
        }),
        Box::new(|m| m.expect.mode_hz[0].mode = 0),
        Box::new(|m| m.expect.mode_hz[1].min_hz = f64::NAN),
        Box::new(|m| m.expect.mode_hz[1].max_hz = 1.0),
        Box::new(|m| m.expect.critical_rpm[0].order = -1.0),
        Box::new(|m| m.expect.no_resonance_in_operating_range[1] = -6.0),
        Box::new(|m| m.operation.operating_range_rpm = None),
    ];
    let rig: Vec<Breaker> = vec![
        Box::new(|m| rubber(m, 2).stiffness = RubberStiffness::Direct(-1.0)),
        Box::new(|m| {
            rubber(m, 2).amplitude_poly = Some(Poly {
                coeffs: [0.0152, 0.0033, 1.0],
                range: None,
            })
        }),
        Box::new(|m| gear(m, 0).ratio = 0.0),
        Box::new(|m| gear(m, 0).mesh_stiffness_nm_per_rad = Some(-1.0)),
        Box::new(|m| gear(m, 0).mesh_damping_nm_s_per_rad = -1.0),
        // A rigid gear with mesh damping (only a file can give it one).
        Box::new(|m| gear(m, 0).mesh_damping_nm_s_per_rad = 5.0),
        Box::new(|m| gear(m, 0).backlash_deg = -1.0),
        Box::new(|m| gear(m, 0).backlash_softening_deg = -1.0),
        Box::new(|m| m.connections[0].to = GROUND.into()),
        Box::new(|m| {
            // A shaft alongside the 1/3 gear: two speeds for gearbox_out.
            let mut extra = m.connections[1].clone();
            extra.name = "bypass".into();
            extra.from = "engine".into();
            extra.to = "gearbox_out".into();
            m.connections.push(extra);
        }),
        Box::new(|m| m.harmonics[0].at = "nowhere".into()),
        Box::new(|m| m.harmonics[0].order = 0.0),
        Box::new(|m| m.harmonics[1].phase_deg = f64::NAN),
        Box::new(|m| m.harmonics[1].amplitude = HarmonicAmplitude::Constant(-1.0)),
        Box::new(|m| {
            m.harmonics[1].amplitude = HarmonicAmplitude::BySpeed {
                speed_rpm: vec![1000.0, 2000.0],
                amplitude_nm: vec![1.0],
            }
        }),
        Box::new(|m| {
            if let Pressure::Single(c) = &mut engine(m).pressure {
                c.crank_angle_deg[3] = c.crank_angle_deg[2];
            }
        }),
    ];
    let (a, b) = (preset("cng-genset"), preset("test-rig-45sh"));
    cng.into_iter()
        .map(|f| (a.clone(), f))
        .chain(rig.into_iter().map(|f| (b.clone(), f)))
        .collect()
}
