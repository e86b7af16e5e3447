"""Shared fixtures: the command-line binary built from the same tree (the reference the
binding is compared with), and the cases the tests use."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest

import gearwear as gw

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli() -> Path:
    """The `gearwear` binary: $GEARWEAR_CLI, else target/release/gearwear of this tree
    (`cargo build --release` makes it; python/ci.sh sets the variable)."""
    p = Path(os.environ.get("GEARWEAR_CLI", REPO / "target" / "release" / "gearwear"))
    if not p.is_file():
        pytest.fail(f"no gearwear binary at {p}: run `cargo build --release` or set GEARWEAR_CLI")
    return p


def run_cli(cli: Path, tmp: Path, command: str, case: gw.Case, *extra: str) -> Path:
    """Run `gearwear COMMAND --config CASE --out DIR -q ...` on `case`; return DIR."""
    cfg = tmp / f"{command}_case.toml"
    cfg.write_text(case.to_toml())
    out = tmp / f"{command}_out"
    subprocess.run(
        [str(cli), "-q", command, "--config", str(cfg), "--out", str(out), *extra],
        check=True,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        timeout=120,
    )
    return out


def cli_summary(cli: Path, tmp: Path, command: str, case: gw.Case, *extra: str) -> dict:
    out = run_cli(cli, tmp, command, case, *extra)
    return json.loads((out / "summary.json").read_text())


#: The paper's case, and another pair: module 3 mm, 25/50 teeth, 30 mm face width, at
#: 40 Hz and 100 N m.
CASES = {
    "paper": gw.Case.paper(),
    "m3_25_50": gw.Case.paper().set(
        {
            "gear.module_mm": 3,
            "gear.teeth_pinion": 25,
            "gear.teeth_gear": 50,
            "gear.face_width_mm": 30,
            "operating.input_speed_hz": 40,
            "operating.load_torque_nm": 100,
        }
    ),
}


@pytest.fixture(params=list(CASES), ids=list(CASES))
def case(request) -> gw.Case:
    return CASES[request.param]


def write_csv(path, columns):
    """The columns as CSV, every float in its shortest exact form (repr)."""
    names = list(columns)
    lines = [",".join(names)]
    for i in range(len(columns[names[0]])):
        lines.append(",".join(repr(float(columns[n][i])) for n in names))
    path.write_text("\n".join(lines) + "\n")
    return path
