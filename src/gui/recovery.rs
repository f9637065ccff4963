//! Crash recovery (issue 16): unsaved edits are written to a recovery file at most
//! [`AUTOSAVE_AFTER`] after a change (a written file is at most that old while the user
//! keeps editing), off the GUI thread, and the file is removed as soon as the model is
//! clean again (saved, another model shown, the edits discarded, the window closed after
//! asking). A window that ends any other way — a crash, a kill, a power cut — leaves its
//! file behind; the next start restores it ([`crate::gui::startup`]), or offers it in the File menu
//! when a model was named on the command line.
//!
//! Each window writes its own file, `<pid>.toml` in [`recovery_dir`], so two windows
//! never write over each other's edits; at start, the files of processes no longer
//! running are the ones to recover. The file is the model file (spec model format) with
//! a first comment line naming the file the model came from.

use crate::gui::app::TorsimApp;
use crate::gui::background::{self, Pending};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
use torsim::model::{Model, parse_model};

/// How long after a change the autosave writes: 1 s (issue 16 asks for at most 2 s).
pub const AUTOSAVE_AFTER: Duration = Duration::from_secs(1);
/// Environment variable that puts the recovery files elsewhere (tests, portable use).
pub const RECOVERY_DIR_ENV: &str = "TORSIM_RECOVERY_DIR";
/// The first line of a recovery file, before the path the model came from.
const HEADER: &str = "# torsim recovery of unsaved edits; model file: ";

/// The folder of the recovery files: `$TORSIM_RECOVERY_DIR`, else `recovery/` in eframe's
/// data folder (`~/.local/share/torsim/recovery` on Linux). `None`: no autosave.
pub fn recovery_dir() -> Option<PathBuf> {
    std::env::var_os(RECOVERY_DIR_ENV)
        .map(PathBuf::from)
        .or_else(|| eframe::storage_dir("torsim").map(|d| d.join("recovery")))
}

/// Unsaved edits found in the recovery folder, left by a window that ended without saving.
#[derive(Debug, Clone)]
pub struct Orphan {
    /// The recovery file.
    pub file: PathBuf,
    /// The edited model.
    pub model: Model,
    /// The file the model came from (`None`: a preset or a new model).
    pub path: Option<PathBuf>,
}

/// The autosave of one window.
#[derive(Debug, Default)]
pub struct Recovery {
    /// This window's recovery file (`None`: autosave off).
    pub file: Option<PathBuf>,
    /// The model revision in the file, if the file holds this window's edits.
    written: Option<u64>,
    /// When the first change not yet written was seen.
    pending_since: Option<Instant>,
    /// A write in progress: the revision it writes and its outcome.
    writing: Option<(u64, Pending<Result<(), String>>)>,
    /// Recovery files of ended windows, the newest first, not yet taken up.
    pub orphans: Vec<Orphan>,
    /// An orphan restored into this window: removed once this window's own file holds it.
    adopted: Option<PathBuf>,
}

impl Recovery {
    /// Autosave into `dir` (this process' file), with the `orphans` found there.
    pub fn in_dir(dir: &Path, orphans: Vec<Orphan>) -> Self {
        Self {
            file: Some(dir.join(format!("{}.toml", std::process::id()))),
            orphans,
            ..Default::default()
        }
    }
}

/// True when a process with this id runs (Linux: `/proc/<pid>`; elsewhere unknown, so
/// false: a running window's file may then be offered, never lost).
fn running(pid: u32) -> bool {
    pid == std::process::id() || Path::new(&format!("/proc/{pid}")).exists()
}

/// The recovery files in `dir` left by windows that no longer run, the newest first.
/// Files that do not read as a model are left where they are.
pub fn orphans(dir: &Path) -> Vec<Orphan> {
    scan(dir, true)
}

/// Every recovery file in `dir`, this process' own and running windows' included.
#[cfg(test)]
pub fn orphans_including_running(dir: &Path) -> Vec<Orphan> {
    scan(dir, false)
}

