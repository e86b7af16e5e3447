//! Results of the wear study (`gearwear wear`, section 4.2 of `run`): a row per update,
//! the profiles of every update, Fig. 11-13 and the summary.

use super::artifacts::Artifacts;
use super::figures::{panel, points_panel, scale_panel, single, Curve};
use super::plot::{Figure, LineStyle, Panel};
use crate::format::shown;
use crate::io::Table;
use crate::study::wear_loop::{UpdateRecord, WearRun};
use crate::study::Model;
use serde_json::json;

/// Value of a piecewise-linear series (x ascending) at x; wear grows linearly in cycles
/// within a block, so this is exact between updates.
pub fn at_cycles(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    if xs.is_empty() {
        return f64::NAN;
    }
    let j = xs.partition_point(|v| *v < x);
    if j == 0 {
        return ys[0];
    }
    if j == xs.len() {
        return ys[ys.len() - 1];
    }
    let t = (x - xs[j - 1]) / (xs[j] - xs[j - 1]);
    ys[j - 1] + (ys[j] - ys[j - 1]) * t
}

/// The tables of one run: `updates_MODE.csv` (a row per update) and
/// `wear_profiles_MODE.csv` (the profiles of every update), file names relative.
pub fn run_tables(model: &Model, run: &WearRun) -> Vec<(String, Table)> {
    let m = run.mode.name();
    vec![
        (format!("updates_{m}.csv"), updates_table(&run.records)),
        (
            format!("wear_profiles_{m}.csv"),
            profiles_table(&model.grid, &run.records),
        ),
    ]
}

/// A row per update of a mesh's records (`updates_MODE.csv`): its cycles (its pinion's
/// revolutions), maximum wear and wear rate, roughness and response summary.
pub fn updates_table(rec: &[UpdateRecord]) -> Table {
    let s = |f: &dyn Fn(&UpdateRecord) -> f64| rec.iter().map(f).collect::<Vec<_>>();
    Table::new()
        .col("update", (0..rec.len()).map(|i| i as f64).collect())
        .col("cycles", s(&|r| r.wear.cycles))
        .col("max_wear_pinion_um", s(&|r| r.wear.max_pinion_m() * 1e6))
        .col("max_wear_gear_um", s(&|r| r.wear.max_gear_m() * 1e6))
        .col(
            "max_wear_rate_pinion_um_per_kcycle",
            s(&|r| r.max_increment_pinion_m() * 1e9),
        )
        .col("roughness_um", s(&|r| r.roughness_um))
        .col("mesh_force_mean_n", s(&|r| r.summary.mesh_force_mean_n))
        .col("mesh_force_max_n", s(&|r| r.summary.mesh_force_max_n))
        .col("dte_max_um", s(&|r| r.summary.dte_max_m * 1e6))
        .col(
            "velocity_y_pinion_rms_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_rms_m_per_s * 1e3),
        )
        .col(
            "friction_coefficient_max",
            s(&|r| r.summary.friction_coefficient_max),
        )
        .col(
            "mesh_harmonic1_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_harmonics_m_per_s[0] * 1e3),
        )
        .col(
            "mesh_harmonic2_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_harmonics_m_per_s[1] * 1e3),
        )
        .col(
            "mesh_harmonic3_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_harmonics_m_per_s[2] * 1e3),
        )
        .col(
            "mesh_harmonic4_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_harmonics_m_per_s[3] * 1e3),
        )
}

/// The profiles of every update of a mesh's records on its grid `g`
/// (`wear_profiles_MODE.csv`).
pub fn profiles_table(g: &crate::geometry::ProfileGrid, rec: &[UpdateRecord]) -> Table {
    let mut t = Table::new()
        .col("rho1_mm", g.rho_pinion_m.iter().map(|x| x * 1e3).collect())
        .col(
            "pinion_radius_mm",
            g.radius_pinion_m.iter().map(|x| x * 1e3).collect(),
        )
        .col(
            "gear_radius_mm",
            g.radius_gear_m.iter().map(|x| x * 1e3).collect(),
        );
    for (i, r) in rec.iter().enumerate() {
        t = t
            .col(
                &format!("wear_pinion_um_u{i}"),
                r.wear.pinion_m.iter().map(|x| x * 1e6).collect(),
            )
            .col(
                &format!("wear_gear_um_u{i}"),
                r.wear.gear_m.iter().map(|x| x * 1e6).collect(),
            )
            .col(
                &format!("rate_pinion_um_per_kcycle_u{i}"),
                r.increment_pinion_m.iter().map(|x| x * 1e9).collect(),
            );
    }
    t
}

