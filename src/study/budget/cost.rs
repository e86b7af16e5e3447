//! What an estimate is: terms of time and memory, each with the keys that drive it; the
//! budget a run may use; and the check of one against the other, whose message names what
//! drives the cost.

use super::evaluation::SECONDS_PER_STEP;

/// Why a run is over its budget (nothing was computed): each of memory, time and the
/// give-up time of one failing evaluation that exceeds it, with its largest term and the
/// keys that drive it. The remedy (ease those keys, or raise the budget) names arguments
/// of the front ends: the job layer adds it (`app::budget`).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("the run is over its budget (nothing was computed): {}", .over.join("; "))]
pub struct OverBudget {
    /// One message per resource over the budget.
    pub over: Vec<String>,
}

const GIB: f64 = 1024.0 * 1024.0 * 1024.0;
/// Memory of the process before any work, bytes (the base of every estimate's memory):
/// its measured resident size with the model built and nothing computed, 15 MB (peak RSS
/// of `gearwear stiffness` on the built-in case, 2026-11-29; `sweep-merge` 11 MB, the
/// binary alone 4.7 MB), rounded up to 20 MB. It was 64 MB, over three times the
/// measured peak of the smallest runs (issue 33).
pub const BASE_BYTES: f64 = 20e6;

/// CPU seconds of the process's start-up, counted by every estimate
/// ([`Estimate::seconds`]): measured 1.5 ms (`gearwear --version`) and 2.1 ms (`gearwear
/// config --markdown`) with `perf stat` (2026-11-30), counted 2 ms (`super::output`).
pub const START_UP_SECONDS: f64 = 2e-3;

/// How much a run may use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Budget {
    /// Memory the run may use, bytes.
    pub memory_bytes: f64,
    /// Time the run may take, s (on one core of the reference machine).
    pub seconds: f64,
}

impl Budget {
    /// 2 GiB and 10 minutes on one core of the reference machine.
    pub const DEFAULT: Budget = Budget {
        memory_bytes: 2.0 * GIB,
        seconds: 600.0,
    };

    /// The default budget times `factor` (> 0).
    pub fn scaled(factor: f64) -> Budget {
        Budget {
            memory_bytes: Self::DEFAULT.memory_bytes * factor,
            seconds: Self::DEFAULT.seconds * factor,
        }
    }
}

/// One contribution to a run's cost, with the keys that drive it.
#[derive(Debug, Clone, PartialEq)]
pub struct Term {
    /// What the term is, in words (`the exact grid posterior`).
    pub what: &'static str,
    /// Time, s (one core of the reference machine).
    pub seconds: f64,
    /// Memory, bytes.
    pub bytes: f64,
    /// The case keys (or arguments) that drive the term, named in the over-budget message.
    pub keys: &'static [&'static str],
}

/// The estimated cost of a run. See the module docs of each job family for the formulas.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// Integrator steps of one evaluation that settles as expected: S (P_c + P_e).
    pub steps_per_evaluation: f64,
    /// Integrator steps of one evaluation that never settles: S (P_max + P_e).
    pub steps_to_give_up: f64,
    /// Samples one dynamic evaluation records: S_d P_e (a bound).
    pub recorded_samples: f64,
    /// Largest wear per cycle at the nominal load (quasi-static), m; None without a pair.
    pub wear_per_cycle_m: Option<f64>,
    /// Updates (records, the first included) of a dynamic and a quasi-static wear study.
    pub wear_updates_dynamic: f64,
    /// Updates (records, the first included) of a quasi-static wear study.
    pub wear_updates_quasi_static: f64,
    /// The contributions to the cost, each with the keys that drive it.
    pub terms: Vec<Term>,
}

impl Estimate {
    /// An estimate of `terms` alone, for a job that runs no evaluation of its own (its
    /// counts of steps, samples and updates zero).
    pub fn of_terms(terms: Vec<Term>) -> Estimate {
        Estimate {
            steps_per_evaluation: 0.0,
            steps_to_give_up: 0.0,
            recorded_samples: 0.0,
            wear_per_cycle_m: None,
            wear_updates_dynamic: 0.0,
            wear_updates_quasi_static: 0.0,
            terms,
        }
    }

    /// Estimated time, s: the process's start-up ([`START_UP_SECONDS`]) and the terms'.
    pub fn seconds(&self) -> f64 {
        START_UP_SECONDS + self.terms.iter().map(|t| t.seconds).sum::<f64>()
    }

    /// Estimated peak memory, bytes: the process's base ([`BASE_BYTES`]) and the terms'.
    pub fn memory_bytes(&self) -> f64 {
        BASE_BYTES + self.terms.iter().map(|t| t.bytes).sum::<f64>()
    }

    /// Ok, or why the run is over `budget`, naming the keys that drive its cost.
    pub fn check(&self, budget: &Budget) -> Result<(), OverBudget> {
        let give_up = self.steps_to_give_up * SECONDS_PER_STEP;
        let (secs, bytes) = (self.seconds(), self.memory_bytes());
        let mut over = Vec::new();
        // An estimate of no terms (a merge of no readable shard) is the process alone:
        // never over a budget, as before the start-up was counted.
        if bytes > budget.memory_bytes && !self.terms.is_empty() {
            let t = self.largest(|t| t.bytes);
            over.push(format!(
                "memory ~{:.3} GB, over the budget of {:.3} GB; most of it: {} ({:.3} GB), driven by {}",
                bytes / 1e9,
                budget.memory_bytes / 1e9,
                t.what,
                t.bytes / 1e9,
                keys(t.keys)
            ));
        }
        if secs > budget.seconds && !self.terms.is_empty() {
            let t = self.largest(|t| t.seconds);
            over.push(format!(
                "time ~{} on one core of the reference machine, over the budget of {}; most of it: {} ({}), driven by {}",
                duration(secs),
                duration(budget.seconds),
                t.what,
                duration(t.seconds),
                keys(t.keys)
            ));
        }
        if give_up > budget.seconds {
            over.push(format!(
                "one dynamic evaluation that finds no steady state integrates {:.3e} steps (~{}) before giving up, over the budget of {}; driven by `numerics.max_mesh_periods` x `numerics.steps_per_mesh_period`",
                self.steps_to_give_up,
                duration(give_up),
                duration(budget.seconds)
            ));
        }
        if over.is_empty() {
            Ok(())
        } else {
            // The remedy (ease those keys, or raise the budget) names arguments of the
            // front ends: the job layer adds it (`app::budget`).
            Err(OverBudget { over })
        }
    }

    fn largest(&self, f: impl Fn(&Term) -> f64) -> &Term {
        self.terms
            .iter()
            .max_by(|a, b| f(a).total_cmp(&f(b)))
            .expect("an estimate has terms")
    }
}

fn keys(k: &[&str]) -> String {
    k.iter()
        .map(|k| format!("`{k}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// "12 s", "3.4 min", "5.1 h", "7.1 days", "2.0e3 days".
fn duration(s: f64) -> String {
    if s < 120.0 {
        format!("{s:.3} s")
    } else if s < 7200.0 {
        format!("{:.1} min", s / 60.0)
    } else if s < 172_800.0 {
        format!("{:.1} h", s / 3600.0)
    } else if s < 8.64e7 {
        format!("{:.1} days", s / 86_400.0)
    } else {
        format!("{:.1e} days", s / 86_400.0)
    }
}
