//! The load duration distribution (LDD) of a measured history, and the load spectrum it
//! gives.
//!
//! **Method: time at level** (ISO 6336-6:2019, the load spectrum of a gear as classes of
//! torque with the time, hence the load cycles, spent in each; the LDD of IEC 61400-4 for
//! wind-turbine gearboxes is the same count). The torque range [0, T_max] is cut into
//! equal classes, and so is the speed range [0, f_max]; the time the history spends in each
//! torque x speed cell is counted, and with it the pinion revolutions there, the integral
//! of the speed over that time. Between samples the history is either
//! - `linear` (default): piecewise linear, so a ramp's time in each class is exact: each
//!   interval is split where the torque or the speed crosses a class edge (or zero), and
//!   each piece is counted in its cell with its exact time, revolutions (the speed is
//!   linear: trapezoid) and torque-revolutions (a product of two linears: Simpson's rule);
//! - `hold`: each sample's values held until the next sample (a data logger's
//!   sample-and-hold, and the form in which a step signal sampled at its switching
//!   instants is exact).
//!
//! The total time is conserved: the cells and the idle time (torque or speed not positive:
//! no load on the drive flank, whose wear the model describes) sum to the record's span.
//!
//! **Each cell becomes a bin**: its share is its revolutions over all revolutions under
//! load; its speed is revolutions / time (the time-weighted mean speed, which keeps the
//! cycles exact); its torque is, by default (`mean`), the revolution-weighted mean torque of
//! the cell. That keeps the wear of the cell exact in the quasi-static limit, because
//! Archard wear per cycle is linear in the load (p0 ~ W^1/2 times the band 2a ~ W^1/2;
//! docs/MODEL.md, section 10). `upper` takes the class's upper edge instead: the conservative
//! choice of rating, which overstates wear by up to one class width.
//!
//! **Why no rainflow count.** Rainflow counting (ASTM E1049) pairs the reversals of a
//! load signal into cycles, for materials whose damage is driven by load ranges. A gear
//! tooth's load cycles are not the torque's reversals: each revolution loads every tooth
//! once whatever the torque does, so the cycles are counted by revolutions at level, which
//! is what time at level gives. Torque changes within a revolution are the dynamic
//! response the model itself computes. Archard wear needs the load and sliding per
//! engagement and the number of engagements: nothing a rainflow count adds.

use super::history::History;
use crate::config::case::TorqueShaft;
use crate::config::operating::{LoadSpectrumSection, SpectrumBin};
use serde::{Deserialize, Serialize};

/// How the history runs between samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Interpolation {
    /// Piecewise linear between samples (the default): a ramp's time in each class is exact.
    #[default]
    Linear,
    /// Each sample's values held until the next sample (sample-and-hold).
    Hold,
}

/// The torque a cell's bin gets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Level {
    /// Revolution-weighted mean torque of the cell.
    #[default]
    Mean,
    /// Upper edge of the torque class.
    Upper,
}

/// Classes and counting rules.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LddSettings {
    /// Number of equal torque classes over [0, T_max] (at most 200).
    pub torque_classes: usize,
    /// Number of equal speed classes over [0, f_max] (at most 50).
    pub speed_classes: usize,
    /// How the history runs between samples.
    pub interpolation: Interpolation,
    /// The torque each cell's bin gets.
    pub level: Level,
}

impl Default for LddSettings {
    fn default() -> Self {
        Self {
            torque_classes: 10,
            speed_classes: 5,
            interpolation: Interpolation::Linear,
            level: Level::Mean,
        }
    }
}

/// Largest number of classes per axis: a spectrum of more than 200 x 50 bins only adds
/// cost (each bin is a dynamic evaluation per wear update).
pub(crate) const MAX_TORQUE_CLASSES: usize = 200;
pub(crate) const MAX_SPEED_CLASSES: usize = 50;

