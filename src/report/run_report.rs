//! The text of `gearwear run`: the HTML report's sections and the headline on standard
//! output. For the paper's case, the comparison with the paper's numbers; for any other
//! case, a summary of the case that was run. Every number comes from the run.

use super::case::{
    cycles_words, load_sentence, load_words, mesh_frequency_hz, poles_sentence, static_mesh_force_n,
};
use super::comparison::{cycles_reached, Compared};
use super::html::{self, FigureBlock, Report, Section, TableBlock};
use crate::config::case::ContactPathModel;
use crate::format::shown;
use crate::store::RunMetadata;
use crate::study::paper::PaperStudy;
use crate::study::wear_loop::WearRun;
use crate::study::Model;
use serde_json::{json, Value};

/// Maximum accumulated pinion wear at the end of a run, um.
fn final_wear_um(r: &WearRun) -> f64 {
    r.last().map_or(f64::NAN, |x| x.wear.max_pinion_m() * 1e6)
}

/// Maximum accumulated pinion wear of a run at `cycles`, um.
fn wear_at_um(r: &WearRun, cycles: f64) -> f64 {
    super::wear::at_cycles(&r.cycles(), &r.max_wear_pinion_m(), cycles) * 1e6
}

/// Largest per-cycle pinion wear of a run's final state, um per 1000 cycles.
fn final_rate_um_per_kcycle(r: &WearRun) -> f64 {
    r.last()
        .map_or(f64::NAN, |x| x.max_increment_pinion_m() * 1e9)
}

/// The key results of a run (new teeth, end of the wear study), display units in the names.
pub fn results_json(study: &PaperStudy) -> Value {
    let new = study.dynamic.records.first().map(|r| &r.summary);
    let (d, q) = (&study.dynamic, &study.quasi_static);
    json!({
        "new_teeth": new.map(|s| json!({
            "dte_max_um": s.dte_max_m * 1e6,
            "mesh_force_mean_n": s.mesh_force_mean_n,
            "mesh_force_max_n": s.mesh_force_max_n,
            "dynamic_factor": s.dynamic_factor,
            "velocity_y_pinion_rms_mm_per_s": s.velocity_y_pinion_rms_m_per_s * 1e3,
        })),
        "max_wear_pinion_um": {"dynamic": final_wear_um(d), "quasi_static": final_wear_um(q)},
        "max_wear_rate_pinion_um_per_kcycle": {
            "dynamic": final_rate_um_per_kcycle(d),
            "quasi_static": final_rate_um_per_kcycle(q),
        },
        "ratio_max_wear_dynamic_to_static": wear_at_um(d, cycles_reached(study)) / wear_at_um(q, cycles_reached(study)),
        "ratio_at_cycles": cycles_reached(study),
    })
}

/// "z = 25/50, m = 3 mm, b = 30 mm".
fn pair_words(model: &Model) -> String {
    let g = &model.case.gear;
    format!(
        "z = {}/{}, m = {} mm, b = {} mm",
        g.teeth_pinion,
        g.teeth_gear,
        shown(g.module_mm),
        shown(g.face_width_mm)
    )
}

/// The run's headline for the paper's case: the comparison, one line per number, with
/// the nominal path's value (the paper's model), the extended contact's (the default)
/// and the paper's.
pub fn comparison_headline(rows: &[Compared]) -> String {
    let value = |r: &Compared, path| match r.under(path) {
        Some(v) => format!(
            "{:>6} ({:>7})",
            shown(v),
            super::html::format_deviation(v, r.paper)
        ),
        None => format!("{:>16}", "not run"),
    };
    let line = |r: &Compared| {
        format!(
            "{:<74} nominal path {}  extended {}  paper {:>6}",
            r.quantity,
            value(r, ContactPathModel::Nominal),
            value(r, ContactPathModel::Extended),
            shown(r.paper),
        )
    };
    rows.iter().map(line).collect::<Vec<_>>().join("\n")
}

