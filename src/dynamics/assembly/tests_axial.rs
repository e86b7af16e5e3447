//! The axial coordinates of a helical pair (docs/MODEL.md 11.6) against matrices written
//! out by hand, and the axial-torsional coupling against the closed form of a 2-DOF
//! system.

use super::elements::{AxialBearing, Body, BodyKind, Drive, Elements, MeshLink};
use super::tests_assembly::paper_by_hand;
use super::{Assembly, Dof};
use crate::config::case::{Case, SpeedBoundary};
use crate::dynamics::params::{AxialSupport, DynamicParams};
use crate::geometry::GearPair;
use nalgebra::{DMatrix, DVector};

/// The paper's 8 x 8 hand matrices grown by the axial block of `bearings` (pinion, gear):
/// inverse masses, K, C, and the gradient with its axial entries +a on z_p, -a on z_g.
fn with_axial_by_hand(
    p: &DynamicParams,
    pair: &GearPair,
    a: f64,
    bearings: [Option<(f64, f64)>; 2],
) -> (Vec<f64>, DMatrix<f64>, DMatrix<f64>, DVector<f64>) {
    let (mut inv, k8, c8, _, g8) = paper_by_hand(p, pair);
    let n = 8 + bearings.iter().flatten().count();
    let (mut k, mut c) = (DMatrix::zeros(n, n), DMatrix::zeros(n, n));
    k.view_mut((0, 0), (8, 8)).copy_from(&k8);
    c.view_mut((0, 0), (8, 8)).copy_from(&c8);
    let mut g = DVector::zeros(n);
    g.rows_mut(0, 8).copy_from(&g8);
    let masses = [p.lumped.mass_pinion_kg, p.lumped.mass_gear_kg];
    let mut z = 8;
    for (body, bearing) in bearings.iter().enumerate() {
        if let Some((kz, cz)) = bearing {
            inv.push(1.0 / masses[body]);
            k[(z, z)] = *kz;
            c[(z, z)] = *cz;
            g[z] = if body == 0 { a } else { -a };
            z += 1;
        }
    }
    (inv, k, c, g)
}

#[test]
fn axial_bearings_add_a_block_after_the_rotations() {
    let mut case = Case::default();
    case.operating.speed_boundary = SpeedBoundary::MotorSlip;
    let pair = GearPair::from_case(&case.gear).unwrap();
    let mut p = DynamicParams::from_case(&case, &pair);
    // tan(beta_b) of 15 deg on the paper's pair, and distinct bearings.
    let a = -0.2513;
    for bearings in [
        [Some((3.1e8, 2.2e5)), Some((7.3e8, 5.1e5))],
        [None, Some((7.3e8, 5.1e5))],
        [Some((3.1e8, 2.2e5)), None],
    ] {
        p.axial = Some(AxialSupport {
            axial_gradient: a,
            bearings,
        });
        let asm = Assembly::new(Elements::single_pair(&p, &pair)).unwrap();
        let (inv, k, c, g) = with_axial_by_hand(&p, &pair, a, bearings);
        let n = inv.len();
        assert_eq!(asm.len(), n, "{bearings:?}");
        assert_eq!(asm.inverse_masses(), &inv[..], "{bearings:?}");
        assert_eq!(asm.stiffness(), &k, "{bearings:?}");
        assert_eq!(asm.damping(), &c, "{bearings:?}");
        assert_eq!(asm.mesh_gradient(0), g, "{bearings:?}");
        // The lateral and rotation blocks keep their numbers; z follows the rotations.
        assert_eq!(asm.index(3, Dof::Rotation), Some(7));
        let z_p = bearings[0].map(|_| 8);
        let z_g = bearings[1].map(|_| 8 + usize::from(bearings[0].is_some()));
        assert_eq!(
            (asm.index(1, Dof::Axial), asm.index(2, Dof::Axial)),
            (z_p, z_g)
        );
        // The mean-stiffness matrix carries the axial-torsional coupling: written out
        // entry by entry where it is new (k r_b1 a between phi_p and z_p, k a^2 on z_p),
        // products in the assembly's order (g_i g_j k), so equal bit for bit.
        let km = 3.1e8;
        let kt = asm.stiffness_with_meshes(&[km]);
        assert_eq!(kt, &k + &g * g.transpose() * km);
        if let Some(z) = z_p {
            assert_eq!(kt[(5, z)], pair.pinion.base_radius_m * a * km);
            assert_eq!(kt[(z, z)], k[(z, z)] + a * a * km);
        }
        if let (Some(zp), Some(zg)) = (z_p, z_g) {
            assert_eq!(kt[(zp, zg)], -(a * a * km));
        }
        let names: Vec<String> = asm.coordinate_names().into_iter().map(|x| x.0).collect();
        assert_eq!(names[7], "phi_brake");
        if let Some(z) = z_g {
            assert_eq!(names[z], "z_gear");
        }
    }
}

