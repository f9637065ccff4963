//! Running the `torsim` binary from integration tests, from the crate root.
#![allow(dead_code)]

use serde_json::Value;
use std::process::{Command, Output};

/// Runs `torsim` with `args` in the crate root.
pub fn torsim(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_torsim"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run torsim")
}

/// Runs a command that must succeed and print exactly one JSON document on stdout.
pub fn json(args: &[&str]) -> Value {
    let out = torsim(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("{args:?}: stdout is not one JSON document: {e}"))
}
