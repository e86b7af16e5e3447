//! Helical stages in a gear train (`[[stage]]` with `helix_angle_deg`; docs/MODEL.md 4.3)
//! against facts that do not come from the train's assembly: the single helical pair as
//! the one-stage train, the matrices of a two-stage train written out by hand with the
//! helical geometry from its closed forms, both mesh frequencies in the spectrum from the
//! teeth and the speed, the spur stage at beta = 0, and the refusals by key.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::study::Model;
use gearwear::wear::WearState;
use nalgebra::{DMatrix, DVector};

mod common;
use common::{gearwear, rejected};

fn case(text: &str) -> gearwear::config::case::Case {
    load_case(text, &[]).unwrap()
}

/// The steady state of `model`'s new teeth (no external error).
fn steady(model: &Model) -> gearwear::dynamics::response::DynamicResponse {
    model
        .dynamic(&WearState::new(model.grid.len()), &ExternalError::none())
        .unwrap()
}

/// The paper's pair at beta = 15 deg, left hand, 60 slices, and its axial bearings.
const HELIX: &str = "helix_angle_deg = 15\nhelix_hand_pinion = \"left\"\n";
const AXIAL: &str = "bearing_axial_stiffness_pinion_n_per_m = 5e8\nbearing_axial_stiffness_gear_n_per_m = 7e8\nbearing_axial_damping_gear_n_s_per_m = 2e5\n";

#[test]
fn a_one_stage_helical_train_is_the_helical_pair_bit_for_bit() {
    // The single helical pair ([gear] and [dynamics] keys, `Model::helical_from_case`)
    // against a [[stage]] that gives the same helix, slices and axial bearings as its own
    // keys: the same slice model, contact lines, bodies and coordinates must give the same
    // numbers bit for bit (the spur one-stage train is the spur pair bit for bit, and the
    // helical stage reuses the pair's mesh, so nothing may differ); planar and with axial
    // coordinates.
    for axial in ["", AXIAL] {
        let single = format!("[gear]\n{HELIX}\n[stiffness]\nslices = 60\n\n[dynamics]\n{axial}");
        let train = format!("[[stage]]\n{HELIX}slices = 60\n{axial}");
        let a = Model::dynamics_from_case(&case(&single)).unwrap();
        let b = Model::dynamics_from_case(&case(&train)).unwrap();
        assert!(a.helical.is_some() && b.train.is_some());
        assert_eq!(a.coordinate_names(), b.coordinate_names());
        let (ra, rb) = (steady(&a), steady(&b));
        assert_eq!(ra.end_state, rb.end_state, "axial: {axial:?}");
        assert_eq!(ra.signals.time_s, rb.signals.time_s);
        assert_eq!(ra.signals.displacement, rb.signals.displacement);
        let (ma, mb) = (&ra.signals.meshes[0], &rb.signals.meshes[0]);
        assert_eq!(ma.dte_m, mb.dte_m);
        assert_eq!(ma.mesh_force_n, mb.mesh_force_n);
        assert_eq!(
            ra.meshes[0].mean_mesh_force_n,
            rb.meshes[0].mean_mesh_force_n
        );
    }
}

/// Stage 1 the paper's spur pair, stage 2 a left-hand helical 23/47 pair (beta = 15 deg,
/// m_n = 2.5 mm) turned a quarter turn, with axial bearings on both its bodies; every
/// body's mass and inertia given.
const TWO_STAGE: &str = r#"
[operating]
input_speed_hz = 30
load_torque_nm = 60

[[stage]]
mass_pinion_kg = 0.6
mass_gear_kg = 1.5
inertia_pinion_kg_m2 = 2e-4
inertia_gear_kg_m2 = 1.2e-3
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
centre_line_deg = 90
helix_angle_deg = 15
helix_hand_pinion = "left"
slices = 60
bearing_axial_stiffness_pinion_n_per_m = 5e8
bearing_axial_stiffness_gear_n_per_m = 7e8
bearing_axial_damping_pinion_n_s_per_m = 2e5
"#;

