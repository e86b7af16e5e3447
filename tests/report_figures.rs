//! The figures of every command: each figure's CSV holds exactly the numbers it plots, and
//! no legend covers a plotted point (checked on the layout the renderer draws to).
//! The run is the built-in (paper's) case, whose report also keeps its comparison.

use std::process::Command;
use std::sync::OnceLock;

use gearwear::config::Case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::report::artifacts::FigureFile;
use gearwear::report::plot::{layout, PanelLayout};
use gearwear::report::sweep_figure::{figure_for, SWEEP_FIGURE_PX};
use gearwear::report::{
    dynamics::dynamics_artifacts, paper::run_artifacts, stiffness::stiffness_artifacts,
    wear::wear_artifacts, Artifacts,
};
use gearwear::store::RunMetadata;
use gearwear::study::paper::{run_paper_study, PaperStudy};
use gearwear::study::sweep::{Crossing, SweepTable};
use gearwear::study::Model;
use gearwear::wear::WearState;

/// The built-in case and its whole study (4e4 cycles: ~0.2 s of CPU in release).
fn paper() -> &'static (Model, PaperStudy) {
    static CELL: OnceLock<(Model, PaperStudy)> = OnceLock::new();
    CELL.get_or_init(|| {
        let model = Model::from_case(&Case::default()).expect("the built-in case builds");
        let (d, q) = (
            gearwear::study::wear_loop::WearRun::new(gearwear::study::wear_loop::WearMode::Dynamic),
            gearwear::study::wear_loop::WearRun::new(
                gearwear::study::wear_loop::WearMode::QuasiStatic,
            ),
        );
        let study = run_paper_study(&model, d, q, &|_, _| Ok(())).expect("the study runs");
        (model, study)
    })
}

/// The artifacts of `run`, `stiffness`, `dynamics` and `wear` on the built-in case.
fn all_artifacts() -> Vec<(&'static str, Artifacts)> {
    let (model, study) = paper();
    let meta = RunMetadata::new("run", &model.case);
    let new_teeth = model
        .dynamic(&WearState::new(model.grid.len()), &ExternalError::none())
        .expect("steady state");
    vec![
        (
            "run",
            run_artifacts(model, study, None, &meta, Default::default()),
        ),
        ("stiffness", stiffness_artifacts(model)),
        (
            "dynamics",
            dynamics_artifacts(model, &new_teeth, "new teeth"),
        ),
        (
            "wear",
            wear_artifacts(model, &[&study.dynamic, &study.quasi_static]),
        ),
    ]
}

/// Columns of a CSV file as numbers (empty cell = NaN), by header name.
fn csv_columns(bytes: &[u8]) -> Vec<(String, Vec<f64>)> {
    let mut r = csv::Reader::from_reader(bytes);
    let names: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    let mut cols = vec![Vec::new(); names.len()];
    for rec in r.records() {
        for (c, cell) in cols.iter_mut().zip(rec.unwrap().iter()) {
            c.push(if cell.is_empty() {
                f64::NAN
            } else {
                cell.parse().unwrap()
            });
        }
    }
    names.into_iter().zip(cols).collect()
}

/// `plotted` is `column` up to trailing empty cells (shorter columns of a CSV are padded):
/// the same numbers bit for bit, NaN where NaN.
fn same_numbers(plotted: &[f64], column: &[f64]) -> bool {
    let n = plotted.len();
    column.len() >= n
        && column[n..].iter().all(|v| v.is_nan())
        && plotted
            .iter()
            .zip(column)
            .all(|(a, b)| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()))
}

