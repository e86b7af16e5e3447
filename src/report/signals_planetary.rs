//! Results of `gearwear signals` on a planetary set (docs/SIGNALS.md 6): `record.csv` (the
//! ring sensor's signal at the case's sampling rate), `orders.csv` (the amplitude of every
//! carrier order of its steady, one-revolution-periodic signal) and `summary.json` with the
//! frequencies and each mesh harmonic's sidebands.

use super::artifacts::Artifacts;
use crate::format::shown;
use crate::io::Table;
use crate::study::planetary_dynamics::PlanetaryDynamics;
use crate::study::planetary_signals::{RingSensor, RingSensorRecord};
use serde_json::json;

/// Sidebands listed either side of each mesh harmonic: two planet-pass multiples.
fn sideband_reach(planets: usize) -> i64 {
    2 * planets as i64
}

/// Everything `gearwear signals` writes for a planetary set; `harmonics` mesh harmonics.
pub fn planetary_signals_artifacts(
    d: &PlanetaryDynamics,
    rec: &RingSensorRecord,
    sensor: RingSensor,
    harmonics: usize,
) -> Artifacts {
    let set = &d.study.set;
    let n = set.planets();
    let zr = set.teeth_ring() as i64;
    let amp = &rec.order_amplitude_n;
    // Line index of carrier order k: k R (R = 1 without a tooth fault).
    let r = rec.revolutions.max(1) as i64;
    let at = |k: i64| {
        usize::try_from(k * r)
            .ok()
            .and_then(|k| amp.get(k))
            .copied()
    };
    let reach = sideband_reach(n);
    let mesh: Vec<_> = (1..=harmonics as i64)
        .filter(|h| at(h * zr).is_some())
        .map(|h| {
            let sidebands: Vec<_> = (-reach..=reach)
                .filter(|l| *l != 0)
                .filter_map(|l| {
                    let k = h * zr + l;
                    at(k).map(|a| {
                        json!({"offset_orders": l, "order": k, "frequency_hz": k as f64 * rec.carrier_hz, "amplitude_n": a})
                    })
                })
                .collect();
            json!({
                "harmonic": h,
                "order": h * zr,
                "frequency_hz": (h * zr) as f64 * rec.carrier_hz,
                "amplitude_n": at(h * zr),
                "sidebands": sidebands,
            })
        })
        .collect();
    let mut v = json!({
        "planetary_signals": {
            "sensor": "on the ring (fixed)",
            "sensor_angle_deg": sensor.angle_rad.to_degrees(),
            "window_half_width_deg": sensor.half_width_rad.to_degrees(),
            "carrier_hz": rec.carrier_hz,
            "mesh_frequency_hz": rec.mesh_frequency_hz,
            "planet_pass_hz": rec.planet_pass_hz,
            "samples_per_revolution": rec.revolution_n.len() / rec.revolutions.max(1),
            "mesh_harmonics": mesh,
            "lumped_parameters": super::stiffness_planetary::lumped_json(&d.study),
        },
        // The acquisition as PHM datasets state it: rate, length, the channel's unit.
        "record": {
            "sampling_rate_hz": sensor.sampling_rate_hz,
            "samples": rec.times_s.len(),
            "duration_s": rec.times_s.len() as f64 / sensor.sampling_rate_hz,
            "channel": "ring_sensor_n",
            "channel_unit": "N",
        },
        "warnings": d.study.warnings,
    });
    if let Some(f) = fault_lines(d, rec, harmonics) {
        v["planetary_signals"]["fault"] = f;
    }
    let mut a = Artifacts {
        headline: format!(
            "planetary signals, {n} planets: a sensor on the ring hears the mesh frequency {} Hz with sidebands at the planet-pass frequency {} Hz (carrier {} Hz)",
            shown(rec.mesh_frequency_hz),
            shown(rec.planet_pass_hz),
            shown(rec.carrier_hz),
        ),
        summary: v,
        ..Default::default()
    };
    a.table(
        "record.csv",
        Table::new()
            .col("time_s", rec.times_s.clone())
            .col("ring_sensor_n", rec.values_n.clone()),
    );
    let orders: Vec<f64> = (0..amp.len()).map(|k| k as f64 / r as f64).collect();
    a.table(
        "orders.csv",
        Table::new()
            .col("carrier_order", orders.clone())
            .col(
                "frequency_hz",
                orders.iter().map(|k| k * rec.carrier_hz).collect(),
            )
            .col("amplitude_n", amp.clone()),
    );
    a
}

/// With a tooth fault: its repeat frequency f_m / P (the sun's rotation relative to the
/// carrier, f_s - f_c, for a sun tooth; the planet's, for a planet tooth) and the lines
/// h f_m + l f_m / P around each mesh harmonic, |l| up to 2 N for N planets (at least 3):
/// a faulty sun tooth meets the N planets in turn, so its characteristic line is
/// N (f_s - f_c) (Feng & Zuo 2012) and the others come from the sensor's window
/// (docs/MODEL.md 12.13); None without one.
fn fault_lines(
    d: &PlanetaryDynamics,
    rec: &RingSensorRecord,
    harmonics: usize,
) -> Option<serde_json::Value> {
    let p = d.study.meshes.periods();
    let f = d.study.meshes.fault()?;
    let zr = d.study.set.teeth_ring();
    let reach = (2 * d.study.set.planets()).max(3) as i64;
    // Lines of the record are f_c / R apart: f_m is z_r R of them, f_m / P is z_r R / P.
    let per_mesh = zr * rec.revolutions.max(1);
    let step = per_mesh / p;
    let amp = &rec.order_amplitude_n;
    let lines: Vec<_> = (1..=harmonics)
        .filter(|h| h * per_mesh < amp.len())
        .map(|h| {
            let sidebands: Vec<_> = (-reach..=reach)
                .filter(|l| *l != 0)
                .filter_map(|l| {
                    let k = (h * per_mesh) as i64 + l * step as i64;
                    let a = usize::try_from(k).ok().and_then(|k| amp.get(k))?;
                    let hz = k as f64 * rec.carrier_hz / rec.revolutions.max(1) as f64;
                    Some(json!({"offset": l, "frequency_hz": hz, "amplitude_n": a}))
                })
                .collect();
            json!({"harmonic": h, "amplitude_n": amp[h * per_mesh], "sidebands": sidebands})
        })
        .collect();
    Some(json!({
        "member": f.member.name(),
        "tooth": f.tooth,
        "period_mesh_periods": p,
        "record_carrier_revolutions": rec.revolutions,
        "fault_frequency_hz": rec.mesh_frequency_hz / p as f64,
        "mesh_harmonics": lines,
    }))
}
