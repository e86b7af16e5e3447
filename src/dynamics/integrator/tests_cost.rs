//! Cost measurement on a 16-state system shaped like the gear model (prints only, no
//! assertion on timing). Run with
//! `cargo test --release --lib dynamics::integrator::tests_cost -- --ignored --nocapture
//! --test-threads=1`. Work counts are deterministic; times depend on the machine's load.

use std::hint::black_box;
use std::time::Instant;

use nalgebra::{Const, SMatrix, SVector};

use super::{OdeSystem, Rk4, Sdirk, SdirkOptions, StepStats, Stepper};

type V16 = SVector<f64, 16>;
type M16 = SMatrix<f64, 16, 16>;

/// 8 unit masses (kg) in a chain: springs 1e7 N/m with 2 % modal-like damping, a "mesh"
/// spring between DOF 3 and 4 of 2e8 N/m whose stiffness switches by +-30 % at 570 Hz
/// (single/double tooth contact) when `varying`, and a coupling damper of `c_coupling`
/// N s/m between DOF 5 and 6 (1.4e8 gives an eigenvalue near -2.8e8 1/s). State
/// `[x (m); v (m/s)]`, forced by 100 N at 30 Hz plus 1 kN static on DOF 0.
struct GearLike {
    varying: bool,
    c_coupling: f64,
    analytic_jacobian: bool,
}

impl GearLike {
    fn mesh_stiffness(&self, t: f64) -> f64 {
        let phase = (t * 570.0).fract();
        if self.varying && phase < 0.6 {
            2.6e8
        } else if self.varying {
            1.4e8
        } else {
            2e8
        }
    }

    /// Stiffness (N/m) and damping (N s/m) matrices at time t.
    fn matrices(&self, t: f64) -> (SMatrix<f64, 8, 8>, SMatrix<f64, 8, 8>) {
        let mut k = SMatrix::<f64, 8, 8>::zeros();
        let mut c = SMatrix::<f64, 8, 8>::zeros();
        let link = |m: &mut SMatrix<f64, 8, 8>, i: usize, j: usize, v: f64| {
            m[(i, i)] += v;
            m[(j, j)] += v;
            m[(i, j)] -= v;
            m[(j, i)] -= v;
        };
        for i in 0..7 {
            let ki = if i == 3 { self.mesh_stiffness(t) } else { 1e7 };
            link(&mut k, i, i + 1, ki);
            let ci = 2.0 * 0.02 * ki.sqrt();
            link(
                &mut c,
                i,
                i + 1,
                if i == 5 { ci + self.c_coupling } else { ci },
            );
        }
        for i in 0..8 {
            k[(i, i)] += 1e7; // bearing to ground
            c[(i, i)] += 2.0 * 0.02 * 1e7_f64.sqrt();
        }
        (k, c)
    }

    fn system_matrix(&self, t: f64) -> M16 {
        let (k, c) = self.matrices(t);
        let mut a = M16::zeros();
        a.fixed_view_mut::<8, 8>(0, 8).fill_with_identity();
        a.fixed_view_mut::<8, 8>(8, 0).copy_from(&(-k));
        a.fixed_view_mut::<8, 8>(8, 8).copy_from(&(-c));
        a
    }
}

/// `GearLike` with its two possible system matrices precomputed, so that `rhs` costs one
/// 16x16 matrix-vector product (the integrator's overhead is then visible).
struct Cached {
    model: GearLike,
    /// System matrices (1/s^2 and 1/s blocks) for mesh stiffness high / low.
    a_high: M16,
    a_low: M16,
}

impl Cached {
    fn new(model: GearLike) -> Self {
        let (a_high, a_low) = (model.system_matrix(0.0), model.system_matrix(0.9 / 570.0));
        Self {
            model,
            a_high,
            a_low,
        }
    }
    fn a(&self, t: f64) -> &M16 {
        if self.model.mesh_stiffness(t) >= 2e8 {
            &self.a_high
        } else {
            &self.a_low
        }
    }
}

impl OdeSystem<Const<16>> for Cached {
    fn rhs(&mut self, t: f64, y: &V16) -> V16 {
        let mut f = self.a(t) * y;
        f[8] += 1e3 + 100.0 * (2.0 * std::f64::consts::PI * 30.0 * t).cos();
        f
    }
    fn jacobian(&mut self, t: f64, _y: &V16) -> Option<M16> {
        self.model.analytic_jacobian.then(|| *self.a(t))
    }
}

fn time_steps<T: Stepper<Const<16>>>(
    stepper: &mut T,
    sys: &mut Cached,
    n: usize,
) -> (f64, StepStats) {
    let (mut t, mut y) = (0.0, V16::zeros());
    let start = Instant::now();
    let stats = stepper.advance(sys, &mut t, black_box(&mut y), n).unwrap();
    let ns = start.elapsed().as_nanos() as f64 / n as f64;
    assert!(y.iter().all(|v| v.is_finite()));
    (ns, stats)
}

fn report(label: &str, ns: f64, s: &StepStats) {
    let n = s.steps as f64;
    println!(
        "{label}: {ns:.0} ns/step, per step: {:.2} rhs, {:.2} Newton it., {:.4} J, {:.4} LU; retries {}",
        s.rhs_calls as f64 / n,
        s.newton_iterations as f64 / n,
        s.jacobian_evals as f64 / n,
        s.lu_factorizations as f64 / n,
        s.retries
    );
}

#[test]
#[ignore = "cost measurement, run in release with --ignored --nocapture"]
fn cost_per_step_on_16_state_system() {
    let n = 100_000;
    let h = 1e-5; // s, ~ mesh period / 175
    let opts = SdirkOptions::default();
    for analytic in [true, false] {
        let mut sys = Cached::new(GearLike {
            varying: false,
            c_coupling: 1.4e8,
            analytic_jacobian: analytic,
        });
        let mut s = Sdirk::<Const<16>>::new(h, opts).unwrap();
        let (ns, st) = time_steps(&mut s, &mut sys, n);
        report(
            &format!("SDIRK3 LTI stiff, analytic J = {analytic}"),
            ns,
            &st,
        );
    }
    for rate in [0.03, 0.1, 0.3, 0.5, 0.9] {
        let mut sys = Cached::new(GearLike {
            varying: true,
            c_coupling: 1.4e8,
            analytic_jacobian: false,
        });
        let o = SdirkOptions {
            refresh_rate: rate,
            ..opts
        };
        let mut s = Sdirk::<Const<16>>::new(h, o).unwrap();
        let (ns, st) = time_steps(&mut s, &mut sys, n);
        report(
            &format!("SDIRK3 switching mesh stiffness, FD J, refresh_rate {rate}"),
            ns,
            &st,
        );
    }
    let mut sys = Cached::new(GearLike {
        varying: false,
        c_coupling: 0.0,
        analytic_jacobian: false,
    });
    let mut rk = Rk4::<Const<16>>::new(h).unwrap();
    let (ns, st) = time_steps(&mut rk, &mut sys, n);
    report("RK4 non-stiff variant (no coupling damper)", ns, &st);
}
