//! The checks of a dataset's study design that name a key and its valid range: the
//! trajectories' length and failure limit, `[records]`, a condition's labels, settings a
//! dataset cannot honour, and one acquisition chain for every condition.

use super::design_file::{Condition, ConditionFile, RecordsFile, StateChoice};
use crate::config::Case;
use toml::Table;

/// Problems of the trajectories' length and failure limit: `max_cycles` in range and
/// beyond the last recorded state, `wear_limit_um` in range.
pub(super) fn run_to_failure_problems(
    states: &StateChoice,
    max_cycles: f64,
    wear_limit_um: f64,
    key: &dyn Fn(&str) -> String,
) -> Vec<String> {
    let mut p = Vec::new();
    if !(1.0..=1e11).contains(&max_cycles) {
        p.push(format!(
            "{} = {max_cycles} is invalid: expected a number in [1, 1e11]",
            key("run_to_failure.max_cycles")
        ));
    }
    if let StateChoice::Cycles(c) = states {
        if c.last().is_some_and(|l| *l > max_cycles) {
            p.push(format!(
                "{} ends at {} cycles, beyond `run_to_failure.max_cycles` = {max_cycles}",
                key("run_to_failure.cycles"),
                c[c.len() - 1]
            ));
        }
    }
    if !(wear_limit_um > 0.0 && wear_limit_um <= 1000.0) {
        p.push(format!(
            "{} = {wear_limit_um} is invalid: expected a number in (0, 1000]",
            key("run_to_failure.wear_limit_um")
        ));
    }
    p
}

/// Problems of `[records]`: the noise realisations and the disk budget out of range.
pub(super) fn records_problems(rec: &RecordsFile, key: &dyn Fn(&str) -> String) -> Vec<String> {
    let mut p = Vec::new();
    if !(1..=1_000_000).contains(&rec.noise_realisations) {
        p.push(format!(
            "{} = {} is invalid: expected a whole number in [1, 1000000]",
            key("records.noise_realisations"),
            rec.noise_realisations
        ));
    }
    if !(rec.disk_budget_gib > 0.0 && rec.disk_budget_gib <= 1e6) {
        p.push(format!(
            "{} = {} is invalid: expected a number in (0, 1e6]",
            key("records.disk_budget_gib"),
            rec.disk_budget_gib
        ));
    }
    p
}

/// Problems of a condition's `fault` and `severity` against what its case models
/// (`label`): a label the case does not model (a "crack" with no crack, a misspelt or
/// free-text label), a severity with no fault, a negative severity.
pub(super) fn label_problems(c: &ConditionFile, label: &str, at: &str) -> Vec<String> {
    let mut p = Vec::new();
    if let Some(given) = &c.fault {
        if given != label {
            p.push(format!(
                "{at}: `fault` = {given:?} is not what the condition's case models ({label:?}): the label is derived from the case's `[[fault]]` (or a planetary set's `[[planetary.fault]]`) tables (\"crack\", \"spall\", \"broken_tip\") and `[teeth]` errors (\"tooth_errors\"), \"none\" without either; give `fault = {label:?}` or leave it out"
            ));
        }
    }
    match (label, c.severity) {
        (_, Some(s)) if !s.is_finite() => {
            p.push(format!("{at}: `severity` = {s} must be a finite number"))
        }
        ("none", Some(s)) if s != 0.0 => p.push(format!(
            "{at}: `severity` = {s} but the condition's case models no fault: a severity needs a `[[fault]]` table (a set's `[[planetary.fault]]`) or `[teeth]` errors in `[condition.case]` (or leave it out: 0)"
        )),
        ("none", _) => {}
        (_, Some(s)) if s < 0.0 => p.push(format!(
            "{at}: `severity` = {s} is invalid for a condition that models {label:?}: expected a number >= 0 (your grade of the fault; absent: 0, ungraded)"
        )),
        _ => {}
    }
    p
}

/// Problems of settings a dataset cannot honour: its records are steady states (each
/// state at its speed and load), so a run-up or a torque fluctuation would be recorded as
/// if used while the records ignore it.
pub(super) fn steady_problems(case: &Case, at: &str) -> Vec<String> {
    let s = &case.signals;
    let mut p = Vec::new();
    if let Some(v) = s.ramp_end_speed_hz {
        p.push(format!(
            "{at}: `signals.ramp_end_speed_hz` = {v} asks for a run-up, but a dataset records steady states (each at its speed and load): remove it (the `signals` command records a run-up), or record several speeds with `operating.input_speed_hz`"
        ));
    }
    if s.torque_fluctuation_rms_nm > 0.0 {
        p.push(format!(
            "{at}: `signals.torque_fluctuation_rms_nm` = {} asks for a fluctuating load, but a dataset records steady states: set it to 0 (the `signals` command records a fluctuating load), or record several loads with `operating.load_torque_nm`",
            s.torque_fluctuation_rms_nm
        ));
    }
    p
}

/// Problems of conditions whose acquisition chain (`[signals]`, the noise seed apart: each
/// record has its own) differs from the first condition's: an index column has one unit
/// and the metadata one chain for every record, so the chain is the dataset's, not a
/// condition's.
pub(super) fn chain_problems(conditions: &[Condition], name: &str) -> Vec<String> {
    let table = |c: &Condition| -> Table {
        let mut s = c.case.signals.clone();
        s.noise_seed = 0;
        Table::try_from(s).unwrap_or_default()
    };
    let Some(first) = conditions.first() else {
        return Vec::new();
    };
    let t0 = table(first);
    let mut p = Vec::new();
    for c in &conditions[1..] {
        let t = table(c);
        let keys: Vec<String> = t0
            .keys()
            .chain(t.keys())
            .filter(|k| t0.get(*k) != t.get(*k))
            .map(|k| format!("`signals.{k}`"))
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        if !keys.is_empty() {
            p.push(format!(
                "{name}: condition `{}` changes the acquisition chain ({}) from condition `{}`'s: every record of a dataset shares one chain (one unit per index column, one sampling rate in the metadata); set it in the design's `case` or `set`",
                c.name,
                keys.join(", "),
                first.name
            ));
        }
    }
    p
}

/// Problems of conditions whose case is a gear train of another number of stages than
/// the first condition's (a single pair counts 0): the index has one set of columns,
/// each stage's wear among them (`index::STAGE_COLUMNS`).
pub(super) fn train_problems(conditions: &[Condition], name: &str) -> Vec<String> {
    let Some(first) = conditions.first() else {
        return Vec::new();
    };
    let stages = |c: &Condition| c.case.stage.len();
    let spelled = |n: usize| match n {
        0 => "a single pair".to_owned(),
        1 => "a train of 1 stage".to_owned(),
        n => format!("a train of {n} stages"),
    };
    conditions[1..]
        .iter()
        .filter(|c| stages(c) != stages(first))
        .map(|c| {
            format!(
                "{name}: condition `{}` is {} ([[stage]] tables) but condition `{}` is {}: every record of a dataset has the same wear columns, one per stage; give every condition the same stages",
                c.name,
                spelled(stages(c)),
                first.name,
                spelled(stages(first))
            )
        })
        .collect()
}
