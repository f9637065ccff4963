//! The window's tests (egui_kittest on the real app): editing, plots, files, unsaved
//! edits and recovery, idleness, layout and image snapshots, ratings, teaching and the
//! diagnosis tab. [`support`] is what they share.

mod app;
mod diagnosis;
mod diagnosis_run;
mod edit;
mod edit_cases;
mod edit_structure;
mod idle;
mod layout;
mod modal_damping;
mod overwrite;
mod plots;
mod ratings;
mod recovery;
mod shaft;
mod snapshots;
mod support;
mod teaching;
mod traces;
mod unsaved;
