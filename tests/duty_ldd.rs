//! The load duration distribution against histories whose time at level is known
//! exactly (issue 20): a square wave, a ramp, conservation of time.

use gearwear::config::case::TorqueShaft;
use gearwear::duty::history::{parse_history, History, DEFAULT_GAP_FACTOR};
use gearwear::duty::ldd::{load_duration_distribution, Interpolation, LddSettings, Level};

fn settings(interpolation: Interpolation, level: Level) -> LddSettings {
    LddSettings {
        torque_classes: 10,
        speed_classes: 5,
        interpolation,
        level,
    }
}

/// Relative agreement: a handful of roundings of sums of ~100 terms.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

#[test]
fn a_square_wave_held_between_samples_counts_exactly() {
    // 3 s at 20 N m, 1 s at 80 N m, ten periods, 25 Hz, sampled every 0.5 s (the switches
    // fall on samples): 30 s and 10 s, 750 and 250 revolutions.
    let mut h = History::default();
    for i in 0..=80 {
        let t = 0.5 * i as f64;
        h.time_s.push(t);
        h.torque_nm.push(if t % 4.0 < 3.0 { 20.0 } else { 80.0 });
        h.input_speed_hz.push(25.0);
    }
    let l = load_duration_distribution(&h, settings(Interpolation::Hold, Level::Mean));
    // Classes of 8 N m over [0, 80]: 20 N m in class 2, 80 N m in the last (9).
    let at = l.time_at_torque_s();
    assert_eq!((at[2], at[9]), (30.0, 10.0));
    assert_eq!(at.iter().sum::<f64>(), 40.0);
    assert_eq!(l.idle_time_s, 0.0);
    let s = l.spectrum(TorqueShaft::Pinion).unwrap();
    assert_eq!(s.bins.len(), 2);
    assert_eq!((s.bins[0].torque_nm, s.bins[1].torque_nm), (20.0, 80.0));
    assert_eq!((s.bins[0].share, s.bins[1].share), (0.75, 0.25));
    assert_eq!(s.bins[0].input_speed_hz, 25.0);
    // The upper level takes the class edges instead: 24 and 80 N m.
    let u = load_duration_distribution(&h, settings(Interpolation::Hold, Level::Upper))
        .spectrum(TorqueShaft::Pinion)
        .unwrap();
    assert!(close(u.bins[0].torque_nm, 24.0) && close(u.bins[1].torque_nm, 80.0));
}

#[test]
fn a_ramp_interpolated_linearly_counts_exactly_however_it_is_sampled() {
    // T = t N m/s over [0, 100] s, f = 10 + 0.2 t Hz, sampled at irregular times (the
    // linear interpolant is the signal itself).
    let times = [0.0, 7.0, 23.5, 50.0, 51.0, 88.0, 100.0];
    let h = History {
        time_s: times.to_vec(),
        torque_nm: times.to_vec(),
        input_speed_hz: times.iter().map(|t| 10.0 + 0.2 * t).collect(),
    };
    let l = load_duration_distribution(&h, settings(Interpolation::Linear, Level::Mean));
    // Ten torque classes of 10 N m: 10 s each.
    for (j, t) in l.time_at_torque_s().iter().enumerate() {
        assert!(close(*t, 10.0), "class {j}: {t}");
    }
    // Speed classes of 6 Hz over [0, 30]: f crosses 12, 18, 24 Hz at 10, 40, 70 s.
    let at = l.time_at_speed_s();
    for (s, want) in [(0, 0.0), (1, 10.0), (2, 30.0), (3, 30.0), (4, 30.0)] {
        assert!(close(at[s], want), "speed class {s}: {}", at[s]);
    }
    // Revolutions in torque class j: integral of 10 + 0.2 t over [10 j, 10 j + 10] =
    // 110 + 20 j; torque-revolutions: integral of t (10 + 0.2 t) = 5 t^2 + t^3 / 15.
    let ns = l.settings.speed_classes;
    for j in 0..10 {
        let row = j * ns..(j + 1) * ns;
        let cycles: f64 = l.cycles[row.clone()].iter().sum();
        assert!(close(cycles, 110.0 + 20.0 * j as f64), "{j}: {cycles}");
        let g = |t: f64| 5.0 * t * t + t * t * t / 15.0;
        let (a, b) = (10.0 * j as f64, 10.0 * j as f64 + 10.0);
        let tc: f64 = l.torque_cycles_nm[row].iter().sum();
        assert!(close(tc, g(b) - g(a)), "{j}: {tc}");
    }
    // Total revolutions: integral of f over [0, 100] = 2000; shares follow them.
    let s = l.spectrum(TorqueShaft::Gear).unwrap();
    assert_eq!(s.torque_shaft, Some(TorqueShaft::Gear));
    assert!(close(s.bins.iter().map(|b| b.share).sum::<f64>(), 1.0));
    assert!(close(l.cycles.iter().sum::<f64>(), 2000.0));
}

