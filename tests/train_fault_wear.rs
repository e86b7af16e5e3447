//! `gearwear wear` on a gear train with a tooth fault on one stage (`fault.stage`,
//! docs/MODEL.md 9.10): the faulty stage worn tooth by tooth over the train's excitation
//! period, the others as before. Checked against the single pair with the same fault (a
//! one-stage train, and a second stage that cannot move), the count of contacts of each
//! tooth computed here from the tooth numbers, a healthy train's wear, and the summaries
//! read back against the case.

mod common;
use common::train::{model, neglected_compliance, reflected_pair, stiff_second_stage, TWO_STAGE};
use common::{read_csv, run_into};
use gearwear::study::train_wear::{next_block, next_train_update, TrainNext, TrainUpdate};
use gearwear::study::wear_loop::{next_update, Next, UpdateRecord, WearMode};
use gearwear::study::Model;
use std::path::Path;

/// A `[[fault]]` table: a crack `depth_mm` deep on tooth `tooth` of `gear` ("pinion" or
/// "gear"), on stage `stage` (None: a single pair's table, without the key).
fn crack(stage: Option<usize>, gear: &str, tooth: usize, depth_mm: f64) -> String {
    let stage = stage.map_or(String::new(), |s| format!("stage = {s}\n"));
    format!(
        "\n[[fault]]\nkind = \"crack\"\n{stage}gear = \"{gear}\"\ntooth = {tooth}\ncrack_depth_mm = {depth_mm}\n"
    )
}

/// The first update (new teeth) of `m`'s train in `mode`.
fn first_update(m: &Model, mode: WearMode) -> TrainUpdate {
    let t = m.train.as_ref().unwrap();
    match next_train_update(m, t, mode, None).unwrap() {
        TrainNext::Update(u) => *u,
        other => panic!("{other:?}"),
    }
}

/// The first record (new teeth) of the single pair `m` in `mode`.
fn first_record(m: &Model, mode: WearMode) -> UpdateRecord {
    match next_update(m, mode, None).unwrap() {
        Next::Record(r) => *r,
        other => panic!("{other:?}"),
    }
}

/// Largest entry of a profile, m.
fn peak(p: &[f64]) -> f64 {
    p.iter().fold(0.0, |a, b| a.max(*b))
}

/// Largest |a - b| over two lists of profiles, m.
fn largest_difference(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    a.iter()
        .zip(b)
        .flat_map(|(x, y)| x.iter().zip(y).map(|(u, v)| (u - v).abs()))
        .fold(0.0, f64::max)
}

