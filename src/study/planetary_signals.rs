//! `gearwear signals` on a planetary set: what a sensor fixed on the ring hears of the
//! steady state's ring meshes (docs/SIGNALS.md 6, docs/MODEL.md 12.7).
//!
//! With the ring fixed the carrier turns at f_c relative to it and the mesh frequency is
//! f_m = z_r f_c, so the ring meshes' forces, T_m = 1 / f_m periodic, and the planets'
//! angles to the sensor repeat after one carrier revolution T_c = z_r T_m: the sensor's
//! signal is T_c-periodic, its lines lie on the carrier's orders k f_c (the mesh harmonic
//! h at k = h z_r, its sidebands at k = h z_r + l). One revolution is sampled exactly at
//! the steady state's samples (S per mesh period, z_r S per revolution), with
//! x = sum_n w(psi_n + theta_c - theta_s) F_rn (`signals::planet_pass`, McFadden & Smith
//! 1985), and its lines are that revolution's discrete Fourier coefficients: exact for a
//! signal band-limited below z_r S / 2 carrier orders. The record at the case's sampling
//! rate is the periodic revolution read by linear interpolation between its samples.
//!
//! With a tooth fault the forces repeat over P mesh periods (`PlanetaryResponse::
//! mesh_periods`: z_s for a sun tooth) and the signal over L = lcm(P, z_r) mesh periods,
//! R = L / z_r carrier revolutions: the record's lines then lie on multiples of f_c / R,
//! which holds both the carrier's orders and the fault's f_m / P (for a sun tooth
//! f_s - f_c, the sun's rotation relative to the carrier; docs/MODEL.md 12.13). Without a
//! fault R = 1 and everything is as above.

use super::planetary_dynamics::PlanetaryDynamics;
use crate::config::planetary::Member;
use crate::dynamics::planetary_steady::PlanetaryResponse;
use crate::signals::planet_pass::window;
use realfft::RealFftPlanner;
use std::f64::consts::PI;

/// The sensor's placement and the record asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingSensor {
    /// The sensor's angle on the ring from planet 1's position at t = 0, rad.
    pub angle_rad: f64,
    /// Half-width of the window over which a planet's ring mesh is heard, rad.
    pub half_width_rad: f64,
    /// Record length, s.
    pub record_s: f64,
    /// Sampling rate, Hz.
    pub sampling_rate_hz: f64,
}

/// The ring sensor's steady signal.
#[derive(Debug, Clone, PartialEq)]
pub struct RingSensorRecord {
    /// Carrier speed relative to the ring, Hz (> 0).
    pub carrier_hz: f64,
    /// Mesh frequency f_m = z_r f_c, Hz.
    pub mesh_frequency_hz: f64,
    /// Planet-pass frequency N f_c, Hz.
    pub planet_pass_hz: f64,
    /// Carrier revolutions R over which the signal repeats (1 without a tooth fault).
    pub revolutions: usize,
    /// R carrier revolutions of the signal at the steady state's samples, N.
    pub revolution_n: Vec<f64>,
    /// Single-sided amplitude of the line k f_c / R (k = 0 ..= half the samples; carrier
    /// order k when R = 1), N: the mean at k = 0, 2 |X_k| / M above.
    pub order_amplitude_n: Vec<f64>,
    /// The record's sample times, s, and values, N.
    pub times_s: Vec<f64>,
    /// The record's values, N.
    pub values_n: Vec<f64>,
}

/// Why a ring sensor's record cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RingSensorError {
    /// The ring turns (another member is held), so a sensor on it turns too.
    #[error("`planetary.fixed` = \"{}\": a sensor on the ring needs the ring held fixed (a turning ring carries the sensor with it)", .0.name())]
    RingNotFixed(Member),
    /// The transform of the revolution failed (realfft's message).
    #[error("the ring sensor's spectrum: {0}")]
    Spectrum(String),
    /// A sample of the sensor's revolution (which its spectrum and record are made of) is
    /// not a finite number (the set's forces overflowed): never written, as a pair's
    /// record with one is not (`signals::Record::check_finite`).
    #[error("the ring sensor's signal is not a finite number at sample {sample} of its period (t = {time_s} s): the record overflows; check the set's load and stiffness")]
    NonFinite {
        /// Index of the first non-finite sample of the revolution.
        sample: usize,
        /// Its time, s.
        time_s: f64,
    },
}

