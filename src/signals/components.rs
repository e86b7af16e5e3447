//! The signals derived from a time-synchronous average (one revolution of a shaft, so
//! DFT bin k is shaft order k), as the condition-monitoring literature defines them
//! (Stewart 1977; McFadden 1987; Zakrajsek, Townsend & Decker 1993, NASA TM-105950;
//! Lebold et al. 2000, "Review of vibration analysis methods for gearbox diagnostics and
//! prognostics", 54th MFPT):
//!
//! - **regular meshing components**: the shaft order and its harmonics (orders 1 to S,
//!   S = [`ComponentSettings::shaft_harmonics`]), the mesh order z (the teeth of the
//!   analysed shaft's gear) and its harmonics h z, and their first-order sidebands
//!   h z +- 1 (up to [`ComponentSettings::sidebands`] orders either side);
//! - **regular signal**: the TSA with only the regular meshing components;
//! - **difference signal**: the TSA minus the regular signal;
//! - **residual signal**: the TSA minus the shaft orders 1..S and the mesh harmonics h z
//!   (sidebands kept);
//! - **band-pass signal and envelope** (NB4, Zakrajsek, Handschuh & Decker 1994): the
//!   orders of the mesh fundamental's band, z - B..z + B with B = floor((z - 1) / 2) (the
//!   widest band that keeps clear of the neighbouring harmonics' bands), and its envelope,
//!   the magnitude of the analytic signal (Hilbert transform by the one-sided spectrum).
//!
//! The mean (order 0) is removed from every derived signal.

use realfft::num_complex::Complex64;
use realfft::RealFftPlanner;

/// Which orders count as the regular meshing components.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ComponentSettings {
    /// Shaft harmonics S counted as regular (orders 1..=S): 2 takes the once- and
    /// twice-per-revolution components of unbalance and misalignment.
    pub shaft_harmonics: usize,
    /// Sideband orders either side of each mesh harmonic counted as regular (1: the
    /// first-order sidebands of the textbook definitions).
    pub sidebands: usize,
    /// Mesh harmonics H whose amplitudes FM0 sums (h = 1..=H; `signals.mesh_harmonics`).
    pub mesh_harmonics: usize,
    /// Highest order of the TSA's passband (None: every order): the orders above, where
    /// the angular resampling is no longer flat (`super::interp::PASSBAND_OVER_FS`), are
    /// left out of every derived signal and TSA indicator.
    pub top_order: Option<usize>,
}

impl Default for ComponentSettings {
    fn default() -> Self {
        Self {
            shaft_harmonics: 2,
            sidebands: 1,
            mesh_harmonics: 4,
            top_order: None,
        }
    }
}

/// The derived signals of one TSA.
#[derive(Debug, Clone, PartialEq)]
pub struct Components {
    /// One-sided spectrum of the TSA, bin k = order k (`realfft` scaling: X_k = sum x e^-i).
    pub spectrum: Vec<Complex64>,
    /// Samples per revolution M.
    pub samples: usize,
    /// Mesh order z: the teeth of the analysed shaft's gear.
    pub mesh_order: usize,
    /// Mesh harmonics FM0 sums ([`ComponentSettings::mesh_harmonics`]).
    pub mesh_harmonic_count: usize,
    /// The TSA restricted to its passband ([`ComponentSettings::top_order`]), mean removed:
    /// what FM0's peak-to-peak and the TSA's RMS are taken of.
    pub in_band: Vec<f64>,
    /// Regular signal: the TSA with only the regular meshing components (M samples).
    pub regular: Vec<f64>,
    /// Difference signal: the TSA minus the regular signal (M samples).
    pub difference: Vec<f64>,
    /// Residual signal: the TSA minus the shaft orders 1..S and the mesh harmonics (M samples).
    pub residual: Vec<f64>,
    /// Band-pass signal: the orders z - B..z + B of the mesh fundamental's band (M samples).
    pub band_pass: Vec<f64>,
    /// Envelope of the band-pass signal, the magnitude of its analytic signal (M samples).
    pub envelope: Vec<f64>,
}

impl Components {
    /// Amplitude of shaft order k (the TSA's Fourier amplitude 2 |X_k| / M).
    pub fn order_amplitude(&self, k: usize) -> f64 {
        self.spectrum
            .get(k)
            .map_or(0.0, |c| 2.0 * c.norm() / self.samples as f64)
    }

    /// The orders h z of mesh harmonics h = 1..=H, H = [`ComponentSettings::mesh_harmonics`]
    /// (the setup checks that they lie in the recorded band; an order at or above M / 2,
    /// which a TSA cannot hold, is left out).
    pub fn mesh_harmonics(&self) -> impl Iterator<Item = usize> + '_ {
        let top = self.samples / 2;
        (1..=self.mesh_harmonic_count)
            .map(move |h| h * self.mesh_order)
            .take_while(move |k| *k < top)
    }
}

