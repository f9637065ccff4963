//! Tests of the elastic amplitude candidates ([`super`]): their deformation, bounds and
//! the stage each builds.

use super::*;
use crate::model::parse_model;

fn bench() -> Model {
    let text = include_str!("../../tests/data/diagnosis/none/model.toml");
    parse_model(text, "none/model.toml").expect("the shipped model reads")
}

#[test]
fn the_deformation_is_the_full_load_twist_on_the_pitch_radius() {
    let model = bench();
    let j = model
        .connections
        .iter()
        .position(|c| c.name == "coupling")
        .expect("a coupling");
    let point = OperatingPoint {
        load: 1.0,
        temperature_c: None,
    };
    let system = System::new(&model, point).expect("linearises");
    let torque_nm = system.mean_torque_nm[j].expect("a mean torque");
    let ConnectionKind::Rubber(stage) = &model.connections[j].kind else {
        panic!("a rubber stage");
    };
    // Closed form of a linear stage: Δθ = T / k, x = |Δθ|·D/2·1000 (D = 0.24 m).
    let k = stage.static_stiffness_nm_per_rad();
    let expected = (torque_nm / k).abs() * 0.12 * 1000.0;
    let x = full_load_deformation_mm(&model, j).expect("a deformation");
    assert!(expected > 0.0);
    assert!((x - expected).abs() < 1e-9 * expected, "{x} vs {expected}");
    assert_eq!(full_load_deformation_mm(&model, 0), None, "no rubber stage");
}

#[test]
fn the_bounds_stiffen_the_working_twist_by_the_stated_fractions() {
    // A stiff coupling: 0.13 mm at full load. α_x(x) − 1 = a2·x² + a1·x (eq. 1).
    let x = 0.13;
    let p = amplitude_param(Some(x));
    let a1 = SEED_AMPLITUDE_POLY[1];
    let stiffening = |a2: f64| a2 * x * x + a1 * x;
    assert!((stiffening(p.hi) - a1 * x - MAX_STIFFENING).abs() < 1e-12);
    assert!((stiffening(p.start) - a1 * x - START_STIFFENING).abs() < 1e-12);
    // Searched in ln a2, three decades below its start.
    assert!(p.log);
    assert_eq!(p.lo, p.start * LOWEST_FRACTION);
    assert!(p.is_absent(Some(p.lo)) && !p.is_absent(Some(0.02 * p.start)));
    // A soft coupling (10 mm): the seed-scale bounds, not narrower.
    let soft = amplitude_param(Some(10.0));
    assert_eq!(
        (soft.start, soft.hi),
        (SEED_AMPLITUDE_POLY[0], SEED_HI_PER_MM2)
    );
    // No static torque: the seed-scale bounds.
    assert_eq!(amplitude_param(None), amplitude_param(Some(0.0)));
    assert_eq!(amplitude_param(None).hi, SEED_HI_PER_MM2);
    // Tiny deformation: held at the effect's own limit.
    assert_eq!(amplitude_param(Some(1e-6)).hi, A2_MAX_PER_MM2);
}

/// The index of the shipped bench's rubber stage `coupling`.
fn coupling(model: &Model) -> usize {
    model
        .connections
        .iter()
        .position(|k| k.name == "coupling")
        .expect("the coupling")
}

/// The stage `coupling` of `model` with candidate `c` applied at its upper bound.
fn stage_at_upper_bound(c: &Candidate, model: &Model) -> crate::model::RubberStage {
    let (m, _) = c
        .apply(model, c.param.hi)
        .expect("applies at its upper bound");
    m.connections
        .iter()
        .find_map(|k| match &k.kind {
            ConnectionKind::Rubber(r) if k.name == "coupling" => Some(r.clone()),
            _ => None,
        })
        .expect("the stage")
}

#[test]
fn the_elastic_candidate_builds_an_elastic_stage_within_its_bounds() {
    let model = bench();
    let j = coupling(&model);
    let c = elastic_candidates(&model, j)[0].clone();
    assert!(elastic_candidates(&model, j + 100).is_empty());
    assert_eq!(
        c.name(),
        "coupling_amplitude_nonlinearity at coupling (elastic)"
    );
    let stage = stage_at_upper_bound(&c, &model);
    assert_eq!(stage.amplitude_form, AmplitudeForm::Elastic);
    assert_eq!(stage.amplitude_poly.map(|p| p.coeffs[0]), Some(c.param.hi));
}

#[test]
fn the_linear_form_fits_a1_with_a2_zero_within_its_bounds() {
    let model = bench();
    let j = coupling(&model);
    let c = elastic_candidates(&model, j)[1].clone();
    assert_eq!(c.form(), Some(LINEAR_FORM));
    assert_eq!(
        c.name(),
        "coupling_amplitude_nonlinearity at coupling (elastic_linear)"
    );
    assert!(is_elastic(&c) && !super::super::screen::linear_sees(&c));
    // α_x − 1 = a1·x at the full-load deformation x: 0.1 at the start, 1.0 at the
    // upper bound (the stiffness doubled).
    let x = full_load_deformation_mm(&model, j).expect("a deformation");
    assert!((c.param.start * x - START_STIFFENING).abs() < 1e-12);
    assert!((c.param.hi * x - MAX_STIFFENING).abs() < 1e-12);
    assert_eq!(c.param.lo, c.param.start * LOWEST_FRACTION);
    let stage = stage_at_upper_bound(&c, &model);
    assert_eq!(stage.amplitude_form, AmplitudeForm::Elastic);
    assert_eq!(
        stage.amplitude_poly.map(|p| p.coeffs),
        Some([0.0, c.param.hi, 1.0])
    );
    // Without a deformation: the values at 1 mm; a tiny one: held at the effect's limit.
    assert_eq!(linear_param(None).start, START_STIFFENING);
    assert_eq!(linear_param(Some(1e-6)).hi, A1_MAX_PER_MM);
}

#[test]
fn the_saturating_form_bends_at_the_full_load_deformation() {
    let model = bench();
    let j = coupling(&model);
    let c = elastic_candidates(&model, j)[2].clone();
    assert_eq!(c.form(), Some(SATURATING_FORM));
    assert_eq!(
        c.name(),
        "coupling_amplitude_nonlinearity at coupling (elastic_saturating)"
    );
    assert!(is_elastic(&c) && !super::super::screen::linear_sees(&c));
    // s·tanh(1) at the full-load deformation: 0.1 at the start, 1.0 at the upper bound.
    let t = 1f64.tanh();
    assert!((c.param.start * t - START_STIFFENING).abs() < 1e-12);
    assert!((c.param.hi * t - MAX_STIFFENING).abs() < 1e-12);
    let x = full_load_deformation_mm(&model, j).expect("a deformation");
    let stage = stage_at_upper_bound(&c, &model);
    assert_eq!(stage.amplitude_form, AmplitudeForm::Elastic);
    assert_eq!(stage.amplitude_poly, None);
    let law = stage.amplitude_saturation.expect("a saturating law");
    assert_eq!(law.stiffening, c.param.hi);
    // Written as text and read back by the effect: to the last digit of `{:e}`.
    assert!((law.deformation_mm - x).abs() < 1e-15 * x, "{law:?} vs {x}");
    assert!((law.secant(x) - 1.0 - MAX_STIFFENING).abs() < 1e-12);
}
