//! The uncertain parameters and their priors (`[calibration]` of the case).
//!
//! - Wear coefficient k (Archard, paper eq. 14), m^2/N: log-uniform on [min, max]
//!   (scale-free: each decade equally likely a priori). Default: the case's k / 100 to
//!   k x 100, four decades around it.
//! - Roughness factor s (-): uniform; multiplies `surface.roughness_table_rms_um`.
//! - Load torque T, N m: uniform; replaces `operating.load_torque_nm`.
//!
//! Equal bounds hold a parameter fixed. Samplers work in unit coordinates u in [0, 1]
//! per parameter (log k for k), where every prior is uniform.

use crate::config::case::{Case, LoadPoint};
use crate::remedy::Problems;
use crate::rng;
use crate::study::budget::ParameterSpan;
use rand::rngs::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// The uncertain parameters, in the order of [`Theta`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Parameter {
    /// Archard wear coefficient k, m^2/N.
    WearCoefficient,
    /// Factor on the roughness law, dimensionless.
    RoughnessScale,
    /// Load torque, N m.
    LoadTorque,
}

/// Values of all three parameters: [k m^2/N, roughness factor -, load torque N m].
pub type Theta = [f64; 3];

pub(crate) const PARAMETERS: [Parameter; 3] = [
    Parameter::WearCoefficient,
    Parameter::RoughnessScale,
    Parameter::LoadTorque,
];

impl Parameter {
    /// Column name in the posterior samples CSV.
    pub fn column(&self) -> &'static str {
        match self {
            Parameter::WearCoefficient => "wear_coefficient_m2_per_n",
            Parameter::RoughnessScale => "roughness_scale",
            Parameter::LoadTorque => "load_torque_nm",
        }
    }

    /// Label for tables and figures, with the unit.
    pub fn label(&self) -> &'static str {
        match self {
            Parameter::WearCoefficient => "wear coefficient k (m^2/N)",
            Parameter::RoughnessScale => "roughness factor (-)",
            Parameter::LoadTorque => "load torque (N m)",
        }
    }

    /// The parameter of a posterior samples CSV column, if any.
    pub fn parse(column: &str) -> Option<Self> {
        PARAMETERS.iter().copied().find(|p| p.column() == column)
    }
}

/// The prior of one parameter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ParamPrior {
    /// The parameter.
    pub parameter: Parameter,
    /// Lower bound, in the parameter's unit.
    pub lo: f64,
    /// Upper bound, in the parameter's unit (equal to `lo`: fixed).
    pub hi: f64,
    /// Log-uniform (else uniform).
    pub log: bool,
}

impl ParamPrior {
    pub(crate) fn is_fixed(&self) -> bool {
        self.lo == self.hi
    }

    /// Unit coordinate of a value (0 at lo, 1 at hi; log scale for a log prior).
    #[cfg(test)]
    pub(crate) fn unit_of(&self, x: f64) -> f64 {
        if self.is_fixed() {
            return 0.5;
        }
        if self.log {
            (x.ln() - self.lo.ln()) / (self.hi.ln() - self.lo.ln())
        } else {
            (x - self.lo) / (self.hi - self.lo)
        }
    }

    /// Value at a unit coordinate.
    pub(crate) fn value_at_unit(&self, u: f64) -> f64 {
        if self.is_fixed() {
            return self.lo;
        }
        if self.log {
            (self.lo.ln() + u * (self.hi.ln() - self.lo.ln())).exp()
        } else {
            self.lo + u * (self.hi - self.lo)
        }
    }

    /// Prior CDF at x.
    #[cfg(test)]
    pub(crate) fn cdf(&self, x: f64) -> f64 {
        if self.is_fixed() {
            return if x < self.lo { 0.0 } else { 1.0 };
        }
        self.unit_of(x).clamp(0.0, 1.0)
    }
}

/// Priors of all three parameters (fixed ones included).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Prior {
    /// Priors in the order of [`Theta`].
    pub params: [ParamPrior; 3],
}

impl Prior {
    /// The priors of a case's `[calibration]` table, with the derived bounds filled in.
    /// Errors name the keys: a prior with no support (min > max, or a log-uniform prior
    /// reaching zero).
    pub fn from_case(case: &Case) -> Result<Self, Problems> {
        let c = &case.calibration;
        let k = case.wear.coefficient_m2_per_n;
        let mut problems = Vec::new();
        let k_lo = c.wear_coefficient_min_m2_per_n.unwrap_or(k / 100.0);
        let k_hi = c.wear_coefficient_max_m2_per_n.unwrap_or(k * 100.0);
        if !(k_lo > 0.0 && k_hi > 0.0) {
            problems.push(format!(
                "prior of the wear coefficient has no support: the log-uniform prior needs bounds > 0, got [{k_lo:e}, {k_hi:e}] (`wear.coefficient_m2_per_n` = {k:e}; set `calibration.wear_coefficient_min_m2_per_n` and `calibration.wear_coefficient_max_m2_per_n`)"
            ));
        }
        let torque = case.operating.load_torque_nm;
        let bounds = [
            (
                "calibration.wear_coefficient_min_m2_per_n",
                "calibration.wear_coefficient_max_m2_per_n",
                k_lo,
                k_hi,
            ),
            (
                "calibration.roughness_scale_min",
                "calibration.roughness_scale_max",
                c.roughness_scale_min,
                c.roughness_scale_max,
            ),
            (
                "calibration.load_torque_min_nm",
                "calibration.load_torque_max_nm",
                c.load_torque_min_nm.unwrap_or(torque),
                c.load_torque_max_nm.unwrap_or(torque),
            ),
        ];
        for (kmin, kmax, lo, hi) in bounds {
            if lo > hi {
                problems.push(format!(
                    "prior with no support: `{kmin}` = {lo} is above `{kmax}` = {hi}"
                ));
            }
        }
        if !problems.is_empty() {
            return Err(problems.into());
        }
        let p = |i: usize, log| ParamPrior {
            parameter: PARAMETERS[i],
            lo: bounds[i].2,
            hi: bounds[i].3,
            log,
        };
        Ok(Self {
            params: [p(0, true), p(1, false), p(2, false)],
        })
    }

