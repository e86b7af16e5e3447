//! The case's per-tooth inputs: manufacturing errors (`[teeth]`), profile modifications
//! (`[modification]`) as the user writes them, and tooth faults (`[[fault]]` tables),
//! resolved when the case is loaded into [`ToothFault`]s (the kind as a [`Fault`] enum,
//! its sizes in SI units with their defaults).
//!
//! Every key is optional and absent by default: a case without them is the paper's
//! identical, perfect teeth and serialises exactly as before (so summaries and checksums
//! of such cases do not change). Checks that need only the case (array lengths against
//! the numbers of teeth, tooth indices, which keys a fault kind takes) live here
//! (`config::teeth_checks`); checks that need the geometry (a crack deeper than the tooth, a
//! spall longer than the profile, a relief longer than the addendum) are made when the
//! model builds its tooth inputs (`study::teeth::ToothInputs::from_case`).

use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// `[teeth]`: manufacturing errors of each gear (docs/MODEL.md, section 9).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct TeethSection {
    /// Position (pitch) error of each pinion tooth, µm on the reference circle, positive
    /// towards the mating flank; z1 values.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pitch_error_pinion_um: Option<Vec<f64>>,
    /// Position (pitch) error of each gear tooth, µm (positive towards the pinion); z2
    /// values.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pitch_error_gear_um: Option<Vec<f64>>,
    /// ISO 1328-1 flank tolerance class: errors not given explicitly are drawn for it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub accuracy_grade: Option<i64>,
    /// Seed of the random draw for `accuracy_grade`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_seed: Option<i64>,
    /// Radial run-out F_r of the pinion (twice its eccentricity), µm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_pinion_um: Option<f64>,
    /// Radial run-out F_r of the gear (twice its eccentricity), µm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_gear_um: Option<f64>,
    /// Angle the pinion turns from the entry of its tooth 0 until its eccentricity points
    /// along the line of action towards the gear, deg.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_pinion_phase_deg: Option<f64>,
    /// Angle the gear turns from the entry of its tooth 0 until its eccentricity points along
    /// the line of action towards the pinion, deg.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_gear_phase_deg: Option<f64>,
    /// Profile slope deviation f_Halpha of the pinion teeth, µm (one value for every tooth,
    /// or z1 values).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_slope_pinion_um: Option<Vec<f64>>,
    /// Profile slope deviation f_Halpha of the gear teeth, µm (one value or z2 values).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_slope_gear_um: Option<Vec<f64>>,
    /// Profile form deviation f_falpha of the pinion teeth, µm (one value or z1 values).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_form_pinion_um: Option<Vec<f64>>,
    /// Profile form deviation f_falpha of the gear teeth, µm (one value or z2 values).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_form_gear_um: Option<Vec<f64>>,
}

impl TeethSection {
    /// Whether no key is given (the paper's perfect teeth).
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
    /// Removed material growing linearly along the relief's length.
    #[default]
    Linear,
    /// Growing with the square of the distance into the relief.
    Parabolic,
}

/// `[modification]`: profile modifications of every tooth of both gears.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct ModificationSection {
    /// Tip relief at the tip (material removed), µm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tip_relief_um: Option<f64>,
    /// Length of the tip relief along the line of action (roll length) from the tip's
    /// contact point, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tip_relief_length_mm: Option<f64>,
    /// Root relief at the start of the active profile (material removed), µm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub root_relief_um: Option<f64>,
    /// Length of the root relief along the line of action from the start of the active
    /// profile, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub root_relief_length_mm: Option<f64>,
    /// Shape of the reliefs along their length (absent: linear).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<ReliefShape>,
    /// Roll angles (rho / r_b) of a measured or designed deviation of every pinion tooth,
    /// deg, ascending.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_roll_pinion_deg: Option<Vec<f64>>,
    /// The pinion's deviation at those roll angles (material removed positive), µm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_deviation_pinion_um: Option<Vec<f64>>,
    /// Roll angles of a deviation of every gear tooth, deg, ascending.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_roll_gear_deg: Option<Vec<f64>>,
    /// The gear's deviation at those roll angles (material removed positive), µm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_deviation_gear_um: Option<Vec<f64>>,
    /// Lead crowning of the pair (both gears together): the gap at each face end over the
    /// face's middle, parabolic across the face, µm (docs/MODEL.md 11.2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crowning_um: Option<f64>,
    /// End relief of the pair (both gears together): the gap at each face end, µm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub end_relief_um: Option<f64>,
    /// Length of the end relief from each face end across the face, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub end_relief_length_mm: Option<f64>,
    /// Shape of the end relief along its length (absent: linear).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub end_relief_shape: Option<ReliefShape>,
    /// Helix slope deviation f_Hbeta of the pair: the gap's difference across the face
    /// width (ISO 1328-1), positive opening it towards the face end y = b, µm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub helix_slope_deviation_um: Option<f64>,
}

