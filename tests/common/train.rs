//! The two-stage reducer of the train tests and its matrices assembled by hand.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::study::Model;
use nalgebra::DMatrix;

/// 19/31 then 23/47, the second stage turned a quarter turn (its gear above its pinion),
/// the paper's pair and bodies as the first stage.
pub const TWO_STAGE: &str = r#"
[operating]
input_speed_hz = 30
load_torque_nm = 60

[[stage]]
shaft_torsional_stiffness_nm_per_rad = 2e5
shaft_torsional_damping_nm_s_per_rad = 5

[[stage]]
module_mm = 2.5
teeth_pinion = 23
teeth_gear = 47
face_width_mm = 25
mass_pinion_kg = 0.9
mass_gear_kg = 3.1
inertia_pinion_kg_m2 = 4e-4
inertia_gear_kg_m2 = 6e-3
bearing_stiffness_pinion_n_per_m = 8e8
bearing_stiffness_gear_n_per_m = 7e8
bearing_damping_gear_n_s_per_m = 3e5
centre_line_deg = 90
"#;

/// The train's model of its dynamics (`Model::dynamics_from_case`: a stage's tooth fault
/// and helical stages taken; the same as `Model::from_case` otherwise).
pub fn model(text: &str, sets: &[&str]) -> Model {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    Model::dynamics_from_case(&load_case(text, &sets).unwrap()).unwrap()
}

/// M (diagonal), K at the mean mesh stiffnesses and C of the two-stage train, assembled
/// here coordinate by coordinate from the case's values: laterals (x, y) of pinion 1,
/// gear 1, pinion 2, gear 2, then the rotations of motor, pinion 1, gear 1, pinion 2,
/// gear 2, brake.
pub fn two_stage_by_hand(m: &Model) -> (Vec<f64>, DMatrix<f64>, DMatrix<f64>) {
    let h = two_stage_parts_by_hand(m);
    (h.mass, h.k, h.c)
}

/// What [`two_stage_by_hand`] assembles, with each mesh's share kept apart.
pub struct HandTrain {
    /// M (diagonal), K at the mean mesh stiffnesses and C with the mesh dampers.
    pub mass: Vec<f64>,
    pub k: DMatrix<f64>,
    pub c: DMatrix<f64>,
    /// C without the mesh dampers and the motor's slip (bearings, shaft, couplings): the
    /// slip is the motor's torque T_0 - c_slip dphi_m/dt, to ground.
    pub c_fixed: DMatrix<f64>,
    pub meshes: Vec<HandMesh>,
}

/// One mesh of [`HandTrain`].
pub struct HandMesh {
    /// d delta / d q.
    pub gradient: [f64; 14],
    /// Mesh damper c_m, N s/m.
    pub damper_n_s_per_m: f64,
    /// First lateral coordinate (x) of its pinion and of its gear.
    pub lateral: [usize; 2],
    /// The line of action d (the force on the pinion is -F d) and the common tangent e
    /// along which friction acts on the pinion: the pinion's surface moves along
    /// s z x d = s (-d_y, d_x) at the contact (s its sense of rotation, +1
    /// counter-clockwise), and slides along -e when it is the faster: e = s (d_y, -d_x).
    pub line_of_action: [f64; 2],
    pub tangent: [f64; 2],
}

