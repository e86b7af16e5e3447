"""Calibration and prediction of a gear train (``[[stage]]``) from Python: observations
name the mesh by a ``stage`` column, and the job is the command line's (equal summaries,
posterior samples to the last bit). The observations are the train's own wear study at a
known wear coefficient, made in Python; the posterior must hold that coefficient."""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest

import gearwear as gw
from conftest import REPO, run_cli, write_csv

#: The wear coefficient the synthetic observations are made at, m^2/N.
K0 = 2.5e-16

#: Coarser numerics than the defaults (the plumbing is under test, not the physics) and a
#: prior of k over [k0 / 2, 2 k0].
CHEAP = {
    "numerics.steps_per_mesh_period": 60,
    "numerics.evaluated_mesh_periods": 2,
    "wear.points_per_profile": 31,
    "wear.coefficient_m2_per_n": K0,
    "wear.total_cycles": 2e4,
    "calibration.wear_coefficient_min_m2_per_n": K0 / 2,
    "calibration.wear_coefficient_max_m2_per_n": 2 * K0,
}

#: A short sampler run: the numbers need not be converged to be compared with the CLI.
SAMPLER = {"seed": 5, "samples": 301, "check_runs": 0}


def _quiet(f, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", gw.GearwearWarning)
        return f(*args, **kwargs)


@pytest.fixture(scope="module")
def case() -> gw.Case:
    return gw.Case.from_toml(REPO / "examples" / "two_stage_reducer.toml").set(CHEAP)


@pytest.fixture(scope="module")
def observations(case):
    """Stage 2's maximum pinion wear at every update of the train's dynamic wear study
    (input cycles), noise-free, given a sigma of 0.02 um."""
    h = _quiet(gw.wear, case, mode="dynamic").history("dynamic")
    rows = (h["stage"] == 2) & (h["input_cycles"] > 0)
    wear = np.asarray(h["max_wear_pinion_um"], dtype=float)[rows]
    assert len(wear) >= 3 and np.all(np.diff(wear) >= 0) and wear[-1] > 0
    return {
        "cycles": np.asarray(h["input_cycles"], dtype=float)[rows],
        "stage": np.asarray(h["stage"], dtype=float)[rows],
        "max_wear_pinion_um": wear,
        "sigma_max_wear_pinion_um": np.full(len(wear), 0.02),
    }


@pytest.fixture(scope="module")
def calibrated(cli, tmp_path_factory, case, observations):
    pd = pytest.importorskip("pandas")
    tmp = tmp_path_factory.mktemp("train_cal")
    py = _quiet(gw.calibrate, case, pd.DataFrame(observations), **SAMPLER)
    obs = write_csv(tmp / "obs.csv", observations)
    args = [f"--{k.replace('_', '-')}={v}" for k, v in SAMPLER.items()]
    out = run_cli(cli, tmp, "calibrate", case, "--observations", str(obs), *args)
    return py, out


def test_train_calibration_equals_cli_and_holds_k0(calibrated):
    py, out = calibrated
    assert py.summary == json.loads((out / "summary.json").read_text())
    assert py.summary["observations"][0]["quantity"] == "max_wear_pinion_um_stage2"
    ref = np.genfromtxt(out / "posterior_samples.csv", delimiter=",", names=True)
    for name in py.samples.columns:
        np.testing.assert_array_equal(py.samples[name], ref[name])
    # Noise-free observations of the train's own wear at k0: the 90 % interval holds k0
    # (a posterior of a few per cent spread; k read against the wrong cycles, e.g. stage
    # 2's own pinion cycles instead of input cycles, would put k0 off by 31/19).
    k = py.parameters["wear_coefficient_m2_per_n"]
    assert k["ci90"][0] < K0 < k["ci90"][1], k
    assert abs(k["median"] / K0 - 1) < 0.05, k


def test_train_prediction_equals_cli(cli, tmp_path, case, calibrated):
    cal, cal_out = calibrated
    extra = {"limit_um": 50, "cycles": 2e4, "grid_points": 11, "check_runs": 0}
    py = _quiet(gw.predict, case, cal, **extra)
    args = [f"--{k.replace('_', '-')}={v}" for k, v in extra.items()]
    out = run_cli(
        cli, tmp_path, "predict", case, "--posterior", str(cal_out / "posterior_samples.csv"), *args
    )
    assert py.summary == json.loads((out / "summary.json").read_text())
