//! A planetary set's lumped parameters for the tests of `[planetary]` cases.

/// Lin & Parker (1999) Table 1 as `[planetary.lumped]`: I = (I / r^2) r^2 and the ring's
/// torsional support k_ru r_r^2 with r the table's base radii (sun 38.7, planet 50.15,
/// ring 137.5 mm, carrier 88.4 mm); the radii cancel from the model. The carrier's
/// torsional support (0 in the table) as given: `gearwear dynamics` holds the output by it.
pub fn lin_parker_lumped(carrier_torsional_nm_per_rad: f64) -> String {
    let r2 = |mm: f64| (mm * 1e-3).powi(2);
    format!(
        "[planetary.lumped]\nmass_sun_kg = 0.4\nmass_planet_kg = 0.66\nmass_ring_kg = 2.35\nmass_carrier_kg = 5.43\n\
         inertia_sun_kg_m2 = {}\ninertia_planet_kg_m2 = {}\ninertia_ring_kg_m2 = {}\ninertia_carrier_kg_m2 = {}\n\
         base_radius_sun_mm = 38.7\nbase_radius_planet_mm = 50.15\nbase_radius_ring_mm = 137.5\ncarrier_radius_mm = 88.4\n\
         mesh_stiffness_sun_planet_n_per_m = 5e8\nmesh_stiffness_ring_planet_n_per_m = 5e8\n\
         bearing_stiffness_sun_n_per_m = 1e8\nbearing_stiffness_planet_n_per_m = 1e8\n\
         bearing_stiffness_ring_n_per_m = 1e8\nbearing_stiffness_carrier_n_per_m = 1e8\n\
         torsional_stiffness_sun_nm_per_rad = 0\ntorsional_stiffness_ring_nm_per_rad = {}\n\
         torsional_stiffness_carrier_nm_per_rad = {}\npressure_angle_deg = 24.6\n",
        0.39 * r2(38.7),
        0.61 * r2(50.15),
        3.0 * r2(137.5),
        6.29 * r2(88.4),
        1e9 * r2(137.5),
        carrier_torsional_nm_per_rad,
    )
}

/// `gearwear STUDY -q` on the case `text` in a fresh folder: the folder (kept alive; the
/// run is in `out`) and `summary.json`; the run must succeed.
pub fn run_case(study: &str, text: &str) -> (tempfile::TempDir, serde_json::Value) {
    run_case_with(study, text, &[])
}

/// As [`run_case`], with the further arguments `extra` (e.g. `--mode quasi-static`).
pub fn run_case_with(
    study: &str,
    text: &str,
    extra: &[&str],
) -> (tempfile::TempDir, serde_json::Value) {
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("case.toml");
    std::fs::write(&case, text).unwrap();
    let out = d.path().join("out");
    let mut a = vec![
        study,
        "-q",
        "--config",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    a.extend(extra);
    let o = super::gearwear(&a);
    assert_eq!(o.status.code(), Some(0), "{}", super::stderr(&o));
    let s = std::fs::read_to_string(out.join("summary.json")).unwrap();
    (d, serde_json::from_str(&s).unwrap())
}
