//! Plots and the HTML report.

pub mod plot;
