//! Damped modes checked against independent facts: the eigenvalues of the dense state
//! matrix (a second solver, on another form of the matrix), the quadratic pencil's
//! singularity at each pole, the undamped limit, and the forced response of the linear
//! model in the time domain, whose peak must sit at the damped mesh pole.

use gearwear::config::load_case;
use gearwear::dynamics::damped_modes::damped_modes;
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::integrator::{OdeSystem, Sdirk, SdirkOptions, Stepper};
use gearwear::dynamics::modal::modes;
use gearwear::dynamics::model::{GearSystem, NDOF};
use gearwear::study::Model;
use nalgebra::{Complex, Const, DMatrix, SMatrix, SVector};

/// The model on the nominal path: the hand linearisation below takes the table's mean
/// mesh stiffness, which is the loaded mean there; with corner contact the modes take the
/// loaded mean (corners included), which tests/corner_contact.rs checks by a second method.
fn model(sets: &[&str]) -> Model {
    let mut sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    sets.insert(0, "contact.path=nominal".into());
    Model::from_case(&load_case("", &sets).expect("valid case")).expect("valid model")
}

/// The linearised matrices assembled here from the model's parts (free coordinates only):
/// mass (diagonal), stiffness K_lin + k_mean g g^T, damping C_lin + c_m g g^T.
/// Independent of `modal::linearised_matrices` and `damped_modes::linearised_damping`.
struct Linear {
    mass: Vec<f64>,
    k: DMatrix<f64>,
    c: DMatrix<f64>,
    k_mean: f64,
    c_mesh: f64,
}

fn linear_of(sys: &GearSystem) -> Linear {
    let (k_lin, c_lin, inv_mass) = sys.linear_parts();
    let free: Vec<usize> = (0..NDOF).filter(|i| inv_mass[*i] > 0.0).collect();
    let g: Vec<f64> = free.iter().map(|&i| sys.mesh_gradient(0)[i]).collect();
    let k_mean = sys.mesh(0).parts.mesh.mean_stiffness_n_per_m();
    let c_mesh = sys.mesh(0).mesh_damping_n_s_per_m;
    let n = free.len();
    Linear {
        mass: free.iter().map(|&i| 1.0 / inv_mass[i]).collect(),
        k: DMatrix::from_fn(n, n, |a, b| {
            k_lin[(free[a], free[b])] + k_mean * g[a] * g[b]
        }),
        c: DMatrix::from_fn(n, n, |a, b| {
            c_lin[(free[a], free[b])] + c_mesh * g[a] * g[b]
        }),
        k_mean,
        c_mesh,
    }
}

const BOUNDARIES: [&str; 3] = ["motor_slip", "motor_speed_imposed", "brake_speed_imposed"];

/// lambda^2 M + lambda C + K and its derivative 2 lambda M + C.
fn pencil(lin: &Linear, lam: Complex<f64>, derivative: bool) -> DMatrix<Complex<f64>> {
    let n = lin.mass.len();
    DMatrix::from_fn(n, n, |i, j| {
        let m = if i == j { lin.mass[i] } else { 0.0 };
        if derivative {
            lam * (2.0 * m) + lin.c[(i, j)]
        } else {
            lam * lam * m + lam * lin.c[(i, j)] + Complex::new(lin.k[(i, j)], 0.0)
        }
    })
}

/// Backward error of lambda as an eigenvalue of the pencil (Tisseur, Linear Algebra
/// Appl. 309 (2000) 339): sigma_min(D(lambda)) / (|lambda|^2 |M| + |lambda| |C| + |K|).
fn backward_error(lin: &Linear, lam: Complex<f64>) -> f64 {
    let norm = |m: &DMatrix<f64>| m.singular_values()[0];
    let m_norm = lin.mass.iter().copied().fold(0.0, f64::max);
    let sv = pencil(lin, lam, false).singular_values();
    sv[sv.len() - 1] / (lam.norm_sqr() * m_norm + lam.norm() * norm(&lin.c) + norm(&lin.k))
}

