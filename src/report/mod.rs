//! Plots and the HTML report.

pub mod figures;
pub mod plot;
