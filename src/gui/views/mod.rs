//! What the window draws, on the GUI thread: the driveline panel ([`editor`]), the
//! schematic ([`schematic`]), the plots of each tab ([`plots`], drawn cheaply through
//! [`decimate`]), the diagnosis tab ([`diagnosis`]) and each tab's "?" text ([`help`]).
//! A view reads the app's model and results and changes the model only through the app
//! (an edit is one undo step, [`crate::gui::app::TorsimApp::commit`]); it never computes
//! more than a frame needs: the results come from [`crate::gui::session`].

pub mod decimate;
pub mod diagnosis;
pub mod editor;
pub mod help;
pub mod plots;
pub mod schematic;
