//! Validation of a model (stub, being written).
use super::{Model, ModelError};

/// Checks a model for everything the file format requires.
pub fn validate(model: &Model) -> Result<(), ModelError> {
    super::graph::speed_ratios(model).map(|_| ())
}
