//! The PNG figures a job draws, counted from its case before the run, so that figures of
//! a requested size (`--figure-size`, Python `figure_size=`) are counted in time one by
//! one ([`super::cost::FigureLoad::term`]; issue 33: `signals` at 8192 x 4096 spent 2.8 s
//! of CPU on its three figures while only the two drawn at once were counted, 1.3 s).
//!
//! One function per job family, each listing the figures its report code draws (the
//! functions named in each) in two classes: figures of one panel, drawn at the requested
//! size, and taller ones (several panels), counted at the tallest figure's size. A figure
//! drawn only under a condition the case cannot tell before the run (a response with no
//! velocity, a wear state that is not reached) is counted: the count is a bound.
//! `tests/budget_figures.rs` counts the image files each job writes for several cases
//! against it.

use super::cost::FigureCount;
use super::teeth::excitation_periods_of;
use crate::config::case::Case;

/// The widest figure a job draws, px: the raster's bound (`report::plot::MAX_SIDE_PX`,
/// above this layer; `tests/budget_figures.rs` checks that they agree).
pub const WIDEST_FIGURE_PX: f64 = 8192.0;

/// Figures in the two classes: `(one-panel, taller)`.
const fn count(one_panel: u32, taller: u32) -> FigureCount {
    FigureCount {
        one_panel: one_panel as f64,
        taller: taller as f64,
        dense: 0.0,
        dense_points: 0.0,
        sized: 0.0,
        sized_px: 0.0,
        sized_max_px: 0.0,
    }
}

/// Whether the case's teeth differ from one another (errors, run-out, faults): the
/// tooth-resolved figures (`report::teeth`) are drawn.
fn resolves_teeth(case: &Case) -> bool {
    !case.fault.is_empty() || excitation_periods_of(case) > 1
}

fn helical(case: &Case) -> bool {
    case.gear.helix_angle_deg != 0.0
}

/// `gearwear stiffness` (`report::stiffness::stiffness_artifacts`): the mesh stiffness
/// (panels) and the pair load (`report::pair_load`), a helical pair's face load
/// (`report::face_load`) instead; the tooth pairs' stiffness of a tooth-resolved case
/// (`report::teeth::add_teeth_artifacts`). A gear train: those of each stage.
pub fn stiffness_figures(case: &Case) -> FigureCount {
    let mut c = if helical(case) {
        count(0, 2)
    } else {
        count(1, 1)
    };
    if resolves_teeth(case) {
        c = c.plus(count(0, 1));
    }
    c.times(case.stage.len().max(1) as f64)
}

/// `gearwear dynamics` (`report::dynamics::dynamics_artifacts`): the pinion's velocity
/// and its spectrum, the DTE, the mesh force, the friction coefficient and force (one
/// panel each); a helical pair's face load; a tooth-resolved case's tooth-pair
/// stiffness and sidebands (`report::teeth`). A gear train: a panel per mesh, counted
/// as taller figures.
pub fn dynamics_figures(case: &Case) -> FigureCount {
    let mut c = if case.stage.is_empty() {
        count(6, 0)
    } else {
        count(2, 4)
    };
    if helical(case) {
        c = c.plus(count(0, 1));
    }
    if resolves_teeth(case) {
        c = c.plus(count(0, 2));
    }
    c
}

/// `gearwear signals` (`report::signals`): the spectrum, the time signal and the
/// time-synchronous average; a run-up's order tracks and Campbell diagram
/// (`report::runup`).
pub fn signals_figures(case: &Case) -> FigureCount {
    let mut c = count(0, 3);
    if case.signals.ramp_end_speed_hz.is_some() {
        c = c.plus(count(0, 2));
    }
    c
}

/// The dense series of a record's figures (`report::signals`), for `channels` sensors:
/// what their data can paint at a requested size ([`FigureCount::dense`], counted by
/// [`super::cost::FigureLoad::term`]). Each series in figures' worth of height (its
/// panel's share) and its points:
/// - the spectrum (`spectrum_figure`, two panels): the first channel's bins, at most
///   L f_s / 2 in each panel (L the record's seconds, f_s the sampling rate);
/// - the time trace (`time_figure`, two panels): each channel's and the tachometer's
///   first revolution of the tachometer's shaft, f_s / f_t + 1 points;
/// - the averages (`tsa_figure`, four panels): per shaft (pinion, gear) the TSA, its
///   residual and difference, a revolution on at most 2 f_s / f points (the power of two
///   at or above f_s / f, `signals::tsa`).
///
/// Speeds are taken at the slowest the record sees (a ramp's start or end): the most
/// points a revolution. The model's figures (smooth curves of a few thousand points) are
/// not counted this way: their pixel rate holds them (docs/RELIABILITY.md).
pub fn record_figures_density(case: &Case, channels: usize) -> FigureCount {
    use crate::config::signals::Shaft;
    let s = &case.signals;
    let fs = s.sampling_rate_hz;
    let f0 = case.operating.input_speed_hz;
    let slowest = s.ramp_end_speed_hz.map_or(1.0, |e| (e / f0).min(1.0));
    let shaft_hz = |shaft: Shaft| {
        let mut t = s.clone();
        t.tachometer_shaft = shaft;
        (t.tachometer_shaft_hz(case) * slowest).max(1e-9)
    };
    // A series paints at most a column per point and every column of the figure: its
    // points are capped at the widest figure, so that the term's min(points, dense W)
    // is that of each series, not of their sum (a 40 s spectrum's 5e5 bins would
    // otherwise stand for the narrow traces' columns too).
    let series = |share: f64, points: f64| FigureCount {
        dense: share,
        dense_points: share * points.min(WIDEST_FIGURE_PX),
        ..FigureCount::default()
    };
    let spectrum = series(1.0, s.record_seconds(case) * fs / 2.0);
    let time = series(
        (channels as f64 + 1.0) / 2.0,
        fs / shaft_hz(s.tachometer_shaft) + 1.0,
    );
    let tsa = |shaft| series(0.75, 2.0 * fs / shaft_hz(shaft));
    spectrum
        .plus(time)
        .plus(tsa(Shaft::Pinion))
        .plus(tsa(Shaft::Gear))
}