#[test]
fn damped_poles_are_the_state_matrix_eigenvalues_and_roots_of_the_pencil() {
    for boundary in BOUNDARIES {
        let m = model(&[&format!("operating.speed_boundary={boundary}")]);
        let (gap, ext) = (PairGap::none(), ExternalError::none());
        let sys = m.system(&gap, &ext, 0.2);
        let lin = linear_of(&sys);
        let n = lin.mass.len();
        // First method: the dense state matrix [[0, I], [-M^-1 K, -M^-1 C]] in the
        // physical coordinates (the implementation works in mass-normalised ones).
        let a = DMatrix::from_fn(2 * n, 2 * n, |i, j| match (i < n, j < n) {
            (true, true) => 0.0,
            (true, false) => f64::from(j == n + i),
            (false, true) => -lin.k[(i - n, j)] / lin.mass[i - n],
            (false, false) => -lin.c[(i - n, j - n)] / lin.mass[i - n],
        });
        let a_norm = a.singular_values()[0];
        // The rigid rotation of the free drivetrain (motor_slip) has lambda = 0: round-off
        // leaves ~1e-8 1/s there, the slowest physical pole is ~1e3 1/s.
        let dense: Vec<Complex<f64>> = a
            .complex_eigenvalues()
            .iter()
            .copied()
            .filter(|z| z.im >= 0.0 && z.norm() > 1e-3)
            .collect();
        let poles = damped_modes(&sys).modes;
        assert_eq!(poles.len(), dense.len(), "{boundary}");
        let mut used = vec![false; dense.len()];
        for p in &poles {
            let lam = Complex::new(p.real_per_s, p.imag_rad_per_s);
            let (j, dist) = dense
                .iter()
                .enumerate()
                .map(|(j, z)| (j, (z - lam).norm()))
                .min_by(|x, y| x.1.total_cmp(&y.1))
                .unwrap();
            // A backward-stable eigen-solver returns an eigenvalue of A + E with
            // |E| ~ eps |A|, which moves a simple eigenvalue by at most ~kappa eps |A|,
            // kappa = |x| |y| / |y^H x| its condition number (Wilkinson). With x = [v;
            // lambda v] and y = [(lambda M + C)^H u; M u] (v, u the right and left null
            // vectors of the pencil), y^H x = u^H (2 lambda M + C) v. The coupling and
            // bearing dampers put several poles close together (kappa up to ~4e5 here)
            // and |A| ~ 2e11, so the bound ranges from 0.05 to ~20 1/s.
            let svd = pencil(&lin, lam, false).svd(true, true);
            let (u, v) = (svd.u.unwrap(), svd.v_t.unwrap());
            let u = u.column(n - 1).into_owned();
            let v = v.row(n - 1).adjoint();
            let x_norm = v.norm() * (1.0 + lam.norm_sqr()).sqrt();
            let lmc = pencil(&lin, lam, true)
                - DMatrix::from_fn(n, n, |i, j| {
                    Complex::new(if i == j { lin.mass[i] } else { 0.0 }, 0.0) * lam
                });
            let y1 = lmc.adjoint() * &u;
            let y_norm = (y1.norm_squared()
                + (0..n).map(|i| (u[i] * lin.mass[i]).norm_sqr()).sum::<f64>())
            .sqrt();
            let kappa =
                x_norm * y_norm / (u.adjoint() * pencil(&lin, lam, true) * &v)[(0, 0)].norm();
            let bound = kappa * f64::EPSILON * a_norm;
            assert!(
                dist <= bound,
                "{boundary}: {lam} vs {}: {dist:e} > {bound:e}",
                dense[j]
            );
            assert!(!used[j], "{boundary}: two poles match {}", dense[j]);
            used[j] = true;
            // Second method: lambda^2 M + lambda C + K is singular at every pole: its
            // backward error (the smallest relative change of M, C, K that makes lambda
            // exact) is of order eps for a backward-stable solution; 1e-12 is ~5000 eps.
            // One per cent away from a pole it is about 1e-2 over the pole's condition
            // number, above 1e-9 for every pole here: the check can fail.
            let eta = backward_error(&lin, lam);
            let eta_off = backward_error(&lin, lam * 1.01);
            assert!(
                eta < 1e-12,
                "{boundary}: pole {lam}: backward error {eta:e}"
            );
            assert!(eta_off > 1e-9, "{boundary}: {lam}: 1 % off: {eta_off:e}");
        }
        // Exactly one oscillatory mesh pole in the default case (docs/MODEL.md).
        assert_eq!(
            damped_modes(&sys).mesh_poles().len(),
            1,
            "{boundary}: one mesh pole"
        );
    }
}

