//! The case's per-tooth inputs: manufacturing errors (`[teeth]`), profile modifications
//! (`[modification]`) and tooth faults (`[[fault]]` tables), as the user writes them.
//!
//! Every key is optional and absent by default: a case without them is the paper's
//! identical, perfect teeth and serialises exactly as before (so summaries and checksums
//! of such cases do not change). Checks that need only the case (array lengths against
//! the numbers of teeth, tooth indices, which keys a fault kind takes) live here
//! ([`teeth_problems`]); checks that need the geometry (a crack deeper than the tooth, a
//! spall longer than the profile, a relief longer than the addendum) are made when the
//! model is built (`study::teeth_domain`).

use serde::{Deserialize, Serialize};

/// `[teeth]`: manufacturing errors of each gear (docs/MODEL.md, section 9).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct TeethSection {
    /// Position (pitch) error of each pinion tooth, um on the reference circle, positive
    /// towards the mating flank; z1 values.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pitch_error_pinion_um: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pitch_error_gear_um: Option<Vec<f64>>,
    /// ISO 1328-1 flank tolerance class: errors not given explicitly are drawn for it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub accuracy_grade: Option<i64>,
    /// Seed of the random draw for `accuracy_grade`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_seed: Option<i64>,
    /// Radial run-out F_r of each gear (twice its eccentricity), um.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_pinion_um: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_gear_um: Option<f64>,
    /// Angle the gear turns from the entry of its tooth 0 until its eccentricity points
    /// along the line of action towards the mate, deg.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_pinion_phase_deg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_gear_phase_deg: Option<f64>,
    /// Profile slope deviation f_Halpha, um (one value for every tooth, or z values).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_slope_pinion_um: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_slope_gear_um: Option<Vec<f64>>,
    /// Profile form deviation f_falpha, um (one value or z values).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_form_pinion_um: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_form_gear_um: Option<Vec<f64>>,
}

impl TeethSection {
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }

    /// Whether the section makes any tooth differ from the paper's: a drawn accuracy
    /// class, or an error or run-out that is not zero. Zero errors, a zero run-out (its
    /// phase then meaningless) and a seed alone change nothing.
    pub fn changes_teeth(&self) -> bool {
        let any = |v: &Option<Vec<f64>>| v.as_ref().is_some_and(|v| v.iter().any(|x| *x != 0.0));
        let nonzero = |v: &Option<f64>| v.is_some_and(|x| x != 0.0);
        self.accuracy_grade.is_some()
            || any(&self.pitch_error_pinion_um)
            || any(&self.pitch_error_gear_um)
            || nonzero(&self.runout_pinion_um)
            || nonzero(&self.runout_gear_um)
            || any(&self.profile_slope_pinion_um)
            || any(&self.profile_slope_gear_um)
            || any(&self.profile_form_pinion_um)
            || any(&self.profile_form_gear_um)
    }
}

/// Shape of a relief along its length.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum ReliefShape {
    #[default]
    Linear,
    Parabolic,
}

/// `[modification]`: profile modifications of every tooth of both gears.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct ModificationSection {
    /// Tip relief at the tip (amount), um, and its length along the line of action, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tip_relief_um: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tip_relief_length_mm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub root_relief_um: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub root_relief_length_mm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<ReliefShape>,
    /// A measured or designed deviation along each gear's roll angle (material removed
    /// positive, um), on every tooth.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_roll_pinion_deg: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_deviation_pinion_um: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_roll_gear_deg: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_deviation_gear_um: Option<Vec<f64>>,
}

impl ModificationSection {
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }

    /// Whether the section removes material anywhere: a relief of a non-zero amount, or a
    /// user profile deviation that is not zero somewhere (a length, a shape or roll angles
    /// alone change nothing).
    pub fn changes_teeth(&self) -> bool {
        let any = |v: &Option<Vec<f64>>| v.as_ref().is_some_and(|v| v.iter().any(|x| *x != 0.0));
        let nonzero = |v: &Option<f64>| v.is_some_and(|x| x != 0.0);
        nonzero(&self.tip_relief_um)
            || nonzero(&self.root_relief_um)
            || any(&self.profile_deviation_pinion_um)
            || any(&self.profile_deviation_gear_um)
    }
}

/// Which gear a per-tooth input belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Member {
    Pinion,
    Gear,
}

impl Member {
    pub fn name(self) -> &'static str {
        match self {
            Member::Pinion => "pinion",
            Member::Gear => "gear",
        }
    }
}

/// Kind of tooth fault.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FaultKind {
    Crack,
    Spall,
    BrokenTip,
}

impl FaultKind {
    pub fn name(self) -> &'static str {
        match self {
            FaultKind::Crack => "crack",
            FaultKind::Spall => "spall",
            FaultKind::BrokenTip => "broken_tip",
        }
    }

    /// The keys of a `[[fault]]` table this kind takes (besides kind, gear, tooth), and
    /// whether each is required.
    pub fn keys(self) -> &'static [(&'static str, bool)] {
        match self {
            FaultKind::Crack => &[
                ("crack_depth_mm", true),
                ("crack_angle_deg", false),
                ("crack_width_fraction", false),
            ],
            FaultKind::Spall => &[
                ("spall_position_mm", true),
                ("spall_length_mm", true),
                ("spall_depth_um", true),
                ("spall_width_fraction", false),
            ],
            FaultKind::BrokenTip => &[("removed_height_mm", true)],
        }
    }
}

