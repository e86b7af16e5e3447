//! The figure of a one-parameter sweep: max DTE and dynamic factor against the varied
//! parameter, one curve per combination of the other varied keys and per continuation
//! branch, with the speeds where a mesh harmonic meets a damped mesh pole marked. A gear
//! train's sweep has one such figure per mesh (`STEM_stage<K>.png`), each with its own
//! mesh's columns and the crossings of its own harmonics.

use super::figures::{panel, Curve};
use super::plot::{Figure, LineStyle};
use crate::study::sweep::{Branch, Crossing, SweepTable, SPEED_KEY};
use std::collections::BTreeMap;

/// One curve: legend name, branch, and points (x, max DTE, dynamic factor).
type Group = (String, Option<Branch>, Vec<(f64, f64, f64)>);

/// Line style of a branch: `up` solid, `down` dashed (ordinary curves keep the cycle).
fn branch_style(b: Option<Branch>) -> Option<LineStyle> {
    b.map(|b| match b {
        Branch::Up => LineStyle::Solid,
        Branch::Down => LineStyle::Dashed,
    })
}

/// Legend name of a branch.
fn branch_name(b: Branch, x_key: &str) -> String {
    let what = if x_key == SPEED_KEY {
        "speed"
    } else {
        "parameter"
    };
    match b {
        Branch::Up => format!("up (rising {what})"),
        Branch::Down => format!("down (falling {what})"),
    }
}

/// Max DTE and dynamic factor against `x_key` (a varied key of `t` with numeric values).
/// `marks` (with `poles_hz`, the damped mesh-pole frequencies) are drawn as labelled
/// vertical lines. `None` when `x_key` is not varied.
pub fn sweep_figure(
    t: &SweepTable,
    x_key: &str,
    marks: &[Crossing],
    poles_hz: &[f64],
) -> Option<Figure> {
    sweep_figure_of(t, x_key, marks, poles_hz, None)
}

/// As [`sweep_figure`], of the columns of mesh `stage` (0-based) of a gear train's table
/// (`None`: the pair's columns).
fn sweep_figure_of(
    t: &SweepTable,
    x_key: &str,
    marks: &[Crossing],
    poles_hz: &[f64],
    stage: Option<usize>,
) -> Option<Figure> {
    let kx = t.keys.iter().position(|k| k == x_key)?;
    // Curves keyed by the other keys' values, then the branch (up before down).
    let mut groups: BTreeMap<(String, Option<u8>), Group> = BTreeMap::new();
    for r in &t.rows {
        let Ok(x) = r.values[kx].parse::<f64>() else {
            continue;
        };
        let others: Vec<String> = (0..t.keys.len())
            .filter(|i| *i != kx)
            .map(|i| value_words(&t.keys[i], &r.values[i]))
            .collect();
        let others = others.join(", ");
        let name = match (r.branch, others.is_empty()) {
            (Some(b), true) => branch_name(b, x_key),
            (Some(b), false) => format!("{others}, {}", branch_name(b, x_key)),
            (None, _) => others.clone(),
        };
        groups
            .entry((others, r.branch.map(|b| b as u8)))
            .or_insert_with(|| (name, r.branch, Vec::new()))
            .2
            .push(match stage.and_then(|k| r.results.meshes.get(k)) {
                Some(m) => (x, m.dte_max_um, m.dynamic_factor),
                None => (
                    x,
                    r.results.dynamics.dte_max_um,
                    r.results.dynamics.dynamic_factor,
                ),
            });
    }
    let (mut c_dte, mut c_df, mut styles) = (Vec::new(), Vec::new(), Vec::new());
    for (name, branch, mut pts) in groups.into_values() {
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let x: Vec<f64> = pts.iter().map(|p| p.0).collect();
        c_dte.push(Curve::new(
            name.clone(),
            x.clone(),
            pts.iter().map(|p| p.1).collect(),
        ));
        c_df.push(Curve::new(name, x, pts.iter().map(|p| p.2).collect()));
        styles.push(branch_style(branch));
    }
    let several = poles_hz.len() > 1;
    let vlines: Vec<(f64, String)> = marks
        .iter()
        .map(|c| (c.input_speed_hz, c.label(several)))
        .collect();
    let x_label = axis_words(x_key);
    let mut p1 = panel(&x_label, "max DTE (µm)", c_dte);
    let mut p2 = panel(&x_label, "dynamic factor (-)", c_df);
    for p in [&mut p1, &mut p2] {
        for (s, style) in p.series.iter_mut().zip(&styles) {
            if let Some(st) = style {
                s.style = *st;
            }
        }
        p.vlines = vlines.clone();
    }
    let poles: Vec<String> = poles_hz.iter().map(|f| format!("{f:.0} Hz")).collect();
    let mut title = if x_key == SPEED_KEY && !poles.is_empty() {
        format!(
            "Speed sweep (markers: k × mesh frequency = damped mesh pole {}, k = 1..4)",
            poles.join(", ")
        )
    } else if x_key == SPEED_KEY {
        "Speed sweep".to_string()
    } else {
        format!("Sweep of the {}", key_words(x_key).0)
    };
    if let Some(k) = stage {
        // Kept short: a train has several mesh poles.
        title = if x_key == SPEED_KEY && !poles.is_empty() {
            format!(
                "Stage {} mesh, speed sweep (markers: k × its mesh frequency = mesh pole {})",
                k + 1,
                poles.join(", ")
            )
        } else {
            format!("Stage {} mesh: {}", k + 1, title.to_lowercase())
        };
    }
    Some(Figure {
        title,
        panels: vec![p1, p2],
    })
}