#[test]
fn every_figure_has_a_csv_with_exactly_its_plotted_numbers() {
    for (command, a) in all_artifacts() {
        assert!(!a.figures.is_empty(), "{command}: no figures");
        for f in &a.figures {
            let csv = f
                .data
                .as_deref()
                .unwrap_or_else(|| panic!("{command} {}: no CSV", f.path));
            let table = a
                .table_at(csv)
                .unwrap_or_else(|| panic!("{command} {}: {csv} not written", f.path));
            // Read back what the file will hold (the numbers round-trip exactly).
            let cols = csv_columns(&table.to_csv().unwrap());
            for (p, panel) in f.figure.panels.iter().enumerate() {
                for s in &panel.series {
                    let n = s.x.len().min(s.y.len());
                    // x and y of the series are two columns of the figure's own table.
                    for (axis, v) in [("x", &s.x[..n]), ("y", &s.y[..n])] {
                        assert!(
                            cols.iter().any(|(_, c)| same_numbers(v, c)),
                            "{command} {} panel {p} series {:?}: {axis} values are no column of {csv}",
                            f.path,
                            s.name
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn wear_figures_have_distinct_tables() {
    // Fig. 11, 12 and 13 once shared one table; each now has its own columns.
    let (model, study) = paper();
    let a = run_artifacts(
        model,
        study,
        None,
        &RunMetadata::new("run", &model.case),
        Default::default(),
    );
    let header = |stem: &str| {
        a.table_at(&format!("csv/{stem}.csv"))
            .unwrap()
            .names
            .clone()
    };
    let h11 = header("fig11_force_and_wear_initial");
    let h12 = header("fig12_wear_rate_evolution");
    let h13 = header("fig13_max_accumulated_wear");
    assert!(h11.iter().any(|n| n == "pair_load_n_dynamic"), "{h11:?}");
    assert!(h12
        .iter()
        .any(|n| n.starts_with("wear_rate_um_per_kcycle_quasi_static_at_")));
    assert!(
        h13.iter().any(|n| n == "max_wear_pinion_um_dynamic"),
        "{h13:?}"
    );
    assert!(h11 != h12 && h12 != h13 && h11 != h13);
}

/// No legend or colour bar of `lay` covers a plotted point or a marker label; a panel with
/// two or more named series has its legend (none is dropped at these sizes); every data
/// pixel lies inside the plot area, so the marks are where the data are drawn.
fn check_layout(what: &str, f: &FigureFile, lays: &[PanelLayout]) {
    assert_eq!(lays.len(), f.figure.panels.len(), "{what}");
    let image = gearwear::report::plot::Rect::at(0, 0, f.width_px, f.height_px);
    for (i, (panel, lay)) in f.figure.panels.iter().zip(lays).enumerate() {
        let named = panel.series.iter().filter(|s| !s.name.is_empty()).count();
        assert_eq!(lay.legend.is_some(), named > 1, "{what} panel {i}: legend");
        assert_eq!(
            lay.color_bar.is_some(),
            panel.color_bar.is_some(),
            "{what} panel {i}"
        );
        // Lines are 2 px wide and markers 4 px in radius around their point.
        let plot = lay.plot.inflate(5);
        assert!(
            lay.marks.iter().all(|m| plot.contains(*m)),
            "{what} panel {i}: mark outside"
        );
        for (kind, r) in [("legend", lay.legend), ("colour bar", lay.color_bar)] {
            let Some(r) = r else { continue };
            assert!(image.x0 <= r.x0 && r.x1 <= image.x1 && image.y0 <= r.y0 && r.y1 <= image.y1);
            let hit = lay.marks.iter().find(|m| r.contains(**m));
            assert!(
                hit.is_none(),
                "{what} panel {i}: {kind} {r:?} covers a point at {hit:?}"
            );
            let label = lay.labels.iter().find(|l| l.intersects(&r));
            assert!(
                label.is_none(),
                "{what} panel {i}: {kind} covers label {label:?}"
            );
        }
        for (j, a) in lay.labels.iter().enumerate() {
            for b in &lay.labels[j + 1..] {
                assert!(!a.intersects(b), "{what} panel {i}: marker labels overlap");
            }
        }
    }
}

/// Every text of a figure a reader sees: title, panel titles, axis labels, legend names,
/// colour-bar label and marker labels.
fn figure_texts(f: &gearwear::report::plot::Figure) -> Vec<String> {
    let mut out = vec![f.title.clone()];
    for p in &f.panels {
        out.extend([p.title.clone(), p.x_label.clone(), p.y_label.clone()]);
        out.extend(p.series.iter().map(|s| s.name.clone()));
        out.extend(p.color_bar.iter().map(|b| b.label.clone()));
        out.extend(p.vlines.iter().map(|v| v.1.clone()));
    }
    out
}

#[test]
fn figure_labels_are_words_not_identifiers() {
    // Code names join words with underscores ("quasi_static", "load_torque_nm"); labels
    // a reader sees use words and unit symbols.
    for (command, a) in all_artifacts() {
        for f in &a.figures {
            for t in figure_texts(&f.figure) {
                assert!(!t.contains('_'), "{command} {}: label {t:?}", f.path);
            }
        }
    }
}

#[test]
fn no_two_legend_entries_are_drawn_alike_in_any_figure_of_the_commands() {
    // Issue 34: bins 1, 17 and 25 of a duty figure were drawn alike. Every named series
    // of a panel must differ from the others in colour, line style or marker as drawn.
    let mut entries = 0;
    for (command, a) in all_artifacts() {
        for f in &a.figures {
            for p in &f.figure.panels {
                entries += p.series.iter().filter(|s| !s.name.is_empty()).count();
                let same = p.indistinct_entries();
                assert!(
                    same.is_empty(),
                    "{command} {}: drawn alike {same:?}",
                    f.path
                );
            }
        }
    }
    assert!(
        entries > 20,
        "only {entries} legend entries: the check would be vacuous"
    );
}

#[test]
fn no_legend_covers_data_in_any_figure_of_the_commands() {
    for (command, a) in all_artifacts() {
        for f in &a.figures {
            let lays = layout(&f.figure, f.width_px, f.height_px).unwrap();
            check_layout(&format!("{command} {}", f.path), f, &lays);
        }
    }
}

#[test]
fn no_legend_covers_data_in_the_sweep_figure() {
    // A real speed sweep with two loads (two named curves per panel) and its resonance
    // markers, built as `sweep` and `sweep-merge` build it from the written files.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s");
    let o = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args([
            "sweep",
            "-q",
            "--vary",
            "operating.input_speed_hz=20:60:5",
            "--vary",
            "operating.load_torque_nm=40,80",
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let table =
        SweepTable::from_csv(&std::fs::read_to_string(out.join("sweep.csv")).unwrap()).unwrap();
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("sweep.json")).unwrap()).unwrap();
    let marks: Vec<Crossing> =
        serde_json::from_value(meta["resonance_crossings"].clone()).unwrap_or_default();
    assert!(
        !marks.is_empty(),
        "the sweep should cross a resonance: {meta}"
    );
    let poles: Vec<f64> = meta["modes"]["mesh_poles"]
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(|p| p["damped_frequency_hz"].as_f64())
                .collect()
        })
        .unwrap_or_default();
    let figure = figure_for(&table, &marks, &poles).expect("a speed sweep has a figure");
    let (w, h) = SWEEP_FIGURE_PX;
    let f = FigureFile {
        path: "sweep.png".into(),
        figure,
        width_px: w,
        height_px: h,
        data: None,
        rendered: None,
    };
    let lays = layout(&f.figure, w, h).unwrap();
    check_layout("sweep", &f, &lays);
    for t in figure_texts(&f.figure) {
        assert!(!t.contains('_'), "sweep: label {t:?}");
    }
}

#[test]
fn the_built_in_case_keeps_its_paper_comparison() {
    let (model, study) = paper();
    let a = run_artifacts(
        model,
        study,
        None,
        &RunMetadata::new("run", &model.case),
        Default::default(),
    );
    assert_eq!(a.summary["paper_case"], true);
    for k in [
        "/paper_comparison/dte_max_um_at_0.5um_wear/paper",
        "/paper_comparison/ratio_max_wear_dynamic_to_static/ours",
    ] {
        assert!(a.summary.pointer(k).is_some(), "{k}");
    }
    assert!(a.summary.get("case_summary").is_none());
    assert!(a.headline.contains("paper"), "{}", a.headline);
    let (_, html) = a.documents.iter().find(|d| d.0 == "report.html").unwrap();
    let html = String::from_utf8(html.clone()).unwrap();
    assert!(html.contains("beside the paper&#39;s"));
    // The paper's own operating point, as the paper prints it (Table 1, section 4.1):
    // 19 teeth at 30 Hz is a 570 Hz mesh frequency.
    assert!(
        html.contains("570 Hz mesh frequency"),
        "mesh frequency sentence"
    );
}

/// The figure of `run` whose file stem is `stem`.
fn run_figure(stem: &str) -> gearwear::report::plot::Figure {
    let (model, study) = paper();
    let a = run_artifacts(
        model,
        study,
        None,
        &RunMetadata::new("run", &model.case),
        Default::default(),
    );
    a.figures
        .iter()
        .find(|f| f.path == format!("{stem}.png"))
        .unwrap_or_else(|| panic!("{stem} missing"))
        .figure
        .clone()
}

#[test]
fn fig7_draws_its_three_wear_states_as_markers() {
    use gearwear::report::plot::{LineStyle, Marker};
    let f = run_figure("fig07_mesh_harmonics");
    for s in &f.panels[0].series {
        assert_eq!(s.x.len(), 3, "{}: one point per wear state", s.name);
        assert_eq!(s.style, LineStyle::Points, "{}: no connecting line", s.name);
        assert_ne!(s.marker, Marker::None, "{}", s.name);
    }
    // Distinct marker shapes, so the four harmonics differ in grey print too.
    let shapes: std::collections::BTreeSet<String> = f.panels[0]
        .series
        .iter()
        .map(|s| format!("{:?}", s.marker))
        .collect();
    assert_eq!(shapes.len(), f.panels[0].series.len());
}

#[test]
fn fig12_curves_have_distinct_colours_on_a_labelled_scale() {
    let f = run_figure("fig12_wear_rate_evolution");
    for p in &f.panels {
        let bar = p.color_bar.as_ref().expect("a colour bar");
        assert!(bar.label.contains("cycles"), "{}", bar.label);
        assert!(bar.max > bar.min);
        // The dynamic run of the paper's case has one curve per update (11 at 4e4
        // cycles): every curve its own colour, so the updates can be told apart.
        let colours: Vec<[u8; 3]> = p.series.iter().map(|s| s.color.unwrap()).collect();
        let distinct: std::collections::BTreeSet<[u8; 3]> = colours.iter().copied().collect();
        if p.title == "dynamic" {
            assert!(colours.len() >= 10, "{}", colours.len());
            assert_eq!(distinct.len(), colours.len(), "{colours:?}");
        }
    }
}
