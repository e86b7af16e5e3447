"""Sweeps against the command line and against single evaluations; tables to pandas."""

import sys

import numpy as np
import pytest

import gearwear as gw
from conftest import run_cli


def read_sweep_csv(path):
    lines = path.read_text().splitlines()
    header = lines[0].split(",")
    rows = [l.split(",") for l in lines[1:]]
    return header, rows


def test_sweep_equals_cli_sweep_csv(cli, tmp_path):
    case = gw.Case.paper()
    s = gw.sweep(case, {"operating.input_speed_hz": "20:40:5", "friction.model": ["xu2007", "none"]})
    assert len(s) == 10 and s.results.shape == (10, len(s.columns))
    out = run_cli(cli, tmp_path, "sweep", case, "--vary", "operating.input_speed_hz=20:40:5",
                  "--vary", "friction.model=xu2007,none")
    header, rows = read_sweep_csv(out / "sweep.csv")
    assert header == s.keys + ["case_id"] + s.columns
    for i, row in enumerate(rows):
        assert int(row[2]) == s.case_ids[i]
        assert row[1] == s.values["friction.model"][i]
        # The CSV's shortest round-trip numbers read back to the same doubles.
        assert [float(x) for x in row[3:]] == s.results[i].tolist()
    assert s.summary["failed"] == [] and s.summary["total_cases"] == 10


def test_sweep_rows_are_single_evaluations():
    case = gw.Case.paper()
    s = gw.sweep(case, {"operating.input_speed_hz": np.array([24.0, 36.0])})
    for speed, dte in zip(s["operating.input_speed_hz"], s["dte_max_um"]):
        d = gw.dynamics(case.set("operating.input_speed_hz", speed))
        assert dte == d.summary["dte"]["max_um"]


def test_to_pandas():
    pd = pytest.importorskip("pandas")
    d = gw.dynamics(gw.Case.paper())
    df = d.to_pandas("timeseries")
    assert isinstance(df, pd.DataFrame)
    assert list(df.columns) == d.tables["timeseries"].columns
    np.testing.assert_array_equal(df["dte_um"].to_numpy(), d.dte_um)
    # Every table the CLI writes, by file stem: the data tables and each figure's own
    # (csv/dte.csv as "dte").
    names = {"timeseries", "path", "modes", "modes_undamped", "spectrum"}
    names |= {"dte", "mesh_force", "velocity_y_pinion", "spectrum_velocity_y_pinion",
              "friction_coefficient", "friction_force"}
    assert set(d.to_pandas()) == names
    s = gw.sweep(gw.Case.paper(), {"operating.input_speed_hz": [25, 30]})
    assert list(s.to_pandas()["operating.input_speed_hz"]) == [25.0, 30.0]
    assert d.tables["path"].to_numpy().shape == (d.tables["path"].n_rows, len(d.tables["path"]))


def test_to_pandas_without_pandas_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # makes `import pandas` fail
    d = gw.stiffness(gw.Case.paper())
    with pytest.raises(ImportError, match="pip install pandas"):
        d.to_pandas("mesh_stiffness")
    # Everything else works without it.
    assert d.table["stiffness_total_n_per_m"].shape == (720,)


def test_sweep_to_a_folder_is_the_cli_sweep_and_merges(cli, tmp_path):
    """With `out`, the sweep writes the command line's files (shards, case records), and
    `sweep_merge` joins them as `gearwear sweep-merge` does."""
    case = gw.Case.paper()
    vary = {"operating.input_speed_hz": "20:40:10"}
    for i in (1, 2):
        gw.sweep(case, vary, out=tmp_path / "py", shard=f"{i}/2")
    merged = gw.sweep_merge([tmp_path / "py"], out=tmp_path / "py_merged")
    whole = gw.sweep(case, vary)
    np.testing.assert_array_equal(merged.results, whole.results)
    assert list(merged.case_ids) == [0, 1, 2]
    ref = run_cli(cli, tmp_path, "sweep", case, "--vary", "operating.input_speed_hz=20:40:10")
    assert (tmp_path / "py_merged" / "sweep.csv").read_text() == (ref / "sweep.csv").read_text()
    # A rerun into the same folder skips every finished case.
    again = gw.sweep(case, vary, out=tmp_path / "py", shard=(1, 2))
    assert again.summary["skipped_finished"] == 2 and again.summary["computed"] == 0


def test_continuation_from_python():
    s = gw.sweep(gw.Case.paper(), {"operating.input_speed_hz": [30, 35]}, continuation="both")
    assert s.branches == ["up", "up", "down", "down"]
    with pytest.raises(gw.CaseError, match="`continuation`"):
        gw.sweep(gw.Case.paper(), {"operating.input_speed_hz": [30, 35]}, run="wear",
                 continuation="up")
