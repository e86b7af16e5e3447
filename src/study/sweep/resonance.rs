//! Input speeds at which a mesh harmonic meets a natural frequency.
//!
//! The mesh frequency of a spur pair is f_m = z1 f_in (z1 pinion teeth, f_in pinion speed
//! in rev/s; `DynamicParams::mesh_frequency_hz`), so harmonic h excites a natural
//! frequency f_n at f_in = f_n / (h z1). Near these speeds the dynamic response of a speed
//! sweep is expected to peak (primary resonance for h = 1, super-harmonic for h > 1).

use serde::{Deserialize, Serialize};

/// One crossing of harmonic `h` with mode `mode` (1-based, ascending frequency).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Crossing {
    pub harmonic: u32,
    pub mode: usize,
    pub natural_frequency_hz: f64,
    pub input_speed_hz: f64,
}

impl Crossing {
    /// Short plot label, e.g. `1x f3`.
    pub fn label(&self) -> String {
        format!("{}x f{}", self.harmonic, self.mode)
    }
}

/// Crossings of harmonics 1..=`max_harmonic` with the natural frequencies (Hz) whose
/// input speed lies in [lo_hz, hi_hz], sorted by speed. Rigid-body modes (f_n ~ 0) are
/// skipped.
pub fn crossings(
    natural_hz: &[f64],
    pinion_teeth: usize,
    max_harmonic: u32,
    lo_hz: f64,
    hi_hz: f64,
) -> Vec<Crossing> {
    let mut out = Vec::new();
    if pinion_teeth == 0 {
        return out;
    }
    for (i, &f_n) in natural_hz.iter().enumerate() {
        // Below 1e-3 Hz a "mode" is a rigid-body rotation at round-off.
        if !(f_n.is_finite() && f_n > 1e-3) {
            continue;
        }
        for h in 1..=max_harmonic {
            let f_in = f_n / (h as f64 * pinion_teeth as f64);
            if f_in >= lo_hz && f_in <= hi_hz {
                out.push(Crossing {
                    harmonic: h,
                    mode: i + 1,
                    natural_frequency_hz: f_n,
                    input_speed_hz: f_in,
                });
            }
        }
    }
    out.sort_by(|a, b| a.input_speed_hz.total_cmp(&b.input_speed_hz));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn speeds_solve_h_z1_f_in_equals_f_n() {
        // z1 = 19: f_n = 1900 Hz is met by harmonic 1 at 100 rev/s, 2 at 50, 3 at 33.3.
        let c = crossings(&[0.0, 1900.0], 19, 3, 40.0, 120.0);
        assert_eq!(c.len(), 2);
        assert_eq!(
            (c[0].harmonic, c[0].mode, c[0].input_speed_hz),
            (2, 2, 50.0)
        );
        assert_eq!((c[1].harmonic, c[1].input_speed_hz), (1, 100.0));
        for x in &c {
            assert!(
                (x.harmonic as f64 * 19.0 * x.input_speed_hz - x.natural_frequency_hz).abs() < 1e-9
            );
        }
        assert!(crossings(&[1900.0], 19, 3, 101.0, 200.0).is_empty());
    }
}
