//! A tooth fault on one stage of a gear train (`[[fault]]` with `fault.stage`,
//! docs/MODEL.md 9.10): where the faulty stage's stiffness dips, the limit of a second
//! stage that cannot move (the single pair with the same fault), the sidebands the fault
//! puts around the stage's mesh harmonics, a zero-size fault, and the refusals.

mod common;
use common::train::{model, neglected_compliance, reflected_pair, stiff_second_stage, TWO_STAGE};
use common::{read_csv, rejected, run_into};
use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::model::MeshFrame;
use gearwear::dynamics::summary::ResponseSummary;
use gearwear::study::Model;
use gearwear::wear::WearState;
use std::path::Path;

const REDUCER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/examples/two_stage_reducer.toml"
);

/// A `[[fault]]` table: a crack `depth_mm` deep on tooth `tooth` of stage `stage`'s
/// `gear` ("pinion" or "gear").
fn crack(stage: usize, gear: &str, tooth: usize, depth_mm: f64) -> String {
    format!(
        "\n[[fault]]\nkind = \"crack\"\nstage = {stage}\ngear = \"{gear}\"\ntooth = {tooth}\ncrack_depth_mm = {depth_mm}\n"
    )
}

/// Total stiffness (the pairs on the path) of mesh `m` of `model`'s train at time `t_s`.
fn stiffness(model: &Model, m: usize, t_s: f64) -> f64 {
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let sys = model.system(&gap, &ext, 0.2);
    let n = model.state_len() / 2;
    let zeros = vec![0.0; n];
    sys.mesh(m)
        .mesh_state(MeshFrame::default(), t_s, &zeros, &zeros)
        .stiffness_total_n_per_m
}

#[test]
fn the_faulty_stage_dips_once_per_revolution_of_its_faulty_gear_and_the_other_stage_not() {
    // 19/31 then 23/47 at 30 Hz, a 2 mm crack on stage 1's gear, tooth 0. Independent of
    // the model: mesh cycle n of stage 1 (the pair entering contact n mesh periods
    // T1 = 1 / (19 x 30 Hz) after t = 0) holds gear tooth n mod 31, and a pair is on the
    // nominal path from its entry for eps1 (the contact ratio) mesh periods. So the
    // cracked tooth is in contact for t / T1 in [31 j, 31 j + eps1], once per revolution
    // of the intermediate shaft (31 T1 = 1 / 18.39 Hz), and softens stage 1 there only.
    let healthy = model(TWO_STAGE, &["contact.path=nominal"]);
    let faulty_text = format!("{TWO_STAGE}{}", crack(1, "gear", 0, 2.0));
    let faulty = model(&faulty_text, &["contact.path=nominal"]);
    let t1 = 1.0 / (19.0 * 30.0);
    let eps1 = healthy.train.as_ref().unwrap().stages[0].pair.contact_ratio;
    // Two revolutions of the faulty gear, 40 samples per mesh period (offset by a
    // quarter sample so that no sample falls on a pair's entry or exit).
    let samples = 62 * 40;
    let mut softened_cycles = std::collections::BTreeSet::new();
    for i in 0..samples {
        let c = (i as f64 + 0.25) / 40.0;
        let t = c * t1;
        let (k0, k1) = (stiffness(&healthy, 0, t), stiffness(&faulty, 0, t));
        let cracked_in_contact = (c % 31.0) < eps1;
        if cracked_in_contact {
            // A 2 mm crack takes a fifth of a tooth's stiffness (docs/MODEL.md 9.5), so
            // the mesh loses at least 1 % wherever the cracked tooth carries.
            assert!(k1 < 0.99 * k0, "t/T1 = {c}: {k1} not below {k0}");
            softened_cycles.insert((c / 31.0).floor() as i64);
        } else {
            assert_eq!(k1, k0, "t/T1 = {c}: stage 1 changed away from the crack");
        }
        // Stage 2's stiffness is the healthy stage's at every instant, bit for bit.
        assert_eq!(
            stiffness(&faulty, 1, t),
            stiffness(&healthy, 1, t),
            "t/T1 = {c}"
        );
    }
    // Once in each of the two revolutions.
    assert_eq!(softened_cycles.into_iter().collect::<Vec<_>>(), vec![0, 1]);
}

