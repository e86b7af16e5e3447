//! Ranges of the counts and settings of `calibrate`, `predict` and the merges, each with
//! its reason, checked before anything is allocated or computed. The run budget
//! (`prognostics::budget`) then bounds what these ranges still allow together.
//!
//! Messages name the setting (`samples`, `walkers`, ...) and never a command-line flag;
//! the front ends say how each setting is given.

/// One setting's valid range and why.
#[derive(Debug, Clone, Copy)]
pub struct Limit {
    /// Name of the setting, as the front ends spell it.
    pub setting: &'static str,
    /// Smallest valid value.
    pub min: f64,
    /// Largest valid value.
    pub max: f64,
    /// Why the range is what it is.
    pub reason: &'static str,
}

/// A setting out of its range: which, and the message.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// Name of the setting out of range.
    pub setting: &'static str,
    /// What is wrong, with the value and the valid range.
    pub message: String,
}

impl Limit {
    /// Ok, or the problem of `value`.
    pub fn check(&self, value: f64) -> Result<(), Problem> {
        if value.is_finite() && (self.min..=self.max).contains(&value) {
            return Ok(());
        }
        Err(Problem {
            setting: self.setting,
            message: format!(
                "{} = {} is outside [{}, {}] ({})",
                self.setting,
                short(value),
                short(self.min),
                short(self.max),
                self.reason
            ),
        })
    }
}

fn short(x: f64) -> String {
    if x.is_finite() && x != 0.0 && (x.abs() >= 1e5 || x.abs() < 1e-3) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// Posterior samples written by `calibrate`.
pub(crate) const CALIBRATE_SAMPLES: Limit = Limit {
    setting: "samples",
    min: 1.0,
    max: 1e6,
    reason: "the 5 % and 95 % points of 1e6 draws are known to well under 0.1 % of the spread; more only grows the CSV (about 60 MB per 1e6 rows) and the bands",
};
/// Walkers of the ensemble sampler (the count must also be even and at least twice the
/// free parameters: the two halves of the stretch move).
pub(crate) const WALKERS: Limit = Limit {
    setting: "walkers",
    min: 2.0,
    max: 1e4,
    reason: "the stretch move needs an even count of at least twice the free parameters; beyond 1e4 walkers three parameters gain nothing",
};
/// Steps of the ensemble sampler.
pub(crate) const STEPS: Limit = Limit {
    setting: "steps",
    min: 2.0,
    max: 1e7,
    reason: "the first half is burn-in, so at least 2 keep a step; 1e7 steps of 32 walkers hold 3e8 positions",
};
/// True wear runs checking the surrogate (at the 5, 50 and 95 % points).
pub(crate) const CHECK_RUNS: Limit = Limit {
    setting: "check_runs",
    min: 0.0,
    max: 3.0,
    reason: "one true run at each of the posterior's 50, 5 and 95 % points",
};
/// Ensemble size of `predict`.
pub(crate) const PREDICT_SAMPLES: Limit = Limit {
    setting: "samples",
    min: 1.0,
    max: 1e7,
    reason: "the life's 5 % point of 1e7 samples is known to 0.01 % of its spread; each sample holds its fan values, so more is memory without information",
};
/// Cycle counts of the fan charts.
pub(crate) const GRID_POINTS: Limit = Limit {
    setting: "grid_points",
    min: 2.0,
    max: 1e4,
    reason: "the fan charts are drawn on a 900-pixel axis; the life itself is located exactly between grid points",
};
/// Horizon of a prediction, cycles: the range of `wear.total_cycles`.
pub(crate) const CYCLES: Limit = Limit {
    setting: "cycles",
    min: 1.0,
    max: 1e11,
    reason: "the range of wear.total_cycles: 1e11 cycles is a pinion at 3000 rpm for 63 years",
};
/// Wear limit of a prediction, um.
pub(crate) const LIMIT_UM: Limit = Limit {
    setting: "limit_um",
    min: 1e-3,
    max: 1e4,
    reason: "a wear depth between 1 nm and 10 mm: deeper than any tooth; the model stops far earlier, when the teeth lose contact",
};

/// The settings of `calibrate`: every problem.
pub(crate) fn check_calibrate(
    samples: usize,
    walkers: usize,
    steps: usize,
    check_runs: usize,
    free_parameters: usize,
) -> Vec<Problem> {
    let mut p: Vec<Problem> = [
        (CALIBRATE_SAMPLES, samples),
        (WALKERS, walkers),
        (STEPS, steps),
        (CHECK_RUNS, check_runs),
    ]
    .iter()
    .filter_map(|(l, v)| l.check(*v as f64).err())
    .collect();
    // The sampler runs for three free parameters (one or two use the exact grid).
    let need = 2 * free_parameters.max(1);
    if free_parameters >= 3 && (walkers < need || !walkers.is_multiple_of(2)) && walkers >= 2 {
        p.push(Problem {
            setting: "walkers",
            message: format!(
                "walkers = {walkers}: the ensemble sampler needs an even number of walkers, at least 2 x {free_parameters} free parameters = {need}"
            ),
        });
    }
    p
}

/// The settings of `predict`: every problem.
pub(crate) fn check_predict(
    limit_um: f64,
    cycles: f64,
    samples: Option<usize>,
    grid_points: usize,
    check_runs: usize,
) -> Vec<Problem> {
    let mut checks = vec![
        (LIMIT_UM, limit_um),
        (CYCLES, cycles),
        (GRID_POINTS, grid_points as f64),
        (CHECK_RUNS, check_runs as f64),
    ];
    if let Some(n) = samples {
        checks.push((PREDICT_SAMPLES, n as f64));
    }
    checks
        .iter()
        .filter_map(|(l, v)| l.check(*v).err())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_out_of_range_are_named_with_their_range() {
        let p = check_calibrate(0, 3, 0, 9, 3);
        let names: Vec<&str> = p.iter().map(|x| x.setting).collect();
        assert!(
            names.contains(&"samples") && names.contains(&"steps"),
            "{p:?}"
        );
        assert!(names.contains(&"check_runs"), "{p:?}");
        assert!(p.iter().any(|x| x.message.contains("even number")), "{p:?}");
        assert!(check_calibrate(2000, 32, 2000, 3, 3).is_empty());
        // Walkers only matter to the sampler (three free parameters).
        assert!(check_calibrate(2000, 3, 2000, 3, 1).is_empty());
        let p = check_predict(10.0, 1e30, Some(0), 1, 3);
        assert_eq!(p.len(), 3, "{p:?}");
        assert!(
            p[0].message.contains("cycles = 1e30") && p[0].message.contains("1e11"),
            "{p:?}"
        );
        assert!(check_predict(10.0, f64::NAN, None, 101, 3)[0]
            .message
            .contains("NaN"));
    }
}