impl ModificationSection {
    /// Whether a lead (face-direction) key is given: crowning, end relief, helix slope.
    pub fn has_lead_keys(&self) -> bool {
        self.crowning_um.is_some()
            || self.end_relief_um.is_some()
            || self.end_relief_length_mm.is_some()
            || self.end_relief_shape.is_some()
            || self.helix_slope_deviation_um.is_some()
    }

    /// The section without its lead keys (the profile modifications only).
    pub fn without_lead_keys(&self) -> Self {
        Self {
            crowning_um: None,
            end_relief_um: None,
            end_relief_length_mm: None,
            end_relief_shape: None,
            helix_slope_deviation_um: None,
            ..self.clone()
        }
    }

    /// Whether no key is given (true involutes).
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
    /// The pinion.
    Pinion,
    /// The gear.
    Gear,
}

impl Member {
    /// Its name in messages and keys.
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
    /// A root crack.
    Crack,
    /// A spall (pit) on the flank.
    Spall,
    /// A broken tip.
    BrokenTip,
}

impl FaultKind {
    /// Its name as the case file spells it.
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
pub(crate) const DEFAULT_CRACK_ANGLE_DEG: f64 = 45.0;

/// Default share of the face width a crack has run across or a spall covers: 1, the whole
/// face.
pub(crate) const DEFAULT_WIDTH_FRACTION: f64 = 1.0;

/// One `[[fault]]` table as the case file writes it: sizes in mm, um and deg, the keys a
/// kind does not take or leaves to their default absent. Read, checked
/// (`teeth_problems`) and resolved into a [`ToothFault`] when the case is loaded; a case
/// serialises its faults back to these tables, unchanged.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FaultTable {
    /// Kind of fault.
    pub kind: FaultKind,
    /// The gear whose tooth has the fault.
    pub gear: Member,
    /// 0-based tooth index (tooth n meets the mate in mesh cycle n, n + z, ...).
    pub tooth: i64,
    /// The stage of a gear train whose pair holds the tooth, 1-based (required with
    /// `[[stage]]` tables, refused without them; docs/MODEL.md 9.10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stage: Option<i64>,
    /// Crack: depth from the root along its path, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_depth_mm: Option<f64>,
    /// Crack: angle of its path to the tooth centreline, deg (absent:
    /// `DEFAULT_CRACK_ANGLE_DEG`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_angle_deg: Option<f64>,
    /// Crack: share of the face width it has run across (absent: the whole face).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_width_fraction: Option<f64>,
    /// Spall: roll distance of its centre from the pitch point, positive towards the tip,
    /// mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_position_mm: Option<f64>,
    /// Spall: its extent as a roll length, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_length_mm: Option<f64>,
    /// Spall: depth of the pit, um.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_depth_um: Option<f64>,
    /// Spall: share of the face width it covers (absent: the whole face).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_width_fraction: Option<f64>,
    /// Broken tip: radial height removed from the tip, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub removed_height_mm: Option<f64>,
    /// A crack or spall on a helical pair: where its span across the face starts, mm from
    /// the face end y = 0 (absent: 0; docs/MODEL.md 11.10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub face_start_mm: Option<f64>,
    /// A crack or spall on a helical pair: where its span across the face ends, mm from
    /// the face end y = 0 (absent: the face width b).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub face_end_mm: Option<f64>,
}