/// Counts per torque x speed cell (row-major: torque class slowest).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ldd {
    /// The classes and counting rules the distribution was counted with.
    pub settings: LddSettings,
    /// Class edges, `classes + 1` each, from 0.
    pub torque_edges_nm: Vec<f64>,
    /// Speed class edges, `speed_classes + 1`, from 0, Hz.
    pub speed_edges_hz: Vec<f64>,
    /// Time in each cell, s.
    pub time_s: Vec<f64>,
    /// Pinion revolutions in each cell (integral of the speed), -.
    pub cycles: Vec<f64>,
    /// Integral of torque x speed over the cell's time, N m (for the mean torque).
    pub torque_cycles_nm: Vec<f64>,
    /// Time with torque or speed not positive (no load on the drive flank), s.
    pub idle_time_s: f64,
    /// The part of `idle_time_s` with the torque negative while the shaft turns (the
    /// coast flank loaded: braking, overrunning), s. Counted as idle because the model
    /// wears the drive flank only; reported so that it is never dropped silently.
    pub reversed_torque_time_s: f64,
    /// Span of the record, last time - first time, s.
    pub span_s: f64,
}

/// Class of `x` on [0, max] cut into `n` classes (values at max in the last one).
fn class(x: f64, width: f64, n: usize) -> usize {
    ((x / width) as usize).min(n - 1)
}

/// The classes' common width: max / n (1 when nothing is positive, to keep it finite).
fn width(max: f64, n: usize) -> f64 {
    if max > 0.0 {
        max / n as f64
    } else {
        1.0
    }
}

impl Ldd {
    fn cells(&self) -> usize {
        self.time_s.len()
    }

    /// Cell index of (torque class, speed class).
    pub fn cell(&self, t: usize, s: usize) -> usize {
        t * self.settings.speed_classes + s
    }

    /// Time under load (every cell), s.
    pub fn loaded_time_s(&self) -> f64 {
        self.time_s.iter().sum()
    }

    /// Time at each torque class (all speeds), s.
    pub fn time_at_torque_s(&self) -> Vec<f64> {
        let ns = self.settings.speed_classes;
        self.time_s.chunks(ns).map(|c| c.iter().sum()).collect()
    }

    /// Time at each speed class (all torques), s.
    pub fn time_at_speed_s(&self) -> Vec<f64> {
        let ns = self.settings.speed_classes;
        (0..ns)
            .map(|s| self.time_s.iter().skip(s).step_by(ns).sum())
            .collect()
    }

    /// The load spectrum: a bin per cell with revolutions (module docs), torques on
    /// `shaft`. None when no time was under load.
    pub fn spectrum(&self, shaft: TorqueShaft) -> Option<LoadSpectrumSection> {
        let total: f64 = self.cycles.iter().sum();
        if total.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let ns = self.settings.speed_classes;
        let bins = (0..self.cells())
            .filter(|i| self.cycles[*i] > 0.0 && self.time_s[*i] > 0.0)
            .map(|i| SpectrumBin {
                torque_nm: match self.settings.level {
                    Level::Mean => self.torque_cycles_nm[i] / self.cycles[i],
                    Level::Upper => self.torque_edges_nm[i / ns + 1],
                },
                input_speed_hz: self.cycles[i] / self.time_s[i],
                share: self.cycles[i] / total,
            })
            .collect();
        let mut s = LoadSpectrumSection::of_bins(bins);
        s.torque_shaft = Some(shaft);
        Some(s)
    }
}