#[test]
fn a_second_stage_that_cannot_move_gives_the_single_pair_with_the_same_fault() {
    // The limit of tests/train_limits.rs with a 1.5 mm crack on stage 1's gear tooth 0:
    // stage 2 (31/62, module 20 mm, 1900 mm wide, bearings at 1e12 N/m) and the shaft at
    // the top of its range (1e10 N m/rad; the schema's limit, above the 1e12
    // being refused) make the train's mesh 1 the first pair alone with stage 2 reflected
    // as rigid inertia on its gear, the same crack on the same tooth. Both repeat over
    // 31 mesh periods (one revolution of the cracked gear). The train's faulty mesh
    // differs from that pair by the order of the compliance the reflection neglects
    // (mesh 2, the shaft and stage 2's bearings against mesh 1, 1.3e-4): within 3 x it,
    // relative to the pair's dynamic amplitudes, as the healthy limit is checked; the
    // crack's own effect on the maximum force is far larger (checked, so that the
    // comparison can fail).
    let fault = crack(1, "gear", 0, 1.5);
    let train = model(
        &format!("{}{fault}", stiff_second_stage(1900.0)),
        &["friction.model=none", "contact.path=nominal"],
    );
    let pair_fault = [
        "fault.kind=crack",
        "fault.gear=gear",
        "fault.tooth=0",
        "fault.crack_depth_mm=1.5",
    ];
    let pair = reflected_pair(&train, &pair_fault);
    let healthy_pair = reflected_pair(&train, &[]);
    let eps = neglected_compliance(&train);
    let solve = |m: &Model| {
        m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
            .unwrap()
    };
    let r_train = solve(&train);
    let r_pair = solve(&pair);
    assert_eq!(r_train.excitation_periods, 31);
    assert_eq!(r_pair.excitation_periods, 31);
    let f1 = train.train.as_ref().unwrap().operating.meshes[0].mesh_frequency_hz;
    let a = ResponseSummary::of_mesh(&r_train, 0, 1.0 / f1, 1);
    let b = ResponseSummary::of(&r_pair);
    let h = ResponseSummary::of(&solve(&healthy_pair));
    let force_pp = b.mesh_force_max_n - b.mesh_force_min_n;
    let dte_pp = b.dte_max_m - b.dte_min_m;
    let diff = [
        (a.mesh_force_max_n - b.mesh_force_max_n).abs() / force_pp,
        (a.mesh_force_min_n - b.mesh_force_min_n).abs() / force_pp,
        ((a.dte_max_m - a.dte_min_m) - dte_pp).abs() / dte_pp,
        (a.dte_max_m - b.dte_max_m).abs() / dte_pp,
    ]
    .into_iter()
    .fold(0.0, f64::max);
    let crack_effect = (b.dte_max_m - h.dte_max_m).abs() / dte_pp;
    println!("neglected {eps:.2e}, difference {diff:.2e}, crack effect {crack_effect:.2e}");
    assert!(diff < 3.0 * eps, "difference {diff:e} beyond 3 x {eps:e}");
    assert!(crack_effect > 30.0 * eps, "crack effect {crack_effect:e}");
}

/// Frequencies (Hz) and the amplitudes of column `col` of a spectrum table.
fn spectrum(path: &Path, col: usize) -> (Vec<f64>, Vec<f64>) {
    let (_, rows) = read_csv(path);
    let f = rows.iter().map(|r| r[0].parse().unwrap()).collect();
    let a = rows.iter().map(|r| r[col].parse().unwrap()).collect();
    (f, a)
}

#[test]
fn a_cracked_stage_pinion_puts_shaft_sidebands_around_its_mesh_harmonics() {
    // The reducer with a 2 mm crack on stage 1's pinion (tooth 0): the spectrum of stage
    // 1's pinion velocity (`dynamics`). Computed here from the teeth and the speed:
    // stage 1 meshes at f_m = 19 x 30 = 570 Hz, its pinion turns at f_in = 30 Hz, and
    // the crack meets the gear once per pinion revolution, so lines rise at
    // h f_m + l f_in. The healthy train repeats every revolution of the intermediate
    // shaft (f_g = 30 x 19 / 31 = 18.39 Hz): its lines lie on multiples of f_g only, and
    // h f_m + l f_in (600 Hz = 32.6 f_g) is none of them. With the crack the response
    // repeats over lcm: 19 revolutions of the intermediate shaft = 31 of the input, so
    // the bins are f_in / 31 apart; each sideband must stand 30 times above the median
    // of its 18 neighbouring bins (combination tones of high order; measured 130 to 450
    // times).
    let d = tempfile::tempdir().unwrap();
    let cracked = d.path().join("cracked.toml");
    let text = std::fs::read_to_string(REDUCER).unwrap();
    std::fs::write(&cracked, format!("{text}{}", crack(1, "pinion", 0, 2.0))).unwrap();
    let healthy = run_into(d.path(), "healthy", &["dynamics"], Some(REDUCER), &[]);
    let faulty = run_into(
        d.path(),
        "faulty",
        &["dynamics"],
        Some(cracked.to_str().unwrap()),
        &[],
    );
    let (f_in, f_m, f_g) = (30.0, 19.0 * 30.0, 30.0 * 19.0 / 31.0);
    let (fh, _) = spectrum(&healthy.join("spectrum.csv"), 1);
    assert!(
        ((fh[1] - fh[0]) / f_g - 1.0).abs() < 1e-9,
        "{}",
        fh[1] - fh[0]
    );
    let (f, a) = spectrum(&faulty.join("spectrum.csv"), 1);
    let df = f[1] - f[0];
    assert!((df / (f_in / 31.0) - 1.0).abs() < 1e-9, "{df}");
    for h in [1.0, 2.0] {
        for l in [-2.0, -1.0, 1.0, 2.0] {
            let line = h * f_m + l * f_in;
            // Not a line of the healthy train.
            let k = line / f_g;
            assert!((k - k.round()).abs() > 0.1, "{line} Hz on the healthy grid");
            let i = (line / df).round() as usize;
            assert!((f[i] - line).abs() < 1e-6 * line, "{} vs {line}", f[i]);
            let mut around: Vec<f64> = (i - 9..=i + 9).filter(|j| *j != i).map(|j| a[j]).collect();
            around.sort_by(f64::total_cmp);
            let median = 0.5 * (around[8] + around[9]);
            println!("{line} Hz: {:.3e}, neighbours' median {median:.3e}", a[i]);
            assert!(a[i] > 30.0 * median, "{line} Hz: {} vs {median}", a[i]);
        }
    }
}

