//! The linear driveline at an operating point: assembly of M, K(f) (complex; rubber as one
//! causal chain, [`one_law`]; shafts with inertia as exact elements, [`distributed`]), C,
//! referred to the engine shaft through the gear tree
//! ([`system`]); the static
//! twist of the rubber stages under the mean torque ([`static_twist`]); the engine torque
//! of seed 001 eq. 3–5 and its harmonics per order ([`engine`], [`excitation`]).

pub(crate) mod dead_zone;
pub mod distributed;
pub mod element;
pub mod engine;
pub mod engine_cycle;
pub mod error;
pub mod excitation;
pub mod matrices;
pub mod modal_damping;
mod one_law;
pub mod static_twist;
pub mod system;
pub mod tooth_contact;
mod topology;

pub use distributed::DistributedShaft;
pub use element::{Element, ElementLaw};
pub use error::PhysicsError;
pub use excitation::Excitation;
pub use system::{OperatingPoint, System};
