//! The diagnosis's entry point (placeholder until the core is merged).

use super::{DiagnoseError, DiagnoseOptions, LabelledRecording, Report};
use crate::model::Model;

/// Diagnoses `model` against `recordings` (`spec/diagnosis.md`); `progress` gets the
/// fraction done (0–1) and the stage's name, and cancels by returning false.
pub fn diagnose(
    _model: &Model,
    _recordings: &[LabelledRecording],
    _options: &DiagnoseOptions,
    _progress: &mut dyn FnMut(f64, &str) -> bool,
) -> Result<Report, DiagnoseError> {
    Err(DiagnoseError::Input(
        "the diagnosis core is not merged yet".into(),
    ))
}
