//! `synth` is a leaf (issue 14, item 3): the library's effect models live in
//! `src/effects/`, and nothing in `src/` outside `synth/` and the front ends (`cli/`,
//! `gui/`, `main.rs`) reaches into `crate::synth`. The diagnosis builds its candidates from
//! `crate::effects`, never from the generator of the cases it is proved on.

use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`, recursively.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let entries = std::fs::read_dir(dir).expect("src/ is readable");
    for entry in entries {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The lines of `text` that name the `synth` module as a path (`crate::synth`,
/// `synth::…`, `torsim::synth`), code or doc link alike.
fn synth_references(text: &str) -> Vec<(usize, String)> {
    text.lines()
        .enumerate()
        .filter(|(_, line)| {
            line.match_indices("synth::").any(|(i, _)| {
                // `synth::` as a whole path segment, not the tail of another name.
                !line[..i]
                    .chars()
                    .next_back()
                    .is_some_and(|c| c.is_alphanumeric() || c == '_')
            })
        })
        .map(|(i, line)| (i + 1, line.trim().to_string()))
        .collect()
}

#[test]
fn the_detector_sees_every_spelling() {
    assert_eq!(synth_references("use crate::synth::Effect;").len(), 1);
    assert_eq!(synth_references("use torsim::synth::{Plan};").len(), 1);
    assert_eq!(synth_references("    synth::build_truth(&m)").len(), 1);
    assert_eq!(synth_references("/// [`crate::synth::rng`]").len(), 1);
    assert!(synth_references("use crate::effects::Effect; // synthesized").is_empty());
    assert!(synth_references("PeakSynthesizer::new(orders)").is_empty());
    assert!(synth_references("pub mod synth;").is_empty());
}

#[test]
fn nothing_outside_synth_and_the_front_ends_imports_synth() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let allowed = ["synth", "cli", "gui", "main.rs"].map(|d| src.join(d));
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    assert!(
        files.len() > 50,
        "found only {} files under src/",
        files.len()
    );
    let mut offending = Vec::new();
    for file in files
        .iter()
        .filter(|f| !allowed.iter().any(|a| f.starts_with(a)))
    {
        let text = std::fs::read_to_string(file).expect("a source file is UTF-8");
        for (line, code) in synth_references(&text) {
            offending.push(format!("{}:{line}: {code}", file.display()));
        }
    }
    assert!(
        offending.is_empty(),
        "synth must be a leaf; these reach into it:\n{}",
        offending.join("\n")
    );
}
