"""Figure formats and size from Python (`figures=`, `figure_size=`): the same files as the
CLI's `--figures`/`--figure-size`, sizes read from the files themselves; bad values raise
CaseError naming the keyword argument, the value and the valid range, before any output."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import gearwear as gw

from conftest import run_cli

#: Coarse grids, two evaluated mesh periods (tests/common CHEAP): a cheap case.
CHEAP = gw.Case.paper().set(
    {
        "numerics.steps_per_mesh_period": 60,
        "numerics.evaluated_mesh_periods": 2,
        "stiffness.table_points_per_mesh_period": 60,
    }
)


def svg_size(p: Path) -> tuple[int, int]:
    root = re.search(r"<svg\b[^>]*>", p.read_text()).group(0)
    return int(re.search(r' width="(\d+)"', root).group(1)), int(re.search(r' height="(\d+)"', root).group(1))


def test_svg_of_the_requested_size_as_the_cli_writes(tmp_path, cli):
    out = tmp_path / "py"
    gw.dynamics(CHEAP, out=out, figures="svg", figure_size=(1200, 800))
    svgs = sorted(p.name for p in out.glob("*.svg"))
    assert svgs and not list(out.glob("*.png"))
    # Every figure of `dynamics` is one panel: each has exactly the size asked for.
    assert all(svg_size(out / n) == (1200, 800) for n in svgs)
    ref = run_cli(cli, tmp_path, "dynamics", CHEAP, "--figures", "svg", "--figure-size", "1200x800")
    assert svgs == sorted(p.name for p in ref.glob("*.svg"))


@pytest.mark.parametrize(
    "kw, needles",
    [
        ({"figures": "gif"}, ["figures", "gif", "png, svg or png,svg"]),
        ({"figure_size": (10, 800)}, ["figure_size", "10x800", "[400, 8192]", "[200, 4096]"]),
        ({"figure_size": (1600, 9000)}, ["figure_size", "1600x9000", "[200, 4096]"]),
    ],
)
def test_bad_figure_options_raise_naming_argument_value_and_range(tmp_path, kw, needles):
    out = tmp_path / "never"
    with pytest.raises(gw.CaseError) as e:
        gw.stiffness(CHEAP, out=out, **kw)
    for n in needles:
        assert n in str(e.value)
    assert not out.exists()