/// A figure of the wear study, its file stem and the table of exactly its data.
pub struct WearFigure {
    /// File stem.
    pub stem: &'static str,
    /// The figure.
    pub figure: Figure,
    /// Exactly the plotted numbers.
    pub table: Table,
}

/// Figures 11-13 from the runs present, each with its own table: the curves are drawn
/// from the table's columns, so a figure shows what its CSV holds.
pub fn wear_figures(model: &Model, runs: &[&WearRun]) -> Vec<WearFigure> {
    let rho_mm: Vec<f64> = model.grid.rho_pinion_m.iter().map(|x| x * 1e3).collect();
    let along = "pinion roll distance along the path of contact (mm)";
    let rate = "wear rate (µm per 1000 cycles)";
    let (mut t11, mut load, mut wear) =
        (Table::new().col("rho1_mm", rho_mm.clone()), vec![], vec![]);
    let radius_mm = model.grid.radius_pinion_m.iter().map(|x| x * 1e3).collect();
    let mut t12 = Table::new()
        .col("rho1_mm", rho_mm.clone())
        .col("pinion_radius_mm", radius_mm);
    let mut panels12 = Vec::new();
    let mut t13 = Table::new();
    let mut f13 = Vec::new();
    for run in runs {
        let (m, label) = (run.mode.name(), run.mode.label());
        if let Some(r0) = run.records.first() {
            let x: Vec<f64> = r0.path_rho1_m.iter().map(|x| x * 1e3).collect();
            let w: Vec<f64> = r0.increment_pinion_m.iter().map(|x| x * 1e9).collect();
            t11 = t11
                .col(&format!("path_rho1_mm_{m}"), x.clone())
                .col(&format!("pair_load_n_{m}"), r0.path_load_n.clone())
                .col(&format!("wear_rate_um_per_kcycle_{m}"), w.clone());
            load.push(Curve::new(label, x, r0.path_load_n.clone()));
            wear.push(Curve::new(label, rho_mm.clone(), w));
        }
        let mut curves = Vec::new();
        for r in &run.records {
            let w: Vec<f64> = r.increment_pinion_m.iter().map(|x| x * 1e9).collect();
            let cycles = r.wear.cycles;
            let name = format!(
                "wear_rate_um_per_kcycle_{m}_at_{}_cycles",
                crate::io::format_number(cycles)
            );
            t12 = t12.col(&name, w.clone());
            curves.push((cycles, Curve::new("", rho_mm.clone(), w)));
        }
        panels12.push((label, curves));
        let max_um: Vec<f64> = run.max_wear_pinion_m().iter().map(|x| x * 1e6).collect();
        t13 = t13
            .col(&format!("cycles_{m}"), run.cycles())
            .col(&format!("max_wear_pinion_um_{m}"), max_um.clone());
        f13.push(Curve::new(label, run.cycles(), max_um));
    }
    // One colour scale for both panels of Fig. 12: the same colour is the same cycle count.
    let all = panels12.iter().flat_map(|p| p.1.iter().map(|c| c.0));
    let (lo, hi) = all.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
        (a.min(c), b.max(c))
    });
    let panels12 = panels12
        .into_iter()
        .map(|(label, curves)| {
            let p = scale_panel(label, along, rate, curves, ("load cycles", lo, hi));
            show_coinciding(p, label)
        })
        .collect();
    vec![
        WearFigure {
            stem: "fig11_force_and_wear_initial",
            figure: Figure {
                title: "Pair load and wear rate along the pinion profile, new teeth".into(),
                panels: vec![
                    panel(along, "pair load (N)", load),
                    panel(along, rate, wear),
                ],
            },
            table: t11,
        },
        WearFigure {
            stem: "fig12_wear_rate_evolution",
            figure: Figure {
                title: "Wear rate along the pinion profile as wear proceeds".into(),
                panels: panels12,
            },
            table: t12,
        },
        WearFigure {
            stem: "fig13_max_accumulated_wear",
            figure: single(
                "Maximum accumulated pinion wear depth",
                points_panel("pinion load cycles", "maximum pinion wear depth (µm)", f13),
            ),
            table: t13,
        },
    ]
}

