//! A tooth fault on the ring of a planetary set (`[[planetary.fault]]` with `gear =
//! "ring"`, docs/MODEL.md 12.14), and a sun fault on a set with unequal planet spacing,
//! checked against independent facts:
//! - kinematics of the mesh stiffness: in the carrier frame the ring turns one ring pitch
//!   per mesh cycle against the sun's sense (Willis: z_s (w_s - w_c) = -z_r (w_r - w_c)),
//!   so ring tooth j, at planet 1's ring-mesh pitch point at c = gamma_rs + j, reaches
//!   planet k (at psi_k, counted in the sun's sense) z_r (2 pi - psi_k) / 2 pi cycles
//!   later: at c = gamma_rs + j - z_r psi_k / 2 pi (mod z_r); its pair is in contact for
//!   the ring contact ratio's cycles around it. Sun tooth i meets planet k at
//!   c = i + z_s psi_k / 2 pi (mod z_s). Both on a set whose planet angles give
//!   non-integer phases (gamma != 0) as well as on the in-phase one;
//! - the ring sensor's spectrum: a ring tooth fixed under the sensor meets the N planets
//!   in turn, N times per carrier revolution relative to the ring, the ring fault's
//!   characteristic frequency N f_c (Feng & Zuo 2012, J. Sound Vib. 331, with the ring
//!   fixed), so the signal keeps its lines on multiples of N f_c and gains the sidebands
//!   h f_m + l N f_c, |l| >= 2, that the healthy set (heard at h f_m and h f_m +- N f_c
//!   through the windows' raised cosine, docs/MODEL.md 12.7) lacks; frequencies from the
//!   teeth and the input speed, amplitudes by a direct Fourier sum;
//! - a crack of zero depth on a ring tooth is the healthy set, bit for bit;
//! - bad input: exit 2 naming the key, the value and the valid range.

mod common;

use common::{gearwear, stderr};
use gearwear::config::load_case;
use gearwear::study::planetary::PlanetaryStudy;
use gearwear::study::planetary_dynamics::PlanetaryDynamics;
use gearwear::study::planetary_signals::{ring_sensor_record, RingSensor, RingSensorError};
use std::f64::consts::PI;

/// The built-in set (24 / 30 / 84, four planets, sun in, ring fixed) with the extra
/// `[planetary]` keys `keys` and `fault` (TOML keys of one `[[planetary.fault]]` table;
/// empty: healthy).
fn set_with(keys: &str, fault: &str) -> String {
    if fault.is_empty() {
        format!("[planetary]\n{keys}\n")
    } else {
        format!("[planetary]\n{keys}\n[[planetary.fault]]\n{fault}\n")
    }
}

/// Three planets at 0, 120 and 250 deg (multiples of 360 / (z_s + z_r) = 3.33 deg):
/// z_s psi / 2 pi = 0, 8, 16.67 and z_r psi / 2 pi = 0, 28, 58.33, so planet 3's meshes
/// have non-integer phases (gamma = 2/3).
const UNEQUAL: &str = "planets = 3\nplanet_angles_deg = [0.0, 120.0, 250.0]";

fn study(keys: &str, fault: &str) -> PlanetaryStudy {
    PlanetaryStudy::from_case(&load_case(&set_with(keys, fault), &[]).unwrap()).unwrap()
}

/// The samples c in [0, span) (step 1 / `per`) where `f` and `g` differ.
fn differing(span: usize, per: usize, f: impl Fn(f64) -> f64, g: impl Fn(f64) -> f64) -> Vec<f64> {
    (0..span * per)
        .map(|i| i as f64 / per as f64)
        .filter(|c| f(*c) != g(*c))
        .collect()
}

