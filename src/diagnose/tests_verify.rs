//! Which screened candidates are verified in the time domain whatever their screening
//! scored ([`super::verify::verified_anyway`]).

use super::candidates::{Candidate, candidates};
use super::candidates_amplitude::is_elastic;
use super::context::Evaluated;
use super::screen::Screened;
use super::verify::{may_be_verified, verified_anyway};
use crate::effects::Effect;
use crate::model::{parse_model, presets};

/// Verified whatever it screened ([`super::verify::verified_anyway`]): an elastic
/// amplitude law the screening found present, and a thermal drift; not an elastic law at
/// its absence, nor a candidate the linear model screens.
#[test]
fn a_present_elastic_law_and_a_drift_are_verified_anyway() {
    let text = presets::preset("diagnosis-bench").expect("shipped").text;
    let model = parse_model(text, "bench.toml").expect("model");
    let list = candidates(&model, &[], true);
    let at = |c: &Candidate, value: f64| Screened {
        candidate: c.clone(),
        evaluated: Evaluated {
            model: model.clone(),
            joint: None,
            simulated: Vec::new(),
            z: Vec::new(),
            factors: Vec::new(),
            value: Some(value),
        },
        verified: false,
        note: String::new(),
        in_time_domain: false,
        rejected: None,
        rejected_steps: Vec::new(),
        unsupported: None,
    };
    let elastic = list
        .iter()
        .find(|c| is_elastic(c))
        .expect("an elastic form");
    assert!(verified_anyway(&at(elastic, elastic.param.start)));
    assert!(!verified_anyway(&at(elastic, 0.0)));
    let drift = list
        .iter()
        .find(|c| c.effect == Effect::CouplingThermalDrift)
        .expect("a thermal form");
    assert!(verified_anyway(&at(drift, 300.0)));
    let seed_law = list
        .iter()
        .find(|c| c.param.key == "a2" && !is_elastic(c))
        .expect("seed 000's amplitude law");
    assert!(!verified_anyway(&at(seed_law, seed_law.param.start)));
}

/// The gate to the time domain ([`super::verify::may_be_verified`]): a gain on the plain
/// fit's fitted χ²/N passes, a loss above the noise does not, and within the noise
/// (χ²/N ≤ 1) a candidate ties with the plain fit and passes (seed 6007's numbers; 6004's
/// Dahl truth, screened at 9.687 against 9.377, stays out).
#[test]
fn the_gate_lets_a_gain_or_a_fit_to_the_noise_through() {
    assert!(may_be_verified(9.0, 9.377));
    assert!(!may_be_verified(9.687, 9.377));
    assert!(may_be_verified(0.681, 0.673));
    assert!(!may_be_verified(1.05, 0.673));
    assert!(may_be_verified(1.0, 0.5));
}
