//! Outputs of a tooth-resolved mesh (cases with `[teeth]`, `[modification]` or `[[fault]]`):
//! the teeth as given or drawn, the mesh stiffness of every tooth pair over the excitation
//! period with the faults marked, each tooth's wear (table and heat map of tooth against
//! roll angle) and the spectrum around the mesh frequency with the shaft-frequency
//! sidebands marked. Added to the stiffness, dynamics, wear and run outputs by
//! [`add_teeth_artifacts`] and friends, so both front ends get them.

use super::artifacts::Artifacts;
use super::figures::{panel, single, spectrum_panel, spectrum_rows, Curve};
use super::plot::Figure;
use crate::config::case::{FaultKind, Member};
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::spectrum::Spectrum;
use crate::dynamics::summary::velocity_y_spectrum;
use crate::format::shown;
use crate::geometry::iso1328::{cumulative_pitch_deviation, single_pitch_deviations};
use crate::geometry::{GearPair, ProfileGrid};
use crate::io::Table;
use crate::study::wear_loop::{UpdateRecord, WearMode, WearRun};
use crate::study::Model;
use crate::wear::ToothWear;
use serde_json::{json, Value};

/// Samples of the mesh stiffness per mesh period in the per-tooth table.
const TVMS_SAMPLES: usize = 64;

/// The per-tooth inputs of one gear as a table (`teeth_pinion.csv`, `teeth_gear.csv`).
pub fn teeth_table(model: &Model, member: Member) -> Option<Table> {
    let t = model.teeth.as_ref()?;
    let i = member as usize;
    let e = &t.errors[i];
    let z = e.position_um.len();
    // The sizes as the case file gives them (its units).
    let fault = |kind: FaultKind, f: &dyn Fn(&crate::config::case::FaultTable) -> Option<f64>| {
        (0..z)
            .map(|tooth| {
                t.faults
                    .iter()
                    .filter(|x| x.gear == member && x.kind() == kind && x.tooth == tooth)
                    .filter_map(|x| f(x.table()))
                    // Not `sum()`: an empty f64 sum is -0.0, written "-0" for a healthy tooth.
                    .fold(0.0, |a, b| a + b)
            })
            .collect()
    };
    Some(
        Table::new()
            .col("tooth", (0..z).map(|t| t as f64).collect())
            .col("position_error_um", e.position_um.clone())
            .col(
                "single_pitch_deviation_um",
                single_pitch_deviations(&e.position_um),
            )
            .col("profile_slope_um", e.profile_slope_um.clone())
            .col("profile_form_um", e.profile_form_um.clone())
            .col(
                "crack_depth_mm",
                fault(FaultKind::Crack, &|f| f.crack_depth_mm),
            )
            .col(
                "spall_depth_um",
                fault(FaultKind::Spall, &|f| f.spall_depth_um),
            )
            .col(
                "broken_tip_removed_mm",
                fault(FaultKind::BrokenTip, &|f| f.removed_height_mm),
            ),
    )
}

/// The `teeth` entry of summaries: what each gear's teeth were given (ISO values derived
/// from them, the class's tolerances when drawn) and the faults.
pub fn teeth_json(model: &Model) -> Option<Value> {
    let t = model.teeth.as_ref()?;
    let gear = |i: usize| {
        let e = &t.errors[i];
        let fpt = single_pitch_deviations(&e.position_um);
        json!({
            "max_single_pitch_deviation_um": fpt.iter().fold(0.0_f64, |a, b| a.max(b.abs())),
            "cumulative_pitch_deviation_um": cumulative_pitch_deviation(&e.position_um),
            "runout_um": e.runout_um,
            "iso1328_tolerances_um": e.tolerances,
        })
    };
    let tm = model.tooth_mesh(&model.new_wear_state())?;
    Some(json!({
        "excitation_mesh_periods": tm.periods(),
        "hunting_mesh_periods": crate::dynamics::tooth_mesh::lcm(model.pair.pinion.teeth, model.pair.gear.teeth),
        "pinion": gear(0),
        "gear": gear(1),
        "faults": t.faults,
        "load_sharing": "by each pair's compression (per-tooth inputs)",
    }))
}

/// The `faults` entry of a gear train's summaries: every tooth fault the train's model
/// holds (a `[[fault]]` table that changes its tooth, on the stage it names), each as its
/// table (kind, stage, gear, tooth and its sizes in the case file's units); None
/// without one (a healthy train's summary is unchanged).
pub fn train_faults_json(train: &crate::study::train::TrainModel) -> Option<Value> {
    let faults: Vec<Value> = train
        .stages
        .iter()
        .filter_map(|s| s.tooth_inputs.as_ref())
        .flat_map(|t| t.faults.iter().filter(|f| f.changes_tooth()))
        .map(|f| json!(f))
        .collect();
    (!faults.is_empty()).then(|| json!(faults))
}

