//! Butcher tableaux of the diagonally implicit Runge-Kutta methods of [`super::Sdirk`].
//!
//! * [`ALEXANDER3`]: the 3-stage, order-3, L-stable, stiffly accurate SDIRK method of
//!   R. Alexander, "Diagonally implicit Runge-Kutta methods for stiff O.D.E.'s",
//!   SIAM J. Numer. Anal. 14(6), 1006-1021 (1977); also in Hairer & Wanner, *Solving
//!   ODEs II*, 2nd ed., Sect. IV.6. No embedded method: fixed steps only.
//!
//!   ```text
//!    gamma      | gamma
//!    (1+gamma)/2| (1-gamma)/2  gamma
//!    1          | b1           b2     gamma
//!   ------------+--------------------------
//!               | b1           b2     gamma
//!   ```
//!   with `b1 = -(6 gamma^2 - 16 gamma + 1)/4`, `b2 = (6 gamma^2 - 20 gamma + 5)/4`.
//! * [`ESDIRK32`]: ESDIRK3(2)4L\[2\]SA of C. A. Kennedy & M. H. Carpenter, "Diagonally
//!   implicit Runge-Kutta methods for ordinary differential equations. A review",
//!   NASA/TM-2016-219173 (2016), Sect. 5.2: 4 stages, the first explicit
//!   (`Y_1 = y_n`), order 3, L-stable, stiffly accurate, **stage order 2** (every stage
//!   satisfies `sum_j a_ij c_j = c_i^2 / 2`), with an embedded order-2 solution `b_hat`
//!   for error estimation. The stage order matters on the gear model: after each mesh
//!   stiffness jump the overdamped bearing velocities settle within a boundary layer of
//!   a few microseconds, where the accuracy of a stiff method is limited by its stage
//!   order (Prothero & Robinson, Math. Comp. 28 (1974) 145), 1 for any SDIRK method.
//!
//! Both share `gamma = 0.43586652150845899942`, the root in (1/3, 1/2) of
//! `gamma^3 - 3 gamma^2 + 3/2 gamma - 1/6 = 0`, which makes `R(infinity) = 0`
//! (L-stability) for a 3-implicit-stage order-3 method. All coefficients are
//! dimensionless.

use nalgebra::Complex;

/// Largest number of stages of a tableau here.
pub const MAX_STAGES: usize = 4;

/// Diagonal coefficient `gamma` (see module docs).
pub const GAMMA: f64 = 0.435_866_521_508_459;

/// A diagonally implicit Runge-Kutta tableau with a constant diagonal `gamma`, optionally
/// with an explicit first stage (`a_11 = 0`, ESDIRK) and an embedded solution.
#[derive(Debug, Clone, PartialEq)]
pub struct Tableau {
    /// Name of the method (in messages).
    pub name: &'static str,
    /// Number of stages used (at most `MAX_STAGES`).
    pub stages: usize,
    /// `a_ij`, lower triangular; `a_ii = gamma` except `a_11 = 0` for an ESDIRK.
    pub a: [[f64; MAX_STAGES]; MAX_STAGES],
    /// Weights `b_i` of the main solution.
    pub b: [f64; MAX_STAGES],
    /// Weights of the embedded lower-order solution, if any.
    pub b_hat: Option<[f64; MAX_STAGES]>,
    /// Nodes `c_i` (stage times as fractions of the step).
    pub c: [f64; MAX_STAGES],
    /// The constant diagonal coefficient gamma.
    pub gamma: f64,
    /// Classical order of the main and the embedded solution.
    pub order: u32,
    /// Classical order of the embedded solution (0 without one).
    pub embedded_order: u32,
}

impl Tableau {
    /// Whether stage 1 is explicit (`Y_1 = y_n`, `k_1 = f(t_n, y_n)`).
    pub fn explicit_first_stage(&self) -> bool {
        self.a[0][0] == 0.0
    }

    /// Linear stability function `R(z) = 1 + z b^T (I - z A)^{-1} 1` (Hairer & Wanner II,
    /// Sect. IV.3) of the main solution, or of the embedded one with `embedded`; one step
    /// on `y' = lambda y` multiplies `y` by `R(h lambda)`. Forward substitution on the
    /// lower triangular `I - z A`.
    pub fn stability_function(&self, z: Complex<f64>, embedded: bool) -> Complex<f64> {
        let one = Complex::new(1.0, 0.0);
        let mut u = [Complex::new(0.0, 0.0); MAX_STAGES]; // u = (I - zA)^{-1} 1
        for i in 0..self.stages {
            let s = (0..i).fold(one, |s, j| s + z * self.a[i][j] * u[j]);
            u[i] = s / (one - z * self.a[i][i]);
        }
        let w = match (embedded, self.b_hat) {
            (true, Some(bh)) => bh,
            _ => self.b,
        };
        one + z * (0..self.stages).map(|i| w[i] * u[i]).sum::<Complex<f64>>()
    }
}

