//! What a sensor fixed on the ring hears of a planetary set's meshes: each planet's
//! mesh force weighted by a window of its angular distance to the sensor, summed
//! (McFadden & Smith 1985, "An explanation for the asymmetry of the modulation sidebands
//! about the tooth meshing frequency in epicyclic gear vibration", Proc. IMechE 199 C;
//! Inalpolat & Kahraman 2009, "A theoretical and experimental investigation of
//! modulation sidebands of planetary gear sets", J. Sound Vib. 323, 677):
//!   x(t) = sum_n w(psi_n + theta_c(t) - theta_sensor) F_n(t),
//! theta_c(t) = 2 pi f_c t the carrier's angle relative to the ring (rad), w a Hann window
//! of half-width theta_w (rad): w(theta) = (1 + cos(pi theta / theta_w)) / 2 for |theta| <
//! theta_w (theta reduced to (-pi, pi]), 0 otherwise. Units: x in those of F (N).
//!
//! Since w is 2 pi-periodic, w = sum_l W_l e^(i l theta), and with equally spaced planets
//! sum_n e^(i l psi_n) vanishes unless l is a multiple of N: a force common to all
//! planets is heard only at f + l f_c with l a multiple of N (the planet-pass frequency's
//! multiples); a force whose phase on planet n is -z_r psi_n (the ring meshes' phasing,
//! Parker & Lin 2004) only at l = z_r (mod N) (McFadden & Smith's asymmetric sidebands).

use std::f64::consts::PI;

/// The Hann window of half-width `half_width_rad` at angular distance `theta_rad`.
pub fn window(theta_rad: f64, half_width_rad: f64) -> f64 {
    let t = theta_rad - 2.0 * PI * ((theta_rad + PI) / (2.0 * PI)).floor();
    if t.abs() < half_width_rad {
        0.5 * (1.0 + (PI * t / half_width_rad).cos())
    } else {
        0.0
    }
}

/// x(t) at `times_s` from each planet's force `force(n, t)` (N), planet angles
/// `psi_rad`, carrier speed relative to the ring `carrier_hz`, the sensor's angle and the
/// window's half-width (rad).
pub fn ring_sensor(
    times_s: &[f64],
    psi_rad: &[f64],
    force: impl Fn(usize, f64) -> f64,
    carrier_hz: f64,
    sensor_rad: f64,
    half_width_rad: f64,
) -> Vec<f64> {
    times_s
        .iter()
        .map(|t| {
            let theta_c = 2.0 * PI * carrier_hz * t;
            psi_rad
                .iter()
                .enumerate()
                .map(|(n, psi)| window(psi + theta_c - sensor_rad, half_width_rad) * force(n, *t))
                .sum()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// |DFT| / samples of the complex record xc + i xs at frequency index `k`.
    fn amplitude(xc: &[f64], xs: &[f64], k: usize) -> f64 {
        let n = xc.len() as f64;
        let (mut re, mut im) = (0.0, 0.0);
        for (j, (c, s)) in xc.iter().zip(xs).enumerate() {
            let (sa, ca) = (2.0 * PI * (k * j) as f64 / n).sin_cos();
            re += c * ca + s * sa;
            im += s * ca - c * sa;
        }
        re.hypot(im) / n
    }

    /// One carrier revolution (f_c = 1 Hz, record 1 s) of a ring-fixed set with z_r = 84
    /// teeth (f_m = 84 Hz), N = 5 planets, each mesh force cos(2 pi f_m t - phase_n): the
    /// amplitude at every frequency index k (Hz) of the positive-frequency part, taken
    /// from the sensor's records of the cosine and the sine forces (x_cos + i x_sin, so
    /// that the force's negative-frequency image, which the window carries to every
    /// line, drops out).
    fn heard(phase: impl Fn(f64) -> f64) -> Vec<f64> {
        // 4000 samples: the planets' 1/5 revolution spacing is a whole 800 samples, so the
        // sampled windows keep the set's symmetry exactly.
        let (samples, zr, n) = (4000, 84.0, 5);
        let psi: Vec<f64> = (0..n).map(|k| 2.0 * PI * k as f64 / n as f64).collect();
        let times: Vec<f64> = (0..samples).map(|j| j as f64 / samples as f64).collect();
        let record = |trig: fn(f64) -> f64| {
            ring_sensor(
                &times,
                &psi,
                |p, t| trig(2.0 * PI * zr * t - phase(psi[p])),
                1.0,
                0.0,
                0.5,
            )
        };
        let (xc, xs) = (record(f64::cos), record(f64::sin));
        (0..200).map(|k| amplitude(&xc, &xs, k)).collect()
    }

    #[test]
    fn in_phase_planets_are_heard_at_planet_pass_multiples_only() {
        // The same force on every planet: energy only at 84 + l with l a multiple of 5.
        // The forbidden lines cancel exactly (sum_n e^(i l psi_n) = 0): rounding, ~1e-16
        // of the top line; 1e-12 is far above that and far below a present sideband.
        let a = heard(|_| 0.0);
        let top = a[84];
        assert!(top > 0.1, "{top}");
        for (k, v) in a.iter().enumerate().take(110).skip(60) {
            let l = k as i64 - 84;
            if l.rem_euclid(5) != 0 {
                assert!(*v < 1e-12 * top, "k = {k}: {v}");
            }
        }
        assert!(a[89] > 1e-3 * top && a[79] > 1e-3 * top);
    }

    #[test]
    fn ring_phased_planets_are_heard_at_shifted_sidebands() {
        // Phase z_r psi_n (ring mesh phasing): energy at 84 + l with l = 84 = 4 (mod 5),
        // l = -1, 4, -6, ...: f_m itself (l = 0) is absent (McFadden & Smith 1985).
        // Tolerance as in the in-phase test.
        let a = heard(|psi| 84.0 * psi);
        let top = a.iter().cloned().fold(0.0, f64::max);
        for (k, v) in a.iter().enumerate().take(110).skip(60) {
            let l = k as i64 - 84;
            if (l - 84).rem_euclid(5) != 0 {
                assert!(*v < 1e-12 * top, "k = {k}: {v}");
            }
        }
        assert!(a[83] > 1e-2 * top, "l = -1 {}", a[83]);
        assert!(a[84] < 1e-12 * top, "f_m itself {}", a[84]);
    }
}