/// Checks that the samples `changed` (over one period of `span` cycles) form one interval
/// around `c0` (modulo the span) as long as `eps` cycles, within a sample at each end;
/// returns the cycle (in [0, span)) where the interval starts, measured from the samples.
fn one_dip_around(changed: &[f64], span: f64, c0: f64, eps: f64, per: usize, what: &str) -> f64 {
    assert!(!changed.is_empty(), "{what}: the fault never meets it");
    // Offsets from c0 in (-span / 2, span / 2].
    let mut off: Vec<f64> = changed
        .iter()
        .map(|c| {
            let d = (c - c0).rem_euclid(span);
            if d > span / 2.0 {
                d - span
            } else {
                d
            }
        })
        .collect();
    off.sort_by(f64::total_cmp);
    let (lo, hi) = (off[0], off[off.len() - 1]);
    let step = 1.0 / per as f64;
    assert!(
        lo <= 1e-9 && hi >= -1e-9,
        "{what}: the dip [{lo}, {hi}] (from c0) misses c0 = {c0}"
    );
    assert!(
        (hi - lo - eps).abs() <= 2.0 * step,
        "{what}: dip {} cycles long, contact ratio {eps}",
        hi - lo
    );
    assert_eq!(
        off.len(),
        ((hi - lo) * per as f64).round() as usize + 1,
        "{what}: the dip is not one interval"
    );
    (c0 + lo).rem_euclid(span)
}

/// Checks that each planet's dip starts where planet 1's does plus the cycles the faulty
/// tooth takes to travel from planet 1 to it, `travel(psi_k)`, measured from the samples
/// (both starts on the same sampling grid: equal to rounding, 1e-9 of a cycle, when the
/// travel is a whole number of samples, else within one sample).
fn starts_follow_travel(
    starts: &[f64],
    psi: &[f64],
    span: f64,
    per: usize,
    travel: impl Fn(f64) -> f64,
    what: &str,
) {
    for (k, (start, psi_k)) in starts.iter().zip(psi).enumerate() {
        let d = (start - starts[0] - travel(*psi_k)).rem_euclid(span);
        let miss = d.min(span - d);
        assert!(
            miss <= 1.0 / per as f64 + 1e-9,
            "{what}: planet {}'s dip starts {miss} cycles off planet 1's plus the tooth's travel",
            k + 1
        );
    }
}

/// The ring fault's dips for every planet of the set `keys`, ring tooth `tooth`.
fn ring_dips(keys: &str, tooth: usize) {
    let healthy = study(keys, "");
    let faulty = study(
        keys,
        &format!("kind = \"crack\"\ngear = \"ring\"\ntooth = {tooth}\ncrack_depth_mm = 1.5"),
    );
    let zr = 84usize;
    let set = &healthy.set;
    let eps = set.ring_planet.contact_ratio;
    // Ring tooth 0's first passage of planet 1's ring-mesh pitch point: gamma_rs (the
    // numbering's reference, docs/MODEL.md 12.14).
    let gamma_rs = set.ring_sun_phase();
    let per = 50;
    assert_eq!(faulty.meshes.periods(), zr);
    let mut starts = Vec::new();
    for (k, psi) in set.planet_angles_rad.iter().enumerate() {
        let c0 = (gamma_rs + tooth as f64 - zr as f64 * psi / (2.0 * PI)).rem_euclid(zr as f64);
        let changed = differing(
            zr,
            per,
            |c| healthy.meshes.ring_n_per_m(k, c),
            |c| faulty.meshes.ring_n_per_m(k, c),
        );
        let what = format!("{keys:?}, planet {}", k + 1);
        starts.push(one_dip_around(&changed, zr as f64, c0, eps, per, &what));
        for c in &changed {
            assert!(faulty.meshes.ring_n_per_m(k, *c) < healthy.meshes.ring_n_per_m(k, *c));
        }
        // The sun meshes never meet a ring tooth.
        assert!(differing(
            zr,
            10,
            |c| healthy.meshes.sun_n_per_m(k, c),
            |c| faulty.meshes.sun_n_per_m(k, c)
        )
        .is_empty());
    }
    // Independent of the numbering's reference gamma_rs: in the carrier frame the ring
    // turns against the sun's sense, one ring pitch (2 pi / z_r) per mesh cycle, so the
    // faulty tooth travels from planet 1 (at 0) to planet k (at psi_k in the sun's sense)
    // through 2 pi - psi_k, z_r (2 pi - psi_k) / 2 pi cycles; its contact with planet k
    // starts that much after its contact with planet 1 (the same approach on every planet).
    let travel = |psi: f64| zr as f64 * (2.0 * PI - psi) / (2.0 * PI);
    starts_follow_travel(
        &starts,
        &set.planet_angles_rad,
        zr as f64,
        per,
        travel,
        keys,
    );
}

