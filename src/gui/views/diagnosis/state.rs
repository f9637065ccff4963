//! What the diagnosis tab holds across frames: the recordings, the run in progress, the
//! finished report, and the file threads (adding recordings, saving the report).

use crate::gui::background::{self, Lost, Pending};
use crate::gui::session::diagnosis::finished::Finished;
use crate::gui::session::diagnosis::job::Job;
use crate::gui::views::diagnosis::load::{self, Loaded, LoadedRecording, Source};
use crate::gui::views::diagnosis::save::Saving;
use torsim::diagnose::{DiagnoseError, DiagnoseOptions, LabelledRecording};
use torsim::model::Model;

/// The diagnosis tab's state.
#[derive(Default)]
pub struct DiagnosisState {
    /// The recordings to diagnose, in the order added.
    pub recordings: Vec<LoadedRecording>,
    /// Files that could not be added, with file and line.
    pub load_errors: Vec<String>,
    /// A loading thread (dialog and reading).
    loading: Option<Pending<Loaded>>,
    /// Settings of the diagnosis (threads: the machine's cores, at most 8).
    pub options: DiagnoseOptions,
    /// The run in progress.
    pub job: Option<Job>,
    /// Id of the last run started.
    last_id: u64,
    /// The last finished diagnosis.
    pub finished: Option<Finished>,
    /// Why the last run ended without a report (`"cancelled"` included).
    pub error: Option<String>,
    /// The report being saved.
    pub saving: Option<Saving>,
    /// A report path chosen, to check against the open files and write
    /// ([`crate::gui::overwrite`]).
    pub pending_save: Option<(
        std::path::PathBuf,
        std::sync::Arc<torsim::diagnose::Report>,
        String,
    )>,
    /// The outcome of the last accept or save, for a person.
    pub message: String,
}

impl DiagnosisState {
    /// True while recordings are being picked or read.
    pub fn loading(&self) -> bool {
        self.loading.is_some()
    }

    /// Adds recordings from `source`, read against the nodes of `model` off the GUI
    /// thread.
    pub fn add(&mut self, source: Source, model: &Model, ctx: &egui::Context) {
        let nodes = model.inertias.iter().map(|n| n.name.clone()).collect();
        let have = self.recordings.iter().map(|r| r.path.clone()).collect();
        match load::start(source, nodes, have, ctx) {
            Ok(rx) => self.loading = Some(rx),
            Err(e) => self.load_errors = vec![e],
        }
    }

    /// Removes the `index`-th recording.
    pub fn remove(&mut self, index: usize) {
        if index < self.recordings.len() {
            self.recordings.remove(index);
            self.relabel();
        }
    }

    /// The labels the report shows: the one rule of the CLI
    /// ([`torsim::diagnose::labels::unique_labels`]), over the whole list.
    fn relabel(&mut self) {
        let own: Vec<String> = self
            .recordings
            .iter()
            .map(|r| r.own_label.clone())
            .collect();
        let paths: Vec<&std::path::Path> =
            self.recordings.iter().map(|r| r.path.as_path()).collect();
        let labels = torsim::diagnose::labels::unique_labels(&own, &paths);
        for (r, label) in self.recordings.iter_mut().zip(labels) {
            r.labelled.label = label;
        }
    }

    /// Starts diagnosing the recordings against `model` (a run in progress is cancelled).
    pub fn start(&mut self, model: &Model, ctx: &egui::Context) {
        if self.recordings.is_empty() {
            return;
        }
        self.last_id += 1;
        let recordings: Vec<LabelledRecording> =
            self.recordings.iter().map(|r| r.labelled.clone()).collect();
        self.error = None;
        self.message.clear();
        match Job::start(
            self.last_id,
            model.clone(),
            recordings,
            self.options.clone(),
            ctx,
        ) {
            Ok(job) => self.job = Some(job),
            Err(e) => self.error = Some(e),
        }
    }

    /// Another model is shown: the run in progress stops, and the recordings (read against
    /// the old model's nodes), the report and the messages go; the settings stay.
    pub fn clear_for_new_model(&mut self) {
        self.cancel();
        *self = Self {
            options: self.options.clone(),
            last_id: self.last_id,
            ..Default::default()
        };
    }

    /// Stops the run in progress, if any (its thread ends at its next step).
    pub fn cancel(&self) {
        if let Some(job) = &self.job {
            job.cancel();
        }
    }

    /// Shows `finished` as the latest diagnosis.
    pub fn show(&mut self, finished: Finished) {
        self.finished = Some(finished);
        self.error = None;
    }

    /// Takes what the threads sent.
    pub fn poll(&mut self) {
        match background::take(&mut self.loading) {
            Some(Ok((added, errors))) => {
                self.load_errors = errors;
                self.recordings.extend(added);
                self.relabel();
            }
            Some(Err(Lost)) => self.load_errors = vec!["reading the recordings failed".into()],
            None => {}
        }
        if let Some(result) = self.job.as_mut().and_then(Job::poll) {
            self.job = None;
            match result {
                Ok(finished) => self.show(*finished),
                Err(DiagnoseError::Cancelled) => self.error = Some("cancelled".into()),
                Err(e) => self.error = Some(e.to_string()),
            }
        }
        if let Some(outcome) = self.saving.as_mut().and_then(Saving::poll)
            && let Some(saving) = self.saving.take()
        {
            match outcome {
                Some(Ok(path)) => {
                    self.pending_save = Some((path, saving.report, saving.model_name));
                }
                Some(Err(e)) => self.message = e,
                None => {}
            }
        }
    }
}
