//! A tooth fault on one member of a planetary set (`[[planetary.fault]]`, docs/MODEL.md
//! 12.14), checked against independent facts:
//! - kinematics of the mesh stiffness: sun tooth i meets planet k at its sun mesh's pitch
//!   point when the sun has turned relative to the carrier by i tooth pitches plus planet
//!   k's angle, i.e. at c = i + z_s psi_k / 2 pi mesh cycles (and every z_s cycles after);
//!   its pair is in contact for the contact ratio's cycles around that instant;
//! - a fault on one planet changes that planet's two meshes only;
//! - the ring sensor's spectrum (McFadden & Smith 1985; Inalpolat & Kahraman 2009): a
//!   cracked sun tooth modulates every mesh at the sun's rotation relative to the carrier,
//!   f_s - f_c, so sidebands h f_m + l (f_s - f_c) appear; the frequencies are computed
//!   here from the teeth and the input speed (Willis), the amplitudes by a direct Fourier
//!   sum over the record's span; the healthy set has none;
//! - a crack of zero depth is the healthy set, bit for bit;
//! - bad input: exit 2 naming the key, the value and the valid range.

mod common;

use common::{gearwear, stderr};
use gearwear::config::load_case;
use gearwear::study::planetary::PlanetaryStudy;
use gearwear::study::planetary_dynamics::PlanetaryDynamics;
use gearwear::study::planetary_signals::{ring_sensor_record, RingSensor};
use std::f64::consts::PI;

/// The built-in set (24 / 30 / 84, four planets, sun in, ring fixed) with `fault` (TOML
/// keys of one `[[planetary.fault]]` table; empty: healthy).
fn set_with(fault: &str) -> String {
    if fault.is_empty() {
        "[planetary]\n".into()
    } else {
        format!("[planetary]\n[[planetary.fault]]\n{fault}\n")
    }
}

