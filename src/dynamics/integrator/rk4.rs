//! The classical explicit fourth-order Runge-Kutta method (Kutta 1901; Hairer, Norsett &
//! Wanner I, Table II.1.2, "the Runge-Kutta method"), fixed step.
//!
//! Stable only for `h*lambda` inside its stability region (real-axis limit -2.785), so it
//! is for non-stiff problems; on the gear model's -1.4e8 1/s eigenvalues it needs
//! `h < 2e-8 s`.

use nalgebra::SVector;

use super::{IntegratorError, OdeSystem, StepStats, Stepper};

/// Fixed-step classical RK4. Four `rhs` calls per step, no allocation.
#[derive(Debug, Clone)]
pub struct Rk4<const N: usize> {
    h: f64,
    stats: StepStats,
}

impl<const N: usize> Rk4<N> {
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
    pub fn step<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut SVector<f64, N>,
    ) -> Result<StepStats, IntegratorError> {
        let h = self.h;
        let k1 = sys.rhs(t, y);
        let k2 = sys.rhs(t + 0.5 * h, &(*y + (0.5 * h) * k1));
        let k3 = sys.rhs(t + 0.5 * h, &(*y + (0.5 * h) * k2));
        let k4 = sys.rhs(t + h, &(*y + h * k3));
        let y_new = *y + (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
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

impl<const N: usize> Stepper<N> for Rk4<N> {
    fn step_size(&self) -> f64 {
        self.h
    }

    fn step<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &mut SVector<f64, N>,
    ) -> Result<StepStats, IntegratorError> {
        Rk4::step(self, sys, t, y)
    }
}