#[test]
fn a_zero_size_fault_on_a_stage_is_the_healthy_train_byte_for_byte() {
    // A crack of zero depth changes no tooth: the stage keeps its identical-teeth path
    // (no tooth-resolved mesh, its load-sharing law), so every table of `dynamics` is
    // the same bytes as without the [[fault]] table.
    let d = tempfile::tempdir().unwrap();
    let zero = d.path().join("zero.toml");
    let text = std::fs::read_to_string(REDUCER).unwrap();
    std::fs::write(&zero, format!("{text}{}", crack(2, "pinion", 3, 0.0))).unwrap();
    let a = run_into(d.path(), "healthy", &["dynamics"], Some(REDUCER), &[]);
    let b = run_into(
        d.path(),
        "zero",
        &["dynamics"],
        Some(zero.to_str().unwrap()),
        &[],
    );
    let mut compared = 0;
    for dir in ["", "csv"] {
        for e in std::fs::read_dir(a.join(dir)).unwrap() {
            let p = e.unwrap().path();
            let name = p.file_name().unwrap().to_str().unwrap().to_string();
            // The manifest and the folder's state file echo the case's hash and the files'
            // places; the summary is compared below without its metadata.
            if p.is_dir()
                || name.starts_with('.')
                || name == "manifest.json"
                || name == "summary.json"
            {
                continue;
            }
            let other = b.join(dir).join(&name);
            let same = std::fs::read(&p).unwrap() == std::fs::read(&other).unwrap();
            assert!(same, "{name} differs");
            compared += 1;
        }
    }
    assert!(compared >= 10, "{compared} files");
    // The summary apart from its metadata (which echoes the case and its hash).
    let summary = |dir: &Path| {
        let mut v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap())
                .unwrap();
        v.as_object_mut().unwrap().remove("metadata");
        v
    };
    assert_eq!(summary(&a), summary(&b));
    // The same crack with a depth does change the train (the comparison can fail).
    let deep = d.path().join("deep.toml");
    std::fs::write(&deep, format!("{text}{}", crack(2, "pinion", 3, 1.0))).unwrap();
    let c = run_into(
        d.path(),
        "deep",
        &["dynamics"],
        Some(deep.to_str().unwrap()),
        &[],
    );
    assert_ne!(summary(&a), summary(&c));
}

/// The reducer with `extra` TOML appended, written into `dir`; its path.
fn reducer_with(dir: &Path, name: &str, extra: &str) -> String {
    let p = dir.join(name);
    let text = std::fs::read_to_string(REDUCER).unwrap();
    std::fs::write(&p, format!("{text}{extra}")).unwrap();
    p.to_str().unwrap().to_string()
}