/// Largest change of a panel's curves from its first (new teeth) below which they are
/// drawn on top of each other, as a fraction of the first curve's maximum: 1 % of a panel's
/// ~260 px plot height is ~2.6 px, about the 2 px width of a line.
const COINCIDE: f64 = 0.01;

/// Largest |curve - first curve| over a panel's curves, as a fraction of the first curve's
/// largest magnitude (0 for fewer than two curves).
pub fn spread_from_first(p: &Panel) -> f64 {
    let Some(first) = p.series.first() else {
        return 0.0;
    };
    let scale = first.y.iter().fold(0.0_f64, |a, y| a.max(y.abs()));
    let change = p.series[1..].iter().fold(0.0_f64, |a, s| {
        s.y.iter()
            .zip(&first.y)
            .fold(a, |a, (y, y0)| a.max((y - y0).abs()))
    });
    if scale > 0.0 {
        change / scale
    } else {
        change
    }
}

/// When a panel's curves coincide (the quasi-static rate hardly changes with wear), the
/// last drawn colour hides every other: the panel's title then says by how much they differ,
/// and the first curve (new teeth) is drawn again, dashed, on top of the last.
fn show_coinciding(mut p: Panel, label: &str) -> Panel {
    let spread = spread_from_first(&p);
    if p.series.len() < 2 || spread >= COINCIDE {
        return p;
    }
    p.title = format!(
        "{label}: all curves coincide (largest change {:.2} % of the maximum); new teeth dashed",
        100.0 * spread
    );
    let mut first = p.series[0].clone();
    first.style = LineStyle::Dashed;
    p.series.push(first);
    p
}

/// summary.json content of the wear study (promised keys).
pub fn wear_summary(dynamic: Option<&WearRun>, qs: Option<&WearRun>) -> serde_json::Value {
    let Some(base) = dynamic.or(qs) else {
        return json!({});
    };
    let cycles = base.cycles();
    let series = |run: Option<&WearRun>, f: &dyn Fn(&WearRun) -> Vec<f64>| -> serde_json::Value {
        match run {
            Some(r) => json!(cycles
                .iter()
                .map(|c| at_cycles(&r.cycles(), &f(r), *c) * 1e6)
                .collect::<Vec<_>>()),
            None => serde_json::Value::Null,
        }
    };
    let mut v = json!({
        "cycles": cycles,
        "max_wear_pinion_um": {"dynamic": series(dynamic, &|r| r.max_wear_pinion_m()), "quasi_static": series(qs, &|r| r.max_wear_pinion_m())},
        "max_wear_gear_um": {"dynamic": series(dynamic, &|r| r.max_wear_gear_m()), "quasi_static": series(qs, &|r| r.max_wear_gear_m())},
        "updates": {
            "dynamic": dynamic.map(|r| r.records.len() - 1),
            "quasi_static": qs.map(|r| r.records.len() - 1),
        },
    });
    // The runs that stopped early, by mode (empty when all reached the total cycles).
    let mut stopped = serde_json::Map::new();
    for r in [dynamic, qs].into_iter().flatten() {
        if let Some(stop) = &r.stopped {
            stopped.insert(r.mode.name().into(), json!(stop));
        }
    }
    v["stopped"] = serde_json::Value::Object(stopped);
    if let (Some(d), Some(q)) = (dynamic, qs) {
        // At the same cycles: a run that stopped early ends before the other.
        let end = d.cycles().last().copied().unwrap_or(0.0);
        let end = end.min(q.cycles().last().copied().unwrap_or(0.0));
        let (hd, hq) = (
            at_cycles(&d.cycles(), &d.max_wear_pinion_m(), end),
            at_cycles(&q.cycles(), &q.max_wear_pinion_m(), end),
        );
        v["ratio_max_wear_dynamic_to_static"] = json!(hd / hq);
        v["ratio_max_wear_rate_dynamic_to_static"] =
            json!(max_rate_at(d, end) / max_rate_at(q, end));
        v["ratio_at_cycles"] = json!(end);
        v["ratio_notes"] = json!("ratio_max_wear_dynamic_to_static: maximum accumulated pinion wear depth at ratio_at_cycles, the last cycle count both runs reached (the total unless one stopped early; paper: ~1.2). ratio_max_wear_rate_dynamic_to_static: maximum pinion wear depth per cycle of each run's state there (the last update at or before it; the paper's 'maximum wear depth', ~1.6).");
    }
    v
}

