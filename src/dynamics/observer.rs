//! What a caller sees of the solution over a period (or a part of one).

use super::model::{ContactModes, GearSystem};

/// What a caller sees of the solution over a period (states y = [q; dq/dt] as slices).
pub trait PeriodObserver {
    /// A point of the solution: the period start and every accepted step's end but the
    /// period's last. `decide` is a time inside the node interval the point opens (the
    /// right limit at a mesh event).
    fn point(&mut self, sys: &GearSystem, t: f64, decide: f64, y: &[f64]);
    /// An accepted step from `(t, y0)` to `(t + h, y1)`, taken in contact modes `mode`.
    fn step(
        &mut self,
        sys: &GearSystem,
        t: f64,
        h: f64,
        y0: &[f64],
        y1: &[f64],
        mode: ContactModes,
    );
}

/// Observes nothing (the periods of the steady-state search).
impl PeriodObserver for () {
    fn point(&mut self, _: &GearSystem, _: f64, _: f64, _: &[f64]) {}
    fn step(&mut self, _: &GearSystem, _: f64, _: f64, _: &[f64], _: &[f64], _: ContactModes) {}
}
