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


#: The size the other commands' tests ask for, and the documented one-panel default.
SIZE, DEFAULT = (1200, 500), (900, 420)


def scaled(w: int, h: int) -> tuple[int, int]:
    """A figure of default size (w, h) at SIZE: each side times SIZE / DEFAULT, rounded."""
    return round(w * SIZE[0] / DEFAULT[0]), round(h * SIZE[1] / DEFAULT[1])


def png_size(p: Path) -> tuple[int, int]:
    b = p.read_bytes()  # IHDR: width and height big-endian at bytes 16-23 (PNG spec 11.2.2)
    return int.from_bytes(b[16:20], "big"), int.from_bytes(b[20:24], "big")


def same_svgs_as_the_clis(py_out: Path, cli_png: Path) -> None:
    """Python's SVG-only folder against the CLI's default one: an SVG of the scaled size
    for each PNG, nothing else drawn, the data files the same bytes."""
    pngs = sorted(cli_png.glob("*.png"))
    assert pngs and not list(py_out.glob("*.png"))
    assert sorted(p.stem for p in py_out.glob("*.svg")) == [p.stem for p in pngs]
    for p in pngs:
        assert svg_size(py_out / f"{p.stem}.svg") == scaled(*png_size(p)), p.name
    for f in cli_png.glob("*.csv"):
        assert (py_out / f.name).read_bytes() == f.read_bytes(), f.name


def test_signals_sweep_and_load_spectrum_take_the_figure_options(tmp_path, cli):
    sig = CHEAP.set("signals.record_length", 0.5)
    gw.signals(sig, out=tmp_path / "sig", figures="svg", figure_size=SIZE)
    same_svgs_as_the_clis(tmp_path / "sig", run_cli(cli, tmp_path, "signals", sig))
    gw.sweep(CHEAP, {"operating.input_speed_hz": [25, 30]}, out=tmp_path / "sw", figures="svg", figure_size=SIZE)
    ref = run_cli(cli, tmp_path, "sweep", CHEAP, "--vary", "operating.input_speed_hz=25,30")
    same_svgs_as_the_clis(tmp_path / "sw", ref)
    history = {"time_s": [0.0, 1.0, 2.0, 3.0], "torque_nm": [20.0, 20.0, 80.0, 80.0], "input_speed_hz": [25.0] * 4}
    gw.load_spectrum(history, out=tmp_path / "ls", figures="svg", figure_size=SIZE)
    gw.load_spectrum(history, out=tmp_path / "ls_png")
    same_svgs_as_the_clis(tmp_path / "ls", tmp_path / "ls_png")


def test_a_calibration_asked_for_svg_only_embeds_svg_in_its_report():
    case = CHEAP.set(
        {
            "wear.points_per_profile": 31,
            "calibration.wear_coefficient_min_m2_per_n": 1.25e-16,
            "calibration.wear_coefficient_max_m2_per_n": 5e-16,
        }
    )
    obs = {"cycles": [1e4, 2e4], "max_wear_pinion_um": [1.5, 3.0], "sigma_max_wear_pinion_um": [0.2, 0.2]}
    r = gw.calibrate(case, obs, samples=100, check_runs=1, figures="svg")
    assert set(r.figures_svg) == {"posterior.svg", "posterior_band.svg"} and not r.figures_png
    html = r.report_html
    assert html.count('src="data:image/svg+xml;') == 2 and "data:image/png" not in html


def _design(tmp: Path) -> Path:
    d = tmp / "design.toml"
    d.write_text('set = ["signals.record_length=0.1"]\n[run_to_failure]\ncycles = [0]\n')
    return d


@pytest.mark.parametrize(
    "name, call",
    [
        ("sweep", lambda t, kw: gw.sweep(CHEAP, {"operating.input_speed_hz": [25]}, out=t / "never", **kw)),
        ("sweep_merge", lambda t, kw: gw.sweep_merge([t / "missing"], t / "never", **kw)),
        ("signals", lambda t, kw: gw.signals(CHEAP, out=t / "never", **kw)),
        ("load_spectrum", lambda t, kw: gw.load_spectrum(t / "missing.csv", out=t / "never", **kw)),
        ("calibrate", lambda t, kw: gw.calibrate(CHEAP, t / "missing.csv", out=t / "never", **kw)),
        ("predict", lambda t, kw: gw.predict(CHEAP, limit_um=10, cycles=1e5, out=t / "never", **kw)),
        ("predict_merge", lambda t, kw: gw.predict_merge([t / "missing"], t / "never", **kw)),
        ("dataset", lambda t, kw: gw.dataset(_design(t), t / "never", **kw)),
        ("dataset_merge", lambda t, kw: gw.dataset_merge([t / "missing"], t / "never", **kw)),
    ],
)
def test_every_function_that_draws_refuses_bad_figure_options(tmp_path, name, call):
    for kw, needles in [
        ({"figures": "gif"}, ["figures", "gif", "png, svg or png,svg"]),
        ({"figure_size": (10, 800)}, ["figure_size", "10x800", "[400, 8192]", "[200, 4096]"]),
    ]:
        with pytest.raises(gw.CaseError) as e:
            call(tmp_path, kw)
        for n in needles:
            assert n in str(e.value), (name, str(e.value))
        assert not (tmp_path / "never").exists(), name
