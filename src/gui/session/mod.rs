//! What runs off the GUI thread, without egui: the simulation thread ([`worker`], its
//! [`messages`] and its cheap results [`cheap_job`]) and
//! the jobs it runs for the window (the time run [`trace_job`] with its plot groups
//! [`trace_series`] and [`trace_data`], the recording [`recording_job`], the run-up
//! spectrograms [`spectrogram`], which use egui's image type only as data), and the
//! diagnosis thread ([`diagnosis`]). Their results are named types that the GUI thread
//! takes from a channel; nothing here draws.
//!
//! The GUI thread's side is the app ([`crate::gui::app`]) with its files, prompts and
//! autosave, and the views ([`crate::gui::views`]).

pub mod cheap_job;
pub mod diagnosis;
pub mod messages;
pub mod recording_job;
pub mod spectrogram;
pub mod trace_data;
pub mod trace_job;
pub mod trace_series;
pub mod worker;