#[test]
fn a_two_stage_train_with_a_helical_stage_assembles_the_matrices_written_by_hand() {
    let m = Model::dynamics_from_case(&case(TWO_STAGE)).unwrap();
    let t = m.train.as_ref().unwrap();
    let asm = &t.assembly;
    let d = &m.case.dynamics;
    // Coordinates: x, y of pinion 1, gear 1, pinion 2, gear 2 (0..8); rotations of motor,
    // pinion 1, gear 1, pinion 2, gear 2, brake (8..14); z of pinion 2 and gear 2 (14, 15).
    let n = 16;
    assert_eq!(asm.len(), n);
    let mut mass = vec![0.6, 0.6, 1.5, 1.5, 0.9, 0.9, 3.1, 3.1];
    mass.extend([
        d.inertia_motor_kg_m2,
        2e-4,
        1.2e-3,
        4e-4,
        6e-3,
        d.inertia_brake_kg_m2,
    ]);
    mass.extend([0.9, 3.1]);
    let inv: Vec<f64> = mass.iter().map(|x| 1.0 / x).collect();
    assert_eq!(asm.inverse_masses(), &inv[..]);
    let (kp, kg) = (
        d.bearing_stiffness_pinion_n_per_m,
        d.bearing_stiffness_gear_n_per_m,
    );
    let (cp, cg) = (
        d.bearing_damping_pinion_n_s_per_m,
        d.bearing_damping_gear_n_s_per_m,
    );
    let mut k = DMatrix::zeros(n, n);
    let mut c = DMatrix::zeros(n, n);
    for (i, (kb, cb)) in [(kp, cp), (kg, cg), (kp, cp), (kg, cg)].iter().enumerate() {
        for j in [2 * i, 2 * i + 1] {
            k[(j, j)] = *kb;
            c[(j, j)] = *cb;
        }
    }
    // Axial bearings: the stage's keys; the gear's damping absent, so its radial one.
    k[(14, 14)] = 5e8;
    c[(14, 14)] = 2e5;
    k[(15, 15)] = 7e8;
    c[(15, 15)] = cg;
    common::train::add_torsional_springs(&mut k, &mut c, &m);
    c[(8, 8)] += m.case.operating.motor_slip_damping_nm_s_per_rad;
    assert_eq!(asm.stiffness(), &k);
    assert_eq!(asm.damping(), &c);
    // Mesh 1, spur: m = 2 mm, 19/31, 20 deg, gear on +x, pinion counter-clockwise:
    // d = (sin phi, cos phi), r_b = z m / 2 cos(phi).
    let phi: f64 = 20f64.to_radians();
    let mut g1 = DVector::zeros(n);
    g1[0] = phi.sin();
    g1[1] = phi.cos();
    g1[2] = -phi.sin();
    g1[3] = -phi.cos();
    g1[9] = 19.0 * 1e-3 * phi.cos();
    g1[10] = -31.0 * 1e-3 * phi.cos();
    // Mesh 2, helical (ISO 21771): alpha_t = atan(tan alpha_n / cos beta),
    // r_b = z m_n / (2 cos beta) cos alpha_t, tan beta_b = tan beta cos alpha_t; the
    // standard centre distance, so the operating transverse angle is alpha_t. Gear on +y,
    // its pinion clockwise: d = (cos alpha_t, sin alpha_t). Left hand: the pinion is
    // pushed against its angular velocity, d delta / d z_p = +tan(beta_b) (MODEL.md 11.6).
    let beta: f64 = 15f64.to_radians();
    let at = (phi.tan() / beta.cos()).atan();
    let rb = |z: f64| z * 2.5e-3 / (2.0 * beta.cos()) * at.cos();
    let tan_bb = beta.tan() * at.cos();
    let mut g2 = DVector::zeros(n);
    g2[4] = at.cos();
    g2[5] = at.sin();
    g2[6] = -at.cos();
    g2[7] = -at.sin();
    g2[11] = rb(23.0);
    g2[12] = -rb(47.0);
    g2[14] = tan_bb;
    g2[15] = -tan_bb;
    // The closed forms and the program's geometry differ by round-off only.
    for (g_hand, mesh) in [(&g1, 0), (&g2, 1)] {
        let g = asm.mesh_gradient(mesh);
        let err = (&g - g_hand).amax();
        assert!(err < 1e-12, "mesh {}: {g} vs {g_hand}", mesh + 1);
    }
    // K + sum k_m g g^T at any mesh stiffnesses: the axial-torsional coupling
    // k r_b1 tan(beta_b) between phi_p2 and z_p2, k tan^2(beta_b) on z_p2.
    let km = [3.7e8, 4.4e8];
    let full = &k + &g1 * g1.transpose() * km[0] + &g2 * g2.transpose() * km[1];
    let err = (asm.stiffness_with_meshes(&km) - &full).amax();
    // The gradients agree to 1e-12 (entries of order 1 and radii of centimetres), so the
    // products k g_i g_j to about 1e-12 of the largest entry; 1e-10 of it leaves margin.
    assert!(err < 1e-10 * full.amax(), "{err} of {}", full.amax());
    assert!((full[(11, 14)] - km[1] * rb(23.0) * tan_bb).abs() < 1e-6 * km[1]);
}

