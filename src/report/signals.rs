//! What `gearwear signals` writes for one record: the record (Parquet and CSV), its
//! spectrum and TSAs, the indicators in the summary, and the figures.

use super::artifacts::Artifacts;
use super::figures::{harmonic_label, mesh_harmonic_lines, panel, Curve};
use super::plot::{Figure, Panel, PanelKind, Series};
use crate::format::shown;
use crate::io::Table;
use crate::signals::analysis::ChannelAnalysis;
use crate::signals::chain::{Shaft, SignalChain};
use crate::signals::files::{channel_column, record_parquet, record_table};
use crate::signals::periodic::PeriodicSignal;
use crate::signals::record::{Kinematics, Record};
use crate::signals::record_spectrum::hann_amplitude_spectrum;
use crate::study::signal_record::SignalRecord;
use serde_json::{json, Value};

/// One period of the bearing forces (the chain's inputs) on M uniform points from time 0,
/// with their harmonics below the Nyquist frequency `fs_hz / 2` (above it the anti-alias
/// filter leaves at most 1e-5 of a line: the record owes them nothing at 1e-3), M the power
/// of two above twice the highest: an FFT of a column returns those lines exactly,
/// C_k = 2 X_k / M, so the record can be rebuilt from this file and the transfer path.
pub fn bearing_forces_table(forces: &[PeriodicSignal], fs_hz: f64) -> Table {
    let period = forces.first().map_or(0.0, |f| f.period_s);
    let below = ((0.5 * fs_hz * period).ceil() as usize).saturating_sub(1);
    let m = (2 * (below + 1)).next_power_of_two().max(16);
    let mut t = Table::new().col(
        "time_s",
        (0..m).map(|i| period * i as f64 / m as f64).collect(),
    );
    for (name, f) in crate::signals::bearing::INPUTS.iter().zip(forces) {
        let kept = PeriodicSignal {
            period_s: f.period_s,
            coefficients: f.coefficients.iter().take(below + 1).copied().collect(),
        };
        t = t.col(&format!("{name}_n"), kept.on_grid(m));
    }
    t
}

/// The chain as a summary object: everything needed to read the files.
pub fn chain_json(chain: &SignalChain, samples: usize) -> Value {
    let a = &chain.acquisition;
    json!({
        "sampling_rate_hz": a.sampling_rate_hz,
        "samples": samples,
        "duration_s": samples as f64 / a.sampling_rate_hz,
        "channel_unit": a.unit.symbol(),
        "sensitivity_mv_per_g": a.sensitivity_mv_per_g,
        "anti_alias": {
            "passband_edge_hz": a.sampling_rate_hz / crate::signals::antialias::SAMPLING_OVER_PASSBAND,
            "stopband_edge_hz": 0.5 * a.sampling_rate_hz,
            "stopband_attenuation_db": a.anti_alias_attenuation_db,
        },
        "noise": a.noise,
        "noise_seed": a.noise_seed,
        "tachometer": {
            "shaft": chain.tachometer.shaft.name(),
            "pulses_per_revolution": chain.tachometer.pulses_per_revolution,
            "high_level_v": crate::signals::tachometer::HIGH_V,
            "duty": crate::signals::tachometer::DUTY,
        },
        "sensors": chain.path.sensors,
        "sensor_placement": chain.path.placement,
        "transfer_path": chain.path.description,
    })
}

/// The shaft speeds (Hz), mesh frequency (Hz) and teeth of a record's pair, as summary JSON.
pub(crate) fn kinematics_json(k: &Kinematics) -> Value {
    json!({
        "pinion_shaft_hz": k.pinion_hz,
        "gear_shaft_hz": k.gear_hz,
        "mesh_hz": k.mesh_hz(),
        "teeth_pinion": k.teeth_pinion,
        "teeth_gear": k.teeth_gear,
    })
}

