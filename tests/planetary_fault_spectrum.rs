//! The faulty member's teeth of a planetary set under a `[load_spectrum]` (docs/MODEL.md
//! 12.12 and 12.16), checked against independent facts, through `gearwear wear`:
//! - the rule of the spectrum, per tooth: over a block of n input cycles from new teeth,
//!   every tooth of the faulty member gains n c sum_i s_i inc_{t,i} (s_i the bins' shares,
//!   inc_{t,i} its wear per pinion cycle at bin i), so its depth is the share-weighted sum
//!   of the depths the set's own study (no spectrum) gives at each bin's operating point
//!   over the same block: separate runs, each through the constant-load loop;
//! - conservation: the mean over the member's teeth equals the member's mean profile,
//!   which the spectrum's loop advances from the meshes' own rates (another output,
//!   `wear_profiles_MODE.csv`).

mod common;
use common::planetary::run_case_with;
use common::read_csv;
use std::path::Path;

/// A sun tooth cracked 1.5 mm deep on the built-in set (24 / 30 / 84, four planets, sun
/// in, ring fixed), worn one block of 1e4 input cycles from new teeth: the threshold of
/// 100 µm never cuts it, so every run's only block is the same n.
const SET: &str = "[planetary]\n[[planetary.fault]]\nkind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1.5\n[wear]\ntotal_cycles = 10000\nblock_cycles = 10000\nthreshold_um = 100\n";

/// The bins (torque on the sun N m, sun speed Hz, share).
const BINS: [(f64, f64, f64); 2] = [(60.0, 30.0, 0.7), (90.0, 20.0, 0.3)];

const MODES: [&str; 2] = ["dynamic", "quasi_static"];

/// Every column of a CSV as numbers, by name.
fn columns(path: &Path) -> Vec<(String, Vec<f64>)> {
    let (h, rows) = read_csv(path);
    h.into_iter()
        .enumerate()
        .map(|(i, name)| (name, rows.iter().map(|r| r[i].parse().unwrap()).collect()))
        .collect()
}

fn peak(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |a, b| a.max(b.abs()))
}

/// `gearwear wear --mode both` of `text`: its output folder (kept alive with its parent).
fn wear(text: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let (d, _) = run_case_with("wear", text, &["--mode", "both"]);
    let out = d.path().join("out");
    (d, out)
}

#[test]
fn a_faulty_sun_s_teeth_under_a_spectrum_are_the_share_weighted_teeth_of_its_bins() {
    let bins: Vec<String> = BINS
        .iter()
        .map(|(t, f, s)| format!("{{torque_nm = {t}, input_speed_hz = {f}, share = {s}}}"))
        .collect();
    let (_s, spectrum) = wear(&format!(
        "{SET}[load_spectrum]\nbins = [{}]\n",
        bins.join(", ")
    ));
    let alone: Vec<_> = BINS
        .iter()
        .map(|(t, f, _)| {
            wear(&format!(
                "[operating]\nload_torque_nm = {t}\ninput_speed_hz = {f}\n{SET}"
            ))
        })
        .collect();
    for mode in MODES {
        let file = format!("teeth_wear_{mode}.csv");
        let mixed = columns(&spectrum.join(&file));
        let each: Vec<_> = alone.iter().map(|(_, o)| columns(&o.join(&file))).collect();
        let mut teeth = 0;
        for (k, (name, got)) in mixed.iter().enumerate() {
            if !name.contains("_tooth") {
                continue;
            }
            teeth += 1;
            let want: Vec<f64> = (0..got.len())
                .map(|p| {
                    BINS.iter()
                        .zip(&each)
                        .map(|((_, _, s), c)| {
                            assert_eq!(c[k].0, *name);
                            s * c[k].1[p]
                        })
                        .sum()
                })
                .collect();
            // The block's products and the two-term sum round differently in the two
            // paths: a few eps of the depth; 1e-12 of the tooth's peak leaves margin.
            let scale = peak(&want);
            assert!(scale > 0.0, "{mode} {name}: no wear");
            for (a, b) in got.iter().zip(&want) {
                assert!(
                    (a - b).abs() <= 1e-12 * scale,
                    "{mode} {name}: spectrum {a:e}, share-weighted bins {b:e}"
                );
            }
        }
        assert_eq!(teeth, 24, "{mode}: every sun tooth");
        // The bins wear the teeth differently (90 N m against 60 N m), so the sum tests
        // the shares, not a copy of one bin.
        let tooth = |c: &Vec<(String, Vec<f64>)>| {
            peak(&c.iter().find(|x| x.0 == "sun_tooth0_um").unwrap().1)
        };
        assert!(tooth(&each[1]) > 1.2 * tooth(&each[0]), "{mode}");
        // The teeth's mean is the sun's mean profile of the spectrum's run.
        let profiles = columns(&spectrum.join(format!("wear_profiles_{mode}.csv")));
        let sun = &profiles.iter().find(|c| c.0 == "sun_um").unwrap().1;
        let z = teeth as f64;
        for (p, h) in sun.iter().enumerate() {
            let mean: f64 = mixed
                .iter()
                .filter(|c| c.0.contains("_tooth"))
                .map(|c| c.1[p])
                .sum::<f64>()
                / z;
            // The same samples grouped by tooth instead of by period (12.16): the
            // rounding of z-term sums, 1e-12 of the profile's peak.
            assert!(
                (mean - h).abs() <= 1e-12 * peak(sun),
                "{mode} point {p}: teeth's mean {mean:e}, profile {h:e}"
            );
        }
    }
}