/// The figure of a sweep table: a speed sweep's (with `marks`, see [`sweep_figure`]) or a
/// continuation sweep's (its branches against the varied value); `None` for other sweeps.
pub fn figure_for(t: &SweepTable, marks: &[Crossing], poles_hz: &[f64]) -> Option<Figure> {
    if t.keys.iter().any(|k| k == SPEED_KEY) {
        sweep_figure(t, SPEED_KEY, marks, poles_hz)
    } else if t.has_branches() {
        sweep_figure(t, t.keys.first()?, &[], &[])
    } else {
        None
    }
}

/// The figures of a sweep table, each with the suffix of its file name after the stem:
/// a single pair's [`figure_for`] (suffix empty), or one per mesh of a gear train
/// (`_stage<K>`), each with the crossings of its own harmonics (`stage_marks`, stage by
/// stage; [`figure_for`]'s `marks` for a table of a pair).
pub fn figures_for(
    t: &SweepTable,
    marks: &[Crossing],
    stage_marks: &[Vec<Crossing>],
    poles_hz: &[f64],
) -> Vec<(String, Figure)> {
    if t.stages == 0 {
        return figure_for(t, marks, poles_hz)
            .map(|f| (String::new(), f))
            .into_iter()
            .collect();
    }
    let x_key = if t.keys.iter().any(|k| k == SPEED_KEY) {
        SPEED_KEY
    } else if t.has_branches() {
        match t.keys.first() {
            Some(k) => k.as_str(),
            None => return Vec::new(),
        }
    } else {
        return Vec::new();
    };
    (0..t.stages)
        .filter_map(|k| {
            let (m, p) = match (x_key == SPEED_KEY, stage_marks.get(k)) {
                (true, Some(m)) => (&m[..], poles_hz),
                _ => (&[][..], &[][..]),
            };
            let f = sweep_figure_of(t, x_key, m, p, Some(k))?;
            Some((format!("_stage{}", k + 1), f))
        })
        .collect()
}

/// Unit suffixes of case keys (the config's naming rule) and their symbols, longest first
/// so that `_n_s_per_m` is not read as `_m`.
const UNITS: [(&str, &str); 14] = [
    ("_nm_s_per_rad", "N m s/rad"),
    ("_nm_per_rad", "N m/rad"),
    ("_n_s_per_m", "N s/m"),
    ("_m2_per_n", "m²/N"),
    ("_n_per_m", "N/m"),
    ("_kg_m2", "kg m²"),
    ("_gpa", "GPa"),
    ("_deg", "deg"),
    ("_kg", "kg"),
    ("_nm", "N m"),
    ("_hz", "Hz"),
    ("_mm", "mm"),
    ("_um", "µm"),
    ("_cp", "cP"),
];

/// A case key in words and its unit: "operating.load_torque_nm" -> ("load torque", "N m");
/// a key without a unit suffix keeps an empty unit.
pub fn key_words(key: &str) -> (String, &'static str) {
    let field = key.rsplit('.').next().unwrap_or(key);
    let (stem, unit) = UNITS
        .iter()
        .find_map(|(suffix, unit)| field.strip_suffix(suffix).map(|s| (s, *unit)))
        .unwrap_or((field, ""));
    (stem.replace('_', " "), unit)
}

/// "load torque 40 N m" for the key and a value of it.
fn value_words(key: &str, value: &str) -> String {
    match key_words(key) {
        (name, "") => format!("{name} {value}"),
        (name, unit) => format!("{name} {value} {unit}"),
    }
}

/// The axis label of a key: "input speed (Hz)".
fn axis_words(key: &str) -> String {
    match key_words(key) {
        (name, "") => name,
        (name, unit) => format!("{name} ({unit})"),
    }
}

/// Size of the two-panel sweep figure, px (taller than the one-panel default).
pub const SWEEP_FIGURE_PX: (u32, u32) = (900, 640);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_read_as_words_with_their_units() {
        assert_eq!(axis_words(SPEED_KEY), "input speed (Hz)");
        assert_eq!(
            value_words("operating.load_torque_nm", "40"),
            "load torque 40 N m"
        );
        let damping = "dynamics.bearing_damping_pinion_n_s_per_m";
        assert_eq!(axis_words(damping), "bearing damping pinion (N s/m)");
        assert_eq!(
            value_words("dynamics.mesh_damping_ratio", "0.1"),
            "mesh damping ratio 0.1"
        );
    }
}
