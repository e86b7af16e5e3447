//! The assembly against matrices assembled by hand: paper eq. (1) written out coordinate
//! by coordinate, and a two-stage reducer's kinematics and rigid rotation.

use super::elements::{Bearing, Body, BodyKind, Drive, Elements, MeshLink, Shaft};
use super::{Assembly, AssemblyError, Dof};
use crate::config::case::{Case, SpeedBoundary};
use crate::dynamics::params::DynamicParams;
use crate::geometry::GearPair;
use nalgebra::{DMatrix, DVector};

/// Inverse masses, K, C, external forces and a mesh gradient.
pub(super) type ByHand = (
    Vec<f64>,
    DMatrix<f64>,
    DMatrix<f64>,
    DVector<f64>,
    DVector<f64>,
);

/// Paper eq. (1) assembled by hand in the order [x_p, y_p, x_g, y_g, phi_m, phi_p, phi_g,
/// phi_b]: inverse masses, K, C, external forces and the mesh gradient.
pub(super) fn paper_by_hand(p: &DynamicParams, pair: &GearPair) -> ByHand {
    let l = &p.lumped;
    let mut inv = vec![
        1.0 / l.mass_pinion_kg,
        1.0 / l.mass_pinion_kg,
        1.0 / l.mass_gear_kg,
        1.0 / l.mass_gear_kg,
        1.0 / l.inertia_motor_kg_m2,
        1.0 / l.inertia_pinion_kg_m2,
        1.0 / l.inertia_gear_kg_m2,
        1.0 / l.inertia_brake_kg_m2,
    ];
    let mut f = DVector::zeros(8);
    match p.speed_boundary {
        SpeedBoundary::MotorSpeedImposed => {
            inv[4] = 0.0;
            f[7] = -p.operating.brake_torque_nm;
        }
        SpeedBoundary::BrakeSpeedImposed => {
            inv[7] = 0.0;
            f[4] = p.operating.motor_torque_nm;
        }
        SpeedBoundary::MotorSlip => {
            f[4] = p.operating.motor_torque_nm;
            f[7] = -p.operating.brake_torque_nm;
        }
    }
    let (kp, kg) = (
        l.bearing_stiffness_pinion_n_per_m,
        l.bearing_stiffness_gear_n_per_m,
    );
    let (cp, cg) = (
        l.bearing_damping_pinion_n_s_per_m,
        l.bearing_damping_gear_n_s_per_m,
    );
    let k = DMatrix::from_diagonal(&DVector::from_vec(vec![kp, kp, kg, kg, 0.0, 0.0, 0.0, 0.0]));
    let c = DMatrix::from_diagonal(&DVector::from_vec(vec![cp, cp, cg, cg, 0.0, 0.0, 0.0, 0.0]));
    let (mut k, mut c) = (k, c);
    let (km, cm) = (
        l.coupling_stiffness_motor_nm_per_rad,
        l.coupling_damping_motor_nm_s_per_rad,
    );
    let (kb, cb) = (
        l.coupling_stiffness_brake_nm_per_rad,
        l.coupling_damping_brake_nm_s_per_rad,
    );
    for (m, a, b) in [(&mut k, km, kb), (&mut c, cm, cb)] {
        m[(4, 4)] = a;
        m[(5, 5)] = a;
        m[(4, 5)] = -a;
        m[(5, 4)] = -a;
        m[(6, 6)] = b;
        m[(7, 7)] = b;
        m[(6, 7)] = -b;
        m[(7, 6)] = -b;
    }
    if p.speed_boundary == SpeedBoundary::MotorSlip {
        c[(4, 4)] += p.motor_slip_damping_nm_s_per_rad;
    }
    let (s, co) = pair.operating_pressure_angle_rad.sin_cos();
    let (rp, rg) = (pair.pinion.base_radius_m, pair.gear.base_radius_m);
    let g = DVector::from_vec(vec![s, co, -s, -co, 0.0, rp, -rg, 0.0]);
    (inv, k, c, f, g)
}

