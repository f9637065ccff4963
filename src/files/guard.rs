//! The output guard (issue 13, "Outputs can never destroy inputs"): given a command's
//! inputs, each output path it is about to write is refused when it resolves to one of
//! them, to an output already claimed, or — for a recording — when the CSV and its sidecar
//! (`<stem>.toml`, `spec/recording-format.md`) would be the same file.
//!
//! Two paths are the same file when their canonical paths are equal (for a file that does
//! not exist yet: its parent's canonical path joined with its name) or, on unix, when both
//! exist with the same device and inode (hard links).

use std::path::{Path, PathBuf};

/// An output that would destroy an input (exit 2 in the CLI).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OutputError {
    /// The output resolves to an input, or to an output already written by this command.
    #[error(
        "{flag} {path}: refused: {written} would replace {what} {input} (an output never replaces an input; choose another name)"
    )]
    ReplacesInput {
        /// The flag or setting that named the output (`--csv`).
        flag: String,
        /// The output as given.
        path: String,
        /// What would be written: `it`, or `its sidecar <path>`.
        written: String,
        /// What the input is (`the model`, `the recording`, `the sidecar of recording`).
        what: String,
        /// The input as given.
        input: String,
    },
    /// A recording's CSV named `*.toml` would be its own sidecar.
    #[error(
        "{flag} {path}: refused: a recording's sidecar is its CSV's name with `.toml`, so the CSV would be its own sidecar; name the CSV `*.csv`"
    )]
    OwnSidecar {
        /// The flag that named the CSV.
        flag: String,
        /// The CSV as given.
        path: String,
    },
}

/// A path's identity: its canonical form and, on unix where it exists, device and inode.
#[derive(Debug, Clone)]
struct Identity {
    canonical: PathBuf,
    inode: Option<(u64, u64)>,
}

impl Identity {
    fn of(path: &Path) -> Identity {
        let canonical = std::fs::canonicalize(path).unwrap_or_else(|_| {
            let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
            match (absolute.parent(), absolute.file_name()) {
                (Some(parent), Some(name)) => std::fs::canonicalize(parent)
                    .map(|p| p.join(name))
                    .unwrap_or(absolute.clone()),
                _ => absolute,
            }
        });
        Identity {
            canonical,
            inode: inode(path),
        }
    }

    fn same(&self, other: &Identity) -> bool {
        self.canonical == other.canonical
            || matches!((self.inode, other.inode), (Some(a), Some(b)) if a == b)
    }
}

#[cfg(unix)]
fn inode(path: &Path) -> Option<(u64, u64)> {
    use std::os::unix::fs::MetadataExt;
    std::fs::metadata(path).ok().map(|m| (m.dev(), m.ino()))
}

#[cfg(not(unix))]
fn inode(_path: &Path) -> Option<(u64, u64)> {
    None
}

/// Whether `a` and `b` name the same file (see the module docs).
pub fn same_file(a: &Path, b: &Path) -> bool {
    Identity::of(a).same(&Identity::of(b))
}

/// The inputs of one command and the outputs claimed so far.
#[derive(Debug, Clone, Default)]
pub struct OutputGuard {
    files: Vec<(String, String, Identity)>,
}

impl OutputGuard {
    /// A guard with no inputs yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds an input file; `what` says what it is in errors (`the model`).
    pub fn input(&mut self, what: &str, path: &Path) -> &mut Self {
        let id = Identity::of(path);
        self.files
            .push((what.to_string(), path.display().to_string(), id));
        self
    }

    /// Adds a recording read by the command: its CSV and its sidecar.
    pub fn recording_input(&mut self, csv: &Path) -> &mut Self {
        self.input("the recording", csv);
        let sidecar = crate::recording::sidecar_path(csv);
        self.input("the sidecar of the recording", &sidecar)
    }

    /// Claims the output `path` named by `flag`: refused when it is an input or an output
    /// claimed before.
    pub fn output(&mut self, flag: &str, path: &Path) -> Result<(), OutputError> {
        self.claim(flag, path, path, "the output")
    }

