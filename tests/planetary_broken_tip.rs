//! A broken tip on one tooth of a planetary set (`[[planetary.fault]]` `kind =
//! "broken_tip"`, docs/MODEL.md 12.13, 12.14), checked against independent facts:
//! - geometry: the tooth is cut at the radius r_a - h (a ring's at r_a + h, its tip being
//!   its inner circle), which lies on the flank at the involute's own roll distance
//!   rho_cut = sqrt(r_cut^2 - r_b^2); a pair holding the tooth carries nothing while its
//!   contact is beyond the cut, so the mesh loses that pair's stiffness for (path end -
//!   cut) / p_b mesh cycles once per the member's period, at the end of the tooth's
//!   contact where its tip is touched (computed here from the radii alone);
//! - kinematics: a sun tooth reaches planet k's pitch point at c0 = i + z_s psi_k / 2 pi
//!   cycles (as for a crack, tests/planetary_fault.rs), so its cut is passed at
//!   c0 + (rho_cut - rho_pitch) / p_b;
//! - a planet's tip is shared by its two flanks: both its meshes lose it;
//! - bad input: a height above the tooth's is refused naming the key and the range.

mod common;

use common::{gearwear, stderr};
use gearwear::config::load_case;
use gearwear::study::planetary::PlanetaryStudy;
use std::f64::consts::PI;

fn set_with(fault: &str) -> String {
    format!("[planetary]\n[[planetary.fault]]\n{fault}\n")
}

fn study(text: &str) -> PlanetaryStudy {
    PlanetaryStudy::from_case(&load_case(text, &[]).unwrap()).unwrap()
}

/// Samples per mesh cycle: the windows below are located to 2 samples (5e-3 cycles, a
/// roll of 5e-3 p_b, about 0.03 mm on this set: far below the cut's own lengths).
const PER: usize = 400;

/// The samples c in [0, span) where `f` is below `g` (a pair lost), and whether `f`
/// ever exceeds `g` (a broken tip only removes stiffness).
fn lost(span: usize, f: impl Fn(f64) -> f64, g: impl Fn(f64) -> f64) -> (Vec<f64>, bool) {
    let mut above = false;
    let c: Vec<f64> = (0..span * PER)
        .map(|i| i as f64 / PER as f64)
        .filter(|c| {
            let (a, b) = (f(*c), g(*c));
            above |= a > b;
            a < b
        })
        .collect();
    (c, above)
}

/// Own roll distance of the radius `r` on the involute of base radius `rb`, m.
fn rho_at(r: f64, rb: f64) -> f64 {
    (r * r - rb * rb).sqrt()
}

/// Checks that `c` is one interval of `len` cycles (2 samples each end), returns its ends.
fn one_window(c: &[f64], len: f64, what: &str) -> (f64, f64) {
    assert!(!c.is_empty(), "{what}: nothing lost");
    let (lo, hi) = (c[0], c[c.len() - 1]);
    let tol = 2.0 / PER as f64;
    assert!(
        (hi - lo - len).abs() <= tol,
        "{what}: lost over {} cycles, expected {len}",
        hi - lo
    );
    assert_eq!(
        c.len(),
        ((hi - lo) * PER as f64).round() as usize + 1,
        "{what}: not one interval"
    );
    (lo, hi)
}

#[test]
fn a_broken_sun_tip_removes_its_pair_beyond_the_cut_when_the_sun_has_turned_to_each_planet() {
    let healthy = study("[planetary]\n");
    let (tooth, h_mm) = (3usize, 1.0);
    let faulty = study(&set_with(&format!(
        "kind = \"broken_tip\"\ngear = \"sun\"\ntooth = {tooth}\nremoved_height_mm = {h_mm}"
    )));
    let sp = &healthy.set.sun_planet;
    let (zs, planets) = (24usize, 4usize);
    let rho_cut = rho_at(
        sp.pinion.tip_radius_m - h_mm * 1e-3,
        sp.pinion.base_radius_m,
    );
    assert!(
        rho_cut > sp.rho_pitch_m && rho_cut < sp.rho_end_m,
        "{rho_cut}"
    );
    let len = (sp.rho_end_m - rho_cut) / sp.base_pitch_m;
    for k in 0..planets {
        let (c, above) = lost(
            zs,
            |c| faulty.meshes.sun_n_per_m(k, c),
            |c| healthy.meshes.sun_n_per_m(k, c),
        );
        assert!(!above, "planet {k}: a broken tip added stiffness");
        let (lo, _) = one_window(&c, len, &format!("planet {k}'s sun mesh"));
        let psi = 2.0 * PI * k as f64 / planets as f64;
        let c0 = (tooth as f64 + zs as f64 * psi / (2.0 * PI)) % zs as f64;
        let cut_at = (c0 + (rho_cut - sp.rho_pitch_m) / sp.base_pitch_m) % zs as f64;
        assert!(
            (lo - cut_at).abs() <= 2.0 / PER as f64,
            "planet {k}: the pair is lost from c = {lo}, the cut is passed at {cut_at}"
        );
        // The ring meshes never meet a sun tooth.
        let (r, _) = lost(
            zs,
            |c| faulty.meshes.ring_n_per_m(k, c),
            |c| healthy.meshes.ring_n_per_m(k, c),
        );
        assert!(r.is_empty(), "planet {k}'s ring mesh changed");
    }
    assert_eq!(faulty.meshes.periods(), zs);
}

