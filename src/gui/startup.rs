//! What the window opens on, in this order: a model named on the command line (an ended
//! window's unsaved edits are then offered in the File menu), else the newest unsaved
//! edits of a window that ended without saving ([`crate::gui::recovery`]), else the last
//! session (eframe's store, unsaved edits included), else the default preset.

use crate::gui::app::{self, TorsimApp};
use crate::gui::recovery::{self, Orphan, Recovery};
use std::path::{Path, PathBuf};
use torsim::model::Model;

/// A model and the file it came from (`None`: a preset or a new model).
pub type Opened = (Model, Option<PathBuf>);

/// The last session's model, its file and whether it had unsaved edits, if stored.
pub fn last_session(
    storage: Option<&dyn eframe::Storage>,
) -> Option<(Model, Option<PathBuf>, bool)> {
    let storage = storage?;
    let text = storage.get_string(app::SESSION_MODEL)?;
    let model = torsim::model::parse_model(&text, "last session").ok()?;
    let path = storage
        .get_string(app::SESSION_PATH)
        .filter(|p| !p.is_empty())
        .map(PathBuf::from);
    let dirty = storage
        .get_string(app::SESSION_DIRTY)
        .is_some_and(|d| d == "true");
    Some((model, path, dirty))
}

/// The recent files of the last session.
pub fn recent_files(storage: Option<&dyn eframe::Storage>) -> Vec<PathBuf> {
    storage
        .and_then(|s| s.get_string(app::SESSION_RECENT))
        .map(|t| {
            t.lines()
                .filter(|l| !l.is_empty())
                .map(PathBuf::from)
                .collect()
        })
        .unwrap_or_default()
}

/// The window on `named` (the command line's model), else on what [`self`] says, with
/// its autosave in `dir` (`None`: off). `fallback` is the default preset's model.
pub fn open_app(
    named: Option<Opened>,
    fallback: Opened,
    session: Option<(Model, Option<PathBuf>, bool)>,
    dir: Option<&Path>,
    wake: impl Fn() + Send + 'static,
) -> TorsimApp {
    let mut orphans: Vec<Orphan> = dir.map(recovery::orphans).unwrap_or_default();
    let mut adopted = None;
    let (model, path, dirty, status) = match (named, orphans.is_empty()) {
        (Some((m, p)), true) => (m, p, false, String::new()),
        (Some((m, p)), false) => (
            m,
            p,
            false,
            "a window ended with unsaved edits: Recover unsaved edits… in the File menu brings them back"
                .into(),
        ),
        (None, false) => {
            let o = orphans.remove(0);
            let status = format!(
                "recovered the unsaved edits of “{}” from a window that ended without saving",
                o.model.name
            );
            adopted = Some(o.file);
            (o.model, o.path, true, status)
        }
        (None, true) => match session {
            Some((m, p, dirty)) => (m, p, dirty, "restored the last session".into()),
            None => (fallback.0, fallback.1, false, String::new()),
        },
    };
    let mut app = TorsimApp::new(model, path, wake);
    app.recovery = match dir {
        Some(dir) => Recovery::in_dir(dir, orphans),
        None => Recovery::default(),
    };
    app.dirty = dirty;
    app.status = status;
    match adopted {
        Some(file) => recovery::adopt(&mut app, file),
        None if dirty => app.revision += 1,
        None => {}
    }
    app
}
