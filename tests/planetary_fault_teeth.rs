//! The faulty member's teeth one by one over a planetary set's wear run (docs/MODEL.md
//! 12.16), checked against independent facts:
//! - conservation: at every update the mean over the member's teeth of their accumulated
//!   depths equals the member's mean profile, which the run advances on its own (each
//!   mesh's wear state, `WearState::advance`) from the mean of the fault period's mesh
//!   periods, not from the teeth;
//! - symmetry: a crack of vanishing depth leaves every tooth's depth equal to the others'
//!   (to the crack's relative compliance, computed here from its table);
//! - the physics' direction: a cracked tooth is softer, carries less of the load and wears
//!   less than its member's other teeth;
//! - `run` reports the faulty tooth's deepest wear beside the deepest of the other teeth
//!   in `summary.json` and the report equal to the wear study's per-tooth table, and that
//!   table's mean over the teeth equals the wear study's profile table (another output,
//!   written from the members' states); a checkpoint whose per-tooth wear is removed is
//!   refused on resume.

mod common;

use common::{number_after, read_csv, stderr};
use gearwear::config::load_case;
use gearwear::dynamics::planetary_dynamic::MeshStiffnessSource;
use gearwear::study::planetary_wear::PlanetaryWearModel;
use gearwear::study::planetary_wear_loop::{run_planetary_wear, PlanetaryWearRun};
use gearwear::study::wear_loop::WearMode;

/// The built-in set (24 / 30 / 84, four planets, sun in, ring fixed) with one
/// `[[planetary.fault]]` table of the keys `fault`.
fn text(fault: &str) -> String {
    format!("[planetary]\n[[planetary.fault]]\n{fault}\n")
}

/// A wear run of the set with `fault` in `mode` to `total` input cycles, and its model.
fn run(fault: &str, mode: WearMode, total: f64) -> (PlanetaryWearModel, PlanetaryWearRun) {
    let case = load_case(&text(fault), &[]).unwrap();
    let model = PlanetaryWearModel::from_case(&case).unwrap();
    let wear = gearwear::config::case::WearSection {
        total_cycles: total,
        ..case.wear.clone()
    };
    let r =
        run_planetary_wear(&model, &wear, PlanetaryWearRun::new(mode), &mut |_| Ok(())).unwrap();
    assert!(r.updates.len() >= 3, "{} updates", r.updates.len());
    (model, r)
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |a, b| a.max(b.abs()))
}

/// At every update, the mean over the teeth of each flank of the faulty member equals
/// that flank's mean profile (`PlanetaryUpdate::flanks`, from the meshes' wear states).
fn assert_conserved(model: &PlanetaryWearModel, run: &PlanetaryWearRun, what: &str) {
    for k in 1..run.updates.len() {
        let upto = PlanetaryWearRun {
            updates: run.updates[..=k].to_vec(),
            ..run.clone()
        };
        let teeth = upto.faulty_teeth(model).unwrap();
        let flanks = run.updates[k].flanks(model);
        for (flank, profiles) in &teeth.flanks {
            let f = flanks
                .iter()
                .find(|f| f.member == teeth.member && f.flank == *flank)
                .unwrap();
            let z = profiles.len() as f64;
            let mean: Vec<f64> = (0..f.depth_m.len())
                .map(|i| profiles.iter().map(|p| p[i]).sum::<f64>() / z)
                .collect();
            let d = mean
                .iter()
                .zip(&f.depth_m)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            // Each update's mean over the teeth equals the mesh increment to the rounding
            // of its sums (z terms, 1e-12 in tests/planetary_fault_wear.rs); the depths are
            // sums of positive block terms, so the relative rounding does not grow.
            assert!(
                d <= 1e-12 * max_abs(&f.depth_m),
                "{what}, update {k}, {flank}: {d:e} of {:e}",
                max_abs(&f.depth_m)
            );
            assert!(max_abs(&f.depth_m) > 0.0, "{what}: the flank wears");
        }
    }
}

#[test]
fn the_teeths_depths_sum_to_the_members_wear_at_every_update() {
    for (fault, mode) in [
        (
            "kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1.5",
            WearMode::Dynamic,
        ),
        (
            "kind = \"crack\"\ngear = \"planet\"\nplanet = 2\ntooth = 7\ncrack_depth_mm = 1.5",
            WearMode::QuasiStatic,
        ),
        (
            "kind = \"crack\"\ngear = \"ring\"\ntooth = 5\ncrack_depth_mm = 1.0",
            WearMode::QuasiStatic,
        ),
    ] {
        let (model, r) = run(fault, mode, 2e4);
        assert_conserved(&model, &r, fault);
    }
}

