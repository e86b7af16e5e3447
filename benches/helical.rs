//! Benchmarks of the helical pair's slice model (issue 30, stiffness part).
//!
//! Run: `cargo bench --bench helical`. Group `helical`, the built-in pair's normal section
//! with beta = 15 deg (right hand), 400 table points per slice, fillet foundation on:
//! - `slice_model_build_20`: `SliceMeshStiffness::new` with N = 20 slices (one slice
//!   table of 400 points, the spur pair's work, and the slice offsets);
//! - `slice_table_20_x_400`: the mesh-stiffness table over one mesh period at 400 phases
//!   (stiffness, centre of pressure, contacts) from the built model;
//! - `continuous_table_400`: the N -> infinity limit at the same 400 phases;
//! - `spur_mesh_table_400`: `MeshStiffness::with_fillet` of the beta = 0 pair, for scale.
//!
//! Group `helical_dynamics` (issue 30 target: a helical pair's cold steady state under 5x
//! the spur pair's of the same transverse geometry), the same pair with the default
//! N = 400 slices, new teeth, default numerics:
//! - `steady_state_helical_400`: `Model::dynamic` from the static equilibrium (cold);
//! - `steady_state_spur_transverse`: the same for the spur pair of its transverse section
//!   (`geometry::helical::transverse_section`), also on the nominal path with the load
//!   shared by compression, as the helical model runs;
//! - `model_build_helical_400`: `Model::helical_from_case` (slice model and line table);
//! - `steady_state_helical_400_crowned`, `model_build_helical_400_crowned`: the same with
//!   a crowning of 8 um (`modification.crowning_um`): each contact line's force from its
//!   slices through the tabulated piecewise-linear force (`stiffness::helical_lead`), and
//!   the build with that table and the static face load solve;
//! - `face_load_direct_crowned`: `DynamicFaceLoad::of` on the crowned steady state: every
//!   recorded sample's contact lines summed slice by slice (N spline evaluations per line),
//!   the work the direct evaluation of the slices would do in every right-hand side (its
//!   cost per sample times the steady state's right-hand sides estimates that choice);
//! - `steady_state_helical_400_axial`: the helical pair with axial bearings of 5e8 N/m on
//!   pinion and gear (docs/MODEL.md 11.6: 10 coordinates, the general right-hand side
//!   instead of the fixed 8-coordinate one), cold, against `steady_state_helical_400`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use gearwear::config::case::{Case, ContactPathModel, LoadSharingModel};
use gearwear::dynamics::excitation::ExternalError;
use gearwear::geometry::helical::{transverse_section, Hand, HelicalPair, HelixSpec};
use gearwear::geometry::GearPair;
use gearwear::stiffness::helical::SliceMeshStiffness;
use gearwear::stiffness::mesh::{FilletSettings, MeshStiffness};
use gearwear::stiffness::potential_energy::ElasticPair;
use gearwear::study::face_load_dynamic::DynamicFaceLoad;
use gearwear::study::Model;
use gearwear::wear::WearState;

/// Criterion settings for a shared 2-core machine: 10 samples, short warm-up.
fn quick() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

fn helical(c: &mut Criterion) {
    let case = Case::default();
    let helix = HelixSpec {
        helix_angle_deg: 15.0,
        hand_pinion: Hand::Right,
    };
    let pair = HelicalPair::from_case(&case.gear, &helix).expect("valid helical pair");
    let elastic = ElasticPair::from_case(&case.materials);
    let points = case.stiffness.table_points_per_mesh_period as usize;
    let fillet = FilletSettings::from_case(&case.stiffness);
    let model =
        SliceMeshStiffness::new(&pair, &elastic, 20, points, fillet).expect("valid slice model");
    let period = pair.transverse.mesh_angle_rad();
    let mut g = c.benchmark_group("helical");
    g.bench_function("slice_model_build_20", |b| {
        b.iter(|| SliceMeshStiffness::new(black_box(&pair), &elastic, 20, points, fillet).unwrap())
    });
    g.bench_function("slice_table_20_x_400", |b| {
        b.iter(|| black_box(&model).table(400))
    });
    g.bench_function("continuous_table_400", |b| {
        b.iter(|| {
            (0..400)
                .map(|i| black_box(&model).continuous_stiffness_n_per_m(period * i as f64 / 400.0))
                .sum::<f64>()
        })
    });
    let spur = GearPair::from_case(&case.gear).expect("paper's pair");
    g.bench_function("spur_mesh_table_400", |b| {
        b.iter(|| MeshStiffness::with_fillet(black_box(&spur), &elastic, points, fillet).unwrap())
    });
    g.finish();
}

fn helical_dynamics(c: &mut Criterion) {
    let mut case = Case::default();
    case.gear.helix_angle_deg = 15.0;
    let helical = Model::helical_from_case(&case).expect("valid helical model");
    let mut spur_case = case.clone();
    spur_case.gear = transverse_section(&case.gear, 15f64.to_radians());
    spur_case.gear.helix_angle_deg = 0.0;
    spur_case.contact.path = ContactPathModel::Nominal;
    spur_case.contact.load_sharing = LoadSharingModel::Stiffness;
    let spur = Model::from_case(&spur_case).expect("valid spur model");
    let mut crowned_case = case.clone();
    crowned_case.modification.crowning_um = Some(8.0);
    let crowned = Model::helical_from_case(&crowned_case).expect("valid crowned model");
    let mut axial_case = case.clone();
    axial_case.dynamics.bearing_axial_stiffness_pinion_n_per_m = Some(5e8);
    axial_case.dynamics.bearing_axial_stiffness_gear_n_per_m = Some(5e8);
    let axial = Model::helical_from_case(&axial_case).expect("valid axial model");
    let run = |m: &Model| {
        m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
            .expect("steady state")
    };
    for (name, m) in [
        ("helical", &helical),
        ("spur", &spur),
        ("crowned", &crowned),
        ("axial", &axial),
    ] {
        let r = run(m);
        eprintln!(
            "{name}: {} steps, {} rhs, {} LU, {} periods",
            r.steps, r.rhs_evaluations, r.factorizations, r.periods_to_converge
        );
    }
    let mut g = c.benchmark_group("helical_dynamics");
    g.bench_function("steady_state_helical_400", |b| {
        b.iter(|| run(black_box(&helical)))
    });
    g.bench_function("steady_state_spur_transverse", |b| {
        b.iter(|| run(black_box(&spur)))
    });
    g.bench_function("steady_state_helical_400_axial", |b| {
        b.iter(|| run(black_box(&axial)))
    });
    g.bench_function("model_build_helical_400", |b| {
        b.iter(|| Model::helical_from_case(black_box(&case)).unwrap())
    });
    g.bench_function("steady_state_helical_400_crowned", |b| {
        b.iter(|| run(black_box(&crowned)))
    });
    let r = run(&crowned);
    eprintln!("crowned: {} samples", r.signals.time_s.len());
    g.bench_function("face_load_direct_crowned", |b| {
        b.iter(|| DynamicFaceLoad::of(black_box(&crowned), &r, &ExternalError::none()))
    });
    g.bench_function("model_build_helical_400_crowned", |b| {
        b.iter(|| Model::helical_from_case(black_box(&crowned_case)).unwrap())
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = quick();
    targets = helical, helical_dynamics
}
criterion_main!(benches);
