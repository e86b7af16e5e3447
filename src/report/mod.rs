//! Plots and the HTML report.

pub mod comparison;
pub mod figures;
pub mod html;
pub mod plot;
pub mod prognostics;
