//! Archard wear of the pinion and gear profiles (paper section 3, eq. 14-17), the
//! transmission error it causes, and the roughness that goes with it.

pub mod archard;
pub mod per_tooth;
pub mod profile_wear;
pub mod roughness;
pub(crate) mod tooth_wear;

pub use archard::{per_cycle_wear, WearIncrement};
pub use profile_wear::WearState;
pub use roughness::RoughnessLaw;
pub use tooth_wear::{SliceWear, ToothWear};