/// The run's headline for any other case: the case, the new teeth, the end of the study.
pub fn case_headline(model: &Model, study: &PaperStudy) -> String {
    let c = &model.case;
    let mut lines = vec![format!(
        "case: {}, {}, {} Hz input, mesh frequency {} Hz, {} cycles",
        pair_words(model),
        load_words(c),
        shown(c.operating.input_speed_hz),
        shown(mesh_frequency_hz(model)),
        cycles_words(c.wear.total_cycles)
    )];
    if let Some(s) = study.dynamic.records.first().map(|r| &r.summary) {
        lines.push(format!(
            "new teeth: max DTE {} µm, mean mesh force {} N, dynamic factor {}, RMS dy_p/dt {} mm/s",
            shown(s.dte_max_m * 1e6),
            shown(s.mesh_force_mean_n),
            shown(s.dynamic_factor),
            shown(s.velocity_y_pinion_rms_m_per_s * 1e3)
        ));
    }
    let at = cycles_reached(study);
    let (d, q) = (
        wear_at_um(&study.dynamic, at),
        wear_at_um(&study.quasi_static, at),
    );
    lines.push(format!(
        "after {} cycles{}: maximum pinion wear {} µm dynamic, {} µm quasi-static (ratio {})",
        cycles_words(at),
        super::wear::ratio_where(&[&study.dynamic, &study.quasi_static], at),
        shown(d),
        shown(q),
        shown(d / q)
    ));
    lines.join("\n")
}

/// The comparison table of the report: quantity | paper | nominal path (the paper's
/// model) and its deviation | extended contact (the default) and its deviation |
/// explanation, the nominal path's deviation highlighted (the reproduction's check). A
/// quantity compared at several wear states shares one explanation: it is written once,
/// at its first row, and the later rows point to that row.
fn comparison_table(caption: &str, rows: &[Compared]) -> TableBlock {
    let header = [
        "quantity",
        "paper",
        "nominal path (paper's model)",
        "relative deviation",
        "extended contact (default)",
        "relative deviation",
        "explanation",
    ];
    let under = |r: &Compared, path| match r.under(path) {
        Some(v) => [html::format_value(v), html::format_deviation(v, r.paper)],
        None => ["not run".into(), "n/a".into()],
    };
    let rows = rows
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let [n, dn] = under(r, ContactPathModel::Nominal);
            let [e, de] = under(r, ContactPathModel::Extended);
            let explanation = match rows[..i].iter().find(|p| p.explanation == r.explanation) {
                Some(first) => format!("As for \"{}\" above.", first.quantity),
                None => r.explanation.clone(),
            };
            let paper = html::format_value(r.paper);
            vec![r.quantity.clone(), paper, n, dn, e, de, explanation]
        })
        .collect();
    TableBlock {
        caption: caption.into(),
        header: header.iter().map(|h| h.to_string()).collect(),
        rows,
        highlight_col: Some(3),
    }
}

/// "1 dynamic update", "4 quasi-static updates".
fn updates_words(n: usize, mode: &str) -> String {
    let s = if n == 1 { "" } else { "s" };
    format!("{n} {mode} update{s}")
}

fn value_row(quantity: &str, value: String) -> Vec<String> {
    vec![quantity.to_string(), value]
}

/// The table that takes the comparison's place for a case that is not the paper's.
fn case_table(model: &Model, study: &PaperStudy) -> TableBlock {
    let c = &model.case;
    let mut rows = vec![
        value_row("gear pair", pair_words(model)),
        value_row("pressure angle (deg)", shown(c.gear.pressure_angle_deg)),
        value_row("contact ratio (-)", shown(model.pair.contact_ratio)),
        value_row("load", load_words(c)),
        value_row("input speed (Hz)", shown(c.operating.input_speed_hz)),
        value_row("mesh frequency (Hz)", shown(mesh_frequency_hz(model))),
        value_row(
            "mean mesh force without friction (N)",
            shown(static_mesh_force_n(model)),
        ),
        value_row(
            "pinion / gear speed (rad/s)",
            format!(
                "{} / {}",
                html::format_value(model.params.operating.pinion_speed_rad_s),
                html::format_value(model.params.operating.gear_speed_rad_s)
            ),
        ),
        value_row(
            "torque on the pinion / gear shaft (N m)",
            format!(
                "{} / {}",
                html::format_value(model.params.operating.motor_torque_nm),
                html::format_value(model.params.operating.brake_torque_nm)
            ),
        ),
    ];
    // The values the case may leave to the geometry, as the model used them.
    for v in model.resolved_parameters().values {
        rows.push(value_row(
            &format!("{} ({})", v.key, v.unit),
            format!(
                "{}{}",
                html::format_value(v.value),
                if v.derived { " (derived)" } else { "" }
            ),
        ));
    }
    rows.extend([
        value_row(
            "mean mesh stiffness (N/m)",
            html::format_value(model.mesh.mean_stiffness_n_per_m()),
        ),
        value_row(
            "wear coefficient (m^2/N)",
            format!("{:e}", c.wear.coefficient_m2_per_n),
        ),
        value_row("load cycles", cycles_words(c.wear.total_cycles)),
    ]);
    if let Some(s) = study.dynamic.records.first().map(|r| &r.summary) {
        rows.push(value_row(
            "max DTE, new teeth (µm)",
            html::format_value(s.dte_max_m * 1e6),
        ));
        rows.push(value_row(
            "mean mesh force, new teeth (N)",
            html::format_value(s.mesh_force_mean_n),
        ));
        rows.push(value_row(
            "dynamic factor (max / mean mesh force), new teeth (-)",
            html::format_value(s.dynamic_factor),
        ));
        rows.push(value_row(
            "RMS of dy_p/dt, new teeth (mm/s)",
            html::format_value(s.velocity_y_pinion_rms_m_per_s * 1e3),
        ));
    }
    let at = cycles_reached(study);
    let cycles = cycles_words(at);
    let (d, q) = (&study.dynamic, &study.quasi_static);
    let rate = |r: &WearRun| super::wear::max_rate_at(r, at) * 1e9;
    rows.push(value_row(
        &format!("max pinion wear after {cycles} cycles, dynamic / quasi-static (µm)"),
        format!(
            "{} / {}",
            html::format_value(wear_at_um(d, at)),
            html::format_value(wear_at_um(q, at))
        ),
    ));
    rows.push(value_row(
        &format!("max pinion wear per 1000 cycles at {cycles} cycles, dynamic / quasi-static (µm)"),
        format!(
            "{} / {}",
            html::format_value(rate(d)),
            html::format_value(rate(q))
        ),
    ));
    TableBlock {
        caption: "The case that was run and its key results.".into(),
        header: vec!["quantity".into(), "value".into()],
        rows,
        highlight_col: None,
    }
}