#[test]
fn the_paper_case_assembles_to_eq_1_bit_for_bit() {
    for boundary in [
        SpeedBoundary::MotorSpeedImposed,
        SpeedBoundary::BrakeSpeedImposed,
        SpeedBoundary::MotorSlip,
    ] {
        let mut case = Case::default();
        case.operating.speed_boundary = boundary;
        // Distinct values everywhere, so that no coordinate can stand in for another.
        case.dynamics.coupling_stiffness_brake_nm_per_rad *= 1.7;
        case.dynamics.coupling_damping_brake_nm_s_per_rad *= 2.3;
        case.dynamics.bearing_damping_gear_n_s_per_m *= 1.3;
        let pair = GearPair::from_case(&case.gear).unwrap();
        let p = DynamicParams::from_case(&case, &pair);
        let asm = Assembly::new(Elements::single_pair(&p, &pair)).unwrap();
        let (inv, k, c, f, g) = paper_by_hand(&p, &pair);
        assert_eq!(asm.len(), 8);
        assert_eq!(asm.inverse_masses(), &inv[..], "{boundary:?}");
        assert_eq!(asm.stiffness(), &k, "{boundary:?}");
        assert_eq!(asm.damping(), &c, "{boundary:?}");
        assert_eq!(asm.external_forces(), &f, "{boundary:?}");
        assert_eq!(asm.mesh_gradient(0), g, "{boundary:?}");
        // The mean-stiffness matrix: K + k g g^T, entry by entry.
        let km = 3.1e8;
        assert_eq!(
            asm.stiffness_with_meshes(&[km]),
            &k + &g * g.transpose() * km
        );
        // Numbering: laterals of pinion and gear, then the four rotations.
        let idx = |b, d| asm.index(b, d);
        assert_eq!(
            (idx(1, Dof::X), idx(1, Dof::Y), idx(2, Dof::X)),
            (Some(0), Some(1), Some(2))
        );
        assert_eq!(
            (idx(0, Dof::X), idx(0, Dof::Rotation), idx(3, Dof::Rotation)),
            (None, Some(4), Some(7))
        );
        let held = match boundary {
            SpeedBoundary::MotorSpeedImposed => Some(4),
            SpeedBoundary::BrakeSpeedImposed => Some(7),
            SpeedBoundary::MotorSlip => None,
        };
        assert_eq!(asm.held(), held);
    }
}

/// Two stages, 19/31 then 23/47, each gear on its own bearings, the intermediate gears
/// joined by a shaft (torsional and lateral); the second stage's gear centre straight
/// above its pinion.
fn two_stage() -> Elements {
    let gear = |name: &str, m: f64, j: f64| Body {
        name: name.into(),
        kind: BodyKind::Gear,
        mass_kg: m,
        inertia_kg_m2: j,
        lateral: true,
    };
    let rot = |name: &str, kind, j| Body {
        name: name.into(),
        kind,
        mass_kg: 0.0,
        inertia_kg_m2: j,
        lateral: false,
    };
    let bearing = |body, k: f64| Bearing {
        body,
        stiffness_n_per_m: [k, 1.5 * k],
        damping_n_s_per_m: [1e3, 2e3],
    };
    let shaft = |ends, k, lateral| Shaft {
        ends,
        torsional_stiffness_nm_per_rad: k,
        torsional_damping_nm_s_per_rad: 0.01 * k,
        lateral_stiffness_n_per_m: lateral,
        lateral_damping_n_s_per_m: 0.0,
    };
    let mesh = |pinion, gear, teeth: [usize; 2], r: [f64; 2], psi| MeshLink {
        pinion,
        gear,
        teeth,
        base_radius_m: r,
        pressure_angle_rad: 0.4,
        centre_line_rad: psi,
        axial_gradient: 0.0,
        tilt: None,
    };
    Elements {
        bodies: vec![
            rot("motor", BodyKind::Motor, 0.01),
            gear("pinion 1", 0.5, 1e-4),
            gear("gear 1", 1.5, 1e-3),
            gear("pinion 2", 0.7, 2e-4),
            gear("gear 2", 3.0, 5e-3),
            rot("brake", BodyKind::Load, 0.05),
        ],
        bearings: [(1, 1e8), (2, 2e8), (3, 3e8), (4, 4e8)]
            .map(|(b, k)| bearing(b, k))
            .to_vec(),
        shafts: vec![
            shaft([0, 1], 1e4, 0.0),
            shaft([2, 3], 5e4, 7e7),
            shaft([4, 5], 2e4, 0.0),
        ],
        meshes: vec![
            mesh(1, 2, [19, 31], [0.0178, 0.0291], 0.0),
            mesh(
                3,
                4,
                [23, 47],
                [0.0216, 0.0442],
                std::f64::consts::FRAC_PI_2,
            ),
        ],
        axial_bearings: Vec::new(),
        tilt_bearings: Vec::new(),
        drive: Drive {
            input: 0,
            output: 5,
            boundary: SpeedBoundary::MotorSlip,
            input_torque_nm: 60.0,
            output_torque_nm: 60.0 * 31.0 / 19.0 * 47.0 / 23.0,
            slip_damping_nm_s_per_rad: 7.0,
        },
    }
}

