//! A CSV input whose header names a column twice is refused (exit 2, naming the column and
//! the file), for every reader that looks its columns up by name: a torque history, a
//! load spectrum file and a transmission error. Without the check the first of the two
//! columns would be read and the second ignored silently (issue 33).
mod common;

use std::path::Path;

fn refused(args: &[&str], what: &str) {
    let o = common::gearwear(args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert!(
        err.contains("`torque_nm` twice") || err.contains("`error_um` twice"),
        "{what}: {err}"
    );
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

#[test]
fn a_history_with_a_repeated_column_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let h = write(
        d.path(),
        "h.csv",
        "time_s,torque_nm,input_speed_hz,torque_nm\n0,10,30,5\n1,10,30,5\n2,20,30,6\n",
    );
    let out = d.path().join("out");
    refused(
        &[
            "load-spectrum",
            "--history",
            &h,
            "--out",
            out.to_str().unwrap(),
        ],
        "history",
    );
    assert!(!out.exists(), "refused before its folder is made");
    // The same file without the repeated column is accepted (the check is what refuses).
    let ok = write(
        d.path(),
        "ok.csv",
        "time_s,torque_nm,input_speed_hz\n0,10,30\n1,10,30\n2,20,30\n",
    );
    common::ok(&[
        "-q",
        "load-spectrum",
        "--history",
        &ok,
        "--out",
        out.to_str().unwrap(),
    ]);
}

#[test]
fn a_load_spectrum_file_with_a_repeated_column_is_refused() {
    let d = tempfile::tempdir().unwrap();
    write(
        d.path(),
        "spectrum.csv",
        "torque_nm,input_speed_hz,share,torque_nm\n60,30,0.5,10\n40,30,0.5,10\n",
    );
    let case = write(
        d.path(),
        "case.toml",
        "[load_spectrum]\nfile = \"spectrum.csv\"\n",
    );
    let out = d.path().join("out");
    refused(
        &["wear", "--config", &case, "--out", out.to_str().unwrap()],
        "spectrum file",
    );
}

#[test]
fn a_transmission_error_with_a_repeated_column_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let te = write(
        d.path(),
        "te.csv",
        "pinion_angle_deg,error_um,error_um\n0,0,1\n5,1,1\n10,0,1\n",
    );
    let out = d.path().join("out");
    refused(
        &[
            "dynamics",
            "--transmission-error",
            &te,
            "--out",
            out.to_str().unwrap(),
        ],
        "transmission error",
    );
}