fn study(fault: &str) -> PlanetaryStudy {
    PlanetaryStudy::from_case(&load_case(&set_with(fault), &[]).unwrap()).unwrap()
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// The samples c in [0, span) (step 1 / `per`) where `f` and `g` differ.
fn differing(span: usize, per: usize, f: impl Fn(f64) -> f64, g: impl Fn(f64) -> f64) -> Vec<f64> {
    (0..span * per)
        .map(|i| i as f64 / per as f64)
        .filter(|c| f(*c) != g(*c))
        .collect()
}

#[test]
fn a_sun_tooth_meets_each_planet_when_the_sun_has_turned_by_the_planets_angle() {
    let tooth = 3;
    let healthy = study("");
    let faulty = study(&format!(
        "kind = \"crack\"\ngear = \"sun\"\ntooth = {tooth}\ncrack_depth_mm = 1.5"
    ));
    let (zs, planets) = (24usize, 4usize);
    let eps = healthy.set.sun_planet.contact_ratio;
    let per = 200;
    for k in 0..planets {
        // Planet k at psi_k = 2 pi k / N: the sun tooth reaches it after turning by
        // i pitches plus psi_k relative to the carrier, z_s psi_k / 2 pi more cycles.
        let psi = 2.0 * PI * k as f64 / planets as f64;
        let c0 = tooth as f64 + zs as f64 * psi / (2.0 * PI);
        let c0 = c0 % zs as f64;
        let changed = differing(
            zs,
            per,
            |c| healthy.meshes.sun_n_per_m(k, c),
            |c| faulty.meshes.sun_n_per_m(k, c),
        );
        assert!(!changed.is_empty(), "planet {k}: the crack never meets it");
        // One contact per sun revolution relative to the carrier, around c0, as long as
        // the contact ratio (within a sample at each end).
        let (lo, hi) = (changed[0], changed[changed.len() - 1]);
        assert!(
            lo <= c0 && c0 <= hi,
            "planet {k}: the dip [{lo}, {hi}] misses c0 = {c0}"
        );
        assert!(
            (hi - lo - eps).abs() <= 2.0 / per as f64,
            "planet {k}: dip {} cycles long, contact ratio {eps}",
            hi - lo
        );
        assert_eq!(
            changed.len(),
            ((hi - lo) * per as f64).round() as usize + 1,
            "planet {k}: the dip is not one interval"
        );
        // A dip: the cracked tooth is softer.
        for c in &changed {
            assert!(faulty.meshes.sun_n_per_m(k, *c) < healthy.meshes.sun_n_per_m(k, *c));
        }
        // The ring meshes never meet a sun tooth.
        assert!(differing(
            zs,
            20,
            |c| healthy.meshes.ring_n_per_m(k, c),
            |c| faulty.meshes.ring_n_per_m(k, c)
        )
        .is_empty());
    }
    assert_eq!(faulty.meshes.periods(), zs);
}

#[test]
fn a_planet_fault_changes_that_planets_meshes_only() {
    let healthy = study("");
    let faulty =
        study("kind = \"crack\"\ngear = \"planet\"\nplanet = 2\ntooth = 5\ncrack_depth_mm = 1.5");
    let zp = 30;
    assert_eq!(faulty.meshes.periods(), zp);
    for k in 0..4 {
        let sun = differing(
            zp,
            50,
            |c| healthy.meshes.sun_n_per_m(k, c),
            |c| faulty.meshes.sun_n_per_m(k, c),
        );
        let ring = differing(
            zp,
            50,
            |c| healthy.meshes.ring_n_per_m(k, c),
            |c| faulty.meshes.ring_n_per_m(k, c),
        );
        if k == 1 {
            // Planet 2 at 90 deg: z_s psi / 2 pi = 6 whole cycles, so its tooth j passes
            // the sun mesh's pitch point at c = j (mod z_p); once per planet revolution
            // relative to the carrier on each mesh, as long as each contact ratio.
            assert!(
                sun.first().unwrap() <= &5.0 && &5.0 <= sun.last().unwrap(),
                "{sun:?}"
            );
            let eps_s = healthy.set.sun_planet.contact_ratio;
            assert!((sun.last().unwrap() - sun.first().unwrap() - eps_s).abs() < 0.05);
            assert!(
                !ring.is_empty(),
                "the crack leaves the planet's ring mesh alone"
            );
            assert!(ring.last().unwrap() - ring.first().unwrap() < 2.5);
        } else {
            assert!(
                sun.is_empty() && ring.is_empty(),
                "planet {} changed",
                k + 1
            );
        }
    }
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
fn a_cracked_sun_tooth_puts_sidebands_at_the_suns_rotation_relative_to_the_carrier() {
    let (zs, zr) = (24usize, 84usize);
    let sensor = RingSensor {
        angle_rad: 0.0,
        half_width_rad: PI / 4.0,
        record_s: 0.01,
        sampling_rate_hz: 1e4,
    };
    let record = |fault: &str| {
        let case = load_case(&set_with(fault), &[]).unwrap();
        let mut d = PlanetaryDynamics::from_case(&case).unwrap();
        let r = d.solve().unwrap();
        let rec = ring_sensor_record(&d, &r, sensor).unwrap();
        (case, rec)
    };
    let (case, healthy) = record("");
    let (_, faulty) = record("kind = \"crack\"\ngear = \"sun\"\ntooth = 7\ncrack_depth_mm = 1.5");
    // Kinematics from the teeth and the input speed (Willis, sun in, ring fixed).
    let f_s = case.operating.input_speed_hz;
    let f_c = f_s * zs as f64 / (zs + zr) as f64;
    let f_m = zr as f64 * f_c;
    let f_rel = f_s - f_c;
    // The faulty signal repeats over lcm(z_s, z_r) mesh periods (the sun tooth's z_s and
    // the carrier's z_r relative to the ring): two carrier revolutions here.
    let lcm = zs / gcd(zs, zr) * zr;
    let span_s = lcm as f64 / f_m;
    let s = case.numerics.steps_per_mesh_period as usize;
    assert_eq!(faulty.revolution_n.len(), lcm * s);
    // The healthy signal repeats every carrier revolution: tiled over the same span.
    assert_eq!(healthy.revolution_n.len(), zr * s);
    let tiled: Vec<f64> = healthy
        .revolution_n
        .iter()
        .cycle()
        .take(lcm * s)
        .copied()
        .collect();
    for h in 1..=2 {
        let mesh = line(&tiled, span_s, h as f64 * f_m);
        assert!(mesh > 0.0);
        for l in [-3, -1, 1, 3] {
            // Odd l: half carrier orders (f_s - f_c = 3.5 f_c), lines no healthy set has.
            let f = h as f64 * f_m + l as f64 * f_rel;
            let (a_faulty, a_healthy) = (
                line(&faulty.revolution_n, span_s, f),
                line(&tiled, span_s, f),
            );
            // Present: above 1e-4 of the mesh harmonic (the 1.5 mm crack gives 5e-4 to
            // 5e-3 of it); absent from the healthy set to round-off (1e-9 of it).
            assert!(
                a_faulty > 1e-4 * mesh,
                "h {h}, l {l}: {a_faulty} vs mesh {mesh}"
            );
            assert!(a_healthy < 1e-9 * mesh, "h {h}, l {l}: healthy {a_healthy}");
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
fn a_crack_of_zero_depth_is_the_healthy_set_bit_for_bit() {
    let (_a, healthy, o) = run("dynamics", &set_with(""));
    assert!(o.status.success(), "{}", stderr(&o));
    for fault in [
        "kind = \"crack\"\ngear = \"sun\"\ntooth = 3\ncrack_depth_mm = 0",
        "kind = \"crack\"\ngear = \"planet\"\nplanet = 3\ntooth = 3\ncrack_depth_mm = 0.0",
    ] {
        let (_b, zero, o) = run("dynamics", &set_with(fault));
        assert!(o.status.success(), "{}", stderr(&o));
        for file in ["mesh_forces.csv", "motions.csv", "load_sharing.csv"] {
            assert_eq!(
                std::fs::read(healthy.join(file)).unwrap(),
                std::fs::read(zero.join(file)).unwrap(),
                "{file} with {fault}"
            );
        }
    }
}

#[test]
fn bad_faults_are_refused_naming_key_value_and_range() {
    for (fault, needles) in [
        (
            "kind = \"crack\"\ngear = \"sun\"\ntooth = 24\ncrack_depth_mm = 1",
            vec!["`planetary.fault.tooth` = 24", "teeth 0 to 23"],
        ),
        (
            "kind = \"crack\"\ngear = \"planet\"\nplanet = 5\ntooth = 2\ncrack_depth_mm = 1",
            vec!["`planetary.fault.planet` = 5", "1..=4"],
        ),
        (
            "kind = \"crack\"\ngear = \"planet\"\ntooth = 2\ncrack_depth_mm = 1",
            vec!["`planetary.fault.planet` is required", "1..=4"],
        ),
        (
            "kind = \"crack\"\ngear = \"planet\"\nplanet = 1\ntooth = 30\ncrack_depth_mm = 1",
            vec!["`planetary.fault.tooth` = 30", "teeth 0 to 29"],
        ),
        (
            "kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 10",
            vec!["`planetary.fault.crack_depth_mm` = 10", "sun tooth 2", "valid [0, "],
        ),
        (
            "kind = \"spall\"\ngear = \"sun\"\ntooth = 2\nspall_position_mm = 0\nspall_length_mm = 1\nspall_depth_um = -5",
            vec!["`planetary.fault.spall_depth_um` = -5", "(planetary fault 1)"],
        ),
    ] {
        let (_d, out, o) = run("dynamics", &set_with(fault));
        assert_eq!(o.status.code(), Some(2), "{fault}: {}", stderr(&o));
        let e = stderr(&o);
        for n in needles {
            assert!(e.contains(n), "{fault}: {e} lacks {n}");
        }
        assert!(!e.contains("panicked") && !out.exists());
    }
    // A pair's [[fault]] on a set (its wear and run take `[[planetary.fault]]`:
    // tests/planetary_fault_wear.rs).
    let pair_fault = "[planetary]\n[[fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 2\ncrack_depth_mm = 1\n";
    let (_d, _, o) = run("dynamics", pair_fault);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("`fault.gear` = \"pinion\"")
            && stderr(&o).contains("[[planetary.fault]]")
    );
}

#[test]
fn the_budget_counts_the_faults_period_and_refuses_one_beyond_the_limits() {
    use gearwear::study::budget::{estimate, Job};
    let healthy = load_case(&set_with(""), &[]).unwrap();
    let faulty = load_case(
        &set_with("kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1"),
        &[],
    )
    .unwrap();
    let (h, f) = (
        estimate(&healthy, Job::Dynamics),
        estimate(&faulty, Job::Dynamics),
    );
    let term = f
        .terms
        .iter()
        .find(|t| t.what.contains("tooth fault"))
        .unwrap();
    assert!(term.seconds > 0.0 && term.bytes > 0.0);
    assert!(!h.terms.iter().any(|t| t.what.contains("tooth fault")));
    // A fault's record of lcm(z_p, z_r) = 9999 x 9998 mesh periods is beyond the limits:
    // the period check names the keys (checked arithmetic, no overflow or panic).
    let mut s = faulty.planetary.clone().unwrap();
    s.teeth_sun = 9999;
    s.teeth_ring = 9998;
    let e = gearwear::study::planetary_fault::fault_periods(&s, 200)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("`planetary.teeth_sun` = 9999") && e.contains("beyond the limit"),
        "{e}"
    );
    let (p, record) =
        gearwear::study::planetary_fault::fault_periods(&faulty.planetary.unwrap(), 200).unwrap();
    assert_eq!((p, record), (24, 168));
}

#[test]
fn dynamics_records_the_faults_period_and_only_the_ring_sensor_needs_lcm_with_the_ring() {
    use gearwear::study::budget::estimate_signals;
    // A 331 / 333 / 997 set (331 and 997 prime: lcm = 330 007 mesh periods) with a sun
    // tooth fault: its dynamics repeats over z_s = 331 periods (66 200 samples at 200
    // steps, far inside the limit of 5e7) and is built; the ring sensor's record spans
    // lcm(331, 997) periods, 6.6e7 samples: refused by `signals` alone, naming lcm.
    let text = |steps: u32| {
        format!(
            "[numerics]\nsteps_per_mesh_period = {steps}\n[planetary]\nteeth_sun = 331\nteeth_planet = 333\nteeth_ring = 997\n[[planetary.fault]]\nkind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1\n"
        )
    };
    let case = load_case(&text(200), &[]).unwrap();
    let s = case.planetary.as_ref().unwrap();
    assert_eq!(
        gearwear::study::planetary_fault::fault_period(s, 200),
        Ok(331)
    );
    assert!(PlanetaryStudy::from_case(&case).is_ok());
    let e = gearwear::study::planetary_fault::fault_periods(s, 200)
        .unwrap_err()
        .to_string();
    assert!(e.contains("lcm(331, 997) = 330007"), "{e}");
    let (_d, out, o) = run("signals", &text(200));
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("330007") && !out.exists());
    // At 50 steps the record is 1.65e7 samples: the signals budget counts them (measured
    // 39-40 bytes a sample for the revolution, its spectrum and record: at least that).
    let case = load_case(&text(50), &[]).unwrap();
    let est = estimate_signals(&case, 2);
    let ring = est
        .terms
        .iter()
        .find(|t| t.what.contains("ring sensor's record"))
        .expect("a ring record term");
    let samples = 331.0 * 997.0 * 50.0;
    assert!(
        ring.bytes >= 39.0 * samples && ring.bytes <= 3.0 * 40.0 * samples,
        "{}",
        ring.bytes
    );
}
