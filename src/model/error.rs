//! Errors from reading and validating a model: they name the file, the line and the key.

use std::fmt;

/// A model that cannot be used, with where and why.
///
/// `Display` gives `file:line: key: message`, leaving out what is unknown (a model built
/// in the GUI has no file or line).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct ModelError {
    /// The model file, when the model came from one.
    pub file: Option<String>,
    /// 1-based line in that file, when known.
    pub line: Option<usize>,
    /// The key path, e.g. `connection[2].stiffness` (empty for the whole file).
    pub key: String,
    /// What is wrong, for a person.
    pub message: String,
}

impl ModelError {
    /// An error at a key path, without file or line (filled in by the reader).
    pub fn at(key: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            file: None,
            line: None,
            key: key.into(),
            message: message.into(),
        }
    }

    /// The same error, placed in a file.
    pub fn in_file(mut self, file: impl Into<String>) -> Self {
        self.file = Some(file.into());
        self
    }
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut wrote = false;
        if let Some(file) = &self.file {
            write!(f, "{file}")?;
            wrote = true;
        }
        if let Some(line) = self.line {
            write!(f, "{}line {line}", if wrote { ":" } else { "" })?;
            wrote = true;
        }
        if !self.key.is_empty() {
            write!(f, "{}key `{}`", if wrote { ": " } else { "" }, self.key)?;
            wrote = true;
        }
        write!(f, "{}{}", if wrote { ": " } else { "" }, self.message)
    }
}