const B1: f64 = -(6.0 * GAMMA * GAMMA - 16.0 * GAMMA + 1.0) / 4.0;
const B2: f64 = (6.0 * GAMMA * GAMMA - 20.0 * GAMMA + 5.0) / 4.0;

/// Alexander's SDIRK3 (see module docs).
pub const ALEXANDER3: Tableau = Tableau {
    name: "SDIRK3 (Alexander 1977)",
    stages: 3,
    a: [
        [GAMMA, 0.0, 0.0, 0.0],
        [(1.0 - GAMMA) / 2.0, GAMMA, 0.0, 0.0],
        [B1, B2, GAMMA, 0.0],
        [0.0; MAX_STAGES],
    ],
    b: [B1, B2, GAMMA, 0.0],
    b_hat: None,
    c: [GAMMA, (1.0 + GAMMA) / 2.0, 1.0, 0.0],
    gamma: GAMMA,
    order: 3,
    embedded_order: 0,
};

// ESDIRK3(2)4L[2]SA, Kennedy & Carpenter (2016), the published coefficients rounded
// to double precision.
const E_A31: f64 = 0.2576482460664272;
const E_A32: f64 = -0.09351476757488625;
const E_B1: f64 = 0.18764102434672383;
const E_B2: f64 = -0.595297473576955;
const E_B3: f64 = 0.9717899277217721;

/// ESDIRK3(2)4L\[2\]SA (see module docs).
pub const ESDIRK32: Tableau = Tableau {
    name: "ESDIRK3(2)4L[2]SA (Kennedy & Carpenter 2016)",
    stages: 4,
    a: [
        [0.0, 0.0, 0.0, 0.0],
        [GAMMA, GAMMA, 0.0, 0.0],
        [E_A31, E_A32, GAMMA, 0.0],
        [E_B1, E_B2, E_B3, GAMMA],
    ],
    b: [E_B1, E_B2, E_B3, GAMMA],
    b_hat: Some([
        0.10889661761586446,
        -0.9153258118707127,
        1.271273597302152,
        0.5351555969526961,
    ]),
    c: [0.0, 2.0 * GAMMA, 0.6, 1.0],
    gamma: GAMMA,
    order: 3,
    embedded_order: 2,
};

#[cfg(test)]
mod tests {
    use super::*;

    /// Tolerance for identities between O(1) coefficients: a few ulps of accumulated
    /// round-off in sums of ~8 products of numbers below 2, and the 19-20 digits the
    /// published coefficients are given to.
    const TOL: f64 = 1e-14;

    /// `sum_i w_i phi_i` over the stages.
    fn dot(t: &Tableau, w: &[f64; MAX_STAGES], phi: impl Fn(usize) -> f64) -> f64 {
        (0..t.stages).map(|i| w[i] * phi(i)).sum()
    }

    /// `sum_j a_ij c_j`.
    fn ac(t: &Tableau, i: usize) -> f64 {
        (0..t.stages).map(|j| t.a[i][j] * t.c[j]).sum()
    }

    fn check_order_three(t: &Tableau) {
        // Butcher's order conditions (Hairer, Norsett & Wanner I, Table II.2.2).
        let b = &t.b;
        assert!((dot(t, b, |_| 1.0) - 1.0).abs() < TOL, "{}", t.name);
        assert!((dot(t, b, |i| t.c[i]) - 0.5).abs() < TOL, "{}", t.name);
        assert!((dot(t, b, |i| t.c[i] * t.c[i]) - 1.0 / 3.0).abs() < TOL);
        assert!((dot(t, b, |i| ac(t, i)) - 1.0 / 6.0).abs() < TOL);
        // Not order 4: the condition sum b c^3 = 1/4 fails.
        assert!((dot(t, b, |i| t.c[i].powi(3)) - 0.25).abs() > 1e-3);
        for i in 0..t.stages {
            // Row sums c_i = sum_j a_ij, and stiff accuracy a_sj = b_j.
            let row: f64 = t.a[i].iter().sum();
            assert!((row - t.c[i]).abs() < TOL, "{} row {i}", t.name);
            assert_eq!(t.a[t.stages - 1][i], t.b[i]);
            // Constant diagonal (except an explicit first stage).
            if i > 0 || !t.explicit_first_stage() {
                assert_eq!(t.a[i][i], t.gamma);
            }
        }
    }