/// A table of `columns` under `names`, in order.
fn named_columns(names: &[&str], columns: impl Iterator<Item = Vec<f64>>) -> Table {
    names
        .iter()
        .zip(columns)
        .fold(Table::new(), |t, (n, v)| t.col(n, v))
}

/// Mesh stiffness over the excitation period of new teeth, per pair (its teeth and
/// stiffness) and in total beside the healthy mesh's, with the engagements of faulty
/// teeth marked: the figure of a readable window of it, that window's rows (exactly what
/// the figure draws) and the table of the whole period.
pub fn tvms_figure(model: &Model) -> Option<(Figure, Table, Table)> {
    let tm = model.tooth_mesh(&model.new_wear_state())?;
    let pair = &model.pair;
    let period = pair.mesh_angle_rad();
    let cols = 10;
    let mut c: Vec<Vec<f64>> = vec![Vec::new(); cols];
    for cycle in 0..tm.periods() as i64 {
        for s in 0..TVMS_SAMPLES {
            let local = period * s as f64 / TVMS_SAMPLES as f64;
            let (mut total, mut healthy) = (0.0, 0.0);
            let mut row = [f64::NAN; 6];
            for (j, (k, rho1)) in pair.pairs_in_contact(local).enumerate() {
                let p = tm.pair(&model.mesh, cycle - k as i64, rho1);
                total += p.stiffness_n_per_m;
                healthy += model.mesh.pair_stiffness_n_per_m(rho1);
                if j < 2 {
                    row[3 * j] = p.pinion_tooth as f64;
                    row[3 * j + 1] = p.gear_tooth as f64;
                    row[3 * j + 2] = p.stiffness_n_per_m;
                }
            }
            let values = [(cycle as f64 * period + local).to_degrees(), cycle as f64];
            for (k, v) in values
                .iter()
                .chain(&row)
                .chain(&[total, healthy])
                .enumerate()
            {
                c[k].push(*v);
            }
        }
    }
    let names = [
        "pinion_angle_deg",
        "mesh_cycle",
        "pinion_tooth_pair0",
        "gear_tooth_pair0",
        "stiffness_pair0_n_per_m",
        "pinion_tooth_pair1",
        "gear_tooth_pair1",
        "stiffness_pair1_n_per_m",
        "stiffness_total_n_per_m",
        "stiffness_total_healthy_n_per_m",
    ];
    let table = named_columns(&names, c.iter().cloned());
    // The figure shows a readable window: 8 mesh periods around the first engagement of
    // the first faulty tooth, else the first pinion revolution (the period's table holds
    // all; the figure's own table only the window, the rule of every figure's data).
    let t = model.teeth.as_ref()?;
    let [z1, z2] = tm.teeth();
    let first_fault = t.faults.first().map(|f| f.tooth);
    let (lo, hi) = match first_fault {
        Some(c0) => (c0.saturating_sub(2), (c0 + 6).min(tm.periods())),
        None => (0, z1.min(tm.periods())),
    };
    let rows = lo * TVMS_SAMPLES..hi * TVMS_SAMPLES;
    let shown = |k: usize| c[k][rows.clone()].to_vec();
    let window = named_columns(&names, (0..names.len()).map(shown));
    // Without a fault the teeth's stiffness is the healthy one (errors, run-out and
    // reliefs move the flanks, not their stiffness): one curve, nothing to compare.
    let curves = if t.faults.is_empty() {
        vec![Curve::new("every tooth pair", shown(0), shown(8))]
    } else {
        vec![
            Curve::new("healthy teeth", shown(0), shown(9)),
            Curve::new("with the faults", shown(0), shown(8)),
        ]
    };
    let mut p = panel("pinion rotation (deg)", "mesh stiffness (N/m)", curves);
    // Mark the start of each engagement of a faulty tooth in the window.
    for f in &t.faults {
        let z = match f.gear {
            Member::Pinion => z1,
            Member::Gear => z2,
        };
        for cycle in (f.tooth..hi).step_by(z.max(1)) {
            if cycle >= lo {
                let label = format!("{} {} tooth {}", f.kind().name(), f.gear.name(), f.tooth);
                p.vlines.push(((cycle as f64 * period).to_degrees(), label));
            }
        }
    }
    let marked = if t.faults.is_empty() {
        "no tooth faults"
    } else {
        "faulty teeth's engagements marked"
    };
    let fig = single(
        &format!(
            "Mesh stiffness of the tooth pairs, mesh cycles {lo} to {} of {} ({marked})",
            hi - 1,
            tm.periods()
        ),
        p,
    );
    Some((fig, window, table))
}