#[test]
fn a_two_stage_train_is_numbered_and_turns_as_its_teeth_say() {
    let asm = Assembly::new(two_stage()).unwrap();
    // 4 gears x 2 laterals, then 6 rotations.
    assert_eq!(asm.len(), 14);
    assert_eq!(asm.index(3, Dof::X), Some(4));
    assert_eq!(asm.index(0, Dof::Rotation), Some(8));
    assert_eq!(asm.index(5, Dof::Rotation), Some(13));
    // Senses alternate across each mesh and hold along each shaft.
    assert_eq!(asm.spin(), &[1.0, 1.0, -1.0, -1.0, 1.0, 1.0]);
    let out = 19.0 / 31.0 * 23.0 / 47.0;
    assert!((asm.speed_ratio()[5] - out).abs() < 1e-15);
    // Second mesh: gear above its pinion (e1 = +y, e2 = -x), pinion turning clockwise
    // (s = -1): d = sin(phi) e1 - cos(phi) e2 = (cos phi, sin phi).
    let (s, c) = 0.4_f64.sin_cos();
    let g = asm.mesh_gradient(1);
    let by_hand = [
        (4, c),
        (5, s),
        (6, -c),
        (7, -s),
        (11, 0.0216),
        (12, -0.0442),
    ];
    for (i, v) in by_hand {
        assert!((g[i] - v).abs() < 1e-15, "coordinate {i}: {} vs {v}", g[i]);
    }
    assert_eq!(g.iter().filter(|v| **v != 0.0).count(), 6);
    // The intermediate shaft's lateral spring joins x_g1 with x_p2 and y_g1 with y_p2.
    let k = asm.stiffness();
    assert_eq!(k[(2, 4)], -7e7);
    assert_eq!(k[(3, 5)], -7e7);
    assert_eq!(k[(2, 2)], 2e8 + 7e7);
    assert_eq!(k[(10, 11)], -5e4);
}

#[test]
fn the_rigid_rotation_twists_no_shaft_and_deflects_no_mesh() {
    let asm = Assembly::new(two_stage()).unwrap();
    let r = asm.rigid_rotation();
    // K r = 0 and each mesh's deflection under r is 0, to round-off of the terms.
    let kr = asm.stiffness() * &r;
    assert!(kr.amax() < 1e-10 * asm.stiffness().amax(), "{kr}");
    for m in 0..2 {
        let d = asm.mesh_gradient(m).dot(&r);
        assert!(d.abs() < 1e-17, "mesh {m}: {d}");
    }
    // The brake turns by the product of the base-radius ratios.
    let expected = 0.0178 / 0.0291 * 0.0216 / 0.0442;
    assert!((r[13] - expected).abs() < 1e-15);
}

#[test]
fn trains_that_cannot_be_assembled_are_named() {
    let mut e = two_stage();
    e.shafts.remove(1);
    assert_eq!(
        Assembly::new(e).unwrap_err(),
        AssemblyError::Disconnected {
            body: "pinion 2".into()
        }
    );
    // A shaft from the input to the second pinion as well: two paths, two speeds.
    let mut e = two_stage();
    e.shafts.push(Shaft {
        ends: [0, 3],
        ..e.shafts[0]
    });
    assert!(matches!(
        Assembly::new(e).unwrap_err(),
        AssemblyError::InconsistentSpeeds { .. } | AssemblyError::MeshSameSense { .. }
    ));
    let mut e = two_stage();
    e.bearings[0].body = 9;
    assert_eq!(
        Assembly::new(e).unwrap_err(),
        AssemblyError::NoSuchBody {
            index: 9,
            bodies: 6
        }
    );
}
