//! Tests of [`super`]: which meshes count as undamped, the damping given at a ratio (by
//! hand from the diagnosis bench's numbers), taking it out, the report's keys and
//! sentence, accepting them, and a backlash candidate's own damping replacing it.

use super::*;
use crate::diagnose::candidates_backlash::backlash_candidates;
use crate::diagnose::report::Verdict;
use crate::effects::backlash::DEFAULT_MESH_DAMPING_RATIO;
use crate::model::{Gear, parse_model, presets};

fn bench() -> Model {
    let text = presets::preset("diagnosis-bench").expect("shipped").text;
    parse_model(text, "diagnosis-bench.toml").expect("valid")
}

fn gear(m: &Model) -> Gear {
    m.connections
        .iter()
        .find_map(|c| match &c.kind {
            ConnectionKind::Gear(g) if c.name == "gearbox" => Some(g.clone()),
            _ => None,
        })
        .expect("the bench's gearbox")
}

fn verdict(effect: &str) -> Verdict {
    Verdict {
        effect: effect.into(),
        confidence: 0.5,
        parameters: BTreeMap::new(),
        explanation: "Told.".into(),
        equivalent_places: Vec::new(),
    }
}

/// The bench's mesh (2.0e6 N·m/rad at the output, ratio 1/3, engine 0.2 kg·m², gearbox
/// output 0.05 kg·m²) in its own mode: J = (0.2·9)·0.05/(0.2·9 + 0.05) = 0.048649 kg·m²,
/// so ζ = 0.1 is c = 2·0.1·√(2e6·0.048649) = 62.385 N·m·s/rad.
#[test]
fn an_undamped_mesh_is_damped_at_the_ratio_of_its_own_mode() {
    let m = bench();
    assert_eq!(undamped(&m), vec!["gearbox".to_string()]);
    let j: f64 = 1.8 * 0.05 / 1.85;
    let c = 2.0 * 0.1 * (2.0e6 * j).sqrt();
    let (d, added) = damped(&m, &undamped(&m), 0.1);
    assert_eq!(added.len(), 1);
    assert_eq!(added[0].0, "gearbox");
    assert!(
        (added[0].1 - c).abs() < 1e-9 * c,
        "{} against {c}",
        added[0].1
    );
    assert!((c - 62.385).abs() < 1e-3);
    assert_eq!(gear(&d).mesh_damping_nm_s_per_rad, added[0].1);
    assert!(undamped(&d).is_empty(), "a damped mesh is not tried again");
    assert_eq!(gear(&without(&d, "gearbox")).mesh_damping_nm_s_per_rad, 0.0);
    assert_eq!(without(&d, "no_such_gear"), d);
}

/// Every verdict but `none` names the added damping under `mesh_damping.<gear>` and says
/// it; accepting puts exactly that value into the gear.
#[test]
fn the_report_names_the_added_damping_and_accepting_puts_it_in() {
    let added = Added {
        ratio: 0.0316,
        dampings: vec![("gearbox".into(), 19.7)],
    };
    assert_eq!(marked(verdict("none"), Some(&added)), verdict("none"));
    assert_eq!(
        marked(verdict("parameter_error"), None),
        verdict("parameter_error")
    );
    let v = marked(verdict("parameter_error"), Some(&added));
    assert_eq!(
        v.parameters.get("mesh_damping.gearbox"),
        Some(&ParameterValue::Number(19.7))
    );
    assert!(v.explanation.starts_with("Told. "));
    assert!(v.explanation.contains("ζ = 0.032"), "{}", v.explanation);
    assert!(v.explanation.contains("`gearbox` 19.700 N·m·s/rad"));
    let m = apply(&bench(), &v.parameters).expect("the bench has the gear");
    assert_eq!(gear(&m).mesh_damping_nm_s_per_rad, 19.7);
    assert_eq!(
        apply(&bench(), &BTreeMap::new()).expect("nothing to do"),
        bench()
    );
}

/// A damping for a gear the model lacks, or one that is no damping, is refused by name.
#[test]
fn a_bad_mesh_damping_is_refused_by_its_key() {
    let mut p = BTreeMap::new();
    p.insert("mesh_damping.shaft".into(), ParameterValue::Number(3.0));
    let e = apply(&bench(), &p).expect_err("`shaft` is no gear");
    assert!(e.contains("`shaft`"), "{e}");
    for bad in [-1.0, f64::NAN] {
        let mut p = BTreeMap::new();
        p.insert("mesh_damping.gearbox".into(), ParameterValue::Number(bad));
        let e = apply(&bench(), &p).expect_err("no damping");
        assert!(e.contains("mesh_damping.gearbox"), "{e}");
    }
    let mut p = BTreeMap::new();
    p.insert(
        "mesh_damping.gearbox".into(),
        ParameterValue::Text("lots".into()),
    );
    assert!(apply(&bench(), &p).is_err());
}

/// A backlash candidate made for the undamped mesh damps it at its own ratio whether or
/// not the diagnosis damped the mesh first: the same model either way.
#[test]
fn a_backlash_candidate_replaces_the_added_damping() {
    let m = bench();
    let (d, _) = damped(&m, &undamped(&m), 0.0316);
    for c in backlash_candidates("gearbox", &gear(&m)) {
        let (from_user, _) = c.apply(&m, 0.1).expect("applies");
        let (from_damped, _) = c.apply(&d, 0.1).expect("applies");
        assert_eq!(from_user, from_damped, "{}", c.name());
        let (zeta_default, _) = damped(&m, &undamped(&m), DEFAULT_MESH_DAMPING_RATIO);
        assert_eq!(
            gear(&from_damped).mesh_damping_nm_s_per_rad,
            gear(&zeta_default).mesh_damping_nm_s_per_rad
        );
    }
}
