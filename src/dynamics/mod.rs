//! The 8-DOF tribo-dynamic model (paper eq. 1-6), its integrator, steady state and signals.

pub mod integrator;
