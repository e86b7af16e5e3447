"""Gear trains and planetary sets from Python: every stage's coordinates and meshes, a
train's wear per mesh, a planetary set's mesh forces, load sharing and ring sensor,
checked against kinematics, statics and the command line's own files."""

from __future__ import annotations

import csv
import math
import subprocess
import warnings

import numpy as np
import pytest

import gearwear as gw
from conftest import REPO, run_cli

TRAIN = REPO / "examples" / "two_stage_reducer.toml"

#: Lin & Parker's (1999) Table 1 as `[planetary.lumped]` (inertias as (I / r^2) r^2 with
#: the table's radii), a 24 / 30 / 84 set of module 2 mm with four planets, sun in at the
#: case's 60 N m, carrier out, ring fixed.
PLANETARY = """
[planetary]
planets = 4
teeth_sun = 24
teeth_planet = 30
teeth_ring = 84
module_mm = 2.0
[planetary.lumped]
mass_sun_kg = 0.4
mass_planet_kg = 0.66
mass_ring_kg = 2.35
mass_carrier_kg = 5.43
inertia_sun_kg_m2 = 0.000584
inertia_planet_kg_m2 = 0.001534
inertia_ring_kg_m2 = 0.0567
inertia_carrier_kg_m2 = 0.04915
base_radius_sun_mm = 38.7
base_radius_planet_mm = 50.15
base_radius_ring_mm = 137.5
carrier_radius_mm = 88.4
mesh_stiffness_sun_planet_n_per_m = 5e8
mesh_stiffness_ring_planet_n_per_m = 5e8
bearing_stiffness_sun_n_per_m = 1e8
bearing_stiffness_planet_n_per_m = 1e8
bearing_stiffness_ring_n_per_m = 1e8
bearing_stiffness_carrier_n_per_m = 1e8
torsional_stiffness_sun_nm_per_rad = 0
torsional_stiffness_ring_nm_per_rad = 1.89e7
torsional_stiffness_carrier_nm_per_rad = 1e6
pressure_angle_deg = 24.6
"""


