//! Continuation along one parameter: run a one-axis sweep in order, each point started
//! from the periodic state the previous point ended in, so that the sweep follows one
//! solution branch.
//!
//! Where two stable periodic solutions coexist (the softening, contact-loss resonance of a
//! spur pair: Kahraman & Blankenship, J. Appl. Mech. 64 (1997) 217), a sweep of rising
//! speed stays on the large-amplitude branch up to its end and then jumps down, a sweep
//! of falling speed stays on the small-amplitude branch and jumps up elsewhere: the two
//! branches differ between the jumps (hysteresis). Every point of an ordinary sweep starts
//! from the static equilibrium instead, and lands on whichever solution attracts it.
//!
//! Choices: the branches are independent (each starts at its first value from the static
//! equilibrium), so `both` runs them side by side; a point that fails is recorded as
//! failed and the next one starts from the last point that succeeded.

use super::case_run::{run_dynamics_from, CaseError, CaseOutcome};
use super::plan::SweepPlan;
use crate::config::Case;
use crate::remedy::{Arg, Problem, Words};
use serde::{Deserialize, Serialize};

/// Direction of a branch along the varied parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Branch {
    /// Rising values.
    Up,
    /// Falling values.
    Down,
}

impl Branch {
    /// `up` or `down` (the `branch` column of the sweep table).
    pub fn name(&self) -> &'static str {
        match self {
            Branch::Up => "up",
            Branch::Down => "down",
        }
    }

    /// The branch named `up` or `down`.
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "up" => Some(Branch::Up),
            "down" => Some(Branch::Down),
            _ => None,
        }
    }
}

/// Which branches a continuation sweep runs (`--continuation up|down|both`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Continuation {
    /// The rising branch only.
    Up,
    /// The falling branch only.
    Down,
    /// Both branches, rising first.
    Both,
}

impl Continuation {
    /// The branches run, in order.
    pub fn branches(&self) -> Vec<Branch> {
        match self {
            Continuation::Up => vec![Branch::Up],
            Continuation::Down => vec![Branch::Down],
            Continuation::Both => vec![Branch::Up, Branch::Down],
        }
    }
}

/// One point of a branch: its case id and the index of its value on the sweep's axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BranchPoint {
    /// The point's case id.
    pub case_id: usize,
    /// Index of its value on the axis, in the order given.
    pub value_index: usize,
}

/// The points of each branch in run order. Case ids number the points in that order,
/// branch after branch (`up` first), so the sweep table lists each branch as it ran.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ContinuationPlan {
    /// Each branch and its points, in run order.
    pub branches: Vec<(Branch, Vec<BranchPoint>)>,
}

impl ContinuationPlan {
    /// Order the single axis of `plan` by its numeric values. Errors: more than one axis,
    /// or a value that is not a finite number (named).
    pub fn new(plan: &SweepPlan, c: Continuation) -> Result<Self, Problem> {
        let [axis] = &plan.axes[..] else {
            return Err(Problem::of(
                Arg::Continuation,
                Words::new()
                    .text("a continuation follows one parameter: give exactly one ")
                    .arg(Arg::Vary)
                    .text(format!(
                        " (got {}: {})",
                        plan.axes.len(),
                        plan.keys().join(", ")
                    )),
            ));
        };
        let mut numbers = Vec::with_capacity(axis.values.len());
        for v in &axis.values {
            match v.as_number() {
                Some(x) => numbers.push(x),
                None => {
                    return Err(Problem::given(
                        Arg::Vary,
                        &axis.key,
                        format!(
                            "value `{}` is not a number (a continuation follows a branch along a numeric parameter)",
                            v.label
                        ),
                    ))
                }
            }
        }
        let mut rising: Vec<usize> = (0..numbers.len()).collect();
        rising.sort_by(|a, b| numbers[*a].total_cmp(&numbers[*b]));
        let mut next_id = 0;
        let branches = c
            .branches()
            .into_iter()
            .map(|b| {
                let order: Vec<usize> = match b {
                    Branch::Up => rising.clone(),
                    Branch::Down => rising.iter().rev().copied().collect(),
                };
                let points = order
                    .into_iter()
                    .map(|value_index| {
                        next_id += 1;
                        BranchPoint {
                            case_id: next_id - 1,
                            value_index,
                        }
                    })
                    .collect();
                (b, points)
            })
            .collect();
        Ok(Self { branches })
    }

    /// Number of points over all branches.
    pub fn len(&self) -> usize {
        self.branches.iter().map(|(_, p)| p.len()).sum()
    }

