//! A sweep held in memory, for callers without an output folder (the Python binding's
//! `sweep`): every case of a plan resolved on a base case and checked before any runs,
//! then run in parallel and collected into a table. `gearwear sweep` puts files,
//! resumption and shards around the same pieces ([`run_case`], [`SweepTable`]).

use super::case_run::{run_case, SweepRun};
use super::plan::SweepPlan;
use super::table::{SweepRow, SweepTable};
use crate::config::{load_case, Case};
use crate::study::Model;
use rayon::prelude::*;

/// One case of a plan, resolved.
#[derive(Debug, Clone)]
pub struct ResolvedCase {
    pub case_id: usize,
    /// Varied values, as given to `--set`.
    pub values: Vec<String>,
    pub case: Case,
}

/// The cases of `plan` on `base`: the base case with each case's overrides, through
/// `load_case` (so a sweep case is exactly the case `--set KEY=value` gives), and each
/// case's model built once to check its geometry. Every problem of every case (naming the
/// case, the key and the value), or the cases in id order.
pub fn resolve_cases(base: &Case, plan: &SweepPlan) -> Result<Vec<ResolvedCase>, Vec<String>> {
    let text = toml::to_string(base).map_err(|e| vec![format!("base case: {e}")])?;
    let keys = plan.keys();
    let what = |id: usize, values: &[String]| {
        let kv: Vec<String> = keys
            .iter()
            .zip(values)
            .map(|(k, v)| format!("{k}={v}"))
            .collect();
        format!("case {id} ({})", kv.join(", "))
    };
    let resolved: Vec<Result<ResolvedCase, Vec<String>>> = (0..plan.len())
        .into_par_iter()
        .map(|id| {
            let values = plan.values_of(id);
            let prefix = |p: &str| format!("{}: {p}", what(id, &values));
            let case = load_case(&text, &plan.overrides_of(id))
                .map_err(|e| e.problems.iter().map(|p| prefix(p)).collect::<Vec<_>>())?;
            Model::from_case(&case)
                .map_err(|e| e.0.iter().map(|p| prefix(p)).collect::<Vec<_>>())?;
            Ok(ResolvedCase {
                case_id: id,
                values,
                case,
            })
        })
        .collect();
    let mut problems = Vec::new();
    let mut cases = Vec::new();
    for r in resolved {
        match r {
            Ok(c) => cases.push(c),
            Err(p) => problems.extend(p),
        }
    }
    if problems.is_empty() {
        Ok(cases)
    } else {
        Err(problems)
    }
}

/// What a sweep left: the table of the cases that ran, and why the others did not.
#[derive(Debug, Clone, Default)]
pub struct SweepOutcome {
    pub table: SweepTable,
    /// (case id, values, error) of each case without a row.
    pub failed: Vec<(usize, Vec<String>, String)>,
    /// The models' warnings, each once.
    pub warnings: Vec<String>,
}

/// Run `cases` in parallel (rayon). `keep_going()` is asked before each case: once it
/// says no, the cases not yet started are skipped (listed as failed, "stopped").
/// `on_case()` is called after each case that ran.
pub fn run_cases(
    cases: &[ResolvedCase],
    keys: Vec<String>,
    run: SweepRun,
    keep_going: &(dyn Fn() -> bool + Sync),
    on_case: &(dyn Fn() + Sync),
) -> SweepOutcome {
    let outcomes: Vec<_> = cases
        .par_iter()
        .map(|c| {
            if !keep_going() {
                return Err("stopped before it ran".to_owned());
            }
            let r = run_case(&c.case, run).map_err(|e| e.to_string());
            on_case();
            r
        })
        .collect();
    let mut out = SweepOutcome {
        table: SweepTable {
            keys,
            columns: run.columns(),
            rows: Vec::new(),
        },
        ..Default::default()
    };
    for (c, r) in cases.iter().zip(outcomes) {
        match r {
            Ok(o) => {
                for w in o.warnings {
                    if !out.warnings.contains(&w) {
                        out.warnings.push(w);
                    }
                }
                out.table.rows.push(SweepRow {
                    case_id: c.case_id,
                    values: c.values.clone(),
                    results: o.results,
                    branch: None,
                });
            }
            Err(e) => out.failed.push((c.case_id, c.values.clone(), e)),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::sweep::parse_vary;

    #[test]
    fn bad_values_are_all_reported_before_anything_runs() {
        let plan = SweepPlan::new(vec![
            parse_vary("operating.input_speed_hz=-1,30").unwrap(),
            parse_vary("gear.module_mm=2,-3").unwrap(),
        ])
        .unwrap();
        let e = resolve_cases(&Case::default(), &plan).unwrap_err();
        // Cases 0 (-1 Hz, 2 mm), 1 (-1 Hz, -3 mm: two problems) and 3 (30 Hz, -3 mm).
        assert_eq!(e.len(), 4, "{e:?}");
        assert!(e[0].starts_with("case 0 (operating.input_speed_hz=-1, gear.module_mm=2)"));
        assert!(e.iter().all(|p| p.contains('`')), "{e:?}");
    }

    #[test]
    fn cases_resolve_as_set_overrides_do() {
        let plan =
            SweepPlan::new(vec![parse_vary("operating.input_speed_hz=20:30:5").unwrap()]).unwrap();
        let cases = resolve_cases(&Case::default(), &plan).unwrap();
        let speeds: Vec<f64> = cases
            .iter()
            .map(|c| c.case.operating.input_speed_hz)
            .collect();
        assert_eq!(speeds, vec![20.0, 25.0, 30.0]);
        let direct = load_case("", &["operating.input_speed_hz=25".into()]).unwrap();
        assert_eq!(cases[1].case, direct);
    }

    #[test]
    fn a_stopped_sweep_runs_nothing() {
        let plan =
            SweepPlan::new(vec![parse_vary("operating.input_speed_hz=20,30").unwrap()]).unwrap();
        let cases = resolve_cases(&Case::default(), &plan).unwrap();
        let out = run_cases(&cases, plan.keys(), SweepRun::Dynamics, &|| false, &|| {});
        assert!(out.table.rows.is_empty());
        assert_eq!(out.failed.len(), 2);
    }
}
