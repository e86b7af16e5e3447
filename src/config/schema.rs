//! One table describing every key of the case file: its unit, meaning, valid range and
//! the reason for that range.
//!
//! The same table prints the commented default (`gearwear config`), validates a loaded
//! case, and writes `docs/CONFIG.md`, so the three cannot drift apart. Every numeric key
//! has a finite range: values outside it are physically meaningless for a spur pair, or
//! make a run that cannot finish (issue 13). What a range cannot express (a bore inside
//! the root circle, a load the flanks cannot carry) is checked where the geometry is
//! known (`geometry::GearPair`, `study::domain`), and the cost of a run by
//! `study::budget`.

/// An interval of numbers; `open_lo` / `open_hi` exclude an end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// Whether the lower end is excluded.
    pub open_lo: bool,
    /// Whether the upper end is excluded.
    pub open_hi: bool,
}

impl Range {
    /// [lo, hi].
    pub const fn closed(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_lo: false,
            open_hi: false,
        }
    }

    /// (lo, hi].
    pub const fn above(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_lo: true,
            open_hi: false,
        }
    }

    /// [lo, hi).
    pub const fn below(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_lo: false,
            open_hi: true,
        }
    }

    /// (lo, hi).
    pub const fn open(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_lo: true,
            open_hi: true,
        }
    }

    /// Whether `x` is a normal (finite, not subnormal) number inside the interval. Zero
    /// is normal here; subnormal numbers (below 2.2e-308 in magnitude) are not: no
    /// quantity of a gear case lies there, and they overflow the solvers' divisions.
    pub fn contains(&self, x: f64) -> bool {
        let normal = x == 0.0 || x.is_normal();
        let lo_ok = if self.open_lo {
            x > self.lo
        } else {
            x >= self.lo
        };
        let hi_ok = if self.open_hi {
            x < self.hi
        } else {
            x <= self.hi
        };
        normal && lo_ok && hi_ok
    }

    /// "[0.1, 50]", "(0, 0.5)", ...
    pub fn describe(&self) -> String {
        format!(
            "{}{}, {}{}",
            if self.open_lo { "(" } else { "[" },
            number(self.lo),
            number(self.hi),
            if self.open_hi { ")" } else { "]" }
        )
    }
}

/// A number as people write it: 0.1, 50, 1e-11, 1e6.
pub fn number(x: f64) -> String {
    let a = x.abs();
    if a != 0.0 && !(1e-3..1e5).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// What values a key accepts.
#[derive(Debug, Clone, Copy)]
pub enum Valid {
    /// A finite number in the range.
    Num(Range),
    /// A number in the range, or the string "derived" (the model computes it from the
    /// geometry).
    NumOrDerived(Range),
    /// A whole number in [lo, hi] (written 25 or 25.0).
    Int(i64, i64),
    /// One of these strings.
    Choice(&'static [&'static str]),
    /// true or false.
    Bool,
    /// A non-empty array of numbers, each in the range.
    NumArray(Range),
}

