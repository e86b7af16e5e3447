//! A signal recomputed from the written files equals gearwear's: `bearing_forces.csv`
//! holds one period of the four bearing forces, uniformly sampled, with every line the
//! chain took in below f_s / 2; its FFT, times the documented transfer path (the generic
//! housing of docs/SIGNALS.md) and anti-alias filter, sampled at n / f_s, is the record.

mod common;
use common::{ok, read_csv};
use gearwear::signals::antialias::AntiAliasFilter;
use gearwear::signals::transfer::TransferPath;
use realfft::num_complex::Complex64;
use realfft::RealFftPlanner;

#[test]
fn the_record_is_rebuilt_from_the_bearing_forces_file_to_1e_3() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("signals");
    ok(&["signals", "--out", out.to_str().unwrap(), "-q"]);
    let (head, rows) = read_csv(&out.join("bearing_forces.csv"));
    assert_eq!(
        head,
        ["time_s", "pinion_x_n", "pinion_y_n", "gear_x_n", "gear_y_n"]
    );
    let cell = |r: &Vec<String>, c: usize| r[c].parse::<f64>().unwrap();
    let m = rows.len();
    assert!(m.is_power_of_two());
    let dt = cell(&rows[1], 0) - cell(&rows[0], 0);
    let period = dt * m as f64;
    // The built-in case repeats every mesh period: 1 / 570 Hz.
    assert!((period * 570.0 - 1.0).abs() < 1e-9, "{period}");
    // Each force's lines C_k = 2 X_k / M (X_k the FFT of the column).
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(m);
    let lines: Vec<Vec<Complex64>> = (1..5)
        .map(|c| {
            let mut x: Vec<f64> = rows.iter().map(|r| cell(r, c)).collect();
            let mut s = fft.make_output_vec();
            fft.process(&mut x, &mut s).unwrap();
            s.iter().map(|v| v * 2.0 / m as f64).collect()
        })
        .collect();
    // The record: sensor `input` (the first) through the generic housing and the
    // 100 dB anti-alias filter at 25.6 kHz, sampled at n / f_s from t = 0.
    let fs = 25_600.0;
    let path = TransferPath::generic_housing();
    let aa = AntiAliasFilter::design(fs, 100.0);
    let (rec_head, rec_rows) = read_csv(&out.join("record.csv"));
    assert_eq!(rec_head[1], "input_m_per_s2");
    let recorded: Vec<f64> = rec_rows.iter().take(2000).map(|r| cell(r, 1)).collect();
    let series: Vec<(f64, Complex64)> = (1..m / 2)
        .map(|k| {
            let f = k as f64 / period;
            let sum: Complex64 = (0..4)
                .map(|j| path.accelerance(0, j, f) * lines[j][k])
                .sum();
            (f, sum * aa.response(f))
        })
        .collect();
    let rebuilt: Vec<f64> = (0..recorded.len())
        .map(|n| {
            let t = n as f64 / fs;
            series
                .iter()
                .map(|(f, c)| {
                    (c * Complex64::from_polar(1.0, 2.0 * std::f64::consts::PI * f * t)).re
                })
                .sum()
        })
        .collect();
    let rms = (recorded.iter().map(|x| x * x).sum::<f64>() / recorded.len() as f64).sqrt();
    let worst = recorded
        .iter()
        .zip(&rebuilt)
        .fold(0.0_f64, |w, (a, b)| w.max((a - b).abs()));
    println!(
        "record rebuilt from bearing_forces.csv ({m} rows): largest difference {:.2e} of the record's RMS {rms:.3} m/s^2",
        worst / rms
    );
    // The record is float32 (6e-8 of each value); the lines above f_s / 2 left out of
    // the file reach the record at most 1e-5 down (100 dB): 1e-3 is the bound.
    assert!(worst < 1e-3 * rms, "{:e}", worst / rms);
}