    #[test]
    fn order_conditions_up_to_three_hold() {
        check_order_three(&ALEXANDER3);
        check_order_three(&ESDIRK32);
    }

    #[test]
    fn esdirk_has_stage_order_two_and_an_order_two_embedding() {
        let t = &ESDIRK32;
        // Stage order 2: every stage integrates t exactly (Kennedy & Carpenter, Sect. 2).
        for i in 0..t.stages {
            assert!((ac(t, i) - 0.5 * t.c[i] * t.c[i]).abs() < TOL, "stage {i}");
        }
        // Embedded order 2, not 3.
        let bh = t.b_hat.unwrap();
        assert!((dot(t, &bh, |_| 1.0) - 1.0).abs() < TOL);
        assert!((dot(t, &bh, |i| t.c[i]) - 0.5).abs() < TOL);
        assert!((dot(t, &bh, |i| t.c[i] * t.c[i]) - 1.0 / 3.0).abs() > 1e-3);
        // Alexander's method has stage order 1 only: its first stage fails it.
        assert!((ac(&ALEXANDER3, 0) - 0.5 * GAMMA * GAMMA).abs() > 1e-2);
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

    /// Closed form of the stability function of any method with 3 implicit stages of
    /// diagonal gamma and order 3: `R(z) = P(z) / (1 - gamma z)^3` with `P` the degree-3
    /// Taylor part of `e^z (1 - gamma z)^3` (Hairer & Wanner II, Sect. IV.6). Computed
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
    fn stability_functions_match_closed_form_and_are_l_stable() {
        for t in [&ALEXANDER3, &ESDIRK32] {
            for &(re, im) in &[
                (-0.5, 0.0),
                (-2.0, 1.0),
                (0.0, 0.3),
                (-1e3, 0.0),
                (-3.0, -40.0),
            ] {
                let z = Complex::new(re, im);
                let (r1, r2) = (t.stability_function(z, false), closed_form_r(z));
                // Both are O(1) rational expressions evaluated with ~30 flops; for the
                // ESDIRK, z b^T u cancels to ~1 from terms of size |z| (its explicit stage
                // keeps u_1 = 1), so the round-off grows like eps |z|.
                let tol = 1e-13 * (1.0 + r2.norm()) + 1e-15 * z.norm();
                assert!((r1 - r2).norm() < tol, "{} z = {z}", t.name);
            }
            // L-stability: R(z) = O(1/z) with leading term -p2 / (gamma^3 z), and
            // |p2| / gamma^3 = 0.2377 / 0.08281 = 2.870; the O(1/z^2) term is 1e-5 of it
            // at z = -1e5.
            let r = t.stability_function(Complex::new(-1e5, 0.0), false).norm();
            assert!(
                (r * 1e5 - 2.870).abs() < 1e-3,
                "{} |R(-1e5)| = {r:e}",
                t.name
            );
        }
        // Alexander's stages have no explicit part: R vanishes to round-off.
        let r_stiff = ALEXANDER3
            .stability_function(Complex::new(-1e8, 0.0), false)
            .norm();
        assert!(
            r_stiff < 3.0e-8 && r_stiff > 2.7e-8,
            "|R(-1e8)| = {r_stiff:e}"
        );
        let r_inf = ALEXANDER3
            .stability_function(Complex::new(-1e15, 0.0), false)
            .norm();
        assert!(r_inf < 1e-14, "|R(-1e15)| = {r_inf:e}");
        // The ESDIRK's limit is the round-off eps |z| above (|h lambda| <= 1e5 on the
        // gear model): still damping at an absurd |z| = 1e12.
        let r_big = ESDIRK32
            .stability_function(Complex::new(-1e12, 0.0), false)
            .norm();
        assert!(r_big < 1e-3, "|R(-1e12)| = {r_big:e}");
        // A-stability sampled on the imaginary axis (max principle: |R| <= 1 there and
        // analyticity in the left half plane give |R| <= 1 on it), for both solutions
        // of the pair: the embedded one must not amplify the stiff modes either.
        for (t, emb) in [(&ALEXANDER3, false), (&ESDIRK32, false), (&ESDIRK32, true)] {
            for k in 0..2000 {
                let y = 1e-3 * 1.01_f64.powi(k);
                let r = t.stability_function(Complex::new(0.0, y), emb).norm();
                assert!(r <= 1.0 + 1e-15, "{} |R(i {y})| = {r}", t.name);
            }
        }
    }
}
