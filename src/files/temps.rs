//! The registry of temporary files in progress (issue 13: "Temporary files are removed on
//! failure and on SIGINT/SIGTERM").
//!
//! A temporary file is registered before it is created and unregistered once it was
//! renamed or removed; both happen under one lock. [`remove_temporaries`] — called by a
//! front end's signal handler, never by the library itself — takes that lock for good,
//! removes every registered file and makes any later registration fail, so no temporary
//! can appear after it ran. The caller then ends the process.

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

/// The registered temporaries, and whether [`remove_temporaries`] has run.
struct Registry {
    paths: Vec<PathBuf>,
    closed: bool,
}

static REGISTRY: Mutex<Registry> = Mutex::new(Registry {
    paths: Vec::new(),
    closed: false,
});

fn lock() -> MutexGuard<'static, Registry> {
    // A panic while holding the lock leaves the list itself consistent.
    REGISTRY.lock().unwrap_or_else(|p| p.into_inner())
}

/// The registry, locked, unless the process is ending (a signal arrived): then no file
/// may be created or renamed any more.
fn open_registry() -> std::io::Result<MutexGuard<'static, Registry>> {
    let registry = lock();
    if registry.closed {
        return Err(std::io::Error::new(
            std::io::ErrorKind::Interrupted,
            "the process is ending (signal received)",
        ));
    }
    Ok(registry)
}

/// Runs `create` with `path` registered, under the registry's lock: the file it creates
/// is removed by [`remove_temporaries`] from then on. Fails when the process is ending.
pub(crate) fn create_registered<T>(
    path: &Path,
    create: impl FnOnce() -> std::io::Result<T>,
) -> std::io::Result<T> {
    let mut registry = open_registry()?;
    let value = create()?;
    registry.paths.push(path.to_path_buf());
    Ok(value)
}

/// Runs `finish` (a rename or a removal of `path`) under the registry's lock and
/// unregisters `path`, whatever the outcome.
pub(crate) fn finish_registered<T>(
    path: &Path,
    finish: impl FnOnce() -> std::io::Result<T>,
) -> std::io::Result<T> {
    let mut registry = open_registry()?;
    let result = finish();
    registry.paths.retain(|p| p != path);
    result
}

/// The temporaries in progress (for tests and diagnostics).
pub fn temporaries() -> Vec<PathBuf> {
    lock().paths.clone()
}

/// Removes every temporary file in progress and refuses new ones; returns how many were
/// removed. For a front end's SIGINT/SIGTERM handler, which then ends the process: the
/// registry's lock stays taken, so a write in progress on another thread blocks before its
/// next create or rename instead of leaving a file behind.
pub fn remove_temporaries() -> usize {
    let mut registry = lock();
    registry.closed = true;
    let mut removed = 0;
    for path in registry.paths.drain(..) {
        if std::fs::remove_file(&path).is_ok() {
            removed += 1;
        }
    }
    // Keep the lock for the rest of the process: the caller exits.
    std::mem::forget(registry);
    removed
}
