//! The diagnosis tab (`spec/diagnosis.md`): load bench recordings, run
//! `torsim::diagnose::diagnose` off the GUI thread with progress and Cancel, and see what
//! it found — the verdict, the mismatch map, the candidates and the before/after plots —
//! then accept the verdict into the model (one undo step) or save the report as HTML.
//!
//! - [`state`]: what the tab holds; [`load`]: adding recordings; [`save`]: the HTML
//!   page. The diagnosis thread and the finished report it builds are in
//!   [`crate::gui::session::diagnosis`].
//! - [`panel`]: the tab; [`verdict`], [`map`], [`candidates`], [`overlays`]: its parts.

pub mod candidates;
pub mod load;
pub mod map;
pub mod overlays;
pub mod panel;
pub mod save;
pub mod state;
pub mod verdict;

pub use panel::diagnosis_ui;
pub use state::DiagnosisState;
