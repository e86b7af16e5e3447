//! One table describing every key of the case file: its unit, meaning and valid range.
//!
//! The same table prints the commented default (`gearwear config`), validates a loaded
//! case, and writes `docs/CONFIG.md`, so the three cannot drift apart.

/// What values a key accepts.
#[derive(Debug, Clone, Copy)]
pub enum Valid {
    /// Strictly positive number.
    Positive,
    /// Zero or more.
    NonNegative,
    /// Closed interval [lo, hi].
    Closed(f64, f64),
    /// Open interval (lo, hi).
    Open(f64, f64),
    /// Whole number at least this.
    IntAtLeast(i64),
    /// One of these strings.
    Choice(&'static [&'static str]),
    /// true or false.
    Bool,
    /// Array of numbers, each zero or more.
    NonNegativeArray,
}

impl Valid {
    /// Human text of the valid range, used in messages and docs.
    pub fn describe(&self) -> String {
        match self {
            Valid::Positive => "a number > 0".into(),
            Valid::NonNegative => "a number >= 0".into(),
            Valid::Closed(a, b) => format!("a number in [{a}, {b}]"),
            Valid::Open(a, b) => format!("a number in ({a}, {b})"),
            Valid::IntAtLeast(n) => format!("a whole number >= {n}"),
            Valid::Choice(c) => format!(
                "one of {}",
                c.iter()
                    .map(|s| format!("\"{s}\""))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            Valid::Bool => "true or false".into(),
            Valid::NonNegativeArray => "an array of numbers >= 0".into(),
        }
    }
}

/// One key of the case file.
#[derive(Debug, Clone, Copy)]
pub struct KeySpec {
    /// Dotted path, `section.key`.
    pub key: &'static str,
    /// Unit ("-" for dimensionless).
    pub unit: &'static str,
    /// What it is, and the source of its default.
    pub doc: &'static str,
    pub valid: Valid,
}

const fn k(key: &'static str, unit: &'static str, valid: Valid, doc: &'static str) -> KeySpec {
    KeySpec {
        key,
        unit,
        doc,
        valid,
    }
}

use Valid::*;

/// Every key, in the order the template prints them.
pub const KEYS: &[KeySpec] = &[
    k("gear.module_mm", "mm", Positive, "Module m (paper Table 1: 2 mm)."),
    k("gear.teeth_pinion", "-", IntAtLeast(6), "Pinion teeth z1 (paper: 19)."),
    k("gear.teeth_gear", "-", IntAtLeast(6), "Gear teeth z2 (paper: 31)."),
    k("gear.pressure_angle_deg", "deg", Closed(10.0, 35.0), "Reference pressure angle alpha (paper: 20)."),
    k("gear.addendum_coefficient", "-", Closed(0.5, 1.5), "Addendum coefficient h_a* (paper: 1.00 m)."),
    k("gear.dedendum_coefficient", "-", Closed(0.8, 2.0), "Dedendum coefficient h_f* (paper: 1.25 m)."),
    k("gear.profile_shift_pinion", "-", Closed(-1.0, 1.5), "Profile shift coefficient x1 (paper: 0)."),
    k("gear.profile_shift_gear", "-", Closed(-1.0, 1.5), "Profile shift coefficient x2 (paper: 0)."),
    k("gear.face_width_mm", "mm", Positive, "Face width b (paper: 20 mm)."),
    k("gear.centre_distance_mm", "mm", Positive, "Operating centre distance; omit for the one the profile shifts give (paper: 50 mm)."),
    k("gear.hub_bore_radius_pinion_mm", "mm", Positive, "Pinion hub bore radius r_int for the fillet foundation (not in the paper; 8 mm gives h_f = r_f/r_int ~ 2)."),
    k("gear.hub_bore_radius_gear_mm", "mm", Positive, "Gear hub bore radius r_int (not in the paper; 14 mm gives h_f ~ 2)."),
    k("gear.tool_tip_radius_coefficient", "-", Closed(0.0, 0.6), "Rack-cutter tip radius / m, for the undercut check (ISO 53 profile A: 0.38)."),
    k("materials.youngs_modulus_pinion_gpa", "GPa", Positive, "Pinion Young's modulus (paper: 205 GPa)."),
    k("materials.poisson_ratio_pinion", "-", Open(0.0, 0.5), "Pinion Poisson's ratio (paper: 0.3)."),
    k("materials.youngs_modulus_gear_gpa", "GPa", Positive, "Gear Young's modulus (paper: 205 GPa)."),
    k("materials.poisson_ratio_gear", "-", Open(0.0, 0.5), "Gear Poisson's ratio (paper: 0.3)."),
    k("operating.input_speed_hz", "Hz", Positive, "Pinion (input) shaft speed (paper 4.1: 30 Hz)."),
    k("operating.load_torque_nm", "N m", Positive, "Load torque (paper: 60 N m)."),
    k("operating.load_torque_shaft", "-", Choice(&["pinion", "gear"]), "Shaft the load torque is referred to; \"pinion\" matches the paper's 3311 N mean force (docs/PAPER_NOTES.md)."),
    k("operating.speed_boundary", "-", Choice(&["motor_speed_imposed", "brake_speed_imposed", "motor_slip"]), "How the mean speed is held: a motor torque law T_0 - c_slip (dtheta_m/dt - Omega) (default, paper eq. 1 keeps the motor as a torque-driven inertia), motor angle imposed, or brake angle imposed. Moves the lowest modes (docs/MODEL.md)."),
    k("operating.motor_slip_damping_nm_s_per_rad", "N m s/rad", Positive, "Slope c_slip of the motor torque-speed law, used by speed_boundary = \"motor_slip\" (10: induction motor with ~3 % rated slip at 60 N m, 30 Hz)."),
    k("lubricant.viscosity_cp", "cP", Positive, "Inlet absolute viscosity nu_0 (not in the paper; 40 cP, ISO VG 100 near 60 degC). Must exceed 1 cP with the Xu model."),
    k("surface.roughness_table_wear_um", "um", NonNegativeArray, "Maximum pinion wear depth at the roughness table points, ascending (paper 4.1: 0.1, 0.5, 1 um)."),
    k("surface.roughness_table_rms_um", "um", NonNegativeArray, "Composite RMS roughness S at those points; linear in between, constant outside (paper's 2.1/1.9/1.5 read as 0.21/0.19/0.15, see docs/MODEL.md)."),
    k("dynamics.mass_pinion_kg", "kg", Positive, "Pinion mass m_p (paper Table 2: 0.7)."),
    k("dynamics.mass_gear_kg", "kg", Positive, "Gear mass m_g (paper: 1.822)."),
    k("dynamics.inertia_pinion_kg_m2", "kg m^2", Positive, "Pinion inertia J_p (paper: 2.331e-4)."),
    k("dynamics.inertia_gear_kg_m2", "kg m^2", Positive, "Gear inertia J_g (paper: 1.392e-3)."),
    k("dynamics.inertia_motor_kg_m2", "kg m^2", Positive, "Motor inertia J_m (paper: 2.1e-3)."),
    k("dynamics.inertia_brake_kg_m2", "kg m^2", Positive, "Brake inertia J_b (paper: 1.05e-2)."),
    k("dynamics.bearing_stiffness_pinion_n_per_m", "N/m", Positive, "Pinion bearing stiffness, x and y (paper: 5e8; printed unit N m read as N/m)."),
    k("dynamics.bearing_stiffness_gear_n_per_m", "N/m", Positive, "Gear bearing stiffness, x and y (paper: 5e8)."),
    k("dynamics.bearing_damping_pinion_n_s_per_m", "N s/m", NonNegative, "Pinion bearing damping, x and y (paper: 4e5)."),
    k("dynamics.bearing_damping_gear_n_s_per_m", "N s/m", NonNegative, "Gear bearing damping, x and y (paper: 4e5)."),
    k("dynamics.coupling_stiffness_motor_nm_per_rad", "N m/rad", Positive, "Motor-pinion coupling torsional stiffness k_mp (paper: 4e7)."),
    k("dynamics.coupling_stiffness_brake_nm_per_rad", "N m/rad", Positive, "Gear-brake coupling torsional stiffness k_bg (paper: 4e7)."),
    k("dynamics.coupling_damping_motor_nm_s_per_rad", "N m s/rad", NonNegative, "Motor-pinion coupling torsional damping c_mp (paper: 3e4)."),
    k("dynamics.coupling_damping_brake_nm_s_per_rad", "N m s/rad", NonNegative, "Gear-brake coupling torsional damping c_bg (paper: 3e4)."),
    k("dynamics.mesh_damping_ratio", "-", Closed(0.0, 1.0), "Mesh damping ratio zeta, c_m = 2 zeta sqrt(k_mean m_e) (not in the paper; 0.05, docs/PAPER_NOTES.md gives 0.03-0.1)."),
    k("stiffness.fillet_foundation", "-", Bool, "Include the Sainsot (2004) fillet-foundation compliance."),
    k("stiffness.table_points_per_mesh_period", "-", IntAtLeast(16), "Samples of the mesh-stiffness table over one mesh period (cubic interpolation in between)."),
    k("contact.load_sharing", "-", Choice(&["pedrero", "stiffness"]), "Load sharing between two pairs: paper eq. (7) (Pedrero) or by pair stiffness and deflection."),
    k("friction.model", "-", Choice(&["xu2007", "constant", "none"]), "Friction coefficient: Xu et al. (2007) regression (paper eq. 8-9), a constant, or none."),
    k("friction.constant_coefficient", "-", Closed(0.0, 1.0), "Coefficient used with model = \"constant\"."),
    k("friction.xu_radius_unit", "-", Choice(&["m", "mm"]), "Unit of the radius of curvature R in Xu's regression (docs/PAPER_NOTES.md; Xu et al. use m)."),
    k("friction.direction_smoothing_m_per_s", "m/s", Positive, "Sliding speed over which the friction direction turns through the pitch point (tanh)."),
    k("wear.coefficient_m2_per_n", "m^2/N", NonNegative, "Archard wear coefficient k (paper's 2.5e-12 read as cm^2/N = 2.5e-16 m^2/N)."),
    k("wear.block_cycles", "cycles", Positive, "Cycles m the per-cycle wear is held for between dynamic updates (paper eq. 17: 1e4)."),
    k("wear.threshold_um", "um", Positive, "Largest wear depth one block may add at any point (paper's epsilon^m: 0.5 um)."),
    k("wear.total_cycles", "cycles", Positive, "Pinion load cycles (revolutions) of the wear study (paper Fig. 13: 4e4)."),
    k("wear.points_per_profile", "-", IntAtLeast(11), "Points on each active profile for the wear bookkeeping."),
    k("numerics.steps_per_mesh_period", "-", IntAtLeast(20), "Grid nodes per mesh period, aligned with the mesh events: the longest integration step and the fewest recorded samples per period."),
    k("numerics.integration_tolerance", "-", Open(0.0, 1.0), "Local error per integration step, relative to the state's scales (static mesh deflection, and its rate at the mesh frequency); the error control adds steps where the dynamics need them."),
    k("numerics.max_mesh_periods", "-", IntAtLeast(2), "Mesh periods after which the search for steady state gives up."),
    k("numerics.steady_state_tolerance", "-", Open(0.0, 1.0), "Steady state: largest change of the state over one mesh period, relative to its scale."),
    k("numerics.evaluated_mesh_periods", "-", IntAtLeast(1), "Mesh periods recorded once steady (signals and spectra)."),
];

/// Look up a key's spec.
pub fn spec(key: &str) -> Option<&'static KeySpec> {
    KEYS.iter().find(|s| s.key == key)
}