/// A per-profile wear map's table on the model's grid: rho1 (mm), both flanks' roll angles
/// (deg, each on its own profile: rho / r_b), then a column per profile and flank,
/// `{flank}_{what}{index}_um` (µm); with the two roll-angle columns for the heat maps.
pub(crate) fn map_table(model: &Model, map: &ToothWear, what: &str) -> (Table, Vec<f64>, Vec<f64>) {
    map_table_on(&model.grid, &model.pair, map, what)
}

/// [`map_table`] on the profile grid `g` of the pair `pair` (a train's stage).
fn map_table_on(
    g: &ProfileGrid,
    pair: &GearPair,
    map: &ToothWear,
    what: &str,
) -> (Table, Vec<f64>, Vec<f64>) {
    let roll =
        |rho: &[f64], rb: f64| -> Vec<f64> { rho.iter().map(|r| (r / rb).to_degrees()).collect() };
    let roll_p = roll(&g.rho_pinion_m, pair.pinion.base_radius_m);
    let roll_g = roll(&g.rho_gear_m, pair.gear.base_radius_m);
    let mut table = Table::new()
        .col("rho1_mm", g.rho_pinion_m.iter().map(|r| r * 1e3).collect())
        .col("pinion_roll_deg", roll_p.clone())
        .col("gear_roll_deg", roll_g.clone());
    for (name, profiles) in [("pinion", &map.pinion_m), ("gear", &map.gear_m)] {
        for (t, p) in profiles.iter().enumerate() {
            table = table.col(
                &format!("{name}_{what}{t}_um"),
                p.iter().map(|h| h * 1e6).collect(),
            );
        }
    }
    (table, roll_p, roll_g)
}

/// The per-tooth wear of the last record of `run` (`teeth_wear_MODE.csv`, a column per
/// tooth) and its heat map, tooth index against the tooth's own roll angle.
pub fn tooth_wear_figure(model: &Model, run: &WearRun) -> Option<(Figure, Table)> {
    tooth_wear_figure_of(&model.grid, &model.pair, run.last()?, run.mode)
}

/// [`tooth_wear_figure`] of a mesh's last record `last` of a run in `mode`, on the profile
/// grid `g` of its pair `pair`: a single pair's, or a faulty train stage's
/// (`report::wear_train`). None when the record has no per-tooth wear.
pub fn tooth_wear_figure_of(
    g: &ProfileGrid,
    pair: &GearPair,
    last: &UpdateRecord,
    mode: WearMode,
) -> Option<(Figure, Table)> {
    let teeth = last.wear.teeth.as_ref()?;
    let (table, roll_p, roll_g) = map_table_on(g, pair, teeth, "tooth");
    let max = teeth.max_m() * 1e6;
    let rows = |n: usize| (0..n).map(|t| t as f64).collect::<Vec<f64>>();
    let heat = |title: &str, roll: &[f64], profiles: &[Vec<f64>]| {
        let mut p = super::figures::heat_panel(roll, &rows(profiles.len()), profiles, max);
        p.title = title.into();
        p.x_label = "roll angle of the tooth's own profile (deg)".into();
        p.y_label = "tooth".into();
        p
    };
    let fig = Figure {
        title: format!(
            "Wear of every tooth after {} cycles ({} study)",
            crate::io::format_number(last.wear.cycles),
            mode.label()
        ),
        panels: vec![
            heat("pinion", &roll_p, &teeth.pinion_m),
            heat("gear", &roll_g, &teeth.gear_m),
        ],
    };
    Some((fig, table))
}