/// The ring sensor's record of the steady state `r` of `d`.
pub fn ring_sensor_record(
    d: &PlanetaryDynamics,
    r: &PlanetaryResponse,
    sensor: RingSensor,
) -> Result<RingSensorRecord, RingSensorError> {
    let set = &d.study.set;
    if set.fixed != Member::Ring {
        return Err(RingSensorError::RingNotFixed(set.fixed));
    }
    let n = set.planets();
    let zr = set.teeth_ring();
    let recorded = r.mesh_forces_n.len();
    let s = recorded / r.mesh_periods.max(1);
    // The signal's period: lcm(P, z_r) mesh periods, R carrier revolutions (module docs;
    // its sample count checked against the limits when the model was built).
    let revolutions = r.mesh_periods.max(1) / gcd(r.mesh_periods.max(1), zr);
    let speeds = d.study.speeds_hz;
    // Carrier relative to the ring, signed (its sense turns the planets past the sensor).
    let fc_signed = speeds[1] - speeds[2];
    let carrier_hz = fc_signed.abs();
    let mesh_hz = zr as f64 * carrier_hz;
    let period_s = 1.0 / mesh_hz;
    let m = revolutions * zr * s;
    let psi = &set.planet_angles_rad;
    let revolution_n: Vec<f64> = (0..m)
        .map(|j| {
            let t = j as f64 * period_s / s as f64;
            let theta_c = 2.0 * PI * fc_signed * t;
            (0..n)
                .map(|p| {
                    let w = window(psi[p] + theta_c - sensor.angle_rad, sensor.half_width_rad);
                    w * r.mesh_forces_n[j % recorded][n + p]
                })
                .sum()
        })
        .collect();
    // Every output (spectrum, record) is made from the revolution: checked once here.
    if let Some(j) = revolution_n.iter().position(|v| !v.is_finite()) {
        return Err(RingSensorError::NonFinite {
            sample: j,
            time_s: j as f64 * period_s / s as f64,
        });
    }
    let order_amplitude_n = order_amplitudes(&revolution_n)?;
    let (times_s, values_n) = periodic_record(
        &revolution_n,
        m as f64 / ((revolutions * zr) as f64 * period_s),
        sensor,
    );
    Ok(RingSensorRecord {
        revolutions,
        carrier_hz,
        mesh_frequency_hz: mesh_hz,
        planet_pass_hz: n as f64 * carrier_hz,
        revolution_n,
        order_amplitude_n,
        times_s,
        values_n,
    })
}

/// Greatest common divisor.
fn gcd(a: usize, b: usize) -> usize {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// Single-sided amplitudes of a periodic signal's harmonics from one period's samples:
/// the mean, then 2 |X_k| / M (and |X_k| / M at the Nyquist order of an even M).
fn order_amplitudes(x: &[f64]) -> Result<Vec<f64>, RingSensorError> {
    let m = x.len();
    let fft = RealFftPlanner::<f64>::new().plan_fft_forward(m);
    let mut input = x.to_vec();
    let mut out = fft.make_output_vec();
    fft.process(&mut input, &mut out)
        .map_err(|e| RingSensorError::Spectrum(e.to_string()))?;
    Ok(out
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let edge = k == 0 || (m.is_multiple_of(2) && k == m / 2);
            c.norm() * if edge { 1.0 } else { 2.0 } / m as f64
        })
        .collect())
}

/// The record at `sensor`'s rate over its length: the periodic `revolution` (sampled at
/// `rate_hz`) read by linear interpolation.
fn periodic_record(revolution: &[f64], rate_hz: f64, sensor: RingSensor) -> (Vec<f64>, Vec<f64>) {
    let m = revolution.len();
    let count = (sensor.record_s * sensor.sampling_rate_hz).round().max(1.0) as usize;
    let times: Vec<f64> = (0..count)
        .map(|i| i as f64 / sensor.sampling_rate_hz)
        .collect();
    let values = times
        .iter()
        .map(|t| {
            let u = t * rate_hz;
            let j = u.floor();
            let f = u - j;
            let j = (j as usize) % m;
            revolution[j] * (1.0 - f) + revolution[(j + 1) % m] * f
        })
        .collect();
    (times, values)
}
