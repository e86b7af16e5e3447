//! What an estimate is: terms of time and memory, each with the keys that drive it; the
//! budget a run may use; and the check of one against the other, whose message names what
//! drives the cost.

use super::evaluation::{SECONDS_PER_STEP, SLOWER_MACHINE_FACTOR};

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
    /// The figures the run draws beyond the default size, counted with every estimate
    /// checked against this budget (`super::output::FigureLoad`).
    pub figures: FigureLoad,
}

impl Budget {
    /// 2 GiB and 10 minutes on one core of the reference machine.
    pub const DEFAULT: Budget = Budget {
        memory_bytes: 2.0 * GIB,
        seconds: 600.0,
        figures: FigureLoad::NONE,
    };

    /// The default budget times `factor` (> 0).
    pub fn scaled(factor: f64) -> Budget {
        Budget {
            memory_bytes: Self::DEFAULT.memory_bytes * factor,
            seconds: Self::DEFAULT.seconds * factor,
            figures: FigureLoad::NONE,
        }
    }

    /// This budget with the run's figures at a requested size counted in every estimate
    /// checked against it.
    pub fn with_figures(self, figures: FigureLoad) -> Budget {
        Budget { figures, ..self }
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
    /// PNG figures the job draws (a bound from its case: `super::figures`), each
    /// counted in time when the budget asks for figures of a larger size
    /// ([`FigureLoad::term`]); None for a job whose figures are not counted one by one
    /// (then only those drawn at once are).
    pub figures_drawn: Option<FigureCount>,
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
            figures_drawn: None,
        }
    }

    /// This estimate with the job's `figures` PNG figures counted (`super::figures`).
    pub fn drawing(self, figures: FigureCount) -> Estimate {
        Estimate {
            figures_drawn: Some(figures),
            ..self
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
        match budget.figures.term(self.figures_drawn) {
            Some(t) if !self.terms.is_empty() => {
                let mut with = self.clone();
                with.terms.push(t);
                with.check_alone(budget)
            }
            _ => self.check_alone(budget),
        }
    }

    /// [`Estimate::check`] of these terms alone.
    fn check_alone(&self, budget: &Budget) -> Result<(), OverBudget> {
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

/// Bytes a pixel of a PNG figure holds while it is drawn and encoded: the RGB raster (3
/// bytes) and the encoder's filtered rows and output. Measured 2026-11-30 (`gearwear
/// stiffness`, two figures drawn at once on two threads, the peak RSS less the 15 MB of
/// the default run over the two figures' pixels): 2.5 at 2048x1024 (13 MB for 5.3e6
/// pixels), 2.8 at 4096x2048 (60 MB, 2.1e7), 2.9 at 8192x4096 (247 MB, 8.5e7); counted 4.
pub const BYTES_PER_FIGURE_PIXEL: f64 = 4.0;

/// CPU seconds per pixel of a PNG figure drawn and encoded, measured 2026-11-30 (CPU
/// time at 8192 x 4096 less that at the default size, over the figures' pixels): 8.3e-9
/// for `stiffness`'s two figures (0.70 s, 8.5e7 pixels), 1.6e-8 for `signals`' three,
/// the densest curves (2.78 s, 1.74e8 pixels); counted 1.6e-8, on every figure a job
/// draws (`super::figures`) at its class's pixels (a taller figure at the tallest's,
/// 1.16 times `signals`' own pixels), times `SLOWER_MACHINE_FACTOR` as every other
/// time term (docs/RELIABILITY.md has the table). (It was not: a dataset's trend figure
/// measured 1.7-1.8e-8 at 4096 x 2048 on 2026-12-01, on the project's CI and here, over
/// the rate counted, and `signals`' figures 1.4 times under it.)
pub const SECONDS_PER_FIGURE_PIXEL: f64 = 1.6e-8;

/// Default height of the tallest figure counted, px: four stacked panels (40 + 300 x 4,
/// `report::figure_output::plot_height`); the figures of every command but a few
/// (below) have at most three (`signals`' TSA, 900 px).
pub const TALLEST_DEFAULT_FIGURE_PX: f64 = 1240.0;

/// CPU seconds per pixel that a figure's dense data paint (`FigureCount::dense`): the
/// stems of a spectrum (two long ones a pixel column, `report::plot::draw::thin_bars`) or a
/// noisy line (at most four points a column) reaching across the plot area, drawn 2 px
/// wide and sampled every 2 px for the legend's layout. Measured 2026-11-30 (`signals`,
/// CPU time less that of a record of the same length and rate drawn with its lines and
/// stems short, over the painted pixels `FigureLoad::term` counts): 2.1e-8 at 4096 x
/// 2048 and 2.8e-8 at 8192 x 4096 (a 40 s record under -20 dB of noise), 2.9e-8 (0.2 s
/// at 4 MHz under noise, every figure painted); counted 4e-8, times
/// `SLOWER_MACHINE_FACTOR` since 2026-12-01. Issue 33: a 40 s record's figures at
/// 8192 x 4096 took 20 s of CPU against 3.2 s counted by their pixels alone.
pub const SECONDS_PER_PAINTED_PIXEL: f64 = 4e-8;

/// Bytes per painted pixel (`FigureCount::dense`) of a figure being drawn: the samples
/// every 2 px along each stem or segment (`report::plot::layout::MARK_STEP_PX`, two i32
/// each) that the panel's layout keeps. Measured 2026-11-30 (peak RSS over that of the
/// same record with short stems, over the painted pixels): 2.5-3.5 at 8192 x 4096, 4 at
/// 4096 x 2048; counted 4, on the figures drawn at once.
pub const BYTES_PER_PAINTED_PIXEL: f64 = 4.0;

/// PNG figures a job draws, in two classes (`super::figures`): figures of one panel
/// (drawn at the requested size) and taller ones (counted at the tallest figure's size);
/// and, for figures of dense data (a record's spectrum, time trace and averages), the
/// pixels their data can paint.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FigureCount {
    /// Figures of one panel.
    pub one_panel: f64,
    /// Figures of several panels.
    pub taller: f64,
    /// Dense series, each in figures' worth of height (its panel's share of its figure):
    /// a series of n points paints at most min(n, W) pixel columns of its panel's height
    /// (a line of n points, n - 1 segments each at most the panel's height; a spectrum's
    /// stems, thinned to two long ones a column), W the figure's width.
    pub dense: f64,
    /// The points of those series, each times its panel's share: with [`Self::dense`],
    /// the painted pixels are at most min(`dense_points`, `dense` W) times the figure's
    /// height (the sum of the series' min(n, W) h is at most both).
    pub dense_points: f64,
    /// Figures counted at their own height, not the tallest's (a sweep's, a dataset's).
    pub sized: f64,
    /// The sum of their default heights, px: at a requested size they take at most
    /// min(s `sized_px`, `sized` M) rows of pixels (s the size's scale of heights, M the
    /// raster's bound: the sum of the capped heights is at most both).
    pub sized_px: f64,
    /// The tallest of them at the default size, px (its raster is the largest held).
    pub sized_max_px: f64,
}

impl FigureCount {
    /// Every figure.
    pub fn total(&self) -> f64 {
        self.one_panel + self.taller + self.sized
    }

    /// These figures and `o`'s.
    pub fn plus(self, o: FigureCount) -> FigureCount {
        FigureCount {
            one_panel: self.one_panel + o.one_panel,
            taller: self.taller + o.taller,
            dense: self.dense + o.dense,
            dense_points: self.dense_points + o.dense_points,
            sized: self.sized + o.sized,
            sized_px: self.sized_px + o.sized_px,
            sized_max_px: self.sized_max_px.max(o.sized_max_px),
        }
    }

    /// These figures `n` times over.
    pub fn times(self, n: f64) -> FigureCount {
        FigureCount {
            one_panel: self.one_panel * n,
            taller: self.taller * n,
            dense: self.dense * n,
            dense_points: self.dense_points * n,
            sized: self.sized * n,
            sized_px: self.sized_px * n,
            sized_max_px: self.sized_max_px,
        }
    }
}

/// PNG figures of a requested size as the budget counts them (plain numbers, so that the
/// cost model imports nothing of the report layer): the pixels of a one-panel figure and
/// of the tallest figure a command draws at that size, and how many figures are drawn at
/// once (the threads: `report::artifacts::stage_figures` renders them in parallel). At
/// the default size nothing is added: the measured base and rates hold the default
/// figures.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FigureLoad {
    /// Pixels of the tallest figure at the requested size.
    pub pixels_per_figure: f64,
    /// Pixels of a one-panel figure at the requested size.
    pub pixels_per_one_panel_figure: f64,
    /// Figures drawn at once.
    pub figures_at_once: f64,
    /// Width of the figures at the requested size, px.
    pub width_px: f64,
    /// Heights at the requested size per default height (the one-panel figures' ratio).
    pub height_scale: f64,
    /// The raster's bound on a side, px.
    pub max_side_px: f64,
}

