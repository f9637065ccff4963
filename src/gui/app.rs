//! The torsim window: the model being edited, the latest results, and the panels.
//! Edits go through [`TorsimApp::commit`], which keeps undo history, marks the model
//! unsaved and sends a new request to the simulation thread.

use super::views::{editor, plots};
use super::{export, files, recordings};
use crate::gui::session::recording_job::RecordingView;
use crate::gui::session::trace_data::LiveTrace;
use crate::gui::session::trace_job::RunAnalysis;
use crate::gui::session::worker::{Modal, PanelError, Payload, SimResult, Worker};
use crate::gui::trace_state::{self, TraceState};
use crate::gui::views::schematic::{self, Selection};
use std::path::PathBuf;
use std::sync::Arc;

use torsim::model::{Model, ModelError, validate};

use torsim::response::Response;
use torsim::transient::Simulation;

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

/// The latest results for the model on screen (the last good ones stay while an edit is
/// invalid or still computing).
#[derive(Default)]
pub struct Results {
    /// Generation of the last request.
    pub generation: u64,
    /// Modes, Campbell diagram and damped modes.
    pub campbell: Option<Arc<Modal>>,
    /// The request the Campbell diagram on screen answers.
    pub campbell_generation: u64,
    /// Forced response.
    pub response: Option<Arc<Response>>,
    /// The coupling ratings on that response, and the linear range.
    pub ratings: Option<Arc<crate::gui::session::worker::RatingsResult>>,
    /// The engine's working cycle at full load.
    pub engine_cycle: Option<Arc<torsim::physics::engine_cycle::EngineCycle>>,
    /// The finished time run.
    pub trace: Option<Arc<Simulation>>,
    /// Progress of the time run.
    pub trace_progress: f32,
    /// What the time run runs, for a person (`"run-up 1000 to 2000 rpm in 60 s"`).
    pub trace_label: String,
    /// The time run's samples as they arrive.
    pub live: Option<LiveTrace>,
    /// Orders and spectrograms of the finished time run.
    pub trace_analysis: Option<Arc<RunAnalysis>>,
    /// The open recording, read and analysed.
    pub recording: Option<Arc<RecordingView>>,
    /// Generation of the last time run cancelled.
    pub trace_cancelled: Option<u64>,
    /// Errors by panel.
    pub errors: Vec<PanelError>,
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
    gesture_start: Option<Model>,
    /// Results.
    pub results: Results,
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
    latency: crate::gui::latency::Latency,
    worker: Worker,
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
            results: Results::default(),
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

    /// Records a finished edit: `before` (or the start of the gesture it ends) goes on the
    /// undo stack, the model is unsaved, results are requested again. The tests' shortcut
    /// for an edit; the views send [`crate::gui::command::Command::Edit`].
    #[cfg(test)]
    pub fn commit(&mut self, before: Model) {
        self.commit_live(before, false);
    }

    /// Records an edit that may be part of a gesture: results are requested at once (so
    /// they follow a drag live), but while `in_progress` the undo step stays open, and the
    /// whole gesture becomes one step when it ends.
    pub fn commit_live(&mut self, before: Model, in_progress: bool) {
        if before != self.model {
            if self.gesture_start.is_none() {
                self.gesture_start = Some(before);
            }
            self.redo.clear();
            self.dirty = true;
            self.revision += 1;
            self.request();
            if self.invalid.is_none() {
                self.latency.edited(self.results.generation);
            }
        }
        if !in_progress {
            self.end_gesture();
        }
    }

    /// True while an edit gesture (a drag, typing in a field) is open.
    pub fn gesture_open(&self) -> bool {
        self.gesture_start.is_some()
    }

    /// Closes the gesture in progress, if any: one undo step when it changed the model.
    fn end_gesture(&mut self) {
        if let Some(start) = self.gesture_start.take()
            && start != self.model
        {
            self.undo.push(start);
        }
    }

    /// Undoes the last edit.
    pub fn undo(&mut self) {
        self.end_gesture();
        if let Some(previous) = self.undo.pop() {
            self.redo.push(std::mem::replace(&mut self.model, previous));
            self.dirty = true;
            self.revision += 1;
            self.request();
        }
    }

    /// Redoes the last undone edit.
    pub fn redo(&mut self) {
        self.end_gesture();
        if let Some(next) = self.redo.pop() {
            self.undo.push(std::mem::replace(&mut self.model, next));
            self.dirty = true;
            self.revision += 1;
            self.request();
        }
    }

    /// Applies what the views asked for this frame, in order; the window draws the
    /// outcome in the next frame, which this asks for.
    pub fn apply_commands(&mut self, ctx: &egui::Context) {
        use crate::gui::command::Command;
        let commands = self.commands.take();
        if !commands.is_empty() {
            ctx.request_repaint();
        }
        for command in commands {
            match command {
                Command::Edit { model, in_progress } => {
                    let before = std::mem::replace(&mut self.model, *model);
                    self.commit_live(before, in_progress);
                }
                Command::EndGesture => self.end_gesture(),
                Command::Undo => self.undo(),
                Command::Redo => self.redo(),
                Command::Select(selection) => self.selected = selection,
                Command::ShowTab(tab) => self.tab = tab,
                Command::Rerun => self.request(),
                Command::CancelTrace => self.cancel_trace(),
            }
        }
    }

    /// Takes every result the worker sent; stale ones are dropped.
    pub fn receive(&mut self) {
        while let Ok(SimResult {
            generation,
            payload,
        }) = self.worker.results.try_recv()
        {
            if let Payload::Cancelled = payload {
                self.results.trace_cancelled = Some(generation);
                continue;
            }
            if generation != self.results.generation {
                continue;
            }
            match payload {
                Payload::Modal(c) => {
                    self.results.campbell = Some(c);
                    self.results.campbell_generation = generation;
                    self.latency.arrived(generation);
                }
                Payload::Response(r) => self.results.response = Some(r),
                Payload::Ratings(r) => self.results.ratings = Some(r),
                Payload::EngineCycle(c) => self.results.engine_cycle = Some(c),
                Payload::Trace(t) => {
                    self.results.trace = Some(t);
                    self.results.trace_progress = 1.0;
                }
                Payload::Progress(p) => self.results.trace_progress = p,
                Payload::Error(e) => self.results.errors.push(e),
                other => trace_state::receive(self, generation, other),
            }
        }
    }

    /// The error of a panel, if any.
    pub fn error_of(&self, panel: &str) -> Option<&str> {
        self.results
            .errors
            .iter()
            .find(|e| e.panel == panel)
            .map(|e| e.message.as_str())
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