/// Each column of a CSV text by its header name.
fn column(text: &str, name: &str) -> Vec<f64> {
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let i = head.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').nth(i).unwrap().parse().unwrap())
        .collect()
}

/// `gearwear dynamics` on `text`: the frequencies and amplitudes of `spectrum.csv`.
fn spectrum(text: &str) -> (Vec<f64>, Vec<f64>) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("train.toml");
    std::fs::write(&file, text).unwrap();
    let out = dir.path().join("out");
    let o = gearwear(&[
        "dynamics",
        "--config",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(out.join("spectrum.csv")).unwrap();
    (
        column(&text, "frequency_hz"),
        column(&text, "velocity_y_pinion_amplitude_mm_per_s"),
    )
}

#[test]
fn both_mesh_frequencies_stand_out_in_the_spectrum() {
    // The spectrum of stage 1's pinion velocity over the train's base period: mesh 1 at
    // f_1 = z_p1 f_in = 19 x 30 Hz, mesh 2 at f_2 = z_p2 f_in z_p1 / z_g1 = 23 x 30 x 19 /
    // 31 Hz (the intermediate shaft's speed), both computed here from the teeth and the
    // input speed. Each must be a line of the spectrum, above its two neighbours.
    let (f, a) = spectrum(TWO_STAGE);
    let df = f[1] - f[0];
    let f2 = 23.0 * 30.0 * 19.0 / 31.0;
    for (name, fm) in [("mesh 1", 19.0 * 30.0), ("mesh 2", f2)] {
        let i = (fm / df).round() as usize;
        // The line lies on a bin (both are whole multiples of the base frequency).
        assert!((f[i] - fm).abs() < 1e-9 * fm, "{name}: {} vs {fm}", f[i]);
        assert!(
            a[i] > a[i - 1] && a[i] > a[i + 1],
            "{name} at {fm} Hz: {} among {} and {}",
            a[i],
            a[i - 1],
            a[i + 1]
        );
    }
    // The helical stage's line is the quieter: its contact lines' total length varies
    // far less over a mesh period than a spur pair's (epsilon_beta = 0.82 here: the
    // stiffness fluctuation of MODEL.md 11.1's contact-line check), so the same stage at
    // beta = 0 must sound louder at f_2 (a factor 2 leaves room for the change of the
    // transverse geometry, which moves the train's modes).
    let (_, spur) = spectrum(&TWO_STAGE.replace("helix_angle_deg = 15", "helix_angle_deg = 0"));
    let i = (f2 / df).round() as usize;
    assert!(spur[i] > 2.0 * a[i], "spur {} vs helical {}", spur[i], a[i]);
}

#[test]
fn at_beta_zero_a_stage_is_the_spur_stage_bit_for_bit() {
    // Stage 2 with `helix_angle_deg = 0` given, and the helical keys a spur stage does
    // not use (slices, axial bearings: ignored with a warning), against the same train
    // without them.
    let spur = TWO_STAGE
        .replace("helix_angle_deg = 15\n", "")
        .replace("helix_hand_pinion = \"left\"\n", "")
        .replace("slices = 60\n", "");
    let spur = spur
        .lines()
        .filter(|l| !l.starts_with("bearing_axial"))
        .collect::<Vec<_>>()
        .join("\n");
    let zero = TWO_STAGE.replace("helix_angle_deg = 15", "helix_angle_deg = 0");
    let a = Model::dynamics_from_case(&case(&spur)).unwrap();
    let b = Model::dynamics_from_case(&case(&zero)).unwrap();
    assert!(b.warnings.iter().any(|w| w.contains("stage 2")
        && w.contains("`stage.bearing_axial_stiffness_pinion_n_per_m` = 500000000 is ignored")));
    assert_eq!(a.coordinate_names(), b.coordinate_names());
    let (ra, rb) = (steady(&a), steady(&b));
    assert_eq!(ra.end_state, rb.end_state);
    for k in 0..2 {
        assert_eq!(ra.signals.meshes[k].dte_m, rb.signals.meshes[k].dte_m);
        assert_eq!(
            ra.signals.meshes[k].mesh_force_n,
            rb.signals.meshes[k].mesh_force_n
        );
    }
}

fn case_file(dir: &tempfile::TempDir, text: &str) -> String {
    let path = dir.path().join("case.toml");
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

#[test]
fn studies_without_helical_stages_refuse_by_key() {
    let dir = tempfile::tempdir().unwrap();
    let file = case_file(&dir, TWO_STAGE);
    for study in ["wear", "run"] {
        rejected(
            &[study, "--config", &file],
            &[
                "`stage.helix_angle_deg` = 15 (stage 2)",
                "helical stage",
                study,
            ],
        );
    }
    // The helix from [gear] for every stage: named as the [gear] key.
    let from_gear = TWO_STAGE.replace("[operating]", "[gear]\nhelix_angle_deg = 12\n\n[operating]");
    let from_gear = from_gear.replace("helix_angle_deg = 15\n", "");
    let file = case_file(&dir, &from_gear);
    rejected(
        &["wear", "--config", &file],
        &["`gear.helix_angle_deg` = 12 (stage 1's, from `[gear]`)"],
    );
    // The library's own constructor, which every other study (dataset, calibrate,
    // predict, the wear sweeps, the spectra) builds on.
    let e = Model::from_case(&case(TWO_STAGE))
        .err()
        .unwrap()
        .to_string();
    assert!(e.contains("`stage.helix_angle_deg` = 15 (stage 2)"), "{e}");
}

#[test]
fn bad_helical_stage_keys_name_the_key_the_value_and_the_range() {
    let dir = tempfile::tempdir().unwrap();
    for (from, to, needles) in [
        (
            "helix_angle_deg = 15",
            "helix_angle_deg = 50",
            &["`stage.helix_angle_deg` = 50", "[0, 45)", "stage 2"][..],
        ),
        (
            "helix_hand_pinion = \"left\"",
            "helix_hand_pinion = \"up\"",
            &["`stage.helix_hand_pinion`", "left", "right", "stage 2"][..],
        ),
        (
            "slices = 60",
            "slices = 0",
            &["`stage.slices` = 0", "10000", "stage 2"][..],
        ),
        (
            "bearing_axial_stiffness_gear_n_per_m = 7e8",
            "bearing_axial_stiffness_gear_n_per_m = 10",
            &[
                "`stage.bearing_axial_stiffness_gear_n_per_m` = 10",
                "stage 2",
            ][..],
        ),
    ] {
        let text = TWO_STAGE.replace(from, to);
        assert_ne!(text, TWO_STAGE);
        let file = case_file(&dir, &text);
        rejected(&["dynamics", "--config", &file], needles);
    }
    // The lead keys need a gap per face slice, which a train's stage does not carry (the
    // stages' domain checks refuse them, a helical stage's too).
    let lead = TWO_STAGE.replace(
        "load_torque_nm = 60",
        "load_torque_nm = 60\nmisalignment_um = 5",
    );
    let file = case_file(&dir, &lead);
    rejected(
        &["dynamics", "--config", &file],
        &["stage 2", "`operating.misalignment_um` = 5", "remove them"],
    );
}
