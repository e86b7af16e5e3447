//! `gearwear signals` as a user meets it: the promised files and summary keys, and each
//! bad input of the signal chain answered with exit code 2 naming the key and the limit.

mod common;

use common::{ok, rejected, CHEAP};

#[test]
fn signals_writes_the_record_its_indicators_and_figures() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sig");
    let mut a = vec![
        "signals",
        "--set",
        "signals.snr_db=30",
        "--set",
        "signals.record_length=0.5",
    ];
    a.extend(CHEAP);
    a.extend(["--out", out.to_str().unwrap()]);
    ok(&a);
    for f in [
        "record.parquet",
        "record.csv",
        "spectrum.csv",
        "spectrum.png",
        "time_signal.png",
        "tsa.png",
        "tsa_pinion.csv",
        "tsa_gear.csv",
    ] {
        assert!(out.join(f).exists(), "{f}");
    }
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    let ind = &s["indicators"][0];
    assert_eq!(ind["channel"], "input");
    for k in ["rms", "crest_factor", "kurtosis"] {
        assert!(ind[k].as_f64().unwrap() > 0.0, "{k}");
    }
    for k in [
        "fm0",
        "fm4",
        "na4",
        "nb4",
        "m6a",
        "m8a",
        "energy_ratio",
        "sideband_level_factor",
        "sideband_index",
    ] {
        assert!(ind["pinion"][k].is_number(), "{k}");
    }
    assert_eq!(s["record"]["samples"], 12_800);
    assert_eq!(s["record"]["channel_unit"], "m/s^2");
    let (h, rows) = common::read_csv(&out.join("record.csv"));
    assert_eq!(
        h,
        [
            "time_s",
            "input_m_per_s2",
            "output_m_per_s2",
            "tachometer_v"
        ]
    );
    assert_eq!(rows.len(), 12_800);
}

#[test]
fn bad_signal_chains_exit_2_naming_the_key_and_the_limit() {
    // A sampling rate below twice the highest mesh harmonic asked for.
    rejected(
        &["signals", "--set", "signals.sampling_rate_hz=4000"],
        &[
            "`signals.sampling_rate_hz` = 4000",
            "mesh harmonic 4",
            "5836.8",
        ],
    );
    // A tachometer on a shaft that does not exist.
    rejected(
        &["signals", "--set", "signals.tachometer_shaft=\"motor\""],
        &["`signals.tachometer_shaft`", "\"pinion\", \"gear\""],
    );
    let dir = tempfile::tempdir().unwrap();
    // A transfer-path mode above the Nyquist frequency.
    let modal = dir.path().join("path.toml");
    std::fs::write(&modal, "sensors = [\"top\"]\n[[mode]]\nfrequency_hz = 15000\ndamping_ratio = 0.03\ngains_per_kg = [[0, 0.1, 0, 0.05]]\n").unwrap();
    rejected(
        &["signals", "--transfer-path", modal.to_str().unwrap()],
        &[
            "15000 Hz",
            "Nyquist frequency 12800 Hz",
            "`signals.sampling_rate_hz`",
            "30000",
        ],
    );
    // Issue 33: a mode at 5e-324 Hz and accelerances of 1e308 gave empty channels and
    // null indicators with exit 0; each is now refused naming its entry and range.
    let tiny = dir.path().join("tiny.toml");
    std::fs::write(&tiny, "sensors = [\"top\"]\n[[mode]]\nfrequency_hz = 5e-324\ndamping_ratio = 0.03\ngains_per_kg = [[0, 0.1, 0, 0.05]]\n").unwrap();
    rejected(
        &["signals", "--transfer-path", tiny.to_str().unwrap()],
        &["mode 1", "`frequency_hz` = 5e-324", "[0.01, 1e7] Hz"],
    );
    let huge = dir.path().join("huge.csv");
    std::fs::write(&huge, "frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n\n100,top,pinion_y,1e308,0\n200,top,pinion_y,1,1e308\n").unwrap();
    rejected(
        &["signals", "--transfer-path", huge.to_str().unwrap()],
        &[
            "line 2",
            "`real_m_per_s2_per_n` = 1e308",
            "line 3",
            "`imag_m_per_s2_per_n` = 1e308",
            "+-1e6",
        ],
    );
    // An FRF table with unsorted or negative frequencies.
    let frf = dir.path().join("frf.csv");
    std::fs::write(&frf, "frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n\n100,top,pinion_y,1,0\n50,top,pinion_y,1,0\n-1,top,gear_y,1,0\n").unwrap();
    rejected(
        &["signals", "--transfer-path", frf.to_str().unwrap()],
        &[
            "line 3",
            "`frequency_hz` = 50",
            "increase strictly",
            "line 4",
            "negative",
        ],
    );
}

#[test]
fn the_signals_budget_counts_the_transfer_paths_sensors() {
    // Issue 33: 5000 modal sensors were estimated at 0.08 GB and 0.15 s and aborted after
    // 66 s at 3.8 GB; 1000 sensors of an FRF table ran 35 s on the same estimate. Each
    // sensor is a channel of the record: counted, refused before anything runs.
    let dir = tempfile::tempdir().unwrap();
    let n = 5000;
    let sensors: Vec<String> = (0..n).map(|i| format!("\"s{i}\"")).collect();
    let gains = vec!["[0.0075, 0.025, 0.005, 0.02]"; n].join(", ");
    let modal = dir.path().join("path.toml");
    std::fs::write(
        &modal,
        format!(
            "sensors = [{}]\n[[mode]]\nfrequency_hz = 2100.0\ndamping_ratio = 0.02\ngains_per_kg = [{gains}]\n",
            sensors.join(", ")
        ),
    )
    .unwrap();
    rejected(
        &["signals", "--transfer-path", modal.to_str().unwrap()],
        &["over its budget", "memory", "the transfer path's sensors"],
    );
    // 1000 sensors of a table at a tenth of the budget (0.2 GB, 60 s): the one-channel
    // count (0.08 GB, 0.15 s) fitted it; the record of 1000 channels does not.
    let mut table =
        String::from("frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n\n");
    for i in 0..1000 {
        for f in [100, 2000, 5000] {
            table.push_str(&format!("{f},s{i},pinion_y,0.01,0.001\n"));
        }
    }
    let frf = dir.path().join("frf.csv");
    std::fs::write(&frf, table).unwrap();
    rejected(
        &[
            "signals",
            "--transfer-path",
            frf.to_str().unwrap(),
            "--budget-scale",
            "0.1",
        ],
        &["over its budget", "the transfer path's sensors"],
    );
}
