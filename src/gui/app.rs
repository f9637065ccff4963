//! The torsim window: the model being edited, the latest results ([`crate::gui::results`]),
//! and the panels. The views change the model through commands, which the edit history
//! applies ([`crate::gui::history`]): undo, the unsaved mark, a new request to the
//! simulation thread.

use super::views::{editor, plots};
use super::{export, files, recordings};
use crate::gui::session::worker::Worker;
use crate::gui::trace_state::{self, TraceState};
use crate::gui::views::schematic::{self, Selection};
use std::path::PathBuf;

use torsim::model::{Model, ModelError, validate};

/// The plot shown in the central panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tab {
    /// Modes over speed with order lines.
    Campbell,
    /// Mode shapes along the driveline.
    Modes,
    /// Forced response over speed.
    Response,
    /// Time traces of a steady run or a run-up, recordings.
    Traces,
    /// Diagnosis of bench recordings against the model.
    Diagnosis,
}

/// The application.
pub struct TorsimApp {
    /// The model being edited.
    pub model: Model,
    /// Where it came from / is saved to.
    pub path: Option<PathBuf>,
    /// True when there are unsaved edits.
    pub dirty: bool,
    /// Earlier versions (undo) and undone ones (redo).
    pub undo: Vec<Model>,
    /// Undone versions.
    pub redo: Vec<Model>,
    /// The model's validation error, if any (results are not requested then).
    pub invalid: Option<String>,
    /// The same error with its key path, which the editor marks.
    pub invalid_error: Option<ModelError>,
    /// The element selected in the schematic or the editor.
    pub selected: Option<Selection>,
    /// What the views asked for this frame, applied at its end ([`Self::apply_commands`]).
    pub commands: crate::gui::command::Commands,
    /// Nodes with a measurement station (from loaded recordings), marked in the schematic.
    pub stations: Vec<String>,
    /// The model before the edit gesture in progress (a drag, or typing in a field that
    /// still has focus): the whole gesture becomes one undo step when it ends.
    pub(crate) gesture_start: Option<Model>,
    /// Results.
    pub results: crate::gui::results::Results,
    /// Central tab.
    pub tab: Tab,
    /// Mode selected for the mode-shape view (0-based).
    pub selected_mode: usize,
    /// What the plots show: selected crossing, response quantity, animation.
    pub plots: plots::PlotState,
    /// Exports in progress (CSV, PNG).
    pub exports: export::Exports,
    /// Speed of the steady time run, rpm.
    pub trace_speed_rpm: f64,
    /// The traces tab: run-up settings, the open recording, the view.
    pub traces: TraceState,
    /// A status line (file saved, errors of file dialogs).
    pub status: String,
    /// Pending file dialog results.
    pub files: files::FileDialogs,
    /// Unsaved edits about to be discarded (another model, or closing): the question.
    pub unsaved: Option<crate::gui::unsaved::Prompt>,
    /// The user chose to discard unsaved edits and close.
    pub close_confirmed: bool,
    /// Recently opened or saved model files, the latest first.
    pub recent: Vec<PathBuf>,
    /// The autosave of unsaved edits ([`crate::gui::recovery`]).
    pub recovery: crate::gui::recovery::Recovery,
    /// Counts the model's changes (edits, undo, redo, another model); the autosave
    /// writes when it moves.
    pub revision: u64,
    /// A save or export that would replace an open file, waiting for the user's answer.
    pub confirm: Option<crate::gui::overwrite::Confirm>,
    /// The diagnosis tab: recordings, the run, the report.
    pub diagnosis: crate::gui::views::diagnosis::DiagnosisState,
    /// The title last sent to the window (sent again only when it changes).
    shown_title: Option<String>,
    /// Edit-to-plot latency, logged when asked for ([`crate::gui::latency`]).
    pub(crate) latency: crate::gui::latency::Latency,
    pub(crate) worker: Worker,
}

impl TorsimApp {
    /// A window on `model` (from `path`, if it came from a file); `wake` repaints.
    pub fn new(model: Model, path: Option<PathBuf>, wake: impl Fn() + Send + 'static) -> Self {
        let trace_speed_rpm = default_trace_speed_rpm(&model);
        let mut app = Self {
            model,
            path,
            dirty: false,
            undo: Vec::new(),
            redo: Vec::new(),
            invalid: None,
            invalid_error: None,
            selected: None,
            commands: Default::default(),
            stations: Vec::new(),
            gesture_start: None,
            results: Default::default(),
            tab: Tab::Campbell,
            selected_mode: 0,
            plots: plots::PlotState::default(),
            exports: export::Exports::default(),
            trace_speed_rpm,
            traces: TraceState::default(),
            status: String::new(),
            files: files::FileDialogs::default(),
            unsaved: None,
            close_confirmed: false,
            recent: Vec::new(),
            recovery: crate::gui::recovery::Recovery::default(),
            revision: 0,
            confirm: None,
            diagnosis: Default::default(),
            shown_title: None,
            latency: crate::gui::latency::Latency::from_env(),
            worker: Worker::start(wake),
        };
        app.request();
        app
    }