    /// The prior whose bounds just span `rows` (log-uniform k): the range a surrogate
    /// must cover to predict from those samples.
    pub fn spanning(rows: &[Theta]) -> Self {
        let p = |i: usize, log| ParamPrior {
            parameter: PARAMETERS[i],
            lo: rows.iter().map(|t| t[i]).fold(f64::INFINITY, f64::min),
            hi: rows.iter().map(|t| t[i]).fold(0.0, f64::max),
            log,
        };
        Self {
            params: [p(0, true), p(1, false), p(2, false)],
        }
    }

    /// Indices of the parameters that are not fixed.
    pub fn free(&self) -> Vec<usize> {
        (0..3).filter(|i| !self.params[*i].is_fixed()).collect()
    }

    /// The parameter values at unit coordinates `u` of the free parameters (fixed ones at
    /// their value).
    pub(crate) fn theta_at(&self, u: &[f64]) -> Theta {
        let mut t = [0.0; 3];
        let free = self.free();
        for (i, p) in self.params.iter().enumerate() {
            t[i] = match free.iter().position(|f| *f == i) {
                Some(j) => p.value_at_unit(u[j]),
                None => p.lo,
            };
        }
        t
    }

    /// One draw from the prior.
    pub fn draw(&self, r: &mut ChaCha8Rng) -> Theta {
        let u: Vec<f64> = self.free().iter().map(|_| rng::uniform(r)).collect();
        self.theta_at(&u)
    }
}

/// The case with the parameters applied: k, the roughness table times the factor, and
/// the load torque. Under a load spectrum the torque is a level relative to the
/// operating torque: every bin's torque is scaled by T / `operating.load_torque_nm`.
pub(crate) fn apply(case: &Case, theta: &Theta) -> Case {
    let mut c = case.clone();
    c.wear.coefficient_m2_per_n = theta[0];
    for r in &mut c.surface.roughness_table_rms_um {
        *r *= theta[1];
    }
    if let Some(s) = c.load_spectrum.as_mut() {
        if theta[2] != case.operating.load_torque_nm {
            s.torque_scale *= theta[2] / case.operating.load_torque_nm;
        }
    }
    c.set_load_point(LoadPoint {
        load_torque_nm: theta[2],
        ..c.load_point()
    });
    c
}

/// The numbers the run budget's estimates need of the span (the cost model sits below
/// prognostics and takes numbers, not a prior).
impl From<&Prior> for ParameterSpan {
    fn from(p: &Prior) -> Self {
        let free = p.free();
        ParameterSpan {
            wear_coefficient_min_m2_per_n: p.params[0].lo,
            wear_coefficient_max_m2_per_n: p.params[0].hi,
            load_torque_max_nm: p.params[2].hi,
            free: free.len(),
            free_besides_wear_coefficient: free.iter().filter(|i| **i != 0).count(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_span_four_decades_around_the_case() {
        let case = Case::default();
        let p = Prior::from_case(&case).unwrap();
        let k = case.wear.coefficient_m2_per_n;
        // k/100 and 100 k by the documented default; relative 1e-12 covers the rounding.
        assert!((p.params[0].lo / (k / 100.0) - 1.0).abs() < 1e-12);
        assert!((p.params[0].hi / (k * 100.0) - 1.0).abs() < 1e-12);
        assert_eq!(p.free(), vec![0]);
        // The case's k sits in the middle of the log scale.
        assert!((p.params[0].unit_of(k) - 0.5).abs() < 1e-12);
        let t = p.theta_at(&[0.5]);
        assert!((t[0] / k - 1.0).abs() < 1e-12);
        assert_eq!((t[1], t[2]), (1.0, case.operating.load_torque_nm));
    }

    #[test]
    fn no_support_names_the_keys() {
        let mut case = Case::default();
        case.calibration.roughness_scale_min = 2.0;
        let e = Prior::from_case(&case).unwrap_err().to_string();
        assert!(e.contains("calibration.roughness_scale_min"), "{e}");
        let mut case = Case::default();
        case.wear.coefficient_m2_per_n = 0.0;
        let e = Prior::from_case(&case).unwrap_err().to_string();
        assert!(
            e.contains("calibration.wear_coefficient_min_m2_per_n"),
            "{e}"
        );
        let mut case = Case::default();
        case.calibration.load_torque_min_nm = Some(80.0);
        let e = Prior::from_case(&case).unwrap_err().to_string();
        assert!(e.contains("calibration.load_torque_min_nm"), "{e}");
    }

    #[test]
    fn apply_sets_the_three_parameters() {
        let c = apply(&Case::default(), &[1e-16, 2.0, 50.0]);
        assert_eq!(c.wear.coefficient_m2_per_n, 1e-16);
        assert_eq!(c.operating.load_torque_nm, 50.0);
        assert_eq!(c.surface.roughness_table_rms_um[0], 0.42);
    }
}