impl FaultTable {
    /// The kind-specific keys and their values as written, by name.
    fn fields(&self) -> [(&'static str, Option<f64>); 8] {
        [
            ("crack_depth_mm", self.crack_depth_mm),
            ("crack_angle_deg", self.crack_angle_deg),
            ("crack_width_fraction", self.crack_width_fraction),
            ("spall_position_mm", self.spall_position_mm),
            ("spall_length_mm", self.spall_length_mm),
            ("spall_depth_um", self.spall_depth_um),
            ("spall_width_fraction", self.spall_width_fraction),
            ("removed_height_mm", self.removed_height_mm),
        ]
    }

    /// The kind-specific keys given, by name.
    pub(crate) fn given(&self) -> [(&'static str, bool); 8] {
        self.fields().map(|(k, v)| (k, v.is_some()))
    }

    /// The value of kind-specific `key` in the case file's unit: as written, or its
    /// default where the file leaves it out (the one place the defaults are applied);
    /// `None` for a required key not given.
    pub fn value(&self, key: &str) -> Option<f64> {
        let written = self
            .fields()
            .iter()
            .find(|(k, _)| *k == key)
            .and_then(|(_, v)| *v);
        written.or(match key {
            "crack_angle_deg" => Some(DEFAULT_CRACK_ANGLE_DEG),
            "crack_width_fraction" | "spall_width_fraction" => Some(DEFAULT_WIDTH_FRACTION),
            _ => None,
        })
    }
}

/// A tooth fault resolved to SI units with its defaults (docs/MODEL.md, section 9): what
/// the model's stiffness, gaps and contact limits are built from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fault {
    /// A root crack (Chen & Shao 2011): a straight path from the root at `angle_rad` to the
    /// tooth centreline, `depth_m` long, across `width_fraction` of the face from one side.
    Crack {
        /// Crack length from the root along its path, m.
        depth_m: f64,
        /// Angle of the crack path to the tooth centreline, rad.
        angle_rad: f64,
        /// Share of the face width the crack has run across (0, 1].
        width_fraction: f64,
    },
    /// A spall (Saxena et al. 2016): a pit `depth_m` deep over the roll lengths
    /// `position_m` +- `length_m` / 2 from the pitch point (positive towards the tip),
    /// across `width_fraction` of the face.
    Spall {
        /// Roll length of the pit's centre from the pitch point, positive towards the tip, m.
        position_m: f64,
        /// Roll length the pit covers along the profile, m.
        length_m: f64,
        /// Depth of the pit normal to the flank, m.
        depth_m: f64,
        /// Share of the face width the pit covers (0, 1].
        width_fraction: f64,
    },
    /// A broken tip: `removed_height_m` of the tooth's radial height gone from the tip.
    BrokenTip {
        /// Radial height removed from the tip, m.
        removed_height_m: f64,
    },
}

/// One tooth fault of a case: the tooth it is on and the fault, resolved when the case is
/// loaded. Serialised as the `[[fault]]` table it was read from ([`ToothFault::table`]),
/// so a case reads back to itself and keeps its checksum.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "FaultTable", into = "FaultTable")]
pub struct ToothFault {
    /// The gear whose tooth has the fault.
    pub gear: Member,
    /// 0-based tooth index (tooth n meets the mate in mesh cycle n, n + z, ...).
    pub tooth: usize,
    /// The fault, in SI units.
    pub fault: Fault,
    table: FaultTable,
}

impl ToothFault {
    /// The kind of the fault.
    pub fn kind(&self) -> FaultKind {
        self.table.kind
    }

    /// Whether the fault changes its tooth: a crack of zero depth removes nothing (its
    /// angle and width then meaningless); a spall and a broken tip have required sizes
    /// above zero.
    pub fn changes_tooth(&self) -> bool {
        match self.fault {
            Fault::Crack { depth_m, .. } => depth_m != 0.0,
            Fault::Spall { .. } | Fault::BrokenTip { .. } => true,
        }
    }

