//! Transient records of a helical pair (docs/MODEL.md 11.11): the run-up and the load
//! fluctuation of `gearwear signals` on the planar helical model. Checked against the
//! steady helical record (a run-up to its own start speed), the spur pair's run-up (beta
//! -> 0 with one slice), the kinematics of the ramp (the mesh line at z1 times the shaft
//! speed the tachometer gives) and the run budget's step count.

mod common;

use gearwear::config::{load_case, Case};
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::model::{ContactModes, GearSystem};
use gearwear::dynamics::period::PeriodObserver;
use gearwear::signals::record::Record;
use gearwear::signals::setup::chain_of;
use gearwear::study::signal_record::periodic_record;
use gearwear::study::transient_signals::transient_clean_record;
use gearwear::study::Model;

fn case(sets: &[&str]) -> Case {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    load_case("", &sets).expect("valid case")
}

fn rms(v: &[f64]) -> f64 {
    (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt()
}

fn without_mean(v: &[f64]) -> Vec<f64> {
    let m = v.iter().sum::<f64>() / v.len() as f64;
    v.iter().map(|x| x - m).collect()
}

/// The largest RMS of a channel's difference over the RMS of the channel, each channel
/// without its mean: the flat path passes the mean bearing force, which the periodic
/// record keeps and the transient record's convolution over its zero-padded grid does
/// not (a real accelerometer's path has no response at 0 Hz).
fn worst_relative_difference(a: &Record, b: &Record) -> f64 {
    assert_eq!(a.channels.len(), b.channels.len());
    a.channels
        .iter()
        .zip(&b.channels)
        .map(|(x, y)| {
            assert_eq!(x.1.len(), y.1.len());
            let (x, y) = (without_mean(&x.1), without_mean(&y.1));
            let d: Vec<f64> = x.iter().zip(&y).map(|(p, q)| p - q).collect();
            rms(&d) / rms(&x)
        })
        .fold(0.0, f64::max)
}

#[test]
fn a_run_up_to_its_own_start_speed_is_the_steady_helical_record() {
    // A helical pair (15 deg, 400 slices), with the axial bearings and a tooth's run-out
    // (its record then repeats over the hunting period), and with tilting bearings and a
    // crowning (the lead gaps, 11.2; the tilt, 11.8): a "ramp" from 30 Hz to
    // 30 Hz integrates the transient from the steady state, which must stay on it. The
    // steady record is rendered from the periodic orbit's Fourier series, the transient
    // from one long integration: two computations. Tolerance as for the spur pair
    // (tests/signals_transient.rs): the transient's steps are chosen afresh at a fifth of
    // the steady state's local error tolerance, and the two grids differ, 2e-3 of the
    // RMS. Dropping the run-out from the transient (as it was dropped before, the
    // system built without the tooth mesh) moves the record by 0.1 of its RMS.
    for sets in [
        vec!["gear.helix_angle_deg=15"],
        vec![
            "gear.helix_angle_deg=15",
            "dynamics.bearing_axial_stiffness_pinion_n_per_m=5e8",
            "dynamics.bearing_axial_stiffness_gear_n_per_m=5e8",
            "teeth.runout_pinion_um=2",
        ],
        vec![
            "gear.helix_angle_deg=15",
            "dynamics.bearing_axial_stiffness_pinion_n_per_m=1e9",
            "dynamics.bearing_axial_stiffness_gear_n_per_m=1e9",
            "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad=1e7",
            "dynamics.bearing_tilt_stiffness_gear_nm_per_rad=1e7",
            "modification.crowning_um=5",
        ],
    ] {
        let mut all = sets.clone();
        all.extend(["signals.record_length=0.2", "signals.ramp_end_speed_hz=30"]);
        let c = case(&all);
        let model = Model::dynamics_from_case(&c).unwrap();
        assert!(model.helical.is_some());
        let setup = chain_of(&c, Some(common::flat_path()), 30.0).unwrap();
        let wear = model.new_wear_state();
        let r = model.dynamic(&wear, &ExternalError::none()).unwrap();
        let (transient, speeds) = transient_clean_record(&model, &setup, &wear).unwrap();
        let steady = periodic_record(&model, &setup, &r).render(&setup.chain, speeds.len());
        assert!(speeds.iter().all(|s| (s - 30.0).abs() < 1e-12));
        let d = worst_relative_difference(&steady, &transient);
        eprintln!("{sets:?}: transient vs steady {d:.3e}");
        assert!(d < 2e-3, "{sets:?}: {d}");
    }
}

#[test]
fn at_beta_to_zero_one_slice_the_helical_run_up_is_the_spur_run_up() {
    // The helical model at 1e-6 deg with one slice is the spur pair of the same face
    // (docs/MODEL.md 11.1): its one contact line is a spur tooth pair whose slice sits
    // L / 2 = b tan(beta_b) / 2 ~ 1e-10 m off the spur pair's positions. The spur case takes
    // the helical model's choices (nominal path, load shared by compressions). Both
    // run up 30 -> 45 Hz over 0.3 s through the same integrator; relative changes of
    // 1e-8 in the stiffness move the error control's step choice continuously, so the
    // records agree far inside the transient's own error (2e-3, test above): 1e-6 asked.
    let common = [
        "contact.path=nominal",
        "contact.load_sharing=stiffness",
        "signals.record_length=0.3",
        "signals.ramp_end_speed_hz=45",
    ];
    let spur = case(&common);
    let mut h = common.to_vec();
    h.extend(["gear.helix_angle_deg=1e-6", "stiffness.slices=1"]);
    let helical = case(&h);
    let record = |c: &Case| {
        let model = Model::dynamics_from_case(c).unwrap();
        let setup = chain_of(c, Some(common::flat_path()), 45.0).unwrap();
        let wear = model.new_wear_state();
        (
            model.helical.is_some(),
            transient_clean_record(&model, &setup, &wear).unwrap(),
        )
    };
    let (is_s, (rs, vs)) = record(&spur);
    let (is_h, (rh, vh)) = record(&helical);
    assert!(!is_s && is_h);
    assert_eq!(vs, vh);
    let d = worst_relative_difference(&rs, &rh);
    eprintln!("spur vs helical run-up: {d:.3e}");
    assert!(d < 1e-6, "{d}");
    assert_eq!(rs.tachometer_v, rh.tachometer_v);
}

/// Frequency (Hz) of the largest Hann-windowed, zero-padded spectral line of `x` (sampled
/// at `fs`) between `lo` and `hi`.
fn peak_hz(x: &[f64], fs: f64, lo: f64, hi: f64) -> f64 {
    use realfft::RealFftPlanner;
    let n = x.len();
    let mean = x.iter().sum::<f64>() / n as f64;
    let padded = 16 * n.next_power_of_two();
    let mut buf = vec![0.0; padded];
    for (i, v) in x.iter().enumerate() {
        let w = 0.5 - 0.5 * (2.0 * std::f64::consts::PI * i as f64 / (n - 1) as f64).cos();
        buf[i] = (v - mean) * w;
    }
    let fft = RealFftPlanner::<f64>::new().plan_fft_forward(padded);
    let mut spec = fft.make_output_vec();
    fft.process(&mut buf, &mut spec).unwrap();
    let df = fs / padded as f64;
    let (k, _) = spec
        .iter()
        .enumerate()
        .filter(|(k, _)| (*k as f64 * df) >= lo && (*k as f64 * df) <= hi)
        .max_by(|a, b| a.1.norm().total_cmp(&b.1.norm()))
        .unwrap();
    k as f64 * df
}

#[test]
fn the_run_ups_mesh_line_follows_z1_times_the_tachometers_shaft_speed() {
    // A run-up 20 -> 40 Hz over 2 s (15 deg, 400 slices): in windows of 0.1 s the bearing
    // force's strongest line between 0.6 and 1.4 times z1 f (f the shaft speed from the
    // tachometer's pulse intervals at the window's centre) must be the mesh line at
    // z1 f. The window's resolution: the Hann main lobe (+-2 / T_w = 20 Hz) while the
    // line sweeps z1 alpha T_w = 19 Hz in it, so its peak sits within half the sweep
    // plus a zero-padded bin of its centre value: 12 Hz allowed (of 380-760 Hz). A
    // transient whose stiffness ignored the ramp (the mesh line held at 380 Hz) fails
    // from the third window on; a line at z2 f or 2 z1 f lies outside the band.
    let c = case(&[
        "gear.helix_angle_deg=15",
        "operating.input_speed_hz=20",
        "signals.ramp_end_speed_hz=40",
        "signals.record_length=2",
    ]);
    let model = Model::dynamics_from_case(&c).unwrap();
    let setup = chain_of(&c, Some(common::flat_path()), 40.0).unwrap();
    let wear = model.new_wear_state();
    let (rec, _) = transient_clean_record(&model, &setup, &wear).unwrap();
    let fs = rec.sampling_rate_hz;
    let edges = gearwear::signals::tachometer::rising_edges(&rec.tachometer_v, fs);
    let ppr = c.signals.tachometer_pulses_per_revolution as f64;
    let z1 = c.gear.teeth_pinion as f64;
    // The shaft speed at time t from the pulse interval around it.
    let shaft_hz = |t: f64| {
        let i = edges.partition_point(|e| *e < t).clamp(1, edges.len() - 1);
        1.0 / (ppr * (edges[i] - edges[i - 1]))
    };
    let window = (0.1 * fs) as usize;
    let x = &rec.channels[0].1;
    let mut worst = 0.0_f64;
    for w in 1..(x.len() / window - 1) {
        let part = &x[w * window..(w + 1) * window];
        let centre = (w as f64 + 0.5) * window as f64 / fs;
        let f = shaft_hz(centre);
        let line = peak_hz(part, fs, 0.6 * z1 * f, 1.4 * z1 * f);
        worst = worst.max((line - z1 * f).abs());
        assert!(
            (line - z1 * f).abs() < 12.0,
            "t = {centre:.2} s: line {line:.1} Hz, z1 f = {:.1} Hz",
            z1 * f
        );
        // The tachometer's speed against the ramp's (not a check of the dynamics: of the
        // tachometer's reading, to a pulse interval's change of the speed).
        assert!((f - (20.0 + 10.0 * centre)).abs() < 0.2, "{f} at {centre}");
    }
    eprintln!("mesh line off z1 f by at most {worst:.2} Hz");
}

/// Counts the accepted steps of an integration.
struct Steps(usize);

impl PeriodObserver for Steps {
    fn point(&mut self, _: &GearSystem, _: f64, _: f64, _: &[f64]) {}
    fn step(&mut self, _: &GearSystem, _: f64, _: f64, _: &[f64], _: &[f64], _: ContactModes) {
        self.0 += 1;
    }
}

#[test]
fn the_budget_counts_the_transients_steps() {
    // The transient's integration as `transient_clean_record` runs it (the drive, the
    // model at the fastest speed, a fifth of the tolerance), its accepted steps counted,
    // against the budget's count of them (`budget::signals::transient_steps`): a bound,
    // whatever the pair. Spur and helical, a run-up and a load fluctuation.
    use gearwear::dynamics::transient::integrate_transient;
    use gearwear::study::budget::signals::transient_steps;
    use gearwear::study::transient_signals::{drive_of, TRANSIENT_TOLERANCE_FACTOR};
    for sets in [
        vec!["signals.ramp_end_speed_hz=45"],
        vec!["gear.helix_angle_deg=15", "signals.ramp_end_speed_hz=45"],
        vec![
            "gear.helix_angle_deg=30",
            "stiffness.slices=100",
            "signals.ramp_end_speed_hz=5",
        ],
        vec![
            "gear.helix_angle_deg=15",
            "signals.torque_fluctuation_rms_nm=10",
        ],
    ] {
        let mut all = sets.clone();
        all.push("signals.record_length=0.2");
        let c = case(&all);
        let model = Model::dynamics_from_case(&c).unwrap();
        let drive = drive_of(&model, 0.2);
        let wear = model.new_wear_state();
        let start = model
            .dynamic(&wear, &ExternalError::none())
            .unwrap()
            .end_state;
        let mut fast_case = c.clone();
        let fastest = c.signals.max_input_speed_hz(&c);
        fast_case.operating.input_speed_hz = fastest;
        let fast = Model::dynamics_from_case(&fast_case).unwrap();
        let gap = fast.wear_gap(&wear);
        let none = ExternalError::none();
        let sys = fast
            .system(&gap, &none, fast.roughness_for(&wear))
            .with_drive(&drive);
        let mut steps = Steps(0);
        let tol = c.numerics.integration_tolerance * TRANSIENT_TOLERANCE_FACTOR;
        let spm = model.settings.steps_per_mesh_period;
        integrate_transient(&sys, &drive, &start, 0.2, spm, tol, &mut steps).unwrap();
        let bound = transient_steps(&c);
        eprintln!("{sets:?}: {} steps, budget {bound:.0}", steps.0);
        assert!(steps.0 as f64 <= bound, "{sets:?}: {} > {bound}", steps.0);
    }
}

#[test]
fn gearwear_signals_records_a_helical_run_up() {
    // The command runs it (it refused a helical transient before) and states the ramp's
    // ends in its summary.
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("o");
    common::ok(&[
        "signals",
        "-q",
        "--set",
        "gear.helix_angle_deg=15",
        "--set",
        "signals.ramp_end_speed_hz=40",
        "--set",
        "signals.record_length=0.2",
        "--out",
        out.to_str().unwrap(),
    ]);
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    // The record's first and last samples' nominal speeds: 30 Hz and 40 Hz less the last
    // sample interval's share of the ramp (10 Hz / 0.2 s / 25 600 Hz = 2e-3 Hz).
    let v = &s["runup"]["input_speed_hz"];
    let (a, b) = (v[0].as_f64().unwrap(), v[1].as_f64().unwrap());
    assert!(
        (a - 30.0).abs() < 1e-9 && (b - 40.0).abs() < 3e-3,
        "{a} {b}"
    );
}
