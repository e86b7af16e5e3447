//! Results of a duty cycle: what `wear` writes under a load spectrum (the single-point
//! outputs of the spectrum's run, read at the monitoring bin, plus what each bin did),
//! and the duty-cycle section `run` adds to its report (the spectrum, wear per bin, the
//! life under the spectrum against the life at each bin).

use super::artifacts::Artifacts;
use super::duty_figures::{
    dynamic_factor_figure, life_figure, spectrum_figure, time_shares, wear_by_bin_figure,
    DutyFigure,
};
use super::html::{format_value, FigureBlock, Section, TableBlock};
use super::wear::wear_artifacts;
use crate::duty::contribution::{combined_run, ranking, BinWear};
use crate::duty::life::{Life, LifeTable};
use crate::duty::wear::SpectrumRun;
use crate::duty::SpectrumModel;
use crate::format::{shown, shown_percent};
use crate::io::Table;
use crate::study::wear_loop::{WearMode, WearRun};
use serde_json::{json, Value};

/// The bins ranked by share of the pinion's wear, as a table (`duty/bins_MODE.csv`).
pub fn ranking_table(sm: &SpectrumModel, r: &[BinWear]) -> Table {
    let col = |f: &dyn Fn(&BinWear) -> f64| r.iter().map(f).collect::<Vec<f64>>();
    let case = |b: &BinWear| sm.bins[b.bin - 1].case.operating.clone();
    Table::new()
        .col("rank", (1..=r.len()).map(|i| i as f64).collect())
        .col("bin", col(&|b| b.bin as f64))
        .col("torque_nm", col(&|b| case(b).load_torque_nm))
        .col("input_speed_hz", col(&|b| case(b).input_speed_hz))
        .col("share_of_cycles", col(&|b| b.share_of_cycles))
        .col("share_of_pinion_wear", col(&|b| b.share_of_pinion_wear))
        .col("share_of_gear_wear", col(&|b| b.share_of_gear_wear))
        .col(
            "share_at_max_pinion_wear",
            col(&|b| b.share_at_max_pinion_wear),
        )
        .col("max_pinion_wear_added_um", col(&|b| b.max_pinion_added_um))
        .col("wear_intensity", col(&|b| b.wear_intensity))
}

/// summary.json's `load_spectrum`: the bins as used, and per run the ranking and the
/// dynamic factor of each bin on new and on the last worn teeth; the life table if any.
pub fn duty_summary(sm: &SpectrumModel, runs: &[&SpectrumRun], life: Option<&LifeTable>) -> Value {
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
                "mesh_frequency_hz": m.params.operating.mesh_frequency_hz,
                "share_of_cycles": sm.shares[i],
                "share_of_time": time.get(i),
            })
        })
        .collect();
    let mut v = json!({
        "bins": bins,
        "monitoring_bin": sm.monitoring + 1,
        "seconds_per_cycle": s.seconds_per_cycle(),
        "notes": "Each update advances every bin by its share of the block's cycles on the shared worn profile (docs/MODEL.md, section 10). The single-point outputs (updates_*.csv, wear_profiles_*.csv, Fig. 11-13) hold the spectrum's wear and the response at the monitoring bin.",
    });
    for r in runs {
        let df = crate::duty::contribution::dynamic_factors(r);
        v[r.mode.name()] = json!({
            "ranking": ranking(r),
            "dynamic_factor_new_teeth": df.first(),
            "dynamic_factor_last_update": df.last(),
            "cycles": r.last().map(|x| x.wear.cycles),
        });
    }
    if let Some(l) = life {
        v["life"] = json!(l);
    }
    v
}

/// The figures of a duty cycle for `runs` (and the life table when given).
pub fn duty_figures(
    sm: &SpectrumModel,
    runs: &[&SpectrumRun],
    life: Option<&LifeTable>,
) -> Vec<DutyFigure> {
    let s = sm.spectrum();
    let dynamic = runs
        .iter()
        .find(|r| r.mode == WearMode::Dynamic)
        .or(runs.first());
    let rank = dynamic.map(|r| ranking(r));
    let mut figs = vec![spectrum_figure(&s, rank.as_deref())];
    let grid = &sm.bins[0].grid;
    for r in runs {
        figs.extend(wear_by_bin_figure(grid, r));
        figs.push(dynamic_factor_figure(r));
    }
    if let Some(l) = life {
        figs.push(life_figure(l));
    }
    figs
}

