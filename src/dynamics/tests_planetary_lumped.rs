//! Tests of the lumped planetary model: Lin & Parker's block matrices assembled by hand
//! and solved by a second eigensolver, their modal structure for N = 3, 4, 5, the
//! kinematic null mode (Willis), and the statics (torque balance, load shares).

use super::planetary_lumped::{ModeClass, PlanetaryLumped};
use crate::config::planetary::LumpedPlanetarySection;
use nalgebra::{DMatrix, DVector};
use std::f64::consts::PI;

/// A set of the size of Lin & Parker's example (masses and stiffnesses of their order),
/// its radii consistent (r_br = r_bs + 2 r_bp, r_c = (r_bs + r_bp) / cos alpha) so that
/// a rigid rotation of the whole set strains nothing.
fn section() -> LumpedPlanetarySection {
    let alpha = 24.6f64;
    let (rs, rp) = (24.0, 36.0);
    let rr = rs + 2.0 * rp;
    let rc = (rs + rp) / alpha.to_radians().cos();
    LumpedPlanetarySection {
        mass_sun_kg: 0.4,
        mass_planet_kg: 0.66,
        mass_ring_kg: 2.35,
        mass_carrier_kg: 5.43,
        inertia_sun_kg_m2: 0.39 * (rs * 1e-3f64).powi(2),
        inertia_planet_kg_m2: 0.61 * (rp * 1e-3f64).powi(2),
        inertia_ring_kg_m2: 3.0 * (rr * 1e-3f64).powi(2),
        inertia_carrier_kg_m2: 6.29 * (rc * 1e-3f64).powi(2),
        base_radius_sun_mm: rs,
        base_radius_planet_mm: rp,
        base_radius_ring_mm: rr,
        carrier_radius_mm: rc,
        mesh_stiffness_sun_planet_n_per_m: 5e8,
        mesh_stiffness_ring_planet_n_per_m: 5e8,
        bearing_stiffness_sun_n_per_m: 1e8,
        bearing_stiffness_planet_n_per_m: 1e8,
        bearing_stiffness_ring_n_per_m: 1e8,
        bearing_stiffness_carrier_n_per_m: 1e8,
        torsional_stiffness_sun_nm_per_rad: 0.0,
        torsional_stiffness_ring_nm_per_rad: 1e9 * (rr * 1e-3f64).powi(2),
        torsional_stiffness_carrier_nm_per_rad: 1e8 * (rc * 1e-3f64).powi(2),
        pressure_angle_deg: alpha,
    }
}

fn equal(n: usize) -> Vec<f64> {
    (0..n).map(|k| 2.0 * PI * k as f64 / n as f64).collect()
}

fn model(n: usize) -> PlanetaryLumped {
    PlanetaryLumped::from_section(&section(), equal(n)).unwrap()
}

