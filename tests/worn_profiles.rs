//! The worn tooth profile figures (`worn_profiles_MODE.png` of `wear` and `run`) on the
//! built-in case: each curve's peak is the study's maximum wear depth at that cycle count
//! as its updates table states it, and the wear vanishes at the pitch point, where the
//! flanks roll without sliding (Archard wear is proportional to the sliding distance).

mod common;
use common::paper::paper;

use gearwear::report::wear::{run_tables, wear_artifacts};
use gearwear::report::worn_profile::{shown_records, worn_profile_figures, SHOWN_STATES};

/// Column `name` of `t`.
fn column<'a>(t: &'a gearwear::io::Table, name: &str) -> &'a [f64] {
    &t.columns[t
        .index_of(name)
        .unwrap_or_else(|| panic!("no column {name}"))]
}

#[test]
fn each_curve_peaks_at_the_maximum_wear_of_the_updates_table() {
    let (model, study) = paper();
    let runs = [&study.dynamic, &study.quasi_static];
    let figs = worn_profile_figures(model, &runs);
    assert_eq!(figs.len(), 2);
    for (run, fig) in runs.iter().zip(&figs) {
        let tables = run_tables(model, run);
        let updates = &tables[0].1;
        let (cycles, pinion, gear) = (
            column(updates, "cycles"),
            column(updates, "max_wear_pinion_um"),
            column(updates, "max_wear_gear_um"),
        );
        let shown = shown_records(run);
        // Several cycle counts, the run's last among them.
        assert!(shown.len() >= 3 && shown.len() <= SHOWN_STATES);
        assert_eq!(shown.last().unwrap().wear.cycles, *cycles.last().unwrap());
        for (panel, want) in fig.figure.panels.iter().zip([pinion, gear]) {
            assert_eq!(panel.series.len(), shown.len());
            for (s, r) in panel.series.iter().zip(&shown) {
                let row = cycles.iter().position(|c| *c == r.wear.cycles).unwrap();
                let peak = s.y.iter().fold(0.0_f64, |a, b| a.max(*b));
                // The same number in the same unit: equal up to the rounding of the
                // conversion to µm (1 ulp of ~1 µm, far below the 1e-12 µm allowed).
                assert!(
                    (peak - want[row]).abs() < 1e-12,
                    "{} {peak} {}",
                    fig.stem,
                    want[row]
                );
            }
        }
    }
    // `wear` lists them with their tables, like the study's other figures.
    let a = wear_artifacts(model, &runs);
    for m in ["dynamic", "quasi_static"] {
        let f = a
            .figures
            .iter()
            .find(|f| f.path == format!("worn_profiles_{m}.png"));
        assert_eq!(
            f.and_then(|f| f.data.clone()),
            Some(format!("csv/worn_profiles_{m}.csv"))
        );
    }
}

#[test]
fn wear_vanishes_at_the_pitch_point() {
    let (model, study) = paper();
    let pitch_mm = model.pair.rho_pitch_m * 1e3;
    let h_mm = model.grid.spacing_m * 1e3;
    for fig in worn_profile_figures(model, &[&study.dynamic, &study.quasi_static]) {
        for panel in &fig.figure.panels {
            let s = panel.series.last().unwrap(); // the most worn state
            let peak = s.y.iter().fold(0.0_f64, |a, b| a.max(*b));
            // Sliding speed is proportional to the distance from the pitch point, so the
            // wear at the grid point nearest to it is at most the wear one grid spacing
            // away: bounded by the local slope times h. Its share of the peak is below
            // 2 % on this grid (the peak lies ~5 mm from the pitch point, h ~ 0.1 mm, and
            // the slope near the pitch is below the mean slope to the peak; measured
            // 0.23 % pinion, 0.86 % gear, dynamic study).
            let (i, x) =
                s.x.iter()
                    .enumerate()
                    .min_by(|a, b| (a.1 - pitch_mm).abs().total_cmp(&(b.1 - pitch_mm).abs()))
                    .unwrap();
            assert!((x - pitch_mm).abs() <= h_mm);
            assert!(
                s.y[i] < 0.02 * peak,
                "{} {}: {} of {peak}",
                fig.stem,
                panel.title,
                s.y[i]
            );
            // And the minimum of the profile lies there, within two grid spacings.
            let j = (0..s.y.len())
                .min_by(|a, b| s.y[*a].total_cmp(&s.y[*b]))
                .unwrap();
            assert!(
                (s.x[j] - pitch_mm).abs() <= 2.0 * h_mm,
                "{} at {}",
                fig.stem,
                s.x[j]
            );
        }
    }
}