    /// Whether the plan has no point.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// A periodic state at a mesh-period boundary (`DynamicResponse::end_state`).
pub type PeriodicState = Vec<f64>;

/// Resume lookup of [`run_branch`]: the end state of point `case_id` if it was already
/// computed from exactly the start state given.
pub(crate) type FinishedLookup<'a> = dyn Fn(usize, Option<&[f64]>) -> Option<PeriodicState> + 'a;

/// Resume lookup of [`run_continuation`], per branch.
pub(crate) type BranchFinishedLookup<'a> =
    dyn Fn(Branch, usize, Option<&[f64]>) -> Option<PeriodicState> + Sync + 'a;

/// What happened at one point of a branch.
pub enum PointRun {
    /// Finished in an earlier run from the same start state (resume): its end state.
    Finished {
        /// The state the point ended in.
        end_state: Vec<f64>,
    },
    /// Computed now from `start` (`None`: the static equilibrium).
    Computed {
        /// The state it started from (`None`: the static equilibrium).
        start: Option<Vec<f64>>,
        /// The case's results and warnings.
        outcome: Box<CaseOutcome>,
        /// The state it ended in (the next point's start).
        end_state: Vec<f64>,
    },
    /// The solver failed (or the case could not be modelled) from `start`.
    Failed {
        /// The state it started from (`None`: the static equilibrium).
        start: Option<Vec<f64>>,
        /// Why it failed.
        error: CaseError,
    },
}

/// Run the points of one branch in order: each starts from the end state of the last
/// point that succeeded before it (the first from the static equilibrium).
///
/// `finished(case_id, start)` returns the end state of a point already computed from
/// exactly this start (so a resumed branch follows the same path, bit for bit, as an
/// uninterrupted one); `report(case_id, run)` receives every point, in order.
pub(crate) fn run_branch(
    points: &[(usize, &Case)],
    finished: &FinishedLookup,
    report: &mut dyn FnMut(usize, PointRun),
    keep_going: &dyn Fn() -> bool,
) {
    let mut start: Option<Vec<f64>> = None;
    for &(case_id, case) in points {
        if !keep_going() {
            return;
        }
        if let Some(end_state) = finished(case_id, start.as_deref()) {
            start = Some(end_state.clone());
            report(case_id, PointRun::Finished { end_state });
            continue;
        }
        match run_dynamics_from(case, start.as_deref()) {
            Ok((outcome, end_state)) => {
                let from = start.take();
                start = Some(end_state.clone());
                report(
                    case_id,
                    PointRun::Computed {
                        start: from,
                        outcome: Box::new(outcome),
                        end_state,
                    },
                );
            }
            Err(error) => report(
                case_id,
                PointRun::Failed {
                    start: start.clone(),
                    error,
                },
            ),
        }
    }
}

/// Run every branch of `plan` (side by side on the rayon pool), `cases[i]` being the
/// resolved case of value `i` of the axis. `finished(branch, case_id, start)` and
/// `report(branch, case_id, run)` as in [`run_branch`]; a branch stops before its next
/// point once `keep_going()` says no.
pub(crate) fn run_continuation(
    plan: &ContinuationPlan,
    cases: &[Case],
    finished: &BranchFinishedLookup,
    report: &(dyn Fn(Branch, usize, PointRun) + Sync),
    keep_going: &(dyn Fn() -> bool + Sync),
) {
    use rayon::prelude::*;
    plan.branches.par_iter().for_each(|(branch, points)| {
        let points: Vec<(usize, &Case)> = points
            .iter()
            .filter_map(|p| cases.get(p.value_index).map(|c| (p.case_id, c)))
            .collect();
        run_branch(
            &points,
            &|id, start| finished(*branch, id, start),
            &mut |id, run| report(*branch, id, run),
            keep_going,
        );
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::sweep::parse_vary;

    #[test]
    fn branches_run_in_numeric_order_with_sequential_ids() {
        let plan = SweepPlan::new(vec![
            parse_vary("operating.input_speed_hz=50,40,45").unwrap()
        ])
        .unwrap();
        let c = ContinuationPlan::new(&plan, Continuation::Both).unwrap();
        let (up, down) = (&c.branches[0], &c.branches[1]);
        assert_eq!((up.0, down.0), (Branch::Up, Branch::Down));
        let idx = |p: &[BranchPoint]| p.iter().map(|x| x.value_index).collect::<Vec<_>>();
        let ids = |p: &[BranchPoint]| p.iter().map(|x| x.case_id).collect::<Vec<_>>();
        // Values 50, 40, 45: rising is 40 (1), 45 (2), 50 (0).
        assert_eq!(idx(&up.1), vec![1, 2, 0]);
        assert_eq!(idx(&down.1), vec![0, 2, 1]);
        assert_eq!(ids(&up.1), vec![0, 1, 2]);
        assert_eq!(ids(&down.1), vec![3, 4, 5]);
        assert_eq!(c.len(), 6);
        let d = ContinuationPlan::new(&plan, Continuation::Down).unwrap();
        assert_eq!(ids(&d.branches[0].1), vec![0, 1, 2]);
    }

    #[test]
    fn two_axes_or_words_are_refused() {
        let two = SweepPlan::new(vec![
            parse_vary("operating.input_speed_hz=40,50").unwrap(),
            parse_vary("operating.load_torque_nm=40,60").unwrap(),
        ])
        .unwrap();
        let e = ContinuationPlan::new(&two, Continuation::Up).unwrap_err();
        assert_eq!(e.arg, Some(Arg::Continuation));
        assert!(e.to_string().contains("exactly one sweep axis"), "{e}");
        let words =
            SweepPlan::new(vec![parse_vary("friction.model=none,xu2007").unwrap()]).unwrap();
        let e = ContinuationPlan::new(&words, Continuation::Up)
            .unwrap_err()
            .to_string();
        assert!(e.contains("`none`") && e.contains("friction.model"), "{e}");
    }
}
