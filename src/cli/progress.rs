//! Progress bars on standard error, hidden when it is not a terminal (logs, pipes, CI).

use crate::study::wear_loop::{WearMode, WearRun};
use indicatif::{MultiProgress, ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;

/// A group of bars drawn together.
pub fn multi() -> MultiProgress {
    let target = if std::io::stderr().is_terminal() {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    };
    MultiProgress::with_draw_target(target)
}

/// A bar over the cycles of a wear run.
pub fn wear_bar(multi: &MultiProgress, total_cycles: f64, mode: WearMode) -> ProgressBar {
    let pb = multi.add(ProgressBar::new(total_cycles.max(0.0) as u64));
    pb.set_style(
        ProgressStyle::with_template(
            "{prefix:>12} [{bar:30}] {pos}/{len} cycles, {msg} (eta {eta})",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    pb.set_prefix(mode.label());
    pb
}

/// Move a wear run's bar to its last update.
pub fn show_wear(pb: &ProgressBar, run: &WearRun) {
    if let Some(r) = run.last() {
        pb.set_position(r.wear.cycles as u64);
        pb.set_message(format!(
            "{} updates, max pinion wear {:.3} um",
            run.records.len() - 1,
            r.wear.max_pinion_m() * 1e6
        ));
    }
}

/// A bar over `len` items of `what` (cases, samples, reference runs).
pub fn count_bar(len: u64, what: &str) -> ProgressBar {
    let target = if std::io::stderr().is_terminal() {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    };
    let pb = ProgressBar::with_draw_target(Some(len), target);
    let template =
        format!("{what:>16} [{{bar:30}}] {{pos}}/{{len}} (elapsed {{elapsed}}, eta {{eta}})");
    pb.set_style(
        ProgressStyle::with_template(&template)
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    pb
}
