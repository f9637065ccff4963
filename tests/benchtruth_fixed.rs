//! The diagnosis benchmark's small fixed set in CI (issue 14, item 4): a few cases of the
//! independent bench (`benchtruth`, which shares no code with torsim), drawn from fixed
//! development seeds, diagnosed by the real `torsim diagnose` binary and scored by the
//! bench's own scorer — a control and four effects of different kinds. The published
//! accuracy comes from `scripts/diagnosis-benchmark.sh` on ≥ 100 fresh seeds; this test
//! only keeps a regression from reaching main unseen.

use benchtruth::bench::{Place, run_case};
use std::path::Path;

/// Development seeds (class = seed mod 11): 11 `none`, 5 `hysteretic_damping`
/// (structural), 13 `coupling_amplitude_nonlinearity` (power law, p = 2), 20
/// `cylinder_imbalance` (one cylinder's pressure scaled), 2087 `gear_backlash` (a softened
/// dead zone of 0.195° in a damped mesh the user's model leaves undamped: named only since
/// the candidate damps the mesh, 11 s in release), 3008 `hysteretic_damping` (structural,
/// where the user's model fits the usual held-out half, χ²/N 1.41, and misses the fitted
/// one, 25.8: named only since the folds swap, `diagnose/holdout.rs`), 3114
/// `parameter_error` (a control whose run-up lingers 2 s at a resonance: named
/// `hysteretic_damping` until the run-up followed the measured speed,
/// `transient/measured_speed.rs`), 3071 `coupling_amplitude_nonlinearity` (a `tanh` law:
/// named only since the saturating form is a candidate and a held-out tie goes to the
/// better fit of the fitted half, `diagnose/tie.rs`; before, `unmodelled_mode`), 3048
/// `parameter_error` (a control whose damped gear mesh the user's model, written in the
/// spec's keys, leaves undamped: named `unmodelled_mode` at the mesh mode until the
/// diagnosis damped an undamped mesh as the recordings say, `diagnose/mesh_damping.rs`),
/// 3077 `gear_backlash` (0.28° of play on a Hertzian contact: named `parameter_error`
/// until the backlash candidates had a Hertzian form, `physics/tooth_contact.rs`; 52 s in
/// release).
const SEEDS: [u64; 10] = [11, 5, 13, 20, 2087, 3008, 3114, 3071, 3048, 3077];

#[test]
fn a_fixed_set_of_independent_cases_is_named_right() {
    let torsim = Path::new(env!("CARGO_BIN_EXE_torsim"));
    let root = tempfile::Builder::new()
        .prefix("torsim-bt-fixed-")
        .tempdir()
        .expect("temp dir");
    let mut failures = Vec::new();
    for seed in SEEDS {
        let row = run_case(torsim, seed, &root.path().join(format!("case-{seed}")));
        let outcome = match row.outcome {
            Ok(o) => o,
            Err(e) => {
                failures.push(format!("seed {seed}: {e}"));
                continue;
            }
        };
        if !outcome.right {
            failures.push(format!(
                "seed {seed}: truth {} ({}) named {}",
                outcome.truth, row.form, outcome.verdict
            ));
        }
        // Never worse than the user's model on the held-out data (issue 14, item 2).
        if let (Some(before), Some(after)) = (outcome.fit_before, outcome.fit_after)
            && after > before
        {
            failures.push(format!(
                "seed {seed}: held-out χ²/N {before:.3} → {after:.3}"
            ));
        }
        // A place the report names must be the truth's or one it says it cannot tell
        // from it.
        if outcome.place == Some(Place::Wrong) {
            failures.push(format!(
                "seed {seed}: {} at the wrong place",
                outcome.verdict
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