/// The dynamic response at the three wear states, as a table.
fn states_table(study: &PaperStudy) -> TableBlock {
    let f = html::format_value;
    TableBlock {
        caption: "Dynamic response at the three wear states.".into(),
        header: [
            "max pinion wear (µm)",
            "roughness (µm)",
            "max DTE (µm)",
            "RMS of dy_p/dt (mm/s)",
            "mean mesh force (N)",
            "dynamic factor (-)",
        ]
        .map(String::from)
        .to_vec(),
        rows: study
            .wear_states
            .iter()
            .map(|s| {
                vec![
                    f(s.max_wear_um),
                    f(s.roughness_um),
                    f(s.summary.dte_max_m * 1e6),
                    f(s.summary.velocity_y_pinion_rms_m_per_s * 1e3),
                    f(s.summary.mesh_force_mean_n),
                    f(s.summary.dynamic_factor),
                ]
            })
            .collect(),
        highlight_col: None,
    }
}

/// The HTML report of a run. `rows` is the paper comparison (empty for a case that is not
/// the paper's: then the case summary takes its place).
pub fn build_report(
    model: &Model,
    study: &PaperStudy,
    rows: &[Compared],
    figs: Vec<FigureBlock>,
    meta: &RunMetadata,
) -> Report {
    let paper = !rows.is_empty();
    let mut it = figs.into_iter();
    let mut take = |n: usize| it.by_ref().take(n).collect::<Vec<_>>();
    let (title, intro, first) = opening(model, study, rows);
    let tag = |s: &str| {
        if paper {
            format!(" (paper section {s})")
        } else {
            String::new()
        }
    };
    let (d, q) = (&study.dynamic, &study.quasi_static);
    let worn_figures = [d, q]
        .iter()
        .filter(|r| !super::worn_profile::shown_records(r).is_empty())
        .count();
    let stiffness = stiffness_section(model, tag("2"), take(1));
    let wear_effects = wear_effects_section(model, study, tag("4.1"), take(7));
    // Figs. 11-13 and the worn profiles of each run that updated.
    let dynamic_effects = dynamic_effects_section(study, tag("4.2"), take(3 + worn_figures));
    Report {
        title,
        intro_html: intro,
        sections: vec![first, stiffness, wear_effects, dynamic_effects]
            .into_iter()
            .chain(super::teeth::teeth_section(model, take(usize::MAX)))
            .collect(),
        footer: format!(
            "gearwear {} | case sha256 {} | command: run",
            meta.version, meta.case_sha256
        ),
    }
}