/// Lin & Parker's (1999) stiffness blocks, written out element by element and placed by
/// hand: K_c1..K_c3 (carrier and planet bearings), K_s1..K_s3 (sun mesh), K_r1..K_r3
/// (ring mesh), plus the supports.
fn hand_stiffness(p: &PlanetaryLumped) -> DMatrix<f64> {
    let n = p.planet_angles_rad.len();
    let dof = 9 + 3 * n;
    let mut k = DMatrix::<f64>::zeros(dof, dof);
    let a = p.pressure_angle_rad;
    let (sa, ca) = a.sin_cos();
    let [ks, kr] = p.mesh_stiffness_n_per_m;
    let kp = p.bearing_n_per_m[3];
    let mut add = |r0: usize, c0: usize, b: [[f64; 3]; 3], sym: bool| {
        for i in 0..3 {
            for j in 0..3 {
                k[(r0 + i, c0 + j)] += b[i][j];
                if sym {
                    k[(c0 + j, r0 + i)] += b[i][j];
                }
            }
        }
    };
    for (q, psi) in p.planet_angles_rad.iter().enumerate() {
        let pl = 9 + 3 * q;
        let (s, c) = (psi - a).sin_cos();
        add(
            6,
            6,
            [
                [ks * s * s, -ks * s * c, -ks * s],
                [-ks * s * c, ks * c * c, ks * c],
                [-ks * s, ks * c, ks],
            ],
            false,
        );
        add(
            6,
            pl,
            [
                [ks * s * sa, ks * s * ca, -ks * s],
                [-ks * c * sa, -ks * c * ca, ks * c],
                [-ks * sa, -ks * ca, ks],
            ],
            true,
        );
        add(
            pl,
            pl,
            [
                [ks * sa * sa, ks * sa * ca, -ks * sa],
                [ks * sa * ca, ks * ca * ca, -ks * ca],
                [-ks * sa, -ks * ca, ks],
            ],
            false,
        );
        let (s, c) = (psi + a).sin_cos();
        add(
            3,
            3,
            [
                [kr * s * s, -kr * s * c, -kr * s],
                [-kr * s * c, kr * c * c, kr * c],
                [-kr * s, kr * c, kr],
            ],
            false,
        );
        add(
            3,
            pl,
            [
                [-kr * s * sa, kr * s * ca, kr * s],
                [kr * c * sa, -kr * c * ca, -kr * c],
                [kr * sa, -kr * ca, -kr],
            ],
            true,
        );
        add(
            pl,
            pl,
            [
                [kr * sa * sa, -kr * sa * ca, -kr * sa],
                [-kr * sa * ca, kr * ca * ca, kr * ca],
                [-kr * sa, kr * ca, kr],
            ],
            false,
        );
        let (s, c) = psi.sin_cos();
        add(
            0,
            0,
            [[kp, 0.0, -kp * s], [0.0, kp, kp * c], [-kp * s, kp * c, kp]],
            false,
        );
        add(
            0,
            pl,
            [
                [-kp * c, kp * s, 0.0],
                [-kp * s, -kp * c, 0.0],
                [0.0, -kp, 0.0],
            ],
            true,
        );
        add(
            pl,
            pl,
            [[kp, 0.0, 0.0], [0.0, kp, 0.0], [0.0, 0.0, 0.0]],
            false,
        );
    }
    for j in 0..3 {
        k[(3 * j, 3 * j)] += p.bearing_n_per_m[j];
        k[(3 * j + 1, 3 * j + 1)] += p.bearing_n_per_m[j];
        k[(3 * j + 2, 3 * j + 2)] += p.torsional_n_per_m[j];
    }
    k
}

#[test]
fn frequencies_equal_a_second_solution_of_hand_assembled_matrices() {
    for n in [3, 4, 5] {
        let p = model(n);
        let kh = hand_stiffness(&p);
        let k = p.stiffness();
        assert!((&k - &kh).abs().max() <= 1e-12 * kh.abs().max(), "N = {n}");
        // Second solver: the eigenvalues of the non-symmetric M^-1 K by Schur.
        let m = p.mass_diagonal();
        let a = DMatrix::from_fn(k.nrows(), k.ncols(), |i, j| kh[(i, j)] / m[i]);
        let mut lam: Vec<f64> = a.complex_eigenvalues().iter().map(|z| z.re).collect();
        lam.sort_by(f64::total_cmp);
        let modes = p.modes();
        for (mode, l) in modes.iter().zip(&lam) {
            let f = l.max(0.0).sqrt() / (2.0 * PI);
            assert!(
                (mode.frequency_hz - f).abs() <= 1e-9 * f,
                "N = {n}: {} vs {f}",
                mode.frequency_hz
            );
        }
    }
}

#[test]
fn modal_structure_is_lin_and_parkers() {
    // Rotational: 6 modes of multiplicity 1; translational: 6 pairs; planet modes: 3, each
    // of multiplicity N - 3 (Lin & Parker 1999, with 3 coordinates per member).
    for n in [3usize, 4, 5] {
        let p = model(n);
        let modes = p.modes();
        assert_eq!(modes.len(), 3 * (n + 3));
        let count = |c: ModeClass| modes.iter().filter(|m| m.class == c).count();
        assert_eq!(count(ModeClass::Rotational), 6, "N = {n}");
        assert_eq!(count(ModeClass::Translational), 12, "N = {n}");
        assert_eq!(count(ModeClass::Planet), 3 * (n - 3), "N = {n}");
        assert_eq!(count(ModeClass::Mixed), 0, "N = {n}");
        for m in &modes {
            let want = match m.class {
                ModeClass::Rotational => 1,
                ModeClass::Translational => 2,
                ModeClass::Planet => n - 3,
                ModeClass::Mixed => unreachable!(),
            };
            assert_eq!(
                m.multiplicity, want,
                "N = {n} {:?} at {} Hz",
                m.class, m.frequency_hz
            );
            let planet = |q: usize, c: usize| m.shape[9 + 3 * q + c];
            let scale = m.shape.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            match m.class {
                // Every planet moves alike.
                ModeClass::Rotational => {
                    for q in 1..n {
                        for c in 0..3 {
                            assert!((planet(q, c) - planet(0, c)).abs() < 1e-9 * scale);
                        }
                    }
                }
                // The planets' motions sum to nothing in each coordinate.
                ModeClass::Planet => {
                    for c in 0..3 {
                        let sum: f64 = (0..n).map(|q| planet(q, c)).sum();
                        assert!(sum.abs() < 1e-9 * scale, "{sum}");
                    }
                }
                _ => {}
            }
        }
    }
}

