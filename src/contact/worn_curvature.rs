//! The curvature of a worn flank (severe wear, issue 18). A flank that has lost w(s)
//! along its normal (s the arc length) is the involute moved inwards by w: its curvature
//! is that of the parallel curve, 1 / (rho - w), plus the wear profile's own second
//! derivative, kappa = 1 / (rho - w) + d^2 w / ds^2 to first order in w (a dent, where w
//! peaks, flattens the flank). On the involute ds = rho d rho / r_b, so
//! d^2 w / ds^2 = (r_b / rho)^2 (w'' - w' / rho) in rho. The Hertz band averages the
//! profile over its width: the second derivative is taken over a stencil of the nominal
//! half-width (at least one grid spacing), which also keeps the kink of the wear profile
//! at the pitch point from becoming a spike of one grid point.

/// Change of the curvature of a worn flank at each grid point, 1/m: own radii of
/// curvature `rho_m` (uniform spacing, ascending), wear `wear_m` (m), base radius `rb_m`,
/// the nominal Hertz half-width `half_width_m` as the smoothing length.
pub fn curvature_change_per_m(
    rho_m: &[f64],
    wear_m: &[f64],
    rb_m: f64,
    half_width_m: f64,
) -> Vec<f64> {
    let n = rho_m.len().min(wear_m.len());
    if n < 3 {
        return vec![0.0; n];
    }
    let h = (rho_m[n - 1] - rho_m[0]) / (n - 1) as f64;
    let m = ((half_width_m / h).round() as usize).clamp(1, (n - 1) / 2);
    (0..n)
        .map(|i| {
            let (a, c) = (i.saturating_sub(m), (i + m).min(n - 1));
            let (a, c) = if c - a < 2 * m {
                // Near an end: the stencil of 2m intervals shifted inside.
                if a == 0 {
                    (0, 2 * m)
                } else {
                    (n - 1 - 2 * m, n - 1)
                }
            } else {
                (a, c)
            };
            let mid = (a + c) / 2;
            let step = (c - mid) as f64 * h;
            let d1 = (wear_m[c] - wear_m[a]) / (2.0 * step);
            let d2 = (wear_m[c] - 2.0 * wear_m[mid] + wear_m[a]) / (step * step);
            let rho = rho_m[i];
            let w = wear_m[i];
            let ratio = rb_m / rho;
            1.0 / (rho - w) - 1.0 / rho + ratio * ratio * (d2 - d1 / rho)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_and_parabolic_wear_by_hand() {
        let rb = 0.018;
        let rho: Vec<f64> = (0..101).map(|i| 0.002 + 1e-4 * i as f64).collect();
        // Uniform wear: only the parallel-curve term, 1/(rho - w) - 1/rho.
        let w = vec![10e-6; 101];
        let k = curvature_change_per_m(&rho, &w, rb, 1e-4);
        assert!((k[50] - (1.0 / (rho[50] - 10e-6) - 1.0 / rho[50])).abs() < 1e-9);
        // Parabolic wear w = c (rho - rho0)^2: w'' = 2c, w' = 2c (rho - rho0); exact on
        // any stencil (a parabola's central differences are exact).
        let (c, r0) = (5.0, 0.007);
        let w: Vec<f64> = rho.iter().map(|r| c * (r - r0).powi(2)).collect();
        let k = curvature_change_per_m(&rho, &w, rb, 3e-4);
        let i = 40;
        let ratio = rb / rho[i];
        let want = 1.0 / (rho[i] - w[i]) - 1.0 / rho[i]
            + ratio * ratio * (2.0 * c - 2.0 * c * (rho[i] - r0) / rho[i]);
        assert!(
            (k[i] - want).abs() < 1e-9 * want.abs().max(1.0),
            "{} vs {want}",
            k[i]
        );
    }
}