#[test]
fn a_broken_planet_tip_is_lost_on_both_its_meshes_and_a_ring_tip_on_every_ring_mesh() {
    let healthy = study("[planetary]\n");
    let h_mm = 0.8;
    let planet = study(&set_with(&format!(
        "kind = \"broken_tip\"\ngear = \"planet\"\nplanet = 2\ntooth = 5\nremoved_height_mm = {h_mm}"
    )));
    let (sp, rp) = (&healthy.set.sun_planet, &healthy.set.ring_planet);
    let p = &rp.planet;
    let rho_cut = rho_at(p.tip_radius_m - h_mm * 1e-3, p.base_radius_m);
    // Sun mesh: the planet is its gear, its own rho is N1N2 - rho1, so its tip is met at
    // the path's start: lost while rho1 < N1N2 - rho_cut.
    let sun_len = (sp.loa_length_m - rho_cut - sp.rho_start_m) / sp.base_pitch_m;
    // Ring mesh: rho1 is the planet's own rho: lost while rho1 > rho_cut.
    let ring_len = (rp.rho_end_m - rho_cut) / rp.base_pitch_m;
    assert!(sun_len > 0.05 && ring_len > 0.05, "{sun_len} {ring_len}");
    let zp = 30;
    for k in 0..4 {
        let (s, _) = lost(
            zp,
            |c| planet.meshes.sun_n_per_m(k, c),
            |c| healthy.meshes.sun_n_per_m(k, c),
        );
        let (r, _) = lost(
            zp,
            |c| planet.meshes.ring_n_per_m(k, c),
            |c| healthy.meshes.ring_n_per_m(k, c),
        );
        if k == 1 {
            one_window(&s, sun_len, "planet 2's sun mesh");
            one_window(&r, ring_len, "planet 2's ring mesh");
        } else {
            assert!(s.is_empty() && r.is_empty(), "planet {} changed", k + 1);
        }
    }
    // A ring tooth: cut at r_a + h (the tip is the inner circle), its own rho2 = rho1 +
    // N1N2: lost while rho2 < rho2_cut, at the ring path's start, on every planet.
    let ring = study(&set_with(&format!(
        "kind = \"broken_tip\"\ngear = \"ring\"\ntooth = 7\nremoved_height_mm = {h_mm}"
    )));
    let r = &rp.ring;
    let rho2_cut = rho_at(r.tip_radius_m + h_mm * 1e-3, r.base_radius_m);
    let len = (rho2_cut - rp.loa_length_m - rp.rho_start_m) / rp.base_pitch_m;
    assert!(len > 0.05, "{len}");
    for k in 0..4 {
        let (c, above) = lost(
            84,
            |c| ring.meshes.ring_n_per_m(k, c),
            |c| healthy.meshes.ring_n_per_m(k, c),
        );
        assert!(!above);
        one_window(&c, len, &format!("planet {}'s ring mesh", k + 1));
    }
}

#[test]
fn a_broken_sun_tip_runs_in_dynamics_and_a_height_above_the_tooth_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("set.toml");
    let out = d.path().join("out");
    std::fs::write(
        &case,
        set_with("kind = \"broken_tip\"\ngear = \"sun\"\ntooth = 3\nremoved_height_mm = 1"),
    )
    .unwrap();
    let o = gearwear(&[
        "dynamics",
        "--config",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["planetary_dynamics"]["fault"]["member"], "sun");
    assert_eq!(s["planetary_dynamics"]["fault"]["period_mesh_periods"], 24);
    let forces = std::fs::read_to_string(out.join("mesh_forces.csv")).unwrap();
    assert!(!forces.contains("NaN") && !forces.contains("inf"));
    // A height above the tooth (module 2 mm: m (h_a* + h_f*) = 4.5 mm tip to root for the
    // sun and for the ring, whose addendum is at most the external one's): refused
    // naming the key and the range.
    for gear in ["sun", "ring"] {
        let bad = d.path().join(format!("bad_{gear}.toml"));
        std::fs::write(
            &bad,
            set_with(&format!(
                "kind = \"broken_tip\"\ngear = \"{gear}\"\ntooth = 3\nremoved_height_mm = 5"
            )),
        )
        .unwrap();
        let dir = d.path().join(format!("out_{gear}"));
        let o = gearwear(&[
            "dynamics",
            "--config",
            bad.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(2), "{gear}: {}", stderr(&o));
        let e = stderr(&o);
        assert!(
            e.contains("`planetary.fault.removed_height_mm` = 5") && e.contains("valid (0, "),
            "{gear}: {e}"
        );
        assert!(!dir.exists());
    }
}
