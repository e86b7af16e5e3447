//! The classical explicit fourth-order Runge-Kutta method (Kutta 1901; Hairer, Norsett &
//! Wanner I, Table II.1.2, "the Runge-Kutta method"), fixed step.
//!
//! Stable only for `h*lambda` inside its stability region (real-axis limit -2.785), so it
//! is for non-stiff problems; on the gear model's -1.4e8 1/s eigenvalues it needs
//! `h < 2e-8 s`.

use nalgebra::allocator::Allocator;
use nalgebra::{DefaultAllocator, Dim};
use std::marker::PhantomData;

use super::{IntegratorError, OdeSystem, StepStats, Stepper, Vector};

/// Fixed-step classical RK4. Four `rhs` calls per step, no allocation (for a size known
/// at compile time).
#[derive(Debug, Clone)]
pub struct Rk4<D> {
    h: f64,
    stats: StepStats,
    dim: PhantomData<D>,
}

impl<D: Dim> Rk4<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// A stepper with step `h` (time units, finite and > 0).
    pub fn new(h: f64) -> Result<Self, IntegratorError> {
        if !(h > 0.0 && h.is_finite()) {
            return Err(IntegratorError::InvalidSetting(
                "step size must be finite and > 0",
            ));
        }
        Ok(Self {
            h,
            stats: StepStats::default(),
            dim: PhantomData,
        })
    }

    /// Counters accumulated since creation or the last [`Rk4::reset_stats`].
    pub fn stats(&self) -> StepStats {
        self.stats
    }

    /// Zeroes the accumulated counters.
    pub fn reset_stats(&mut self) {
        self.stats = StepStats::default();
    }

    /// One step `y(t) -> y(t + h)`; `y` is untouched on error (non-finite result).
    pub fn step<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut Vector<D>,
    ) -> Result<StepStats, IntegratorError> {
        let h = self.h;
        let k1 = sys.rhs(t, y);
        let k2 = sys.rhs(t + 0.5 * h, &(&*y + &k1 * (0.5 * h)));
        let k3 = sys.rhs(t + 0.5 * h, &(&*y + &k2 * (0.5 * h)));
        let k4 = sys.rhs(t + h, &(&*y + &k3 * h));
        let y_new = &*y + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0);
        let st = StepStats {
            steps: 1,
            rhs_calls: 4,
            ..StepStats::default()
        };
        if !y_new.iter().all(|v| v.is_finite()) {
            self.stats.rhs_calls += st.rhs_calls;
            return Err(IntegratorError::NonFinite { t });
        }
        *y = y_new;
        self.stats.accumulate(&st);
        Ok(st)
    }
}

impl<D: Dim> Stepper<D> for Rk4<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    fn step_size(&self) -> f64 {
        self.h
    }

    fn step<S: OdeSystem<D>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut Vector<D>,
    ) -> Result<StepStats, IntegratorError> {
        Rk4::step(self, sys, t, y)
    }
}
