//! The cases of a sweep, resolved and checked before any runs: every value of every axis
//! on the base case (a bad value is named once, with its key), every case of the shard
//! (its resolved case and hash), the budget of each, and the model of each case still to
//! run. Every problem is reported at once.

use super::super::{budget, JobError};
use crate::config::case::is_per_tooth_key;
use crate::config::load::case_with;
use crate::config::Case;
use crate::remedy::{Arg, Problem};
use crate::store::RunMetadata;
use crate::study::budget::{Budget, Job as Cost};
use crate::study::sweep::{SweepPlan, SweepRun};
use rayon::prelude::*;

/// One case of the shard, resolved and validated.
pub struct Planned {
    pub id: usize,
    /// Labels of its values, one per axis.
    pub labels: Vec<String>,
    pub case: Case,
    /// SHA-256 of the resolved case (`RunMetadata::case_sha256`).
    pub hash: String,
}

/// Every value of every axis set on the base case alone, so a bad value is reported
/// (key and value named) before anything runs, once however many cases share it.
pub fn check_values(base: &Case, plan: &SweepPlan) -> Result<(), JobError> {
    let mut problems = Vec::new();
    for axis in &plan.axes {
        for v in &axis.values {
            if let Err(e) = case_with(base, &[(axis.key.as_str(), v.value.clone())]) {
                problems.extend(e.problems.into_iter().map(|p| {
                    Problem::given(Arg::Vary, &axis.key, p)
                        .in_context(&format!("value `{}`: ", v.label))
                }));
            }
        }
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(JobError::Input(problems))
    }
}

/// The cases `ids` (case id, index in the plan) resolved, each within the budget.
pub fn resolve(
    base: &Case,
    plan: &SweepPlan,
    ids: &[(usize, usize)],
    run: SweepRun,
    limit: Option<&Budget>,
) -> Result<Vec<Planned>, JobError> {
    // The rows are compared with each other: one load-sharing law for all of them,
    // decided from the plan so that every shard decides alike.
    let any_per_tooth =
        base.has_per_tooth_inputs() || plan.axes.iter().any(|a| is_per_tooth_key(&a.key));
    let resolved: Vec<Result<Planned, Problem>> = ids
        .par_iter()
        .map(|&(id, index)| {
            let what = || format!("case {id} ({})", plan.describe(index));
            let mut case = case_with(base, &plan.settings_of(index)).map_err(|e| {
                let list: Vec<String> = e.problems.iter().map(|p| p.to_string()).collect();
                Problem::new(format!("{}: {}", what(), list.join("; ")))
            })?;
            case.share_one_law(any_per_tooth);
            let hash = RunMetadata::new("sweep", &case).case_sha256;
            Ok(Planned {
                id,
                labels: plan.labels_of(index),
                case,
                hash,
            })
        })
        .collect();
    let (ok, bad): (Vec<_>, Vec<_>) = resolved.into_iter().partition(Result::is_ok);
    if !bad.is_empty() {
        return Err(JobError::Input(
            bad.into_iter().filter_map(Result::err).collect(),
        ));
    }
    let planned: Vec<Planned> = ok.into_iter().filter_map(Result::ok).collect();
    // A helical pair's planar model refuses what it cannot take
    // (`super::helical::refusal`): refused here, before any case runs, rather than as
    // failed cases. A planetary set's checks are its own (`super::planetary`).
    let helical: Vec<Problem> = planned
        .iter()
        .filter(|p| p.case.gear.helix_angle_deg != 0.0 && p.case.planetary.is_none())
        .filter_map(|p| {
            let first = super::helical::refusal(&p.case, run)?;
            Some(Problem::new(first).in_context(&format!(
                "case {} ({}): ",
                p.id,
                describe(plan, p)
            )))
        })
        .take(10)
        .collect();
    if !helical.is_empty() {
        return Err(JobError::Input(helical));
    }
    // Every case of a gear train has the base's stages (its row's columns are per mesh).
    // Each case against the budget (the number of cases is the user's explicit choice).
    check_stage_counts(base, plan, &planned)?;
    let named: Vec<(String, &Case)> = planned
        .iter()
        .map(|p| (format!("case {} ({})", p.id, describe(plan, p)), &p.case))
        .collect();
    super::planetary::check_planetary(base, &named)?;
    let over: Vec<Problem> = planned
        .iter()
        .filter_map(|p| {
            let e = budget::check(&p.case, Cost::SweepCase(run), limit).err()?;
            let JobError::Input(mut problems) = e else {
                return None;
            };
            let first = problems.pop()?;
            Some(first.in_context(&format!("case {} ({}): ", p.id, describe(plan, p))))
        })
        .take(10)
        .collect();
    if !over.is_empty() {
        return Err(JobError::Input(over));
    }
    Ok(planned)
}

/// "KEY=label, ..." of a planned case.
/// Every case must have the base case's number of `[[stage]]` tables: the table's columns
/// (one set per mesh) and a continuation's state are those of one train. A varied
/// `stage.KEY` (without a table number) on a single pair makes each case a one-stage
/// train: refused, naming the key.
fn check_stage_counts(base: &Case, plan: &SweepPlan, planned: &[Planned]) -> Result<(), JobError> {
    let n = base.stage.len();
    let Some(p) = planned.iter().find(|p| p.case.stage.len() != n) else {
        return Ok(());
    };
    let keys: Vec<String> = plan
        .keys()
        .into_iter()
        .filter(|k| k.starts_with("stage."))
        .collect();
    Err(JobError::input(Problem::new(format!(
        "case {} ({}) has {} [[stage]] table(s), the base case {n}: the varied key(s) [{}] change the number of stages, and a sweep's columns are those of one train (vary stage.N.KEY of a case file with its [[stage]] tables)",
        p.id,
        describe(plan, p),
        p.case.stage.len(),
        keys.join(", ")
    ))))
}

pub fn describe(plan: &SweepPlan, p: &Planned) -> String {
    plan.keys()
        .iter()
        .zip(&p.labels)
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The models of the cases still to run build (geometry, settings), or every problem.
pub fn check_models(plan: &SweepPlan, pending: &[&Planned], run: SweepRun) -> Result<(), JobError> {
    let problems: Vec<Problem> = pending
        .par_iter()
        .filter_map(|p| {
            super::planetary::model_error(&p.case, run)
                .map(|e| Problem::new(format!("case {} ({}): {e}", p.id, describe(plan, p))))
        })
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(JobError::Input(problems))
    }
}
