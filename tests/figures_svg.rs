//! The real figures, read back from their SVG as a reader reads them: the axis scale from
//! the tick labels' text and positions, the data from the stroked segments. Fig. 8 (mesh
//! force) of the built-in case and the mesh force of a contact-loss case: no drawn segment
//! leaves the range of the plotted data.

mod common;
use common::figures::attr;
use common::paper::paper;

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::report::artifacts::{plot_height, PLOT_W};
use gearwear::report::dynamics::dynamics_artifacts;
use gearwear::report::paper::section41_figures;
use gearwear::report::plot::{layout, render_svg, Figure};
use gearwear::study::Model;
use gearwear::wear::WearState;

/// A stroked `<polyline>`: its colour ("#RRGGBB"), stroke width and points in pixels.
struct Stroke {
    color: String,
    width: f64,
    points: Vec<(f64, f64)>,
}

fn strokes(svg: &str) -> Vec<Stroke> {
    svg.split("<polyline")
        .skip(1)
        .filter_map(|t| {
            let points = attr(t, "points")?
                .split_whitespace()
                .filter_map(|p| {
                    let (x, y) = p.split_once(',')?;
                    Some((x.parse().ok()?, y.parse().ok()?))
                })
                .collect();
            Some(Stroke {
                color: attr(t, "stroke")?.to_string(),
                width: attr(t, "stroke-width")?.parse().ok()?,
                points,
            })
        })
        .collect()
}

/// The numeric tick labels of the y axis: (pixel y of the label's anchor, value). plotters
/// writes them right-aligned (`text-anchor="end"`), anchored on the tick's pixel row.
fn y_ticks(svg: &str) -> Vec<(f64, f64)> {
    svg.split("<text")
        .skip(1)
        .filter(|t| attr(t, "text-anchor") == Some("end"))
        .filter_map(|t| {
            let text = t.split_once('>')?.1.split("</text>").next()?.trim();
            Some((attr(t, "y")?.parse().ok()?, text.parse().ok()?))
        })
        .collect()
}

/// The y axis as the tick labels show it: value = a + b * pixel_y, fitted through the two
/// outermost labels; every other label must lie on it to within 1 px (their positions are
/// whole pixels), or the scale is not linear and the test cannot read it.
fn y_scale(svg: &str) -> (f64, f64) {
    let ticks = y_ticks(svg);
    assert!(ticks.len() >= 3, "too few y tick labels: {ticks:?}");
    let (lo, hi) = (ticks[0], ticks[ticks.len() - 1]);
    let b = (hi.1 - lo.1) / (hi.0 - lo.0);
    let a = lo.1 - b * lo.0;
    for (py, v) in &ticks {
        assert!(
            ((v - a) / b - py).abs() <= 1.0,
            "tick {v} at {py} px off the scale"
        );
    }
    (a, b)
}

/// Stroke of one drawn curve: 2 px (`draw.rs`); axes, grid and markers are 1 px.
const CURVE_STROKE_PX: f64 = 2.0;

/// Tolerance in pixels: plotters rounds each data point to a whole pixel (0.5 px) and the
/// tick labels are anchored on whole pixels (0.5 px more on the fitted scale); a segment
/// past the data by one pixel or more (the reported spikes ran hundreds of pixels) fails.
const TOL_PX: f64 = 1.0;

/// Checks from the SVG of `fig` (one panel) that every stroked piece of every curve is a
/// single straight segment (no join, so no miter spike however the renderer draws it)
/// with both ends inside [min, max] of the plotted y data, and that the curves reach the
/// data's extremes (the scale is read right). Returns the number of pieces checked.
fn assert_curves_within_data(fig: &Figure, what: &str) -> usize {
    let (w, h) = (PLOT_W, plot_height(fig.panels.len()));
    let svg = render_svg(fig, w, h).expect("renders");
    let lay = layout(fig, w, h).expect("lays out");
    let legend = lay[0].legend.unwrap_or_default();
    let (a, b) = y_scale(&svg);
    let ys: Vec<f64> = fig.panels[0]
        .series
        .iter()
        .flat_map(|s| s.y.clone())
        .collect();
    let (lo, hi) = ys
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), y| {
            (l.min(*y), h.max(*y))
        });
    let tol = TOL_PX * b.abs();
    let in_legend = |p: &(f64, f64)| legend.contains((p.0 as i32, p.1 as i32));
    let curves: Vec<Stroke> = strokes(&svg)
        .into_iter()
        .filter(|s| s.width == CURVE_STROKE_PX && !s.points.iter().all(in_legend))
        .collect();
    let (mut top, mut bottom) = (f64::NEG_INFINITY, f64::INFINITY);
    for s in &curves {
        assert_eq!(s.points.len(), 2, "{what}: a {} piece with a join", s.color);
        for (_, py) in &s.points {
            let v = a + b * py;
            assert!(
                v >= lo - tol && v <= hi + tol,
                "{what}: a {} segment reaches {v:.1}, data in [{lo:.1}, {hi:.1}] (1 px = {:.2})",
                s.color,
                b.abs()
            );
            (top, bottom) = (top.max(v), bottom.min(v));
        }
    }
    assert!(
        (top - hi).abs() <= tol && (bottom - lo).abs() <= tol,
        "{what}: drawn [{bottom:.1}, {top:.1}] vs data [{lo:.1}, {hi:.1}]"
    );
    curves.len()
}

