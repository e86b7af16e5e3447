//! `gearwear dynamics` on a gear train draws every mesh: the transmission-error and
//! mesh-force figures have a panel per stage, and their tables a column per mesh whose
//! extremes are the ones `summary.json` reports for that mesh (computed apart, from the
//! response's summary, not from the figure's table).

mod common;
use common::read_csv;

const REDUCER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/examples/two_stage_reducer.toml"
);

/// The column `name` of a CSV table as numbers.
fn column(path: &std::path::Path, name: &str) -> Vec<f64> {
    let (head, rows) = read_csv(path);
    let k = head
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("{}: no column {name} in {head:?}", path.display()));
    rows.iter().map(|r| r[k].parse().unwrap()).collect()
}

#[test]
fn the_dynamics_figures_of_a_train_show_every_mesh() {
    let d = tempfile::tempdir().unwrap();
    let out = common::run_into(d.path(), "train", &["dynamics"], Some(REDUCER), &[]);
    let summary: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    let meshes = summary["meshes"].as_array().unwrap();
    assert_eq!(meshes.len(), 2);
    for (file, first, later, key) in [
        ("csv/dte.csv", "dte_um", "mesh2_dte_um", "dte"),
        (
            "csv/mesh_force.csv",
            "mesh_force_n",
            "mesh2_mesh_force_n",
            "mesh_force",
        ),
    ] {
        let (head, _) = read_csv(&out.join(file));
        assert_eq!(head, ["time_ms", first, later], "{file}");
        for (m, col) in [first, later].iter().enumerate() {
            let v = column(&out.join(file), col);
            let max = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let min = v.iter().copied().fold(f64::INFINITY, f64::min);
            let s = &meshes[m][key];
            let (smax, smin) = if key == "dte" {
                (s["max_um"].as_f64().unwrap(), s["min_um"].as_f64().unwrap())
            } else {
                (s["max_n"].as_f64().unwrap(), s["min_n"].as_f64().unwrap())
            };
            // The same samples: the figure's table and the summary both read the
            // recorded response, so the extremes agree to the CSV's round trip.
            assert!((max - smax).abs() <= 1e-12 * smax.abs(), "{file} {col} max");
            assert!((min - smin).abs() <= 1e-12 * smin.abs(), "{file} {col} min");
        }
    }
}