/// Largest per-cycle pinion wear of a run's state at `cycles` (its last update at or
/// before them; the first if none), m.
pub fn max_rate_at(r: &WearRun, cycles: f64) -> f64 {
    r.records
        .iter()
        .take_while(|x| x.wear.cycles <= cycles)
        .last()
        .or(r.records.first())
        .map_or(f64::NAN, |x| x.max_increment_pinion_m())
}

/// Why a ratio is taken before the total cycles: " (where both runs reached: the
/// dynamic run stopped early)", or nothing when every run reached its end together.
pub fn ratio_where(runs: &[&WearRun], at: f64) -> String {
    let stopped: Vec<&str> = runs
        .iter()
        .filter(|r| r.stopped.is_some() && r.cycles().last().is_some_and(|c| *c <= at))
        .map(|r| r.mode.label())
        .collect();
    if stopped.is_empty() {
        String::new()
    } else {
        format!(
            " (the last both runs reached: the {} run stopped early)",
            stopped.join(" and ")
        )
    }
}

/// Everything `gearwear wear` writes for the runs present (one or both modes).
pub fn wear_artifacts(model: &Model, runs: &[&WearRun]) -> Artifacts {
    use crate::study::wear_loop::WearMode;
    let mut a = Artifacts::default();
    for r in runs {
        for (name, t) in run_tables(model, r) {
            a.table(name, t);
        }
    }
    for f in wear_figures(model, runs) {
        a.figure_with_data(format!("{}.png", f.stem), f.figure, f.table);
    }
    for f in super::worn_profile::worn_profile_figures(model, runs) {
        a.figure_with_data(format!("{}.png", f.stem), f.figure, f.table);
    }
    let find = |m: WearMode| runs.iter().copied().find(|r| r.mode == m);
    let mut v = wear_summary(find(WearMode::Dynamic), find(WearMode::QuasiStatic));
    v["warnings"] = json!(model.warnings);
    a.headline = wear_headline(runs, &v);
    a.summary = v;
    super::teeth::add_teeth_artifacts(model, &mut a);
    super::teeth::add_tooth_wear_artifacts(model, runs, &mut a);
    super::helical_wear::add_wear_map_artifacts(model, runs, &mut a);
    a
}

/// A line per mode (final cycles, maximum pinion wear), and the ratio when both ran.
pub fn wear_headline(runs: &[&WearRun], v: &serde_json::Value) -> String {
    let mut lines: Vec<String> = runs
        .iter()
        .filter_map(|r| {
            r.last().map(|l| {
                format!(
                    "{}: {} updates to {} cycles, maximum pinion wear {} µm",
                    r.mode.label(),
                    r.records.len() - 1,
                    shown(l.wear.cycles),
                    shown(l.wear.max_pinion_m() * 1e6)
                )
            })
        })
        .collect();
    if let (Some(x), Some(at)) = (
        v["ratio_max_wear_dynamic_to_static"].as_f64(),
        v["ratio_at_cycles"].as_f64(),
    ) {
        lines.push(format!(
            "dynamic / quasi-static maximum accumulated pinion wear at {} cycles{}: {}",
            shown(at),
            ratio_where(runs, at),
            shown(x)
        ));
    }
    lines.join("\n")
}