#[test]
fn fig08_mesh_force_is_drawn_inside_the_data_range() {
    let (model, study) = paper();
    let fig = section41_figures(model, study)
        .into_iter()
        .find(|f| f.file == "fig08_mesh_force")
        .expect("Fig. 8 is built");
    // Three wear states: solid, dashed and dotted, each with its force jumps (a pair
    // entering or leaving the mesh) that plotters drew with spikes past the data.
    assert_eq!(fig.figure.panels[0].series.len(), 3);
    let pieces = assert_curves_within_data(&fig.figure, "fig08");
    // 3 mesh periods of ~230 points each per curve: hundreds of pieces were checked.
    assert!(pieces > 1000, "{pieces} pieces");
}

#[test]
fn a_contact_loss_mesh_force_is_drawn_inside_the_data_range() {
    // Mesh frequency near the softening resonance of `brake_speed_imposed` (tests/solver.rs
    // `contact_loss_resonance_is_solved_at_every_point`): the teeth separate, the force
    // drops to 0 and jumps back, the steepest steps a mesh-force plot has.
    let sets = [
        "operating.input_speed_hz=57".to_string(),
        "operating.speed_boundary=brake_speed_imposed".to_string(),
        // The paper's contact model: with corner contact this pair keeps touching here
        // (the load passes between pairs gradually, so the mesh is not kicked open).
        "contact.path=nominal".to_string(),
    ];
    let model = Model::from_case(&load_case("", &sets).expect("valid case")).expect("model");
    let r = model
        .dynamic(&WearState::new(model.grid.len()), &ExternalError::none())
        .expect("steady state");
    assert_eq!(
        r.signals.meshes[0]
            .mesh_force_n
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min),
        0.0,
        "the case must lose contact"
    );
    let a = dynamics_artifacts(&model, &r, "new teeth");
    let f = a
        .figures
        .iter()
        .find(|f| f.path == "mesh_force.png")
        .expect("the mesh force figure");
    assert!(assert_curves_within_data(&f.figure, "contact loss") > 100);
}

/// The numeric tick labels of the x axis: (pixel x of the label's anchor, value), centred
/// under their ticks (`text-anchor="middle"`, hanging below the axis, `dy="0.76em"`).
fn x_ticks(svg: &str) -> Vec<(f64, f64)> {
    svg.split("<text")
        .skip(1)
        .filter(|t| attr(t, "text-anchor") == Some("middle") && attr(t, "dy") == Some("0.76em"))
        .filter_map(|t| {
            let text = t.split_once('>')?.1.split("</text>").next()?.trim();
            Some((attr(t, "x")?.parse().ok()?, text.parse().ok()?))
        })
        .collect()
}

#[test]
fn the_life_histogram_spans_the_lives_not_zero() {
    use gearwear::prognostics::predict::LifeSummary;
    use gearwear::report::prognostics::life_figure;
    // Lives clustered far from zero (a calibrated posterior): 8e6 to 9e6 cycles.
    let lives: Vec<f64> = (0..500).map(|i| 8e6 + 2e3 * f64::from(i)).collect();
    let life = LifeSummary {
        samples: 500,
        reached: 500,
        p05: Some(8.05e6),
        median: Some(8.5e6),
        p95: Some(8.95e6),
        beyond_horizon: 0,
        unknown: 0,
        prob_beyond_horizon: 0.0,
        prob_beyond_horizon_bounds: (0.0, 0.0),
        spread_reached: 0.0,
    };
    let fig = life_figure(&lives, &life, 1e7);
    let (w, h) = (PLOT_W, plot_height(1));
    let svg = render_svg(&fig, w, h).expect("renders");
    let plot = layout(&fig, w, h).expect("lays out")[0].plot;
    // The x axis as its labels show it (thousands of cycles), read at the plot's edges.
    let t = x_ticks(&svg);
    assert!(t.len() >= 3, "{t:?}");
    let (a, b) = (t[0], t[t.len() - 1]);
    let at = |px: f64| a.1 + (px - a.0) * (b.1 - a.1) / (b.0 - a.0);
    let (left, right) = (at(f64::from(plot.x0)) * 1e3, at(f64::from(plot.x1)) * 1e3);
    // The axis covers the lives (8e6-9e6) with the renderer's 5 % margins plus half a bin
    // (1/80 of the span) each side: 7.93e6-9.07e6 up to a pixel; from 0 the data would
    // fill 1/9 of it.
    let span = 9e6 - 8e6;
    let margin = (0.05 * 1.025 + 0.0125) * span + 2.0 * (right - left) / f64::from(plot.width());
    assert!(left > 8e6 - margin && left < 8e6, "axis starts at {left}");
    assert!(right < 9e6 + margin && right > 9e6, "axis ends at {right}");
}

