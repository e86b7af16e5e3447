//! Results of a gear train (`[[stage]]`) under a load spectrum (`duty::train`): the
//! train's own outputs (`report::wear_train`, `report::run_train`) of the spectrum's run
//! read as one train run (each mesh's shared wear, its wear per cycle under the spectrum,
//! the monitoring bin's response), plus `load_spectrum` in `summary.json`, lines on
//! stdout and a duty-cycle section in the report.
//!
//! `load_spectrum`: the bins as used (torque, its shaft, input speed, shares of cycles and
//! time) with every stage's operating point at each bin (pinion speed and torque, gear
//! torque, mesh frequency), and per mode the input cycles and hours run, per mesh its
//! wear, the share of it each bin added and its life to the wear limit, and the mesh that
//! limits the train's life.

use super::duty_figures::{spectrum_figure, time_shares, wear_by_bin_titled, DutyFigure};
use super::html::{Section, TableBlock};
use crate::duty::train::{TrainSpectrum, TrainSpectrumRun};
use crate::duty::train_life::{seconds_per_input_cycle, under_spectrum, TrainUnderSpectrum};
use crate::duty::wear::{SpectrumRecord, SpectrumRun};
use crate::format::{shown, shown_percent};
use serde_json::{json, Value};
use std::f64::consts::PI;

/// Every stage's operating point at bin `i`.
fn stages_at_bin(ts: &TrainSpectrum, i: usize) -> Vec<Value> {
    ts.trains[i]
        .operating
        .meshes
        .iter()
        .enumerate()
        .map(|(k, p)| {
            json!({
                "stage": k + 1,
                "pinion_speed_hz": p.pinion_speed_rad_s / (2.0 * PI),
                "pinion_torque_nm": p.pinion_torque_nm,
                "gear_torque_nm": p.gear_torque_nm,
                "mesh_frequency_hz": p.mesh_frequency_hz,
            })
        })
        .collect()
}

/// The figures of a train under a spectrum: the spectrum's bins, and per mode and mesh
/// the wear each bin added along the mesh's pinion and gear profiles (the single pair's
/// figures, `duty_figures`, read on each mesh's shared flanks and its own pinion cycles).
pub fn train_duty_figures(ts: &TrainSpectrum, runs: &[&TrainSpectrumRun]) -> Vec<DutyFigure> {
    let mut figs = vec![spectrum_figure(&ts.sm.spectrum(), None)];
    let train = ts.trains[ts.sm.monitoring];
    for r in runs {
        let Some(last) = r.records.last() else {
            continue;
        };
        for (k, stage) in train.stages.iter().enumerate() {
            // Mesh k's flanks as a single pair's spectrum run of one update: its shared
            // wear (every bin's record holds the same) and what each bin added to it.
            let mesh = SpectrumRun {
                mode: r.mode,
                shares: r.shares.clone(),
                records: vec![SpectrumRecord {
                    wear: last.bins[0].meshes[k].wear.clone(),
                    roughness_um: last.bins[0].meshes[k].roughness_um,
                    bins: Vec::new(),
                    by_bin_pinion_m: last.by_bin_pinion_m.iter().map(|b| b[k].clone()).collect(),
                    by_bin_gear_m: last.by_bin_gear_m.iter().map(|b| b[k].clone()).collect(),
                }],
                stopped: None,
            };
            let (z1, z2) = (stage.pair.pinion.teeth, stage.pair.gear.teeth);
            let title = |cycles: f64| {
                format!(
                    "Stage {} ({z1}/{z2}): wear added by each bin of the spectrum, {} cycles of its pinion ({})",
                    k + 1,
                    crate::io::format_number(cycles),
                    r.mode.label()
                )
            };
            if let Some(mut f) = wear_by_bin_titled(&stage.grid, &mesh, &title) {
                f.stem = format!("duty_wear_by_bin_{}_stage{}", r.mode.name(), k + 1);
                figs.push(f);
            }
        }
    }
    figs
}

/// `summary.json`'s `load_spectrum` (see the module docs).
pub fn train_duty_summary(ts: &TrainSpectrum, runs: &[&TrainSpectrumRun]) -> Value {
    let sm = ts.sm;
    let s = sm.spectrum();
    let time = time_shares(&s);
    let bins: Vec<Value> = sm
        .bins
        .iter()
        .enumerate()
        .map(|(i, m)| {
            json!({
                "bin": i + 1,
                "torque_nm": m.case.operating.load_torque_nm,
                "torque_shaft": m.case.operating.load_torque_shaft,
                "input_speed_hz": m.case.operating.input_speed_hz,
                "share_of_cycles": sm.shares[i],
                "share_of_time": time.get(i),
                "stages": stages_at_bin(ts, i),
            })
        })
        .collect();
    let mut v = json!({
        "bins": bins,
        "monitoring_bin": sm.monitoring + 1,
        "seconds_per_input_cycle": seconds_per_input_cycle(ts),
        "notes": "Shares are shares of input cycles (stage 1's pinion); each update advances every mesh by every bin's share of the block on the shared worn flanks (docs/MODEL.md, section 10.1). The train's outputs (wear_history_*.csv, updates_*_stageK.csv, meshes, limiting_mesh) hold the spectrum's wear and the response at the monitoring bin. torque_shaft \"gear\" is the output shaft: the last stage's gear.",
    });
    for r in runs {
        v[r.mode.name()] = json!(under_spectrum(ts, r));
    }
    v
}

