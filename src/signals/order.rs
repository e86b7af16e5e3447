//! Order tracking of a run-up or coast-down with the tachometer (computed order
//! tracking, Fyfe & Munck 1997), and the time-frequency map of a record for a Campbell
//! diagram.
//!
//! - **Angle domain.** The record is resampled at equal angles of the tracked shaft: the
//!   time at each angle from the tachometer's pulses (`super::tsa::time_at_angle`), the
//!   value by band-limited interpolation (`super::interp`). M samples per revolution, M
//!   the power of two at or above the samples per revolution at the slowest speed, so
//!   nothing of the recorded band is lost anywhere on the ramp.
//! - **Order spectra.** Blocks of `block_revolutions` revolutions, Hann window, amplitude
//!   scaling (a steady order on a bin shows its amplitude); order resolution 1 / block.
//!   Each block is labelled with the shaft's mean speed over it (revolutions / duration).
//! - **Time-frequency map** (Campbell): blocks of `block` samples with half overlap,
//!   Hann window, each labelled with the tracked shaft's mean speed over the block.

use super::interp;
use super::record_spectrum::hann_amplitude_spectrum;
use super::tsa::time_at_angle;
use std::f64::consts::PI;

/// Order spectra along a ramp.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct OrderMap {
    /// Orders of the spectrum bins (k / block revolutions).
    pub orders: Vec<f64>,
    /// Mean shaft speed of each block, Hz.
    pub speed_hz: Vec<f64>,
    /// `amplitude[block][bin]`.
    pub amplitude: Vec<Vec<f64>>,
}

impl OrderMap {
    /// Amplitude of the bin nearest `order` in every block.
    pub fn track(&self, order: f64) -> Vec<f64> {
        let step = self.orders.get(1).copied().unwrap_or(1.0);
        let k = (order / step).round() as usize;
        self.amplitude
            .iter()
            .map(|a| a.get(k).copied().unwrap_or(0.0))
            .collect()
    }
}

/// Order spectra of `x` (at `fs_hz`) for the shaft turning `ratio` times per revolution of
/// the tachometer's (pulses `edges`, `n` per revolution).
pub fn order_map(
    x: &[f64],
    fs_hz: f64,
    edges: &[f64],
    n: usize,
    ratio: f64,
    block_revolutions: usize,
) -> OrderMap {
    if edges.len() < 3 || block_revolutions == 0 {
        return OrderMap::default();
    }
    let two_pi = 2.0 * PI;
    let tach_span = two_pi * (edges.len() - 1) as f64 / n as f64;
    // Slowest revolution of the tracked shaft: the longest interval between pulses.
    let longest_pulse = edges.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
    let slowest_rev_s = longest_pulse * n as f64 / ratio;
    let m = ((fs_hz * slowest_rev_s).ceil() as usize)
        .next_power_of_two()
        .max(16);
    let revolutions = (tach_span * ratio / two_pi).floor() as usize;
    let mut map = OrderMap {
        orders: (0..=m * block_revolutions / 2)
            .map(|k| k as f64 / block_revolutions as f64)
            .collect(),
        ..Default::default()
    };
    let mut r = 0;
    while r + block_revolutions <= revolutions {
        let len = m * block_revolutions;
        let times: Vec<f64> = (0..=len)
            .map(|i| time_at_angle(edges, n, two_pi * (r as f64 + i as f64 / m as f64) / ratio))
            .collect();
        let (t0, t1) = (times[0], times[len]);
        r += block_revolutions;
        if !interp::inside(x.len(), fs_hz, t0) || !interp::inside(x.len(), fs_hz, t1) {
            continue;
        }
        let values: Vec<f64> = times[..len]
            .iter()
            .map(|t| interp::at(x, fs_hz, *t))
            .collect();
        // Amplitudes per order: a "sampling rate" of m samples per revolution.
        let (_, amp) = hann_amplitude_spectrum(&values, m as f64);
        map.speed_hz.push(block_revolutions as f64 / (t1 - t0));
        map.amplitude.push(amp);
    }
    map
}

/// A time-frequency map for a Campbell diagram.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct CampbellMap {
    pub frequency_hz: Vec<f64>,
    /// Tracked shaft's mean speed over each block, Hz.
    pub speed_hz: Vec<f64>,
    /// `amplitude[block][bin]`.
    pub amplitude: Vec<Vec<f64>>,
}