impl Valid {
    /// Human text of the valid values, used in messages and docs.
    pub fn describe(&self) -> String {
        match self {
            Valid::Num(r) => format!("a number in {}", r.describe()),
            Valid::NumOrDerived(r) => format!("a number in {}, or \"derived\"", r.describe()),
            Valid::Int(a, b) => format!("a whole number in [{a}, {}]", number(*b as f64)),
            Valid::Choice(c) => format!(
                "one of {}",
                c.iter()
                    .map(|s| format!("\"{s}\""))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            Valid::Bool => "true or false".into(),
            Valid::NumArray(r) => format!("an array of numbers in {}", r.describe()),
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
    /// The values it accepts.
    pub valid: Valid,
    /// Why the valid range is what it is.
    pub reason: &'static str,
}

const fn k(
    key: &'static str,
    unit: &'static str,
    valid: Valid,
    doc: &'static str,
    reason: &'static str,
) -> KeySpec {
    KeySpec {
        key,
        unit,
        doc,
        valid,
        reason,
    }
}

use Valid::*;

const MASS: Range = Range::closed(1e-4, 1e5);
const INERTIA: Range = Range::closed(1e-10, 1e5);
const BORE: Range = Range::closed(0.1, 1e4);
/// Per-tooth errors and deviations, um.
const TOOTH_ERROR: Range = Range::closed(-1000.0, 1000.0);

/// Every key, in the order the template prints them.
pub const KEYS: &[KeySpec] = &[
    k("gear.module_mm", "mm", Num(Range::closed(0.1, 50.0)), "Module m (paper Table 1: 2 mm).",
      "From instrument gears (0.1 mm) to the largest modules of ISO 54 (50 mm); below, a tooth is a few grains of steel and the continuum beam and Hertz models of a tooth no longer hold."),
    k("gear.teeth_pinion", "-", Int(6, 1000), "Pinion teeth z1 (paper: 19).",
      "Below 6 teeth no standard pair meshes; 1000 covers the largest bull gears."),
    k("gear.teeth_gear", "-", Int(6, 1000), "Gear teeth z2 (paper: 31).",
      "As for the pinion."),
    k("gear.pressure_angle_deg", "deg", Num(Range::closed(10.0, 35.0)), "Reference pressure angle alpha (paper: 20).",
      "Standard racks use 14.5 to 25 deg; outside 10-35 deg teeth undercut or point for any usual tooth count."),
    k("gear.addendum_coefficient", "-", Num(Range::closed(0.5, 1.5)), "Addendum coefficient h_a* (paper: 1.00 m).",
      "Stub (0.8) to long-addendum (1.2-1.4) systems; beyond, tips point or the contact ratio falls below 1."),
    k("gear.dedendum_coefficient", "-", Num(Range::closed(0.8, 2.0)), "Dedendum coefficient h_f* (paper: 1.25 m).",
      "Stub teeth (~1.0) to deep-root racks (~1.6), with room either side."),
    k("gear.profile_shift_pinion", "-", Num(Range::closed(-1.0, 1.5)), "Profile shift coefficient x1 (paper: 0).",
      "Beyond these shifts teeth point (positive) or are cut away (negative) for any tooth count the model accepts."),
    k("gear.profile_shift_gear", "-", Num(Range::closed(-1.0, 1.5)), "Profile shift coefficient x2 (paper: 0).",
      "As for the pinion."),
    k("gear.face_width_mm", "mm", Num(Range::closed(0.1, 2000.0)), "Face width b (paper: 20 mm).",
      "Instrument gears to mill drives; the pair also needs 1 <= b/m <= 100 (checked with the module): a narrower tooth is a plate, a wider one cannot bear evenly."),
    k("gear.centre_distance_mm", "mm", Num(Range::closed(0.1, 1e5)), "Operating centre distance; omit for the one the profile shifts give (paper: 50 mm).",
      "Checked against the pair: the tooth tips must reach each other (contact ratio >= 1) without interfering."),
    k("gear.hub_bore_radius_pinion_mm", "mm", NumOrDerived(BORE), "Pinion hub bore radius r_int for the fillet foundation (not in the paper; 8 mm gives h_f = r_f/r_int ~ 2). \"derived\": r_f/2.",
      "At least 0.1 mm (a smaller bore is a solid blank, which Sainsot's ring model does not describe) and inside the root circle (checked with the geometry); \"derived\" puts h_f = 2, inside Sainsot's fit (1.4-7)."),
    k("gear.hub_bore_radius_gear_mm", "mm", NumOrDerived(BORE), "Gear hub bore radius r_int (not in the paper; 14 mm gives h_f ~ 2). \"derived\": r_f/2.",
      "As for the pinion."),
    k("gear.tool_tip_radius_coefficient", "-", Num(Range::closed(0.0, 0.6)), "Rack-cutter tip radius / m: the root fillet, the undercut check and Sainsot's theta_f (ISO 53 profile A: 0.38).",
      "ISO 53 racks use 0.25-0.4; a larger radius no longer fits the rack's tip for usual dedendums."),
    k("gear.helix_angle_deg", "deg", Num(Range::below(0.0, 45.0)), "Helix angle beta at the reference cylinder; 0 (default) is a spur pair. A helical pair reads the other `gear` keys as the normal section (module m_n, pressure angle alpha_n, shifts x_n); `gearwear stiffness`, `gearwear dynamics` (planar model: slice mesh stiffness, axial force reported), `gearwear signals` (its steady record), `gearwear wear` (Archard wear per face slice, docs/MODEL.md 11.3), `gearwear sweep` (of dynamics or wear, docs/MODEL.md 11.4) and `gearwear run` (those studies with a report, docs/MODEL.md 11.5) take it; `dataset`, `calibrate` and `predict` refuse it. Example: examples/helical_pair.toml.",
      "Parallel-axis helical gears run up to about 45 deg; ISO 6336's helical stiffness is not made for more."),
    k("gear.helix_hand_pinion", "-", Choice(&["left", "right"]), "Hand of the pinion's helix; the gear takes the other. Ignored at a helix angle of 0.",
      "-"),
    k("materials.youngs_modulus_pinion_gpa", "GPa", Num(Range::closed(1.0, 1000.0)), "Pinion Young's modulus (paper: 205 GPa).",
      "Engineering polymers (~1-3 GPa) to cemented carbide (~650 GPa)."),
    k("materials.poisson_ratio_pinion", "-", Num(Range::open(0.0, 0.5)), "Pinion Poisson's ratio (paper: 0.3).",
      "Isotropic solids with a positive ratio; 0.5 (incompressible) divides by zero in the shear modulus' uses."),
    k("materials.youngs_modulus_gear_gpa", "GPa", Num(Range::closed(1.0, 1000.0)), "Gear Young's modulus (paper: 205 GPa).",
      "As for the pinion."),
    k("materials.poisson_ratio_gear", "-", Num(Range::open(0.0, 0.5)), "Gear Poisson's ratio (paper: 0.3).",
      "As for the pinion."),
    k("operating.input_speed_rpm", "rpm", Num(Range::closed(6e-5, 60_000.0)), "Pinion (input) shaft speed in revolutions per minute, instead of `operating.input_speed_hz` (give one of the two); read as input_speed_hz = rpm / 60, so the case is the same either way.",
      "the range of `operating.input_speed_hz` times 60"),
    k("operating.input_speed_hz", "Hz", Num(Range::closed(1e-6, 1000.0)), "Pinion (input) shaft speed (paper 4.1: 30 Hz).",
      "From a turn in 12 days (the quasi-static limit, used by tests of the model) to 60000 rpm; high-speed turbine gears stay below ~500 Hz."),
    k("operating.load_torque_nm", "N m", Num(Range::closed(1e-3, 1e7)), "Load torque (paper: 60 N m).",
      "Instrument drives (mN m) to rolling-mill drives (10 MN m); the Hertz pressure it gives on this pair must also stay below 10 GPa (checked with the geometry), far beyond any steel's elastic limit."),
    k("operating.load_torque_shaft", "-", Choice(&["pinion", "gear"]), "Shaft the load torque is referred to; \"pinion\" matches the paper's 3311 N mean force (docs/MODEL.md).",
      "-"),
    k("operating.speed_boundary", "-", Choice(&["motor_speed_imposed", "brake_speed_imposed", "motor_slip"]), "How the mean speed is held: a motor torque law T_0 - c_slip (dtheta_m/dt - Omega) (default, paper eq. 1 keeps the motor as a torque-driven inertia), motor angle imposed, or brake angle imposed. Moves the lowest modes (docs/MODEL.md).",
      "-"),
    k("operating.motor_slip_damping_nm_s_per_rad", "N m s/rad", Num(Range::closed(1e-3, 1e6)), "Slope c_slip of the motor torque-speed law, used by speed_boundary = \"motor_slip\" (10: induction motor with ~3 % rated slip at 60 N m, 30 Hz).",
      "Torque-speed slopes of real motors, from small servo motors to multi-MW drives."),
    k("operating.misalignment_um", "µm", Num(Range::closed(-1000.0, 1000.0)), "Mesh misalignment: the difference across the face width of the flanks' separation, linear, positive opening it towards the face end y = b; in `operating.misalignment_plane`. Taken by `gearwear stiffness` (face load distribution, K_Hbeta) and, on a helical pair, by `gearwear dynamics`, `wear`, `run` and `sweep` (docs/MODEL.md 11.1-11.5). Absent: 0.",
      "A millimetre either way over a face is beyond any shaft and housing the model takes; a value leaving the load on one slice is refused with the geometry."),
    k("operating.misalignment_plane", "-", Choice(&["action", "normal"]), "Plane of `operating.misalignment_um`: \"action\" (default) opens a gap along the line of action; \"normal\" (through the axis, normal to the plane of action) moves the flanks along each other, opens no gap to first order and is ignored with a warning (docs/MODEL.md 11.2).",
      "-"),
    k("load_spectrum.torque_shaft", "-", Choice(&["pinion", "gear"]), "Shaft the spectrum's bin torques are on (on a gear train: \"pinion\" the input shaft, \"gear\" the output shaft, the last stage's gear; on a planetary set only \"pinion\": the input member); omit for `operating.load_torque_shaft`. The bins themselves are `bins = [{torque_nm, input_speed_hz (or input_speed_rpm), share (or hours)}, ...]` or `file = \"spectrum.csv\"` (see \"Load spectrum\" above).",
      "-"),
    k("load_spectrum.torque_scale", "-", Num(Range::closed(1e-3, 1e3)), "Factor on every bin's torque (a sweep axis: all torques x 1.2); omit for 1.",
      "Each scaled torque must also lie in the range of `operating.load_torque_nm` (checked per bin); a factor of 1000 either way spans any re-rating."),
    k("load_spectrum.speed_scale", "-", Num(Range::closed(1e-3, 1e3)), "Factor on every bin's input speed; omit for 1.",
      "Each scaled speed must also lie in the range of `operating.input_speed_hz` (checked per bin)."),
    k("load_spectrum.monitoring_bin", "-", Int(1, 10_000), "Bin (1-based) at which vibration observations are taken for `calibrate` (a monitoring system records at a reference condition); omit for the bin with the largest share.",
      "At most the number of bins (checked), itself at most 10 000."),
    k("load_spectrum.life_wear_limit_um", "µm", Num(Range::closed(0.01, 1000.0)), "Maximum pinion wear depth that ends the flanks' life in the life table of `run` and `wear` (under the spectrum and at each bin alone; on a planetary set the largest depth of any member flank, docs/MODEL.md 12.12; 10 µm: a fifth of a 2 mm module's customary 0.05 m wear allowance).",
      "From the first running-in (0.01 µm) to a millimetre; the model stops earlier where the worn teeth lose contact (docs/MODEL.md)."),
    k("lubricant.viscosity_cp", "cP", Num(Range::closed(0.1, 1e5)), "Inlet absolute viscosity nu_0 (not in the paper; 40 cP, ISO VG 100 near 60 degC). Must exceed 1 cP with the Xu model.",
      "Light solvents (~0.3 cP) to cold heavy gear oil (~1e4 cP); Xu's regression also needs > 1 cP (checked)."),
    k("surface.roughness_table_wear_um", "µm", NumArray(Range::closed(0.0, 1000.0)), "Maximum pinion wear depth at the roughness table points, ascending (paper 4.1: 0.1, 0.5, 1 µm).",
      "Up to a millimetre of wear, far beyond the small-wear model; the table must ascend (checked)."),
    k("surface.roughness_table_rms_um", "µm", NumArray(Range::closed(0.0, 5.0)), "Composite RMS roughness S at those points; linear in between, constant outside (paper's 2.1/1.9/1.5 read as 0.21/0.19/0.15, see docs/MODEL.md).",
      "Ground to rough-hobbed flanks; Xu's regression grows as exp(e^S) and overflows near S = 7 µm."),
    k("dynamics.mass_pinion_kg", "kg", NumOrDerived(MASS), "Pinion mass m_p (paper Table 2: 0.7). \"derived\": a solid blank of the face width between bore and pitch circle.",
      "0.1 g to 100 t; a value more than 2 times off the geometry's estimate is warned about."),
    k("dynamics.mass_gear_kg", "kg", NumOrDerived(MASS), "Gear mass m_g (paper: 1.822). \"derived\" as for the pinion.",
      "As for the pinion."),
    k("dynamics.inertia_pinion_kg_m2", "kg m^2", NumOrDerived(INERTIA), "Pinion inertia J_p (paper: 2.331e-4). \"derived\": the blank's polar inertia.",
      "A 1 mm steel disk (~1e-10) to a 100 t, 2 m wheel; a value more than 2 times off the geometry's estimate is warned about."),
    k("dynamics.inertia_gear_kg_m2", "kg m^2", NumOrDerived(INERTIA), "Gear inertia J_g (paper: 1.392e-3). \"derived\" as for the pinion.",
      "As for the pinion."),
    k("dynamics.blank_density_kg_per_m3", "kg/m^3", Num(Range::closed(500.0, 25000.0)), "Density of both gear blanks, used by the \"derived\" masses and inertias (steel: 7850).",
      "Polymers (~900-1400) to tungsten alloys (~19000)."),
    k("dynamics.inertia_motor_kg_m2", "kg m^2", Num(INERTIA), "Motor inertia J_m (paper: 2.1e-3).",
      "As for the gears; the geometry cannot give it."),
    k("dynamics.inertia_brake_kg_m2", "kg m^2", Num(INERTIA), "Brake inertia J_b (paper: 1.05e-2).",
      "As for the motor."),
    k("dynamics.bearing_stiffness_pinion_n_per_m", "N/m", Num(Range::closed(1e4, 1e12)), "Pinion bearing stiffness, x and y (paper: 5e8; printed unit N m read as N/m).",
      "Compliant mounts to the stiffest rolling bearings (~1e10 N/m), with margin."),
    k("dynamics.bearing_stiffness_gear_n_per_m", "N/m", Num(Range::closed(1e4, 1e12)), "Gear bearing stiffness, x and y (paper: 5e8).",
      "As for the pinion."),
    k("dynamics.bearing_damping_pinion_n_s_per_m", "N s/m", Num(Range::closed(0.0, 1e8)), "Pinion bearing damping, x and y (paper: 4e5).",
      "Undamped to 100 times the paper's heavily damped bearings."),
    k("dynamics.bearing_damping_gear_n_s_per_m", "N s/m", Num(Range::closed(0.0, 1e8)), "Gear bearing damping, x and y (paper: 4e5).",
      "As for the pinion."),
    k("dynamics.coupling_stiffness_motor_nm_per_rad", "N m/rad", Num(Range::closed(1.0, 1e10)), "Motor-pinion coupling torsional stiffness k_mp (paper: 4e7).",
      "Soft elastomer couplings (~1e2) to rigid shafts of large drives."),
    k("dynamics.coupling_stiffness_brake_nm_per_rad", "N m/rad", Num(Range::closed(1.0, 1e10)), "Gear-brake coupling torsional stiffness k_bg (paper: 4e7).",
      "As for the motor coupling."),
    k("dynamics.coupling_damping_motor_nm_s_per_rad", "N m s/rad", Num(Range::closed(0.0, 1e7)), "Motor-pinion coupling torsional damping c_mp (paper: 3e4).",
      "Undamped to 300 times the paper's value."),
    k("dynamics.coupling_damping_brake_nm_s_per_rad", "N m s/rad", Num(Range::closed(0.0, 1e7)), "Gear-brake coupling torsional damping c_bg (paper: 3e4).",
      "As for the motor coupling."),
    k("dynamics.mesh_damping_ratio", "-", Num(Range::closed(0.0, 1.0)), "Mesh damping ratio zeta, c_m = 2 zeta sqrt(k_mean m_e) (not in the paper; 0.05, measured gears show 0.03-0.1).",
      "Undamped to critically damped."),
    k("dynamics.bearing_axial_stiffness_pinion_n_per_m", "N/m", Num(Range::closed(1e4, 1e12)), "Pinion axial bearing stiffness (a helical pair only). Given, the pinion carries an axial degree of freedom z_p held by this spring and the mesh deflection takes its axial motion (docs/MODEL.md 11.6); absent (default): the axial bearing is rigid, the planar model of docs/MODEL.md 11.1. Ignored, with a warning, on a spur pair (no axial mesh force).",
      "As the radial `dynamics.bearing_stiffness_pinion_n_per_m`: compliant mounts to the stiffest rolling bearings, with margin; rigid is the key left out."),
    k("dynamics.bearing_axial_stiffness_gear_n_per_m", "N/m", Num(Range::closed(1e4, 1e12)), "Gear axial bearing stiffness, as the pinion's (absent: rigid).",
      "As for the pinion."),
    k("dynamics.bearing_axial_damping_pinion_n_s_per_m", "N s/m", Num(Range::closed(0.0, 1e8)), "Pinion axial bearing damping, taken with `dynamics.bearing_axial_stiffness_pinion_n_per_m` (absent: the radial `dynamics.bearing_damping_pinion_n_s_per_m`, the same bearing's; the paper gives no axial value).",
      "As the radial damping."),
    k("dynamics.bearing_axial_damping_gear_n_s_per_m", "N s/m", Num(Range::closed(0.0, 1e8)), "Gear axial bearing damping, taken with `dynamics.bearing_axial_stiffness_gear_n_per_m` (absent: the radial `dynamics.bearing_damping_gear_n_s_per_m`).",
      "As for the pinion."),
    k("dynamics.bearing_tilt_stiffness_pinion_nm_per_rad", "N m/rad", Num(Range::closed(1e3, 1e12)), "Pinion tilting bearing stiffness about each of the two axes normal to its shaft (a single helical pair in `gearwear dynamics`, `signals`, `stiffness` and the dynamics sweeps). Given, the pinion carries two tilting degrees of freedom held by this spring, and each face slice's mesh deflection takes the tilt (docs/MODEL.md 11.8); absent (default): tilting is held rigidly, the planar or axial model exactly as without the key. Ignored, with a warning, on a spur pair; refused by trains, planetary sets and, on a helical pair, the wear studies (`wear`, `run`, a load spectrum, a wear sweep). The tilting moments reach no sensor in `signals`.",
      "From a soft overhung shaft (1e3 N m/rad) to rigid mounts; rigid is the key left out."),
    k("dynamics.bearing_tilt_stiffness_gear_nm_per_rad", "N m/rad", Num(Range::closed(1e3, 1e12)), "Gear tilting bearing stiffness, as the pinion's (absent: rigid).",
      "As for the pinion."),
    k("dynamics.bearing_tilt_damping_pinion_nm_s_per_rad", "N m s/rad", Num(Range::closed(0.0, 1e6)), "Pinion tilting bearing damping about each axis normal to the shaft, taken with `dynamics.bearing_tilt_stiffness_pinion_nm_per_rad` (absent: 0; the paper gives no tilting value).",
      "Undamped to heavily damped."),
    k("dynamics.bearing_tilt_damping_gear_nm_s_per_rad", "N m s/rad", Num(Range::closed(0.0, 1e6)), "Gear tilting bearing damping, taken with `dynamics.bearing_tilt_stiffness_gear_nm_per_rad` (absent: 0).",
      "As for the pinion."),
    k("stiffness.fillet_foundation", "-", Bool, "Include the Sainsot (2004) fillet-foundation compliance.",
      "-"),
    k("stiffness.fillet_root_angle", "-", Choice(&["fillet_junction", "flank_extension"]), "Where Sainsot's root half angle theta_f (and S_f = 2 r_f theta_f) is taken: where the root fillet meets the root circle (Sainsot et al. 2004; Chen & Shao 2011; default), or where the flank's extension meets it (gearwear before issue 10). docs/MODEL.md.",
      "-"),
    k("stiffness.allow_fillet_extrapolation", "-", Bool, "Use Sainsot's fit outside its published range (1.4 <= h_f <= 7, 0.01 <= theta_f <= 0.12 rad), with a warning; false makes it an error, except for theta_f up to 0.25 rad (pinions of fewer than 26 teeth), which is extrapolated without a warning (measured smooth; docs/MODEL.md).",
      "-"),
    k("stiffness.table_points_per_mesh_period", "-", Int(16, 100_000), "Samples of the mesh-stiffness table over one mesh period (cubic interpolation in between).",
      "16 points resolve the curve to ~1e-4; beyond 1e5 only round-off changes."),
    k("stiffness.slices", "-", Int(1, 10_000), "Slices N across the face of a helical pair, each a transverse spur slice of width b/N staggered by y tan(beta_b) (default 400: the peak-to-peak mesh stiffness within 1 % of its N -> infinity limit needs about 300). Unused by a spur pair.",
      "One slice is the transverse pair unstaggered; 10 000 slices of a 1 m face are 0.1 mm wide."),
    k("contact.load_sharing", "-", Choice(&["auto", "pedrero", "stiffness"]), "Load sharing between two pairs: paper eq. (7) (Pedrero), by pair stiffness and deflection, or auto: Pedrero for identical, perfect teeth of contact ratio between 1 and 2 meeting on the nominal path only (the paper's case, `contact.path` = \"nominal\"), by stiffness otherwise (corner contact, per-tooth inputs, higher contact ratios). Pedrero's law needs `contact.path` = \"nominal\". Give \"stiffness\" to compare nominal-path cases with and without per-tooth inputs under one law.",
      "-"),
    k("contact.path", "-", Choice(&["extended", "nominal"]), "Where the teeth touch: \"extended\" (the default): on the path and, under load, by the tip corners before its start and after its end, so the load passes gradually from pair to pair (corner contact; the pairs then share the load by their compressions); \"nominal\": only on the nominal path of contact, perfect involutes meeting nowhere else (the paper's model: give it to reproduce the paper's numbers; `gearwear run` of the paper's case reports both). docs/MODEL.md, section 4.2.",
      "-"),
    k("friction.model", "-", Choice(&["xu2007", "constant", "none"]), "Friction coefficient: Xu et al. (2007) regression (paper eq. 8-9), a constant, or none.",
      "-"),
    k("friction.constant_coefficient", "-", Num(Range::closed(0.0, 1.0)), "Coefficient used with model = \"constant\".",
      "Frictionless to dry steel on steel (~0.8)."),
    k("friction.xu_radius_unit", "-", Choice(&["m", "mm"]), "Unit of the radius of curvature R in Xu's regression (docs/MODEL.md; Xu et al. use m).",
      "-"),
    k("friction.direction_smoothing_m_per_s", "m/s", Num(Range::closed(1e-6, 10.0)), "Sliding speed over which the friction direction turns through the pitch point (tanh).",
      "A micrometre per second (a sign switch) to 10 m/s (smoother than any real sliding)."),
    k("wear.coefficient_m2_per_n", "m^2/N", Num(Range::closed(0.0, 1e-11)), "Archard wear coefficient k (paper's 2.5e-12 read as cm^2/N = 2.5e-16 m^2/N).",
      "Archard's dimensionless coefficient K <= 1e-2 (severe adhesive wear) over a hardness >= 1 GPa gives k <= 1e-11 m^2/N; lubricated gears lie near 1e-18 to 1e-15."),
    k("wear.block_cycles", "cycles", Num(Range::closed(1.0, 1e11)), "Cycles m the per-cycle wear is held for between dynamic updates (paper eq. 17: 1e4; a gear train: input cycles, revolutions of stage 1's pinion).",
      "A block holds at least one load cycle; the number of updates it makes is checked by the run budget."),
    k("wear.threshold_um", "µm", Num(Range::closed(1e-3, 1e6)), "Largest wear depth one block may add at any point (paper's epsilon^m: 0.5 µm).",
      "From 1 nm (atomic layers) up; a threshold of a metre is never reached and turns the cut off. The number of updates it makes is checked by the run budget."),
    k("wear.total_cycles", "cycles", Num(Range::closed(1.0, 1e11)), "Pinion load cycles (revolutions) of the wear study (paper Fig. 13: 4e4; a gear train: input cycles, revolutions of stage 1's pinion, each stage's pinion turning its own count).",
      "1e10 revolutions is about 30 years of running at 10 Hz; the run's cost is checked by the run budget."),
    k("wear.points_per_profile", "-", Int(11, 100_000), "Points on each active profile for the wear bookkeeping.",
      "11 points resolve the wear profile's shape; 1e5 points are 0.1 µm apart on a 10 mm path."),
    k("wear.worn_geometry", "-", Choice(&["involute", "worn"]), "What the contact sees of a worn flank: \"involute\" (absent; the paper's model: wear only opens gaps) or \"worn\" (severe wear: the teeth thinned by their wear in the potential-energy integrals, the Hertz curvature of the worn flank, loads shared by compression; docs/MODEL.md, section 9).",
      "-"),
    k("numerics.steps_per_mesh_period", "-", Int(20, 1_000_000), "Grid nodes per mesh period, aligned with the mesh events: the longest integration step and the fewest recorded samples per period.",
      "Below 20 the mesh events are barely resolved (docs/MODEL.md, convergence); the cost of more is checked by the run budget."),
    k("numerics.integration_tolerance", "-", Num(Range::closed(1e-9, 0.1)), "Local error per integration step, relative to the state's scales (static mesh deflection, and its rate at the mesh frequency); the error control adds steps where the dynamics need them.",
      "Below 1e-9 round-off in the error estimate exceeds the tolerance (measured: 1e-10 fails at the first step at 0.5 Hz); near the bound, slow speeds on coarse grids can fail too (1e-8 at 0.5 Hz with 20 grid nodes per period), with a message naming this key. Above 0.1 the grid nodes, not the error control, set every step. The steps it adds are checked by the run budget."),
    k("numerics.max_mesh_periods", "-", Int(2, 1_000_000), "Mesh periods after which the search for steady state gives up.",
      "Two periods are the least a comparison needs; the cost of more is checked by the run budget."),
    k("numerics.steady_state_tolerance", "-", Num(Range::closed(1e-12, 0.5)), "Steady state: largest change of the state over one mesh period, relative to its scale.",
      "Below ~1e-12 the change between periods is round-off and may never settle; above 0.5 nothing is periodic."),
    k("numerics.evaluated_mesh_periods", "-", Int(1, 100_000), "Mesh periods recorded once steady (signals and spectra).",
      "At least one period; the memory of more is checked by the run budget."),
    k("output.full_tables", "-", Bool, "Write a long run's per-point tables (`timeseries`, `path`: over 1e6 values, e.g. a hunting period's 589 mesh periods) at every recorded point. false (the default): such a table is written at every k-th row, k the smallest stride that leaves at most 5e5 values, stated in summary.json (`output.thinned_tables`); the figures, their data tables, the spectra and the summary are computed from every point either way. Shorter tables (the paper's case) are always whole.",
      "A switch: the full tables of a hunting period take about 50 MB."),
    k("calibration.wear_coefficient_min_m2_per_n", "m^2/N", Num(Range::closed(1e-22, 1e-11)), "Lower bound of the log-uniform prior of the wear coefficient k (`gearwear calibrate`/`predict`); omit for the case's k / 100.",
      "Inside the wear coefficient's own range (up to 1e-11); 1e-22 is far below any measured gear wear coefficient."),
    k("calibration.wear_coefficient_max_m2_per_n", "m^2/N", Num(Range::closed(1e-22, 1e-11)), "Upper bound of the log-uniform prior of k; omit for the case's k x 100. Equal bounds hold k fixed.",
      "As for the lower bound."),
    k("calibration.roughness_scale_min", "-", Num(Range::closed(0.01, 10.0)), "Lower bound of the uniform prior of the factor applied to `surface.roughness_table_rms_um` (1 and 1: not calibrated).",
      "A factor of 100 either way covers any ground or hobbed finish from the table's values."),
    k("calibration.roughness_scale_max", "-", Num(Range::closed(0.01, 10.0)), "Upper bound of the uniform prior of the roughness factor.",
      "As for the lower bound."),
    k("calibration.load_torque_min_nm", "N m", Num(Range::closed(1e-3, 1e7)), "Lower bound of the uniform prior of `operating.load_torque_nm`; omit (with the max) to hold the case's torque fixed.",
      "As for `operating.load_torque_nm`."),
    k("calibration.load_torque_max_nm", "N m", Num(Range::closed(1e-3, 1e7)), "Upper bound of the uniform prior of the load torque.",
      "As for `operating.load_torque_nm`."),
    k("calibration.grid_points", "-", Int(16, 10_000), "Cells per parameter of the exact grid posterior (used with one or two uncertain parameters).",
      "16 cells resolve a smooth posterior; the surrogate makes cells cheap, but 1e4 per parameter (1e8 for two) is beyond any use."),
    k("calibration.surrogate_nodes", "-", Int(2, 50), "Reference wear runs per uncertain parameter other than k (roughness factor, load torque); the surrogate interpolates linearly between them.",
      "Linear interpolation needs two; each node is a whole wear study, and 50 resolve any smooth response."),
    k("signals.sampling_rate_hz", "Hz", Num(Range::closed(1000.0, 1e7)), "Sampling rate f_s of a record (`gearwear signals`, datasets; 2.56 x 10 kHz). The usable, alias-free band is f_s / 2.56.",
      "1 kHz (slow machinery) to 10 MHz (acoustic emission); the highest mesh harmonic analysed must lie below f_s / 2.56 and every mode of the transfer path below f_s / 2 (checked with the pair)."),
    k("signals.record_length", "s or rev", Num(Range::above(0.0, 1e5)), "Length of a record, in `signals.record_length_unit`.",
      "Up to 1e5 s or revolutions; the record's memory and a dataset's disk use are checked before it starts."),
    k("signals.record_length_unit", "-", Choice(&["s", "revolutions"]), "Unit of `signals.record_length`: seconds, or revolutions of the tachometer's shaft.",
      "-"),
    k("signals.anti_alias_attenuation_db", "dB", Num(Range::closed(40.0, 160.0)), "Stopband attenuation of the anti-alias filter at and above f_s / 2 (passband to f_s / 2.56; docs/SIGNALS.md).",
      "40 dB is a crude filter; beyond 160 dB the double-precision samples themselves are the limit."),
    k("signals.channel_unit", "-", Choice(&["m/s^2", "g", "mV"]), "Unit of the accelerometer channels: m/s^2, standard gravity (9.80665 m/s^2), or the sensor's voltage (mV, through `signals.sensitivity_mv_per_g`).",
      "-"),
    k("signals.sensitivity_mv_per_g", "mV/g", Num(Range::closed(1e-3, 1e5)), "Accelerometer sensitivity (100 mV/g: a general-purpose IEPE sensor).",
      "Shock sensors (~0.05 mV/g) to seismic ones (~10 V/g), with margin."),
    k("signals.snr_db", "dB", Num(Range::closed(-40.0, 200.0)), "Measurement noise as a signal-to-noise ratio of each channel (powers); omit for none. Not with `signals.noise_density_ug_per_sqrt_hz`.",
      "From noise 100 times the signal's power to beyond double precision."),
    k("signals.noise_density_ug_per_sqrt_hz", "ug/sqrt(Hz)", Num(Range::above(0.0, 1e6)), "Measurement noise as a one-sided amplitude spectral density, white to f_s / 2 (accelerometer data sheets: 1-100 ug/sqrt(Hz)); omit for none.",
      "Up to 1 g/sqrt(Hz), far beyond any sensor."),
    k("signals.noise_seed", "-", Int(0, 9_007_199_254_740_992), "Seed of the measurement noise (same seed, same noise, on any machine).",
      "Any whole number up to 2^53 (exact in every number format that reads the files)."),
    k("signals.tachometer_shaft", "-", Choice(&["pinion", "gear"]), "Shaft the tachometer reads: the pinion's (input) or the gear's (output).",
      "-"),
    k("signals.tachometer_pulses_per_revolution", "-", Int(1, 10_000), "Tachometer pulses per revolution of its shaft (PHM 2009: 10).",
      "One keyway to the finest encoder discs."),
    k("signals.mesh_harmonics", "-", Int(1, 100), "Mesh harmonics analysed: FM0's sum and the labelled spectrum lines. The highest must lie in the recorded band f_s / 2.56.",
      "At least the mesh fundamental; 100 harmonics exceed any recorded band."),
    k("signals.torque_fluctuation_rms_nm", "N m", Num(Range::closed(0.0, 1e7)), "RMS of a seeded random load-torque fluctuation added to `operating.load_torque_nm` (band-limited, flat to its bandwidth); 0: none. The record is then a transient simulation.",
      "As the load torque; it must stay below the mean torque (checked), or the mesh would be driven backwards."),
    k("signals.torque_fluctuation_bandwidth_hz", "Hz", Num(Range::above(0.0, 1e4)), "Bandwidth of the torque fluctuation (flat from 0 to this frequency).",
      "Drivetrain load fluctuations lie well below 10 kHz."),
    k("signals.torque_fluctuation_seed", "-", Int(0, 9_007_199_254_740_992), "Seed of the torque fluctuation.",
      "As `signals.noise_seed`."),
    k("signals.ramp_end_speed_hz", "Hz", Num(Range::closed(1e-3, 1000.0)), "Run-up or coast-down: the input speed at the end of the record, rising or falling linearly from `operating.input_speed_hz` at its start (a transient simulation); omit for steady speed.",
      "As `operating.input_speed_hz`."),
    k("signals.sensor_stage", "-", Int(1, 100), "Gear trains: the stage (1 to the number of `[[stage]]` tables) whose pinion and gear bearings the transfer path's four inputs are, and whose pinion (`\"pinion\"`) and gear (`\"gear\"`) shafts `signals.tachometer_shaft` and the indicators refer to; omit for stage 1 (a single pair is stage 1).",
      "One of the case's stages (checked against their number)."),
    k("signals.ring_sensor_angle_deg", "deg", Num(Range::closed(0.0, 360.0)), "Planetary sets: the sensor's angle on the fixed ring, from planet 1's position at the record's start in the carrier's sense of rotation; omit for 0 (docs/SIGNALS.md, section 6).",
      "Any place on the ring: one full turn."),
    k("signals.ring_sensor_half_width_deg", "deg", Num(Range::above(0.0, 180.0)), "Planetary sets: half-width of the Hann window over which the ring sensor hears a planet's ring mesh (McFadden & Smith 1985); omit for 180 / N, half the planet spacing, so that each planet is heard alone as it passes.",
      "Up to half a turn: a wider window would hear a planet on both sides."),
    k("teeth.pitch_error_pinion_um", "µm", NumArray(TOOTH_ERROR), "Position (pitch) error of each pinion tooth, z1 values: how far its loaded flank stands ahead of its ideal position towards the gear (positive: earlier contact), an arc on the reference circle. The single pitch deviations of ISO 1328-1 are the differences of neighbours. Absent: perfect spacing (docs/MODEL.md, section 9).",
      "A millimetre either way is far beyond the coarsest ISO 1328-1 class for any gear the model takes."),
    k("teeth.pitch_error_gear_um", "µm", NumArray(TOOTH_ERROR), "Position (pitch) error of each gear tooth, z2 values (positive towards the pinion).",
      "As for the pinion."),
    k("teeth.accuracy_grade", "-", Int(1, 12), "ISO 1328-1 flank tolerance class: pitch, profile slope and profile form errors not given explicitly are drawn (seeded) from its tolerances (docs/MODEL.md, section 9). Absent: none drawn.",
      "ISO 1328-1:2013 defines classes 1 to 11; 12 extrapolates its formulas one more step of sqrt(2) (with a warning)."),
    k("teeth.error_seed", "-", Int(0, 1_000_000_000_000), "Seed of the random draw for `teeth.accuracy_grade` (absent: 0); the same seed gives the same teeth.",
      "Any whole number up to 1e12."),
    k("teeth.runout_pinion_um", "µm", Num(Range::closed(0.0, 1000.0)), "Radial run-out F_r of the pinion (twice its eccentricity): a displacement along the line of action turning once per pinion revolution. Absent: 0.",
      "A millimetre is far beyond any ISO 1328 class for the gears the model takes."),
    k("teeth.runout_gear_um", "µm", Num(Range::closed(0.0, 1000.0)), "Radial run-out F_r of the gear (twice its eccentricity). Absent: 0.",
      "As for the pinion."),
    k("teeth.runout_pinion_phase_deg", "deg", Num(Range::closed(-360.0, 360.0)), "Pinion rotation from the entry of its tooth 0 until its eccentricity points along the line of action towards the gear. Absent: 0.",
      "One turn either way."),
    k("teeth.runout_gear_phase_deg", "deg", Num(Range::closed(-360.0, 360.0)), "Gear rotation from the entry of its tooth 0 until its eccentricity points along the line of action towards the pinion. Absent: 0.",
      "One turn either way."),
    k("teeth.profile_slope_pinion_um", "µm", NumArray(TOOTH_ERROR), "Profile slope deviation f_Halpha of the pinion teeth: linear along the active profile, positive adds material at the tip; one value for every tooth or z1 values.",
      "As for the pitch errors."),
    k("teeth.profile_slope_gear_um", "µm", NumArray(TOOTH_ERROR), "Profile slope deviation f_Halpha of the gear teeth (one value or z2 values).",
      "As for the pitch errors."),
    k("teeth.profile_form_pinion_um", "µm", NumArray(TOOTH_ERROR), "Profile form deviation f_falpha of the pinion teeth: a parabola along the active profile, positive bulges out at its middle; one value or z1 values.",
      "As for the pitch errors."),
    k("teeth.profile_form_gear_um", "µm", NumArray(TOOTH_ERROR), "Profile form deviation f_falpha of the gear teeth (one value or z2 values).",
      "As for the pitch errors."),
    k("modification.tip_relief_um", "µm", Num(Range::closed(0.0, 1000.0)), "Tip relief of every tooth of both gears: material removed at the tip (Tavakoli & Houser 1986). Absent: none.",
      "Reliefs are tens of micrometres; a millimetre is beyond any design. Its length is checked against the addendum."),
    k("modification.tip_relief_length_mm", "mm", Num(Range::above(0.0, 100.0)), "Length of the tip relief along the line of action (roll length), from the tip's contact point; at most the addendum's roll length (checked).",
      "Checked against each gear's addendum with the geometry."),
    k("modification.root_relief_um", "µm", Num(Range::closed(0.0, 1000.0)), "Root relief of every tooth: material removed at the start of the active profile. Absent: none.",
      "As for the tip relief."),
    k("modification.root_relief_length_mm", "mm", Num(Range::above(0.0, 100.0)), "Length of the root relief along the line of action, from the start of the active profile; at most the active dedendum's roll length (checked).",
      "Checked against each gear's active dedendum with the geometry."),
    k("modification.shape", "-", Choice(&["linear", "parabolic"]), "Shape of the reliefs along their length (absent: \"linear\").",
      "-"),
    k("modification.profile_roll_pinion_deg", "deg", NumArray(Range::closed(0.0, 180.0)), "Roll angles (rho / r_b) of a user profile deviation of the pinion, ascending; with `modification.profile_deviation_pinion_um`.",
      "Roll angles of an involute lie well inside half a turn."),
    k("modification.profile_deviation_pinion_um", "µm", NumArray(TOOTH_ERROR), "Profile deviation of every pinion tooth at those roll angles (material removed positive), linear in between, constant beyond.",
      "As for the pitch errors."),
    k("modification.profile_roll_gear_deg", "deg", NumArray(Range::closed(0.0, 180.0)), "Roll angles of a user profile deviation of the gear, ascending.",
      "As for the pinion."),
    k("modification.profile_deviation_gear_um", "µm", NumArray(TOOTH_ERROR), "Profile deviation of every gear tooth at those roll angles (material removed positive).",
      "As for the pitch errors."),
    k("modification.crowning_um", "µm", Num(Range::closed(0.0, 1000.0)), "Lead crowning of the pair (both gears' together): the gap at each face end over the middle, parabolic across the face (docs/MODEL.md 11.2). Taken by `gearwear stiffness` (face load distribution, K_Hbeta) and, on a helical pair, by `gearwear dynamics`, `wear`, `run` and `sweep` (docs/MODEL.md 11.1-11.5). Absent: none.",
      "Crownings are tens of micrometres; at most the tooth's whole depth (checked with the geometry)."),
    k("modification.end_relief_um", "µm", Num(Range::closed(0.0, 1000.0)), "End relief of the pair at each face end (both gears' together), with `modification.end_relief_length_mm`. Absent: none.",
      "As for the crowning; crowning and end relief together at most the whole depth (checked)."),
    k("modification.end_relief_length_mm", "mm", Num(Range::above(0.0, 1000.0)), "Length of the end relief from each face end across the face; at most half the face width (checked).",
      "Checked against half the face width with the geometry."),
    k("modification.end_relief_shape", "-", Choice(&["linear", "parabolic"]), "Shape of the end relief along its length: the gap falls linearly, or with the square of the distance, to 0 at its inner end (absent: \"linear\").",
      "-"),
    k("modification.helix_slope_deviation_um", "µm", Num(Range::closed(-1000.0, 1000.0)), "Helix slope deviation f_Hbeta of the pair (ISO 1328-1): the gap's difference across the face width, linear; positive opens it towards the face end y = b (the end the pinion's angular velocity points to). Absent: 0.",
      "A millimetre either way is far beyond the coarsest ISO 1328-1 class for any gear the model takes."),
    k("fault.kind", "-", Choice(&["crack", "spall", "broken_tip"]), "Kind of a tooth fault, one `[[fault]]` table each: a root crack (Chen & Shao 2011), a spall (Saxena et al. 2016) or a broken tip (docs/MODEL.md, section 9).",
      "-"),
    k("fault.gear", "-", Choice(&["pinion", "gear"]), "The gear whose tooth has the fault.",
      "-"),
    k("fault.tooth", "-", Int(0, 999), "0-based index of the faulty tooth (checked against the gear's teeth).",
      "Teeth are numbered 0 to z - 1; z is at most 1000."),
    k("fault.stage", "-", Int(1, 16), "On a gear train (`[[stage]]` tables; required there): the stage, counted from 1, whose pair holds the faulty tooth (`fault.gear` its pinion or gear, `fault.tooth` among its teeth). `gearwear stiffness`, `dynamics`, `signals`, `sweep` of dynamics, `wear` and `run` take it (the stage worn tooth by tooth); `dataset`, `calibrate`, `predict`, a wear sweep and a `[load_spectrum]` refuse a train with a fault (docs/MODEL.md 9.10). Refused on a single pair.",
      "A train has at most 16 stages; checked against the case's stages."),
    k("fault.crack_depth_mm", "mm", Num(Range::closed(0.0, 100.0)), "Crack: depth from the root along its path (required for a crack); its reach across the tooth is checked against the root thickness.",
      "Checked against the tooth with the geometry."),
    k("fault.crack_angle_deg", "deg", Num(Range::above(0.0, 90.0)), "Crack: angle of its path to the tooth centreline (absent: 45, Chen & Shao 2011).",
      "A crack along the centreline (0) removes nothing; 90 runs straight across the tooth."),
    k("fault.crack_width_fraction", "-", Num(Range::above(0.0, 1.0)), "Crack: share of the face width it has run across at its depth, from one face (absent: 1, through the face) A spur pair's: refused on a helical pair, whose fault covers the span `fault.face_start_mm` to `fault.face_end_mm`.",
      "From a crack at one face to one through the whole face."),
    k("fault.spall_position_mm", "mm", Num(Range::closed(-100.0, 100.0)), "Spall: roll distance of its centre from the pitch point (along the line of action, a difference of the tooth's radius of curvature rho), positive towards the tip (required for a spall).",
      "Checked against the active profile with the geometry."),
    k("fault.spall_length_mm", "mm", Num(Range::above(0.0, 100.0)), "Spall: its extent as a roll length, the difference of the radii of curvature rho of its two edges (along the line of action, like `spall_position_mm` and the relief lengths; required). A length s measured on the flank surface (a photo, a profile trace) converts locally as roll length = (r_b / rho) s, r_b the tooth's base radius and rho at the spall (2.75 at the paper pinion's pitch point: 0.36 mm on the flank is 1 mm of roll; exactly, the flank distance between rho_a and rho_b is abs(rho_b^2 - rho_a^2) / (2 r_b)); docs/MODEL.md, section 9.5.",
      "The spall must lie on the active profile (checked with the geometry)."),
    k("fault.spall_depth_um", "µm", Num(Range::above(0.0, 10_000.0)), "Spall: depth of the pit (required); at most 95 % of the tooth's thickness at the spall's upper edge (checked).",
      "Pits are tens to hundreds of micrometres deep; 1 cm is beyond any tooth the model takes."),
    k("fault.spall_width_fraction", "-", Num(Range::above(0.0, 1.0)), "Spall: share of the face width it covers (absent: 1, across the whole face) A spur pair's: refused on a helical pair, whose fault covers the span `fault.face_start_mm` to `fault.face_end_mm`.",
      "From a pit of no width to one across the face."),
    k("fault.removed_height_mm", "mm", Num(Range::above(0.0, 100.0)), "Broken tip: radial height removed from the tip (required); at most the tooth's height above the root circle (checked).",
      "Checked against the tooth with the geometry."),
    k("fault.face_start_mm", "mm", Num(Range::closed(0.0, 2000.0)), "A crack or spall on a helical pair: where its span across the face starts, measured from the face end y = 0 (absent: 0). Only the face slices whose centres lie in [face_start_mm, face_end_mm] are weakened or pitted; each such slice carries the fault as a spur slice would (docs/MODEL.md 11.9). Refused on a spur pair (its fault spans the face by `fault.crack_width_fraction` or `fault.spall_width_fraction`) and on a train's stage.",
      "Checked against `gear.face_width_mm`: it must lie in [0, b] and below `fault.face_end_mm`."),
    k("fault.face_end_mm", "mm", Num(Range::closed(0.0, 2000.0)), "A crack or spall on a helical pair: where its span across the face ends, measured from the face end y = 0 (absent: the face width b, the whole face from `fault.face_start_mm`). docs/MODEL.md 11.9.",
      "Checked against `gear.face_width_mm`: it must lie in [0, b] and above `fault.face_start_mm`."),
    k("stage.module_mm", "mm", Num(Range::closed(0.1, 50.0)), "A stage's module, one `[[stage]]` table per stage of a parallel-axis train in the order the power flows (absent: `gear.module_mm`; docs/MODEL.md, section 4.1). Every key of a stage defaults to its `[gear]` or `[dynamics]` namesake.",
      "As `gear.module_mm`."),
    k("stage.teeth_pinion", "-", Int(6, 1000), "The stage's driving gear's teeth (absent: `gear.teeth_pinion`).",
      "As `gear.teeth_pinion`."),
    k("stage.teeth_gear", "-", Int(6, 1000), "The stage's driven gear's teeth (absent: `gear.teeth_gear`).",
      "As `gear.teeth_gear`."),
    k("stage.pressure_angle_deg", "deg", Num(Range::closed(10.0, 35.0)), "The stage's reference pressure angle (absent: `gear.pressure_angle_deg`).",
      "As `gear.pressure_angle_deg`."),
    k("stage.addendum_coefficient", "-", Num(Range::closed(0.5, 1.5)), "The stage's addendum coefficient (absent: `gear.addendum_coefficient`).",
      "As `gear.addendum_coefficient`."),
    k("stage.dedendum_coefficient", "-", Num(Range::closed(0.8, 2.0)), "The stage's dedendum coefficient (absent: `gear.dedendum_coefficient`).",
      "As `gear.dedendum_coefficient`."),
    k("stage.profile_shift_pinion", "-", Num(Range::closed(-1.0, 1.5)), "The stage's pinion profile shift (absent: `gear.profile_shift_pinion`).",
      "As `gear.profile_shift_pinion`."),
    k("stage.profile_shift_gear", "-", Num(Range::closed(-1.0, 1.5)), "The stage's gear profile shift (absent: `gear.profile_shift_gear`).",
      "As `gear.profile_shift_gear`."),
    k("stage.face_width_mm", "mm", Num(Range::closed(0.1, 2000.0)), "The stage's face width (absent: `gear.face_width_mm`).",
      "As `gear.face_width_mm`."),
    k("stage.centre_distance_mm", "mm", Num(Range::closed(0.1, 1e5)), "The stage's operating centre distance (absent: `gear.centre_distance_mm`, or the one the profile shifts give).",
      "As `gear.centre_distance_mm`: checked against the stage's pair."),
    k("stage.hub_bore_radius_pinion_mm", "mm", NumOrDerived(BORE), "The stage's pinion hub bore radius (absent: `gear.hub_bore_radius_pinion_mm`).",
      "As `gear.hub_bore_radius_pinion_mm`."),
    k("stage.hub_bore_radius_gear_mm", "mm", NumOrDerived(BORE), "The stage's gear hub bore radius (absent: `gear.hub_bore_radius_gear_mm`).",
      "As `gear.hub_bore_radius_gear_mm`."),
    k("stage.tool_tip_radius_coefficient", "-", Num(Range::closed(0.0, 0.6)), "The stage's rack-cutter tip radius / m (absent: `gear.tool_tip_radius_coefficient`).",
      "As `gear.tool_tip_radius_coefficient`."),
    k("stage.mass_pinion_kg", "kg", NumOrDerived(MASS), "The stage's pinion mass (absent: `dynamics.mass_pinion_kg`; \"derived\": the stage's blank).",
      "As `dynamics.mass_pinion_kg`."),
    k("stage.mass_gear_kg", "kg", NumOrDerived(MASS), "The stage's gear mass (absent: `dynamics.mass_gear_kg`).",
      "As `dynamics.mass_gear_kg`."),
    k("stage.inertia_pinion_kg_m2", "kg m^2", NumOrDerived(INERTIA), "The stage's pinion inertia (absent: `dynamics.inertia_pinion_kg_m2`).",
      "As `dynamics.inertia_pinion_kg_m2`."),
    k("stage.inertia_gear_kg_m2", "kg m^2", NumOrDerived(INERTIA), "The stage's gear inertia (absent: `dynamics.inertia_gear_kg_m2`).",
      "As `dynamics.inertia_gear_kg_m2`."),
    k("stage.bearing_stiffness_pinion_n_per_m", "N/m", Num(Range::closed(1e4, 1e12)), "The stage's pinion bearing stiffness, x and y (absent: `dynamics.bearing_stiffness_pinion_n_per_m`).",
      "As `dynamics.bearing_stiffness_pinion_n_per_m`: a bearing holds every gear to ground, so no gear floats free."),
    k("stage.bearing_stiffness_gear_n_per_m", "N/m", Num(Range::closed(1e4, 1e12)), "The stage's gear bearing stiffness, x and y (absent: `dynamics.bearing_stiffness_gear_n_per_m`).",
      "As for the pinion."),
    k("stage.bearing_damping_pinion_n_s_per_m", "N s/m", Num(Range::closed(0.0, 1e8)), "The stage's pinion bearing damping, x and y (absent: `dynamics.bearing_damping_pinion_n_s_per_m`).",
      "As `dynamics.bearing_damping_pinion_n_s_per_m`."),
    k("stage.bearing_damping_gear_n_s_per_m", "N s/m", Num(Range::closed(0.0, 1e8)), "The stage's gear bearing damping, x and y (absent: `dynamics.bearing_damping_gear_n_s_per_m`).",
      "As `dynamics.bearing_damping_gear_n_s_per_m`."),
    k("stage.mesh_damping_ratio", "-", Num(Range::closed(0.0, 1.0)), "The stage's mesh damping ratio (absent: `dynamics.mesh_damping_ratio`).",
      "As `dynamics.mesh_damping_ratio`."),
    k("stage.shaft_torsional_stiffness_nm_per_rad", "N m/rad", Num(Range::closed(1.0, 1e10)), "Torsional stiffness of the shaft carrying this stage's gear and the next stage's pinion (required on every stage but the last).",
      "As the couplings': a shaft of no stiffness would leave the next stage connected to nothing."),
    k("stage.shaft_torsional_damping_nm_s_per_rad", "N m s/rad", Num(Range::closed(0.0, 1e7)), "Torsional damping of that shaft (absent: 0).",
      "As the couplings'."),
    k("stage.centre_line_deg", "deg", Num(Range::closed(-360.0, 360.0)), "Direction of the stage's gear centre seen from its pinion's, deg from +x (absent: 0: the centres in a line). It turns the stage's line of action in the plane, and with it the bearing forces' directions.",
      "An angle; one turn either way."),
    k("stage.helix_angle_deg", "deg", Num(Range::below(0.0, 45.0)), "The stage's helix angle (absent: `gear.helix_angle_deg`; 0: a spur stage). A helical stage's mesh is the slice model of a helical pair and its axial force loads the stage's axial bearings (docs/MODEL.md 4.3); `gearwear stiffness`, `gearwear dynamics`, `gearwear signals` and `gearwear sweep` of dynamics take a train with helical stages, the other studies refuse it.",
      "As `gear.helix_angle_deg`."),
    k("stage.helix_hand_pinion", "-", Choice(&["left", "right"]), "Hand of the stage's pinion helix, the stage's gear the other (absent: `gear.helix_hand_pinion`).",
      "-"),
    k("stage.slices", "-", Int(1, 10_000), "Slices across the stage's face (absent: `stiffness.slices`); unused by a spur stage.",
      "As `stiffness.slices`."),
    k("stage.bearing_axial_stiffness_pinion_n_per_m", "N/m", Num(Range::closed(1e4, 1e12)), "Axial bearing stiffness of the stage's pinion (absent: `dynamics.bearing_axial_stiffness_pinion_n_per_m`; both absent: rigid). On a helical stage the pinion then carries its own axial coordinate (docs/MODEL.md 4.3); ignored with a warning on a spur stage.",
      "As `dynamics.bearing_axial_stiffness_pinion_n_per_m`."),
    k("stage.bearing_axial_stiffness_gear_n_per_m", "N/m", Num(Range::closed(1e4, 1e12)), "Axial bearing stiffness of the stage's gear (absent: `dynamics.bearing_axial_stiffness_gear_n_per_m`; both absent: rigid).",
      "As for the pinion."),
    k("stage.bearing_axial_damping_pinion_n_s_per_m", "N s/m", Num(Range::closed(0.0, 1e8)), "Axial bearing damping of the stage's pinion (absent: `dynamics.bearing_axial_damping_pinion_n_s_per_m`, else the stage's radial pinion bearing damping).",
      "As the radial damping."),
    k("stage.bearing_axial_damping_gear_n_s_per_m", "N s/m", Num(Range::closed(0.0, 1e8)), "Axial bearing damping of the stage's gear (absent: `dynamics.bearing_axial_damping_gear_n_s_per_m`, else the stage's radial gear bearing damping).",
      "As for the pinion."),
    k("planetary.planets", "-", Int(1, 32), "A planetary set instead of the pair (`[planetary]`, absent by default; docs/MODEL.md section 12): number of planets N, equally spaced unless `planetary.planet_angles_deg` is given. `gearwear stiffness`, `dynamics`, `signals`, `wear`, `dataset` (with `dataset-merge`), `run` and `sweep` (of dynamics) take such a case, `wear` and `run` also under a `[load_spectrum]` (each bin's torque and speed the input member's; docs/MODEL.md 12.12); the other studies refuse it.",
      "At least one planet; 32 is far above any built set (3 to 12 is usual) and bounds the lumped model (3 (N + 3) coordinates)."),
    k("planetary.planet_angles_deg", "deg", NumArray(Range::below(0.0, 360.0)), "Planet positions on the carrier, the first 0, increasing within one revolution, each on a multiple of 360 / (z_s + z_r) deg (checked). Absent: 360 n / N.",
      "Angles within one revolution; the assembly condition is checked with the teeth."),
    k("planetary.teeth_sun", "-", Int(6, 10_000), "Sun teeth z_s (default 24).",
      "Below 6 teeth no standard gear meshes; 10000 bounds the tables, far beyond any built sun."),
    k("planetary.teeth_planet", "-", Int(6, 10_000), "Teeth z_p of every planet (default 30).",
      "As for the sun."),
    k("planetary.teeth_ring", "-", Int(12, 10_000), "Ring teeth z_r, counted positive (default 84); with unshifted gears z_r = z_s + 2 z_p (the centre distances are checked).",
      "A ring needs room for a sun and two planets of at least 6 teeth each (checked with the geometry)."),
    k("planetary.module_mm", "mm", Num(Range::above(0.0, 100.0)), "Module m of every gear of the set (default 2 mm).",
      "Positive; 100 mm is beyond the largest planetary stages built."),
    k("planetary.pressure_angle_deg", "deg", Num(Range::above(10.0, 35.0)), "Reference pressure angle alpha of the set (default 20).",
      "As `gear.pressure_angle_deg`: outside 10-35 deg teeth undercut or point."),
    k("planetary.addendum_coefficient", "-", Num(Range::above(0.0, 2.0)), "Addendum coefficient h_a* of sun and planets, in modules (default 1).",
      "Positive and at most two modules: longer teeth point for any usual tooth count."),
    k("planetary.addendum_coefficient_ring", "-", Num(Range::above(0.0, 2.0)), "Addendum coefficient of the ring, in modules (default 0.8: a full-depth ring tip reaches below the planet's involute and is refused as tip interference).",
      "As for the external gears."),
    k("planetary.dedendum_coefficient", "-", Num(Range::above(0.0, 2.5)), "Dedendum coefficient h_f* of every gear, in modules (default 1.25).",
      "Positive and at most two and a half modules, beyond any deep-root rack."),
    k("planetary.tool_tip_radius_coefficient", "-", Num(Range::closed(0.0, 0.6)), "Rack-cutter tip radius of the external gears, in modules (default 0.38).",
      "As `gear.tool_tip_radius_coefficient`: a larger radius no longer fits the rack's tip."),
    k("planetary.face_width_mm", "mm", Num(Range::above(0.0, 2000.0)), "Face width b of every mesh (default 20 mm).",
      "Positive, up to the widest mill drives."),
    k("planetary.profile_shift_sun", "-", Num(Range::closed(-1.5, 1.5)), "Profile shift coefficient of the sun x_s (default 0).",
      "Beyond 1.5 modules either way teeth point or are cut away for any tooth count."),
    k("planetary.profile_shift_planet", "-", Num(Range::closed(-1.5, 1.5)), "Profile shift coefficient of the planets x_p (default 0).",
      "As for the sun."),
    k("planetary.profile_shift_ring", "-", Num(Range::closed(-1.5, 1.5)), "Profile shift coefficient of the ring x_r, ISO 21771's sign: positive thickens the ring's tooth and moves its tip circle inwards (default 0).",
      "As for the sun."),
    k("planetary.input", "-", Choice(&["sun", "carrier", "ring"]), "The member the power comes in on (default \"sun\").",
      "-"),
    k("planetary.output", "-", Choice(&["sun", "carrier", "ring"]), "The member the power leaves by (default \"carrier\").",
      "-"),
    k("planetary.fixed", "-", Choice(&["sun", "carrier", "ring"]), "The member held fixed (default \"ring\"); input, output and fixed must differ.",
      "-"),
    k("planetary.planet_tangential_error_um", "µm", NumArray(Range::closed(-1000.0, 1000.0)), "Position error of each planet's pin on the carrier along its tangential coordinate (positive in the sense the planet angles count), one value per planet. It opens a gap e_t cos(alpha) on both of the planet's meshes (docs/MODEL.md 12.8); with the sun driving, a positive error holds the planet back from the load. Absent: none.",
      "A millimetre is far beyond any carrier's tolerance (pin position errors are tens of micrometres); an error that would leave a planet without load at the case's torque is refused by `gearwear dynamics`."),
    k("planetary.planet_radial_error_um", "µm", NumArray(Range::closed(-1000.0, 1000.0)), "Position error of each planet's pin along its radial coordinate (positive away from the sun), one value per planet: a gap e_r sin(alpha_s) on its sun mesh and -e_r sin(alpha_r) on its ring mesh. Absent: none.",
      "As for the tangential error."),
    k("planetary.floating_sun", "-", Bool, "A floating sun: its lateral bearing stiffness is zero, the sun's x and y held by its meshes alone, whatever `planetary.lumped.bearing_stiffness_sun_n_per_m` gives (default false).",
      "-"),
    k("planetary.fault.kind", "-", Choice(&["crack", "spall", "broken_tip"]), "A tooth fault on one member of the set, one `[[planetary.fault]]` table (at most one so far): its kind, \"crack\" or \"spall\" (\"broken_tip\" is not built on a set yet). Its sizes are the `fault.*` keys of the kind (`crack_depth_mm`, `crack_angle_deg`, `crack_width_fraction`; `spall_position_mm`, `spall_length_mm`, `spall_depth_um`, `spall_width_fraction`) with the pair's meaning, units, defaults and ranges. `gearwear dynamics`, `signals` and `sweep` (of dynamics) take it; `wear`, `run` and `dataset` refuse it. The response then repeats over the fault's period (z_s mesh periods for a sun tooth, z_p for a planet's, z_r for a ring tooth's); docs/MODEL.md 12.13, 12.14.",
      "-"),
    k("planetary.fault.gear", "-", Choice(&["sun", "planet", "ring"]), "The member whose tooth has the fault: \"sun\" (every planet's sun mesh meets it once per sun revolution relative to the carrier) or \"planet\" (`planetary.fault.planet`'s two meshes; a crack softens both, a spall lies on the flank the sun loads) or \"ring\" (every planet's ring mesh meets it once per ring revolution relative to the carrier; a crack at its root on the flank the planets load, a spall on that flank, its position counted from the pitch point towards the ring's tip; docs/MODEL.md 12.14).",
      "-"),
    k("planetary.fault.planet", "-", Int(1, 32), "The planet whose tooth has the fault, 1..=N as the outputs number them (required for `gear = \"planet\"`, refused for the others).",
      "Checked against `planetary.planets`."),
    k("planetary.fault.tooth", "-", Int(0, 9_999), "0-based index of the faulty tooth on its member (checked against its teeth): sun tooth 0 is at planet 1's sun mesh pitch point at t = 0 and tooth i follows i mesh cycles later; planet tooth j passes its sun mesh's pitch point j mesh cycles after the first passage at or after t = 0; ring tooth 0 is at planet 1's ring mesh pitch point at its first passage at or after t = 0 and tooth j follows j mesh cycles later (docs/MODEL.md 12.13, 12.14).",
      "Teeth are numbered 0 to z - 1; z is at most 10000."),
    k("planetary.lumped.mass_sun_kg", "kg", NumOrDerived(Range::above(0.0, 1e6)), "`[planetary.lumped]`, a set's lumped parameters (Lin & Parker 1999). Every key optional: absent or \"derived\", it is derived from the geometry (docs/MODEL.md 12.4) and the value used is in summary.json's `lumped_parameters`; a given key wins. Sun mass (derived: a solid disk of the face width out to the reference circle at `dynamics.blank_density_kg_per_m3`).",
      "Positive; a million kilograms is beyond any gear."),
    k("planetary.lumped.mass_planet_kg", "kg", NumOrDerived(Range::above(0.0, 1e6)), "Mass of each planet (derived: a solid disk as the sun's).", "As for the sun."),
    k("planetary.lumped.mass_ring_kg", "kg", NumOrDerived(Range::above(0.0, 1e6)), "Ring mass (derived: an annulus of the face width from the root circle out to a rim 3.5 modules thick, ISO 6336-3's Y_B = 1 rim of an internal gear).", "As for the sun."),
    k("planetary.lumped.mass_carrier_kg", "kg", NumOrDerived(Range::above(0.0, 1e6)), "Carrier mass (derived: two side plates b/2 thick, solid disks of radius carrier radius + planet reference radius).", "As for the sun."),
    k("planetary.lumped.inertia_sun_kg_m2", "kg m^2", NumOrDerived(Range::above(0.0, 1e6)), "Sun polar moment of inertia (the model divides it by the base radius squared; derived: m (r_o^2 + r_i^2) / 2 of the mass's body).",
      "Positive; a 1e6 kg m^2 wheel is beyond any gear."),
    k("planetary.lumped.inertia_planet_kg_m2", "kg m^2", NumOrDerived(Range::above(0.0, 1e6)), "Polar moment of inertia of each planet.", "As for the sun."),
    k("planetary.lumped.inertia_ring_kg_m2", "kg m^2", NumOrDerived(Range::above(0.0, 1e6)), "Ring polar moment of inertia.", "As for the sun."),
    k("planetary.lumped.inertia_carrier_kg_m2", "kg m^2", NumOrDerived(Range::above(0.0, 1e6)), "Carrier polar moment of inertia.", "As for the sun."),
    k("planetary.lumped.base_radius_sun_mm", "mm", NumOrDerived(Range::above(0.0, 1e5)), "Sun base radius (the modal table's; `gearwear dynamics` takes the geometry's; derived: the geometry's).",
      "Positive, up to 100 m: beyond any gear."),
    k("planetary.lumped.base_radius_planet_mm", "mm", NumOrDerived(Range::above(0.0, 1e5)), "Planet base radius.", "As for the sun."),
    k("planetary.lumped.base_radius_ring_mm", "mm", NumOrDerived(Range::above(0.0, 1e5)), "Ring base radius.", "As for the sun."),
    k("planetary.lumped.carrier_radius_mm", "mm", NumOrDerived(Range::above(0.0, 1e5)), "Carrier radius, sun centre to planet pin (derived: the sun-planet operating centre distance).", "As for the sun."),
    k("planetary.lumped.mesh_stiffness_sun_planet_n_per_m", "N/m", NumOrDerived(Range::above(0.0, 1e14)), "Mean sun-planet mesh stiffness (the modal table's; `gearwear dynamics` takes the meshes' own; derived: the mesh's mean).",
      "Positive, up to a hundred times the stiffest gear meshes (~1e10 N/m per metre of face, wide faces)."),
    k("planetary.lumped.mesh_stiffness_ring_planet_n_per_m", "N/m", NumOrDerived(Range::above(0.0, 1e14)), "Mean ring-planet mesh stiffness.", "As for the sun mesh."),
    k("planetary.lumped.bearing_stiffness_sun_n_per_m", "N/m", NumOrDerived(Range::closed(0.0, 1e16)), "Sun bearing stiffness, each lateral direction (0: a sun free laterally, held by its meshes; derived: `dynamics.bearing_stiffness_pinion_n_per_m`).",
      "Zero (free) to far stiffer than any bearing: 1e16 N/m models a rigid support."),
    k("planetary.lumped.bearing_stiffness_planet_n_per_m", "N/m", NumOrDerived(Range::above(0.0, 1e16)), "Planet bearing (pin) stiffness, radial and tangential (derived: `dynamics.bearing_stiffness_pinion_n_per_m`).",
      "Positive (a planet needs its pin), up to a rigid pin."),
    k("planetary.lumped.bearing_stiffness_ring_n_per_m", "N/m", NumOrDerived(Range::closed(0.0, 1e16)), "Ring support stiffness, each lateral direction (derived: `dynamics.bearing_stiffness_gear_n_per_m`).", "As for the sun."),
    k("planetary.lumped.bearing_stiffness_carrier_n_per_m", "N/m", NumOrDerived(Range::closed(0.0, 1e16)), "Carrier bearing stiffness, each lateral direction (derived: `dynamics.bearing_stiffness_gear_n_per_m`).", "As for the sun."),
    k("planetary.lumped.torsional_stiffness_sun_nm_per_rad", "N m/rad", NumOrDerived(Range::closed(0.0, 1e16)), "Sun torsional support (0: free; `gearwear dynamics` needs the output's and the fixed member's positive and leaves out the input's). Derived by the member's role: input `dynamics.coupling_stiffness_motor_nm_per_rad`, output `dynamics.coupling_stiffness_brake_nm_per_rad`, fixed 100 times the latter.",
      "Zero (free) to a rigid support."),
    k("planetary.lumped.torsional_stiffness_ring_nm_per_rad", "N m/rad", NumOrDerived(Range::closed(0.0, 1e16)), "Ring torsional support.", "As for the sun."),
    k("planetary.lumped.torsional_stiffness_carrier_nm_per_rad", "N m/rad", NumOrDerived(Range::closed(0.0, 1e16)), "Carrier torsional support.", "As for the sun."),
    k("planetary.lumped.pressure_angle_deg", "deg", NumOrDerived(Range::open(0.0, 45.0)), "Operating pressure angle of both meshes (the modal table's; `gearwear dynamics` takes the geometry's; derived: the sun-planet mesh's).",
      "A pressure angle between 0 and 45 deg; usual sets run at 20-25."),
];

/// Sections written as arrays of tables (`[[fault]]`), each table keyed as the schema's
/// `section.key` entries.
pub(crate) const TABLE_ARRAYS: &[&str] = &["fault", "stage"];

/// Sections absent from the default case (written commented out in the template) whose
/// keys the schema lists; read apart from the other sections (`config::load`).
pub(crate) const OPTIONAL_SECTIONS: &[&str] = &["planetary"];

/// Look up a key's spec.
pub fn spec(key: &str) -> Option<&'static KeySpec> {
    KEYS.iter().find(|s| s.key == key)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_include_their_closed_ends_and_exclude_open_ends_and_subnormals() {
        let r = Range::closed(0.0, 1.0);
        assert!(r.contains(0.0) && r.contains(1.0) && r.contains(0.5));
        assert!(!r.contains(5e-324) && !r.contains(f64::NAN) && !r.contains(1.0 + 1e-15));
        let o = Range::open(0.0, 0.5);
        assert!(!o.contains(0.0) && !o.contains(0.5) && o.contains(0.3));
        assert!(!Range::closed(-1.0, f64::INFINITY).contains(f64::INFINITY));
        assert_eq!(Range::above(0.0, 1e4).describe(), "(0, 10000]");
        assert_eq!(Range::closed(0.1, 1e4).describe(), "[0.1, 10000]");
        assert_eq!(Range::closed(0.0, 1e-11).describe(), "[0, 1e-11]");
        assert_eq!(Range::closed(1e-12, 0.5).describe(), "[1e-12, 0.5]");
    }

    #[test]
    fn every_numeric_key_has_a_finite_range_and_a_reason() {
        for s in KEYS {
            let r = match s.valid {
                Num(r) | NumOrDerived(r) | NumArray(r) => Some(r),
                Int(lo, hi) => {
                    assert!(lo <= hi, "{}", s.key);
                    None
                }
                Choice(_) | Bool => None,
            };
            if let Some(r) = r {
                assert!(
                    r.lo.is_finite() && r.hi.is_finite() && r.lo < r.hi,
                    "{}",
                    s.key
                );
                assert!(s.reason.len() > 10, "{} needs a reason", s.key);
            }
        }
    }
}
