//! Property (issue 13, deliverable 5): `torsim::signal::analyse` of any finite, uniform
//! recording — random speeds around a positive mean, random rate and length above the
//! two-working-cycle minimum, steady or run-up, one or two stations — never panics; it
//! returns a result or an error. A result holds no NaN or infinity.

mod proptest_support;

use proptest::prelude::*;
use torsim::recording::check_recording;
use torsim::signal::analyse;

proptest! {
    // 96 cases of up to 60 000 samples (most of a few thousand): about 1 s in a debug
    // build; about 9 in 10 analyse, the rest are refused (too short for a run-up's STFT).
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn analyse_never_panics(case in proptest_support::recording_case()) {
        let recording = case.recording();
        // Finite and uniform by construction.
        prop_assert!(check_recording(&recording, "case.csv").is_ok());
        let result = analyse(&recording);
        if let Ok(analysis) = result {
            // `{:?}` prints every number the analysis holds.
            let printed = format!("{analysis:?}");
            prop_assert!(!printed.contains("NaN") && !printed.contains("inf"),
                "non-finite value in the analysis of {:?}", case);
        }
    }
}

/// The strategy's recordings are analysable (else the property would only ever see
/// errors): a plain steady case gives a result with its two working cycles or more.
#[test]
fn a_plain_case_is_analysed() {
    let case = proptest_support::RecordingCase {
        rate_hz: 5000.0,
        mean_rpm: 3000.0,
        cycles: 4.0,
        noise: 0.0,
        order2: 0.05,
        ramp: None,
        second: Some(0.5),
        t0_s: 0.0,
        seed: 1,
    };
    let analysis = analyse(&case.recording()).expect("a plain steady recording analyses");
    assert!(analysis.cycles >= 2, "{} cycles", analysis.cycles);
    assert_eq!(analysis.stations.len(), 2);
}