/// Short-time spectra of `x` in blocks of `block` samples (half overlap), each labelled
/// with the speed of the shaft turning `ratio` times per tachometer revolution.
pub(crate) fn campbell_map(
    x: &[f64],
    fs_hz: f64,
    edges: &[f64],
    n: usize,
    ratio: f64,
    block: usize,
) -> CampbellMap {
    let mut map = CampbellMap::default();
    if edges.len() < 2 || block < 16 {
        return map;
    }
    let angle_at = |t: f64| -> f64 {
        // Tachometer angle by linear interpolation of the pulse times (rad).
        let j = edges.partition_point(|e| *e <= t).clamp(1, edges.len() - 1);
        let (a, b) = (edges[j - 1], edges[j]);
        2.0 * PI * ((j - 1) as f64 + (t - a) / (b - a)) / n as f64
    };
    let mut start = 0;
    while start + block <= x.len() {
        let (t0, t1) = (start as f64 / fs_hz, (start + block) as f64 / fs_hz);
        if t0 >= edges[0] && t1 <= edges[edges.len() - 1] {
            let (f, a) = hann_amplitude_spectrum(&x[start..start + block], fs_hz);
            if map.frequency_hz.is_empty() {
                map.frequency_hz = f;
            }
            map.speed_hz
                .push(ratio * (angle_at(t1) - angle_at(t0)) / (2.0 * PI) / (t1 - t0));
            map.amplitude.push(a);
        }
        start += block / 2;
    }
    map
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_order_of_a_ramp_keeps_its_amplitude_in_the_order_domain() {
        // A shaft from 10 to 30 Hz in 4 s; a component of order 7 with amplitude 2 and one
        // of order 13 with amplitude growing with speed (0.05 x speed in Hz).
        let fs = 20_000.0;
        let (f0, f1, dur) = (10.0, 30.0, 4.0);
        let a = (f1 - f0) / dur;
        let angle = |t: f64| 2.0 * PI * (f0 * t + 0.5 * a * t * t);
        let x: Vec<f64> = (0..(fs * dur) as usize)
            .map(|i| {
                let t = i as f64 / fs;
                let th = angle(t);
                2.0 * (7.0 * th).sin() + 0.05 * (f0 + a * t) * (13.0 * th).cos()
            })
            .collect();
        // One pulse a revolution, exact times.
        let mut edges = Vec::new();
        let mut k = 1.0;
        loop {
            // f0 t + a t^2 / 2 = k.
            let t = (-f0 + (f0 * f0 + 2.0 * a * k).sqrt()) / a;
            if t > dur {
                break;
            }
            edges.push(t);
            k += 1.0;
        }
        let map = order_map(&x, fs, &edges, 1, 1.0, 4);
        assert!(map.amplitude.len() > 10);
        for ((o7, o13), v) in map
            .track(7.0)
            .iter()
            .zip(map.track(13.0))
            .zip(&map.speed_hz)
        {
            // Constant amplitude 2 (to the window's leakage of a slightly varying speed
            // within a block: the interpolation error ~1e-5 and the exact order bin).
            assert!((o7 - 2.0).abs() < 1e-3, "{o7} at {v} Hz");
            // The block's mean amplitude of a linearly growing one: 0.05 x mean speed,
            // within the speed's change over a block (4 revolutions, <= 4 % at 10 Hz).
            assert!((o13 - 0.05 * v).abs() < 0.04 * 0.05 * v, "{o13} at {v} Hz");
        }
        let c = campbell_map(&x, fs, &edges, 1, 1.0, 4096);
        assert!(c.amplitude.len() > 10);
        // The 7th order's frequency in each block is 7 x speed: the spectrum's peak lies
        // within a bin (4.9 Hz) plus the ramp's sweep over the block (7 x 5 Hz/s x 0.2 s).
        for (a, v) in c.amplitude.iter().zip(&c.speed_hz) {
            let k = a
                .iter()
                .enumerate()
                .skip(20)
                .max_by(|p, q| p.1.total_cmp(q.1))
                .unwrap()
                .0;
            let f = c.frequency_hz[k];
            if (7.0 * v - 13.0 * v).abs() > 50.0 {
                assert!(
                    (f - 7.0 * v).abs() < 4.9 + 7.0 || (f - 13.0 * v).abs() < 4.9 + 13.0,
                    "{f} vs {v}"
                );
            }
        }
    }
}
