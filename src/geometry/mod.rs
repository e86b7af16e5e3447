//! Involute spur-pair geometry: radii, path of contact, profile points.

pub mod blank;
pub mod flank_shape;
pub mod involute;
pub mod iso1328;
pub mod pair;
pub mod profile;

pub use pair::{Gear, GearPair, GeometryError};
pub use profile::ProfileGrid;
