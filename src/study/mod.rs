//! Studies: the assembled model of a case, the coupled dynamics-wear loop and its
//! quasi-static twin, the wear states of the paper's section 4.1.

pub mod budget;
pub mod dataset;
pub mod domain;
pub mod face_load;
pub mod face_load_dynamic;
pub mod helical;
pub mod helical_dynamics;
pub mod helical_teeth;
pub mod helical_tilt;
mod helical_tooth_wear;
pub mod helical_wear;
pub mod model;
pub mod model_error;
pub mod modes;
pub mod paper;
pub mod parallel_runs;
pub mod planetary;
pub mod planetary_dynamics;
pub mod planetary_fault;
pub mod planetary_lumped;
pub mod planetary_signals;
pub mod planetary_teeth;
pub mod planetary_wear;
pub mod planetary_wear_check;
pub mod planetary_wear_loop;
pub mod signal_record;
pub mod sweep;
pub mod teeth;
pub mod train;
pub mod train_helical;
pub mod train_stages;
pub mod train_wear;
pub mod train_wear_check;
pub mod transient_signals;
pub mod wear_check;
pub mod wear_loop;

pub use model::{Model, ModelError};
pub use modes::ModalAnalysis;