def _quiet(f, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", gw.GearwearWarning)
        return f(*args, **kwargs)


@pytest.fixture(scope="module")
def train() -> gw.Case:
    return gw.Case.from_toml(TRAIN)


@pytest.fixture(scope="module")
def planetary() -> gw.Case:
    return gw.Case.from_toml(PLANETARY)


def _time_mean(t: np.ndarray, y: np.ndarray) -> float:
    """The time average of y over the recorded span (trapezoid rule: the samples are the
    integrator's steps, not evenly spaced)."""
    return float(np.trapezoid(y, t) / (t[-1] - t[0]))


def test_train_dynamics_has_every_stage(train, cli, tmp_path):
    r = _quiet(gw.dynamics, train)
    # Two stages: 4 lateral coordinates per stage, rotations of motor, four gears, brake.
    assert len(r.coordinates) == 2 * 4 + 6 == r.summary["train"]["coordinates"]
    assert r.coordinates[:4] == ["x_pinion1", "y_pinion1", "x_gear1", "y_gear1"]
    assert r.coordinate_units.count("rad") == 6
    n = len(r.time_s)
    for a in (r.displacement, r.velocity, r.acceleration):
        assert a.shape == (n, 14) and np.isfinite(a).all()
    assert r.mode_shapes.shape[1] == 14
    assert r.n_meshes == 2
    # The record spans the train's base period: one turn of the intermediate shaft,
    # z_gear1 / (z_pinion1 f_in) = 31 / (19 x 30 Hz) (from the tooth numbers).
    base = 31 / (19 * 30.0)
    assert abs(r.summary["train"]["base_period_s"] - base) < 1e-12 * base
    # Each mesh's time-averaged force is its summary mean (the samples are the
    # integrator's steps; the trapezoid rule's error on them is below 1e-4 here).
    for k in (1, 2):
        m = r.mesh(k)
        s = r.summary["meshes"][k - 1]
        assert m.stage == k == s["stage"]
        mean = _time_mean(m.time_s, m.mesh_force_n)
        assert abs(mean / s["mesh_force"]["mean_n"] - 1) < 1e-4
        assert m.mesh_force_n.max() == pytest.approx(s["mesh_force"]["max_n"], rel=1e-12)
    # Stage 1 is what the pair-named views give.
    assert np.array_equal(r.mesh(1).dte_um, r.dte_um)
    # Stage 2's columns are the command line's, bit for bit.
    out = run_cli(cli, tmp_path, "dynamics", train)
    with open(out / "timeseries.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert np.array_equal(r.mesh(2).mesh_force_n, [float(x["mesh2_force_n"]) for x in rows])
    assert np.array_equal(r.displacement[:, 13], [float(x["phi_brake_rad"]) for x in rows])
    with pytest.raises(ValueError, match="meshes 1 .. 2"):
        r.mesh(3)
    with pytest.raises(TypeError):
        r.mesh(1.0)


def test_the_pair_keeps_its_eight_coordinates():
    r = _quiet(
        gw.dynamics,
        gw.Case.paper().set(
            {"numerics.steps_per_mesh_period": 60, "numerics.evaluated_mesh_periods": 2}
        ),
    )
    assert r.coordinates == list(gw.COORDINATES)
    assert r.coordinate_units == list(gw.COORDINATE_UNITS)
    assert r.n_meshes == 1
    assert np.array_equal(r.mesh(1).mesh_force_n, r.mesh_force_n)


def test_train_wear_per_mesh(train):
    total = 1e4
    w = _quiet(gw.wear, train.set("wear.total_cycles", total))
    assert w.is_train
    stages = w.stages
    assert len(stages) == 2 and all(set(s) == {"dynamic", "quasi_static"} for s in stages)
    for mode in ("dynamic", "quasi_static"):
        # Stage 1's pinion turns with the input; stage 2's pinion turns 19/31 as often
        # (it shares the intermediate shaft with stage 1's 31-tooth gear).
        assert stages[0][mode].cycles[-1] == pytest.approx(total, rel=1e-12)
        assert stages[1][mode].cycles[-1] == pytest.approx(total * 19 / 31, rel=1e-12)
        for s in stages:
            wear = s[mode].max_wear_pinion_um
            assert (np.diff(wear) >= 0).all() and wear[-1] > 0
        h = w.history(mode)
        assert set(h["stage"].tolist()) == {1, 2}
    with pytest.raises(ValueError, match="stages"):
        w.runs
    with pytest.raises(KeyError, match="sideways"):
        w.history("sideways")


def test_train_sweep_has_every_mesh_and_equals_dynamics(train, cli, tmp_path):
    # A sweep of a train (a stage key varied) in memory: one column set per mesh, each
    # row the numbers of `gw.dynamics` on the same case (the same computation, so equal
    # to the last bit), and the table the command line's (the CSV's shortest round-trip
    # numbers read back to the same doubles).
    cheap = train.set("numerics.steps_per_mesh_period", 60).set(
        "numerics.evaluated_mesh_periods", 2
    )
    s = _quiet(gw.sweep, cheap, {"stage.2.face_width_mm": [20.0, 25.0]})
    assert len(s) == 2
    for k in (1, 2):
        for c in ("mesh_frequency_hz", "dte_max_um", "mesh_force_mean_n",
                  "mesh_force_max_n", "dynamic_factor"):
            assert f"stage{k}_{c}" in s.columns
    for i, width in enumerate(s["stage.2.face_width_mm"]):
        d = _quiet(gw.dynamics, cheap.set("stage.2.face_width_mm", float(width)))
        for m in d.summary["meshes"]:
            k = m["stage"]
            assert s[f"stage{k}_dte_max_um"][i] == m["dte"]["max_um"]
            assert s[f"stage{k}_dynamic_factor"][i] == m["mesh_force"]["dynamic_factor"]
            assert s[f"stage{k}_mesh_frequency_hz"][i] == m["mesh_frequency_hz"]
    out = run_cli(cli, tmp_path, "sweep", cheap, "--vary", "stage.2.face_width_mm=20,25")
    with open(out / "sweep.csv") as f:
        rows = list(csv.reader(f))
    assert rows[0] == s.keys + ["case_id"] + s.columns
    for i, row in enumerate(rows[1:]):
        assert [float(x) for x in row[2:]] == s.results[i].tolist()
    # A train's wear sweep: each mesh's final depths and the limiting stage, the numbers
    # of `gw.wear` on the same case (the same computation: equal to the last bit).
    case = cheap.set("wear.total_cycles", 2e3)
    ws = _quiet(gw.sweep, case, {"operating.input_speed_hz": [30.0]}, run="wear")
    w = _quiet(gw.wear, case)
    for mode in ("dynamic", "quasi_static"):
        for k in (0, 1):
            run = w.stages[k][mode]
            for flank in ("pinion", "gear"):
                col = f"stage{k + 1}_wear_max_{flank}_{mode}_um"
                assert ws[col][0] == getattr(run, f"max_wear_{flank}_um")[-1] > 0
        limiting = w.summary["limiting_mesh"][mode]["stage"]
        assert ws[f"wear_limiting_stage_{mode}"][0] == limiting


def test_a_single_pair_has_no_stages():
    w = _quiet(
        gw.wear,
        gw.Case.paper().set(
            {"wear.total_cycles": 2e3, "numerics.steps_per_mesh_period": 60}
        ),
        "quasi_static",
    )
    assert not w.is_train and w.stages == []
    assert w.quasi_static is not None and w.dynamic is None


def test_planetary_dynamics(planetary):
    r = _quiet(gw.dynamics, planetary)
    assert isinstance(r, gw.PlanetaryDynamicsResult)
    assert r.planets == 4
    n = len(r.time_s)
    assert r.sun_planet_force_n.shape == r.ring_planet_force_n.shape == (n, 4)
    # Load sharing recomputed from the forces: N x a planet's mean over the sum of the
    # means; identical, equally spaced planets without errors share equally.
    means = np.array([_time_mean(r.time_s, f) for f in r.sun_planet_force_n.T])
    assert np.allclose(4 * means / means.sum(), 1.0, atol=1e-9)
    assert np.allclose(r.load_sharing_factor, 1.0, atol=1e-9)
    # Torque balance on the sun: the four meshes carry 60 N m at the sun's base radius
    # m z_s cos(20 deg) / 2. The table samples 200 points per mesh period across the
    # force's jumps at contact changes (about 300 N), so its average is off the exact
    # integral by up to a few 1e-3.
    r_bs = 2e-3 * 24 * math.cos(math.radians(20)) / 2
    assert means.mean() == pytest.approx(60 / (4 * r_bs), rel=3e-3)
    # Mesh frequency z_r f_carrier, the carrier at f_sun z_s / (z_s + z_r) (Willis, ring
    # fixed), the sun at the case's 30 Hz.
    f_c = 30.0 * 24 / (24 + 84)
    assert r.mesh_frequency_hz == pytest.approx(84 * f_c, rel=1e-12)


def test_planetary_signals(planetary):
    s = _quiet(gw.signals, planetary)
    assert isinstance(s, gw.PlanetarySignalsResult)
    t = s.record["time_s"]
    assert s.sampling_rate_hz == pytest.approx(1 / (t[1] - t[0]), rel=1e-9)
    assert s.summary["record"]["samples"] == len(t) == s.record.n_rows
    assert s.channel_unit == "N"
    f_c = 30.0 * 24 / (24 + 84)
    assert s.planet_pass_hz == pytest.approx(4 * f_c, rel=1e-12)
    assert s.mesh_frequency_hz == pytest.approx(84 * f_c, rel=1e-12)
    # The orders' frequencies are the carrier orders times the carrier frequency.
    o = s.orders
    assert np.allclose(o["frequency_hz"], o["carrier_order"] * f_c, rtol=1e-12)


def test_train_and_planetary_cases_survive_text_and_pickle(train, planetary):
    # `to_toml` and pickling write the commented case; a train's stages and a planetary
    # set (with its lumped sub-table) must read back, not fall back to the paper's pair.
    import pickle

    for case in (train, planetary):
        assert gw.Case.from_toml(case.to_toml()) == case
        assert pickle.loads(pickle.dumps(case)) == case
    assert "[[stage]]" in train.to_toml()


def test_train_run_is_its_studies(train):
    # `run` on a train nests the wear job's files: its runs per mesh must be those of a
    # separate `wear` (a second path through the application), and the limiting mesh
    # the stage whose pinion or gear wore deepest.
    case = train.set("wear.total_cycles", 2e3)
    r = _quiet(gw.run, case)
    w = _quiet(gw.wear, case)
    assert isinstance(r, gw.RunResult) and r.is_train and len(r.stages) == 2
    for mode in ("dynamic", "quasi_static"):
        for k in (0, 1):
            a, b = r.stages[k][mode], w.stages[k][mode]
            assert np.array_equal(a.cycles, b.cycles)
            assert np.array_equal(a.max_wear_pinion_um, b.max_wear_pinion_um)
        deepest = [
            max(s[mode].max_wear_pinion_um[-1], s[mode].max_wear_gear_um[-1])
            for s in r.stages
        ]
        limiting = r.summary["limiting_mesh"][mode]
        assert limiting["stage"] == 1 + int(np.argmax(deepest))
        assert limiting["max_wear_um"] == max(deepest)
    assert len(r.summary["meshes"]) == 2


def test_planetary_dataset_labels_follow_the_sets_kinematics_and_equal_the_cli(cli, tmp_path):
    """A planetary set's run-to-failure dataset from Python (the example set, sun in at
    25 Hz, ring fixed): one ring-sensor record per state, labelled per member. The labels
    are checked against the set's kinematics computed here: the mesh frequency z_r f_c with
    f_c = f_s z_s / (z_s + z_r); each member's tooth contacts after C sun revolutions, the
    sun's N C (1 - z_s / (z_s + z_r)) (every planet meets each sun tooth once per sun
    revolution relative to the carrier), a planet's C (z_s / z_p)(1 - z_s / (z_s + z_r)),
    the ring's N C z_s / (z_s + z_r); new teeth at 0 cycles, the deepest member named
    after. The same design from the command line gives the same files, byte for byte."""
    text = (
        f'case = "{REPO / "examples" / "planetary_set.toml"}"\nseed = 5\n'
        'set = ["signals.record_length=0.05"]\n'
        "[run_to_failure]\ncycles = [0, 5e4]\nmax_cycles = 1e5\nwear_limit_um = 50\n"
    )
    design = tmp_path / "design.toml"
    design.write_text(text)
    r = gw.dataset(design, tmp_path / "py")
    assert r.summary["records"] == 2
    ref = tmp_path / "cli"
    run = [str(cli), "-q", "dataset", "--design", str(design), "--out", str(ref)]
    subprocess.run(run, check=True, timeout=300)
    for f in ["index.csv", "index.parquet", "signals/0000001.parquet"]:
        assert (tmp_path / "py" / f).read_bytes() == (ref / f).read_bytes(), f
    with open(ref / "index.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    zs, zp, zr, n, fs = 23, 31, 85, 4, 25.0
    carrier = zs / (zs + zr)  # carrier turns per sun turn, ring fixed
    members = ["sun"] + [f"planet{k}" for k in range(1, n + 1)] + ["ring"]
    for row in rows:
        c = float(row["cycles"])
        assert math.isclose(float(row["mesh_hz"]), zr * fs * carrier, rel_tol=1e-12)
        want = {"sun": n * c * (1 - carrier), "ring": n * c * carrier}
        want.update({f"planet{k}": c * zs / zp * (1 - carrier) for k in range(1, n + 1)})
        for m in members:
            got = float(row[f"tooth_contacts_{m}"])
            assert math.isclose(got, want[m], rel_tol=1e-9, abs_tol=1e-9), (m, c, got, want[m])
        wear = {m: float(row[f"wear_max_um_{m}"]) for m in members}
        if c == 0:
            assert all(w == 0 for w in wear.values()) and row["limiting_member"] == ""
        else:
            assert min(wear.values()) > 0
            assert row["limiting_member"] == max(wear, key=wear.get)
    assert [float(x["cycles"]) for x in rows] == [0.0, 5e4]
