//! The tilting coordinates of a helical pair (docs/MODEL.md 11.8) against matrices written
//! out by hand, and the tilting entries of the mesh gradient against the rigid-body
//! kinematics of the contact point computed with 3-D cross products.

use super::elements::{Elements, MeshTilt};
use super::tests_assembly::paper_by_hand;
use super::{Assembly, Dof};
use crate::config::case::Case;
use crate::dynamics::params::{DynamicParams, TiltSupport};
use crate::geometry::GearPair;
use nalgebra::{DMatrix, DVector, Vector3};

/// Arbitrary but plausible mesh terms: a right-hand pinion at beta_b ~ 14 deg.
const TILT: MeshTilt = MeshTilt {
    centre_lever_m: 1.7e-3,
    signed_tan_base_helix: 0.2507,
    gap_moment_nm: 0.37,
    line_of_action_length_m: 0.0258,
    tilting_stiffness_nm_per_rad: 1.345e4,
};

/// d delta / d(theta_x, theta_y) of pinion and gear from the rigid-body motion of the
/// mesh's contact point, written in 3-D: the plane (x, y), z along the pinion's angular
/// velocity (the paper's layout turns counter-clockwise: z = +z_plane). A tilt theta of
/// a body moves its point P (relative to its centre) by theta x P; the deflection along
/// the transverse line of action gains d . (u_p - u_g) - s t z . (u_p - u_g) (the axial
/// motion's share, docs/MODEL.md 11.6), the pinion's point at r_b1 n + rho d, the gear's
/// at -r_b2 n + (rho - L) d, both at face position zeta. The mesh's mean lever is the
/// point zeta = 0, rho = mu / (s t).
fn tilt_gradient_by_cross_products(d2: [f64; 2], rb: [f64; 2]) -> [f64; 4] {
    let d = Vector3::new(d2[0], d2[1], 0.0);
    let z = Vector3::z();
    let n = d.cross(&z);
    let st = TILT.signed_tan_base_helix;
    let rho = TILT.centre_lever_m / st;
    let p_pinion = rb[0] * n + rho * d;
    let p_gear = -rb[1] * n + (rho - TILT.line_of_action_length_m) * d;
    let deflection = |u: Vector3<f64>| d.dot(&u) - st * z.dot(&u);
    let axes = [Vector3::x(), Vector3::y()];
    [
        deflection(axes[0].cross(&p_pinion)),
        deflection(axes[1].cross(&p_pinion)),
        -deflection(axes[0].cross(&p_gear)),
        -deflection(axes[1].cross(&p_gear)),
    ]
}

fn tilting_params(bearings: [Option<(f64, f64)>; 2]) -> (DynamicParams, GearPair) {
    let case = Case::default();
    let pair = GearPair::from_case(&case.gear).unwrap();
    let mut p = DynamicParams::from_case(&case, &pair);
    p.tilt = Some(TiltSupport {
        mesh: TILT,
        bearings,
        diametral_inertia_kg_m2: [1.4e-4, 7.6e-4],
    });
    (p, pair)
}

#[test]
fn tilting_bearings_add_a_block_and_the_mesh_its_tilting_terms() {
    let bearings = [Some((1e5, 3.0)), Some((2e5, 5.0))];
    let (p, pair) = tilting_params(bearings);
    let asm = Assembly::new(Elements::single_pair(&p, &pair)).unwrap();
    assert_eq!(asm.len(), 12);
    let (mut inv, k8, c8, f8, g8) = paper_by_hand(&p, &pair);
    // The first 8 coordinates keep their numbers and matrices.
    let (mut k, mut c) = (DMatrix::zeros(12, 12), DMatrix::zeros(12, 12));
    k.view_mut((0, 0), (8, 8)).copy_from(&k8);
    c.view_mut((0, 0), (8, 8)).copy_from(&c8);
    // Inertias: the diametral ones, twice per body.
    inv.extend([1.0 / 1.4e-4, 1.0 / 1.4e-4, 1.0 / 7.6e-4, 1.0 / 7.6e-4]);
    // The tilting bearings on their diagonals.
    for (i, (kt, ct)) in [
        (8, (1e5, 3.0)),
        (9, (1e5, 3.0)),
        (10, (2e5, 5.0)),
        (11, (2e5, 5.0)),
    ] {
        k[(i, i)] = kt;
        c[(i, i)] = ct;
    }
    // The mesh's tilting spring J on tau = a_g - a_p, a = theta . n, n = d x z with the
    // paper's d = (sin alpha, cos alpha): n = (cos alpha, -sin alpha).
    let (sa, ca) = pair.operating_pressure_angle_rad.sin_cos();
    let h = [-ca, sa, ca, -sa];
    let mut f = DVector::zeros(12);
    f.rows_mut(0, 8).copy_from(&f8);
    for i in 0..4 {
        for j in 0..4 {
            k[(8 + i, 8 + j)] += TILT.tilting_stiffness_nm_per_rad * h[i] * h[j];
        }
        f[8 + i] += TILT.gap_moment_nm * h[i];
    }
    assert_eq!(asm.inverse_masses(), &inv[..]);
    assert_eq!(asm.stiffness(), &k);
    assert_eq!(asm.damping(), &c);
    assert_eq!(asm.external_forces(), &f);
    // The gradient: the planar entries unchanged, the tilting ones the cross products'.
    let g = asm.mesh_gradient(0);
    assert_eq!(g.rows(0, 8), g8.rows(0, 8));
    let rb = [pair.pinion.base_radius_m, pair.gear.base_radius_m];
    let by_hand = tilt_gradient_by_cross_products([sa, ca], rb);
    for (i, want) in by_hand.iter().enumerate() {
        // A few roundings of products of numbers ~1e-2: 1e-15 m/rad absolute.
        assert!(
            (g[8 + i] - want).abs() <= 1e-15,
            "{i}: {} against {want}",
            g[8 + i]
        );
    }
    assert_eq!(asm.index(1, Dof::TiltX), Some(8));
    assert_eq!(asm.index(2, Dof::TiltY), Some(11));
    let names: Vec<String> = asm.coordinate_names().into_iter().map(|x| x.0).collect();
    assert_eq!(
        names[8..],
        [
            "tilt_x_pinion",
            "tilt_y_pinion",
            "tilt_x_gear",
            "tilt_y_gear"
        ]
    );
}

#[test]
fn a_body_without_a_tilting_bearing_has_no_tilting_coordinates() {
    let (p, pair) = tilting_params([None, Some((2e5, 5.0))]);
    let asm = Assembly::new(Elements::single_pair(&p, &pair)).unwrap();
    assert_eq!(asm.len(), 10);
    assert_eq!(asm.index(1, Dof::TiltX), None);
    assert_eq!(asm.index(2, Dof::TiltX), Some(8));
    let (sa, ca) = pair.operating_pressure_angle_rad.sin_cos();
    let rb = [pair.pinion.base_radius_m, pair.gear.base_radius_m];
    let by_hand = tilt_gradient_by_cross_products([sa, ca], rb);
    let g = asm.mesh_gradient(0);
    assert!((g[8] - by_hand[2]).abs() <= 1e-15 && (g[9] - by_hand[3]).abs() <= 1e-15);
    // The mesh's tilting spring acts on the gear's tilt alone: J n n^T.
    assert_eq!(
        asm.stiffness()[(8, 8)],
        2e5 + TILT.tilting_stiffness_nm_per_rad * ca * ca
    );
}