#[test]
fn a_skewed_life_spread_is_binned_on_log_cycles() {
    use gearwear::report::prognostics::life_bins;
    // 200 lives at 1e3 and 10 spread to 1e5: on linear bins of 0..1e5 both groups' first
    // members share the first bin; on log10 bins over [3, 5] they are 40 bins apart.
    let mut lives = vec![1e3; 200];
    lives.extend((1..=10).map(|i| 1e4 * f64::from(i)));
    let (x, counts, log) = life_bins(&lives);
    assert!(log);
    assert_eq!(counts.iter().sum::<f64>(), 210.0); // every life in a bin
    assert_eq!(counts[0], 200.0);
    // Bin centres span log10 of the lives: half a bin (1/80 of 2 decades) inside each end.
    assert!(
        (x[0] - (3.0 + 2.0 / 80.0)).abs() < 1e-12 && (x[39] - (5.0 - 2.0 / 80.0)).abs() < 1e-12
    );
    // A narrow spread stays linear.
    let (_, _, log) = life_bins(&[8e6, 8.5e6, 9e6]);
    assert!(!log);
}

#[test]
fn fig12_quasi_static_panel_shows_new_teeth_over_the_last_state() {
    use gearwear::report::wear::{spread_from_first, wear_figures};
    let (model, study) = paper();
    let figs = wear_figures(model, &[&study.dynamic, &study.quasi_static]);
    let fig = &figs
        .iter()
        .find(|f| f.stem == "fig12_wear_rate_evolution")
        .unwrap()
        .figure;
    let (dynamic, qs) = (&fig.panels[0], &fig.panels[1]);
    // Independent of the figure: the quasi-static rate of the study's first and last
    // records differ by < 1 % of its maximum (the quasi-static load ignores the worn
    // profile's dynamics), the dynamic one by far more (measured 0.03 % and 20 %).
    let rate = |r: &gearwear::study::wear_loop::UpdateRecord| r.increment_pinion_m.clone();
    let (q0, q1) = (
        rate(&study.quasi_static.records[0]),
        rate(study.quasi_static.last().unwrap()),
    );
    let max = q0.iter().fold(0.0_f64, |a, b| a.max(*b));
    let change = q0
        .iter()
        .zip(&q1)
        .fold(0.0_f64, |a, (x, y)| a.max((x - y).abs()));
    assert!(change < 0.01 * max, "{change} vs {max}");
    assert!(spread_from_first(dynamic) > 0.05);
    // The quasi-static panel says so and draws the new-teeth curve (the scale's first
    // colour) again, dashed, last: visible on top of the final state's colour.
    assert!(qs.title.contains("coincide"), "{}", qs.title);
    let (first, last) = (&qs.series[0], qs.series.last().unwrap());
    assert_eq!((first.color, &first.y), (last.color, &last.y));
    assert_eq!(last.style, gearwear::report::plot::LineStyle::Dashed);
    assert!(!dynamic.title.contains("coincide"));
    // In the SVG, the first colour's pieces come after every other colour's in the panel.
    let svg = render_svg(fig, PLOT_W, plot_height(2)).expect("renders");
    let hex = |c: [u8; 3]| format!("#{:02X}{:02X}{:02X}", c[0], c[1], c[2]);
    let (c0, c_end) = (
        hex(first.color.unwrap()),
        hex(qs.series[qs.series.len() - 2].color.unwrap()),
    );
    let s = strokes(&svg);
    let last_end = s.iter().rposition(|p| p.color == c_end).unwrap();
    let last_first = s.iter().rposition(|p| p.color == c0).unwrap();
    assert!(last_first > last_end);
}
