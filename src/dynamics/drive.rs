//! A drive that varies in time: the nominal input speed as a linear ramp (run-up or
//! coast-down) and a load-torque fluctuation, for transient simulations
//! (`dynamics::transient`).
//!
//! The model's angles are deviations from the nominal rotation (`dynamics::model`):
//! theta_p = Theta_p(t) + phi_p with Theta_p(t) = Omega_0 t + alpha t^2 / 2 on the pinion
//! side (motor and pinion) and (z1/z2) Theta_p(t) on the gear side (gear and brake). With
//! a nominal acceleration alpha the equations of motion of the deviations gain the
//! inertial term -J alpha (-J alpha z1/z2 on the gear side): d^2 phi / dt^2 equals
//! (torques) / J minus d^2 Theta / dt^2. A coordinate held to the nominal rotation (an imposed speed) keeps
//! phi = 0. The motor slip law T_0 - c_slip dphi_m/dt follows the ramp (its synchronous
//! reference is the nominal speed), so the slip supplies the accelerating torque.
//!
//! The torque fluctuation dT(t) (seeded, band-limited: `signals::noise::band_limited`) is
//! tabulated at a uniform rate and interpolated by a Catmull-Rom cubic (C1); it adds to the
//! load torque where the load acts: the brake, or the motor when the brake's speed is
//! imposed (`operating.speed_boundary`).

/// A tabulated signal at a uniform rate, cubic (Catmull-Rom) in between, held beyond
/// its ends.
#[derive(Debug, Clone, PartialEq)]
pub struct Tabulated {
    /// Samples per second, Hz (sample k at t = k / rate).
    pub rate_hz: f64,
    /// The samples, in the signal's unit.
    pub values: Vec<f64>,
}

impl Tabulated {
    /// The value at `t_s` (s): Catmull-Rom cubic between the samples, the end values beyond
    /// them, 0 when there are none.
    pub fn at(&self, t_s: f64) -> f64 {
        let n = self.values.len();
        if n == 0 {
            return 0.0;
        }
        let u = (t_s * self.rate_hz).clamp(0.0, (n - 1) as f64);
        let i = (u.floor() as usize).min(n.saturating_sub(2));
        let s = u - i as f64;
        let v = |k: isize| self.values[(i as isize + k).clamp(0, n as isize - 1) as usize];
        let (p0, p1, p2, p3) = (v(-1), v(0), v(1), v(2));
        // Catmull-Rom: tangents (p2 - p0)/2 and (p3 - p1)/2.
        let (m1, m2) = (0.5 * (p2 - p0), 0.5 * (p3 - p1));
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * p1
            + (s3 - 2.0 * s2 + s) * m1
            + (-2.0 * s3 + 3.0 * s2) * p2
            + (s3 - s2) * m2
    }
}

/// The nominal speed profile and torque fluctuation of a transient simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct Drive {
    /// Nominal pinion speed at t = 0, rad/s.
    pub start_rad_s: f64,
    /// Nominal pinion acceleration over [0, `ramp_s`], rad/s^2 (constant speed after).
    pub accel_rad_s2: f64,
    /// Duration of the speed ramp, s.
    pub ramp_s: f64,
    /// Load-torque fluctuation on the shaft where the load acts (module docs), N m.
    pub torque_nm: Option<Tabulated>,
}

impl Drive {
    /// A constant speed, no fluctuation.
    pub fn steady(speed_rad_s: f64) -> Self {
        Self {
            start_rad_s: speed_rad_s,
            accel_rad_s2: 0.0,
            ramp_s: 0.0,
            torque_nm: None,
        }
    }

    /// Nominal pinion angle Theta_p(t), rad.
    pub fn angle(&self, t_s: f64) -> f64 {
        let tr = t_s.min(self.ramp_s).max(0.0);
        let base = self.start_rad_s * t_s + 0.5 * self.accel_rad_s2 * tr * tr;
        // After the ramp: the end speed times the time past it.
        base + self.accel_rad_s2 * self.ramp_s * (t_s - self.ramp_s).max(0.0)
    }

    /// Nominal pinion speed, rad/s.
    pub fn speed(&self, t_s: f64) -> f64 {
        self.start_rad_s + self.accel_rad_s2 * t_s.clamp(0.0, self.ramp_s)
    }

    /// Nominal pinion acceleration, rad/s^2.
    pub fn accel(&self, t_s: f64) -> f64 {
        if (0.0..self.ramp_s).contains(&t_s) {
            self.accel_rad_s2
        } else {
            0.0
        }
    }

    /// Time at which the nominal pinion angle reaches `theta` (>= 0), s.
    pub fn time_at_angle(&self, theta: f64) -> f64 {
        let (w0, a, tr) = (self.start_rad_s, self.accel_rad_s2, self.ramp_s);
        let theta_ramp = self.angle(tr);
        if theta <= theta_ramp && a != 0.0 {
            // w0 t + a t^2 / 2 = theta, the root that is reached first (a stable form).
            let disc = (w0 * w0 + 2.0 * a * theta).max(0.0);
            2.0 * theta / (w0 + disc.sqrt())
        } else if theta <= theta_ramp {
            theta / w0
        } else {
            tr + (theta - theta_ramp) / self.speed(tr)
        }
    }

    /// Load-torque fluctuation at t, N m.
    pub fn torque_at(&self, t_s: f64) -> f64 {
        self.torque_nm.as_ref().map_or(0.0, |tab| tab.at(t_s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angle_speed_and_inverse_agree() {
        let d = Drive {
            start_rad_s: 31.4,
            accel_rad_s2: 34.6,
            ramp_s: 10.0,
            torque_nm: None,
        };
        for t in [0.0, 0.3, 5.0, 9.99, 10.0, 12.5] {
            let th = d.angle(t);
            assert!((d.time_at_angle(th) - t).abs() < 1e-12 * (1.0 + t), "{t}");
            // Speed is the angle's derivative (central difference, error ~h^2 a''' = 0).
            let h = 1e-4;
            if (t - 10.0).abs() > 2.0 * h && t > h {
                let num = (d.angle(t + h) - d.angle(t - h)) / (2.0 * h);
                assert!((num - d.speed(t)).abs() < 1e-8 * d.speed(t), "{t}");
            }
        }
        // Coast-down: a falling ramp inverts the same way.
        let c = Drive {
            start_rad_s: 377.0,
            accel_rad_s2: -30.0,
            ramp_s: 10.0,
            torque_nm: None,
        };
        for t in [0.1, 4.0, 9.5] {
            assert!((c.time_at_angle(c.angle(t)) - t).abs() < 1e-11);
        }
    }

    #[test]
    fn catmull_rom_passes_through_samples_and_is_exact_for_quadratics() {
        let tab = Tabulated {
            rate_hz: 10.0,
            values: (0..20).map(|i| (i as f64 * 0.1).powi(2)).collect(),
        };
        assert!((tab.at(0.5) - 0.25).abs() < 1e-15);
        // Catmull-Rom reproduces quadratics exactly inside (its tangents are exact).
        assert!((tab.at(0.73) - 0.73f64.powi(2)).abs() < 1e-12);
    }
}
