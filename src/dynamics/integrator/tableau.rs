//! Butcher tableau of the 3-stage, order-3, L-stable, stiffly accurate SDIRK method of
//! R. Alexander, "Diagonally implicit Runge-Kutta methods for stiff O.D.E.'s",
//! SIAM J. Numer. Anal. 14(6), 1006-1021 (1977); also listed in Hairer & Wanner,
//! *Solving ODEs II*, 2nd ed., Sect. IV.6 (SDIRK methods), and in Kennedy & Carpenter,
//! "Diagonally implicit Runge-Kutta methods for ODEs. A review", NASA/TM-2016-219173.
//!
//! ```text
//!  gamma      | gamma
//!  (1+gamma)/2| (1-gamma)/2  gamma
//!  1          | b1           b2     gamma
//! ------------+--------------------------
//!             | b1           b2     gamma
//! ```
//! with `b1 = -(6 gamma^2 - 16 gamma + 1)/4`, `b2 = (6 gamma^2 - 20 gamma + 5)/4` and
//! `gamma = 0.43586652150845899942`, the root in (1/3, 1/2) of
//! `gamma^3 - 3 gamma^2 + 3/2 gamma - 1/6 = 0`; that root makes the cubic coefficient of the
//! stability function's numerator vanish, i.e. `R(infinity) = 0` (L-stability).
//! The last row of `A` equals `b` (stiffly accurate): `y_{n+1}` is the last stage value.
//!
//! All coefficients are dimensionless.

use nalgebra::Complex;

/// Number of stages.
pub const STAGES: usize = 3;

/// Diagonal coefficient `gamma` (see module docs).
pub const GAMMA: f64 = 0.435_866_521_508_459;

const B1: f64 = -(6.0 * GAMMA * GAMMA - 16.0 * GAMMA + 1.0) / 4.0;
const B2: f64 = (6.0 * GAMMA * GAMMA - 20.0 * GAMMA + 5.0) / 4.0;

/// Stage coefficients `a_ij` (lower triangular, constant diagonal `GAMMA`).
pub const A: [[f64; STAGES]; STAGES] = [
    [GAMMA, 0.0, 0.0],
    [(1.0 - GAMMA) / 2.0, GAMMA, 0.0],
    [B1, B2, GAMMA],
];

/// Weights `b_i` (equal to the last row of `A`).
pub const B: [f64; STAGES] = [B1, B2, GAMMA];

/// Nodes `c_i = sum_j a_ij`.
pub const C: [f64; STAGES] = [GAMMA, (1.0 + GAMMA) / 2.0, 1.0];

