//! The transfer path from the bearing forces to the accelerations at named sensors on the
//! housing: a modal model (structural modes given by frequency, damping and a gain per
//! sensor and bearing-force input) or a measured FRF table ([`super::frf_table`]).
//!
//! Modal accelerance (e.g. Ewins, *Modal Testing*, 2nd ed., eq. 2.60 with viscous modal
//! damping, times -omega^2 for acceleration), with the time dependence e^(i omega t):
//!
//! A_sj(omega) = sum_r G_rsj (-omega^2) / (omega_r^2 - omega^2 + 2 i zeta_r omega_r omega),
//!
//! G_rsj = phi_r(s) phi_r(j) / m_r the modal constant of mode r between input j and sensor
//! s, in 1/kg: the accelerance far above the mode ("mass line"), m/s^2 per N. A single
//! mode is the single-degree-of-freedom oscillator m a'' + c a' + k a = F with G = 1/m,
//! omega_r^2 = k/m, 2 zeta_r omega_r = c/m.
//!
//! The bearing-force inputs are the forces the shafts exert on the housing through the
//! bearings (`super::bearing`), in the model's frame: pinion x, pinion y, gear x, gear y.

use super::frf_table::FrfTable;
use realfft::num_complex::Complex64;
use std::f64::consts::PI;

/// One structural mode of the housing.
#[derive(Debug, Clone, PartialEq)]
pub struct StructuralMode {
    /// Natural frequency f_r, Hz.
    pub frequency_hz: f64,
    /// Viscous modal damping ratio zeta_r.
    pub damping_ratio: f64,
    /// Modal constant G_rsj per sensor s (outer) and input j (inner,
    /// `INPUTS` order), 1/kg (m/s^2 per N far above the mode).
    pub gains_per_kg: Vec<[f64; 4]>,
}

/// How the path is described.
#[derive(Debug, Clone, PartialEq)]
pub enum PathModel {
    /// A sum of structural modes (modal accelerance).
    Modal(Vec<StructuralMode>),
    /// A table of measured FRFs.
    Table(FrfTable),
}

/// A transfer path to named sensors.
#[derive(Debug, Clone, PartialEq)]
pub struct TransferPath {
    /// Sensor names, in channel order.
    pub sensors: Vec<String>,
    /// How the path is described.
    pub model: PathModel,
    /// What the path is (for metadata): "generic housing (...)", a file name, ...
    pub description: String,
    /// Where the sensors sit and what direction they measure, in words (for metadata).
    pub placement: String,
}

/// Modal accelerance of one mode at frequency f (see the module docs), m/s^2 per N.
pub(crate) fn modal_accelerance(
    gain_per_kg: f64,
    frequency_hz: f64,
    damping: f64,
    f_hz: f64,
) -> Complex64 {
    let w = 2.0 * PI * f_hz;
    let wr = 2.0 * PI * frequency_hz;
    let den = Complex64::new(wr * wr - w * w, 2.0 * damping * wr * w);
    Complex64::new(-gain_per_kg * w * w, 0.0) / den
}

impl TransferPath {
    /// Accelerance from input `j` (`bearing::INPUTS` order) to sensor `s`
    /// at `f_hz`, m/s^2 per N.
    pub fn accelerance(&self, s: usize, j: usize, f_hz: f64) -> Complex64 {
        match &self.model {
            PathModel::Modal(modes) => modes
                .iter()
                .map(|m| {
                    modal_accelerance(m.gains_per_kg[s][j], m.frequency_hz, m.damping_ratio, f_hz)
                })
                .sum(),
            PathModel::Table(t) => t.at(s, j, f_hz),
        }
    }

