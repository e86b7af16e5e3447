//! What a command's process costs besides its computations: its start-up, and for
//! `stiffness`, whose computations take milliseconds, the tables and figures it writes.
//!
//! The start-up is counted by every estimate ([`super::cost::START_UP_SECONDS`]).
//!
//! Measured 2026-11-30 with `perf stat -e task-clock` (CPU time, both threads) on the
//! shared 2-core machine at load 5-6:
//! - the process's start-up (the binary loaded, the arguments read, nothing computed):
//!   1.5 ms (`gearwear --version`) and 2.1 ms (`gearwear config --markdown`);
//! - a PNG figure of `stiffness` at the default size (900 x 420 pixels a panel; the
//!   raster drawn and deflated): the run with PNG figures less the same run with SVG
//!   figures, per figure, 8.7 ms (the built-in pair, 2 figures: 30.6 against 13.3 ms),
//!   10.6 ms (the two-stage example, 3: 55.6 against 23.7), 8.0 ms (that train with a
//!   crack on stage 1's pinion, 4: 66.3 against 34.2) and 9.0 ms (the pair with a
//!   cracked tooth, 2: 41.0 against 22.9);
//! - each mesh's stiffness model and tables (the SVG runs less the start-up and the
//!   computations the other terms count): 9 ms (the pair: 13.3 - 2.1 - 1.8), 10 ms a
//!   mesh (the train: 23.7 - 2.1 - 1.8, two meshes).
//!
//! Before (issue 33), `stiffness` was estimated at its computations alone, 2 ms for the
//! built-in pair and 12 ms for the cracked train, against 30 and 66 ms of CPU.

use super::cost::Term;
use super::evaluation::SLOWER_MACHINE_FACTOR;
use crate::config::Case;

/// CPU seconds of one PNG figure at the default size: measured 8-10.6 ms (module docs),
/// counted 10 ms, times [`SLOWER_MACHINE_FACTOR`]. (A larger figure size costs more:
/// [`FigureLoad`], counted with the budget.)
const SECONDS_PER_FIGURE: f64 = 10e-3 * SLOWER_MACHINE_FACTOR;

/// CPU seconds of one mesh's stiffness model and tables in `stiffness`: measured 9-10 ms
/// (module docs), counted 10 ms, times [`SLOWER_MACHINE_FACTOR`].
const SECONDS_PER_MESH_OUTPUT: f64 = 10e-3 * SLOWER_MACHINE_FACTOR;

/// The figures `gearwear stiffness` writes for `case` (`report::stiffness`,
/// `report::stiffness_train`): one mesh-stiffness figure per mesh (a train's stages, or
/// the pair), one more (the pair loads of identical teeth, or a tooth-resolved pair's
/// teeth), and a train's tooth-resolved figure per faulty stage (`faulty_stages`).
pub fn stiffness_figures(case: &Case, faulty_stages: usize) -> usize {
    let meshes = case.stage.len().max(1);
    meshes
        + 1
        + if case.stage.is_empty() {
            0
        } else {
            faulty_stages
        }
}

/// The term of `stiffness`'s output for `case` with `faulty_stages` tooth-resolved train
/// stages: each mesh's model and tables, and its figures.
pub fn stiffness_output_term(case: &Case, faulty_stages: usize) -> Term {
    let meshes = case.stage.len().max(1) as f64;
    let figures = stiffness_figures(case, faulty_stages) as f64;
    Term {
        what: "the tables and figures written",
        seconds: meshes * SECONDS_PER_MESH_OUTPUT + figures * SECONDS_PER_FIGURE,
        bytes: 0.0,
        keys: &["the case's stages and tooth faults"],
    }
}
