//! What the two dataset-folder fuzz targets share: the files of two real small datasets
//! (the targets' seeds, `fuzz/seeds/dataset_sidecar` and `fuzz/seeds/dataset_shard`), and
//! the index a run or merge builds from sidecars and a description, with its trends
//! table and figure, through the functions the app calls (`app::dataset::folder`).
//!
//! The two datasets: `examples/dataset/quick_start.toml` with `signals.record_length=0.1`
//! (2 conditions x 2 states, 2 sensors: 4 records), and a design of 1 condition at the
//! pinion cycles [0, 1e4], speeds [25, 35] Hz, 2 noise realisations, CSV records, 0.05 s
//! records on coarse grids (8 records).

// Each target compiles this module and uses a part of it.
#![allow(dead_code)]

use gearwear::app::dataset::folder::{parse_sidecar, Sidecar};
use gearwear::app::dataset::index_files::index_tables;
use gearwear::io::columns_csv::columns_csv;
use gearwear::report::artifacts::Rendered;
use gearwear::report::dataset_trends::trend_figure;
use gearwear::report::figure_output::FigureOutput;
use gearwear::study::dataset::trends::{trend_columns, trends};
use serde_json::Value;
use std::path::Path;
use std::sync::OnceLock;

/// The real datasets' descriptions (`state/dataset.json`).
pub const DESCRIPTIONS: [&[u8]; 2] = [
    include_bytes!("../../seeds/dataset_shard/quick_start_dataset.json"),
    include_bytes!("../../seeds/dataset_shard/small_dataset.json"),
];

/// The real datasets' sidecars (`records/<id>.json`), both datasets.
const SIDECARS: [&[u8]; 12] = [
    include_bytes!("../../seeds/dataset_sidecar/quick_start_0000000.json"),
    include_bytes!("../../seeds/dataset_sidecar/quick_start_0000001.json"),
    include_bytes!("../../seeds/dataset_sidecar/quick_start_0000002.json"),
    include_bytes!("../../seeds/dataset_sidecar/quick_start_0000003.json"),
    include_bytes!("../../seeds/dataset_sidecar/small_0000000.json"),
    include_bytes!("../../seeds/dataset_sidecar/small_0000001.json"),
    include_bytes!("../../seeds/dataset_sidecar/small_0000002.json"),
    include_bytes!("../../seeds/dataset_sidecar/small_0000003.json"),
    include_bytes!("../../seeds/dataset_sidecar/small_0000004.json"),
    include_bytes!("../../seeds/dataset_sidecar/small_0000005.json"),
    include_bytes!("../../seeds/dataset_sidecar/small_0000006.json"),
    include_bytes!("../../seeds/dataset_sidecar/small_0000007.json"),
];

/// The real sidecars, parsed as a folder reads them.
pub fn real_sidecars() -> &'static [Sidecar] {
    static S: OnceLock<Vec<Sidecar>> = OnceLock::new();
    S.get_or_init(|| {
        SIDECARS
            .iter()
            .map(|b| parse_sidecar(b).expect("a real sidecar parses"))
            .collect()
    })
}

/// The real descriptions, parsed.
pub fn real_descriptions() -> &'static [Value] {
    static D: OnceLock<Vec<Value>> = OnceLock::new();
    D.get_or_init(|| {
        DESCRIPTIONS
            .iter()
            .map(|b| serde_json::from_slice(b).expect("a real description parses"))
            .collect()
    })
}

/// Build the index of `cars` (one per record id, as a folder holds them) under `body` (a
/// dataset of `total` records) as a run or a merge does, then its trends table and figure
/// (SVG): an error is a refusal, never a panic; every record is indexed or counted
/// missing.
pub fn index_and_trends(cars: Vec<Sidecar>, body: &Value, total: usize) {
    let Ok(t) = index_tables(cars, body, total, Path::new("state/dataset.json")) else {
        return;
    };
    assert_eq!(t.present + t.missing.count, total);
    assert!(t.missing.listed.len() <= t.missing.count);
    let Some(tr) = trends(&t.columns) else {
        return;
    };
    let _ = columns_csv(&trend_columns(&tr));
    let figure = trend_figure(&tr, &t.channel_unit);
    let svg = FigureOutput {
        png: false,
        svg: true,
        size_px: None,
    };
    let _ = Rendered::of(&figure, (900, 1500), svg, "indicator_trends.png");
}