/// The recovery files in `dir` that read as a model, the newest first; with
/// `skip_running`, not those of running processes.
fn scan(dir: &Path, skip_running: bool) -> Vec<Orphan> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut found: Vec<(std::time::SystemTime, Orphan)> = entries
        .flatten()
        .filter_map(|e| {
            let file = e.path();
            let pid: u32 = file.file_stem()?.to_str()?.parse().ok()?;
            if file.extension()? != "toml" || (skip_running && running(pid)) {
                return None;
            }
            let text = std::fs::read_to_string(&file).ok()?;
            let model = parse_model(&text, &file.display().to_string()).ok()?;
            let path = text
                .lines()
                .next()
                .and_then(|l| l.strip_prefix(HEADER))
                .filter(|p| !p.is_empty())
                .map(PathBuf::from);
            let modified = e.metadata().and_then(|m| m.modified()).ok()?;
            Some((modified, Orphan { file, model, path }))
        })
        .collect();
    found.sort_by_key(|f| std::cmp::Reverse(f.0));
    found.into_iter().map(|(_, o)| o).collect()
}

/// The text of a recovery file: the header with `path`, then the model file.
fn file_text(model: &Model, path: Option<&Path>) -> String {
    let path = path.map(|p| p.display().to_string()).unwrap_or_default();
    format!("{HEADER}{path}\n{}", torsim::model::to_toml_string(model))
}

/// Once per frame: writes unsaved edits [`AUTOSAVE_AFTER`] after a change (asking for
/// one repaint then, so an idle window stays idle), takes the outcome of a write, and
/// removes the file once the model is clean.
pub fn tick(app: &mut TorsimApp, ctx: &egui::Context) {
    if let Some((revision, pending)) = &app.recovery.writing
        && let Some(outcome) = pending.poll()
    {
        let revision = *revision;
        app.recovery.writing = None;
        let outcome = outcome.unwrap_or_else(|_| Err("the autosave thread ended".into()));
        match outcome {
            Ok(()) => {
                app.recovery.written = Some(revision);
                if let Some(old) = app.recovery.adopted.take() {
                    let _ = std::fs::remove_file(old);
                }
            }
            Err(e) => app.status = format!("could not autosave the unsaved edits: {e}"),
        }
    }
    if app.recovery.writing.is_some() {
        return;
    }
    if !app.dirty {
        if app.recovery.written.is_some() {
            discard(app);
        }
        return;
    }
    let Some(file) = app.recovery.file.clone() else {
        return;
    };
    if app.recovery.written == Some(app.revision) {
        return;
    }
    let since = *app.recovery.pending_since.get_or_insert_with(Instant::now);
    let waited = since.elapsed();
    if waited < AUTOSAVE_AFTER {
        ctx.request_repaint_after(AUTOSAVE_AFTER - waited);
        return;
    }
    app.recovery.pending_since = None;
    let text = file_text(&app.model, app.path.as_deref());
    let spawned = background::spawn("torsim-autosave", ctx, move || {
        file.parent()
            .map_or(Ok(()), std::fs::create_dir_all)
            .and_then(|()| torsim::files::write_atomic(&file, text))
            .map_err(|e| format!("{}: {e}", file.display()))
    });
    match spawned {
        Ok(pending) => app.recovery.writing = Some((app.revision, pending)),
        Err(e) => app.status = format!("could not autosave the unsaved edits: {e}"),
    }
}

/// The model is clean or its edits were let go: this window's file goes.
pub fn discard(app: &mut TorsimApp) {
    app.recovery.pending_since = None;
    if app.recovery.written.take().is_some()
        && let Some(file) = &app.recovery.file
    {
        let _ = std::fs::remove_file(file);
    }
}

/// True when the File menu can offer edits of an ended window.
pub fn can_recover(app: &TorsimApp) -> bool {
    !app.recovery.orphans.is_empty()
}

/// File → Recover unsaved edits…: the newest orphan becomes the model (asking first
/// when this window has unsaved edits), unsaved, and its file goes once this window's
/// autosave holds it.
pub fn recover(app: &mut TorsimApp) {
    if app.recovery.orphans.is_empty() {
        return;
    }
    let orphan = app.recovery.orphans.remove(0);
    let status = format!(
        "recovered the unsaved edits of “{}” from a window that ended without saving",
        orphan.model.name
    );
    crate::gui::unsaved::replace_or_ask_recovered(app, orphan, status);
}

/// The model just shown came from `file`, an ended window's recovery file: it is
/// unsaved, due for this window's autosave, and `file` goes once that is written.
pub fn adopt(app: &mut TorsimApp, file: PathBuf) {
    app.dirty = true;
    app.revision += 1;
    app.recovery.adopted = Some(file);
}