#[test]
fn a_ring_tooth_meets_each_planet_when_the_ring_has_turned_back_to_it() {
    ring_dips("", 5);
    ring_dips(UNEQUAL, 11);
}

#[test]
fn a_sun_tooth_meets_each_unequally_spaced_planet_at_its_own_phase() {
    let tooth = 7;
    let healthy = study(UNEQUAL, "");
    let faulty = study(
        UNEQUAL,
        &format!("kind = \"crack\"\ngear = \"sun\"\ntooth = {tooth}\ncrack_depth_mm = 1.5"),
    );
    let zs = 24usize;
    let eps = healthy.set.sun_planet.contact_ratio;
    let per = 200;
    let gammas = healthy.set.sun_planet_phases();
    assert!(gammas[2] > 0.1, "planet 3's phase {} is whole", gammas[2]);
    let mut starts = Vec::new();
    for (k, psi) in healthy.set.planet_angles_rad.iter().enumerate() {
        let c0 = (tooth as f64 + zs as f64 * psi / (2.0 * PI)).rem_euclid(zs as f64);
        let changed = differing(
            zs,
            per,
            |c| healthy.meshes.sun_n_per_m(k, c),
            |c| faulty.meshes.sun_n_per_m(k, c),
        );
        starts.push(one_dip_around(
            &changed,
            zs as f64,
            c0,
            eps,
            per,
            &format!("planet {}", k + 1),
        ));
    }
    // In the carrier frame the sun turns in its own sense, one sun pitch per mesh cycle:
    // its faulty tooth reaches planet k (at psi_k in that sense) z_s psi_k / 2 pi cycles
    // after planet 1.
    let travel = |psi: f64| zs as f64 * psi / (2.0 * PI);
    let psi = &healthy.set.planet_angles_rad;
    starts_follow_travel(&starts, psi, zs as f64, per, travel, "sun");
}

/// The amplitude of the line at `f_hz` of the periodic signal `x`, one period `span_s`
/// long, sampled evenly: 2 / M |sum x_j e^(-2 pi i f t_j)|.
fn line(x: &[f64], span_s: f64, f_hz: f64) -> f64 {
    let m = x.len() as f64;
    let (mut re, mut im) = (0.0, 0.0);
    for (j, v) in x.iter().enumerate() {
        let a = 2.0 * PI * f_hz * span_s * j as f64 / m;
        re += v * a.cos();
        im -= v * a.sin();
    }
    2.0 * re.hypot(im) / m
}

