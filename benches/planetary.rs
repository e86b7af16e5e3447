//! Benchmark of a planetary set's dynamic model (issue 31).
//!
//! Run: `cargo bench --bench planetary`. Group `planetary`, the four-planet 24 / 30 / 84
//! set (module 2 mm, sun in at 30 Hz and 60 N m, carrier out, ring fixed) with Lin &
//! Parker's (1999) Table 1 masses and supports (the carrier held by a 1e6 N m/rad shaft),
//! the case's default numerics (200 samples per mesh period, tolerances 1e-5 and 1e-6):
//! - `build_4_planets`: `PlanetaryDynamics::from_case` (geometry, both meshes' tables,
//!   the model);
//! - `steady_state_4_planets`: one cold steady state (from the static equilibrium, 42
//!   states, 4 mesh periods of quasi-Newton shooting to the 1e-6 periodicity and one recorded).

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use gearwear::config::case::Case;
use gearwear::config::planetary::{LumpedPlanetarySection, PlanetarySection};
use gearwear::study::planetary_dynamics::PlanetaryDynamics;

/// Criterion settings for a shared 2-core machine: 10 samples, short warm-up.
fn quick() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(8))
}

/// Lin & Parker (1999) Table 1 with the inertias as I = (I / r^2) r^2.
fn lumped() -> LumpedPlanetarySection {
    let r2 = |mm: f64| (mm * 1e-3_f64).powi(2);
    LumpedPlanetarySection {
        mass_sun_kg: 0.4,
        mass_planet_kg: 0.66,
        mass_ring_kg: 2.35,
        mass_carrier_kg: 5.43,
        inertia_sun_kg_m2: 0.39 * r2(38.7),
        inertia_planet_kg_m2: 0.61 * r2(50.15),
        inertia_ring_kg_m2: 3.0 * r2(137.5),
        inertia_carrier_kg_m2: 6.29 * r2(88.4),
        base_radius_sun_mm: 38.7,
        base_radius_planet_mm: 50.15,
        base_radius_ring_mm: 137.5,
        carrier_radius_mm: 88.4,
        mesh_stiffness_sun_planet_n_per_m: 5e8,
        mesh_stiffness_ring_planet_n_per_m: 5e8,
        bearing_stiffness_sun_n_per_m: 1e8,
        bearing_stiffness_planet_n_per_m: 1e8,
        bearing_stiffness_ring_n_per_m: 1e8,
        bearing_stiffness_carrier_n_per_m: 1e8,
        torsional_stiffness_sun_nm_per_rad: 0.0,
        torsional_stiffness_ring_nm_per_rad: 1e9 * r2(137.5),
        torsional_stiffness_carrier_nm_per_rad: 1e6,
        pressure_angle_deg: 24.6,
    }
}

fn planetary(c: &mut Criterion) {
    let case = Case {
        planetary: Some(PlanetarySection {
            lumped: Some(lumped().into()),
            ..PlanetarySection::default()
        }),
        ..Case::default()
    };
    let built = PlanetaryDynamics::from_case(&case).expect("valid planetary case");
    let mut g = c.benchmark_group("planetary");
    g.bench_function("build_4_planets", |b| {
        b.iter(|| PlanetaryDynamics::from_case(black_box(&case)).unwrap())
    });
    g.bench_function("steady_state_4_planets", |b| {
        b.iter(|| black_box(built.clone()).solve().unwrap())
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = quick();
    targets = planetary
}
criterion_main!(benches);
