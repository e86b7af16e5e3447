//! The first step of a dataset job, before any work: the design checked against the
//! signal chain of every condition and against the disk budget; the dataset's key and its
//! description.

use super::folder::MAX_DATASET_FILE_BYTES;
use super::request::{DatasetError, DatasetRequest};
use crate::checksum::sha256_hex;
use crate::config::case::Case;
use crate::report::signals::chain_json;
use crate::signals::files::units;
use crate::signals::setup::{chain_of, ChainSetup};
use crate::study::budget::{trajectory_bytes, RecordSize};
use crate::study::dataset::index::sensor_column_problems;
use crate::study::dataset::plan::plan_of;
use crate::study::dataset::{DatasetDesign, StateChoice};
use serde_json::{json, Value};

/// Bytes of the metadata and labels of one record besides its signals (sidecar JSON with
/// the indicators and per-tooth wear, index row), a generous bound from measured files.
const LABEL_BYTES_PER_RECORD: f64 = 16_384.0;

/// The case a condition's chain is checked against: the case itself for a single pair;
/// a gear train's sensor stage as a single-pair case at its own pinion speed
/// (`signals.sensor_stage`, as the `signals` command checks a train's chain).
fn chain_case(case: &crate::config::Case) -> Result<crate::config::Case, Vec<String>> {
    if case.stage.is_empty() {
        return Ok(case.clone());
    }
    let model = crate::study::Model::from_case(case).map_err(|e| e.0)?;
    let stages = model.train.as_ref().map_or(&[][..], |t| &t.stages[..]);
    let k = case
        .signals
        .sensor_stage_index()
        .min(stages.len().max(1) - 1);
    stages
        .get(k)
        .map(|s| s.case.clone())
        .ok_or_else(|| vec!["the train has no stage".to_owned()])
}

/// A single helical pair's model built as its states will be (its wear per slice,
/// `Model::wear_study_from_case`): what it refuses (tilting keys, per-tooth inputs, ...)
/// is refused with the design, before the folder is opened. Nothing to check otherwise
/// (a spur pair's and a train's model is built when its trajectory runs, as before).
fn helical_model_check(case: &Case) -> Result<(), Vec<String>> {
    if !case.stage.is_empty() || case.gear.helix_angle_deg == 0.0 {
        return Ok(());
    }
    crate::study::Model::wear_study_from_case(case, super::state_files::DATASET)
        .map(|_| ())
        .map_err(|e| e.0)
}

/// The tachometer shaft's speed, Hz, at the input speed `input_hz`, for the chain `s` of
/// a condition's `case`: the single pair's pinion or gear; a train's sensor stage's
/// pinion or gear (`signals.sensor_stage`), through the ratios of the stages before it,
/// as `study::signal_record` turns them (each condition's own: conditions may differ in
/// their stages' teeth).
fn tachometer_hz(case: &Case, s: &ChainSetup, input_hz: f64) -> f64 {
    let gear_shaft = s.chain.tachometer.shaft == crate::signals::chain::Shaft::Gear;
    let ratio = |g: &crate::config::case::GearSection| g.teeth_pinion as f64 / g.teeth_gear as f64;
    if case.stage.is_empty() {
        let g = &case.gear;
        return if gear_shaft {
            input_hz * g.teeth_pinion as f64 / g.teeth_gear as f64
        } else {
            input_hz
        };
    }
    let k = case.signals.sensor_stage_index().min(case.stage.len() - 1);
    let through = if gear_shaft { k + 1 } else { k };
    case.stage[..through]
        .iter()
        .fold(input_hz, |hz, st| hz * ratio(&st.gear_section(&case.gear)))
}

/// The tachometer shaft's speed the description's record is sized at: a train's sensor
/// stage shaft at the first design speed ([`tachometer_hz`]); a single pair's first
/// design speed, as it always was (its description unchanged byte for byte).
fn record_shaft_hz(d: &DatasetDesign, s: &ChainSetup) -> f64 {
    if d.conditions[0].case.stage.is_empty() {
        d.speeds_hz[0]
    } else {
        tachometer_hz(&d.conditions[0].case, s, d.speeds_hz[0])
    }
}