impl FigureLoad {
    /// No figure beyond the default size.
    pub const NONE: FigureLoad = FigureLoad {
        pixels_per_figure: 0.0,
        pixels_per_one_panel_figure: 0.0,
        figures_at_once: 0.0,
        width_px: 0.0,
        height_scale: 0.0,
        max_side_px: 0.0,
    };

    /// PNG figures whose one-panel size is `(w, h)` px against the default `default_px`
    /// (w, h), each side at most `max_side_px` (the raster's bound), drawn on `threads`
    /// threads: the tallest figure ([`TALLEST_DEFAULT_FIGURE_PX`] by default) scaled as
    /// `report::figure_output::FigureOutput::size_of` scales it, in saturating
    /// arithmetic (u64 pixels of two u32 sides never wrap).
    pub fn at_size(
        (w, h): (u32, u32),
        default_px: (u32, u32),
        max_side_px: u32,
        threads: usize,
    ) -> FigureLoad {
        let width = (u64::from(w)).min(u64::from(max_side_px));
        let tall = TALLEST_DEFAULT_FIGURE_PX * f64::from(h) / f64::from(default_px.1.max(1));
        let height = (tall.round() as u64).clamp(1, u64::from(max_side_px));
        let one = u64::from(h).clamp(1, u64::from(max_side_px));
        FigureLoad {
            pixels_per_figure: width.saturating_mul(height) as f64,
            pixels_per_one_panel_figure: width.saturating_mul(one) as f64,
            figures_at_once: threads.max(1) as f64,
            width_px: width as f64,
            height_scale: f64::from(h) / f64::from(default_px.1.max(1)),
            max_side_px: f64::from(max_side_px),
        }
    }

