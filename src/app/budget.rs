//! The run budget in every job: a job over its budget is refused before anything is
//! computed, naming the keys that drive the cost and how to raise the budget (the remedy,
//! worded with the front ends' arguments, is added here, at the application's edge). The
//! cost model itself, one module per job family, is `study::budget`. A job takes the
//! budget as `Option<Budget>`: `None` runs without the check, a scaled [`Budget`] raises
//! it knowingly.

use super::JobError;
use crate::config::Case;
use crate::remedy::{Arg, Problem, Remedy, Words};
use crate::study::budget::{estimate, Budget, FigureLoad, Job};

/// The budget a front end passes by default.
pub const DEFAULT: Option<Budget> = Some(Budget::DEFAULT);

/// `budget` with the job's PNG figures counted at the size `figures` asks for
/// (`study::budget::FigureLoad`: the tallest figure's raster on each thread, every figure
/// the job draws in time, `study::budget::figures`; issue 33: a
/// figure size of 8192 x 4096 took 0.26 GB against 0.020 GB estimated). Nothing is added
/// at the default size, for SVG alone, or for options the job refuses when it resolves
/// them (before any work).
pub fn with_figures(
    budget: Option<Budget>,
    figures: &crate::report::figure_output::FigureRequest,
) -> Option<Budget> {
    use crate::report::figure_output::{PLOT_H, PLOT_W};
    let load = match figures.resolve() {
        Ok(out) if out.png => out.size_px.map(|size| {
            FigureLoad::at_size(
                size,
                (PLOT_W, PLOT_H),
                crate::report::plot::MAX_SIDE_PX,
                rayon::current_num_threads(),
            )
        }),
        _ => None,
    };
    budget.map(|b| b.with_figures(load.unwrap_or(FigureLoad::NONE)))
}

/// The remedy of a run over budget.
pub fn over_budget(message: impl std::fmt::Display) -> Problem {
    Problem::new(message.to_string()).remedy(Remedy::new(
        Words::new()
            .text("ease those keys (lower a length, count or rate; raise a speed), or raise the budget knowingly with ")
            .arg(Arg::BudgetScale)
            .text(" X (or drop the check with ")
            .arg(Arg::NoBudget)
            .text(")"),
    ))
}

/// Refuse `job` on `case` if it is over `budget` (`None`: no check).
/// Under a load spectrum, a bin the model refuses (a load beyond the flanks, a speed out
/// of range) is named rather than priced: the estimate of such a bin is meaningless (a
/// wear rate from a load the flanks cannot carry), so the wear and run jobs, which run
/// every bin, build the bins' models when their estimate is over the budget and return
/// the bins' problems when there are any (a spur or helical pair, a train; a planetary
/// set's bins are its own job's).
pub fn check(case: &Case, job: Job, budget: Option<&Budget>) -> Result<(), JobError> {
    let runs_bins = matches!(job, Job::Wear { .. } | Job::Run)
        && case.load_spectrum.is_some()
        && case.planetary.is_none();
    match budget {
        Some(b) => estimate(case, job).check(b).map_err(|m| {
            if runs_bins {
                if let Err(e) = crate::duty::SpectrumModel::dynamics_from_case(case) {
                    return JobError::from(e);
                }
            }
            JobError::input(over_budget(m))
        }),
        None => Ok(()),
    }
}

/// Refuse a job whose estimate, made once its inputs are read (observations, posterior,
/// shards, tables), is over `budget` (`None`: no check).
pub fn check_estimate(
    e: &crate::study::budget::Estimate,
    budget: Option<&Budget>,
) -> Result<(), JobError> {
    match budget {
        Some(b) => e.check(b).map_err(|m| JobError::input(over_budget(m))),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::figure_output::{plot_height, FigureOutput, FigureRequest, PLOT_W};

    fn request(formats: &str, size: Option<&str>) -> FigureRequest {
        FigureRequest {
            formats: Some(formats.into()),
            size: size.map(str::to_owned),
        }
    }

    #[test]
    fn figures_at_a_requested_size_count_their_rasters() {
        let b = DEFAULT;
        // The default size, SVG alone and a size the job refuses add nothing.
        for r in [
            request("png", None),
            request("svg", Some("8192x4096")),
            request("png", Some("99x99")),
        ] {
            assert_eq!(with_figures(b, &r).unwrap().figures, FigureLoad::NONE);
        }
        assert_eq!(with_figures(None, &request("png", Some("8192x4096"))), None);
        // 8192 x 4096: the figures drawn at once hold at least their RGB rasters (3 bytes
        // a pixel) at the size the report renders them (`FigureOutput::size_of`): the
        // two-panel figure of `stiffness` (8192 x 6242) on every thread.
        let load = with_figures(b, &request("png,svg", Some("8192x4096")))
            .unwrap()
            .figures;
        let out = FigureOutput::parse("png", Some("8192x4096")).unwrap();
        let (w, h) = out.size_of((PLOT_W, plot_height(2)));
        let threads = rayon::current_num_threads() as f64;
        let term = load.term(None).unwrap();
        assert!(term.bytes >= threads * 3.0 * f64::from(w) * f64::from(h));
        // ... and at most the raster bound's 8192 x 8192 pixels on each thread at the
        // counted 4 bytes.
        assert!(term.bytes <= threads * 4.0 * 8192.0 * 8192.0);
        // A job's estimate checked against this budget carries the term: a stiffness
        // run fits the default budget at the default size, not at 8192 x 4096 under a
        // budget of 0.1 GB (a 0.26 GB peak measured, issue 33).
        let e = crate::study::budget::estimate(&Case::default(), Job::Stiffness);
        let small = Budget {
            memory_bytes: 0.1e9,
            ..Budget::DEFAULT
        };
        assert!(e.check(&small).is_ok());
        let m = e.check(&small.with_figures(load)).unwrap_err().to_string();
        assert!(m.contains("the figures at the requested size"), "{m}");
    }
}
