//! `[[planetary.fault]]`: a tooth fault on one member of a planetary set, as the keys of a
//! pair's `[[fault]]` table (docs/MODEL.md 12.13).

use super::teeth::{Fault, FaultKind, FaultTable, Member as PairMember};
use serde::{Deserialize, Serialize};

/// The member of a set whose tooth has a fault.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FaultyGear {
    /// The sun.
    Sun,
    /// One planet (`planetary.fault.planet`).
    Planet,
    /// The ring.
    Ring,
}

impl FaultyGear {
    /// The case file's word for it.
    pub fn name(self) -> &'static str {
        match self {
            FaultyGear::Sun => "sun",
            FaultyGear::Planet => "planet",
            FaultyGear::Ring => "ring",
        }
    }
}

/// `[[planetary.fault]]`: a crack or a spall on one tooth of the sun, of one planet or of
/// the ring, the keys of a pair's `[[fault]]` table (`config::teeth::FaultTable`: the
/// same kinds, sizes, units, defaults and meaning) with `gear` one of the set's members
/// and `planet` naming the planet (1..=N, as every output numbers them).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanetaryFault {
    /// Kind of fault (a crack or a spall on a set so far).
    pub kind: FaultKind,
    /// The member whose tooth has the fault.
    pub gear: FaultyGear,
    /// The planet, 1..=N (required for `gear = "planet"`, refused otherwise).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub planet: Option<i64>,
    /// 0-based tooth index on that member (docs/MODEL.md 12.13 numbers the teeth).
    pub tooth: i64,
    /// Crack: depth from the root along its path, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_depth_mm: Option<f64>,
    /// Crack: angle of its path to the tooth centreline, deg (absent: 45).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_angle_deg: Option<f64>,
    /// Crack: share of the face width it has run across (absent: 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_width_fraction: Option<f64>,
    /// Spall: roll distance of its centre from the pitch point, towards the tip, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_position_mm: Option<f64>,
    /// Spall: its extent as a roll length, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_length_mm: Option<f64>,
    /// Spall: depth of the pit, um.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_depth_um: Option<f64>,
    /// Spall: share of the face width it covers (absent: 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_width_fraction: Option<f64>,
    /// Broken tip: radial height removed from the tip, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub removed_height_mm: Option<f64>,
}

impl PlanetaryFault {
    /// Its sizes as a pair's `[[fault]]` table (`gear`, `tooth` unread): the pair's defaults.
    pub fn as_pair_table(&self) -> FaultTable {
        FaultTable {
            kind: self.kind,
            gear: PairMember::Pinion,
            tooth: self.tooth,
            stage: None,
            crack_depth_mm: self.crack_depth_mm,
            crack_angle_deg: self.crack_angle_deg,
            crack_width_fraction: self.crack_width_fraction,
            spall_position_mm: self.spall_position_mm,
            spall_length_mm: self.spall_length_mm,
            spall_depth_um: self.spall_depth_um,
            spall_width_fraction: self.spall_width_fraction,
            removed_height_mm: self.removed_height_mm,
            face_start_mm: None,
            face_end_mm: None,
        }
    }

    /// The fault in SI units with its defaults (`FaultTable::resolved`).
    pub fn fault(&self) -> Fault {
        self.as_pair_table().resolved()
    }

    /// Whether it changes its tooth (a crack of zero depth does not).
    pub fn changes_tooth(&self) -> bool {
        match self.fault() {
            Fault::Crack { depth_m, .. } => depth_m != 0.0,
            Fault::Spall { .. } | Fault::BrokenTip { .. } => true,
        }
    }

    /// A key's value as written (its default where left out; NaN for another kind's key).
    pub fn written(&self, key: &str) -> f64 {
        self.as_pair_table().value(key).unwrap_or(f64::NAN)
    }

    /// Who it is in messages: `sun tooth 3`, `planet 2 tooth 3`.
    pub fn who(&self) -> String {
        match (self.gear, self.planet) {
            (FaultyGear::Planet, Some(p)) => format!("planet {p} tooth {}", self.tooth),
            (g, _) => format!("{} tooth {}", g.name(), self.tooth),
        }
    }
}

/// Of a set's `[[planetary.fault]]` tables, the one the model applies: the first that
/// changes its tooth (a crack of zero depth is the healthy set).
pub fn active(faults: &[PlanetaryFault]) -> Option<&PlanetaryFault> {
    faults.iter().find(|f| f.changes_tooth())
}
