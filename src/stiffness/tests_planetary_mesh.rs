//! Tests of every mesh's stiffness over time in a planetary set (`planetary_mesh`) against
//! the mean of the tables integrated independently and the phasing rules of Parker & Lin
//! (2004): for equally spaced planets, the sum over the planets of a mesh's stiffness
//! keeps only the harmonics h with h z / N an integer (z = z_s for the sun meshes, z_r
//! for the ring meshes), since sum_n exp(-2 pi i h z n / N) is N for those and 0 for all
//! others.

use super::internal::InternalMeshStiffness;
use super::mesh::MeshStiffness;
use super::planetary_mesh::PlanetaryMeshes;
use super::potential_energy::ElasticPair;
use crate::config::case::MaterialsSection;
use crate::config::planetary::PlanetarySection;
use crate::geometry::planetary::PlanetarySet;
use std::f64::consts::PI;

/// The meshes of a set with `n` planets and teeth (z_s, z_p, z_r), module 2 mm.
pub(crate) fn meshes_of(n: i64, zs: i64, zp: i64, zr: i64) -> (PlanetarySet, PlanetaryMeshes) {
    let sec = PlanetarySection {
        planets: n,
        teeth_sun: zs,
        teeth_planet: zp,
        teeth_ring: zr,
        ..PlanetarySection::default()
    };
    let set = PlanetarySet::from_case(&sec).expect("a valid set");
    let elastic = ElasticPair::from_case(&MaterialsSection::default());
    let sun = MeshStiffness::with_fillet(&set.sun_planet, &elastic, 200, None).unwrap();
    let ring = InternalMeshStiffness::new(&set.ring_planet, &elastic, false);
    let meshes = PlanetaryMeshes::new(&set, &sun, &ring);
    (set, meshes)
}

/// |h-th Fourier coefficient| of `f` sampled at `samples` points over one mesh cycle,
/// the samples at (j + 0.37) / samples so that none falls on a contact change.
fn harmonic(f: impl Fn(f64) -> f64, h: usize, samples: usize) -> f64 {
    let (mut re, mut im) = (0.0, 0.0);
    for j in 0..samples {
        let c = (j as f64 + 0.37) / samples as f64;
        let (s, co) = (2.0 * PI * h as f64 * c).sin_cos();
        let v = f(c);
        re += v * co;
        im += v * s;
    }
    re.hypot(im) / samples as f64
}

#[test]
fn sampled_means_equal_the_tables_integrals() {
    let (set, m) = meshes_of(4, 24, 30, 84);
    let [ks, kr] = m.mean_n_per_m();
    let samples = 20_000;
    for p in 0..set.planets() {
        let mean = |f: &dyn Fn(f64) -> f64| {
            (0..samples)
                .map(|j| f((j as f64 + 0.5) / samples as f64))
                .sum::<f64>()
                / samples as f64
        };
        // Midpoint samples of a function with two jumps of ~40 % per cycle err by at most
        // a jump times half a sample (1e-5 relative); the ring's linear table by ~1e-6;
        // 1e-4 leaves room and still fails a phase or a pair count wrong by one.
        let s = mean(&|c| m.sun_n_per_m(p, c));
        let r = mean(&|c| m.ring_n_per_m(p, c));
        assert!((s / ks - 1.0).abs() < 1e-4, "sun mesh {p}: {s} vs {ks}");
        assert!((r / kr - 1.0).abs() < 1e-4, "ring mesh {p}: {r} vs {kr}");
    }
}

#[test]
fn in_phase_planets_mesh_alike() {
    // 24 / 30 / 84 with 4 planets: z_s / N = 6 and z_r / N = 21 are integers, every
    // gamma is 0 (Parker & Lin 2004): all sun meshes, and all ring meshes, coincide.
    let (_, m) = meshes_of(4, 24, 30, 84);
    for j in 0..200 {
        let c = j as f64 / 200.0 + 0.001;
        for p in 1..4 {
            assert_eq!(m.sun_n_per_m(p, c), m.sun_n_per_m(0, c));
            assert_eq!(m.ring_n_per_m(p, c), m.ring_n_per_m(0, c));
        }
    }
}