/// The lines on stdout for the runs under the spectrum.
pub fn train_duty_lines(ts: &TrainSpectrum, runs: &[&TrainSpectrumRun]) -> Vec<String> {
    let mut lines = Vec::new();
    for r in runs {
        let Some(u) = under_spectrum(ts, r) else {
            continue;
        };
        let mode = r.mode.label();
        lines.push(format!(
            "{mode}, under the load spectrum ({} bins): {} input cycles = {} h",
            ts.sm.len(),
            shown(u.input_cycles),
            shown(u.hours)
        ));
        for m in &u.meshes {
            let by_bin: Vec<String> = m
                .share_of_pinion_wear_by_bin
                .iter()
                .enumerate()
                .map(|(i, x)| format!("bin {} {}", i + 1, shown_percent(*x)))
                .collect();
            lines.push(format!(
                "{mode}, stage {}: life to {} µm {}; pinion wear by bin: {}",
                m.stage,
                shown(u.life_wear_limit_um),
                life_words(m.life_hours, &m.life),
                by_bin.join(", ")
            ));
        }
        if let Some(k) = u.limiting_stage {
            lines.push(format!(
                "{mode}: stage {k} limits the train's life under the spectrum"
            ));
        }
    }
    lines
}

/// A life in words.
fn life_words(hours: Option<f64>, life: &crate::duty::life::Life) -> String {
    match (life.cycles(), hours) {
        (Some(n), Some(h)) => format!("{} input cycles = {} h", shown(n), shown(h)),
        _ => "not reached within the run".into(),
    }
}

/// The report's duty-cycle section: the bins with every stage's torque, and per mesh its
/// wear, the bins' shares of it and its life.
pub fn train_duty_section(ts: &TrainSpectrum, runs: &[&TrainSpectrumRun]) -> Section {
    let sm = ts.sm;
    let nk = ts.meshes();
    let mut header = vec![
        "bin".into(),
        "input speed (Hz)".into(),
        "share of cycles".into(),
    ];
    header.extend((1..=nk).map(|k| format!("stage {k} pinion torque (N m)")));
    let rows = (0..sm.len())
        .map(|i| {
            let o = &sm.bins[i].case.operating;
            let mut row = vec![
                (i + 1).to_string(),
                shown(o.input_speed_hz),
                shown_percent(sm.shares[i]),
            ];
            row.extend(
                ts.trains[i]
                    .operating
                    .meshes
                    .iter()
                    .map(|p| shown(p.pinion_torque_nm)),
            );
            row
        })
        .collect();
    let mut tables = vec![TableBlock {
        caption: "The load spectrum: each bin's input speed, share of the input cycles and every stage's pinion torque (from the ratios).".into(),
        header,
        rows,
        highlight_col: None,
    }];
    for r in runs {
        if let Some(u) = under_spectrum(ts, r) {
            tables.push(mesh_table(r.mode.label(), &u));
        }
    }
    Section {
        heading: "Duty cycle: the train's wear and life under the load spectrum".into(),
        paragraphs: vec![format!(
            "The train runs through {} operating bins. Every wear update advances every mesh by every bin's share of the block's input cycles on the shared worn flanks (docs/MODEL.md, section 10.1); the stage sections above show the spectrum's wear and the response at bin {} (the monitoring bin). The mesh whose wear reaches the limit first limits the train's life.",
            sm.len(),
            sm.monitoring + 1
        )],
        figures: Vec::new(),
        tables,
    }
}

/// Per mesh: its wear, the share of it each bin added and its life.
fn mesh_table(mode: &str, u: &TrainUnderSpectrum) -> TableBlock {
    let rows = u
        .meshes
        .iter()
        .map(|m| {
            let by_bin: Vec<String> = m
                .share_of_pinion_wear_by_bin
                .iter()
                .map(|x| shown_percent(*x))
                .collect();
            vec![
                m.stage.to_string(),
                shown(m.max_wear_pinion_um),
                shown(m.max_wear_gear_um),
                by_bin.join(" / "),
                life_words(m.life_hours, &m.life),
            ]
        })
        .collect();
    TableBlock {
        caption: format!(
            "{mode}: every mesh's wear after {} input cycles ({} h), the share of its pinion wear each bin added, and its life to {} µm.",
            shown(u.input_cycles),
            shown(u.hours),
            shown(u.life_wear_limit_um)
        ),
        header: vec![
            "stage".into(),
            "max pinion wear (µm)".into(),
            "max gear wear (µm)".into(),
            "pinion wear by bin".into(),
            "life".into(),
        ],
        rows,
        highlight_col: None,
    }
}

/// What a spectrum adds to a train's outputs: `load_spectrum` in the summary, lines on
/// stdout, the report's section.
pub struct TrainDutyParts {
    /// `summary.json`'s `load_spectrum`.
    pub summary: Value,
    /// Lines added to the headline.
    pub lines: Vec<String>,
    /// The report's duty-cycle section.
    pub section: Section,
    /// The spectrum's figures (`train_duty_figures`).
    pub figures: Vec<DutyFigure>,
}

impl TrainDutyParts {
    /// The parts of `runs` under `ts`'s spectrum.
    pub fn of(ts: &TrainSpectrum, runs: &[&TrainSpectrumRun]) -> Self {
        Self {
            summary: train_duty_summary(ts, runs),
            lines: train_duty_lines(ts, runs),
            section: train_duty_section(ts, runs),
            figures: train_duty_figures(ts, runs),
        }
    }

    /// Add the summary, the lines and the figures (each with its table) to a train's
    /// wear artifacts.
    pub fn add_to(&self, a: &mut super::artifacts::Artifacts) {
        a.summary["load_spectrum"] = self.summary.clone();
        for f in &self.figures {
            a.figure_with_data(format!("{}.png", f.stem), f.figure.clone(), f.table.clone());
        }
        for l in &self.lines {
            if !a.headline.is_empty() {
                a.headline.push('\n');
            }
            a.headline.push_str(l);
        }
    }
}