/// Default crack angle to the tooth centreline, deg (Chen & Shao 2011 use 45 deg).
pub const DEFAULT_CRACK_ANGLE_DEG: f64 = 45.0;

/// One `[[fault]]` table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FaultSpec {
    pub kind: FaultKind,
    pub gear: Member,
    /// 0-based tooth index (tooth n meets the mate in mesh cycle n, n + z, ...).
    pub tooth: i64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_depth_mm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_angle_deg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_width_fraction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_position_mm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_length_mm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_depth_um: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_width_fraction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub removed_height_mm: Option<f64>,
}

impl FaultSpec {
    /// Whether the fault changes its tooth: a crack of zero depth removes nothing (its
    /// angle and width then meaningless); a spall and a broken tip have required sizes
    /// above zero.
    pub fn changes_tooth(&self) -> bool {
        match self.kind {
            FaultKind::Crack => self.crack_depth_mm.is_some_and(|d| d != 0.0),
            FaultKind::Spall | FaultKind::BrokenTip => true,
        }
    }

    /// The kind-specific keys given, by name.
    fn given(&self) -> [(&'static str, bool); 8] {
        [
            ("crack_depth_mm", self.crack_depth_mm.is_some()),
            ("crack_angle_deg", self.crack_angle_deg.is_some()),
            ("crack_width_fraction", self.crack_width_fraction.is_some()),
            ("spall_position_mm", self.spall_position_mm.is_some()),
            ("spall_length_mm", self.spall_length_mm.is_some()),
            ("spall_depth_um", self.spall_depth_um.is_some()),
            ("spall_width_fraction", self.spall_width_fraction.is_some()),
            ("removed_height_mm", self.removed_height_mm.is_some()),
        ]
    }
}

/// Problems of the per-tooth inputs that the case alone shows: array lengths against the
/// numbers of teeth, tooth indices, a fault's keys against its kind, ascending roll
/// angles. `z1`, `z2`: teeth of pinion and gear.
pub fn teeth_problems(
    t: &TeethSection,
    m: &ModificationSection,
    faults: &[FaultSpec],
    z1: i64,
    z2: i64,
) -> Vec<String> {
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
    for (i, f) in faults.iter().enumerate() {
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
        let own = f.kind.keys();
        for (key, given) in f.given() {
            let takes = own.iter().find(|(k, _)| *k == key);
            match takes {
                None if given => p.push(format!(
                    "`fault.{key}` (fault {i}) does not apply to kind \"{}\"; its keys: {}",
                    f.kind.name(),
                    own.iter().map(|(k, _)| *k).collect::<Vec<_>>().join(", ")
                )),
                Some((_, true)) if !given => p.push(format!(
                    "`fault.{key}` is required for a fault of kind \"{}\" (fault {i}, {} tooth {})",
                    f.kind.name(),
                    f.gear.name(),
                    f.tooth
                )),
                _ => {}
            }
        }
        for (j, g) in faults.iter().enumerate().take(i) {
            if g.gear == f.gear && g.tooth == f.tooth && g.kind == f.kind {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn fault(kind: FaultKind, tooth: i64) -> FaultSpec {
        FaultSpec {
            kind,
            gear: Member::Pinion,
            tooth,
            crack_depth_mm: None,
            crack_angle_deg: None,
            crack_width_fraction: None,
            spall_position_mm: None,
            spall_length_mm: None,
            spall_depth_um: None,
            spall_width_fraction: None,
            removed_height_mm: None,
        }
    }

    #[test]
    fn wrong_lengths_name_both_lengths_and_indices_the_valid_range() {
        let t = TeethSection {
            pitch_error_pinion_um: Some(vec![1.0; 18]),
            profile_form_gear_um: Some(vec![1.0; 2]),
            ..Default::default()
        };
        let mut crack = fault(FaultKind::Crack, 19);
        crack.spall_depth_um = Some(3.0);
        let p = teeth_problems(&t, &ModificationSection::default(), &[crack], 19, 31);
        let all = p.join("\n");
        assert!(
            all.contains("18 values") && all.contains("19 teeth"),
            "{all}"
        );
        assert!(
            all.contains("has 2 values") && all.contains("(31)"),
            "{all}"
        );
        assert!(
            all.contains("`fault.tooth` = 19") && all.contains("0 to 18"),
            "{all}"
        );
        assert!(all.contains("`fault.crack_depth_mm` is required"), "{all}");
        assert!(all.contains("`fault.spall_depth_um`") && all.contains("does not apply"));
    }

    #[test]
    fn empty_sections_serialise_to_nothing() {
        let v = toml::Value::try_from(TeethSection::default()).unwrap();
        assert_eq!(v.as_table().map(|t| t.len()), Some(0));
        let v = toml::Value::try_from(ModificationSection::default()).unwrap();
        assert_eq!(v.as_table().map(|t| t.len()), Some(0));
    }
}
