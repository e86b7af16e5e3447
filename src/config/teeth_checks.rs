//! Checks of the per-tooth inputs that need only the case (`config::teeth`): array
//! lengths against the numbers of teeth, tooth indices, which keys a fault kind takes,
//! ascending roll angles. Checks that need the geometry are made when the model builds
//! its tooth inputs (`study::teeth::ToothInputs::from_case`).

use super::case::GearSection;
use super::teeth::{key_problems, FaultTable, Member, ModificationSection, TeethSection};

/// Problems of the per-tooth inputs that the case alone shows: array lengths against the
/// numbers of teeth, tooth indices, a fault's keys against its kind, ascending roll
/// angles. `z1`, `z2`: teeth of pinion and gear.
pub(crate) fn teeth_problems(
    t: &TeethSection,
    m: &ModificationSection,
    faults: &[FaultTable],
    z1: i64,
    z2: i64,
    stage_teeth: &[[i64; 2]],
) -> Vec<String> {
    let mut p = array_length_problems(t, z1, z2);
    p.extend(profile_deviation_problems(m));
    p.extend(fault_problems(faults, [z1, z2], stage_teeth));
    p
}

/// Per-tooth arrays of `[teeth]` whose lengths do not match the numbers of teeth (`z1`,
/// `z2`): a pitch error per tooth; a profile deviation for every tooth (1) or per tooth.
fn array_length_problems(t: &TeethSection, z1: i64, z2: i64) -> Vec<String> {
    let mut p = Vec::new();
    let exact = |key: &str, v: &Option<Vec<f64>>, z: i64, who: &str, p: &mut Vec<String>| {
        if let Some(v) = v {
            if v.len() as i64 != z {
                p.push(format!(
                    "`teeth.{key}` has {} values but the {who} has {z} teeth: give one value per tooth ({z})",
                    v.len()
                ));
            }
        }
    };
    exact(
        "pitch_error_pinion_um",
        &t.pitch_error_pinion_um,
        z1,
        "pinion",
        &mut p,
    );
    exact(
        "pitch_error_gear_um",
        &t.pitch_error_gear_um,
        z2,
        "gear",
        &mut p,
    );
    for (key, v, z, who) in [
        (
            "profile_slope_pinion_um",
            &t.profile_slope_pinion_um,
            z1,
            "pinion",
        ),
        (
            "profile_slope_gear_um",
            &t.profile_slope_gear_um,
            z2,
            "gear",
        ),
        (
            "profile_form_pinion_um",
            &t.profile_form_pinion_um,
            z1,
            "pinion",
        ),
        ("profile_form_gear_um", &t.profile_form_gear_um, z2, "gear"),
    ] {
        if let Some(v) = v {
            if v.len() != 1 && v.len() as i64 != z {
                p.push(format!(
                    "`teeth.{key}` has {} values but the {who} has {z} teeth: give one value for every tooth (1) or one per tooth ({z})",
                    v.len()
                ));
            }
        }
    }
    p
}

/// A user profile deviation of `[modification]` whose roll angles and deviations do not
/// go together: given alone, of different lengths, or the angles not strictly ascending.
fn profile_deviation_problems(m: &ModificationSection) -> Vec<String> {
    let mut p = Vec::new();
    for (who, roll, dev) in [
        (
            "pinion",
            &m.profile_roll_pinion_deg,
            &m.profile_deviation_pinion_um,
        ),
        (
            "gear",
            &m.profile_roll_gear_deg,
            &m.profile_deviation_gear_um,
        ),
    ] {
        match (roll, dev) {
            (Some(r), Some(d)) => {
                if r.len() != d.len() {
                    p.push(format!(
                        "`modification.profile_roll_{who}_deg` has {} values but `modification.profile_deviation_{who}_um` has {}: they must have the same length",
                        r.len(),
                        d.len()
                    ));
                }
                if r.len() < 2 || r.windows(2).any(|w| w[1] <= w[0]) {
                    p.push(format!(
                        "`modification.profile_roll_{who}_deg` must hold at least 2 strictly ascending roll angles"
                    ));
                }
            }
            (None, None) => {}
            _ => p.push(format!(
                "`modification.profile_roll_{who}_deg` and `modification.profile_deviation_{who}_um` go together: give both or neither"
            )),
        }
    }
    p
}

