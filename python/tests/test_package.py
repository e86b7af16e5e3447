"""The typing stub matches the native module; the examples run."""

import ast
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import gearwear
import gearwear._gearwear as native

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent / "examples"


def stub_names(tree):
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return names


def test_stub_lists_the_native_module():
    stub = Path(gearwear.__file__).with_name("_gearwear.pyi")
    assert stub.is_file() and Path(gearwear.__file__).with_name("py.typed").is_file()
    tree = ast.parse(stub.read_text())
    public = {n for n in dir(native) if not n.startswith("__") or n == "__version__"}
    assert stub_names(tree) == public
    case_stub = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Case")
    methods = {n.name for n in case_stub.body if isinstance(n, ast.FunctionDef)}
    assert {m for m in dir(native.Case) if not m.startswith("_")} <= methods


def test_public_functions_have_docstrings_with_units():
    for name in ("stiffness", "dynamics", "wear", "run", "sweep"):
        doc = getattr(gearwear, name).__doc__
        assert doc and f"gearwear {name}" in doc
    assert "µm" in gearwear.dynamics.__doc__ and "deg" in gearwear.dynamics.__doc__
    assert "Valid" in gearwear.Case.paper().to_toml()


def test_example_script_runs(tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg")
    subprocess.run(
        [sys.executable, str(EXAMPLES / "fig13_and_speed_sweep.py"), "--out", str(tmp_path)],
        check=True,
        env=env,
        timeout=300,
    )
    for png in ("fig13_max_accumulated_wear.png", "speed_sweep.png"):
        assert (tmp_path / png).stat().st_size > 10_000


def test_notebook_is_valid_and_runs(tmp_path, monkeypatch):
    nb = json.loads((EXAMPLES / "fig13_and_speed_sweep.ipynb").read_text())
    assert nb["nbformat"] == 4
    nbformat = pytest.importorskip("nbformat")
    nbformat.validate(nbformat.reads(json.dumps(nb), as_version=4))
    # Its code cells, in order, run headless.
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    code = "\n".join(
        "".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"
    )
    exec(compile(code, "notebook", "exec"), {"__name__": "__notebook__"})


def test_dir_shows_the_public_api_only():
    assert dir(gearwear) == sorted(gearwear.__all__)
    for name in gearwear.__all__:
        assert hasattr(gearwear, name), name
    # Every study of the command line, each documented with its command.
    for name, command in [("sweep_merge", "sweep-merge"), ("calibrate", "calibrate"),
                          ("predict", "predict"), ("predict_merge", "predict-merge")]:
        assert f"gearwear {command}" in getattr(gearwear, name).__doc__


def test_results_are_named_objects_not_tuples():
    case = gearwear.Case.paper()
    s = gearwear.sweep(case, {"operating.input_speed_hz": [25, 30]})
    assert isinstance(s, gearwear.SweepResult) and not isinstance(s, tuple)
    assert s.keys == ["operating.input_speed_hz"] and s.branches == [None, None]
    assert s.summary["rows"] == 2 and s.headline.startswith("sweep: 2 rows")
    d = gearwear.dynamics(case)
    assert isinstance(d, gearwear.DynamicsResult) and d.out is None and d.incomplete is None


def test_the_run_budget_applies_and_is_raised_by_argument():
    """The budget of the command line holds in Python too, named in Python's terms."""
    big = gearwear.Case.paper().set("numerics.evaluated_mesh_periods", 1e5)
    with pytest.raises(gearwear.CaseError) as e:
        gearwear.dynamics(big)
    msg = str(e.value)
    assert "over its budget" in msg and "`budget_scale`" in msg and "--" not in msg
    with pytest.raises(ValueError, match="budget_scale"):
        gearwear.dynamics(gearwear.Case.paper(), budget_scale=0)
