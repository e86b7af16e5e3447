//! Involute spur-pair geometry: radii, path of contact, profile points.

pub mod blank;
pub mod involute;
pub mod pair;
pub mod profile;

pub use pair::{Gear, GearPair, GeometryError};
pub use profile::ProfileGrid;
