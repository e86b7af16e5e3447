//! The worn tooth profiles of a wear study: accumulated wear depth along the pinion and
//! gear profiles at several cycle counts (`worn_profiles_MODE.png` of `wear` and `run`).

use super::figures::{scale_panel, Curve};
use super::plot::Figure;
use crate::io::{format_number, Table};
use crate::study::wear_loop::{UpdateRecord, WearRun};
use crate::study::Model;

/// Worn states shown per figure at most (plus evenly spaced records up to the last).
pub const SHOWN_STATES: usize = 6;

/// A worn-profile figure, its file stem and the table of exactly its data.
pub struct WornProfileFigure {
    /// File stem.
    pub stem: String,
    /// The figure.
    pub figure: Figure,
    /// Exactly the plotted numbers.
    pub table: Table,
}

/// The records shown: up to [`SHOWN_STATES`] spread evenly over the run's updates, the
/// last included, new teeth (no wear) left out.
pub fn shown_records(run: &WearRun) -> Vec<&UpdateRecord> {
    let n = run.records.len();
    if n < 2 {
        return Vec::new();
    }
    let mut idx: Vec<usize> = (1..=SHOWN_STATES)
        .map(|k| (k * (n - 1)).div_ceil(SHOWN_STATES))
        .collect();
    idx.dedup();
    idx.into_iter().map(|i| &run.records[i]).collect()
}

/// The profile of one gear at a record: the shared profile, or with per-tooth wear the
/// worst tooth's (the one holding the largest depth at that cycle count; on a helical
/// pair the worst slice of a tooth), so the curve's
/// maximum is the study's maximum wear depth (`updates_MODE.csv`).
fn profile_m(r: &UpdateRecord, pinion: bool) -> Vec<f64> {
    let shared = if pinion {
        &r.wear.pinion_m
    } else {
        &r.wear.gear_m
    };
    let Some(t) = &r.wear.teeth else {
        return shared.clone();
    };
    let teeth = if pinion { &t.pinion_m } else { &t.gear_m };
    let peak = |p: &Vec<f64>| p.iter().fold(0.0_f64, |a, b| a.max(*b));
    teeth
        .iter()
        .max_by(|a, b| peak(a).total_cmp(&peak(b)))
        .cloned()
        .unwrap_or_else(|| shared.clone())
}

/// The worn pinion and gear profiles of `run` at the [`shown_records`], one panel per gear,
/// coloured by load cycles; `None` when the run has no update.
pub fn worn_profile_figure(model: &Model, run: &WearRun) -> Option<WornProfileFigure> {
    let shown = shown_records(run);
    let (first, last) = (shown.first()?, shown.last()?);
    let (m, label) = (run.mode.name(), run.mode.label());
    let rho_mm: Vec<f64> = model.grid.rho_pinion_m.iter().map(|x| x * 1e3).collect();
    let per_tooth = first.wear.teeth.is_some();
    // A helical pair's per-tooth state holds every tooth's face slices (z N profiles a
    // gear): the worst profile is then one slice of one tooth.
    let sliced = first
        .wear
        .teeth
        .as_ref()
        .is_some_and(|t| t.pinion_m.len() > model.pair.pinion.teeth);
    let which = match (per_tooth, sliced) {
        (true, true) => ", worst tooth slice",
        (true, false) => ", worst tooth",
        _ => "",
    };
    let mut table = Table::new().col("rho1_mm", rho_mm.clone());
    let mut panels = Vec::new();
    let names = [
        (true, "pinion"),
        (false, "gear (conjugate points: its tip at the left)"),
    ];
    for (pinion, gear) in names {
        let mut curves = Vec::new();
        for r in &shown {
            let um: Vec<f64> = profile_m(r, pinion).iter().map(|x| x * 1e6).collect();
            let g = if pinion { "pinion" } else { "gear" };
            let col = format!("wear_{g}_um_at_{}_cycles", format_number(r.wear.cycles));
            table = table.col(&col, um.clone());
            curves.push((r.wear.cycles, Curve::new("", rho_mm.clone(), um)));
        }
        let title = format!("{gear}{which}");
        let scale = ("load cycles", 0.0, last.wear.cycles);
        panels.push(scale_panel(
            &title,
            "contact point: pinion roll distance along the path of contact (mm)",
            "wear depth (µm)",
            curves,
            scale,
        ));
    }
    Some(WornProfileFigure {
        stem: format!("worn_profiles_{m}"),
        figure: Figure {
            title: format!("Worn tooth profiles ({label} wear study)"),
            panels,
        },
        table,
    })
}

/// The worn-profile figures of the runs present, in the order given.
pub fn worn_profile_figures(model: &Model, runs: &[&WearRun]) -> Vec<WornProfileFigure> {
    runs.iter()
        .filter_map(|r| worn_profile_figure(model, r))
        .collect()
}
