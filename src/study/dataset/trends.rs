//! Condition-indicator trends along the run-to-failure trajectories of a dataset
//! (`indicator_trends.csv` and `.png`, docs/SIGNALS.md "Indicator trends"), from its
//! index columns: for each condition at each speed and load, the trajectory's states in
//! order of cycles, each indicator averaged over the state's noise realisations.
//!
//! The indicators followed are those of the first channel: the record's RMS and
//! kurtosis, and FM0, FM4, NA4 (the index's trend-normalised value) and the sideband
//! level factor of the pinion's TSA.

use crate::io::parquet::{Column, ColumnData};

/// Index-column suffixes (after `<channel>_`) of the indicators followed.
pub const TREND_INDICATORS: [&str; 6] = [
    "rms",
    "kurtosis",
    "pinion_fm0",
    "pinion_fm4",
    "pinion_na4",
    "pinion_sideband_level_factor",
];

/// Label columns carried into the trend table (means over the realisations, which share
/// them).
const WEAR_COLUMNS: [&str; 2] = ["max_wear_pinion_um", "max_wear_gear_um"];

/// One trajectory at one speed and load: its states in order of cycles.
#[derive(Debug, Clone, PartialEq)]
pub struct TrendLine {
    /// The condition's name.
    pub condition: String,
    /// Input speed, Hz.
    pub input_speed_hz: f64,
    /// Load torque, N m.
    pub load_torque_nm: f64,
    /// Index of each state along the trajectory.
    pub trajectory_state: Vec<i64>,
    /// Pinion cycles of each state.
    pub cycles: Vec<f64>,
    /// Records averaged at each state.
    pub realisations: Vec<i64>,
    /// (index column, mean value at each state): the wear columns, then the indicators.
    pub values: Vec<(String, Vec<f64>)>,
}

/// The trends of a dataset.
#[derive(Debug, Clone, PartialEq)]
pub struct Trends {
    /// The channel whose indicators are followed.
    pub channel: String,
    /// One line per condition, speed and load.
    pub lines: Vec<TrendLine>,
}

fn f64s<'a>(cols: &'a [Column], name: &str) -> Option<&'a [f64]> {
    match &cols.iter().find(|c| c.name == name)?.data {
        ColumnData::F64(v) => Some(v),
        _ => None,
    }
}

fn i64s<'a>(cols: &'a [Column], name: &str) -> Option<&'a [i64]> {
    match &cols.iter().find(|c| c.name == name)?.data {
        ColumnData::I64(v) => Some(v),
        _ => None,
    }
}

fn texts<'a>(cols: &'a [Column], name: &str) -> Option<&'a [String]> {
    match &cols.iter().find(|c| c.name == name)?.data {
        ColumnData::Text(v) => Some(v),
        _ => None,
    }
}

/// The trends of the index `cols` (`study::dataset::index::index_columns`); `None` when
/// the index has no rows or no channel.
pub fn trends(cols: &[Column]) -> Option<Trends> {
    let channel = cols
        .iter()
        .find_map(|c| c.name.strip_suffix("_pinion_fm0"))?
        .to_owned();
    let condition = texts(cols, "condition")?;
    let speed = f64s(cols, "input_speed_hz")?;
    let load = f64s(cols, "load_torque_nm")?;
    let state = i64s(cols, "trajectory_state")?;
    let cycles = f64s(cols, "cycles")?;
    let names: Vec<String> = WEAR_COLUMNS
        .iter()
        .map(|s| s.to_string())
        .chain(TREND_INDICATORS.iter().map(|s| format!("{channel}_{s}")))
        .collect();
    let series: Vec<&[f64]> = names.iter().map(|n| f64s(cols, n)).collect::<Option<_>>()?;
    // Lines in order of first appearance (record ids: conditions slowest), states within
    // a line in order of cycles.
    let mut lines: Vec<(TrendLine, Vec<Vec<usize>>)> = Vec::new();
    for row in 0..condition.len() {
        let same = |l: &TrendLine| {
            l.condition == condition[row]
                && l.input_speed_hz.to_bits() == speed[row].to_bits()
                && l.load_torque_nm.to_bits() == load[row].to_bits()
        };
        let k = match lines.iter().position(|(l, _)| same(l)) {
            Some(k) => k,
            None => {
                lines.push((
                    TrendLine {
                        condition: condition[row].clone(),
                        input_speed_hz: speed[row],
                        load_torque_nm: load[row],
                        trajectory_state: Vec::new(),
                        cycles: Vec::new(),
                        realisations: Vec::new(),
                        values: Vec::new(),
                    },
                    Vec::new(),
                ));
                lines.len() - 1
            }
        };
        let (line, members) = &mut lines[k];
        match line.trajectory_state.iter().position(|s| *s == state[row]) {
            Some(j) => members[j].push(row),
            None => {
                line.trajectory_state.push(state[row]);
                line.cycles.push(cycles[row]);
                members.push(vec![row]);
            }
        }
    }
    let lines = lines
        .into_iter()
        .map(|(mut line, members)| {
            let mut order: Vec<usize> = (0..members.len()).collect();
            order.sort_by(|a, b| {
                line.cycles[*a]
                    .total_cmp(&line.cycles[*b])
                    .then(line.trajectory_state[*a].cmp(&line.trajectory_state[*b]))
            });
            line.trajectory_state = order.iter().map(|j| line.trajectory_state[*j]).collect();
            line.cycles = order.iter().map(|j| line.cycles[*j]).collect();
            line.realisations = order.iter().map(|j| members[*j].len() as i64).collect();
            line.values = names
                .iter()
                .zip(&series)
                .map(|(n, v)| {
                    let means = order
                        .iter()
                        .map(|j| {
                            let rows = &members[*j];
                            rows.iter().map(|r| v[*r]).sum::<f64>() / rows.len() as f64
                        })
                        .collect();
                    (n.clone(), means)
                })
                .collect();
            line
        })
        .collect();
    Some(Trends { channel, lines })
}

/// The trend table: one row per line and state.
pub fn trend_columns(t: &Trends) -> Vec<Column> {
    use ColumnData::*;
    let rows =
        |f: &dyn Fn(&TrendLine) -> Vec<f64>| -> Vec<f64> { t.lines.iter().flat_map(f).collect() };
    let repeat = |l: &TrendLine, x: f64| vec![x; l.cycles.len()];
    let mut cols = vec![
        Column::new(
            "condition",
            Text(
                t.lines
                    .iter()
                    .flat_map(|l| vec![l.condition.clone(); l.cycles.len()])
                    .collect(),
            ),
        ),
        Column::new(
            "input_speed_hz",
            F64(rows(&|l| repeat(l, l.input_speed_hz))),
        ),
        Column::new(
            "load_torque_nm",
            F64(rows(&|l| repeat(l, l.load_torque_nm))),
        ),
        Column::new(
            "trajectory_state",
            I64(t
                .lines
                .iter()
                .flat_map(|l| l.trajectory_state.clone())
                .collect()),
        ),
        Column::new("cycles", F64(rows(&|l| l.cycles.clone()))),
        Column::new(
            "realisations",
            I64(t
                .lines
                .iter()
                .flat_map(|l| l.realisations.clone())
                .collect()),
        ),
    ];
    let names: Vec<String> = t.lines.first().map_or(Vec::new(), |l| {
        l.values.iter().map(|(n, _)| n.clone()).collect()
    });
    for (k, n) in names.iter().enumerate() {
        cols.push(Column::new(
            n.clone(),
            F64(rows(&|l| l.values[k].1.clone())),
        ));
    }
    cols
}