/// The report's title, introduction (HTML) and first section: the paper comparison when
/// `rows` has it, else the case summary.
fn opening(model: &Model, study: &PaperStudy, rows: &[Compared]) -> (String, String, Section) {
    let c = &model.case;
    let source = "<em>A Dynamic Wear Prediction Model for Studying the Interactions between Surface Wear and Dynamic Response of Spur Gears</em>, Coatings 2022, 12(9), 1250";
    let case_words = format!(
        "{}, {} Hz input (mesh frequency {:.0} Hz), {}, wear coefficient {:.2e} m²/N, {} cycles",
        pair_words(model),
        c.operating.input_speed_hz,
        mesh_frequency_hz(model),
        load_words(c),
        c.wear.coefficient_m2_per_n,
        cycles_words(c.wear.total_cycles)
    );
    if !rows.is_empty() {
        let table = comparison_table(
            "Our headline numbers beside the paper's (sections 4.1 and 4.2), under the paper's own contact model (perfect involutes meeting on the nominal path only, `contact.path` = \"nominal\") and under the default extended contact (tip corners touching beyond the path under load, docs/MODEL.md section 4.2). Deviations are discussed in docs/REPRODUCTION.md.",
            rows,
        );
        (
            "gearwear: dynamic wear prediction of the paper's spur pair".to_string(),
            format!("<p>Reproduction of section 4 of {source}: {}. The model as implemented and every choice where the paper is silent or wrong: docs/MODEL.md.</p>", html::escape(&case_words)),
            Section { heading: "Headline numbers".into(), tables: vec![table], ..Default::default() },
        )
    } else {
        (
            format!("gearwear: dynamic wear prediction, {}", pair_words(model)),
            format!("<p>Dynamic wear study of a spur pair with the tribo-dynamic wear model of {source}, as gearwear implements it (docs/MODEL.md): {}.</p>", html::escape(&case_words)),
            Section { heading: "The case and its key results".into(), tables: vec![case_table(model, study)], ..Default::default() },
        )
    }
}

/// The mesh stiffness section (`tag`: the paper's section in brackets, or empty).
pub(crate) fn stiffness_section(model: &Model, tag: String, figures: Vec<FigureBlock>) -> Section {
    let method = if model.case.stiffness.fillet_foundation {
        "Potential energy method with the Sainsot fillet foundation"
    } else {
        "Potential energy method without the fillet foundation"
    };
    Section {
        heading: format!("Mesh stiffness{tag}"),
        paragraphs: vec![format!(
            "{method}: k_m from {:.3e} to {:.3e} N/m, mean {:.3e} N/m; contact ratio {:.4}.",
            model.mesh.min_stiffness_n_per_m(),
            model.mesh.max_stiffness_n_per_m(),
            model.mesh.mean_stiffness_n_per_m(),
            model.pair.contact_ratio
        )],
        figures,
        tables: vec![],
    }
}

/// The section on the effects of wear on the dynamic response: the wear states and their
/// table.
fn wear_effects_section(
    model: &Model,
    study: &PaperStudy,
    tag: String,
    figures: Vec<FigureBlock>,
) -> Section {
    let list = |f: &dyn Fn(&crate::study::paper::WearStateResult) -> f64| {
        study
            .wear_states
            .iter()
            .map(|s| format!("{}", f(s)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    Section {
        heading: format!("Effects of wear on the dynamic response{tag}"),
        paragraphs: vec![
            format!(
                "Wear states: the dynamic wear study's own profile scaled to a maximum pinion wear of {} µm, with the composite roughness the case's law gives at that depth ({} µm).",
                list(&|s| s.max_wear_um),
                list(&|s| (s.roughness_um * 1e4).round() / 1e4),
            ),
            format!("{} {}", load_sentence(model), poles_sentence(model)),
        ],
        figures,
        tables: vec![states_table(study)],
    }
}

/// The section on the effects of the dynamic response on wear: both wear runs' reach and
/// maximum wear.
fn dynamic_effects_section(study: &PaperStudy, tag: String, figures: Vec<FigureBlock>) -> Section {
    let (d, q) = (&study.dynamic, &study.quasi_static);
    Section {
        heading: format!("Effects of the dynamic response on wear{tag}"),
        paragraphs: vec![format!(
            "Wear study to {} cycles: {} and {}; maximum pinion wear {} µm dynamic and {} µm quasi-static.",
            cycles_words(cycles_reached(study)),
            updates_words(d.records.len().saturating_sub(1), "dynamic"),
            updates_words(q.records.len().saturating_sub(1), "quasi-static"),
            html::format_value(wear_at_um(d, cycles_reached(study))),
            html::format_value(wear_at_um(q, cycles_reached(study))),
        )],
        figures,
        tables: vec![],
    }
}
