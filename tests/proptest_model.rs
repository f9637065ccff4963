//! Property (issue 13, deliverable 5): any valid model round-trips through the writer
//! and the reader — `parse_model(to_toml_string(m)) == m` — and writing is idempotent.
//! The written text never holds `nan` or `inf` (no output holds NaN).

mod proptest_support;

use proptest::prelude::*;
use torsim::model::{parse_model, to_toml_string, validate};

proptest! {
    // 1024 cases: about 1 s in a debug build (a model writes and parses in ~1 ms).
    #![proptest_config(ProptestConfig::with_cases(1024))]

    #[test]
    fn a_valid_model_round_trips(model in proptest_support::model()) {
        // Valid by construction; a failure here is a bug in the strategy, not torsim.
        prop_assert!(validate(&model).is_ok(), "{:?}", validate(&model));
        let text = to_toml_string(&model);
        let lower = text.to_lowercase();
        for word in ["= nan", "= inf", "= -inf", " nan,", " inf,"] {
            prop_assert!(!lower.contains(word), "`{}` written:\n{}", word, text);
        }
        let again = parse_model(&text, "written.toml");
        prop_assert!(again.is_ok(), "written model does not read: {:?}\n{}", again, text);
        let again = again.unwrap();
        prop_assert_eq!(&again, &model, "written text:\n{}", text);
        prop_assert_eq!(to_toml_string(&again), text, "writing is not idempotent");
    }
}
