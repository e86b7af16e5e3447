//! Results of a planetary set (`[planetary]`) under a load spectrum
//! (`duty::planetary`): the set's own outputs (`report::wear_planetary`) of the
//! spectrum's run read as one run of the set (every mesh's shared wear, its wear per
//! pinion cycle under the spectrum, the monitoring bin's response), plus `load_spectrum`
//! in `summary.json`, a table per mode, lines on stdout and the report's duty-cycle
//! section.
//!
//! - `load_spectrum` (summary.json): the bins as used (the input member's torque and
//!   speed, shares of cycles and of time) with every member's speed and the mesh
//!   frequency at each bin, the monitoring bin, the seconds per input cycle, and per mode
//!   the input cycles and hours run, per member flank its wear, the share of its volume
//!   and the largest depth each bin added and its life to the wear limit, and the member
//!   that limits the set's life (`duty::planetary_life`).
//! - `duty_by_bin_MODE.csv`: a row per bin (its number, torque, speed and share of
//!   cycles), then for every member flank the share of its wear volume the bin added and
//!   the largest depth it added (µm).
//! - The spectrum's figure (`duty_spectrum.png`, `report::duty_figures::spectrum_figure`).

use super::artifacts::Artifacts;
use super::duty_figures::{spectrum_figure, time_shares};
use super::html::{Section, TableBlock};
use crate::duty::life::Life;
use crate::duty::planetary::{PlanetarySpectrum, PlanetarySpectrumRun};
use crate::duty::planetary_life::{set_under_spectrum, SetUnderSpectrum};
use crate::format::{shown, shown_percent};
use crate::io::Table;
use serde_json::{json, Value};

/// A flank's column stem, e.g. `planet_2_ring_side` (as `report::wear_planetary`'s).
fn stem(member: &str, flank: &str) -> String {
    if member == flank {
        member.to_string()
    } else {
        format!("{member}_{flank}")
    }
}

/// `summary.json`'s `load_spectrum` (see the module docs).
pub fn planetary_duty_summary(ps: &PlanetarySpectrum, runs: &[&PlanetarySpectrumRun]) -> Value {
    let time = time_shares(&ps.spectrum);
    let bins: Vec<Value> = ps
        .models
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let s = &m.dynamics.study;
            json!({
                "bin": i + 1,
                "input_member": s.set.input.name(),
                "input_torque_nm": ps.spectrum.torque_nm(i),
                "input_speed_hz": ps.spectrum.input_speed_hz(i),
                "share_of_cycles": ps.shares[i],
                "share_of_time": time.get(i),
                "member_speeds_hz": {"sun": s.speeds_hz[0], "carrier": s.speeds_hz[1], "ring": s.speeds_hz[2]},
                "mesh_frequency_hz": s.set.mesh_frequency_hz(s.speeds_hz),
            })
        })
        .collect();
    let mut v = json!({
        "bins": bins,
        "monitoring_bin": ps.monitoring + 1,
        "seconds_per_input_cycle": ps.seconds_per_input_cycle(),
        "notes": "Each bin is the set at the bin's operating point: its torque_nm and input_speed_hz are the input member's (planetary.input). Shares are shares of input cycles; each update advances every mesh by every bin's share of the block on the shared worn flanks (docs/MODEL.md 12.12). The set's outputs (wear_history_*.csv, mesh_history_*.csv, wear_profiles_*.csv, planetary_wear) hold the spectrum's wear and the response at the monitoring bin.",
    });
    for r in runs {
        v[r.mode.name()] = json!(set_under_spectrum(ps, r));
    }
    v
}

/// `duty_by_bin_MODE.csv` of `u` (see the module docs).
pub fn by_bin_table(ps: &PlanetarySpectrum, u: &SetUnderSpectrum) -> Table {
    let n = ps.bins();
    let s = &ps.spectrum;
    let mut t = Table::new()
        .col("bin", (1..=n).map(|i| i as f64).collect())
        .col("input_torque_nm", (0..n).map(|i| s.torque_nm(i)).collect())
        .col(
            "input_speed_hz",
            (0..n).map(|i| s.input_speed_hz(i)).collect(),
        )
        .col("share_of_cycles", ps.shares.clone());
    for f in &u.flanks {
        let st = stem(&f.member, &f.flank);
        t = t
            .col(
                &format!("share_of_volume_{st}"),
                f.share_of_volume_by_bin.clone(),
            )
            .col(
                &format!("max_wear_added_{st}_um"),
                f.max_wear_added_by_bin_um.clone(),
            );
    }
    t
}

/// A life in words.
fn life_words(hours: Option<f64>, life: &Life) -> String {
    match (life.cycles(), hours) {
        (Some(n), Some(h)) => format!("{} input cycles = {} h", shown(n), shown(h)),
        _ => "not reached within the run".into(),
    }
}