/// Linear stability function `R(z) = 1 + z b^T (I - z A)^{-1} 1` of the tableau
/// (Hairer & Wanner II, Sect. IV.3), evaluated by forward substitution on the lower
/// triangular `I - z A`. One step of the method on `y' = lambda y` multiplies `y` by
/// `R(h lambda)`.
pub fn stability_function(z: Complex<f64>) -> Complex<f64> {
    let one = Complex::new(1.0, 0.0);
    let mut u = [Complex::new(0.0, 0.0); STAGES]; // u = (I - zA)^{-1} 1
    for i in 0..STAGES {
        let mut s = one;
        for j in 0..i {
            s += z * A[i][j] * u[j];
        }
        u[i] = s / (one - z * A[i][i]);
    }
    one + z * (0..STAGES).map(|i| B[i] * u[i]).sum::<Complex<f64>>()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tolerance for identities between O(1) coefficients: a few ulps of accumulated
    /// round-off in sums of ~6 products of numbers below 2.
    const TOL: f64 = 1e-14;

    #[test]
    fn order_conditions_up_to_three_hold() {
        // Butcher's order conditions (Hairer, Norsett & Wanner I, Table II.2.2).
        let sum_b: f64 = B.iter().sum();
        let sum_bc: f64 = (0..STAGES).map(|i| B[i] * C[i]).sum();
        let sum_bc2: f64 = (0..STAGES).map(|i| B[i] * C[i] * C[i]).sum();
        let sum_bac: f64 = (0..STAGES)
            .map(|i| B[i] * (0..STAGES).map(|j| A[i][j] * C[j]).sum::<f64>())
            .sum();
        assert!((sum_b - 1.0).abs() < TOL, "sum b = {sum_b}");
        assert!((sum_bc - 0.5).abs() < TOL, "sum b c = {sum_bc}");
        assert!((sum_bc2 - 1.0 / 3.0).abs() < TOL, "sum b c^2 = {sum_bc2}");
        assert!((sum_bac - 1.0 / 6.0).abs() < TOL, "sum b a c = {sum_bac}");
        // Row-sum condition c_i = sum_j a_ij and stiff accuracy a_3j = b_j.
        for i in 0..STAGES {
            let row: f64 = A[i].iter().sum();
            assert!((row - C[i]).abs() < TOL);
            assert_eq!(A[STAGES - 1][i], B[i]);
        }
        // Order is exactly 3, not 4: the fourth-order condition sum b c^3 = 1/4 fails.
        let sum_bc3: f64 = (0..STAGES).map(|i| B[i] * C[i].powi(3)).sum();
        assert!((sum_bc3 - 0.25).abs() > 1e-3);
    }

    #[test]
    fn gamma_is_the_l_stable_root_of_the_cubic() {
        // Independent root: Newton on p(x) = x^3 - 3x^2 + 3x/2 - 1/6 started at 0.4.
        let p = |x: f64| x * x * x - 3.0 * x * x + 1.5 * x - 1.0 / 6.0;
        let dp = |x: f64| 3.0 * x * x - 6.0 * x + 1.5;
        let mut x = 0.4;
        for _ in 0..50 {
            x -= p(x) / dp(x);
        }
        // Both are the same double up to the last-digit rounding of the literal.
        assert!((x - GAMMA).abs() < 4.0 * f64::EPSILON, "{x} vs {GAMMA}");
    }

    /// Closed form of an order-3 SDIRK stability function, which depends on gamma only:
    /// `R(z) = P(z) / (1 - gamma z)^3` with `P` the degree-3 Taylor part of
    /// `e^z (1 - gamma z)^3` (Hairer & Wanner II, Sect. IV.6). Computed
    /// without the tableau entries, so it checks them independently.
    fn closed_form_r(z: Complex<f64>) -> Complex<f64> {
        let g = GAMMA;
        let p1 = 1.0 - 3.0 * g;
        let p2 = 0.5 - 3.0 * g + 3.0 * g * g;
        let p3 = 1.0 / 6.0 - 1.5 * g + 3.0 * g * g - g * g * g;
        let num = 1.0 + z * (p1 + z * (p2 + z * p3));
        num / (1.0 - z * g).powi(3)
    }

    #[test]
    fn stability_function_matches_closed_form_and_is_l_stable() {
        for &(re, im) in &[
            (-0.5, 0.0),
            (-2.0, 1.0),
            (0.0, 0.3),
            (-1e3, 0.0),
            (-3.0, -40.0),
        ] {
            let z = Complex::new(re, im);
            let (r1, r2) = (stability_function(z), closed_form_r(z));
            // Both are O(1) rational expressions evaluated with ~20 flops.
            assert!((r1 - r2).norm() < 1e-13 * (1.0 + r2.norm()), "z = {z}");
        }
        // L-stability: R(z) = O(1/z) with leading term -p2 / (gamma^3 z), and
        // |p2| / gamma^3 = 0.2377 / 0.08281 = 2.87, so |R(-1e8)| = 2.87e-8.
        let r_stiff = stability_function(Complex::new(-1e8, 0.0)).norm();
        assert!(
            r_stiff < 3.0e-8 && r_stiff > 2.7e-8,
            "|R(-1e8)| = {r_stiff:e}"
        );
        let r_inf = stability_function(Complex::new(-1e15, 0.0)).norm();
        assert!(r_inf < 1e-14, "|R(-1e15)| = {r_inf:e}");
        // A-stability sampled on the imaginary axis (max principle: |R| <= 1 there and
        // analyticity in the left half plane give |R| <= 1 on it).
        for k in 0..2000 {
            let y = 1e-3 * 1.01_f64.powi(k);
            let r = stability_function(Complex::new(0.0, y)).norm();
            assert!(r <= 1.0 + 1e-15, "|R(i {y})| = {r}");
        }
    }
}