/// The profiles without their end points (the ends of the path of contact).
fn inner(p: &[Vec<f64>]) -> Vec<Vec<f64>> {
    p.iter().map(|v| v[1..v.len() - 1].to_vec()).collect()
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

fn summary(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

#[test]
fn a_one_stage_train_with_a_fault_wears_as_the_single_pair_with_it_byte_for_byte() {
    // The paper's pair with a 1.5 mm crack on gear tooth 4, alone and as a one-stage
    // train (the same fault, `fault.stage` = 1), both modes to 2e4 cycles: one mesh, one
    // cycle factor of exactly 1, one base period = one mesh period, so the train's
    // stage has the pair's excitation period (31 mesh periods) and every tooth the
    // pair's engagements: the same updates, mean profiles and per-tooth wear, byte for
    // byte. Both summaries state the fault as the case gives it.
    let d = tempfile::tempdir().unwrap();
    let pair = write(d.path(), "pair.toml", &crack(None, "gear", 4, 1.5));
    let train = write(
        d.path(),
        "train.toml",
        &format!("[[stage]]\n{}", crack(Some(1), "gear", 4, 1.5)),
    );
    let total = ["wear.total_cycles=20000"];
    let args = ["wear", "--mode", "both"];
    let a = run_into(d.path(), "pair", &args, Some(&pair), &total);
    let b = run_into(d.path(), "train", &args, Some(&train), &total);
    for mode in ["dynamic", "quasi_static"] {
        for (x, y) in [
            (
                format!("updates_{mode}.csv"),
                format!("updates_{mode}_stage1.csv"),
            ),
            (
                format!("wear_profiles_{mode}.csv"),
                format!("wear_profiles_{mode}_stage1.csv"),
            ),
            (
                format!("csv/teeth_wear_{mode}.csv"),
                format!("csv/teeth_wear_{mode}_stage1.csv"),
            ),
        ] {
            assert_eq!(
                std::fs::read(a.join(&x)).unwrap(),
                std::fs::read(b.join(&y)).unwrap(),
                "{x} vs {y}"
            );
        }
        assert!(b.join(format!("teeth_wear_{mode}_stage1.png")).exists());
    }
    // The faults modelled, read back against the case: the pair's under `teeth`, the
    // train's with its stage.
    let want =
        serde_json::json!({"kind": "crack", "gear": "gear", "tooth": 4, "crack_depth_mm": 1.5});
    assert_eq!(summary(&a)["teeth"]["faults"], serde_json::json!([want]));
    let mut staged = want.clone();
    staged["stage"] = serde_json::json!(1);
    let sb = summary(&b);
    assert_eq!(sb["faults"], serde_json::json!([staged]));
    assert_eq!(sb["meshes"][0]["per_tooth_wear"], true);
}

#[test]
fn a_second_stage_that_cannot_move_wears_stage_one_as_the_single_pair_with_the_fault() {
    // tests/train_fault.rs's limit (stage 2 of module 20 mm, 1900 mm wide, bearings at
    // 1e12 N/m, the shaft at 1e10 N m/rad, the schema's maximum) with a 1.5 mm crack on
    // stage 1's gear tooth 0, against the first pair alone with stage 2 reflected as
    // rigid inertia and the same crack: each tooth's Archard wear per cycle of new
    // teeth, dynamic. Per pass h = k p0 s, p0 ~ sqrt(w) and s ~ a ~ sqrt(w) (Hertz), so
    // h is linear in the pair load w and differs as the loads do: the dynamic force
    // differs by at most 3 x the neglected compliance eps of its peak-to-peak
    // (tests/train_fault.rs), so each tooth's wear by at most 3 eps (F_pp / F_min) of the
    // peak wear rate (the load ratio at the lightest point of the force). A tooth's wear
    // is read from its one pass, sampled at the train's nodes (both meshes' events),
    // which the pair's are not: the path's linear interpolation across the load's jumps
    // errs to first order in the node spacing, so by about twice its change when the
    // train's steps are doubled (delta, measured here); 3 delta allows for the pair's
    // own error. The crack's own effect on its tooth's wear is far larger (checked, so
    // that the comparison can fail).
    let text = format!(
        "{}{}",
        stiff_second_stage(1900.0),
        crack(Some(1), "gear", 0, 1.5)
    );
    let sets = ["friction.model=none", "contact.path=nominal"];
    let train = model(&text, &sets);
    let fine = model(
        &text,
        &[sets[0], sets[1], "numerics.steps_per_mesh_period=400"],
    );
    let fault = [
        "fault.kind=crack",
        "fault.gear=gear",
        "fault.tooth=0",
        "fault.crack_depth_mm=1.5",
    ];
    let pair = reflected_pair(&train, &fault);
    let eps = neglected_compliance(&train);
    let u = first_update(&train, WearMode::Dynamic);
    let v = first_update(&fine, WearMode::Dynamic);
    let r = first_record(&pair, WearMode::Dynamic);
    let (a, b, f) = (
        u.meshes[0].increment_teeth.as_ref().unwrap(),
        r.increment_teeth.as_ref().unwrap(),
        v.meshes[0].increment_teeth.as_ref().unwrap(),
    );
    let scale = b
        .gear_m
        .iter()
        .chain(&b.pinion_m)
        .map(|p| peak(p))
        .fold(0.0, f64::max);
    // Inside the path: at its two ends the wear is read from the sample nearest the
    // end, which the train's nodes (stage 2's events among them) and the pair's place
    // differently (measured: 1.3e-3 of the peak at the gear's last point, every tooth
    // alike; 1.3e-6 between the train's own steps and twice them).
    let both = |x: &gearwear::wear::ToothWear, y: &gearwear::wear::ToothWear| {
        let g = largest_difference(&inner(&x.gear_m), &inner(&y.gear_m));
        g.max(largest_difference(&inner(&x.pinion_m), &inner(&y.pinion_m))) / scale
    };
    let (diff, delta) = (both(a, b), both(a, f));
    let s = &r.summary;
    let load = 3.0 * eps * (s.mesh_force_max_n - s.mesh_force_min_n) / s.mesh_force_min_n;
    let bound = load + 3.0 * delta;
    // The cracked tooth against a healthy one of the same gear, far from it (tooth 15).
    let crack_effect = largest_difference(&b.gear_m[0..1], &b.gear_m[15..16]) / scale;
    println!("neglected {eps:.2e}: wear difference {diff:.2e}, bound {bound:.2e} (load {load:.2e}, nodes {delta:.2e}), crack effect {crack_effect:.2e}");
    assert!(diff < bound, "difference {diff:e} beyond {bound:e}");
    assert!(crack_effect > 5.0 * bound, "crack effect {crack_effect:e}");
}

/// The reducer of tests/common/train.rs with a 2 mm crack on stage 1's gear tooth 0
/// (z = 31, so the train repeats every base period: one turn of the intermediate
/// shaft), or healthy.
fn reducer(fault: bool, sets: &[&str]) -> Model {
    let extra = if fault {
        crack(Some(1), "gear", 0, 2.0)
    } else {
        String::new()
    };
    model(&format!("{TWO_STAGE}{extra}"), sets)
}

#[test]
fn healthy_teeth_of_the_faulty_gear_wear_by_their_count_of_contacts_and_the_cracked_one_differs() {
    // Quasi-statically each mesh carries its shaft's torque alone, and a tooth pair's
    // load depends only on the pairs in contact with it. Stage 1 (19/31, contact ratio
    // below 2) puts gear tooth b in contact with teeth b - 1 and b + 1 only, so teeth 2
    // to 29 of the cracked gear (tooth 0) meet the healthy train's loads exactly. Over a
    // block of n input cycles each gear tooth makes n z_p1 / z_g1 contacts (the turns of
    // the intermediate shaft, counted here from the teeth), each wearing it by the
    // healthy train's wear per contact: its gear wear per pinion cycle times z_g1 / z_p1
    // (eq. 17's share per pinion cycle). Every pinion tooth meets every gear tooth
    // (19 and 31 coprime), so the pinion's teeth wear alike, bit for bit.
    //
    // Tooth b's wear is read from its one pass, sampled at the nodes of the base period
    // (both meshes' events), the healthy train's from all 31 passes merged: the path's
    // linear interpolation across the load's jumps errs to first order in the node
    // spacing, so by about twice its change when the steps are doubled (delta, measured
    // here on the faulty train; 3 delta allows for the healthy train's own error).
    // One block of 1e4 input cycles, never cut by the threshold.
    let one = ["wear.block_cycles=1e4", "wear.threshold_um=1e6"];
    let (faulty, healthy) = (reducer(true, &one), reducer(false, &one));
    let fine = reducer(
        true,
        &[one[0], one[1], "numerics.steps_per_mesh_period=400"],
    );
    let mode = WearMode::QuasiStatic;
    let u = first_update(&faulty, mode);
    let h = first_update(&healthy, mode);
    let t = faulty.train.as_ref().unwrap();
    let block = next_block(&faulty, t, &u).unwrap();
    let fine_block = next_block(
        &fine,
        fine.train.as_ref().unwrap(),
        &first_update(&fine, mode),
    )
    .unwrap();
    let n = block.input_cycles;
    assert_eq!(fine_block.input_cycles, n);
    let (zp, zg) = (19.0, 31.0);
    let contacts = n * zp / zg;
    let per_contact: Vec<f64> = h.meshes[0]
        .increment_gear_m
        .iter()
        .map(|x| x * zg / zp)
        .collect();
    let worn = block.wears[0].teeth.as_ref().unwrap();
    let worn_fine = fine_block.wears[0].teeth.as_ref().unwrap();
    let scale = peak(&per_contact) * contacts;
    let far = 2..=29;
    let mut worst: f64 = 0.0;
    for b in far.clone() {
        for (w, c) in worn.gear_m[b].iter().zip(&per_contact) {
            worst = worst.max((w - contacts * c).abs());
        }
    }
    let delta = largest_difference(&worn.gear_m[2..30], &worn_fine.gear_m[2..30]) / scale;
    let worst = worst / scale;
    println!("healthy gear teeth: largest difference {worst:.2e} of the peak, delta {delta:.2e}");
    assert!(worst <= 3.0 * delta, "{worst:e} vs 3 x {delta:e}");
    let first = &worn.pinion_m[0];
    assert!(worn.pinion_m.iter().all(|p| p == first));
    // The cracked tooth: softer, it carries less of the load where two pairs share it,
    // and its neighbours more; its wear differs from theirs and from the healthy count,
    // by more than the nodes' error.
    let rel = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
            / scale
    };
    let healthy_wear: Vec<f64> = per_contact.iter().map(|c| c * contacts).collect();
    let g = &worn.gear_m;
    let against = [
        ("tooth 30", rel(&g[0], &g[30])),
        ("tooth 1", rel(&g[0], &g[1])),
        ("the count of contacts", rel(&g[0], &healthy_wear)),
    ];
    println!(
        "quasi-static, after {contacts:.0} contacts: peak wear of the cracked tooth {:.4} um, of teeth 30 and 1 {:.4}, {:.4}, by the count {:.4}; differences {against:?}",
        peak(&g[0]) * 1e6,
        peak(&g[30]) * 1e6,
        peak(&g[1]) * 1e6,
        peak(&healthy_wear) * 1e6
    );
    for (what, d) in against {
        assert!(d > 3.0 * delta, "cracked tooth against {what}: {d:e}");
    }
    let dy = first_update(&faulty, WearMode::Dynamic);
    let inc = dy.meshes[0].increment_teeth.as_ref().unwrap();
    let peaks: Vec<f64> = inc.gear_m.iter().map(|p| peak(p) * 1e9).collect();
    println!("dynamic, new teeth: wear rate of the gear's teeth, um per 1000 cycles: {peaks:.4?}");
}

#[test]
fn the_healthy_stage_of_a_faulty_train_wears_one_profile_as_in_the_healthy_train() {
    // A crack on stage 1's pinion (z = 19): the train repeats over 19 base periods, and
    // stage 2 is not tooth-resolved: its wear is one profile for every tooth (no
    // per-tooth state, no per-tooth output). Quasi-statically it carries its shaft's
    // torque whatever stage 1's teeth are, so its wear per cycle is the healthy
    // train's: the same path sampled at the same nodes of each base period.
    let faulty = model(
        &format!("{TWO_STAGE}{}", crack(Some(1), "pinion", 0, 2.0)),
        &[],
    );
    let healthy = reducer(false, &[]);
    let mode = WearMode::QuasiStatic;
    let u = first_update(&faulty, mode);
    let h = first_update(&healthy, mode);
    let s2 = &u.meshes[1];
    assert!(s2.wear.teeth.is_none() && s2.increment_teeth.is_none());
    assert!(u.meshes[0].wear.teeth.is_some());
    let t = faulty.train.as_ref().unwrap();
    let block = next_block(&faulty, t, &u).unwrap();
    assert!(block.wears[1].teeth.is_none());
    let diff = largest_difference(
        &[s2.increment_pinion_m.clone(), s2.increment_gear_m.clone()],
        &[
            h.meshes[1].increment_pinion_m.clone(),
            h.meshes[1].increment_gear_m.clone(),
        ],
    ) / peak(&h.meshes[1].increment_pinion_m);
    println!("stage 2 against the healthy train's: {diff:.2e}");
    assert!(diff <= 1e-9, "{diff:e}");
}

#[test]
fn the_train_states_the_faults_it_modelled_in_its_summaries() {
    // `dynamics` and `wear` of the reducer with a crack on stage 2's pinion tooth 3 and
    // a zero-depth crack on stage 1 (which changes no tooth, so it is not modelled):
    // `faults` lists the first as the case gives it.
    let d = tempfile::tempdir().unwrap();
    let text = format!(
        "{TWO_STAGE}{}{}",
        crack(Some(2), "pinion", 3, 1.0),
        crack(Some(1), "gear", 5, 0.0)
    );
    let case = write(d.path(), "c.toml", &text);
    let want = serde_json::json!([{"kind": "crack", "stage": 2, "gear": "pinion", "tooth": 3, "crack_depth_mm": 1.0}]);
    let dy = run_into(d.path(), "dyn", &["dynamics"], Some(&case), &[]);
    assert_eq!(summary(&dy)["faults"], want);
    let w = run_into(
        d.path(),
        "wear",
        &["wear", "--mode", "quasi-static"],
        Some(&case),
        &["wear.total_cycles=1e4"],
    );
    let sw = summary(&w);
    assert_eq!(sw["faults"], want);
    assert_eq!(sw["meshes"][0]["per_tooth_wear"], false);
    assert_eq!(sw["meshes"][1]["per_tooth_wear"], true);
    // The healthy stage has no per-tooth output; the faulty one the pair's columns.
    assert!(!w.join("csv/teeth_wear_quasi_static_stage1.csv").exists());
    let (h, _) = read_csv(&w.join("csv/teeth_wear_quasi_static_stage2.csv"));
    assert!(
        h.contains(&"pinion_tooth22_um".to_string()) && h.contains(&"gear_tooth46_um".to_string())
    );
    // A healthy train states none.
    let healthy = write(d.path(), "h.toml", TWO_STAGE);
    let hd = run_into(d.path(), "hdyn", &["dynamics"], Some(&healthy), &[]);
    assert!(summary(&hd).get("faults").is_none());
}
