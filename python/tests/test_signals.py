"""The signal studies from Python: the same summaries and files as the command line."""

import json
import subprocess

import numpy as np
import pytest

import gearwear as gw
from conftest import cli_summary


def _case() -> gw.Case:
    return gw.Case.paper().set("signals.record_length", 0.25).set("signals.snr_db", 30.0)


def test_signals_equals_cli_and_holds_the_record(cli, tmp_path):
    case = _case()
    r = gw.signals(case)
    assert r.summary == cli_summary(cli, tmp_path, "signals", case)
    rec = r.record
    assert rec.columns == ["time_s", "input_m_per_s2", "output_m_per_s2", "tachometer_v"]
    assert len(rec["time_s"]) == int(0.25 * r.sampling_rate_hz)
    assert r.channel_unit == "m/s^2"
    ind = r.indicators[0]
    assert ind["channel"] == "input" and ind["pinion"]["revolutions"] >= 6
    # The tachometer swings between 0 and 5 V (its filtered edges ring a little beyond).
    tach = rec["tachometer_v"]
    assert -0.5 < tach.min() < 0.5 and 4.5 < tach.max() < 5.5


def test_dataset_and_merge_from_python_equal_the_cli(cli, tmp_path):
    design = tmp_path / "design.toml"
    design.write_text(
        'seed = 3\nset = ["signals.record_length=0.1", "signals.snr_db=30", '
        '"numerics.steps_per_mesh_period=60", "stiffness.table_points_per_mesh_period=60"]\n'
        "[run_to_failure]\ncycles = [0, 5000]\nmax_cycles = 5000\n"
        "[records]\nnoise_realisations = 2\n"
    )
    py_out = tmp_path / "py"
    r = gw.dataset(design, py_out)
    assert r.summary["records"] == 4 and r.summary["computed"] == 4
    assert r.index_path is not None
    ref = tmp_path / "cli"
    subprocess.run(
        [str(cli), "-q", "dataset", "--design", str(design), "--out", str(ref)],
        check=True,
        timeout=300,
    )
    for f in ["index.csv", "index.parquet", "metadata.json", "signals/0000003.parquet"]:
        assert (py_out / f).read_bytes() == (ref / f).read_bytes(), f
    # Two shards from Python, merged: the same dataset.
    for i in (1, 2):
        gw.dataset(design, tmp_path / f"s{i}", shard=(i, 2))
    # The merge's check of every record is counted first: over a vanishing budget it is
    # refused before any work, and no folder is made.
    with pytest.raises(gw.CaseError, match="over its budget"):
        gw.dataset_merge([tmp_path / "s1", tmp_path / "s2"], tmp_path / "refused", budget_scale=1e-9)
    assert not (tmp_path / "refused").exists()
    m = gw.dataset_merge([tmp_path / "s1", tmp_path / "s2"], tmp_path / "merged")
    assert m.summary["missing"] == []
    assert (tmp_path / "merged" / "index.parquet").read_bytes() == (ref / "index.parquet").read_bytes()
    meta = json.loads((ref / "metadata.json").read_text())
    assert meta["records_present"] == 4
    idx = np.genfromtxt(ref / "index.csv", delimiter=",", names=True, dtype=None, encoding="utf-8")
    assert list(idx["cycles"]) == [0.0, 0.0, 5000.0, 5000.0]


def test_dataset_design_as_text_dict_or_case_gives_the_file_designs_records(tmp_path):
    """A design given as TOML text, as a dict, or as a dict whose ``case`` is a Case
    object builds the records a design file builds: the same signals, byte for byte."""
    sets = ["signals.record_length=0.1", "numerics.steps_per_mesh_period=60",
            "stiffness.table_points_per_mesh_period=60"]
    text = (
        "seed = 5\nset = " + json.dumps(sets) + "\n"
        "[run_to_failure]\ncycles = [0, 4000]\nmax_cycles = 4000\n"
        "[[condition]]\nname = \"healthy\"\n"
        "[[condition]]\nname = \"cracked\"\nfault = \"crack\"\n"
        "[[condition.case.fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 0\n"
        "crack_depth_mm = 1.0\n"
    )
    design = tmp_path / "design.toml"
    design.write_text(text)
    as_dict = {
        "seed": 5,
        "set": sets,
        "run_to_failure": {"cycles": [0, 4000], "max_cycles": 4000},
        "condition": [
            {"name": "healthy"},
            {"name": "cracked", "fault": "crack",
             "case": {"fault": [{"kind": "crack", "gear": "pinion", "tooth": 0,
                                 "crack_depth_mm": 1.0}]}},
        ],
    }
    with_case = dict(as_dict, case=gw.Case.paper())
    outs = {
        "file": gw.dataset(design, tmp_path / "file"),
        "text": gw.dataset(text, tmp_path / "text"),
        "dict": gw.dataset(as_dict, tmp_path / "dict"),
        "case": gw.dataset(with_case, tmp_path / "case"),
    }
    assert all(r.summary["records"] == 4 for r in outs.values())
    ref = sorted((tmp_path / "file" / "signals").iterdir())
    assert len(ref) == 4
    for name in ("text", "dict", "case"):
        got = sorted((tmp_path / name / "signals").iterdir())
        assert [p.name for p in got] == [p.name for p in ref], name
        for a, b in zip(got, ref):
            assert a.read_bytes() == b.read_bytes(), (name, a.name)


def test_dataset_design_given_wrongly_is_refused_by_name(tmp_path):
    with pytest.raises(TypeError, match="design"):
        gw.dataset(3, tmp_path / "never")
    with pytest.raises(gw.CaseError, match="unknown field `run_to_failur`"):
        gw.dataset({"run_to_failur": {"states": 2}}, tmp_path / "never")
    assert not (tmp_path / "never").exists()


def test_dataset_merge_takes_the_transfer_path_its_design_was_made_with(tmp_path):
    """A merge recomputes a sample of its inputs' records, so a design with a transfer-path
    file needs that file (checked against the hash the shard keeps): refused without it,
    nothing written; merged with it, to the input's own index."""
    (tmp_path / "path.toml").write_text(
        'sensors = ["a"]\n[[mode]]\nfrequency_hz = 2100\ndamping_ratio = 0.02\n'
        "gains_per_kg = [[0.0075, 0.025, 0.005, 0.02]]\n"
    )
    design = tmp_path / "design.toml"
    design.write_text(
        'transfer_path = "path.toml"\nseed = 3\nset = ["signals.record_length=0.1"]\n'
        "[run_to_failure]\nstates = 2\nmax_cycles = 1e4\nwear_limit_um = 10\n"
        "[records]\nnoise_realisations = 1\n"
    )
    gw.dataset(design, tmp_path / "ds")
    with pytest.raises(ValueError, match="as its transfer path"):
        gw.dataset_merge([tmp_path / "ds"], tmp_path / "m1")
    assert not (tmp_path / "m1").exists()
    gw.dataset_merge([tmp_path / "ds"], tmp_path / "m2", transfer_path=tmp_path / "path.toml")
    assert (tmp_path / "m2" / "index.csv").read_bytes() == (tmp_path / "ds" / "index.csv").read_bytes()