/// The chain setup of each condition, checked at the design's fastest speed.
fn setups(req: &DatasetRequest) -> Result<Vec<ChainSetup>, Vec<String>> {
    let d = req.design;
    let fastest = d.speeds_hz.iter().fold(0.0_f64, |a, b| a.max(*b));
    let mut problems = Vec::new();
    let mut out: Vec<ChainSetup> = Vec::new();
    let mixed = super::plan_planetary::mixed_problems(d);
    if !mixed.is_empty() {
        return Err(mixed);
    }
    for c in &d.conditions {
        let mut case = c.case.clone();
        case.set_load_point(crate::config::case::LoadPoint {
            input_speed_hz: fastest,
            ..case.load_point()
        });
        let setup = if case.planetary.is_some() {
            super::plan_planetary::planetary_setup(req, &case)
        } else if let Err(e) = crate::study::train::refuse_fault(&case, "`gearwear dataset`") {
            Err(e.0)
        } else if let Err(e) = helical_model_check(&case) {
            Err(e)
        } else {
            chain_case(&case).and_then(|k| {
                chain_of(&k, req.path.clone(), k.signals.max_input_speed_hz(&k))
                    .map_err(|p| p.messages())
            })
        };
        match setup {
            Ok(s) => out.push(s),
            Err(e) => problems.extend(
                e.into_iter()
                    .map(|m| format!("condition `{}`: {m}", c.name)),
            ),
        }
    }
    // Sensors name index columns (one set of channels for every record: the chain is the
    // dataset's, `study::dataset::design`).
    if let Some(first) = out.first() {
        problems.extend(
            sensor_column_problems(&first.chain.path.sensors)
                .into_iter()
                .map(|m| format!("transfer path: {m}")),
        );
    }
    if problems.is_empty() {
        Ok(out)
    } else {
        Err(problems)
    }
}

/// The longest record of the dataset (the most samples, at the slowest speed) and the most
/// channels of any condition's chain: what the run budget counts per record.
pub fn record_size(d: &DatasetDesign, setups: &[ChainSetup]) -> RecordSize {
    let slowest = d.speeds_hz.iter().fold(f64::INFINITY, |a, b| a.min(*b));
    setups.iter().zip(&d.conditions).fold(
        RecordSize {
            samples: 0.0,
            channels: 0.0,
        },
        |acc, (s, c)| RecordSize {
            samples: acc
                .samples
                .max(s.chain.samples(tachometer_hz(&c.case, s, slowest)) as f64),
            channels: acc.channels.max(s.chain.path.sensors.len() as f64),
        },
    )
}

/// Bytes of a dataset's files besides its records and trajectories: the indicator trends'
/// figure (measured 92 kB at the default size) and table, the metadata and description
/// (8 kB and 5 kB for one condition), the index's fixed part.
const FIXED_BYTES: f64 = 256.0 * 1024.0;

/// How many times the budget's nominal count of wear updates a trajectory may run: the
/// threshold shortens the blocks when the wear runs faster than nominal
/// (`tests/dataset_budget.rs` prints both counts).
const TRAJECTORY_UPDATE_MARGIN: f64 = 2.0;

/// Estimated bytes of the whole dataset (module docs of [`super::folder`]): every record
/// (signals, CSV, labels), each condition's kept trajectory, and the fixed files.
pub fn estimate_bytes(d: &DatasetDesign, setups: &[ChainSetup]) -> f64 {
    let trajectories: f64 = d
        .conditions
        .iter()
        // At most what a folder keeps: a longer one is refused by its own check
        // ([`trajectory_problems`]), after the run budget, which names its cost first.
        .map(|c| {
            (TRAJECTORY_UPDATE_MARGIN * trajectory_bytes(&c.case, d.max_cycles))
                .min(MAX_DATASET_FILE_BYTES as f64)
        })
        .sum();
    records_bytes(d, setups) + trajectories + FIXED_BYTES
}

/// Estimated bytes of the dataset's records: the largest record's files times the count.
fn records_bytes(d: &DatasetDesign, setups: &[ChainSetup]) -> f64 {
    let plan = plan_of(d);
    let slowest = d.speeds_hz.iter().fold(f64::INFINITY, |a, b| a.min(*b));
    let per_state: f64 = setups
        .iter()
        .zip(&d.conditions)
        .map(|(s, c)| {
            let shaft_hz = tachometer_hz(&c.case, s, slowest);
            let n = s.chain.samples(shaft_hz) as f64;
            let columns = (s.chain.path.sensors.len() + 1) as f64;
            let csv = if d.csv {
                n * (columns + 1.0) * 16.0
            } else {
                0.0
            };
            n * columns * 4.0 + csv + LABEL_BYTES_PER_RECORD
        })
        .fold(0.0, f64::max);
    per_state * plan.records() as f64
}

/// Hash of everything the dataset is generated from.
pub fn dataset_key(d: &DatasetDesign, path_bytes: &[u8]) -> String {
    let cases: Vec<String> = d
        .conditions
        .iter()
        .map(|c| toml::to_string(&c.case).unwrap_or_default())
        .collect();
    key_of_parts(
        &d.text,
        &cases,
        &sha256_hex(path_bytes),
        env!("CARGO_PKG_VERSION"),
    )
}