#[test]
fn total_time_is_conserved_and_idle_time_is_counted_apart() {
    // A torque that reverses (coast: no load on the drive flank) and a speed that stops,
    // sampled irregularly; every second of the span lands in a cell or in the idle time.
    let mut h = History::default();
    let mut t = 0.0;
    let mut x: u64 = 12345;
    for _ in 0..5000 {
        // A linear congruential step (Knuth's MMIX constants) for irregular intervals.
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        t += 0.01 + 0.02 * ((x >> 33) as f64 / (1u64 << 31) as f64);
        h.time_s.push(t);
        h.torque_nm.push(80.0 * (0.7 * t).sin() + 20.0);
        h.input_speed_hz.push((30.0 * (0.1 * t).cos()).max(-5.0));
    }
    for interpolation in [Interpolation::Linear, Interpolation::Hold] {
        let l = load_duration_distribution(&h, settings(interpolation, Level::Mean));
        let counted = l.loaded_time_s() + l.idle_time_s;
        assert!(
            (counted - l.span_s).abs() < 1e-9 * l.span_s,
            "{interpolation:?}: {counted} of {}",
            l.span_s
        );
        assert!(l.idle_time_s > 0.1 * l.span_s && l.loaded_time_s() > 0.1 * l.span_s);
    }
}

#[test]
fn the_time_with_reversed_torque_is_counted_apart_exactly() {
    // Torque 100 - 50 t N m over t = 0..4 s at 20 Hz: negative from t = 2 s on (the coast
    // flank loaded), 2 s exactly under linear interpolation; then the speed ramps to zero
    // over 4..6 s with the torque still negative, which is stopped, not reversed, only
    // while the speed is zero (never here: it reaches zero at the last sample).
    let mut h = History::default();
    for (t, q, f) in [
        (0.0, 100.0, 20.0),
        (4.0, -100.0, 20.0),
        (6.0, -100.0, 0.0),
        (7.0, 0.0, 0.0),
    ] {
        h.time_s.push(t);
        h.torque_nm.push(q);
        h.input_speed_hz.push(f);
    }
    let l = load_duration_distribution(&h, settings(Interpolation::Linear, Level::Mean));
    // Reversed: 2..4 s and 4..6 s (the speed above zero until t = 6 s): 4 s. Idle also
    // holds 6..7 s, standing still.
    assert!(
        close(l.reversed_torque_time_s, 4.0),
        "{}",
        l.reversed_torque_time_s
    );
    assert!(close(l.idle_time_s, 5.0), "{}", l.idle_time_s);
    assert!(close(l.loaded_time_s(), 2.0), "{}", l.loaded_time_s());
    // Held samples: 0..4 s at +100 N m, 4..6 s at -100 N m turning, 6..7 s standing.
    let l = load_duration_distribution(&h, settings(Interpolation::Hold, Level::Mean));
    assert!(
        close(l.reversed_torque_time_s, 2.0),
        "{}",
        l.reversed_torque_time_s
    );
    assert!(close(l.idle_time_s, 3.0), "{}", l.idle_time_s);
}

#[test]
fn a_csv_history_gives_the_same_counts() {
    let mut text = String::from("time_s,torque_nm,input_speed_rpm\n");
    for i in 0..=80 {
        let t = 0.5 * i as f64;
        text.push_str(&format!(
            "{t},{},1500\n",
            if t % 4.0 < 3.0 { 20 } else { 80 }
        ));
    }
    let h = parse_history(text.as_bytes(), DEFAULT_GAP_FACTOR).unwrap();
    let s = load_duration_distribution(&h, settings(Interpolation::Hold, Level::Mean))
        .spectrum(TorqueShaft::Pinion)
        .unwrap();
    // 1500 rpm = 25 Hz.
    assert_eq!(s.bins[0].input_speed_hz, 25.0);
    assert_eq!((s.bins[0].share, s.bins[1].share), (0.75, 0.25));
}
