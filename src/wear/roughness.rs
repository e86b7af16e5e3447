//! Composite RMS roughness as a function of wear (paper 4.1: the roughness falls from
//! 2.1 to 1.9 to 1.5 um as the maximum wear depth goes 0.1 -> 0.5 -> 1 um; see
//! docs/MODEL.md for the units reading). Piecewise linear, constant outside the table.

use crate::config::case::SurfaceSection;

/// Composite RMS roughness as a piecewise linear function of the maximum wear depth
/// (paper section 4.1), constant outside its table.
#[derive(Debug, Clone, PartialEq)]
pub struct RoughnessLaw {
    wear_m: Vec<f64>,
    rms_um: Vec<f64>,
}

impl RoughnessLaw {
    /// The law of the case's `[surface]` table (wear in um there, m inside).
    pub fn from_case(s: &SurfaceSection) -> Self {
        Self {
            wear_m: s.roughness_table_wear_um.iter().map(|w| w * 1e-6).collect(),
            rms_um: s.roughness_table_rms_um.clone(),
        }
    }

    /// Roughness (um) at a maximum pinion wear depth (m).
    pub fn rms_um(&self, max_wear_m: f64) -> f64 {
        let (w, r) = (&self.wear_m, &self.rms_um);
        if w.is_empty() {
            return 0.0;
        }
        if max_wear_m <= w[0] {
            return r[0];
        }
        for i in 1..w.len() {
            if max_wear_m <= w[i] {
                let t = (max_wear_m - w[i - 1]) / (w[i] - w[i - 1]);
                return r[i - 1] + (r[i] - r[i - 1]) * t;
            }
        }
        r[r.len() - 1]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_points_and_clamping() {
        let law = RoughnessLaw::from_case(&SurfaceSection::default());
        assert!((law.rms_um(0.0) - 0.21).abs() < 1e-15);
        assert!((law.rms_um(0.5e-6) - 0.19).abs() < 1e-12);
        assert!((law.rms_um(0.75e-6) - 0.17).abs() < 1e-12);
        assert!((law.rms_um(5e-6) - 0.15).abs() < 1e-15);
    }
}
