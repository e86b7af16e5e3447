//! The types of a dataset's study design: the `design.toml` tables as written (read by
//! `design`, checked by `design_checks`) and the validated design they give.

use crate::config::Case;
use serde::Deserialize;
use toml::Table;

/// `design.toml` as written (module docs of `design`).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(crate) struct DesignFile {
    pub(crate) case: Option<String>,
    #[serde(default)]
    pub(crate) set: Vec<String>,
    pub(crate) transfer_path: Option<String>,
    #[serde(default, deserialize_with = "seed")]
    pub(crate) seed: u64,
    #[serde(default)]
    pub(crate) run_to_failure: RunToFailureFile,
    #[serde(default)]
    pub(crate) operating: OperatingFile,
    #[serde(default)]
    pub(crate) records: RecordsFile,
    #[serde(default)]
    pub(crate) condition: Vec<ConditionFile>,
}

/// The design's `seed`: a whole number in [0, 2^53], written as an integer or a whole
/// float (`crate::rng::MAX_SEED`); the message names the key, the value and the range.
fn seed<'de, D: serde::Deserializer<'de>>(d: D) -> Result<u64, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Number {
        Int(i64),
        Float(f64),
    }
    match Number::deserialize(d) {
        Ok(Number::Int(i)) => crate::rng::seed_from_i128("seed", i as i128).map_err(|e| e.to_string()),
        Ok(Number::Float(x)) => crate::rng::seed_from_f64("seed", x).map_err(|e| e.to_string()),
        Err(_) => Err(format!(
            "`seed` is not a number (text, a boolean or a table): expected a whole number in [0, {}]",
            crate::rng::MAX_SEED
        )),
    }
    .map_err(serde::de::Error::custom)
}

/// `[run_to_failure]` as written: states, cycles, max_cycles, wear_limit_um.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(crate) struct RunToFailureFile {
    pub(crate) states: Option<i64>,
    pub(crate) cycles: Option<Vec<f64>>,
    pub(crate) max_cycles: Option<f64>,
    pub(crate) wear_limit_um: Option<f64>,
}

/// `[operating]` as written: the speeds (Hz) and torques (N m) of every state.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(crate) struct OperatingFile {
    pub(crate) input_speed_hz: Option<Vec<f64>>,
    pub(crate) load_torque_nm: Option<Vec<f64>>,
}

/// `[records]` as written: noise realisations, CSV copies, disk budget (GiB).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub(crate) struct RecordsFile {
    pub(crate) noise_realisations: i64,
    pub(crate) csv: bool,
    pub(crate) disk_budget_gib: f64,
}

impl Default for RecordsFile {
    fn default() -> Self {
        Self {
            noise_realisations: 1,
            csv: false,
            disk_budget_gib: 10.0,
        }
    }
}

/// One `[[condition]]` as written: its name, labels and case overrides.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ConditionFile {
    pub(crate) name: String,
    pub(crate) fault: Option<String>,
    pub(crate) severity: Option<f64>,
    #[serde(default)]
    pub(crate) case: Table,
}

/// Which states of a wear trajectory are recorded.
#[derive(Debug, Clone, PartialEq)]
pub enum StateChoice {
    /// This many, evenly spaced in cycles from 0 to the trajectory's end.
    Count(usize),
    /// At these pinion cycle counts (ascending).
    Cycles(Vec<f64>),
}

/// A fault type and severity: the case it is modelled by, and its labels.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// The condition's name (unique in the design; names the trajectory's state file).
    pub name: String,
    /// What the case models ([`super::design::fault_label`]): never a free text.
    pub fault: String,
    /// The user's grade of the fault: 0 without one (or ungraded), >= 0 with one.
    pub severity: f64,
    /// The resolved case of this condition at the design's base operating point.
    pub case: Case,
}

/// A validated design.
#[derive(Debug, Clone, PartialEq)]
pub struct DatasetDesign {
    /// Seed every record's noise seed derives from (with the record id).
    pub seed: u64,
    /// The transfer-path file, as written in the design (resolved against its folder).
    pub transfer_path: Option<std::path::PathBuf>,
    /// The states recorded along each trajectory (a count from new to failure, or cycle
    /// counts).
    pub states: StateChoice,
    /// Longest trajectory, pinion cycles.
    pub max_cycles: f64,
    /// Failure: the deepest wear (pinion or gear profile) reaching this, µm.
    pub wear_limit_um: f64,
    /// Input speeds each state is recorded at, Hz.
    pub speeds_hz: Vec<f64>,
    /// Load torques each state is recorded at, N m.
    pub torques_nm: Vec<f64>,
    /// Records per physical state, each with its own noise.
    pub noise_realisations: usize,
    /// Write a CSV copy of each record (PHM 2009 style) as well.
    pub csv: bool,
    /// Largest estimated size of the dataset accepted, GiB.
    pub disk_budget_gib: f64,
    /// The fault conditions, each with its own trajectory.
    pub conditions: Vec<Condition>,
    /// The design's text, for the metadata.
    pub text: String,
}
