//! The step grid of a planetary set's mesh period (`planetary_steady`, docs/MODEL.md
//! 12.6): the equally spaced sample times and the times where a mesh's stiffness jumps,
//! nodes that no step crosses.

/// A node of the period's step grid (no step crosses one).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Node {
    /// Time from the period's start, s.
    pub t_s: f64,
    /// One of the equally spaced sample times.
    pub sample: bool,
    /// A mesh's stiffness jumps here.
    pub jump: bool,
}

/// Nodes closer than this fraction of a sample interval are one: a jump moved onto a
/// sample time by at most 1e-6 of a sample interval changes the stiffness for that
/// long only (an error far below the integration tolerance) and avoids slivers of steps.
const NODE_MERGE: f64 = 1e-6;

/// The step grid of one period `period_s` long: the `samples` + 1 equally spaced sample
/// times (both ends included) and the stiffness jumps at `jump_cycles` (fractions of the
/// period), sorted, a jump within [`NODE_MERGE`] of a sample interval from a sample
/// marked on the sample.
pub(crate) fn period_grid(jump_cycles: &[f64], period_s: f64, samples: usize) -> Vec<Node> {
    let dt = period_s / samples as f64;
    let mut grid: Vec<Node> = (0..=samples)
        .map(|k| Node {
            t_s: k as f64 * dt,
            sample: true,
            jump: false,
        })
        .collect();
    for c in jump_cycles {
        let x = c * samples as f64;
        let k = x.round() as usize;
        if (x - k as f64).abs() < NODE_MERGE {
            grid[k].jump = true;
            if k == samples {
                grid[0].jump = true;
            }
        } else {
            grid.push(Node {
                t_s: c * period_s,
                sample: false,
                jump: true,
            });
        }
    }
    grid.sort_by(|a, b| a.t_s.total_cmp(&b.t_s));
    grid
}
