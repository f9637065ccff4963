//! Where a model comes from: a model file, or `preset:NAME` for a preset shipped in the
//! binary. The one place that resolves such an argument, for the CLI's commands and the
//! window alike (issue 16, item 8: the window no longer borrows it from the CLI).

use super::presets::{PRESETS, preset};
use super::{Model, ModelError, parse_model, read_model_file};
use std::path::{Path, PathBuf};

/// Prefix naming a shipped preset instead of a file: `preset:cng-genset`.
pub const PRESET_PREFIX: &str = "preset:";

/// A model and the file it was read from (`None` for a preset, which has no file to save
/// back to).
#[derive(Debug, Clone, PartialEq)]
pub struct Sourced {
    /// The model, read and validated.
    pub model: Model,
    /// The model file, when the argument named one.
    pub path: Option<PathBuf>,
}

/// Whether `arg` names a shipped preset (`preset:NAME`) rather than a file.
pub fn is_preset(arg: &str) -> bool {
    arg.starts_with(PRESET_PREFIX)
}

/// Reads the model `arg` names: a file path, or `preset:NAME`. An unknown preset's error
/// lists the shipped ones; a file's error names file, line and key.
pub fn load_model(arg: &str) -> Result<Sourced, ModelError> {
    if let Some(name) = arg.strip_prefix(PRESET_PREFIX) {
        let Some(found) = preset(name) else {
            let names: Vec<&str> = PRESETS.iter().map(|p| p.name).collect();
            return Err(ModelError::at(
                "",
                format!("no preset `{name}`; shipped presets: {}", names.join(", ")),
            )
            .in_file(arg));
        };
        let model = parse_model(found.text, arg)?;
        return Ok(Sourced { model, path: None });
    }
    let path = Path::new(arg);
    Ok(Sourced {
        model: read_model_file(path)?,
        path: Some(path.to_path_buf()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_and_files_resolve() {
        let sourced = load_model("preset:two-inertia").expect("a shipped preset");
        assert_eq!(sourced.path, None);
        assert_eq!(sourced.model.inertias.len(), 2);

        let e = load_model("preset:no-such").expect_err("unknown preset");
        assert!(e.to_string().contains("two-inertia"), "{e}");

        let file = concat!(env!("CARGO_MANIFEST_DIR"), "/presets/two-inertia.toml");
        let sourced = load_model(file).expect("the same preset as a file");
        assert_eq!(sourced.path.as_deref(), Some(Path::new(file)));
        assert!(load_model("/no/such/model.toml").is_err());
    }
}
