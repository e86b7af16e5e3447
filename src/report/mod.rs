//! Plots and the HTML report.

pub mod comparison;
pub mod figures;
pub mod html;
pub mod modes;
pub mod plot;
pub mod sweep_figure;
