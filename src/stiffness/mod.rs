//! Mesh stiffness: potential energy method (bending, shear, axial, Hertz, fillet
//! foundation), the single-pair stiffness along the path of contact, the mesh-period
//! table, the helical pair's slice model, and the ISO 6336-1 Method B cross-check.

pub mod face_load;
pub mod fillet;
pub mod helical;
pub mod helical_lead;
pub mod internal;
pub mod iso6336;
pub mod mesh;
pub mod planetary_mesh;
pub mod potential_energy;
pub mod ring_tooth_faults;
pub mod tooth_faults;
pub mod worn_tooth;

#[cfg(test)]
mod tests_internal;
#[cfg(test)]
pub(crate) mod tests_planetary_mesh;
