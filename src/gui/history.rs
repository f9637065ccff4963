//! The edit history of the window (issue 16): every change a view asks for arrives as a
//! [`Command`] and is applied here at the end of the frame; an edit is one undo step
//! (a drag or typing in a field is one gesture), marks the model unsaved, moves the
//! autosave's revision and requests new results.

use crate::gui::app::TorsimApp;
use crate::gui::command::Command;
use torsim::model::Model;

impl TorsimApp {
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
}