/// The two-stage reducer's matrices by hand, each mesh apart (see [`two_stage_by_hand`]).
pub fn two_stage_parts_by_hand(m: &Model) -> HandTrain {
    let t = m.train.as_ref().unwrap();
    let (s1, s2) = (&t.stages[0], &t.stages[1]);
    let d = &m.case.dynamics;
    let mut mass = vec![0.0; 14];
    let mut k = DMatrix::zeros(14, 14);
    let mut c = DMatrix::zeros(14, 14);
    let lat = [
        (
            s1.lumped.mass_pinion_kg,
            s1.lumped.bearing_stiffness_pinion_n_per_m,
            s1.lumped.bearing_damping_pinion_n_s_per_m,
        ),
        (
            s1.lumped.mass_gear_kg,
            s1.lumped.bearing_stiffness_gear_n_per_m,
            s1.lumped.bearing_damping_gear_n_s_per_m,
        ),
        (0.9, 8e8, d.bearing_damping_pinion_n_s_per_m),
        (3.1, 7e8, 3e5),
    ];
    for (b, (mb, kb, cb)) in lat.iter().enumerate() {
        for i in [2 * b, 2 * b + 1] {
            mass[i] = *mb;
            k[(i, i)] = *kb;
            c[(i, i)] = *cb;
        }
    }
    let inertia = [
        d.inertia_motor_kg_m2,
        s1.lumped.inertia_pinion_kg_m2,
        s1.lumped.inertia_gear_kg_m2,
        4e-4,
        6e-3,
        d.inertia_brake_kg_m2,
    ];
    for (b, j) in inertia.iter().enumerate() {
        mass[8 + b] = *j;
    }
    // Torsional springs: motor-pinion 1, gear 1-pinion 2 (the shaft), gear 2-brake.
    add_torsional_springs(&mut k, &mut c, m);
    let c_fixed = c.clone();
    c[(8, 8)] += m.case.operating.motor_slip_damping_nm_s_per_rad;
    let mut meshes = Vec::new();
    // Meshes. Stage 1: gear on +x, pinion counter-clockwise: line of action
    // (sin phi, cos phi). Stage 2: gear on +y, its pinion clockwise (it turns with gear
    // 1): the force on the pinion -F d must turn it counter-clockwise about the contact
    // near (0, r_p): d = (cos phi, sin phi).
    for (stage, lat_p, lat_g, rot_p, rot_g, dir) in [
        (
            s1,
            0,
            2,
            9,
            10,
            [
                s1.pair.operating_pressure_angle_rad.sin(),
                s1.pair.operating_pressure_angle_rad.cos(),
            ],
        ),
        (
            s2,
            4,
            6,
            11,
            12,
            [
                s2.pair.operating_pressure_angle_rad.cos(),
                s2.pair.operating_pressure_angle_rad.sin(),
            ],
        ),
    ] {
        let mut g = [0.0; 14];
        g[lat_p] = dir[0];
        g[lat_p + 1] = dir[1];
        g[lat_g] = -dir[0];
        g[lat_g + 1] = -dir[1];
        g[rot_p] = stage.pair.pinion.base_radius_m;
        g[rot_g] = -stage.pair.gear.base_radius_m;
        let km = stage.mesh.mean_stiffness_n_per_m();
        // c_m = 2 zeta sqrt(k m_e), m_e = J_p J_g / (J_p r_g^2 + J_g r_p^2).
        let (jp, jg) = (mass[rot_p], mass[rot_g]);
        let (rp, rg) = (g[rot_p], -g[rot_g]);
        let me = jp * jg / (jp * rg * rg + jg * rp * rp);
        let cm = 2.0 * d.mesh_damping_ratio * (km * me).sqrt();
        // Stage 1's pinion turns counter-clockwise, stage 2's (on gear 1's shaft) clockwise.
        let spin = if lat_p == 0 { 1.0 } else { -1.0 };
        meshes.push(HandMesh {
            gradient: g,
            damper_n_s_per_m: cm,
            lateral: [lat_p, lat_g],
            line_of_action: dir,
            tangent: [spin * dir[1], -spin * dir[0]],
        });
        for i in 0..14 {
            for j in 0..14 {
                k[(i, j)] += km * g[i] * g[j];
                c[(i, j)] += cm * g[i] * g[j];
            }
        }
    }
    HandTrain {
        mass,
        k,
        c,
        c_fixed,
        meshes,
    }
}

/// Stage 2 as rigid as the case allows: a 31-tooth pinion (so mesh 2 repeats with mesh 1
/// and the base period is one mesh period) and a 62-tooth gear (ratio 1/2 exactly), module
/// 20 mm and `width_mm` wide (mesh 2's stiffness about width/20 x mesh 1's, its radius
/// 10x), bearings and shaft at the top of their ranges.
pub fn stiff_second_stage(width_mm: f64) -> String {
    format!(
        r#"
[[stage]]
shaft_torsional_stiffness_nm_per_rad = 1e10

[[stage]]
module_mm = 20
teeth_pinion = 31
teeth_gear = 62
face_width_mm = {width_mm}
hub_bore_radius_pinion_mm = "derived"
hub_bore_radius_gear_mm = "derived"
mass_pinion_kg = 2.0
mass_gear_kg = 5.0
inertia_pinion_kg_m2 = 4e-4
inertia_gear_kg_m2 = 6e-3
bearing_stiffness_pinion_n_per_m = 1e12
bearing_stiffness_gear_n_per_m = 1e12
"#
    )
}

