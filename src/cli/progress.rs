//! The terminal observer of a job: progress bars on standard error (hidden when it is not
//! a terminal: logs, pipes, CI), notes and warnings on standard error.

use crate::app::{Observer, Task, Unit};
use indicatif::{MultiProgress, ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::Mutex;

/// See the module docs.
pub(crate) struct Terminal {
    multi: MultiProgress,
    bars: Mutex<Vec<(&'static str, ProgressBar)>>,
}

impl Default for Terminal {
    fn default() -> Self {
        Self::new()
    }
}

impl Terminal {
    pub(crate) fn new() -> Self {
        let target = if std::io::stderr().is_terminal() {
            ProgressDrawTarget::stderr()
        } else {
            ProgressDrawTarget::hidden()
        };
        Self {
            multi: MultiProgress::with_draw_target(target),
            bars: Mutex::new(Vec::new()),
        }
    }

    fn bar(&self, task: &Task) -> Option<ProgressBar> {
        let bars = self.bars.lock().ok()?;
        bars.iter()
            .find(|(id, _)| *id == task.id)
            .map(|b| b.1.clone())
    }
}

/// A bar's look: over a wear run's cycles, with its status; or over counted items.
fn style(task: &Task) -> ProgressStyle {
    let template = match task.unit {
        Unit::Cycles => "{prefix:>12} [{bar:30}] {pos}/{len} cycles, {msg} (eta {eta})".to_owned(),
        Unit::Items => format!(
            "{:>16} [{{bar:30}}] {{pos}}/{{len}} (elapsed {{elapsed}}, eta {{eta}})",
            task.label
        ),
    };
    ProgressStyle::with_template(&template)
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> ")
}

impl Observer for Terminal {
    fn start(&self, task: &Task) {
        let pb = self.multi.add(ProgressBar::new(task.total.max(0.0) as u64));
        pb.set_style(style(task));
        pb.set_prefix(task.label);
        if let Ok(mut bars) = self.bars.lock() {
            bars.push((task.id, pb));
        }
    }

    fn advance(&self, task: &Task, done: f64, status: &str) {
        if let Some(pb) = self.bar(task) {
            pb.set_position(done.max(0.0) as u64);
            if !status.is_empty() {
                pb.set_message(status.to_owned());
            }
        }
    }

    fn finish(&self, task: &Task) {
        if let Ok(mut bars) = self.bars.lock() {
            if let Some(i) = bars.iter().position(|(id, _)| *id == task.id) {
                bars.remove(i).1.finish_and_clear();
            }
        }
    }

    fn note(&self, text: &str) {
        self.multi.suspend(|| eprintln!("{text}"));
    }

    fn warning(&self, text: &str) {
        self.multi.suspend(|| eprintln!("warning: {text}"));
    }
}