/// Everything `wear` writes under a load spectrum: the single-point outputs of the
/// spectrum's runs (monitoring bin), the rankings and the duty figures, the summary's
/// `load_spectrum`, and the life table when given.
pub fn duty_wear_artifacts(
    sm: &SpectrumModel,
    runs: &[&SpectrumRun],
    life: Option<&LifeTable>,
) -> Artifacts {
    let combined: Vec<WearRun> = runs
        .iter()
        .map(|r| combined_run(r, sm.monitoring))
        .collect();
    let refs: Vec<&WearRun> = combined.iter().collect();
    let mut a = wear_artifacts(&sm.bins[sm.monitoring], &refs);
    a.summary["warnings"] = json!(sm.warnings());
    for r in runs {
        a.table(
            format!("duty/bins_{}.csv", r.mode.name()),
            ranking_table(sm, &ranking(r)),
        );
    }
    for f in duty_figures(sm, runs, life) {
        a.figure_with_data(format!("{}.png", f.stem), f.figure, f.table);
    }
    a.summary["load_spectrum"] = duty_summary(sm, runs, life);
    a.headline.push_str(&duty_headline(sm, runs));
    if let Some(l) = life {
        a.headline.push_str(&life_headline(l));
    }
    a
}

/// The life line: cycles and hours under the spectrum, and the linear mix of the bins'.
fn life_headline(l: &LifeTable) -> String {
    format!(
        "\nlife to {} µm ({}): {} cycles{} under the spectrum, {} cycles by the linear mix of the bins' lives",
        shown(l.limit_um),
        l.mode.label(),
        life_words(&l.spectrum),
        l.spectrum_hours
            .map_or(String::new(), |h| format!(" ({} h)", shown(h))),
        l.linear_mix_cycles.map_or("-".into(), format_value)
    )
}

/// A line naming the bin that wears most, per run.
fn duty_headline(sm: &SpectrumModel, runs: &[&SpectrumRun]) -> String {
    runs.iter()
        .filter_map(|r| {
            let top = ranking(r).into_iter().next()?;
            Some(format!(
                "\n{}: {} bins; bin {} ({} N m, {} Hz) did {} of the pinion's wear in {} of the cycles",
                r.mode.label(),
                sm.len(),
                top.bin,
                shown(sm.bins[top.bin - 1].case.operating.load_torque_nm),
                shown(sm.bins[top.bin - 1].case.operating.input_speed_hz),
                shown_percent(top.share_of_pinion_wear),
                shown_percent(top.share_of_cycles)
            ))
        })
        .collect()
}

fn life_words(l: &Life) -> String {
    match l {
        Life::Reached { cycles } => format_value(*cycles),
        Life::Beyond { cycles, .. } => format!("> {}", format_value(*cycles)),
    }
}

fn hours(h: Option<f64>) -> String {
    h.map_or("-".into(), format_value)
}

/// The duty-cycle section of the `run` report; `figs`: the rendered duty figures, in
/// [`duty_figures`] order.
pub fn duty_section(
    sm: &SpectrumModel,
    run: &SpectrumRun,
    life: Option<&LifeTable>,
    figs: Vec<FigureBlock>,
) -> Section {
    let mut tables = vec![spectrum_table(sm, run)];
    let mut paragraphs = vec![format!(
        "The gearbox runs through {} operating bins. Every wear update advances all of them on the shared worn profile, each by its share of the block's cycles (docs/MODEL.md, section 10); the single-point figures above show the spectrum's wear and the response at bin {} (the monitoring bin). A bin whose share of the wear exceeds its share of the cycles wears the flanks faster than its time suggests.",
        sm.len(),
        sm.monitoring + 1
    )];
    if let Some(l) = life {
        paragraphs.push(life_paragraph(l));
        tables.push(life_table(l));
    }
    Section {
        heading: "Duty cycle: wear and life under the load spectrum".into(),
        paragraphs,
        figures: figs,
        tables,
    }
}

/// The load spectrum's table: each bin's torque, speed, shares of cycles, time and pinion
/// wear, and its dynamic factor on new and on the last teeth.
fn spectrum_table(sm: &SpectrumModel, run: &SpectrumRun) -> TableBlock {
    let s = sm.spectrum();
    let time = time_shares(&s);
    let rank = ranking(run);
    let wear_of = |bin: usize| rank.iter().find(|b| b.bin == bin);
    TableBlock {
        caption: format!(
            "The load spectrum (torques on the {} shaft) and each bin's part of the pinion's wear ({} run).",
            match s.shaft(sm.case.operating.load_torque_shaft) {
                crate::config::case::TorqueShaft::Pinion => "pinion",
                crate::config::case::TorqueShaft::Gear => "gear",
            },
            run.mode.label()
        ),
        header: [
            "bin", "torque (N m)", "input speed (Hz)", "share of cycles", "share of time",
            "share of pinion wear", "wear / cycles share", "dynamic factor, new → last",
        ]
        .map(String::from)
        .to_vec(),
        rows: (0..sm.len())
            .map(|i| {
                let w = wear_of(i + 1);
                let df = |r: Option<&crate::duty::wear::SpectrumRecord>| {
                    r.map_or(f64::NAN, |x| x.bins[i].summary.dynamic_factor)
                };
                vec![
                    format!("{}", i + 1),
                    format_value(sm.bins[i].case.operating.load_torque_nm),
                    format_value(sm.bins[i].case.operating.input_speed_hz),
                    format_value(sm.shares[i]),
                    format_value(time[i]),
                    w.map_or("-".into(), |b| format_value(b.share_of_pinion_wear)),
                    w.map_or("-".into(), |b| format_value(b.wear_intensity)),
                    format!(
                        "{} → {}",
                        format_value(df(run.records.first())),
                        format_value(df(run.records.last()))
                    ),
                ]
            })
            .collect(),
        highlight_col: Some(5),
    }
}