#[test]
fn a_cracked_ring_tooth_puts_sidebands_at_the_planets_passing_it() {
    let (zs, zr, n) = (24usize, 84usize, 4usize);
    let sensor = RingSensor {
        angle_rad: 0.0,
        half_width_rad: PI / n as f64,
        record_s: 0.01,
        sampling_rate_hz: 1e4,
    };
    let record = |fault: &str| {
        let case = load_case(&set_with("", fault), &[]).unwrap();
        let mut d = PlanetaryDynamics::from_case(&case).unwrap();
        let r = d.solve().unwrap();
        let rec = ring_sensor_record(&d, &r, sensor).unwrap();
        (case, rec)
    };
    let (case, healthy) = record("");
    let (_, faulty) = record("kind = \"crack\"\ngear = \"ring\"\ntooth = 10\ncrack_depth_mm = 1.5");
    // Kinematics from the teeth and the input speed (Willis, sun in, ring fixed).
    let f_s = case.operating.input_speed_hz;
    let f_c = f_s * zs as f64 / (zs + zr) as f64;
    let f_m = zr as f64 * f_c;
    // The ring tooth's period z_r mesh periods is the carrier's revolution: both signals
    // repeat over one revolution.
    let span_s = zr as f64 / f_m;
    let s = case.numerics.steps_per_mesh_period as usize;
    assert_eq!(faulty.revolution_n.len(), zr * s);
    assert_eq!(healthy.revolution_n.len(), zr * s);
    for h in 1..=2 {
        let mesh = line(&healthy.revolution_n, span_s, h as f64 * f_m);
        assert!(mesh > 0.0);
        for l in [-3, -2, 2, 3] {
            let f = h as f64 * f_m + (l * n as i32) as f64 * f_c;
            let (a_faulty, a_healthy) = (
                line(&faulty.revolution_n, span_s, f),
                line(&healthy.revolution_n, span_s, f),
            );
            // Present: above 1e-4 of the mesh harmonic (the 1.5 mm crack gives 3e-4 to
            // 6e-4 of it); absent from the healthy set to round-off (1e-9 of it).
            assert!(
                a_faulty > 1e-4 * mesh,
                "h {h}, l {l}: {a_faulty} vs mesh {mesh}"
            );
            assert!(a_healthy < 1e-9 * mesh, "h {h}, l {l}: healthy {a_healthy}");
        }
        // Off the multiples of N f_c: the faulty set, which repeats when the carrier has
        // turned one planet spacing (equally spaced, in-phase planets, a tooth fixed on
        // the ring), has none either: below 1e-9 of the mesh harmonic (measured 1e-12;
        // the steady state's periodicity, 6e-14 here, and the sums' round-off bound it).
        for l in [-3, -2, -1, 1, 2, 3, 5] {
            let f = h as f64 * f_m + l as f64 * f_c;
            let a = line(&faulty.revolution_n, span_s, f);
            assert!(
                a < 1e-9 * mesh,
                "h {h}, order offset {l}: {a} vs mesh {mesh}"
            );
        }
    }
}

