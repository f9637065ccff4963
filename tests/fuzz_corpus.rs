//! Replays the saved fuzz corpus (`fuzz/corpus/<target>/*`) through the fuzz targets'
//! own bodies on stable (issue 13, deliverable 5): every file must be read without a
//! panic, and what a reader accepts must write back to text that reads equal.
//!
//! The bodies are `fuzz/src/lib.rs`, included here by path, so this test and
//! `cargo fuzz run <target>` make the same calls. A crash the fuzzer finds is copied into
//! `fuzz/regressions/<target>/` until the reader is fixed, then moved into
//! `fuzz/corpus/<target>/` (see scripts/fuzz.sh): libFuzzer replays its corpus first, so
//! an input that still crashes must not be there.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;

#[path = "../fuzz/src/lib.rs"]
mod targets;

/// Runs `body` on every file of `fuzz/<set>/<target>/`; fails naming every file that
/// panicked, with its message.
fn replay(set: &str, target: &str, body: fn(&[u8])) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join(set)
        .join(target);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .collect();
    files.sort();
    // The seeds alone are over 20 files per target; fewer means the corpus went missing.
    let least = if set == "corpus" { 20 } else { 1 };
    assert!(
        files.len() >= least,
        "{}: only {} files",
        dir.display(),
        files.len()
    );
    let mut failures = Vec::new();
    for path in &files {
        let data = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        if let Err(payload) = catch_unwind(AssertUnwindSafe(|| body(&data))) {
            let message = payload
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| payload.downcast_ref::<&str>().copied())
                .unwrap_or("(no message)");
            let first_line = message.lines().next().unwrap_or("");
            failures.push(format!("{}: {first_line}", path.display()));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} corpus files panicked:\n{}",
        failures.len(),
        files.len(),
        failures.join("\n")
    );
}

#[test]
fn model_corpus_reads_without_panic() {
    replay("corpus", "model", targets::model);
}

#[test]
fn recording_corpus_reads_without_panic() {
    replay("corpus", "recording", targets::recording);
}

#[test]
fn sidecar_corpus_reads_without_panic() {
    replay("corpus", "sidecar", targets::sidecar);
}

/// Inputs the fuzzer found, kept as regressions once fixed: `sidecar/speed-1e300.toml` —
/// `sidecar_string` wrote `speed_rpm = 1e300` as 301 digits, which TOML reads as an
/// overflowing integer, so a written sidecar did not read back.
#[test]
fn regressions_read_without_panic() {
    replay("regressions", "sidecar", targets::sidecar);
}

/// The fixed sidecar and CSV the targets build on are valid, so the targets reach past
/// the first error (a test that cannot fail otherwise: a broken fixture would make every
/// input an early `Err`).
#[test]
fn the_targets_fixtures_are_valid() {
    let meta = torsim::recording::parse_sidecar(targets::SIDECAR, "fuzz.toml").expect("sidecar");
    let nodes: Vec<String> = targets::NODES.iter().map(|n| n.to_string()).collect();
    let recording =
        torsim::recording::parse_recording(&targets::valid_csv(), "fuzz.csv", meta, Some(&nodes))
            .expect("the fixed CSV reads");
    assert_eq!(recording.time_s.len(), 300);
}
