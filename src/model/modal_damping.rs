//! `[modal_damping]`: damping given as a ratio of critical per mode, as OpenTorsion and
//! DyRoBeS users give it (issue 15, item 4), instead of (or beside) dampers on nodes and
//! shafts:
//!
//! ```toml
//! [modal_damping]
//! zeta = 0.02                # every flexible mode
//! # zeta = [0.02, 0.015]     # mode 1, mode 2; modes above the list get none
//! ```
//!
//! The physics builds from it the damping matrix `C = M·Φ·diag(2ζ_r·ω_r)·Φᵀ·M` over the
//! model's undamped flexible modes (mass-normalised shapes Φ, `Φᵀ·M·Φ = I`), added to the
//! dampers' matrix in every analysis ([`crate::physics::modal_damping`]). Rigid-body modes
//! get none.

use super::error::ModelError;
use super::spanned::{Tab, item_f64, item_f64s};

/// Modal damping ratios (fractions of critical, 0 ≤ ζ < 1).
#[derive(Debug, Clone, PartialEq)]
pub enum ModalDamping {
    /// One ζ for every flexible mode.
    All(f64),
    /// ζ of flexible modes 1, 2, … in ascending frequency; modes above the list get 0.
    PerMode(Vec<f64>),
}

impl ModalDamping {
    /// ζ of flexible mode `index` (0-based, ascending frequency).
    pub fn zeta_of(&self, index: usize) -> f64 {
        match self {
            Self::All(z) => *z,
            Self::PerMode(list) => list.get(index).copied().unwrap_or(0.0),
        }
    }

    /// Every ζ written in the file, with its key path (`modal_damping.zeta[1]`).
    fn values(&self) -> Vec<(String, f64)> {
        match self {
            Self::All(z) => vec![("modal_damping.zeta".to_string(), *z)],
            Self::PerMode(list) => list
                .iter()
                .enumerate()
                .map(|(i, z)| (format!("modal_damping.zeta[{i}]"), *z))
                .collect(),
        }
    }
}

/// Reads `[modal_damping]`: `zeta`, a number or a non-empty list of numbers.
pub(super) fn read(t: &Tab) -> Result<ModalDamping, ModelError> {
    t.allow(&["zeta"])?;
    let item = t.req("zeta")?;
    let key = t.key("zeta");
    if item.is_array() {
        let list = item_f64s(item, &key)?;
        if list.is_empty() {
            return Err(ModelError::at(
                &key,
                "an empty list: give ζ per mode, or one number for all",
            ));
        }
        Ok(ModalDamping::PerMode(list))
    } else {
        Ok(ModalDamping::All(item_f64(item, &key).map_err(|_| {
            ModelError::at(
                &key,
                "expected a number (ζ of every mode) or a list of numbers (ζ per mode)",
            )
        })?))
    }
}

/// Every ζ is finite, ≥ 0 and < 1 (a ratio of critical: 1 is no vibration at all).
pub(super) fn validate(damping: &ModalDamping) -> Result<(), ModelError> {
    for (key, z) in damping.values() {
        if !(z.is_finite() && (0.0..1.0).contains(&z)) {
            return Err(ModelError::at(
                &key,
                format!(
                    "ζ must be a ratio of critical damping, 0 ≤ ζ < 1 (0.02 is 2 %), found {z}"
                ),
            ));
        }
    }
    Ok(())
}

/// The `[modal_damping]` table as the writer prints it (numbers with `num`).
pub(super) fn write(out: &mut String, damping: &ModalDamping, num: impl Fn(f64) -> String) {
    out.push_str("\n[modal_damping]\n");
    let value = match damping {
        ModalDamping::All(z) => num(*z),
        ModalDamping::PerMode(list) => format!(
            "[{}]",
            list.iter().map(|z| num(*z)).collect::<Vec<_>>().join(", ")
        ),
    };
    out.push_str(&format!("zeta = {value}\n"));
}
