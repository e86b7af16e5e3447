//! Contact mechanics: Hertz line contact, surface kinematics, friction, load sharing.

pub mod friction;
pub mod hertz;
pub mod kinematics;
pub mod load_sharing;
pub mod worn_curvature;