    /// Claims a recording's CSV `csv` named by `flag`, and its sidecar.
    pub fn recording_output(&mut self, flag: &str, csv: &Path) -> Result<(), OutputError> {
        let sidecar = crate::recording::sidecar_path(csv);
        // An input it would destroy is named first.
        self.claim(flag, csv, csv, "the output")?;
        if same_file(csv, &sidecar) {
            return Err(OutputError::OwnSidecar {
                flag: flag.to_string(),
                path: csv.display().to_string(),
            });
        }
        self.claim(flag, csv, &sidecar, "the output")
    }

    fn claim(
        &mut self,
        flag: &str,
        given: &Path,
        written: &Path,
        what: &str,
    ) -> Result<(), OutputError> {
        let id = Identity::of(written);
        if let Some((input_what, input, _)) = self.files.iter().find(|(_, _, i)| i.same(&id)) {
            return Err(OutputError::ReplacesInput {
                flag: flag.to_string(),
                path: given.display().to_string(),
                written: if written == given {
                    "it".into()
                } else {
                    format!("its sidecar {}", written.display())
                },
                what: input_what.clone(),
                input: input.clone(),
            });
        }
        self.files.push((
            format!("{what} of {flag}"),
            written.display().to_string(),
            id,
        ));
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh empty directory, removed when the returned guard is dropped.
    fn dir(name: &str) -> tempfile::TempDir {
        tempfile::Builder::new()
            .prefix(&format!("torsim-guard-{name}-"))
            .tempdir()
            .unwrap()
    }

    #[test]
    fn an_output_resolving_to_an_input_is_refused() {
        let scratch = dir("input");
        let d = scratch.path();
        let model = d.join("run.toml");
        std::fs::write(&model, "x").unwrap();
        let mut guard = OutputGuard::new();
        guard.input("the model", &model);
        // The same file through `..` and `.`; and a new file in the same folder.
        let roundabout = d.join("sub/../run.toml");
        std::fs::create_dir_all(d.join("sub")).unwrap();
        let e = guard.clone().output("--csv", &roundabout).unwrap_err();
        assert!(e.to_string().contains("would replace the model"), "{e}");
        assert!(guard.clone().output("--csv", &d.join("./new.csv")).is_ok());
        // The sidecar of `run.csv` is the model.
        let e = guard
            .clone()
            .recording_output("--csv", &d.join("run.csv"))
            .unwrap_err();
        let text = e.to_string();
        assert!(text.starts_with("--csv "), "{text}");
        assert!(text.contains("run.toml would replace the model"), "{text}");
        assert!(text.contains("its sidecar"), "{text}");
    }

    #[test]
    fn a_csv_named_toml_is_its_own_sidecar() {
        let scratch = dir("own");
        let d = scratch.path();
        let e = OutputGuard::new()
            .recording_output("--csv", &d.join("out.toml"))
            .unwrap_err();
        assert!(matches!(e, OutputError::OwnSidecar { .. }), "{e}");
        assert!(e.to_string().contains("its own sidecar"));
    }

    #[test]
    fn inputs_of_a_recording_and_outputs_claimed_twice() {
        let scratch = dir("pair");
        let d = scratch.path();
        let csv = d.join("a.csv");
        std::fs::write(&csv, "x").unwrap();
        std::fs::write(d.join("a.toml"), "x").unwrap();
        let mut guard = OutputGuard::new();
        guard.recording_input(&csv);
        let e = guard
            .clone()
            .output("--report", &d.join("a.toml"))
            .unwrap_err();
        assert!(
            e.to_string().contains("the sidecar of the recording"),
            "{e}"
        );
        assert!(guard.output("--out", &d.join("b.csv")).is_ok());
        let e = guard.output("--out", &d.join("b.csv")).unwrap_err();
        assert!(e.to_string().contains("the output of --out"), "{e}");
    }

    #[cfg(unix)]
    #[test]
    fn a_hard_link_is_the_same_file() {
        let scratch = dir("link");
        let d = scratch.path();
        let model = d.join("m.toml");
        std::fs::write(&model, "x").unwrap();
        let link = d.join("other.csv");
        std::fs::hard_link(&model, &link).unwrap();
        let mut guard = OutputGuard::new();
        guard.input("the model", &model);
        assert!(guard.output("--csv", &link).is_err());
    }
}