#[test]
fn without_axial_support_the_single_pair_is_unchanged() {
    let case = Case::default();
    let pair = GearPair::from_case(&case.gear).unwrap();
    let p = DynamicParams::from_case(&case, &pair);
    let asm = Assembly::new(Elements::single_pair(&p, &pair)).unwrap();
    assert_eq!(asm.len(), 8);
    assert!(asm.meshes()[0].axial.iter().all(Option::is_none));
}

/// A pinion that turns and slides axially against a gear whose rotation is imposed: the
/// 2-DOF system (phi_p, z_p) with M = diag(J, m) and
/// K = [[k r^2, k r a], [k r a, k_a + k a^2]] (the mesh spring k along the gradient
/// (r, a) plus the axial bearing k_a). Its omega^2 are the roots of
/// omega^4 - T omega^2 + D = 0, T = k r^2 / J + (k_a + k a^2) / m, D = k k_a r^2 / (J m).
#[test]
fn a_pinion_sliding_against_a_held_gear_has_the_closed_form_frequencies() {
    let (j, m, r, rg, a, k, ka) = (2.331e-4, 0.7, 0.0178, 0.0291, -0.2513, 3.4e8, 5e8);
    let body = |name: &str, kind| Body {
        name: name.into(),
        kind,
        mass_kg: m,
        inertia_kg_m2: j,
        lateral: false,
    };
    let e = Elements {
        bodies: vec![body("pinion", BodyKind::Gear), body("gear", BodyKind::Gear)],
        bearings: Vec::new(),
        shafts: Vec::new(),
        meshes: vec![MeshLink {
            pinion: 0,
            gear: 1,
            teeth: [19, 31],
            base_radius_m: [r, rg],
            pressure_angle_rad: 0.35,
            centre_line_rad: 0.0,
            axial_gradient: a,
            tilt: None,
        }],
        axial_bearings: vec![AxialBearing {
            body: 0,
            stiffness_n_per_m: ka,
            damping_n_s_per_m: 0.0,
        }],
        tilt_bearings: Vec::new(),
        drive: Drive {
            input: 1,
            output: 0,
            boundary: SpeedBoundary::MotorSpeedImposed,
            input_torque_nm: 0.0,
            output_torque_nm: 10.0,
            slip_damping_nm_s_per_rad: 0.0,
        },
    };
    let asm = Assembly::new(e).unwrap();
    // Free coordinates: phi_p and z_p (the gear's rotation is held: inverse mass 0).
    let kt = asm.stiffness_with_meshes(&[k]);
    let inv = asm.inverse_masses();
    let free: Vec<usize> = (0..asm.len()).filter(|i| inv[*i] > 0.0).collect();
    assert_eq!(free.len(), 2);
    let a_mat = DMatrix::from_fn(2, 2, |i, l| inv[free[i]] * kt[(free[i], free[l])]);
    let mut w2: Vec<f64> = a_mat.complex_eigenvalues().iter().map(|z| z.re).collect();
    w2.sort_by(f64::total_cmp);
    let t = k * r * r / j + (ka + k * a * a) / m;
    let d = k * ka * r * r / (j * m);
    let disc = (0.25 * t * t - d).sqrt();
    let closed = [0.5 * t - disc, 0.5 * t + disc];
    for (got, want) in w2.iter().zip(closed) {
        // Both roots ~1e9..1e13 rad^2/s^2: a 2 x 2 eigen-solve is exact to a few ulps of
        // the larger one, so 1e-9 relative to the larger root bounds it.
        assert!((got - want).abs() <= 1e-9 * closed[1], "{got} {want}");
    }
    // The coupling moves both frequencies off the uncoupled ones (a = 0).
    let uncoupled = [k * r * r / j, ka / m];
    assert!(closed
        .iter()
        .all(|w| uncoupled.iter().all(|u| (w - u).abs() > 1e-3 * u)));
}