/// `gearwear wear` in `modes` modes (`report::wear::wear_artifacts`): Figs. 11 and 12
/// (panels) and 13 (one panel), a worn profile per mode (`report::worn_profile`); a
/// tooth-resolved case's tooth-pair stiffness and tooth wear per mode; a helical pair's
/// wear map per mode (`report::helical_wear`); under a load spectrum its duty figures
/// (`report::duty::duty_figures`: the spectrum, the wear by bin and the dynamic factor
/// per mode, the life; and the load-duration figures of `report::ldd`).
pub fn wear_figures(case: &Case, modes: u32) -> FigureCount {
    let mut c = count(1, 2 + modes);
    if resolves_teeth(case) {
        c = c.plus(count(0, 1 + modes));
    }
    if helical(case) {
        c = c.plus(count(0, modes));
    }
    if case.load_spectrum.is_some() {
        c = c.plus(count(0, 4 + 2 * modes));
    }
    c.times(case.stage.len().max(1) as f64)
}

/// `gearwear run` (`report::paper::run_figures`): the paper's Figs. 2 and 4-13 and a
/// worn profile per mode (both modes), a tooth-resolved case's three
/// (`report::teeth::run_teeth_figures`), and under a load spectrum the duty figures of
/// `wear`. A helical pair (`report::run_helical`): the figures of `stiffness`,
/// `dynamics` and `wear` in both modes, each in its folder, and the paper's Figs. 4-10.
pub fn run_figures(case: &Case) -> FigureCount {
    if helical(case) {
        return stiffness_figures(case)
            .plus(dynamics_figures(case))
            .plus(count(7, 0))
            .plus(wear_figures(case, 2));
    }
    let mut c = count(8, 5);
    if resolves_teeth(case) {
        c = c.plus(count(0, 3));
    }
    if case.load_spectrum.is_some() {
        c = c.plus(count(0, 8));
    }
    c.times(case.stage.len().max(1) as f64)
}

/// Default height of a dataset's indicator-trend figure, px (`indicator_trends.png`,
/// `app::dataset::index_files`: 900 x 1500, seven panels; `tests/budget_figure_jobs.rs`
/// checks the file against it).
pub const DATASET_TREND_FIGURE_PX: f64 = 1500.0;

/// Default height of a sweep's figure, px (`report::sweep_figure::SWEEP_FIGURE_PX`, two
/// panels; `tests/budget_figure_jobs.rs` checks the file against it).
pub const SWEEP_FIGURE_PX: f64 = 640.0;

/// `n` figures of the default height `height_px`, each counted at its own height
/// ([`FigureCount::sized`]).
fn of_height(n: f64, height_px: f64) -> FigureCount {
    FigureCount {
        sized: n,
        sized_px: n * height_px,
        sized_max_px: height_px,
        ..FigureCount::default()
    }
}

/// `gearwear dataset` and `dataset-merge`: the indicator trends, one figure of
/// [`DATASET_TREND_FIGURE_PX`] (seven panels), drawn once the index is written. (It was
/// counted as the figures drawn at once, two on two threads; issue 33.)
pub fn dataset_figures() -> FigureCount {
    of_height(1.0, DATASET_TREND_FIGURE_PX)
}

/// A sweep (`app::sweep`, `report::sweep_figure::figures_for`): one figure of two panels
/// ([`SWEEP_FIGURE_PX`] high) per mesh of `base` (one for a pair) when an axis is the input speed or the
/// sweep follows branches (`continuation`); none otherwise. A sweep's cases draw nothing.
/// (It was counted as the figures drawn at once, two on two threads, whether it drew one
/// or none; issue 33.)
pub fn sweep_figures(
    base: &Case,
    plan: &crate::study::sweep::plan::SweepPlan,
    continuation: bool,
) -> FigureCount {
    let speed = plan
        .axes
        .iter()
        .any(|a| a.key == crate::study::sweep::SPEED_KEY);
    if speed || continuation {
        of_height(base.stage.len().max(1) as f64, SWEEP_FIGURE_PX)
    } else {
        FigureCount::default()
    }
}