/// The pinion-velocity spectrum around the mesh frequency, with the sidebands of both
/// shafts' frequencies marked (resolved over the excitation period of a tooth-resolved
/// response: bins of f_mesh / P).
/// `spec` is the response's pinion y velocity spectrum (`velocity_y_spectrum`).
pub fn sideband_figure(model: &Model, spec: &Spectrum, label: &str) -> (Figure, Table) {
    let f_mesh = model.params.operating.mesh_frequency_hz;
    let f_p = model.params.operating.pinion_speed_rad_s / std::f64::consts::TAU;
    let f_g = model.params.operating.gear_speed_rad_s / std::f64::consts::TAU;
    let (f, a) = spectrum_rows(&spec.frequency_hz, &spec.amplitude, f_mesh + 5.5 * f_p);
    let (f, a): (Vec<f64>, Vec<f64>) = f
        .into_iter()
        .zip(a)
        .filter(|(x, _)| *x >= f_mesh - 5.5 * f_p)
        .map(|(x, y)| (x, y * 1e3))
        .unzip();
    let mut p = spectrum_panel("amplitude (mm/s)", &f, &a, f_mesh);
    // Sidebands are decades below the mesh harmonic: a log axis shows them.
    p.log_y = true;
    // Labelled as the `signals` spectrum labels its sidebands ("+1 pinion": the mesh
    // frequency plus once the pinion's rotation frequency).
    for k in [1.0, 2.0] {
        for (fs, shaft) in [(f_p, "pinion"), (f_g, "gear")] {
            for sign in [-1.0, 1.0] {
                let lab = if sign > 0.0 {
                    format!("+{k} {shaft}")
                } else {
                    String::new()
                };
                p.vlines.push((f_mesh + sign * k * fs, lab));
            }
        }
    }
    let fig = single(
        &format!(
            "Pinion velocity around the mesh frequency, sidebands of the shaft speeds ({label})"
        ),
        p,
    );
    let table = Table::new()
        .col("frequency_hz", f)
        .col("velocity_y_pinion_amplitude_mm_per_s", a);
    (fig, table)
}

/// Adds the teeth tables, the summary entry and the per-tooth mesh stiffness to `a`
/// (stiffness, dynamics and wear outputs of a tooth-resolved case; nothing otherwise).
pub fn add_teeth_artifacts(model: &Model, a: &mut Artifacts) {
    if model.teeth.is_none() {
        return;
    }
    for (m, name) in [
        (Member::Pinion, "teeth_pinion.csv"),
        (Member::Gear, "teeth_gear.csv"),
    ] {
        if let Some(t) = teeth_table(model, m) {
            a.table(name, t);
        }
    }
    if let Some(v) = teeth_json(model) {
        a.summary["teeth"] = v;
    }
    if let Some((fig, window, period)) = tvms_figure(model) {
        a.figure_with_data("teeth_mesh_stiffness.png", fig, window);
        a.table("teeth_mesh_stiffness_period.csv", period);
    }
}

/// Adds the static transmission error of these teeth to the stiffness outputs: the
/// quasi-static response of the new teeth (no inertia; `dynamics::quasi_static`) over
/// the excitation period, as `teeth.quasi_static_te` in the summary and
/// `csv/teeth_quasi_static_te.csv`. The stiffness table's `quasi_static_te` is the
/// identical, perfect teeth's over one mesh period; reliefs, errors and faults change
/// this one (docs/MODEL.md, section 9.8).
pub fn add_teeth_static_te(model: &Model, a: &mut Artifacts) {
    if model.teeth.is_none() {
        return;
    }
    let r = model.quasi_static(&model.new_wear_state(), &ExternalError::none());
    let te_um: Vec<f64> = r.signals.meshes[0].dte_m.iter().map(|d| d * 1e6).collect();
    if te_um.is_empty() {
        return;
    }
    let min = te_um.iter().fold(f64::INFINITY, |a, b| a.min(*b));
    let max = te_um.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b));
    a.summary["teeth"]["quasi_static_te"] = json!({
        "min_um": min,
        "max_um": max,
        "peak_to_peak_um": max - min,
        "mesh_periods": r.excitation_periods,
    });
    let omega = model.params.operating.pinion_speed_rad_s;
    let table = Table::new()
        .col(
            "pinion_angle_deg",
            r.signals
                .time_s
                .iter()
                .map(|t| (omega * t).to_degrees())
                .collect(),
        )
        .col("quasi_static_te_um", te_um)
        .col(
            "quasi_static_mesh_force_n",
            r.signals.meshes[0].mesh_force_n.clone(),
        );
    a.table("csv/teeth_quasi_static_te.csv", table);
    a.headline.push_str(&format!(
        "; static TE of these teeth {} to {} µm over {} mesh periods",
        shown(min),
        shown(max),
        r.excitation_periods
    ));
}

/// Adds the sideband spectrum of a tooth-resolved dynamic response to `a`.
/// `spec` is the response's pinion y velocity spectrum (`velocity_y_spectrum`).
pub fn add_sideband_artifacts(
    model: &Model,
    r: &DynamicResponse,
    spec: &Spectrum,
    label: &str,
    a: &mut Artifacts,
) {
    if model.teeth.is_none() || r.signals.velocity.is_empty() {
        return;
    }
    let (fig, table) = sideband_figure(model, spec, label);
    a.figure_with_data("teeth_spectrum_sidebands.png", fig, table);
    a.summary["excitation_mesh_periods"] = json!(r.excitation_periods);
}

