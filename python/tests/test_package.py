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
    assert "um" in gearwear.dynamics.__doc__ and "deg" in gearwear.dynamics.__doc__
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
