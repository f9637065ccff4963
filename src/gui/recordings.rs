//! Recordings in the window: File → Open recording… asks for a CSV on a background thread
//! (rfd, so the window never freezes); the path goes to the simulation thread with the
//! next request, which reads and analyses it ([`super::recording_job`]) and simulates its
//! regime; the traces tab overlays the two. Its stations are marked in the schematic.

use super::app::{Tab, TorsimApp};
use super::trace_state::{TraceMode, TraceView};
use crossbeam_channel::bounded;
use std::path::PathBuf;

/// Opens the file dialog on its own thread; the answer is taken by [`poll`].
pub fn open_dialog(app: &mut TorsimApp, ctx: &egui::Context) {
    let (tx, rx) = bounded(1);
    let ctx = ctx.clone();
    let spawned = std::thread::Builder::new()
        .name("torsim-recording-dialog".into())
        .spawn(move || {
            let path = rfd::FileDialog::new()
                .set_title("Open recording")
                .add_filter("recording (CSV with a .toml sidecar)", &["csv"])
                .pick_file();
            let _ = tx.send(path);
            ctx.request_repaint();
        });
    match spawned {
        Ok(_) => app.traces.dialog = Some(rx),
        Err(e) => app.status = format!("cannot open the file dialog: {e}"),
    }
}

/// Takes the dialog's answer, if there is one.
pub fn poll(app: &mut TorsimApp) {
    let Some(rx) = &app.traces.dialog else {
        return;
    };
    if let Ok(answer) = rx.try_recv() {
        app.traces.dialog = None;
        if let Some(path) = answer {
            open_recording(app, path);
        }
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
