"""Duty cycles from Python: the load spectrum of a measured history (the same numbers as
`gearwear load-spectrum`, exact on a history whose time at level is known), a case given
that spectrum, bad histories refused, and the per-bin results of a wear study under it."""

from __future__ import annotations

import csv
import subprocess
from pathlib import Path

import numpy as np
import pytest

import gearwear as gw


def square_wave() -> dict:
    """3 s at 20 N m then 1 s at 80 N m, ten periods, 1500 rpm, sampled every 0.5 s (the
    switches on samples): held between samples, 30 s and 10 s, 750 and 250 revolutions."""
    t = 0.5 * np.arange(81)
    return {
        "time_s": t,
        "torque_nm": np.where(t % 4.0 < 3.0, 20.0, 80.0),
        "input_speed_rpm": np.full(t.shape, 1500.0),
    }


def test_a_history_gives_the_exact_spectrum_and_the_cli_numbers(tmp_path: Path, cli: Path):
    h = square_wave()
    r = gw.load_spectrum(h, interpolation="hold", out=tmp_path / "py")
    # Exact: shares 0.75 / 0.25 of the revolutions, 25 Hz, the two torques.
    assert list(r.bins["share"]) == [0.75, 0.25]
    assert list(r.bins["torque_nm"]) == [20.0, 80.0]
    assert list(r.bins["input_speed_hz"]) == [25.0, 25.0]
    # Time is conserved: every cell plus idle time is the record's span.
    assert r.ldd["time_s"].sum() + r.summary["time"]["idle_s"] == r.summary["history"]["span_s"] == 40.0
    assert (tmp_path / "py" / "ldd_time_at_level.png").is_file()
    # The command line on the same history as a CSV file: the same spectrum, bit for bit.
    path = tmp_path / "history.csv"
    with path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(list(h))
        for row in zip(*h.values()):
            w.writerow([repr(float(x)) for x in row])
    subprocess.run(
        [str(cli), "-q", "load-spectrum", "--history", str(path), "--out", str(tmp_path / "cli"),
         "--interpolation", "hold"],
        check=True,
        timeout=60,
    )
    assert (tmp_path / "cli" / "spectrum.csv").read_bytes() == (tmp_path / "py" / "spectrum.csv").read_bytes()
    # The spectrum applied to a case.
    case = r.apply(gw.Case.paper())
    assert case["load_spectrum.torque_shaft"] == "pinion"
    assert r.toml.startswith("# The load spectrum")


def test_bad_histories_and_options_name_the_argument():
    h = square_wave()
    h["torque_nm"] = h["torque_nm"].copy()
    h["torque_nm"][3] = np.nan
    with pytest.raises(gw.CaseError) as e:
        gw.load_spectrum(h)
    msg = str(e.value)
    assert "`history`" in msg and "row 4" in msg and "torque_nm" in msg, msg
    with pytest.raises(gw.CaseError) as e:
        gw.load_spectrum(square_wave(), torque_classes=0)
    assert "`torque_classes`" in str(e.value)
    with pytest.raises(ValueError):
        gw.load_spectrum(square_wave(), level="max")
    with pytest.raises(gw.CaseError) as e:
        gw.load_spectrum(square_wave(), merge_below_share=0.5)
    assert "`merge_below_share`" in str(e.value) and "[0, 0.1]" in str(e.value)


def test_a_wear_study_under_a_spectrum_shows_each_bin():
    case = gw.Case.paper().set(
        {
            "wear.total_cycles": 1.5e4,
            "numerics.steps_per_mesh_period": 60,
            "numerics.evaluated_mesh_periods": 2,
            "stiffness.table_points_per_mesh_period": 60,
        }
    )
    spectrum = gw.load_spectrum(square_wave(), interpolation="hold")
    w = gw.wear(spectrum.apply(case), mode="quasi_static")
    d = w.duty
    assert d is not None and gw.wear(case, mode="quasi_static").duty is None
    assert d.spectrum.n_rows == 2
    ranking = d.ranking("quasi_static")
    # The shares of wear of all bins make the whole (to round-off of two sums).
    assert abs(ranking["share_of_pinion_wear"].sum() - 1.0) < 1e-12
    # The heavier bin wears more per cycle: its wear intensity is above 1.
    heavy = ranking["bin"] == 2.0
    assert ranking["wear_intensity"][heavy][0] > 1.0
    # Per profile point, the bins' wear sums to the total (round-off of a 2-term sum).
    by = d.wear_by_bin("quasi_static")
    total = by["wear_pinion_total_um"]
    parts = by["wear_pinion_bin1_um"] + by["wear_pinion_bin2_um"]
    assert np.allclose(parts, total, rtol=1e-12, atol=1e-15)
    assert d.dynamic_factor("quasi_static").n_rows == len(w.quasi_static.cycles)
    # The life table, as `run` gives it: the spectrum and both bins.
    assert d.life is not None and d.summary["life"]["mode"] == "quasi_static"


def test_a_sweep_of_the_torque_scale_runs_each_case_under_its_spectrum():
    case = gw.Case.paper().set(
        {
            "wear.total_cycles": 1.5e4,
            "numerics.steps_per_mesh_period": 60,
            "numerics.evaluated_mesh_periods": 2,
            "stiffness.table_points_per_mesh_period": 60,
        }
    )
    case = gw.load_spectrum(square_wave(), interpolation="hold").apply(case)
    s = gw.sweep(case, {"load_spectrum.torque_scale": [1.0, 1.2]}, run="wear")
    qs = s["wear_max_pinion_quasi_static_um"]
    # Quasi-statically, Archard wear of new teeth is linear in the load (p0 and the Hertz
    # band both grow as W^1/2); 1.5e4 cycles wear ~1 um, moving the loads by a few per
    # mille: 1 % holds it with margin.
    assert abs(qs[1] / qs[0] / 1.2 - 1.0) < 0.01, qs
    # The sweep's row is the wear study of that case, bit for bit.
    w = gw.wear(case.set("load_spectrum.torque_scale", 1.2), mode="quasi_static")
    assert w.quasi_static.max_wear_pinion_um[-1] == qs[1]