/// The sentence on life to the wear limit under the spectrum against the linear mix of
/// the bins' own lives.
fn life_paragraph(l: &LifeTable) -> String {
    format!(
        "Life to {} µm of maximum pinion wear ({}): {} cycles under the spectrum ({} h); the linear mix of the bins' own lives, 1 / Σ s_i / L_i, gives {} cycles. Where the two differ, the bins interact through the worn profile.",
        l.limit_um,
        l.mode.label(),
        life_words(&l.spectrum),
        hours(l.spectrum_hours),
        l.linear_mix_cycles.map_or("-".into(), format_value)
    )
}

/// The table of cycles (and hours) to the wear limit under the spectrum and at each bin
/// alone.
fn life_table(l: &LifeTable) -> TableBlock {
    let mut rows = vec![vec![
        "spectrum".into(),
        "-".into(),
        "-".into(),
        life_words(&l.spectrum),
        hours(l.spectrum_hours),
    ]];
    rows.extend(l.bins.iter().map(|b| {
        vec![
            format!("bin {} alone", b.bin),
            format_value(b.torque_nm),
            format_value(b.input_speed_hz),
            life_words(&b.life),
            hours(b.hours),
        ]
    }));
    TableBlock {
        caption: "Cycles (and hours) to the wear limit under the spectrum and at each bin alone."
            .into(),
        header: [
            "duty",
            "torque (N m)",
            "input speed (Hz)",
            "cycles to the limit",
            "hours",
        ]
        .map(String::from)
        .to_vec(),
        rows,
        highlight_col: Some(3),
    }
}

/// Everything `run` writes under a load spectrum: the paper's section 4 on the spectrum's
/// runs (responses at the monitoring bin, never set beside the paper's numbers: the paper
/// runs one operating point), the duty figures with their data, the spectrum's tables,
/// summary.json's `load_spectrum`, and the report with its duty-cycle section; the
/// figures in the formats and size of `figures`.
pub fn duty_run_artifacts(
    sm: &SpectrumModel,
    study: &crate::duty::study::DutyStudy,
    meta: &crate::store::RunMetadata,
    figures: super::figure_output::FigureOutput,
) -> Option<Artifacts> {
    use super::artifacts::{embed_figures, EmbeddedFigure};
    let paper = study.paper.as_ref()?;
    let monitor = &sm.bins[sm.monitoring];
    let (mut a, mut report) =
        super::paper::run_artifacts_and_report(monitor, paper, meta, None, figures);
    let runs: Vec<&SpectrumRun> = study.runs.iter().collect();
    let figs = duty_figures(sm, &runs, study.life.as_ref());
    let blocks = embed_figures(
        &mut a,
        figs.into_iter()
            .map(|f| EmbeddedFigure {
                caption: format!("{}.", f.figure.title),
                stem: f.stem,
                figure: f.figure,
                table: f.table,
            })
            .collect(),
    );
    for r in &runs {
        a.table(
            format!("csv/duty_bins_{}.csv", r.mode.name()),
            ranking_table(sm, &ranking(r)),
        );
    }
    let main = study.run(WearMode::Dynamic).or(runs.first().copied())?;
    report
        .sections
        .push(duty_section(sm, main, study.life.as_ref(), blocks));
    report.title = format!("{} under a load spectrum", report.title);
    a.summary["differs_from_paper_case_in"] = json!(super::case::paper_case_differences(&sm.case));
    a.summary["load_spectrum"] = duty_summary(sm, &runs, study.life.as_ref());
    a.summary["warnings"] = json!(sm.warnings());
    a.headline.push_str(&duty_headline(sm, &runs));
    if let Some(l) = &study.life {
        a.headline.push_str(&life_headline(l));
    }
    a.documents.push((
        "report.html".into(),
        super::html::render(&report).into_bytes(),
    ));
    Some(a)
}