/// Adds each run's per-tooth wear table and heat map to `a`.
pub fn add_tooth_wear_artifacts(model: &Model, runs: &[&WearRun], a: &mut Artifacts) {
    if model.helical.is_some() {
        // A helical pair's per-tooth table carries its face slices
        // (`report::helical_wear`, docs/MODEL.md 11.13).
        return;
    }
    for run in runs {
        if let Some((fig, table)) = tooth_wear_figure(model, run) {
            a.figure_with_data(format!("teeth_wear_{}.png", run.mode.name()), fig, table);
        }
    }
}

/// The figures of the run report's section on the teeth (after the paper's): the mesh
/// stiffness of the tooth pairs, the sidebands of the first wear state's response and
/// each tooth's wear at the end of the dynamic study. None for identical teeth.
pub fn run_teeth_figures(
    model: &Model,
    study: &crate::study::paper::PaperStudy,
) -> Vec<super::figures::Fig> {
    let mut figs = Vec::new();
    if model.teeth.is_none() {
        return figs;
    }
    let mut push = |file: &str, caption: String, (figure, table): (Figure, Table)| {
        figs.push(super::figures::Fig {
            file: file.into(),
            paper_figure: 0,
            caption,
            figure,
            table,
        })
    };
    if let Some((figure, window, _)) = tvms_figure(model) {
        push(
            "teeth_mesh_stiffness",
            "Mesh stiffness of the tooth pairs of new teeth, beside identical healthy teeth".into(),
            (figure, window),
        );
    }
    if let Some(s) = study.wear_states.first() {
        let label = format!("{} µm wear state", s.max_wear_um);
        push(
            "teeth_spectrum_sidebands",
            format!("Pinion velocity spectrum around the mesh frequency over the excitation period ({label}): the shaft-frequency sidebands"),
            sideband_figure(model, &velocity_y_spectrum(&s.response), &label),
        );
    }
    if let Some(w) = tooth_wear_figure(model, &study.dynamic) {
        push(
            "teeth_wear_dynamic",
            "Wear of every tooth at the end of the dynamic wear study".into(),
            w,
        );
    }
    figs
}

/// The run report's section on the teeth: what they were given and the figures.
pub fn teeth_section(
    model: &Model,
    figures: Vec<super::html::FigureBlock>,
) -> Option<super::html::Section> {
    let t = model.teeth.as_ref()?;
    let tm = model.tooth_mesh(&model.new_wear_state())?;
    let mut paragraphs = vec![format!(
        "Every tooth has its own flank: mesh cycle n engages pinion tooth n mod {} and gear tooth n mod {}; the excitation repeats after {} mesh periods and the steady state is found over them (docs/MODEL.md, section 9). Pair loads follow each pair's compression.",
        model.pair.pinion.teeth,
        model.pair.gear.teeth,
        tm.periods()
    )];
    for (i, name) in ["pinion", "gear"].iter().enumerate() {
        let e = &t.errors[i];
        paragraphs.push(format!(
            "{name}: cumulative pitch deviation {:.3} µm, largest single pitch deviation {:.3} µm, run-out {} µm{}.",
            cumulative_pitch_deviation(&e.position_um),
            single_pitch_deviations(&e.position_um)
                .iter()
                .fold(0.0_f64, |a, b| a.max(b.abs())),
            e.runout_um,
            e.tolerances.map_or(String::new(), |tol| format!(
                " (drawn for ISO 1328-1 class {}: f_pT {:.2} µm, F_pT {:.2} µm)",
                tol.class, tol.single_pitch_um, tol.cumulative_pitch_um
            ))
        ));
    }
    for f in &t.faults {
        paragraphs.push(format!(
            "Fault: {} on {} tooth {}.",
            f.kind().name(),
            f.gear.name(),
            f.tooth
        ));
    }
    Some(super::html::Section {
        heading: "Tooth-resolved mesh".into(),
        paragraphs,
        figures,
        tables: vec![],
    })
}

/// The line a report gives a faulty tooth's wear at the end of a wear run (`label`, e.g.
/// "dynamic"): the deepest wear of `who` (e.g. "pinion tooth 3") beside that of the other
/// teeth of `member` (e.g. "pinion"), each already shown in µm (`own`, `others`).
pub(crate) fn own_and_others_line(
    label: &str,
    who: &str,
    member: &str,
    (own, others): (&str, &str),
) -> String {
    format!("{label}: the deepest wear of {who} is {own} µm, of the {member}'s other teeth {others} µm.")
}