/// Everything `gearwear signals` writes (`label` names the state in titles).
pub fn signals_artifacts(
    rec: &SignalRecord,
    chain: &SignalChain,
    mesh_harmonics: usize,
    label: &str,
) -> Artifacts {
    let mut a = Artifacts::default();
    let unit = chain.acquisition.unit;
    let r = &rec.record;
    a.table("record.csv", record_table(r, unit));
    match record_parquet(r, unit, None) {
        Ok(bytes) => a.documents.push(("record.parquet".into(), bytes)),
        Err(e) => a
            .headline
            .push_str(&format!("record.parquet not written: {e}\n")),
    }
    a.summary = json!({
        "record": chain_json(chain, r.len()),
        "kinematics": kinematics_json(&rec.kinematics),
        "indicators": rec.analysis.iter().map(|c| c.indicators()).collect::<Vec<_>>(),
        "response": rec.response,
        "files": {
            "record.parquet": "the record: one float32 column per accelerometer and the tachometer (docs/SIGNALS.md)",
            "record.csv": "the same samples as CSV, with time_s",
        },
    });
    if !rec.train_meshes.is_empty() {
        // A train's every mesh, stage order: where its lines lie in the spectrum.
        a.summary["kinematics"]["meshes"] = rec.train_meshes.iter().map(kinematics_json).collect();
    }
    if let Some(forces) = &rec.bearing_forces {
        a.table(
            "bearing_forces.csv",
            bearing_forces_table(forces, chain.acquisition.sampling_rate_hz),
        );
        a.summary["files"]["bearing_forces.csv"] = json!("one period of the four bearing forces on the housing (N), uniformly sampled from time 0 with every harmonic below f_s / 2 that the chain took in: the FFT of a column gives its lines exactly (docs/SIGNALS.md)");
    }
    let unit_label = unit.symbol();
    let spec = spectrum_table(r, unit);
    a.figure_sized(
        "spectrum.png",
        spectrum_figure(r, rec, mesh_harmonics, unit_label, label),
        900,
        700,
    );
    a.table("spectrum.csv", spec);
    a.figure_sized(
        "time_signal.png",
        time_figure(r, &rec.kinematics, chain, unit_label, label),
        900,
        640,
    );
    for shaft in [Shaft::Pinion, Shaft::Gear] {
        if let Some(t) = tsa_table(&rec.analysis, shaft) {
            a.table(format!("tsa_{}.csv", shaft.name()), t);
        }
    }
    if rec.input_speed_hz.0 != rec.input_speed_hz.1 {
        let runup = super::runup::runup_artifacts(&mut a, rec, chain, mesh_harmonics, unit_label);
        a.summary["runup"] = runup;
    }
    a.figure_sized(
        "tsa.png",
        tsa_figure(&rec.analysis, unit_label, label),
        900,
        900,
    );
    // One line per channel: a sensor on the other housing may see a fault the first misses.
    let lines: Vec<String> = rec
        .analysis
        .iter()
        .map(|c| channel_headline(&c.indicators(), unit_label))
        .collect();
    a.headline.push_str(&lines.join("\n"));
    a
}

/// A channel's indicators for a person: its signal's and its pinion TSA's.
fn channel_headline(i: &crate::signals::analysis::ChannelIndicators, unit_label: &str) -> String {
    format!(
        "{}: RMS {} {unit_label}, crest factor {}, kurtosis {}{}",
        i.channel,
        shown(i.signal.rms),
        shown(i.signal.crest_factor),
        shown(i.signal.kurtosis),
        i.pinion.map_or(String::new(), |p| format!(
            "; pinion TSA ({} revolutions): FM0 {}, FM4 {}, NA4 {}",
            p.revolutions,
            shown(p.fm0),
            shown(p.fm4),
            shown(p.na4)
        ))
    )
}

fn spectrum_table(r: &Record, unit: crate::signals::chain::ChannelUnit) -> Table {
    let mut t = Table::new();
    for (i, (name, x)) in r.channels.iter().enumerate() {
        let (f, amp) = hann_amplitude_spectrum(x, r.sampling_rate_hz);
        if i == 0 {
            t = t.col("frequency_hz", f);
        }
        t = t.col(&format!("{}_amplitude", channel_column(name, unit)), amp);
    }
    t
}

/// Spectrum of the first channel: the recorded band with the mesh harmonics marked, and
/// the band around the mesh frequency with the shaft sidebands marked.
fn spectrum_figure(
    r: &Record,
    rec: &SignalRecord,
    harmonics: usize,
    unit: &str,
    label: &str,
) -> Figure {
    let Some((name, x)) = r.channels.first() else {
        return Figure::default();
    };
    let (f, amp) = hann_amplitude_spectrum(x, r.sampling_rate_hz);
    let band = r.sampling_rate_hz / crate::signals::antialias::SAMPLING_OVER_PASSBAND;
    let keep = |lo: f64, hi: f64| -> (Vec<f64>, Vec<f64>) {
        f.iter()
            .zip(&amp)
            .filter(|(f, _)| **f >= lo && **f <= hi)
            .map(|(f, a)| (*f, *a))
            .unzip()
    };
    let k = &rec.kinematics;
    let fm = k.mesh_hz();
    // Every mesh of a train is in the record (the housing carries them all).
    let meshes_hz: Vec<f64> = match rec.train_meshes.as_slice() {
        [] => vec![fm],
        t => t.iter().map(Kinematics::mesh_hz).collect(),
    };
    let stems = |x: Vec<f64>, y: Vec<f64>| Series {
        x,
        y,
        ..Default::default()
    };
    let (fx, fy) = keep(0.0, band);
    let full = Panel {
        title: format!("{name}: recorded band (to f_s / 2.56)"),
        x_label: "frequency (Hz)".into(),
        y_label: format!("amplitude ({unit})"),
        series: vec![stems(fx, fy)],
        vlines: mesh_harmonic_lines(&meshes_hz, band, harmonics),
        kind: PanelKind::Bars,
        log_y: true,
        ..Default::default()
    };
    // Around the strongest mesh harmonic of the recorded band (where the housing
    // carries the mesh best), its sidebands at the shaft speeds marked.
    // A tone between bins spreads over its neighbours (Hann main lobe): the
    // largest of the three bins around each harmonic stands for its level.
    let df = r.sampling_rate_hz / x.len() as f64;
    let level = |f: f64| {
        let b = (f / df).round() as usize;
        amp[b.saturating_sub(1)..(b + 2).min(amp.len())]
            .iter()
            .fold(0.0_f64, |m, a| m.max(*a))
    };
    let strongest = (1..)
        .map(|h| h as f64 * fm)
        .take_while(|f| *f <= band)
        .max_by(|a, b| level(*a).total_cmp(&level(*b)))
        .unwrap_or(fm);
    let h0 = (strongest / fm).round() as usize;
    let span = 4.5 * k.pinion_hz.max(k.gear_hz);
    let (zx, zy) = keep(strongest - span, strongest + span);
    let mut side = vec![(strongest, harmonic_label(h0))];
    for (sh, f) in [("pinion", k.pinion_hz), ("gear", k.gear_hz)] {
        for n in [-2.0, -1.0, 1.0, 2.0] {
            // A real minus sign (U+2212), as on the axes.
            let sign = if n < 0.0 { '\u{2212}' } else { '+' };
            side.push((strongest + n * f, format!("{sign}{} {sh}", n.abs())));
        }
    }
    let zoom = Panel {
        title: format!(
            "around the strongest mesh harmonic ({}): sidebands at the shaft speeds",
            harmonic_label(h0)
        ),
        x_label: "frequency (Hz)".into(),
        y_label: format!("amplitude ({unit})"),
        series: vec![stems(zx, zy)],
        vlines: side,
        kind: PanelKind::Bars,
        log_y: true,
        ..Default::default()
    };
    Figure {
        title: format!("Spectrum (Hann window), {label}"),
        panels: vec![full, zoom],
    }
}

