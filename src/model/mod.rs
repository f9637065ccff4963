//! The driveline model: its data ([`types`]), reading and writing model files
//! ([`read`], [`write`]), validation with errors that name file, line and key
//! ([`validate`], [`error`]), the gear tree ([`graph`]), the rubber coupling law of
//! seed 000 ([`rubber`]) and the presets shipped in the binary ([`presets`]).

pub mod amplitude_form;
pub mod amplitude_saturation;
pub mod engine_types;
pub mod error;
pub mod frequency_law;
pub mod frequency_zener;
pub mod graph;
mod key_lines;
pub mod modal_damping;
pub mod names;
pub mod operation_types;
pub mod presets;
pub mod rating;
pub mod read;
mod read_sections;
pub mod rubber;
pub mod source;
mod spanned;
pub mod types;
pub mod validate;
mod validate_engine;
pub mod validate_scale;
pub mod write;

pub use amplitude_form::AmplitudeForm;
pub use amplitude_saturation::AmplitudeSaturation;
pub use engine_types::*;
pub use error::ModelError;
pub use frequency_law::PowerLaw;
pub use frequency_zener::ZenerLaw;
pub use modal_damping::ModalDamping;
pub use operation_types::*;
pub use rating::CouplingRating;
pub use read::{parse_model, read_model_file};
pub use source::{PRESET_PREFIX, Sourced, is_preset, load_model};
pub use types::*;
pub use validate::{MAX_SEGMENTS, validate};
pub use write::{save_model_file, to_toml_string};