#[test]
fn sequential_phasing_cancels_the_summed_harmonics_not_multiple_of_n() {
    // 26 / 29 / 84 with 5 planets: (26 + 84) / 5 = 22 (equally spaced), z_s / N = 5.2 and
    // z_r / N = 16.8 (sequentially phased). The summed sun and ring stiffness keep the
    // harmonics h = 5, 10 only among 1..=10.
    let (set, m) = meshes_of(5, 26, 29, 84);
    let n = set.planets();
    // 500 samples: the phases k / 5 are whole shifts of 100 samples, so the cancellation
    // is exact up to rounding; 1e-9 of the mean stiffness is far above that (~1e-14) and
    // far below a single mesh's harmonics (~1e-2 of the mean for h <= 10).
    let samples = 500;
    for (name, mean, f) in [
        (
            "sun",
            m.mean_n_per_m()[0],
            Box::new(|c: f64| (0..n).map(|p| m.sun_n_per_m(p, c)).sum::<f64>())
                as Box<dyn Fn(f64) -> f64>,
        ),
        (
            "ring",
            m.mean_n_per_m()[1],
            Box::new(|c: f64| (0..n).map(|p| m.ring_n_per_m(p, c)).sum::<f64>()),
        ),
    ] {
        for h in 1..=10 {
            let a = harmonic(&f, h, samples);
            if h % n == 0 {
                assert!(a > 1e-3 * mean, "{name} h = {h} should be present: {a}");
            } else {
                assert!(a < 1e-9 * mean, "{name} h = {h} should cancel: {a}");
            }
        }
        // One mesh alone has every harmonic: the cancellation is the phasing's.
        let single = harmonic(|c| m.sun_n_per_m(0, c), 1, samples);
        assert!(single > 1e-3 * mean, "{name}: single mesh h = 1 {single}");
    }
}

/// The cycles in [0, 1) where a scan of every mesh's stiffness at `points` equally
/// spaced cycles steps by more than `threshold`, N/m: each jump as the scan interval
/// (lower, upper end) holding it.
fn scanned_jumps(m: &PlanetaryMeshes, points: usize, threshold: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for p in 0..m.planets() {
        let sun = |c| m.sun_n_per_m(p, c);
        let ring = |c| m.ring_n_per_m(p, c);
        let meshes: [&dyn Fn(f64) -> f64; 2] = [&sun, &ring];
        for k in meshes {
            for j in 0..points {
                let (a, b) = (j as f64 / points as f64, (j + 1) as f64 / points as f64);
                if (k(b) - k(a)).abs() > threshold {
                    out.push((a, b));
                }
            }
        }
    }
    out
}

#[test]
fn jump_cycles_are_where_the_scanned_stiffness_jumps() {
    // Independent of `jump_cycles` (phases plus contact ratios): a scan of every mesh's
    // stiffness over one cycle at 2e5 points. Between two points k changes smoothly by
    // ~1e-5 of its mean at most (a pair's stiffness changes by less than its mean over
    // a cycle), a pair entering or leaving by 20-60 % of it: a step above 5 % of the mean
    // is a jump. Each scanned jump's interval (5e-6 cycles) must hold a node, and every
    // node a scanned jump, in an in-phase (4 planets, 4 distinct nodes: all meshes
    // alike) and a sequentially phased set (5 planets, up to 20 nodes).
    for (n, zs, zp, zr) in [(4, 24, 30, 84), (5, 26, 29, 84)] {
        let (_, m) = meshes_of(n, zs, zp, zr);
        let nodes = m.jump_cycles();
        let threshold = 0.05 * m.mean_n_per_m()[0].min(m.mean_n_per_m()[1]);
        let scanned = scanned_jumps(&m, 200_000, threshold);
        assert!(!nodes.is_empty() && nodes.windows(2).all(|w| w[0] < w[1]));
        let holds = |(a, b): (f64, f64), c: f64| c >= a - 1e-9 && c <= b + 1e-9;
        for &iv in &scanned {
            assert!(
                nodes.iter().any(|&c| holds(iv, c) || holds(iv, c + 1.0)),
                "{n} planets: a jump in {iv:?} with no node ({nodes:?})"
            );
        }
        for &c in &nodes {
            assert!(
                scanned.iter().any(|&iv| holds(iv, c) || holds(iv, c + 1.0)),
                "{n} planets: node {c} where no mesh jumps"
            );
        }
        if n == 5 {
            // Sequential phasing: the five planets' meshes jump at distinct times.
            assert!(nodes.len() > 4, "{nodes:?}");
        }
    }
}

#[test]
fn a_contact_set_decided_before_a_jump_holds_at_the_jump() {
    // A step ending on a node decides its pairs at its middle: at the node the decided
    // stiffness is the one just before it (the left limit, continuous within a contact
    // set), the undecided one the one just after.
    let (_, m) = meshes_of(5, 26, 29, 84);
    for c in m.jump_cycles() {
        let c = c + 1.0; // away from 0, where the left limit is the previous cycle's
        for p in 0..m.planets() {
            let left = m.sun_n_per_m(p, c - 1e-9);
            let decided = m.sun_n_per_m_decided(p, c, c - 1e-4);
            // Within the smooth change over 1e-9 cycles (1e-8 of the mean at most).
            assert!((decided - left).abs() < 1e-6 * left, "sun {p} at {c}");
            let left = m.ring_n_per_m(p, c - 1e-9);
            let decided = m.ring_n_per_m_decided(p, c, c - 1e-4);
            assert!((decided - left).abs() < 1e-6 * left, "ring {p} at {c}");
        }
    }
}
