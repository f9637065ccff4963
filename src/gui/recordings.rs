//! Recordings in the window: File → Open recording… asks for a CSV on a background thread
//! (rfd, so the window never freezes); the path goes to the simulation thread with the
//! next request, which reads and analyses it ([`crate::gui::session::recording_job`]) and simulates its
//! regime; the traces tab overlays the two. Its stations are marked in the schematic.

use crate::gui::app::{Tab, TorsimApp};
use crate::gui::background;
use crate::gui::trace_state::{TraceMode, TraceView};
use std::path::PathBuf;

/// Opens the file dialog on its own thread; the answer is taken by [`poll`].
pub fn open_dialog(app: &mut TorsimApp, ctx: &egui::Context) {
    let spawned = background::spawn("torsim-recording-dialog", ctx, || {
        rfd::FileDialog::new()
            .set_title("Open recording")
            .add_filter("recording (CSV with a .toml sidecar)", &["csv"])
            .pick_file()
    });
    match spawned {
        Ok(pending) => app.traces.dialog = Some(pending),
        Err(e) => app.status = format!("cannot open the file dialog: {e}"),
    }
}

/// Takes the dialog's answer, if there is one.
pub fn poll(app: &mut TorsimApp) {
    if let Some(Ok(Some(path))) = background::take(&mut app.traces.dialog) {
        open_recording(app, path);
    }
}

/// Opens the recording at `path` (a CSV with its `.toml` sidecar): it is read and
/// analysed on the simulation thread, and the time run follows its regime.
pub fn open_recording(app: &mut TorsimApp, path: PathBuf) {
    app.traces.recording = Some(path);
    app.traces.mode = TraceMode::Recording;
    app.results.recording = None;
    app.stations.clear();
    app.tab = Tab::Traces;
    if app.traces.view == TraceView::Spectrogram {
        app.traces.view = TraceView::Traces;
    }
    app.request();
}

/// Closes the recording; the time run goes back to a steady run.
pub fn close_recording(app: &mut TorsimApp) {
    app.traces.recording = None;
    app.results.recording = None;
    app.stations.clear();
    if app.traces.mode == TraceMode::Recording {
        app.traces.mode = TraceMode::Steady;
    }
    app.traces.measured_stft = false;
    app.request();
}
