//! Involute spur-pair geometry: radii, path of contact, profile points; the helical pair's
//! transverse section, contact ratios and contact lines.

pub mod blank;
pub mod corner;
pub mod flank_shape;
pub mod helical;
pub mod internal;
pub mod involute;
pub mod iso1328;
pub mod pair;
pub mod planetary;
pub mod profile;

pub use pair::{Gear, GearPair, GeometryError};
pub use profile::ProfileGrid;

#[cfg(test)]
mod tests_planetary;