    /// Validates the model and, when valid, asks the worker for new results.
    pub fn request(&mut self) {
        match validate(&self.model) {
            Ok(()) => {
                self.invalid = None;
                self.invalid_error = None;
                self.results.generation += 1;
                self.results.errors.clear();
                let spec = self.traces.spec(&self.model, self.trace_speed_rpm);
                self.results.trace_progress = 0.0;
                self.results.trace_label = trace_state::pending_label(&spec);
                self.worker.request(
                    self.results.generation,
                    &self.model,
                    spec,
                    self.traces.recording.clone(),
                    self.stations.clone(),
                );
            }
            Err(e) => {
                self.invalid = Some(e.to_string());
                self.invalid_error = Some(e);
            }
        }
    }

    /// Stops the running time run; the other results stay.
    pub fn cancel_trace(&self) {
        self.worker.cancel(self.results.generation);
    }

    /// The window title: model name, file, unsaved mark.
    pub fn title(&self) -> String {
        let file = self
            .path
            .as_ref()
            .map_or("(unsaved preset)".into(), |p| p.display().to_string());
        format!(
            "torsim — {} — {file}{}",
            self.model.name,
            if self.dirty { " •" } else { "" }
        )
    }
}

/// Storage keys of the last session.
pub const SESSION_MODEL: &str = "torsim.model_toml";
/// Storage key of the last session's file path.
pub const SESSION_PATH: &str = "torsim.model_path";
/// Storage key: the last session had unsaved edits.
pub const SESSION_DIRTY: &str = "torsim.dirty";
/// Storage key of the recent files, one path per line.
pub const SESSION_RECENT: &str = "torsim.recent";

/// The speed of a steady time run on a new model, rpm: the middle of the operating
/// range, else of the speed range, else 1500.
pub fn default_trace_speed_rpm(model: &Model) -> f64 {
    model
        .operation
        .operating_range_rpm
        .or(model.operation.speed_range_rpm)
        .map_or(1500.0, |[a, b]| 0.5 * (a + b))
}

impl eframe::App for TorsimApp {
    /// The model as it stands (saved or not) is kept for the next start.
    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        storage.set_string(SESSION_MODEL, torsim::model::to_toml_string(&self.model));
        storage.set_string(
            SESSION_PATH,
            self.path
                .as_ref()
                .map(|p| p.display().to_string())
                .unwrap_or_default(),
        );
        storage.set_string(SESSION_DIRTY, self.dirty.to_string());
        let recent: Vec<String> = self
            .recent
            .iter()
            .map(|p| p.display().to_string())
            .collect();
        storage.set_string(SESSION_RECENT, recent.join("\n"));
    }

    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.latency.frame();
        crate::gui::unsaved::close_or_ask(self, ui.ctx());
        self.receive();
        files::poll(self, ui.ctx());
        export::poll(self, ui.ctx());
        recordings::poll(self);
        self.diagnosis.poll();
        crate::gui::overwrite::ui(self, ui.ctx());
        crate::gui::unsaved::ui(self, ui.ctx());
        crate::gui::recovery::tick(self, ui.ctx());
        // A viewport command repaints the window: sent on every frame, the title kept an
        // idle window redrawing at full rate (issue 16: 183 % of two cores measured).
        let title = self.title();
        if self.shown_title.as_deref() != Some(title.as_str()) {
            ui.ctx()
                .send_viewport_cmd(egui::ViewportCommand::Title(title.clone()));
            self.shown_title = Some(title);
        }
        let undo = egui::KeyboardShortcut::new(egui::Modifiers::COMMAND, egui::Key::Z);
        let redo = egui::KeyboardShortcut::new(
            egui::Modifiers::COMMAND | egui::Modifiers::SHIFT,
            egui::Key::Z,
        );
        if ui.ctx().input_mut(|i| i.consume_shortcut(&redo)) {
            self.redo();
        } else if ui.ctx().input_mut(|i| i.consume_shortcut(&undo)) {
            self.undo();
        }
        egui::Panel::top("menu").show(ui, |ui| files::menu_ui(self, ui));
        egui::Panel::bottom("status").show(ui, |ui| {
            ui.horizontal(|ui| {
                if let Some(e) = &self.invalid {
                    ui.colored_label(
                        ui.visuals().error_fg_color,
                        format!("Invalid model: {e} — showing the last good results"),
                    );
                } else {
                    ui.label(&self.status);
                }
            });
        });
        let strip = schematic::strip_height(&self.model, 0.4 * ui.available_height());
        egui::Panel::top("schematic")
            .exact_size(strip)
            .show(ui, |ui| schematic::schematic_ui(self, ui));
        egui::Panel::left("driveline")
            .resizable(true)
            .default_size(360.0)
            .show(ui, |ui| editor::driveline_ui(self, ui));
        egui::CentralPanel::default().show(ui, |ui| plots::central_ui(self, ui));
        self.apply_commands(ui.ctx());
        if self.tab == Tab::Campbell && self.results.campbell.is_some() {
            self.latency.drawn(self.results.campbell_generation);
        }
    }
}