    /// The default path: a generic gearbox housing, not a measured one. Two sensors,
    /// `input` on the pinion's bearing housing and `output` on the gear's, each measuring
    /// in the y direction (perpendicular to the line joining the shaft centres, the
    /// usual top-of-housing mount). Three modes of a cast housing bolted to its base (modal
    /// masses of tens of kg):
    ///
    /// | mode | f (Hz) | zeta | modal mass (kg) | shape: pinion x, y; gear x, y; sensors input, output |
    /// |---|---|---|---|---|
    /// | housing bending, bearings in phase | 2100 | 0.02 | 40 | 0.3, 1.0; 0.2, 0.8; 1.0, 0.8 |
    /// | housing rocking, bearings in antiphase | 3700 | 0.03 | 30 | 0.2, 1.0; -0.2, -0.9; 1.0, -0.9 |
    /// | local mode of the input bearing seat | 6300 | 0.04 | 15 | 0.5, 0.9; 0.05, 0.1; 1.0, 0.1 |
    ///
    /// Cast housings of gear test rigs show their first modes between 1 and 10 kHz with
    /// modal damping of 1-5 %; the numbers are plausible, not measured. A user with a
    /// measured housing gives its modes or FRF table instead (docs/SIGNALS.md).
    pub fn generic_housing() -> Self {
        // (f, zeta, modal mass, shape at [pinion x, pinion y, gear x, gear y], shape at sensors)
        type GenericMode = (f64, f64, f64, [f64; 4], [f64; 2]);
        let modes: [GenericMode; 3] = [
            (2100.0, 0.02, 40.0, [0.3, 1.0, 0.2, 0.8], [1.0, 0.8]),
            (3700.0, 0.03, 30.0, [0.2, 1.0, -0.2, -0.9], [1.0, -0.9]),
            (6300.0, 0.04, 15.0, [0.5, 0.9, 0.05, 0.1], [1.0, 0.1]),
        ];
        let modes = modes
            .iter()
            .map(|(f, z, m, at_inputs, at_sensors)| StructuralMode {
                frequency_hz: *f,
                damping_ratio: *z,
                gains_per_kg: at_sensors
                    .iter()
                    .map(|ps| std::array::from_fn(|j| ps * at_inputs[j] / m))
                    .collect(),
            })
            .collect();
        Self {
            sensors: vec!["input".into(), "output".into()],
            model: PathModel::Modal(modes),
            description: "generic housing (built-in, not measured): modes 2100, 3700, 6300 Hz"
                .into(),
            placement: "`input` on the pinion's bearing housing, `output` on the gear's; both measure the housing's acceleration in y, perpendicular to the line of centres (a top-of-housing mount)".into(),
        }
    }

    /// Problems of the path at sampling rate `fs_hz` (`rate_key` names the setting in
    /// messages): a mode at or above the Nyquist frequency is not recorded faithfully
    /// and is refused.
    pub(crate) fn problems_at(&self, fs_hz: f64, rate_key: &str) -> Vec<String> {
        let nyquist = 0.5 * fs_hz;
        let mut out = Vec::new();
        if let PathModel::Modal(modes) = &self.model {
            for (r, m) in modes.iter().enumerate() {
                if m.frequency_hz >= nyquist {
                    out.push(format!(
                        "transfer path mode {} at {} Hz lies at or above the Nyquist frequency {} Hz of `{rate_key}` = {}: raise `{rate_key}` above {} Hz or drop the mode",
                        r + 1,
                        m.frequency_hz,
                        nyquist,
                        fs_hz,
                        2.0 * m.frequency_hz
                    ));
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_mode_is_the_sdof_oscillator() {
        // m a'' + c a' + k a = F: receptance 1/(k - m w^2 + i c w), accelerance -w^2 times it.
        let (m, k, c): (f64, f64, f64) = (2.0, 3.0e8, 4.0e3);
        let fr = (k / m).sqrt() / (2.0 * PI);
        let zeta = c / (2.0 * (k * m).sqrt());
        for f in [10.0, fr * 0.9, fr, fr * 1.3, 5.0 * fr] {
            let w = 2.0 * PI * f;
            let direct = Complex64::new(-w * w, 0.0) / Complex64::new(k - m * w * w, c * w);
            let modal = modal_accelerance(1.0 / m, fr, zeta, f);
            assert!((modal - direct).norm() < 1e-12 * direct.norm(), "{f}");
        }
    }

    #[test]
    fn generic_housing_is_reciprocal_in_shape_and_below_nyquist_at_25_6_khz() {
        let p = TransferPath::generic_housing();
        assert!(p
            .problems_at(25_600.0, "signals.sampling_rate_hz")
            .is_empty());
        let bad = p.problems_at(10_000.0, "signals.sampling_rate_hz");
        // 6300 Hz lies above 5 kHz, and 3700 < 5000 does not.
        assert_eq!(bad.len(), 1, "{bad:?}");
        assert!(bad[0].contains("`signals.sampling_rate_hz`") && bad[0].contains("12600"));
        // Far above every mode the accelerance is the sum of the modal constants.
        let a = p.accelerance(0, 1, 1e7);
        let PathModel::Modal(modes) = &p.model else {
            unreachable!()
        };
        let sum: f64 = modes.iter().map(|m| m.gains_per_kg[0][1]).sum();
        assert!((a.re - sum).abs() < 1e-3 * sum.abs() && a.im.abs() < 1e-2 * sum.abs());
    }
}
