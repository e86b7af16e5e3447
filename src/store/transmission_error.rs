//! Reading an external transmission error: a CSV with the header
//! `pinion_angle_deg,error_um` (more columns are ignored), one row per sample over (at
//! least) one mesh period of 360/z1 degrees. Angles are reduced modulo the mesh period
//! and interpolated linearly and periodically (`dynamics::excitation::ExternalError`).

use crate::dynamics::excitation::ExternalError;
use std::path::Path;

/// Why a transmission-error file or array cannot be used; the message names the file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{source_name}: {reason}")]
pub(crate) struct TransmissionErrorInput {
    pub source_name: String,
    pub reason: String,
}

/// Check samples (pinion angle rad, error m) and build the excitation: at least two
/// finite samples, angles strictly increasing, covering one whole mesh period (the span
/// plus one mean spacing reaches the period, so both `0..period` with its end repeated and
/// `0..period - spacing` are whole periods). `source_name` names the input in messages.
pub(crate) fn transmission_error_from_samples(
    samples: &[(f64, f64)],
    mesh_angle_rad: f64,
    source_name: &str,
) -> Result<ExternalError, TransmissionErrorInput> {
    let bad = |reason: String| TransmissionErrorInput {
        source_name: source_name.to_owned(),
        reason,
    };
    if samples.len() < 2 {
        return Err(bad(format!(
            "needs at least two samples over one mesh period ({:.4} deg), found {}",
            mesh_angle_rad.to_degrees(),
            samples.len()
        )));
    }
    if let Some(i) = samples
        .iter()
        .position(|(a, e)| !a.is_finite() || !e.is_finite())
    {
        return Err(bad(format!("sample {} is not a finite number", i + 1)));
    }
    if let Some(i) = samples.windows(2).position(|w| w[1].0 <= w[0].0) {
        return Err(bad(format!(
            "angles must increase: sample {} ({:.6} deg) does not follow sample {} ({:.6} deg)",
            i + 2,
            samples[i + 1].0.to_degrees(),
            i + 1,
            samples[i].0.to_degrees()
        )));
    }
    let span = samples[samples.len() - 1].0 - samples[0].0;
    let spacing = span / (samples.len() - 1) as f64;
    if span + spacing < mesh_angle_rad * (1.0 - 1e-9) {
        return Err(bad(format!(
            "the angles cover {:.4} deg, less than one mesh period of {:.4} deg (360/z1): give the error over a whole mesh period",
            span.to_degrees(),
            mesh_angle_rad.to_degrees()
        )));
    }
    if span > mesh_angle_rad * (1.0 + 1e-9) {
        // More than a period: the reduction modulo the period would fold it onto itself.
        return Err(bad(format!(
            "the angles cover {:.4} deg, more than one mesh period of {:.4} deg (360/z1): give exactly one period",
            span.to_degrees(),
            mesh_angle_rad.to_degrees()
        )));
    }
    Ok(ExternalError::new(samples, mesh_angle_rad))
}

/// As [`transmission_error_from_samples`], from samples in the file's units: (pinion
/// angle deg, error um).
pub(crate) fn transmission_error_from_deg_um(
    samples_deg_um: &[(f64, f64)],
    mesh_angle_rad: f64,
    source_name: &str,
) -> Result<ExternalError, TransmissionErrorInput> {
    let si: Vec<(f64, f64)> = samples_deg_um
        .iter()
        .map(|(deg, um)| (deg.to_radians(), um * 1e-6))
        .collect();
    transmission_error_from_samples(&si, mesh_angle_rad, source_name)
}

/// Most samples of a transmission error over one mesh period (a million points resolve
/// any profile error a gear can have).
pub(crate) const MAX_SAMPLES: usize = 1_000_000;

/// Read a transmission-error CSV file (see the module docs): a regular file of bounded
/// size (`io::input`).
pub(crate) fn read_transmission_error(
    path: &Path,
    mesh_angle_rad: f64,
) -> Result<ExternalError, TransmissionErrorInput> {
    let name = path.display().to_string();
    let bad = |reason: String| TransmissionErrorInput {
        source_name: name.clone(),
        reason,
    };
    let bytes = crate::io::input::read_input(
        path,
        "transmission-error file",
        crate::io::input::MAX_TRANSMISSION_ERROR_BYTES,
    )
    .map_err(|e| bad(e.reason))?;
    let mut r = csv::Reader::from_reader(bytes.as_slice());
    let headers = r.headers().map_err(|e| bad(e.to_string()))?.clone();
    if let Some(name) = crate::io::table::repeated_column(headers.iter()) {
        return Err(bad(format!(
            "the header names the column `{}` twice: keep one",
            crate::format::clip(name, crate::format::SHOWN_CHARS)
        )));
    }
    let col = |n: &str| headers.iter().position(|h| h.trim() == n);
    let (Some(ia), Some(ie)) = (col("pinion_angle_deg"), col("error_um")) else {
        return Err(bad(format!(
            "expected the header `pinion_angle_deg,error_um`, found `{}`",
            headers.iter().collect::<Vec<_>>().join(",")
        )));
    };
    let mut samples = Vec::new();
    for (line, rec) in r.records().enumerate() {
        if line >= MAX_SAMPLES {
            return Err(bad(format!(
                "more than {MAX_SAMPLES} samples: one mesh period needs far fewer"
            )));
        }
        let rec = rec.map_err(|e| bad(e.to_string()))?;
        let parse = |i: usize| -> Result<f64, TransmissionErrorInput> {
            let s = rec.get(i).unwrap_or("").trim();
            s.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| bad(format!("row {}: `{s}` is not a finite number", line + 2)))
        };
        samples.push((parse(ia)?, parse(ie)?));
    }
    transmission_error_from_deg_um(&samples, mesh_angle_rad, &name)
}

#[cfg(test)]
mod tests {
    use super::*;

    const PERIOD: f64 = 2.0 * std::f64::consts::PI / 19.0;

    fn samples(n: usize, span: f64) -> Vec<(f64, f64)> {
        (0..n)
            .map(|i| (span * i as f64 / (n - 1) as f64, 1e-6))
            .collect()
    }

    #[test]
    fn a_whole_period_is_accepted_either_way() {
        // With the end point repeated, and without it.
        assert!(transmission_error_from_samples(&samples(11, PERIOD), PERIOD, "f").is_ok());
        assert!(transmission_error_from_samples(&samples(10, PERIOD * 0.9), PERIOD, "f").is_ok());
    }

    #[test]
    fn part_of_a_period_is_refused_with_the_numbers() {
        let e = transmission_error_from_samples(&samples(6, 5f64.to_radians()), PERIOD, "te.csv")
            .unwrap_err()
            .to_string();
        assert!(e.contains("te.csv") && e.contains("5.0000 deg"), "{e}");
        assert!(e.contains("18.9474"), "{e}");
    }

    #[test]
    fn unordered_or_non_finite_samples_are_refused() {
        let mut s = samples(5, PERIOD);
        s.swap(1, 2);
        assert!(transmission_error_from_samples(&s, PERIOD, "f").is_err());
        let mut s = samples(5, PERIOD);
        s[3].1 = f64::NAN;
        assert!(transmission_error_from_samples(&s, PERIOD, "f").is_err());
    }
}
