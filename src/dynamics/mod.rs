//! The 8-DOF tribo-dynamic model (paper eq. 1-6), its integrator, steady state,
//! quasi-static twin, signals and modes.

pub mod assembly;
pub mod contact_path;
pub mod damped_modes;
pub mod drive;
pub mod excitation;
pub mod fourier;
pub mod grid;
pub mod hunting;
pub mod integrator;
pub mod modal;
pub mod model;
pub mod observer;
pub mod params;
pub mod period;
pub mod period_search;
pub mod planetary_dynamic;
mod planetary_grid;
pub mod planetary_lumped;
pub mod planetary_steady;
pub mod quasi_static;
pub mod recorder;
pub mod response;
pub mod shooting;
pub mod spectrum;
pub mod state_scales;
pub mod steady;
pub mod step_failure;
pub mod summary;
pub mod tooth_mesh;
pub mod transient;

#[cfg(test)]
mod tests_planetary_dynamic;
#[cfg(test)]
mod tests_planetary_load_sharing;
#[cfg(test)]
mod tests_planetary_lumped;
#[cfg(test)]
mod tests_planetary_published;
