//! A diagnosis runs on its own thread (`torsim-diagnose`), as the simulation thread does
//! its work (`crate::gui::session::worker`): the GUI thread only starts it and takes its
//! messages. Each run has an id (its generation): messages of an older run are dropped.
//! The progress callback sends the fraction and stage, wakes the GUI
//! (`request_repaint`) and returns false once Cancel set the flag, which ends the run at
//! its next step. The verdict's model ([`Finished`]) is built on the thread too.

use crate::gui::background;
use crate::gui::session::diagnosis::finished::Finished;
use crossbeam_channel::Receiver;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use torsim::diagnose::{DiagnoseError, DiagnoseOptions, LabelledRecording, diagnose};
use torsim::model::Model;

/// What the diagnosis thread sends: an event of run `id`.
pub struct JobMessage {
    /// The run (messages of an older run are dropped).
    pub id: u64,
    /// What happened.
    pub event: JobEvent,
}

/// An event of a diagnosis run.
pub enum JobEvent {
    /// The run is at `fraction` (0–1) of `stage` (`"fitting gear_backlash at gearbox"`).
    Progress {
        /// Fraction done, 0–1.
        fraction: f64,
        /// The stage, for a person.
        stage: String,
    },
    /// The run ended: the report with its accepted model, or why not.
    Done(Result<Box<Finished>, DiagnoseError>),
}

/// A diagnosis in progress.
pub struct Job {
    /// Its id.
    pub id: u64,
    /// Fraction done, 0–1.
    pub fraction: f64,
    /// Stage, for a person.
    pub stage: String,
    /// Set by Cancel; the thread stops at its next step.
    cancel: Arc<AtomicBool>,
    /// Messages from the thread.
    messages: Receiver<JobMessage>,
}

impl Job {
    /// Starts diagnosing `recordings` against `model` on a new thread.
    pub fn start(
        id: u64,
        model: Model,
        recordings: Vec<LabelledRecording>,
        options: DiagnoseOptions,
        ctx: &egui::Context,
    ) -> Result<Self, String> {
        let cancel = Arc::new(AtomicBool::new(false));
        let flag = cancel.clone();
        let messages = background::spawn_stream("torsim-diagnose", ctx, move |sink| {
            let mut progress = |fraction: f64, stage: &str| {
                sink.send(JobMessage {
                    id,
                    event: JobEvent::Progress {
                        fraction,
                        stage: stage.to_string(),
                    },
                });
                !flag.load(Ordering::SeqCst)
            };
            let result = diagnose(&model, &recordings, &options, &mut progress)
                .map(|report| Box::new(Finished::new(model, report)));
            sink.send(JobMessage {
                id,
                event: JobEvent::Done(result),
            });
        })
        .map_err(|e| format!("cannot start the diagnosis: {e}"))?;
        Ok(Self {
            id,
            fraction: 0.0,
            stage: "starting".into(),
            cancel,
            messages,
        })
    }

    /// Asks the thread to stop at its next step.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::SeqCst);
    }

    /// True once Cancel was pressed.
    pub fn cancelling(&self) -> bool {
        self.cancel.load(Ordering::SeqCst)
    }

    /// Takes the thread's messages: progress updates this job, the end is returned
    /// (`Err(Cancelled)` also when the thread died without an answer).
    pub fn poll(&mut self) -> Option<Result<Box<Finished>, DiagnoseError>> {
        loop {
            match self.messages.try_recv() {
                Ok(JobMessage {
                    id,
                    event: JobEvent::Progress { fraction, stage },
                }) if id == self.id => {
                    self.fraction = fraction;
                    self.stage = stage;
                }
                Ok(JobMessage {
                    id,
                    event: JobEvent::Done(result),
                }) if id == self.id => return Some(result),
                Ok(_) => {}
                Err(crossbeam_channel::TryRecvError::Empty) => return None,
                Err(crossbeam_channel::TryRecvError::Disconnected) => {
                    return Some(Err(DiagnoseError::Input(
                        "the diagnosis thread ended without an answer".into(),
                    )));
                }
            }
        }
    }
}

impl Drop for Job {
    /// A window closed mid-run stops the thread at its next step (not waited for).
    fn drop(&mut self) {
        self.cancel();
    }
}