#[test]
fn a_cracked_tooth_wears_less_and_a_vanishing_crack_leaves_the_teeth_alike() {
    for mode in [WearMode::QuasiStatic, WearMode::Dynamic] {
        let (model, r) = run(
            "kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1.5",
            mode,
            2e4,
        );
        let t = r.faulty_teeth(&model).unwrap();
        let (_, profiles) = &t.flanks[0];
        let own = max_abs(&profiles[2]);
        let others = profiles
            .iter()
            .enumerate()
            .filter(|(k, _)| *k != 2)
            .map(|(_, p)| max_abs(p))
            .fold(0.0, f64::max);
        // The crack's compliance in series lowers its pairs' stiffness: they carry less
        // of the mesh force (pair_loads splits it by stiffness), so the tooth wears less.
        assert!(own < others, "{mode:?}: cracked {own:e}, others {others:e}");
    }
    let (model, r) = run(
        "kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1e-4",
        WearMode::QuasiStatic,
        2e4,
    );
    let MeshStiffnessSource::Tables(m) = &model.dynamics.model.source else {
        panic!("tables")
    };
    // The crack's relative compliance delta = c k: its pairs' loads, and their Archard
    // wear, differ from the others' by about delta (as tests/planetary_fault_wear.rs).
    let delta = max_abs(m.fault().unwrap().sun_m_per_n.as_ref().unwrap()) * m.mean_n_per_m()[0];
    let t = r.faulty_teeth(&model).unwrap();
    let (_, profiles) = &t.flanks[0];
    let scale = profiles.iter().map(|p| max_abs(p)).fold(0.0, f64::max);
    for (k, p) in profiles.iter().enumerate() {
        let d = p
            .iter()
            .zip(&profiles[2])
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        // Four times delta as the healthy-set comparison; the quasi-static loads have no
        // steady-state residual, only rounding (1e-12).
        assert!(
            d <= (4.0 * delta + 1e-12) * scale,
            "tooth {k}: {d:e} of {scale:e} (delta {delta:e})"
        );
    }
}

/// Column `name`'s values in a table.
fn column(names: &[String], rows: &[Vec<String>], name: &str) -> Vec<f64> {
    let i = names.iter().position(|n| n == name).unwrap();
    rows.iter().map(|r| r[i].parse().unwrap()).collect()
}

#[test]
fn run_reports_the_faulty_tooth_beside_the_others_and_resume_checks_the_teeth() {
    let d = tempfile::tempdir().unwrap();
    let path = d.path().join("case.toml");
    std::fs::write(
        &path,
        text("kind = \"crack\"\ngear = \"sun\"\ntooth = 2\ncrack_depth_mm = 1.5"),
    )
    .unwrap();
    let out = d.path().join("out");
    let args: Vec<String> = [
        "run",
        "-q",
        "--config",
        path.to_str().unwrap(),
        "--set",
        "wear.total_cycles=2e4",
        "--out",
        out.to_str().unwrap(),
    ]
    .map(String::from)
    .to_vec();
    let o = common::resume::run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let f = &summary["planetary_run"]["faulty_tooth"];
    assert_eq!(f["member"], "sun");
    assert_eq!(f["tooth"], 2);
    assert_eq!(f["kind"], "crack");
    let report = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(report.contains("Fault: crack on sun tooth 2."), "{report}");
    for (mode, label) in [("dynamic", "dynamic"), ("quasi_static", "quasi-static")] {
        let (names, rows) = read_csv(&out.join(format!("wear/teeth_wear_{mode}.csv")));
        let teeth: Vec<Vec<f64>> = (0..24)
            .map(|t| column(&names, &rows, &format!("sun_tooth{t}_um")))
            .collect();
        let own = max_abs(&teeth[2]);
        let others = (0..24)
            .filter(|t| *t != 2)
            .map(|t| max_abs(&teeth[t]))
            .fold(0.0, f64::max);
        let v = &f["final"][mode]["sun"];
        // The summary holds the doubles the table prints (shortest round trip each).
        assert_eq!(v["tooth_max_wear_um"].as_f64().unwrap(), own, "{mode}");
        assert_eq!(v["other_teeth_max_wear_um"].as_f64().unwrap(), others);
        let line = format!("{label}: the deepest wear of sun tooth 2 is ");
        let shown = number_after(&report, &line);
        // Shown to 4 significant digits: within half a unit of the fourth.
        assert!((shown / own - 1.0).abs() < 1e-3, "{shown} vs {own}");
        let i = report.find(&line).unwrap();
        let shown_others = number_after(&report[i..], "other teeth ");
        assert!((shown_others / others - 1.0).abs() < 1e-3);
        // The teeth's mean against the profiles table, written from the meshes' states.
        let (pn, pr) = read_csv(&out.join(format!("wear/wear_profiles_{mode}.csv")));
        let sun = column(&pn, &pr, "sun_um");
        for (i, s) in sun.iter().enumerate() {
            let mean = teeth.iter().map(|t| t[i]).sum::<f64>() / 24.0;
            // Both tables print shortest round-trip doubles; the two sums agree to 1e-12.
            assert!((mean - s).abs() <= 1e-12 * max_abs(&sun), "{mode} {i}");
        }
    }
    // A sun mesh's record without its teeth's increments (checksum recomputed) is
    // refused on resume, naming what is missing.
    let log = out.join("checkpoint_dynamic_sun_planet_1.jsonl");
    common::resume::edit_update(&log, 1, true, &|v| {
        v.as_object_mut().unwrap().remove("increment_teeth");
    });
    common::resume::refused(&args, "teeth removed", &["per-tooth", "sun_planet_1"]);
}
