//! Atomic writes: a temporary file in the target's directory (`.<name>.<pid>.tmp`),
//! written whole and synced, then renamed over the target. A reader never sees half a
//! file; on any failure the temporary file is removed and the target is left as it was
//! (issue 13: "Temporary files are removed on failure"). Every temporary is registered in
//! [`super::temps`] while it exists, so a signal handler can remove it.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::temps::{create_registered, finish_registered};

/// A complete temporary file waiting to be renamed over its target. Dropping it without
/// [`TempFile::persist`] removes it.
#[derive(Debug)]
pub struct TempFile {
    tmp: PathBuf,
    target: PathBuf,
    done: bool,
}

impl TempFile {
    /// Writes `bytes` to a temporary file beside `target` and syncs it; `target` is not
    /// touched. On failure nothing is left behind.
    pub fn write(target: &Path, bytes: &[u8]) -> std::io::Result<TempFile> {
        let name = target
            .file_name()
            .map_or_else(|| "file".into(), |n| n.to_string_lossy().into_owned());
        let tmp = target.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
        // A rename over a folder fails only at the end: refuse it before writing anything,
        // so the first file of a pair is not replaced when the second cannot be.
        if std::fs::symlink_metadata(target).is_ok_and(|m| m.is_dir()) {
            return Err(std::io::Error::new(
                std::io::ErrorKind::IsADirectory,
                "is a folder",
            ));
        }
        let mut file = create_registered(&tmp, || std::fs::File::create(&tmp))?;
        // From here on, dropping `staged` removes the temporary file.
        let staged = TempFile {
            tmp,
            target: target.to_path_buf(),
            done: false,
        };
        file.write_all(bytes)?;
        file.sync_all()?;
        Ok(staged)
    }

    /// The temporary file's path.
    pub fn temporary(&self) -> &Path {
        &self.tmp
    }

    /// The file this one replaces once persisted.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Renames the temporary file over its target.
    pub fn persist(mut self) -> std::io::Result<()> {
        self.done = true;
        let result = finish_registered(&self.tmp, || std::fs::rename(&self.tmp, &self.target));
        if result.is_err() {
            let _ = finish_registered(&self.tmp, || std::fs::remove_file(&self.tmp));
        }
        result
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.done {
            // Best effort: a failure leaves a file the signal handler may still remove.
            let _ = finish_registered(&self.tmp, || std::fs::remove_file(&self.tmp));
        }
    }
}

/// Writes `bytes` to `path` atomically (see the module docs).
pub fn write_atomic(path: &Path, bytes: impl AsRef<[u8]>) -> std::io::Result<()> {
    TempFile::write(path, bytes.as_ref())?.persist()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh empty directory, removed when the returned guard is dropped.
    fn dir(name: &str) -> tempfile::TempDir {
        tempfile::Builder::new()
            .prefix(&format!("torsim-files-{name}-"))
            .tempdir()
            .unwrap()
    }

    #[test]
    fn writes_whole_files_and_leaves_a_target_alone_on_failure() {
        let scratch = dir("atomic");
        let dir = scratch.path();
        let path = dir.join("a.txt");
        write_atomic(&path, "one").unwrap();
        write_atomic(&path, "two").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "two");
        assert!(write_atomic(&dir.join("missing/b.txt"), "x").is_err());
        let left: Vec<_> = std::fs::read_dir(dir).unwrap().collect();
        assert_eq!(left.len(), 1, "no temporary file is left");
    }

    #[test]
    fn a_dropped_temporary_is_removed_and_unregistered() {
        let scratch = dir("dropped");
        let dir = scratch.path();
        let path = dir.join("a.txt");
        std::fs::write(&path, "old").unwrap();
        let staged = TempFile::write(&path, b"new").unwrap();
        let tmp = staged.temporary().to_path_buf();
        assert!(tmp.exists());
        assert!(super::super::temps::temporaries().contains(&tmp));
        drop(staged);
        assert!(!tmp.exists());
        assert!(!super::super::temps::temporaries().contains(&tmp));
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
    }

    #[test]
    fn a_failed_rename_removes_the_temporary() {
        let scratch = dir("rename");
        let dir = scratch.path();
        // A directory as the target: the rename over it fails.
        let target = dir.join("sub");
        std::fs::create_dir_all(target.join("inner")).unwrap();
        assert!(write_atomic(&target, "x").is_err());
        let names: Vec<_> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, vec![std::ffi::OsString::from("sub")]);
    }
}