/// The lines on stdout for the runs under the spectrum.
pub fn planetary_duty_lines(ps: &PlanetarySpectrum, runs: &[&PlanetarySpectrumRun]) -> Vec<String> {
    let mut lines = Vec::new();
    for r in runs {
        let Some(u) = set_under_spectrum(ps, r) else {
            continue;
        };
        let mode = r.mode.label();
        lines.push(format!(
            "{mode}, under the load spectrum ({} bins): {} input cycles = {} h",
            ps.bins(),
            shown(u.input_cycles),
            shown(u.hours)
        ));
        if let (Some(m), Some(f)) = (&u.limiting_member, &u.limiting_flank) {
            let life = match (u.life_input_cycles, u.life_hours) {
                (Some(n), Some(h)) => format!("{} input cycles = {} h", shown(n), shown(h)),
                _ => "not reached within the run".into(),
            };
            let by_bin = u
                .flanks
                .iter()
                .find(|x| &x.member == m && &x.flank == f)
                .map(|x| {
                    x.share_of_volume_by_bin
                        .iter()
                        .enumerate()
                        .map(|(i, s)| format!("bin {} {}", i + 1, shown_percent(*s)))
                        .collect::<Vec<_>>()
                        .join(", ")
                })
                .unwrap_or_default();
            lines.push(format!(
                "{mode}: the {} ({} flank) limits the set's life to {} µm: {life}; its wear volume by bin: {by_bin}",
                m.replace('_', " "),
                f.replace('_', " "),
                shown(u.life_wear_limit_um),
            ));
        }
    }
    lines
}

/// The report's duty-cycle section: the bins with every member's speed, and per mode
/// every member flank's wear, the bins' shares of it and its life.
pub fn planetary_duty_section(ps: &PlanetarySpectrum, runs: &[&PlanetarySpectrumRun]) -> Section {
    let rows = ps
        .models
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let w = m.dynamics.study.speeds_hz;
            vec![
                (i + 1).to_string(),
                shown(ps.spectrum.torque_nm(i)),
                shown(ps.spectrum.input_speed_hz(i)),
                shown_percent(ps.shares[i]),
                shown(w[0]),
                shown(w[1]),
                shown(w[2]),
            ]
        })
        .collect();
    let mut tables = vec![TableBlock {
        caption: "The load spectrum: each bin's input member torque and speed, its share of the input cycles and every member's speed (Willis).".into(),
        header: ["bin", "input torque (N m)", "input speed (Hz)", "share of cycles", "sun (Hz)", "carrier (Hz)", "ring (Hz)"]
            .map(String::from)
            .to_vec(),
        rows,
        highlight_col: None,
    }];
    for r in runs {
        if let Some(u) = set_under_spectrum(ps, r) {
            tables.push(flank_table(r.mode.label(), &u));
        }
    }
    Section {
        heading: "Duty cycle: the set's wear and life under the load spectrum".into(),
        paragraphs: vec![format!(
            "The set runs through {} operating bins. Every wear update advances every mesh by every bin's share of the block's input cycles on the shared worn flanks (docs/MODEL.md 12.12); the wear sections show the spectrum's wear and the response at bin {} (the monitoring bin). The member flank whose wear reaches the limit first limits the set's life.",
            ps.bins(),
            ps.monitoring + 1
        )],
        figures: Vec::new(),
        tables,
    }
}

/// Per member flank: its wear, the share of its volume each bin added and its life.
fn flank_table(mode: &str, u: &SetUnderSpectrum) -> TableBlock {
    let rows = u
        .flanks
        .iter()
        .map(|f| {
            let by_bin: Vec<String> = f
                .share_of_volume_by_bin
                .iter()
                .map(|x| shown_percent(*x))
                .collect();
            vec![
                format!("{} ({})", f.member, f.flank).replace('_', " "),
                shown(f.max_wear_um),
                shown(f.volume_mm3),
                by_bin.join(" / "),
                life_words(f.life_hours, &f.life),
            ]
        })
        .collect();
    TableBlock {
        caption: format!(
            "{mode}: every member flank's wear after {} input cycles ({} h), the share of its wear volume each bin added, and its life to {} µm.",
            shown(u.input_cycles),
            shown(u.hours),
            shown(u.life_wear_limit_um)
        ),
        header: ["member (flank)", "max wear (µm)", "volume (mm^3)", "volume by bin", "life"]
            .map(String::from)
            .to_vec(),
        rows,
        highlight_col: None,
    }
}

/// Add what the spectrum adds to a set's wear artifacts `a`: `load_spectrum` in the
/// summary, a `duty_by_bin_MODE.csv` per mode, the spectrum's figure and the lines.
pub fn add_planetary_duty(
    ps: &PlanetarySpectrum,
    runs: &[&PlanetarySpectrumRun],
    a: &mut Artifacts,
) {
    a.summary["load_spectrum"] = planetary_duty_summary(ps, runs);
    for r in runs {
        if let Some(u) = set_under_spectrum(ps, r) {
            a.table(
                format!("duty_by_bin_{}.csv", r.mode.name()),
                by_bin_table(ps, &u),
            );
        }
    }
    let f = spectrum_figure(&ps.spectrum, None);
    a.figure_with_data(format!("{}.png", f.stem), f.figure, f.table);
    for l in planetary_duty_lines(ps, runs) {
        if !a.headline.is_empty() {
            a.headline.push('\n');
        }
        a.headline.push_str(&l);
    }
}