/// Count `h` (checked: at least two samples, time increasing) into its LDD.
pub fn load_duration_distribution(h: &History, settings: LddSettings) -> Ldd {
    let (nt, ns) = (
        settings.torque_classes.max(1),
        settings.speed_classes.max(1),
    );
    let t_max = h.torque_nm.iter().fold(0.0_f64, |m, x| m.max(*x));
    let f_max = h.input_speed_hz.iter().fold(0.0_f64, |m, x| m.max(*x));
    let (wt, wf) = (width(t_max, nt), width(f_max, ns));
    let mut ldd = Ldd {
        settings: LddSettings {
            torque_classes: nt,
            speed_classes: ns,
            ..settings
        },
        torque_edges_nm: (0..=nt).map(|k| k as f64 * wt).collect(),
        speed_edges_hz: (0..=ns).map(|k| k as f64 * wf).collect(),
        time_s: vec![0.0; nt * ns],
        cycles: vec![0.0; nt * ns],
        torque_cycles_nm: vec![0.0; nt * ns],
        idle_time_s: 0.0,
        reversed_torque_time_s: 0.0,
        span_s: h.time_s.last().unwrap_or(&0.0) - h.time_s.first().unwrap_or(&0.0),
    };
    // Adds a piece of duration dt at midpoint values (q, f) with its integrals.
    let mut add = |dt: f64, q: f64, f: f64, cycles: f64, torque_cycles: f64| {
        if q <= 0.0 || f <= 0.0 {
            ldd.idle_time_s += dt;
            if q < 0.0 && f > 0.0 {
                ldd.reversed_torque_time_s += dt;
            }
            return;
        }
        let i = class(q, wt, nt) * ns + class(f, wf, ns);
        ldd.time_s[i] += dt;
        ldd.cycles[i] += cycles;
        ldd.torque_cycles_nm[i] += torque_cycles;
    };
    let n = h.time_s.len();
    let mut cuts: Vec<f64> = Vec::with_capacity(16);
    for k in 0..n.saturating_sub(1) {
        let (t0, t1) = (h.time_s[k], h.time_s[k + 1]);
        let dt = t1 - t0;
        let (q0, q1, f0, f1) = (
            h.torque_nm[k],
            h.torque_nm[k + 1],
            h.input_speed_hz[k],
            h.input_speed_hz[k + 1],
        );
        if settings.interpolation == Interpolation::Hold {
            add(dt, q0, f0, f0 * dt, q0 * f0 * dt);
            continue;
        }
        // Fractions of the interval where torque or speed cross a class edge or zero.
        cuts.clear();
        crossings(q0, q1, wt, nt, &mut cuts);
        crossings(f0, f1, wf, ns, &mut cuts);
        cuts.sort_by(f64::total_cmp);
        let mut a = 0.0;
        for b in cuts.iter().copied().chain(std::iter::once(1.0)) {
            if b <= a {
                continue;
            }
            let lerp = |x0: f64, x1: f64, u: f64| x0 + (x1 - x0) * u;
            let (qa, qb, fa, fb) = (
                lerp(q0, q1, a),
                lerp(q0, q1, b),
                lerp(f0, f1, a),
                lerp(f0, f1, b),
            );
            let m = 0.5 * (a + b);
            let (qm, fm) = (lerp(q0, q1, m), lerp(f0, f1, m));
            let d = (b - a) * dt;
            // Speed linear: trapezoid exact; torque x speed quadratic: Simpson exact.
            add(
                d,
                qm,
                fm,
                0.5 * (fa + fb) * d,
                d / 6.0 * (qa * fa + 4.0 * qm * fm + qb * fb),
            );
            a = b;
        }
    }
    ldd
}

/// Fractions u in (0, 1) where x0 + (x1 - x0) u crosses zero or an edge k w (k = 1..n-1).
fn crossings(x0: f64, x1: f64, w: f64, n: usize, out: &mut Vec<f64>) {
    if x0 == x1 {
        return;
    }
    let (lo, hi) = (x0.min(x1), x0.max(x1));
    let mut push = |e: f64| {
        if e > lo && e < hi {
            out.push((e - x0) / (x1 - x0));
        }
    };
    push(0.0);
    if hi <= 0.0 {
        return;
    }
    let k_lo = ((lo.max(0.0) / w).floor() as usize).max(1);
    let k_hi = ((hi / w).ceil() as usize).min(n.saturating_sub(1));
    for k in k_lo..=k_hi {
        push(k as f64 * w);
    }
}