/// The revision of what a record holds and how its labels are computed, part of every
/// dataset key: a folder made by a build of another revision is another design's (refused
/// as such, not as edited records). 2: indicators computed from the float32 samples as
/// stored, and no limiting stage for a train's new teeth.
const RECORD_REVISION: &str = "records-2";

/// The dataset key of a design's text, its conditions' cases (as TOML), the SHA-256 of
/// its transfer-path file, the program version and [`RECORD_REVISION`].
fn key_of_parts(design: &str, cases: &[String], path_sha256: &str, version: &str) -> String {
    let mut text = design.to_owned();
    for c in cases {
        text.push_str(c);
    }
    text.push_str(path_sha256);
    text.push_str(version);
    text.push_str(RECORD_REVISION);
    sha256_hex(text.as_bytes())
}

/// The key a description's own fields give (its design, cases, transfer-path hash and
/// version), `None` when one is missing: a description whose `dataset_key` is not this
/// was edited (a merge refuses it).
pub fn key_of_description(body: &Value) -> Option<String> {
    let cases: Option<Vec<String>> = body["cases"]
        .as_array()?
        .iter()
        .map(|c| c["case_toml"].as_str().map(str::to_owned))
        .collect();
    Some(key_of_parts(
        body["design"].as_str()?,
        &cases?,
        body["transfer_path_sha256"].as_str()?,
        body["version"].as_str()?,
    ))
}

/// The dataset's description (`state/dataset.json`, the body of metadata.json).
pub(super) fn description(req: &DatasetRequest, setups: &[ChainSetup], key: &str) -> Value {
    let d = req.design;
    let plan = plan_of(d);
    let first = &setups[0].chain;
    let probe = crate::signals::record::Record {
        sampling_rate_hz: first.acquisition.sampling_rate_hz,
        channels: first
            .path
            .sensors
            .iter()
            .map(|s| (s.clone(), Vec::new()))
            .collect(),
        tachometer_v: Vec::new(),
    };
    let mut body = json!({
        "program": "gearwear",
        "version": env!("CARGO_PKG_VERSION"),
        "dataset_key": key,
        "transfer_path_sha256": sha256_hex(&req.path_bytes),
        "design": d.text,
        "seed": d.seed,
        "records": plan.records(),
        "physical_states": plan.physical_states(),
        "axes": {
            "conditions": d.conditions.iter().map(|c| json!({"name": c.name, "fault": c.fault, "severity": c.severity})).collect::<Vec<_>>(),
            "states": match &d.states { StateChoice::Count(n) => json!({"evenly_spaced": n}), StateChoice::Cycles(c) => json!({"cycles": c}) },
            "input_speed_hz": d.speeds_hz,
            "load_torque_nm": d.torques_nm,
            "noise_realisations": d.noise_realisations,
        },
        "record_id": "((((condition x states + state) x speeds + speed) x loads + load) x realisations + realisation)",
        "run_to_failure": {"max_cycles": d.max_cycles, "wear_limit_um": d.wear_limit_um, "failure": "the deepest wear, pinion or gear profile, reaches wear_limit_um"},
        "record": chain_json(first, first.samples(record_shaft_hz(d, &setups[0]))),
        "signal_columns": units(&probe, first.acquisition.unit),
        "cases": d.conditions.iter().map(|c| json!({"condition": c.name, "case_toml": toml::to_string(&c.case).unwrap_or_default()})).collect::<Vec<_>>(),
        "layout": {
            "signals/<record_id>.parquet": "one record: a float32 column per accelerometer and the tachometer; sampling rate and units in the file's key-value metadata",
            "csv/<record_id>.csv": "the same record as CSV with time_s (when the design asks)",
            "records/<record_id>.json": "labels and indicators of one record",
            "index.parquet": "one row per record: labels and indicators (index.csv: the same as CSV)",
            "indicator_trends.csv": "the first channel's indicators along each trajectory (condition x speed x load), mean over the noise realisations of each state",
            "indicator_trends.png": "the same as a figure, against the pinion load cycles (indicator_trends.svg beside or instead of it when the job asks for SVG)",
            "state/": "the dataset's description and run-to-failure trajectories (used by resumes and merges)",
        },
    });
    if !d.conditions[0].case.stage.is_empty() {
        body["run_to_failure"]["failure"] = json!(
            "the deepest wear of any stage's mesh, pinion or gear profile, reaches wear_limit_um"
        );
        body["train"] = train_json(d);
    }
    if d.conditions[0].case.planetary.is_some() {
        super::plan_planetary::planetary_description(&mut body, d);
    }
    body
}