/// Problems of the `[[fault]]` tables: a tooth index outside its gear (`pair`: teeth of
/// pinion and gear; on a train, `stage_teeth` of each stage, the fault's `stage` key
/// checked first, `config::train::fault_stage_problem`), keys against the kind, two
/// tables for one fault.
fn fault_problems(faults: &[FaultTable], pair: [i64; 2], stage_teeth: &[[i64; 2]]) -> Vec<String> {
    let mut p = Vec::new();
    for (i, f) in faults.iter().enumerate() {
        if let Some(problem) = super::train::fault_stage_problem(i, f.stage, stage_teeth.len()) {
            p.push(problem);
            continue;
        }
        let [z1, z2] = f
            .stage
            .and_then(|s| stage_teeth.get(usize::try_from(s - 1).ok()?))
            .copied()
            .unwrap_or(pair);
        let z = match f.gear {
            Member::Pinion => z1,
            Member::Gear => z2,
        };
        if f.tooth < 0 || f.tooth >= z {
            p.push(format!(
                "`fault.tooth` = {} (fault {i}, {} {}) is invalid: the {} has teeth 0 to {}",
                f.tooth,
                f.kind.name(),
                f.gear.name(),
                f.gear.name(),
                z - 1
            ));
        }
        p.extend(key_problems(f, i));
        for (j, g) in faults.iter().enumerate().take(i) {
            if g.gear == f.gear && g.tooth == f.tooth && g.kind == f.kind && g.stage == f.stage {
                p.push(format!(
                    "faults {j} and {i} are both a {} on {} tooth {}: give one table per fault",
                    f.kind.name(),
                    f.gear.name(),
                    f.tooth
                ));
            }
        }
    }
    p
}

/// The problems of the faults' spans across the face (`fault.face_start_mm`,
/// `fault.face_end_mm`, docs/MODEL.md 11.10): given only on a helical single pair (a spur
/// pair's fault spans the face by `fault.crack_width_fraction` or
/// `fault.spall_width_fraction`; a train's stage takes no span yet), each end within
/// [0, b] mm and the start below the end.
pub(crate) fn face_span_problems(faults: &[FaultTable], gear: &GearSection) -> Vec<String> {
    let mut p = Vec::new();
    let b = gear.face_width_mm;
    for (i, f) in faults.iter().enumerate() {
        let given = [
            ("face_start_mm", f.face_start_mm),
            ("face_end_mm", f.face_end_mm),
        ];
        if given.iter().all(|(_, v)| v.is_none()) {
            continue;
        }
        let which = format!(
            "fault {i}, {} {} tooth {}",
            f.kind.name(),
            f.gear.name(),
            f.tooth
        );
        if gear.helix_angle_deg == 0.0 || f.stage.is_some() {
            p.push(format!(
                "`fault.face_start_mm` / `fault.face_end_mm` ({which}) place a fault across the face of a helical single pair (`gear.helix_angle_deg` > 0, no `[[stage]]`); a spur pair's fault spans the face by `fault.crack_width_fraction` or `fault.spall_width_fraction`"
            ));
            continue;
        }
        for (key, v) in given {
            if let Some(v) = v.filter(|v| !(0.0..=b).contains(v)) {
                p.push(format!(
                    "`fault.{key}` = {v} ({which}) is outside the face: it must lie in [0, {b}] mm (`gear.face_width_mm` = {b})"
                ));
            }
        }
        let (start, end) = (f.face_start_mm.unwrap_or(0.0), f.face_end_mm.unwrap_or(b));
        if start >= end {
            p.push(format!(
                "`fault.face_start_mm` = {start} must lie below `fault.face_end_mm` = {end} ({which}): the span [start, end] must hold part of the face [0, {b}] mm"
            ));
        }
    }
    p
}