    /// The term of these figures when the job draws `drawn` (None: a job whose figures
    /// are not counted one by one, counted as the figures drawn at once, all tall), None
    /// when there are none: the figures drawn at once (at most those drawn) hold the
    /// tallest figure's raster each, and every figure drawn takes its time at its class's
    /// pixels (issue 33: `signals` at 8192 x 4096 drew three figures in 2.8 s of CPU
    /// while the two drawn at once were counted, 1.3 s).
    pub fn term(&self, drawn: Option<FigureCount>) -> Option<Term> {
        let drawn = drawn.unwrap_or(FigureCount {
            taller: self.figures_at_once,
            ..FigureCount::default()
        });
        // Figures of their own height: their capped heights' sum, bounded.
        let rows = |px: f64, n: f64| (self.height_scale * px).min(n * self.max_side_px);
        let sized = self.width_px * rows(drawn.sized_px, drawn.sized);
        let pixels = drawn.one_panel * self.pixels_per_one_panel_figure
            + drawn.taller * self.pixels_per_figure
            + sized;
        let at_once = drawn.total().min(self.figures_at_once);
        // The largest raster held: the tallest figure's, or a figure of its own height's
        // when it draws only those or one is taller; no more rasters than its pixels.
        let largest = if drawn.one_panel + drawn.taller > 0.0 {
            self.pixels_per_figure
        } else {
            0.0
        }
        .max(if drawn.sized > 0.0 {
            self.width_px * rows(drawn.sized_max_px, 1.0)
        } else {
            0.0
        });
        let rasters = (at_once * largest).min(pixels);
        // Painted pixels of dense data, at the tallest figure's height (a bound), and
        // those of the figures drawn at once (at most that many figures' worth).
        let height = self.pixels_per_figure / self.width_px.max(1.0);
        let painted = drawn.dense_points.min(drawn.dense * self.width_px) * height;
        let painted_at_once = painted.min(at_once * largest);
        (self.pixels_per_figure > 0.0 && drawn.total() > 0.0).then_some(Term {
            what:
                "the figures at the requested size (their pixels and the pixels their data paint)",
            seconds: (pixels * SECONDS_PER_FIGURE_PIXEL + painted * SECONDS_PER_PAINTED_PIXEL)
                * SLOWER_MACHINE_FACTOR,
            bytes: rasters * BYTES_PER_FIGURE_PIXEL + painted_at_once * BYTES_PER_PAINTED_PIXEL,
            keys: if painted > 0.0 {
                &[
                    "the figure size",
                    "signals.record_length",
                    "signals.sampling_rate_hz",
                ]
            } else {
                &["the figure size"]
            },
        })
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