#[test]
fn without_damping_the_poles_are_the_undamped_natural_frequencies() {
    for boundary in BOUNDARIES {
        let mut m = model(&[
            &format!("operating.speed_boundary={boundary}"),
            // Friction makes the state matrix non-symmetric (its moment arms move with
            // the contact point): only the conservative model has purely imaginary poles.
            "friction.model=none",
            "dynamics.mesh_damping_ratio=0",
            "dynamics.bearing_damping_pinion_n_s_per_m=0",
            "dynamics.bearing_damping_gear_n_s_per_m=0",
            "dynamics.coupling_damping_motor_nm_s_per_rad=0",
            "dynamics.coupling_damping_brake_nm_s_per_rad=0",
        ]);
        // The slip law's damper (the case file requires c_slip > 0) removed by hand.
        m.params.motor_slip_damping_nm_s_per_rad = 0.0;
        let (gap, ext) = (PairGap::none(), ExternalError::none());
        let sys = m.system(&gap, &ext, 0.2);
        let undamped: Vec<f64> = modes(&sys)
            .frequency_hz
            .into_iter()
            .filter(|f| *f > 1e-3) // the rigid rotation of motor_slip
            .collect();
        let poles = damped_modes(&sys).modes;
        assert_eq!(poles.len(), undamped.len(), "{boundary}");
        for (p, f) in poles.iter().zip(&undamped) {
            // Undamped: lambda = +-i omega_n, so zeta = 0 and |Im lambda| = omega_n. Both
            // are double-precision eigen-solutions (symmetric vs. non-symmetric Schur):
            // 1e-6 relative, as for the undamped check above; zeta to 1e-9 (Re lambda is
            // round-off, ~1e-5 1/s against omega ~ 5e3-4e5 rad/s).
            assert!(
                (p.damped_frequency_hz - f).abs() < 1e-6 * f,
                "{boundary}: {} vs {f}",
                p.damped_frequency_hz
            );
            assert!(
                p.damping_ratio.abs() < 1e-9,
                "{boundary}: zeta {}",
                p.damping_ratio
            );
        }
    }
}

/// The linear model with constant (mean) mesh stiffness driven by a transmission error
/// e(t) = a sin(w t) through the mesh spring and damper (paper eq. 2 sign: the mesh
/// force is k (delta + e) + c (d delta/dt + de/dt)), in the 8 coordinates (an imposed
/// coordinate has zero inverse mass).
struct ForcedLinear {
    a: SMatrix<f64, 16, 16>,
    b_e: SVector<f64, 16>,
    b_de: SVector<f64, 16>,
    omega: f64,
}

impl OdeSystem<Const<16>> for ForcedLinear {
    fn rhs(&mut self, t: f64, y: &SVector<f64, 16>) -> SVector<f64, 16> {
        let (s, c) = (self.omega * t).sin_cos();
        self.a * y + self.b_e * s + self.b_de * (self.omega * c)
    }
    fn jacobian(&mut self, _t: f64, _y: &SVector<f64, 16>) -> Option<SMatrix<f64, 16, 16>> {
        Some(self.a)
    }
}