    /// The stage of a gear train whose pair holds the tooth, 0-based (None on a single
    /// pair; the config checks make it present and in range on a train).
    pub fn stage_index(&self) -> Option<usize> {
        self.table
            .stage
            .and_then(|s| usize::try_from(s).ok())
            .and_then(|s| s.checked_sub(1))
    }

    /// The table as the case file gave it (its units, absent keys absent): for tables
    /// that quote the case file's values.
    pub fn table(&self) -> &FaultTable {
        &self.table
    }

    /// The span of the face the fault covers on a helical pair, m from the face end y = 0
    /// (`fault.face_start_mm`, `fault.face_end_mm`; absent: 0 and `face_width_m`, the whole
    /// face; docs/MODEL.md 11.10).
    pub fn face_span_m(&self, face_width_m: f64) -> (f64, f64) {
        (
            self.table.face_start_mm.map_or(0.0, |x| x * 1e-3),
            self.table.face_end_mm.map_or(face_width_m, |x| x * 1e-3),
        )
    }

    /// Whether the case gives the fault a span across the face (`fault.face_start_mm` or
    /// `fault.face_end_mm`).
    pub fn has_face_span(&self) -> bool {
        self.table.face_start_mm.is_some() || self.table.face_end_mm.is_some()
    }

    /// The value of one of its kind's keys as the case file gave it, in the file's unit
    /// (its default where the file leaves it out): for messages that quote it. NaN for a
    /// key of another kind.
    pub fn written(&self, key: &str) -> f64 {
        self.table.value(key).unwrap_or(f64::NAN)
    }
}

impl TryFrom<FaultTable> for ToothFault {
    type Error = String;

    /// The fault of `table`, or the problems that keep it from being one (its keys against
    /// its kind, a negative tooth; the tooth against the gear's teeth is checked with the
    /// case, `teeth_problems`).
    fn try_from(table: FaultTable) -> Result<Self, String> {
        let mut p = key_problems(&table, 0);
        let tooth = usize::try_from(table.tooth).map_err(|_| {
            format!(
                "`fault.tooth` = {} is invalid: teeth are numbered from 0",
                table.tooth
            )
        });
        if let Err(e) = &tooth {
            p.push(e.clone());
        }
        if !p.is_empty() {
            return Err(p.join("; "));
        }
        let fault = table.resolved();
        Ok(Self {
            gear: table.gear,
            tooth: tooth.unwrap_or(0),
            fault,
            table,
        })
    }
}

impl FaultTable {
    /// The fault its keys give, in SI units with the defaults applied: the one place a
    /// table's sizes are resolved (a pair's `[[fault]]` and a planetary set's
    /// `[[planetary.fault]]`, `config::planetary`). A required key not given counts as 0
    /// (its absence is a problem the callers report first).
    pub(crate) fn resolved(&self) -> Fault {
        let table = self;
        let v = |key: &str| table.value(key).unwrap_or(0.0);
        match table.kind {
            FaultKind::Crack => Fault::Crack {
                depth_m: v("crack_depth_mm") * 1e-3,
                angle_rad: v("crack_angle_deg") * PI / 180.0,
                width_fraction: v("crack_width_fraction"),
            },
            FaultKind::Spall => Fault::Spall {
                position_m: v("spall_position_mm") * 1e-3,
                length_m: v("spall_length_mm") * 1e-3,
                depth_m: v("spall_depth_um") * 1e-6,
                width_fraction: v("spall_width_fraction"),
            },
            FaultKind::BrokenTip => Fault::BrokenTip {
                removed_height_m: v("removed_height_mm") * 1e-3,
            },
        }
    }
}

impl From<ToothFault> for FaultTable {
    fn from(f: ToothFault) -> Self {
        f.table
    }
}

/// The problems of fault `i`'s keys against its kind: a key the kind does not take, a
/// required one missing.
pub(super) fn key_problems(f: &FaultTable, i: usize) -> Vec<String> {
    let mut p = Vec::new();
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
    p
}
