//! Cell averages of a sampled signal: the mean of its piecewise-linear interpolant over
//! each cell of a uniform grid, and the box filter they amount to.
//!
//! The bearing forces carry the damper force c_b dq/dt of the bearings, whose velocities
//! settle within microseconds after every stiffness jump; the integrator resolves those
//! layers with short steps. Reading the signal at grid points would weigh a layer by where
//! a point happens to fall (its low-frequency content, its area, would be wrong by the
//! layer's share); the cell mean keeps every layer's area. A cell mean is the signal
//! filtered by a box of the cell's width, whose response sinc(pi f w) is divided out
//! where the record needs the signal itself (`box_response`).

/// Mean over each of `n` cells of width `w` starting at `start` of the piecewise-linear
/// interpolant of (t, x) (t ascending). With `period` the signal is periodic with that
/// period (the interpolant closes on the first sample one period later); without, it is
/// held at its end values outside the samples.
#[cfg(test)]
pub(crate) fn cell_means(
    t: &[f64],
    x: &[f64],
    start: f64,
    w: f64,
    n: usize,
    period: Option<f64>,
) -> Vec<f64> {
    let mut sums = vec![0.0; n];
    if t.is_empty() {
        return sums;
    }
    // Segments of the interpolant (a, xa) -> (b, xb), the periodic closure last.
    let mut segments: Vec<(f64, f64, f64, f64)> = t
        .windows(2)
        .zip(x.windows(2))
        .map(|(tt, xx)| (tt[0], xx[0], tt[1], xx[1]))
        .collect();
    if let Some(p) = period {
        let last = t.len() - 1;
        segments.push((t[last], x[last], t[0] + p, x[0]));
    }
    let span = n as f64 * w;
    let copies: Vec<f64> = match period {
        // Every copy of the period that overlaps the grid.
        Some(p) => {
            let k0 = ((start - (t[0] + p)) / p).floor() as i64;
            let k1 = ((start + span - t[0]) / p).ceil() as i64;
            (k0..=k1).map(|k| k as f64 * p).collect()
        }
        None => vec![0.0],
    };
    for shift in copies {
        for &(a, xa, b, xb) in &segments {
            let (a, b) = (a + shift, b + shift);
            if b <= a || b <= start || a >= start + span {
                continue;
            }
            let slope = (xb - xa) / (b - a);
            let i0 = (((a.max(start)) - start) / w).floor().max(0.0) as usize;
            let i1 = ((((b.min(start + span)) - start) / w).ceil() as usize).min(n);
            for (i, s) in sums.iter_mut().enumerate().take(i1).skip(i0) {
                let lo = a.max(start + i as f64 * w);
                let hi = b.min(start + (i + 1) as f64 * w);
                if hi > lo {
                    // Integral of the segment's line over [lo, hi].
                    let mid = 0.5 * (lo + hi);
                    *s += (xa + slope * (mid - a)) * (hi - lo);
                }
            }
        }
    }
    if period.is_none() {
        // Held end values where the cells reach beyond the samples.
        let (first, last) = (t[0], t[t.len() - 1]);
        for (i, s) in sums.iter_mut().enumerate() {
            let (lo, hi) = (start + i as f64 * w, start + (i + 1) as f64 * w);
            *s += x[0] * (first.min(hi) - lo).max(0.0)
                + x[x.len() - 1] * (hi - last.max(lo)).max(0.0);
        }
    }
    sums.iter().map(|s| s / w).collect()
}

/// Response of the box filter of width `w` at `f_hz` (centred: real), sinc(pi f w).
pub(crate) fn box_response(f_hz: f64, w: f64) -> f64 {
    let a = std::f64::consts::PI * f_hz * w;
    if a.abs() < 1e-12 {
        1.0
    } else {
        a.sin() / a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cell_means_keep_the_area_of_a_narrow_spike() {
        // A triangle spike of base 2 us and height 1000 at t = 10.3 us: area 1e-3.
        let t = [0.0, 9.3e-6, 10.3e-6, 11.3e-6, 40e-6];
        let x = [0.0, 0.0, 1000.0, 0.0, 0.0];
        let m = cell_means(&t, &x, 0.0, 5e-6, 8, None);
        let area: f64 = m.iter().map(|v| v * 5e-6).sum();
        assert!((area - 1e-3).abs() < 1e-15, "{area}");
        // Point samples every 5 us would see 0 or the slope's value: 0 at 5, 10 and 15 us
        // misses 70 % of the spike.
    }

    #[test]
    fn periodic_means_of_a_line_segment_signal_are_exact() {
        // Sawtooth x = t on [0, 1), period 1, cells of 0.25 from 0.1: means of t over each
        // cell with the wrap at 1.
        let t = [0.0, 0.5, 0.999_999];
        let x = [0.0, 0.5, 0.999_999];
        let m = cell_means(&t, &x, 0.1, 0.25, 4, Some(1.0));
        // Cells [0.1,0.35], [0.35,0.6], [0.6,0.85], [0.85,1.1]: means 0.225, 0.475, 0.725,
        // and (0.15 x 0.925 + 0.1 x 0.05) / 0.25 = 0.575 (the last line, from 0.999999 back
        // to 0 at 1.0, is negligible).
        for (v, want) in m.iter().zip([0.225, 0.475, 0.725, 0.575]) {
            assert!((v - want).abs() < 1e-5, "{m:?}");
        }
    }
}