#[test]
fn a_stage_fault_is_refused_by_key_where_it_is_wrong_or_not_built() {
    let d = tempfile::tempdir().unwrap();
    let table = "\n[[fault]]\nkind = \"crack\"\ngear = \"gear\"\ntooth = 0\ncrack_depth_mm = 1\n";
    // No stage on a train.
    let none = reducer_with(d.path(), "none.toml", table);
    rejected(
        &["dynamics", "--config", &none],
        &["`fault.stage` is required", "fault 0", "1 to 2"],
    );
    // A stage the train does not have.
    let three = reducer_with(d.path(), "three.toml", &crack(3, "gear", 0, 1.0));
    rejected(
        &["dynamics", "--config", &three],
        &["`fault.stage` = 3", "fault 0", "stages 1 to 2"],
    );
    // A stage on a single pair.
    let pair = d.path().join("pair.toml");
    std::fs::write(&pair, crack(1, "gear", 0, 1.0)).unwrap();
    rejected(
        &["dynamics", "--config", pair.to_str().unwrap()],
        &["`fault.stage` = 1", "single pair", "remove the key"],
    );
    // A tooth checked against its own stage's gear: 40 is on stage 2's 47-tooth gear,
    // not on stage 1's 31-tooth one.
    let tooth = reducer_with(d.path(), "tooth.toml", &crack(1, "gear", 40, 1.0));
    rejected(
        &["dynamics", "--config", &tooth],
        &["`fault.tooth` = 40", "teeth 0 to 30"],
    );
    let ok_tooth = reducer_with(d.path(), "ok_tooth.toml", &crack(2, "gear", 40, 1.0));
    gearwear::config::load_case(&std::fs::read_to_string(&ok_tooth).unwrap(), &[]).unwrap();
    // The studies built on the train's wear beyond one operating point refuse a fault,
    // naming the key and the study (`wear` and `run` at one point take it,
    // tests/train_fault_wear.rs).
    let cracked = reducer_with(d.path(), "cracked.toml", &crack(2, "pinion", 0, 1.0));
    let spectrum = "[load_spectrum]\nbins = [{ torque_nm = 60, input_speed_hz = 30, share = 1 }]\n";
    let under = reducer_with(
        d.path(),
        "under.toml",
        &format!("{}\n{spectrum}", crack(2, "pinion", 0, 1.0)),
    );
    for (study, args) in [
        (
            "`gearwear wear` under a [load_spectrum]",
            vec!["wear", "--config", &under],
        ),
        (
            "`gearwear run` under a [load_spectrum]",
            vec!["run", "--config", &under],
        ),
    ] {
        rejected(&args, &["`fault.stage` = 2", study, "not built yet"]);
    }
    // A fault on a helical stage (its slices would each need it) is not built: refused by
    // the `dynamics` that takes it on a spur stage.
    rejected(
        &[
            "dynamics",
            "--config",
            &cracked,
            "--set",
            "stage.2.helix_angle_deg=15",
        ],
        &["`fault.stage` = 2", "helical stage", "not built yet"],
    );
    // A wear sweep whose base has a crack of zero size (allowed: it changes no tooth) and
    // whose varied depth makes a crack: that case is refused, not worn as new teeth.
    let zero = reducer_with(d.path(), "zero.toml", &crack(1, "gear", 3, 0.0));
    let out = d.path().join("sweep");
    let o = common::gearwear(&[
        "-q",
        "sweep",
        "--config",
        &zero,
        "--set",
        "wear.total_cycles=2e4",
        "--vary",
        "fault.1.crack_depth_mm=0,1.5",
        "--run",
        "wear",
        "--no-budget",
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = common::stderr(&o);
    assert!(!o.status.success(), "{err}");
    assert!(
        err.contains("1 of 2 cases failed")
            && err.contains("`fault.stage` = 1")
            && err.contains("the train's wear"),
        "{err}"
    );
}

#[test]
fn the_periods_of_a_stage_fault_are_the_shared_shafts_revolutions_that_bring_its_tooth_back() {
    // The reducer's base period is one revolution of the shaft the two stages share (31
    // mesh periods of stage 1, whose gear has 31 teeth, and 23 of stage 2, whose pinion has
    // 23). A fault on stage 2's gear (z = 47) comes back after m base periods with 23 m a
    // multiple of 47: m = 47; a fault on stage 1's pinion (z = 19) with 31 m a multiple
    // of 19: m = 19; on stage 2's pinion (z = 23, one per base period): m = 1; stage 2's
    // gear with 46 teeth: 23 m a multiple of 46, m = 2. Counted by hand here, against the
    // solver's count (`dynamics::grid::excitation_periods` of the built system) and the
    // budget's (`study::budget::excitation_periods_of`, from the case alone).
    let text = std::fs::read_to_string(REDUCER).unwrap();
    for (fault, sets, hand) in [
        (crack(2, "gear", 3, 1.0), vec![], 47),
        (crack(1, "pinion", 0, 1.0), vec![], 19),
        (crack(2, "pinion", 5, 1.0), vec![], 1),
        (crack(2, "gear", 3, 1.0), vec!["stage.2.teeth_gear=46"], 2),
    ] {
        let m = model(&format!("{text}{fault}"), &sets);
        let (gap, ext) = (PairGap::none(), ExternalError::none());
        let sys = m.system(&gap, &ext, 0.0);
        let solver = gearwear::dynamics::grid::excitation_periods(&sys);
        let budget = gearwear::study::budget::excitation_periods_of(&m.case);
        assert_eq!(solver, Some(hand), "{fault} {sets:?}: solver");
        assert_eq!(budget, hand, "{fault} {sets:?}: budget");
    }
}