fn inverse(spec: &[Complex64], m: usize, keep: impl Fn(usize) -> bool) -> Vec<f64> {
    let mut planner = RealFftPlanner::<f64>::new();
    let ifft = planner.plan_fft_inverse(m);
    let mut s = ifft.make_input_vec();
    for (k, v) in s.iter_mut().enumerate() {
        if k > 0 && keep(k) {
            *v = spec[k];
        }
    }
    if let Some(last) = s.last_mut() {
        last.im = 0.0;
    }
    let mut out = ifft.make_output_vec();
    ifft.process(&mut s, &mut out)
        .expect("FFT buffers sized by the plan");
    out.iter_mut().for_each(|v| *v /= m as f64);
    out
}

/// Magnitude of the analytic signal of the orders in `lo..=hi` (Hilbert envelope).
fn envelope(spec: &[Complex64], m: usize, lo: usize, hi: usize) -> Vec<f64> {
    let mut planner = rustfft::FftPlanner::<f64>::new();
    let fft = planner.plan_fft_inverse(m);
    let mut buf = vec![Complex64::new(0.0, 0.0); m];
    for k in lo.max(1)..=hi.min(m / 2 - 1) {
        // Analytic signal: positive frequencies doubled, negative ones removed.
        buf[k] = spec[k] * 2.0;
    }
    fft.process(&mut buf);
    buf.iter().map(|c| c.norm() / m as f64).collect()
}

/// The derived signals of `tsa` (one revolution, M = len a power of two) for mesh order
/// `mesh_order` (module docs).
pub fn components(tsa: &[f64], mesh_order: usize, settings: ComponentSettings) -> Components {
    let m = tsa.len();
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(m);
    let mut spectrum = fft.make_output_vec();
    fft.process(&mut tsa.to_vec(), &mut spectrum)
        .expect("FFT buffers sized by the plan");
    if let Some(top) = settings.top_order {
        for c in spectrum.iter_mut().skip(top + 1) {
            *c = Complex64::new(0.0, 0.0);
        }
    }
    let in_band = inverse(&spectrum, m, |_| true);
    let z = mesh_order.max(1);
    let shaft = |k: usize| (1..=settings.shaft_harmonics).contains(&k);
    let mesh = |k: usize| k.is_multiple_of(z);
    let sideband = |k: usize| {
        let r = k % z;
        let d = r.min(z - r);
        // Near a mesh harmonic h z with h >= 1 (not the sidebands of order 0).
        d >= 1 && d <= settings.sidebands && k + d >= z
    };
    let regular = inverse(&spectrum, m, |k| shaft(k) || mesh(k) || sideband(k));
    let residual = inverse(&spectrum, m, |k| !(shaft(k) || mesh(k)));
    let difference = inverse(&spectrum, m, |k| !(shaft(k) || mesh(k) || sideband(k)));
    let b = (z - 1) / 2;
    let (lo, hi) = (z - b, z + b);
    let band_pass = inverse(&spectrum, m, |k| (lo..=hi).contains(&k));
    let envelope = envelope(&spectrum, m, lo, hi);
    Components {
        spectrum,
        samples: m,
        mesh_order: z,
        mesh_harmonic_count: settings.mesh_harmonics,
        in_band,
        regular,
        difference,
        residual,
        band_pass,
        envelope,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn each_order_goes_where_the_definitions_put_it() {
        let (m, z) = (512, 19);
        // Orders: 1 (shaft), 7 (other), 19 (mesh), 20 (sideband), 38 (2nd mesh), 40 (2 orders off).
        let orders = [
            (1, 1.0),
            (7, 0.5),
            (19, 2.0),
            (20, 0.3),
            (38, 0.7),
            (40, 0.2),
        ];
        let x: Vec<f64> = (0..m)
            .map(|i| {
                let a = 2.0 * PI * i as f64 / m as f64;
                orders
                    .iter()
                    .map(|(k, amp)| amp * (*k as f64 * a).cos())
                    .sum()
            })
            .collect();
        let c = components(&x, z, ComponentSettings::default());
        for (k, amp) in orders {
            assert!((c.order_amplitude(k) - amp).abs() < 1e-12, "order {k}");
        }
        let has = |sig: &[f64], k: usize| {
            let a = 2.0 * PI / m as f64;
            let proj: f64 = sig
                .iter()
                .enumerate()
                .map(|(i, v)| v * (k as f64 * a * i as f64).cos())
                .sum();
            2.0 * proj / m as f64
        };
        // regular: 1, 19, 20, 38; difference: 7, 40; residual: 7, 20, 40.
        for (k, amp) in orders {
            let in_regular = matches!(k, 1 | 19 | 20 | 38);
            let in_residual = matches!(k, 7 | 20 | 40);
            assert!(
                (has(&c.regular, k) - if in_regular { amp } else { 0.0 }).abs() < 1e-12,
                "regular {k}"
            );
            assert!(
                (has(&c.difference, k) - if in_regular { 0.0 } else { amp }).abs() < 1e-12,
                "difference {k}"
            );
            assert!(
                (has(&c.residual, k) - if in_residual { amp } else { 0.0 }).abs() < 1e-12,
                "residual {k}"
            );
        }
        // Band 10..=28 around order 19: orders 19 and 20; their envelope is
        // |2 + 0.3 e^(i a)|, between 1.7 and 2.3.
        let (lo, hi) = c
            .envelope
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
        assert!(
            (lo - 1.7).abs() < 1e-9 && (hi - 2.3).abs() < 1e-9,
            "{lo} {hi}"
        );
    }
}
