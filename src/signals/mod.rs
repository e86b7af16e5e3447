//! What a sensor records: the housing vibration at named accelerometers, the tachometer,
//! and what condition monitoring computes from them (docs/SIGNALS.md).
//!
//! The chain: bearing forces ([`bearing`]) -> transfer path ([`transfer`], [`frf_table`])
//! -> anti-alias filter and sampling ([`antialias`], [`periodic`], [`record`]) with
//! measurement noise ([`noise`]) and a tachometer ([`tachometer`]); then the
//! time-synchronous average (`tsa`, [`interp`]), its derived signals ([`components`])
//! and the condition indicators ([`indicators`]).

pub mod analysis;
pub mod antialias;
pub(crate) mod area;
pub mod bearing;
pub mod chain;
pub mod components;
pub(crate) mod files;
pub mod frf_table;
pub mod indicators;
pub mod interp;
pub mod noise;
pub mod order;
pub mod path_file;
pub mod periodic;
pub mod planet_pass;
pub mod record;
pub mod record_spectrum;
pub mod setup;
pub mod tachometer;
pub mod transfer;
pub mod transient_record;
pub(crate) mod tsa;

#[cfg(test)]
mod tests_acquisition;