/// The first revolutions of every channel and of the tachometer.
fn time_figure(r: &Record, k: &Kinematics, chain: &SignalChain, unit: &str, label: &str) -> Figure {
    let rev = 1.0 / k.shaft_hz(chain.tachometer.shaft);
    let n = ((rev * r.sampling_rate_hz).ceil() as usize + 1).min(r.len());
    let t: Vec<f64> = (0..n).map(|i| r.time_s(i) * 1e3).collect();
    let channels = panel(
        "time (ms)",
        &format!("acceleration ({unit})"),
        r.channels
            .iter()
            .map(|(name, x)| Curve::new(name.clone(), t.clone(), x[..n].to_vec()))
            .collect(),
    );
    let tach = panel(
        "time (ms)",
        "tachometer (V)",
        vec![Curve::new(
            format!(
                "{} pulses per {} revolution",
                chain.tachometer.pulses_per_revolution,
                chain.tachometer.shaft.name()
            ),
            t.clone(),
            r.tachometer_v[..n].to_vec(),
        )],
    );
    Figure {
        title: format!("Record, first revolution of the tachometer shaft, {label}"),
        panels: vec![channels, tach],
    }
}

fn tsa_table(analysis: &[ChannelAnalysis], shaft: Shaft) -> Option<Table> {
    let mut t: Option<Table> = None;
    for ch in analysis {
        let Some(s) = ch.shafts.iter().find(|s| s.shaft == shaft) else {
            continue;
        };
        let m = s.tsa.values.len();
        let mut table = t.take().unwrap_or_else(|| {
            Table::new().col(
                "angle_deg",
                (0..m).map(|i| 360.0 * i as f64 / m as f64).collect(),
            )
        });
        if table.rows() != m {
            t = Some(table);
            continue;
        }
        for (what, v) in [
            ("tsa", &s.tsa.values),
            ("regular", &s.components.regular),
            ("residual", &s.components.residual),
            ("difference", &s.components.difference),
        ] {
            table = table.col(&format!("{}_{what}", ch.name), v.clone());
        }
        t = Some(table);
    }
    t
}

/// TSA of the first channel per shaft, and its residual and difference signals.
fn tsa_figure(analysis: &[ChannelAnalysis], unit: &str, label: &str) -> Figure {
    let mut panels = Vec::new();
    if let Some(ch) = analysis.first() {
        for s in &ch.shafts {
            let m = s.tsa.values.len();
            let deg: Vec<f64> = (0..m).map(|i| 360.0 * i as f64 / m as f64).collect();
            let mut p = panel(
                "shaft angle (deg)",
                &format!("TSA ({unit})"),
                vec![Curve::new(
                    format!("{} TSA, {} revolutions", ch.name, s.tsa.revolutions),
                    deg.clone(),
                    s.tsa.values.clone(),
                )],
            );
            p.title = format!("{} shaft", s.shaft.name());
            panels.push(p);
            let name = s.shaft.name();
            panels.push(panel(
                "shaft angle (deg)",
                &format!("({unit})"),
                vec![
                    Curve::new(
                        format!("{name} residual"),
                        deg.clone(),
                        s.components.residual.clone(),
                    ),
                    Curve::new(
                        format!("{name} difference"),
                        deg,
                        s.components.difference.clone(),
                    ),
                ],
            ));
        }
    }
    Figure {
        title: format!("Time-synchronous averages, {label}"),
        panels,
    }
}
