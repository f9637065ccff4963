//! A scratch directory for one test: new and empty under the system temp dir, and removed
//! with everything in it when dropped, so a test leaves nothing behind, passed or failed.
#![allow(dead_code)]

use std::path::Path;

/// A fresh empty directory, removed when dropped; it derefs to its path, so
/// `dir.join("x")`, `&dir` as a `&Path` and `dir.display()` work as on a `PathBuf`. Bind
/// it to a named variable (not `_`) that lives as long as the test uses the path.
#[derive(Debug)]
#[must_use = "the directory is removed when this is dropped"]
pub struct Scratch(tempfile::TempDir);

impl Scratch {
    /// A new directory whose name starts with `prefix` (a random suffix makes it unique).
    pub fn new(prefix: &str) -> Self {
        Self(
            tempfile::Builder::new()
                .prefix(prefix)
                .tempdir()
                .expect("create scratch dir"),
        )
    }
}

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        self.0.path()
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        self.0.path()
    }
}