/// Steady amplitude of the DTE (delta = g^T q) per unit TE amplitude at `f_hz`, by time
/// integration (SDIRK, 64 steps per forcing period) through the transient, then the
/// Fourier coefficient of delta over 4 whole periods.
fn dte_gain(sys: &GearSystem, lin: &Linear, f_hz: f64) -> f64 {
    let (k_lin, c_lin, inv_mass) = sys.linear_parts();
    let g = sys.mesh_gradient(0);
    let mut a = SMatrix::<f64, 16, 16>::zeros();
    let (mut b_e, mut b_de) = (SVector::<f64, 16>::zeros(), SVector::<f64, 16>::zeros());
    for i in 0..NDOF {
        a[(i, NDOF + i)] = 1.0;
        for j in 0..NDOF {
            let k = k_lin[(i, j)] + lin.k_mean * g[i] * g[j];
            let c = c_lin[(i, j)] + lin.c_mesh * g[i] * g[j];
            a[(NDOF + i, j)] = -k * inv_mass[i];
            a[(NDOF + i, NDOF + j)] = -c * inv_mass[i];
        }
        b_e[NDOF + i] = -lin.k_mean * g[i] * inv_mass[i];
        b_de[NDOF + i] = -lin.c_mesh * g[i] * inv_mass[i];
    }
    let omega = 2.0 * std::f64::consts::PI * f_hz;
    let mut ode = ForcedLinear {
        a,
        b_e,
        b_de,
        omega,
    };
    let steps = 64;
    let h = 1.0 / (f_hz * steps as f64);
    let mut sd = Sdirk::<Const<16>>::new(h, SdirkOptions::default()).unwrap();
    // The slowest decaying pole of the three boundaries has Re lambda ~ -820 1/s
    // (tau = 1.2 ms): 20 ms of transient leaves e^-16 ~ 1e-7 of it.
    let transient = (0.02 * f_hz).ceil() as usize;
    let (mut t, mut y) = (0.0, SVector::<f64, 16>::zeros());
    sd.advance(&mut ode, &mut t, &mut y, transient * steps)
        .unwrap();
    let (mut cs, mut sn) = (0.0, 0.0);
    let periods = 4;
    for _ in 0..periods * steps {
        // Rectangle rule on whole periods: exact for the harmonic itself.
        let delta: f64 = (0..NDOF).map(|i| g[i] * y[i]).sum();
        cs += delta * (omega * t).cos();
        sn += delta * (omega * t).sin();
        sd.step(&mut ode, t, &mut y).unwrap();
        t += h;
    }
    let n = (periods * steps) as f64;
    2.0 * (cs * cs + sn * sn).sqrt() / n
}

#[test]
fn dte_response_to_a_harmonic_transmission_error_peaks_at_the_damped_mesh_pole() {
    for boundary in BOUNDARIES {
        let m = model(&[&format!("operating.speed_boundary={boundary}")]);
        let (gap, ext) = (PairGap::none(), ExternalError::none());
        let sys = m.system(&gap, &ext, 0.2);
        let lin = linear_of(&sys);
        let dm = damped_modes(&sys);
        let pole = dm.mesh_poles()[0].clone();
        let f_d = pole.damped_frequency_hz;
        // Coarse scan at 2 % of f_d, then 0.2 % around the best, then a parabola
        // through the best three points.
        let scan = |lo: f64, step: f64, n: usize| -> (f64, f64, f64) {
            let pts: Vec<(f64, f64)> = (0..n)
                .map(|i| {
                    let f = lo + step * i as f64;
                    (f, dte_gain(&sys, &lin, f))
                })
                .collect();
            let k = (1..n - 1)
                .max_by(|a, b| pts[*a].1.total_cmp(&pts[*b].1))
                .unwrap();
            let (y0, y1, y2) = (pts[k - 1].1, pts[k].1, pts[k + 1].1);
            let shift = 0.5 * (y0 - y2) / (y0 - 2.0 * y1 + y2);
            (pts[k].0 + shift * step, pts[k].0, y1)
        };
        let (_, coarse, _) = scan(0.6 * f_d, 0.02 * f_d, 41);
        let (f_peak, _, gain) = scan(coarse - 0.02 * f_d, 0.002 * f_d, 21);
        // Where the peak must be: for one mode of damping ratio zeta, every response
        // ratio peaks between omega_n (1 - zeta^2) and omega_n (omega_n = |lambda|): the
        // receptance at omega_n sqrt(1 - 2 zeta^2), the mobility at omega_n, the ratio
        // (k + i c w) / (k - m w^2 + i c w) that maps a TE to the DTE at
        // omega_n sqrt(sqrt(1 + 8 zeta^2) - 1) / (2 zeta). The damped frequency
        // omega_d = omega_n sqrt(1 - zeta^2) lies in that interval, so the peak is
        // within zeta^2 f_n of f_d; the parabola through points 0.2 % apart adds
        // < 0.1 % of f_d (the peak is ~2 zeta f_n >> 0.2 % wide).
        let tol = pole.damping_ratio.powi(2) * pole.pole_magnitude_hz + 1e-3 * f_d;
        assert!(
            (f_peak - f_d).abs() < tol,
            "{boundary}: DTE gain {gain:.3} peaks at {f_peak:.1} Hz, mesh pole {f_d:.1} Hz (tol {tol:.1})"
        );
        // The undamped modes do not explain it: the peak is farther from every one of
        // them than the tolerance.
        for f_u in modes(&sys).frequency_hz {
            assert!((f_peak - f_u).abs() > tol, "{boundary}: undamped {f_u} Hz");
        }
    }
}
