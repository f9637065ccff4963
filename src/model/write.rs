//! Writing model files (stub, being written).
use super::Model;
use std::path::Path;

/// The model as model-file text.
pub fn to_toml_string(_model: &Model) -> String {
    String::new()
}

/// Writes the model file atomically.
pub fn save_model_file(model: &Model, path: &Path) -> std::io::Result<()> {
    std::fs::write(path, to_toml_string(model))
}
