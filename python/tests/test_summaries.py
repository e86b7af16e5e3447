"""Each study's summary equals the command line's summary.json for the same case: the
same keys and the same floats (compared exactly: serde_json writes the shortest form that
reads back to the same double, so any difference would be a real one)."""

import json

import pytest

import gearwear as gw
from conftest import cli_summary, run_cli


@pytest.mark.parametrize("study", ["stiffness", "dynamics", "wear"])
def test_summary_equals_cli(cli, tmp_path, case, study):
    py = getattr(gw, study)(case).summary
    ref = cli_summary(cli, tmp_path, study, case)
    assert py == ref
    # The metadata names the same resolved case.
    assert py["metadata"]["case_sha256"] == case.sha256


def test_wear_single_mode_equals_cli(cli, tmp_path):
    case = gw.Case.paper()
    py = gw.wear(case, mode="quasi_static").summary
    assert py == cli_summary(cli, tmp_path, "wear", case, "--mode", "quasi-static")
    assert py["max_wear_pinion_um"]["dynamic"] is None


def test_dynamics_with_transmission_error_equals_cli(cli, tmp_path):
    """The same error given as a CSV file to the CLI and as an array to Python."""
    import numpy as np

    case = gw.Case.paper()
    period_deg = 360.0 / case["gear.teeth_pinion"]
    angle = np.linspace(0.0, period_deg, 41)
    error = 2.0 * np.sin(2 * np.pi * angle / period_deg)
    csv = tmp_path / "te.csv"
    csv.write_text(
        "pinion_angle_deg,error_um\n"
        + "".join(f"{a!r},{e!r}\n" for a, e in zip(angle.tolist(), error.tolist()))
    )
    te = np.column_stack([angle, error])
    py = gw.dynamics(case, transmission_error=te).summary
    ref = cli_summary(cli, tmp_path, "dynamics", case, "--transmission-error", str(csv))
    assert py == ref
    # The error changes the response (it is used at all).
    assert py["dte"] != gw.dynamics(case).summary["dte"]


def test_run_writes_the_cli_output_set(cli, tmp_path):
    """`run(case, out)` publishes the same files, byte for byte (the manifests list each
    file with its SHA-256), and its summary is the CLI's."""
    case = gw.Case.paper()
    ours = tmp_path / "py_run"
    r = gw.run(case, out=ours)
    ref = run_cli(cli, tmp_path, "run", case)
    m_py = json.loads((ours / "manifest.json").read_text())
    m_cli = json.loads((ref / "manifest.json").read_text())
    assert m_py["files"] == m_cli["files"]
    assert m_py["state_files"] == m_cli["state_files"]
    assert r.summary == json.loads((ref / "summary.json").read_text())
    assert set(r.figures_png) == {f["path"] for f in m_cli["files"] if f["path"].endswith(".png")}
    assert r.report_html == (ref / "report.html").read_text()
