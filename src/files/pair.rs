//! A recording's CSV and its sidecar, written in stages (issue 13, "Guard a recording's
//! CSV + sidecar pair"): both temporaries are written first; if either cannot be written
//! nothing is renamed and both are removed. Then the CSV is renamed over its target, then
//! the sidecar. Two renames cannot be atomic together, so the sidecar carries the CSV's
//! hash and row count and readers refuse a mismatched pair; the stages are public so a
//! test can stop between them.

use std::path::{Path, PathBuf};

use super::atomic::TempFile;

/// A file of the pair that could not be written.
#[derive(Debug, thiserror::Error)]
#[error("{}: cannot write: {source}", path.display())]
pub struct PairError {
    /// The target that could not be written.
    pub path: PathBuf,
    /// Why.
    pub source: std::io::Error,
}

/// Both temporaries written and synced; neither target touched yet. Dropping it removes
/// both temporaries.
#[derive(Debug)]
pub struct PreparedPair {
    csv: TempFile,
    sidecar: TempFile,
}

/// The CSV renamed over its target; the sidecar's temporary waits. Dropping it removes
/// the sidecar's temporary (the pair is then mismatched, which readers refuse).
#[derive(Debug)]
pub struct FirstCommitted {
    sidecar: TempFile,
}

impl PreparedPair {
    /// Writes the temporaries of `csv` and `sidecar`; on failure neither is left.
    pub fn prepare(
        csv: &Path,
        csv_bytes: &[u8],
        sidecar: &Path,
        sidecar_bytes: &[u8],
    ) -> Result<PreparedPair, PairError> {
        let stage = |path: &Path, bytes: &[u8]| {
            TempFile::write(path, bytes).map_err(|source| PairError {
                path: path.to_path_buf(),
                source,
            })
        };
        let csv = stage(csv, csv_bytes)?;
        let sidecar = stage(sidecar, sidecar_bytes)?;
        Ok(PreparedPair { csv, sidecar })
    }

    /// The two temporary files (CSV, sidecar).
    pub fn temporaries(&self) -> [&Path; 2] {
        [self.csv.temporary(), self.sidecar.temporary()]
    }

    /// Renames the CSV over its target.
    pub fn commit_first(self) -> Result<FirstCommitted, PairError> {
        let path = self.csv.target().to_path_buf();
        let sidecar = self.sidecar;
        self.csv
            .persist()
            .map_err(|source| PairError { path, source })?;
        Ok(FirstCommitted { sidecar })
    }

    /// Both stages: the CSV, then the sidecar.
    pub fn commit(self) -> Result<(), PairError> {
        self.commit_first()?.commit_second()
    }
}

impl FirstCommitted {
    /// Renames the sidecar over its target.
    pub fn commit_second(self) -> Result<(), PairError> {
        let path = self.sidecar.target().to_path_buf();
        self.sidecar
            .persist()
            .map_err(|source| PairError { path, source })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sidecar_that_cannot_be_written_leaves_both_targets_and_no_temporary() {
        let scratch = tempfile::Builder::new()
            .prefix("torsim-pair-")
            .tempdir()
            .unwrap();
        let dir = scratch.path();
        let csv = dir.join("a.csv");
        std::fs::write(&csv, "old csv").unwrap();
        // The sidecar's folder does not exist: its temporary cannot be created.
        let sidecar = dir.join("missing/a.toml");
        let e = PreparedPair::prepare(&csv, b"new csv", &sidecar, b"new toml").unwrap_err();
        assert_eq!(e.path, sidecar);
        assert_eq!(std::fs::read_to_string(&csv).unwrap(), "old csv");
        let names: Vec<_> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(
            names,
            vec![std::ffi::OsString::from("a.csv")],
            "no temporary left"
        );
    }

    #[test]
    fn a_sidecar_that_is_a_folder_is_refused_before_the_csv_is_replaced() {
        let scratch = tempfile::Builder::new()
            .prefix("torsim-pair-dir-")
            .tempdir()
            .unwrap();
        let dir = scratch.path();
        std::fs::create_dir_all(dir.join("a.toml/inner")).unwrap();
        let csv = dir.join("a.csv");
        std::fs::write(&csv, "old csv").unwrap();
        let e = PreparedPair::prepare(&csv, b"new", &dir.join("a.toml"), b"new").unwrap_err();
        assert!(
            e.to_string().contains("a.toml: cannot write: is a folder"),
            "{e}"
        );
        assert_eq!(std::fs::read_to_string(&csv).unwrap(), "old csv");
        assert_eq!(
            std::fs::read_dir(dir).unwrap().count(),
            2,
            "no temporary left"
        );
    }
}