/// What a gear train's dataset states of its trains (`description`): for each condition,
/// each stage's gear data (its `[gear]` keys as the stage resolves them), ratio and
/// pinion revolutions per input revolution, and every mesh frequency at each design
/// speed (turned through the tooth counts as `study::signal_record` turns them); and
/// what a train record's labels mean.
fn train_json(d: &DatasetDesign) -> Value {
    let conditions: Vec<Value> = d
        .conditions
        .iter()
        .map(|c| {
            let case = &c.case;
            let gears: Vec<_> = case
                .stage
                .iter()
                .map(|st| st.gear_section(&case.gear))
                .collect();
            let mut per_input = 1.0;
            let stages: Vec<Value> = gears
                .iter()
                .enumerate()
                .map(|(k, g)| {
                    let v = json!({
                        "stage": k + 1,
                        "gear": g,
                        "ratio": g.teeth_gear as f64 / g.teeth_pinion as f64,
                        "pinion_revolutions_per_input_revolution": per_input,
                    });
                    per_input *= g.teeth_pinion as f64 / g.teeth_gear as f64;
                    v
                })
                .collect();
            let mesh_hz: Vec<Value> = d
                .speeds_hz
                .iter()
                .map(|&f_in| {
                    let mut shaft_hz = f_in;
                    let meshes: Vec<f64> = gears
                        .iter()
                        .map(|g| {
                            let f_m = shaft_hz * g.teeth_pinion as f64;
                            shaft_hz = f_m / g.teeth_gear as f64;
                            f_m
                        })
                        .collect();
                    json!({"input_speed_hz": f_in, "mesh_hz": meshes, "output_shaft_hz": shaft_hz})
                })
                .collect();
            json!({"condition": c.name, "stages": stages, "mesh_frequencies": mesh_hz})
        })
        .collect();
    let first = &d.conditions[0].case;
    json!({
        "conditions": conditions,
        "sensor_stage": first.signals.sensor_stage_index() + 1,
        "labels": "a train's record: `cycles` and `remaining_cycles` are input cycles (stage 1's pinion, the motor's shaft); `max_wear_pinion_um` and `max_wear_gear_um` the deepest of any stage; `mesh_hz` and the TSA indicators' shafts the sensor stage's; each stage's wear, pinion cycles and mesh frequency in `<name>_stage<k>` columns (sidecar: `stages`), the deepest-worn stage in `limiting_stage`",
    })
}

/// The conditions whose kept trajectory would exceed the largest file a dataset folder
/// reads back ([`MAX_DATASET_FILE_BYTES`]): refused before any work (after the run
/// budget), since a resume could never reuse it (`study::budget::trajectory_bytes`).
pub(super) fn trajectory_problems(d: &DatasetDesign) -> Vec<String> {
    let cap = MAX_DATASET_FILE_BYTES as f64;
    d.conditions
        .iter()
        .filter_map(|c| {
            let bytes = trajectory_bytes(&c.case, d.max_cycles);
            (bytes > cap || bytes.is_nan()).then(|| {
                format!(
                    "condition `{}`: its run-to-failure trajectory would take about {:.3e} GiB in state/, more than the {} GiB a dataset folder keeps: lower `run_to_failure.max_cycles` = {}, or raise `wear.block_cycles` or `wear.threshold_um`, or lower `wear.points_per_profile`",
                    c.name,
                    bytes / 1024f64.powi(3),
                    MAX_DATASET_FILE_BYTES >> 30,
                    d.max_cycles
                )
            })
        })
        .collect()
}

/// A request checked before anything is written: the chain of every condition and the
/// estimated size against the disk budget.
pub struct Checked {
    pub(super) setups: Vec<ChainSetup>,
    /// Estimated bytes of the whole dataset ([`estimate_bytes`]), checked against the disk
    /// budget.
    pub estimated_bytes: f64,
    /// The longest record, for the run budget.
    pub record: RecordSize,
}

/// Check `req` (the first step of [`super`]'s).
pub fn check_dataset(req: &DatasetRequest) -> Result<Checked, DatasetError> {
    let d = req.design;
    let setups = setups(req).map_err(DatasetError::Input)?;
    let estimated = estimate_bytes(d, &setups);
    let budget = d.disk_budget_gib * 1024f64.powi(3);
    if estimated > budget {
        return Err(DatasetError::Input(vec![format!(
            "the dataset would take about {:.2} GiB ({} records), more than `records.disk_budget_gib` = {}: raise the budget, or make fewer or shorter records",
            estimated / 1024f64.powi(3),
            plan_of(d).records(),
            d.disk_budget_gib
        )]));
    }
    Ok(Checked {
        record: record_size(d, &setups),
        setups,
        estimated_bytes: estimated,
    })
}
