//! The modes of a case as tables (`modes.csv`, `modes_undamped.csv`) and summary keys.

use crate::dynamics::damped_modes::{PoleKind, MESH_POLE_MIN_SHARE};
use crate::io::Table;
use crate::study::ModalAnalysis;
use serde_json::{json, Value};

/// `modes.csv`: one row per damped pole (Im lambda >= 0), by pole magnitude: the pole,
/// its frequencies, damping ratio, mesh strain-energy share, whether it is oscillatory
/// and a mesh pole (1/0), and the complex shape (real and imaginary parts, largest
/// mass-normalised component real).
pub fn damped_table(m: &ModalAnalysis) -> Table {
    let d = &m.damped.modes;
    let col = |f: &dyn Fn(&crate::dynamics::damped_modes::DampedMode) -> f64| {
        d.iter().map(f).collect::<Vec<f64>>()
    };
    let flag = |b: bool| if b { 1.0 } else { 0.0 };
    let mut t = Table::new()
        .col("pole", (1..=d.len()).map(|i| i as f64).collect())
        .col("eigenvalue_real_per_s", col(&|x| x.real_per_s))
        .col("eigenvalue_imag_rad_per_s", col(&|x| x.imag_rad_per_s))
        .col("damped_frequency_hz", col(&|x| x.damped_frequency_hz))
        .col("pole_magnitude_hz", col(&|x| x.pole_magnitude_hz))
        .col("damping_ratio", col(&|x| x.damping_ratio))
        .col("mesh_energy_share", col(&|x| x.mesh_energy_share))
        .col(
            "oscillatory",
            col(&|x| flag(x.kind == PoleKind::Oscillatory)),
        )
        .col(
            "mesh_pole",
            col(&|x| {
                flag(x.kind == PoleKind::Oscillatory && x.mesh_energy_share >= MESH_POLE_MIN_SHARE)
            }),
        );
    for (k, (name, unit)) in m.coordinates.iter().enumerate() {
        t = t
            .col(&format!("shape_{name}_re_{unit}"), col(&|x| x.shape[k].re))
            .col(&format!("shape_{name}_im_{unit}"), col(&|x| x.shape[k].im));
    }
    t
}

/// `modes_undamped.csv`: the undamped natural frequencies (all damping removed) and their
/// mass-normalised shapes.
pub fn undamped_table(m: &ModalAnalysis) -> Table {
    let u = &m.undamped;
    let mut t = Table::new()
        .col(
            "mode",
            (1..=u.frequency_hz.len()).map(|i| i as f64).collect(),
        )
        .col("undamped_frequency_hz", u.frequency_hz.clone());
    for (k, (name, _)) in m.coordinates.iter().enumerate() {
        t = t.col(
            &format!("shape_{name}"),
            u.shapes.iter().map(|s| s[k]).collect(),
        );
    }
    t
}

/// Summary keys: `undamped_natural_frequencies_hz`, `damped_modes` and `mesh_poles`.
pub fn modes_json(m: &ModalAnalysis) -> Value {
    json!({
        "undamped_natural_frequencies_hz": m.undamped.frequency_hz,
        "damped_modes": m.damped.modes,
        "mesh_poles": m.damped.mesh_poles(),
        "mesh_pole_min_energy_share": MESH_POLE_MIN_SHARE,
    })
}