/// The first stage alone with the rigid second stage reflected onto its gear's shaft
/// (ratio rho = 1/2): gear inertia J_g1 + J_p2 + J_g2 rho^2, the brake's coupling and
/// inertia times rho^2, `extra` settings (e.g. a fault), and the mesh damping ratio that gives the train's mesh-1 damper
/// c_m (which the train computes from J_g1 alone).
pub fn reflected_pair(train: &Model, extra: &[&str]) -> Model {
    let t = train.train.as_ref().unwrap();
    let (s1, s2) = (&t.stages[0].lumped, &t.stages[1].lumped);
    let rho: f64 = 0.5;
    let d = &train.case.dynamics;
    let j_gear =
        s1.inertia_gear_kg_m2 + s2.inertia_pinion_kg_m2 + s2.inertia_gear_kg_m2 * rho * rho;
    let edits = |zeta: f64| -> Vec<String> {
        vec![
            format!("dynamics.inertia_gear_kg_m2={j_gear:e}"),
            format!(
                "dynamics.inertia_brake_kg_m2={:e}",
                d.inertia_brake_kg_m2 * rho * rho
            ),
            format!(
                "dynamics.coupling_stiffness_brake_nm_per_rad={:e}",
                d.coupling_stiffness_brake_nm_per_rad * rho * rho
            ),
            format!(
                "dynamics.coupling_damping_brake_nm_s_per_rad={:e}",
                d.coupling_damping_brake_nm_s_per_rad * rho * rho
            ),
            format!("dynamics.mesh_damping_ratio={zeta:e}"),
            "friction.model=none".to_string(),
            // The train's own contact model.
            format!(
                "contact.path={}",
                serde_json::to_value(train.case.contact.path).unwrap()
            ),
        ]
        .into_iter()
        .chain(extra.iter().map(|s| s.to_string()))
        .collect()
    };
    let build = |zeta: f64| {
        let sets = edits(zeta);
        let sets: Vec<&str> = sets.iter().map(String::as_str).collect();
        model("", &sets)
    };
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let c_train = train.system(&gap, &ext, 0.2).mesh(0).mesh_damping_n_s_per_m;
    let zeta = d.mesh_damping_ratio;
    let first = build(zeta);
    let c_first = first.system(&gap, &ext, 0.2).mesh(0).mesh_damping_n_s_per_m;
    // c_m is proportional to zeta.
    build(zeta * c_train / c_first)
}

/// The compliance the rigid-stage limit neglects, relative to mesh 1's: mesh 2's
/// torsional compliance seen from the intermediate shaft, 1 / (k_m2 r_p2^2), the shaft's
/// 1 / k_s, and stage 2's bearings' 1 / (k_b r_p2^2) (each against mesh 1's
/// 1 / (k_m1 r_g1^2)).
pub fn neglected_compliance(train: &Model) -> f64 {
    let t = train.train.as_ref().unwrap();
    let (s1, s2) = (&t.stages[0], &t.stages[1]);
    let r_g1 = s1.pair.gear.base_radius_m;
    let r_p2 = s2.pair.pinion.base_radius_m;
    let k1 = s1.mesh.mean_stiffness_n_per_m() * r_g1 * r_g1;
    let k2 = s2.mesh.mean_stiffness_n_per_m() * r_p2 * r_p2;
    let k_b = s2.lumped.bearing_stiffness_pinion_n_per_m * r_p2 * r_p2;
    k1 / k2 + k1 / 1e10 + k1 / k_b
}

/// The two-stage train's torsional springs and dampers written into `k` and `c` at the
/// rotation coordinates 8..=13 (motor, pinion 1, gear 1, pinion 2, gear 2, brake): the
/// motor coupling, the shaft between the stages (2e5 N m/rad, 5 N m s/rad, TWO_STAGE's),
/// the brake coupling, each +v on its two diagonals and -v off them.
pub fn add_torsional_springs(k: &mut DMatrix<f64>, c: &mut DMatrix<f64>, m: &Model) {
    let d = &m.case.dynamics;
    for (a, b, ks, cs) in [
        (
            8,
            9,
            d.coupling_stiffness_motor_nm_per_rad,
            d.coupling_damping_motor_nm_s_per_rad,
        ),
        (10, 11, 2e5, 5.0),
        (
            12,
            13,
            d.coupling_stiffness_brake_nm_per_rad,
            d.coupling_damping_brake_nm_s_per_rad,
        ),
    ] {
        for (mat, v) in [(&mut *k, ks), (&mut *c, cs)] {
            mat[(a, a)] += v;
            mat[(b, b)] += v;
            mat[(a, b)] -= v;
            mat[(b, a)] -= v;
        }
    }
}
