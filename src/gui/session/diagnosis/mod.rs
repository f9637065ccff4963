//! The diagnosis off the GUI thread: [`job`] runs `torsim::diagnose::diagnose` on its own
//! thread with progress and Cancel; [`finished`] is the report with its accepted model,
//! built on that thread. The tab that starts it and shows it is
//! [`crate::gui::views::diagnosis`].

pub mod finished;
pub mod job;
