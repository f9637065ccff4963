//! What a view asks of the app (issue 16, item 8, in the way of rerun's `SystemCommand`):
//! a view reads the model and the results, keeps its own view state, and changes the
//! model, the selection, the tab or the runs only by pushing a [`Command`]. The app
//! applies them at the end of the frame ([`crate::gui::app::TorsimApp::apply_commands`]),
//! so every change to the model goes through one place: the undo stack, the unsaved
//! mark, the autosave and the request for new results.

use crate::gui::app::Tab;
use crate::gui::views::schematic::Selection;
use torsim::model::Model;

/// A change a view asks for.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// The model as edited this frame. While `in_progress` (a drag, a field being typed
    /// in) the gesture stays one open undo step; results are requested at once either way.
    Edit {
        /// The edited model.
        model: Box<Model>,
        /// True while the gesture goes on.
        in_progress: bool,
    },
    /// The gesture in progress, if any, ended without a further change.
    EndGesture,
    /// Undo the last edit.
    Undo,
    /// Redo the last undone edit.
    Redo,
    /// Select an element (schematic and driveline panel), or nothing.
    Select(Option<Selection>),
    /// Show a tab.
    ShowTab(Tab),
    /// Compute the results again (the time run's settings changed, or Run again).
    Rerun,
    /// Stop the running time run; the other results stay.
    CancelTrace,
}

/// The commands of one frame, in the order the views pushed them.
#[derive(Debug, Default)]
pub struct Commands {
    queue: Vec<Command>,
}

impl Commands {
    /// Asks for `command` at the end of the frame.
    pub fn push(&mut self, command: Command) {
        self.queue.push(command);
    }

    /// Takes every command pushed so far, oldest first.
    pub fn take(&mut self) -> Vec<Command> {
        std::mem::take(&mut self.queue)
    }
}
