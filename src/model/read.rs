//! Reading model files (stub, being written).
use super::{Model, ModelError};
use std::path::Path;

/// Parses and validates a model file's text; `file` names it in errors.
pub fn parse_model(_text: &str, file: &str) -> Result<Model, ModelError> {
    Err(ModelError::at("", "reader not written yet").in_file(file))
}

/// Reads, parses and validates a model file.
pub fn read_model_file(path: &Path) -> Result<Model, ModelError> {
    let text = std::fs::read_to_string(path).map_err(|e| {
        ModelError::at("", format!("cannot read: {e}")).in_file(path.display().to_string())
    })?;
    parse_model(&text, &path.display().to_string())
}