/// Run `gearwear <cmd>` on the case `text`; the folder (kept alive), output and process.
fn run(cmd: &str, text: &str) -> (tempfile::TempDir, std::path::PathBuf, std::process::Output) {
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("case.toml");
    std::fs::write(&case, text).unwrap();
    let out = d.path().join("out");
    let o = gearwear(&[
        cmd,
        "-q",
        "--config",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (d, out, o)
}

#[test]
fn a_ring_crack_of_zero_depth_is_the_healthy_set_bit_for_bit() {
    let (_a, healthy, o) = run("dynamics", &set_with("", ""));
    assert!(o.status.success(), "{}", stderr(&o));
    let zero = "kind = \"crack\"\ngear = \"ring\"\ntooth = 83\ncrack_depth_mm = 0";
    let (_b, zero, o) = run("dynamics", &set_with("", zero));
    assert!(o.status.success(), "{}", stderr(&o));
    for file in ["mesh_forces.csv", "motions.csv", "load_sharing.csv"] {
        assert_eq!(
            std::fs::read(healthy.join(file)).unwrap(),
            std::fs::read(zero.join(file)).unwrap(),
            "{file}"
        );
    }
}

#[test]
fn bad_ring_faults_are_refused_naming_key_value_and_range() {
    for (fault, needles) in [
        (
            "kind = \"crack\"\ngear = \"ring\"\ntooth = 84\ncrack_depth_mm = 1",
            vec!["`planetary.fault.tooth` = 84", "teeth 0 to 83"],
        ),
        (
            "kind = \"crack\"\ngear = \"ring\"\nplanet = 2\ntooth = 3\ncrack_depth_mm = 1",
            vec!["`planetary.fault.planet` = 2", "not to the ring"],
        ),
        (
            "kind = \"crack\"\ngear = \"ring\"\ntooth = 2\ncrack_depth_mm = 10",
            vec![
                "`planetary.fault.crack_depth_mm` = 10",
                "ring tooth 2",
                "valid [0, ",
            ],
        ),
        (
            "kind = \"spall\"\ngear = \"ring\"\ntooth = 2\nspall_position_mm = 0\nspall_length_mm = 20\nspall_depth_um = 20",
            vec!["`planetary.fault.spall_length_mm` = 20", "ring tooth 2", "valid (0, "],
        ),
        (
            "kind = \"spall\"\ngear = \"ring\"\ntooth = 2\nspall_position_mm = 8\nspall_length_mm = 0.5\nspall_depth_um = 20",
            vec!["`planetary.fault.spall_position_mm` = 8", "ring tooth 2", "within ["],
        ),
        (
            "kind = \"spall\"\ngear = \"ring\"\ntooth = 2\nspall_position_mm = 0\nspall_length_mm = 0.5\nspall_depth_um = 9000",
            vec!["`planetary.fault.spall_depth_um` = 9000", "ring tooth 2", "valid (0, "],
        ),
        (
            "kind = \"broken_tip\"\ngear = \"ring\"\ntooth = 2\nremoved_height_mm = 4.6",
            vec![
                "`planetary.fault.removed_height_mm` = 4.6",
                "ring tooth 2",
                "valid (0, ",
            ],
        ),
    ] {
        let (_d, out, o) = run("dynamics", &set_with("", fault));
        assert_eq!(o.status.code(), Some(2), "{fault}: {}", stderr(&o));
        let e = stderr(&o);
        for n in needles {
            assert!(e.contains(n), "{fault}: {e} lacks {n}");
        }
        assert!(!e.contains("panicked") && !out.exists());
    }
}

#[test]
fn a_ring_faults_period_is_one_ring_revolution_relative_to_the_carrier() {
    use gearwear::study::budget::{estimate, Job};
    let faulty = load_case(
        &set_with(
            "",
            "kind = \"spall\"\ngear = \"ring\"\ntooth = 2\nspall_position_mm = 0\nspall_length_mm = 0.5\nspall_depth_um = 20",
        ),
        &[],
    )
    .unwrap();
    // z_r mesh periods for the response and for the ring sensor's record (lcm(z_r, z_r)).
    let (p, record) =
        gearwear::study::planetary_fault::fault_periods(faulty.planetary.as_ref().unwrap(), 200)
            .unwrap();
    assert_eq!((p, record), (84, 84));
    let term = estimate(&faulty, Job::Dynamics)
        .terms
        .into_iter()
        .find(|t| t.what.contains("tooth fault"))
        .unwrap();
    assert!(term.seconds > 0.0 && term.bytes > 0.0);
    assert!(term.keys.contains(&"planetary.teeth_ring"));
    // A ring of 9999 teeth at 6000 samples per mesh period: beyond the record limit.
    let mut s = faulty.planetary.clone().unwrap();
    s.teeth_ring = 9999;
    let e = gearwear::study::planetary_fault::fault_periods(&s, 6000)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("`planetary.teeth_ring` = 9999") && e.contains("beyond the limit"),
        "{e}"
    );
}

/// A steady state whose force overflowed gives no ring record (nor spectrum): the error
/// names the first sample of the sensor's period that is not finite, at its time (sample
/// j of a period of s steps per mesh period lies at j / (s f_m)).
#[test]
fn an_overflowed_force_gives_no_ring_record() {
    let case = load_case(&set_with("", ""), &[]).unwrap();
    let mut d = PlanetaryDynamics::from_case(&case).unwrap();
    let mut r = d.solve().unwrap();
    let sensor = RingSensor {
        angle_rad: 0.0,
        half_width_rad: PI / 4.0,
        record_s: 0.01,
        sampling_rate_hz: 1e4,
    };
    assert!(ring_sensor_record(&d, &r, sensor).is_ok());
    // Planet 1's ring mesh (the ring meshes follow the N sun meshes) at step 3, when the
    // window around the sensor at 0 rad holds planet 1 (at 0 rad at t = 0).
    let planets = 4;
    r.mesh_forces_n[3][planets] = f64::INFINITY;
    match ring_sensor_record(&d, &r, sensor) {
        Err(RingSensorError::NonFinite { sample, time_s }) => {
            assert_eq!(sample, 3);
            let zr = 84.0;
            let f_m = zr * case.operating.input_speed_hz * 24.0 / (24.0 + zr);
            let s = case.numerics.steps_per_mesh_period as f64;
            assert!((time_s - 3.0 / (s * f_m)).abs() < 1e-12 * time_s.max(1e-9));
        }
        other => panic!("expected a non-finite record, got {other:?}"),
    }
}
