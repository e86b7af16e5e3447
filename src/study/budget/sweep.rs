//! The cost of a sweep, estimated without resolving every case (a few sampled values of
//! each axis), and of `sweep-merge`.

use super::case_jobs::{estimate, Job};
use super::cost::{Estimate, Term, BASE_BYTES};
use crate::config::case::Case;
use crate::config::load::case_with;
use crate::study::sweep::plan::{AxisValue, SweepPlan};

/// Values of an axis at which a sweep's cost is sampled: the first and last, the
/// numerically smallest and largest, and up to [`SAMPLED_VALUES`] spread between, so that
/// estimating a sweep costs milliseconds however many values an axis has.
pub const SAMPLED_VALUES: usize = 8;

fn sampled_indices(values: &[AxisValue]) -> Vec<usize> {
    let n = values.len();
    if n == 0 {
        return Vec::new();
    }
    let mut idx: std::collections::BTreeSet<usize> = (0..SAMPLED_VALUES.min(n))
        .map(|i| i * (n - 1) / (SAMPLED_VALUES - 1).max(1))
        .collect();
    idx.insert(n - 1);
    let num = |v: &AxisValue| {
        v.value
            .as_float()
            .or_else(|| v.value.as_integer().map(|i| i as f64))
    };
    let numbered: Vec<(usize, f64)> = (0..n)
        .filter_map(|i| num(&values[i]).map(|x| (i, x)))
        .collect();
    if let Some(lo) = numbered.iter().min_by(|a, b| a.1.total_cmp(&b.1)) {
        idx.insert(lo.0);
    }
    if let Some(hi) = numbered.iter().max_by(|a, b| a.1.total_cmp(&b.1)) {
        idx.insert(hi.0);
    }
    idx.into_iter().collect()
}

/// The estimated cost of `sweep-merge` of tables of `bytes` in all: the text, the rows
/// parsed (their values as text and numbers) and the merged table's CSV, about four times
/// the text.
pub fn estimate_sweep_merge(bytes: u64) -> Estimate {
    Estimate::of_terms(vec![Term {
        what: "the tables read and merged",
        seconds: bytes as f64 * 2e-8,
        bytes: 4.0 * bytes as f64,
        keys: &["the size of the tables merged"],
    }])
}

/// Memory a sweep holds per case besides the cases in flight: the resolved case, its
/// record and its row, bytes.
pub const BYTES_PER_SWEEP_CASE: f64 = 16e3;

/// What a sweep's estimate found.
#[derive(Debug, Clone)]
pub(crate) struct SweepEstimate {
    /// The sweep as one job: every case of the shard, one after the other (time), and the
    /// cases in flight on `threads` threads plus the records (memory).
    pub total: Estimate,
    /// One case with every axis at its costliest sampled value, and its overrides.
    pub worst_case: Estimate,
    pub worst_overrides: Vec<String>,
}

/// Estimate a sweep of `cases` cases (those of its shard) over `axes` (key, values) on
/// `threads` threads without resolving every case: `load(overrides)` gives the case of a
/// set of overrides (None when it does not load: the sweep reports those itself). The
/// cost per case is sampled at a few values of each axis (the others at the base case);
/// the total is the base cost times, per axis, the mean ratio of its sampled values to the
/// base (exact when the cost does not depend on a varied key, and when it is a product of
/// per-axis factors); the worst case puts every axis at its costliest sampled value. The
/// sweep's figures (`continuation`: it follows branches) are counted with the total, each
/// as it is drawn (`super::figures::sweep_figures`); a case draws none.
pub(crate) fn estimate_sweep(
    base: &Case,
    plan: &SweepPlan,
    (job, continuation): (Job, bool),
    cases: usize,
    threads: usize,
) -> Option<SweepEstimate> {
    let load = |settings: &[(&str, toml::Value)]| case_with(base, settings).ok();
    let base_e = estimate(&load(&[])?, job);
    let (base_s, base_b) = (base_e.seconds().max(1e-9), base_e.memory_bytes());
    let mut ratio = 1.0;
    let mut worst: Vec<(&str, toml::Value)> = Vec::new();
    let mut worst_overrides = Vec::new();
    for axis in &plan.axes {
        let mut sum = 0.0;
        let mut n = 0.0;
        let mut costliest: Option<(f64, usize)> = None;
        for i in sampled_indices(&axis.values) {
            let Some(c) = load(&[(axis.key.as_str(), axis.values[i].value.clone())]) else {
                continue;
            };
            let e = estimate(&c, job);
            let cost = e.seconds() / base_s + e.memory_bytes() / base_b;
            sum += e.seconds() / base_s;
            n += 1.0;
            if costliest.as_ref().is_none_or(|(c0, _)| cost > *c0) {
                costliest = Some((cost, i));
            }
        }
        if n > 0.0 {
            ratio *= sum / n;
        }
        if let Some((_, i)) = costliest {
            worst.push((axis.key.as_str(), axis.values[i].value.clone()));
            worst_overrides.push(format!("{}={}", axis.key, axis.values[i].label));
        }
    }
    let worst_case = estimate(&load(&worst).or_else(|| load(&[]))?, job);
    let cases_f = cases as f64;
    let in_flight = (threads.max(1) as f64).min(cases_f);
    let total = Estimate {
        terms: vec![
            Term {
                what: "the sweep's cases, one after the other",
                seconds: cases_f * base_s * ratio,
                bytes: 0.0,
                keys: &["the number of cases of the shard", "the varied keys"],
            },
            Term {
                what: "the cases in flight, and every case's record",
                seconds: 0.0,
                bytes: in_flight * (worst_case.memory_bytes() - BASE_BYTES)
                    + cases_f * BYTES_PER_SWEEP_CASE,
                keys: &["the number of cases of the shard", "the varied keys"],
            },
        ],
        steps_to_give_up: worst_case.steps_to_give_up,
        ..worst_case.clone()
    }
    .drawing(super::figures::sweep_figures(base, plan, continuation));
    Some(SweepEstimate {
        total,
        worst_case,
        worst_overrides,
    })
}