#[test]
fn unequal_spacing_breaks_the_structure() {
    let p = PlanetaryLumped::from_section(&section(), vec![0.0, 2.0, 4.5]).unwrap();
    assert!(p.modes().iter().any(|m| m.class == ModeClass::Mixed));
}

#[test]
fn mechanism_mode_follows_willis() {
    // With the sun's and the carrier's supports removed and the ring held, the set is a
    // mechanism: u_c = r_c theta_c, eta_n = u_c, u_s = 2 u_c cos(alpha), u_n = -u_c cos(alpha)
    // strains nothing, and theta_s / theta_c = 1 + r_br / r_bs (Willis with the ring fixed).
    let mut s = section();
    s.torsional_stiffness_carrier_nm_per_rad = 0.0;
    let p = PlanetaryLumped::from_section(&s, equal(4)).unwrap();
    let ca = p.pressure_angle_rad.cos();
    let mut v = DVector::zeros(p.dofs());
    v[2] = 1.0;
    v[8] = 2.0 * ca;
    for q in 0..4 {
        v[9 + 3 * q + 1] = 1.0;
        v[9 + 3 * q + 2] = -ca;
    }
    let k = p.stiffness();
    // Rounding only: K v ~ 1e-16 |K| |v|.
    assert!(
        (&k * &v).norm() < 1e-12 * k.norm() * v.norm(),
        "{}",
        (&k * &v).norm()
    );
    let [rc, rr, rs, _] = p.radius_m;
    let ratio = (v[8] / rs) / (v[2] / rc);
    assert!((ratio - (1.0 + rr / rs)).abs() < 1e-12, "{ratio}");
    // The lowest mode is that mechanism, at zero frequency.
    assert!(p.modes()[0].frequency_hz < 1e-3);
}

#[test]
fn statics_balance_torques_and_share_load_equally() {
    // Sun in (torque T on its u: T / r_bs), ring held by its torsional support, carrier
    // by its own (the load): T_carrier = -T (1 + r_br / r_bs), the three balance, and each
    // sun mesh carries T / (N r_bs).
    for n in [3usize, 4, 5] {
        let p = model(n);
        let [rc, rr, rs, _] = p.radius_m;
        let t_in = 100.0;
        let mut f = DVector::zeros(p.dofs());
        f[8] = t_in / rs;
        let q = p.static_response(&f).expect("grounded");
        let t_ring = -p.torsional_n_per_m[1] * q[5] * rr;
        let t_carrier = -p.torsional_n_per_m[0] * q[2] * rc;
        assert!((t_in + t_ring + t_carrier).abs() < 1e-9 * t_in);
        assert!(
            (t_carrier / t_in + (1.0 + rr / rs)).abs() < 1e-9,
            "{}",
            t_carrier / t_in
        );
        let (sun, ring) = p.mesh_loads(&q);
        for (fs, fr) in sun.iter().zip(&ring) {
            assert!((fs / (t_in / rs) - 1.0 / n as f64).abs() < 1e-9, "{fs}");
            assert!((fr - fs).abs() < 1e-9 * fs);
        }
    }
}

#[test]
fn bad_lumped_values_are_named() {
    let mut s = section();
    s.mass_sun_kg = -1.0;
    s.pressure_angle_deg = 60.0;
    let e = PlanetaryLumped::from_section(&s, equal(3))
        .unwrap_err()
        .messages();
    assert!(
        e.iter().any(|m| m.contains("planetary.lumped.mass_sun_kg")),
        "{e:?}"
    );
    assert!(
        e.iter()
            .any(|m| m.contains("planetary.lumped.pressure_angle_deg")),
        "{e:?}"
    );
}
