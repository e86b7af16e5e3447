"""Calibration and prediction from Python give the command line's numbers: the same job of
the library runs under both, so the summaries are equal (every float compared exactly:
serde_json writes the shortest form that reads back to the same double). Observations and
posterior samples go in as numpy arrays or pandas DataFrames directly."""

import json
import subprocess

import numpy as np
import pytest

import gearwear as gw
from conftest import run_cli, write_csv

#: A short sampler run: the numbers need not be converged to be compared.
SAMPLER = {"seed": 3, "samples": 300, "steps": 200, "check_runs": 1}


@pytest.fixture(scope="module")
def observations():
    """Measurements of the paper's gearbox at a "true" wear coefficient of 4e-16 m^2/N:
    every second update of a dynamic wear study to 4e4 cycles, the wear 2 % high with a
    stated sigma, the vibration as computed (its noise is inferred)."""
    truth = gw.Case.paper().set({"wear.coefficient_m2_per_n": 4e-16, "wear.total_cycles": 4e4})
    run = gw.wear(truth, mode="dynamic").dynamic
    rows = slice(1, None, 2)
    return {
        "cycles": run.cycles[rows],
        "max_wear_pinion_um": run.max_wear_pinion_um[rows] * 1.02,
        "velocity_y_pinion_rms_mm_per_s": run.updates["velocity_y_pinion_rms_mm_per_s"][rows],
        "sigma_max_wear_pinion_um": np.full(len(run.cycles[rows]), 0.2),
    }


def cli_json(out, name="summary.json"):
    return json.loads((out / name).read_text())


@pytest.fixture(scope="module")
def calibrated(cli, tmp_path_factory, observations):
    """The calibration from Python (observations as a pandas DataFrame) and from the CLI
    (the same numbers in a CSV file)."""
    pd = pytest.importorskip("pandas")
    tmp = tmp_path_factory.mktemp("cal")
    case = gw.Case.paper()
    py = gw.calibrate(case, pd.DataFrame(observations), **SAMPLER)
    csv = write_csv(tmp / "obs.csv", observations)
    args = [f"--{k.replace('_', '-')}={v}" for k, v in SAMPLER.items()]
    out = run_cli(cli, tmp, "calibrate", case, "--observations", str(csv), *args)
    return py, out


def test_calibrate_equals_cli(calibrated):
    py, out = calibrated
    assert isinstance(py, gw.CalibrationResult)
    assert py.summary == cli_json(out)
    # The posterior samples too, to the last bit.
    ref = np.genfromtxt(out / "posterior_samples.csv", delimiter=",", names=True)
    for name in py.samples.columns:
        np.testing.assert_array_equal(py.samples[name], ref[name])
    k = py.parameters["wear_coefficient_m2_per_n"]
    assert k["ci90"][0] < k["median"] < k["ci90"][1]
    assert py.report_html.startswith("<!DOCTYPE html>")
    assert set(py.figures_png) == {"posterior.png", "posterior_band.png"}


def test_observations_as_numpy_give_the_same_posterior(calibrated, observations):
    py, _ = calibrated
    case = gw.Case.paper()
    names = list(observations)
    table = np.column_stack([observations[n] for n in names])
    as_array = gw.calibrate(case, table, columns=names, **SAMPLER)
    assert as_array.summary == py.summary
    structured = np.rec.fromarrays([observations[n] for n in names], names=names)
    assert gw.calibrate(case, structured, **SAMPLER).summary == py.summary


def test_predict_equals_cli(cli, tmp_path, calibrated):
    """The posterior of the calibration goes into predict as the result itself: the same
    samples, the same identity (the SHA-256 of their CSV form), the same numbers."""
    cal, cal_out = calibrated
    case = gw.Case.paper()
    py = gw.predict(case, cal, limit_um=10, cycles=1e5, seed=2, check_runs=1)
    assert isinstance(py, gw.PredictionResult)
    out = run_cli(
        cli,
        tmp_path,
        "predict",
        case,
        "--posterior",
        str(cal_out / "posterior_samples.csv"),
        "--limit-um=10",
        "--cycles=1e5",
        "--seed=2",
        "--check-runs=1",
    )
    assert py.summary == cli_json(out)
    assert py.life["median"] is None or py.life["p05"] <= py.life["median"]
    # From the prior, sharded and merged, against the CLI's shards and merge.
    shards = [
        gw.predict(case, limit_um=10, cycles=1e5, samples=40, shard=(i, 2), out=tmp_path / "py")
        for i in (1, 2)
    ]
    assert all(s.out == tmp_path / "py" for s in shards)
    merged = gw.predict_merge([tmp_path / "py"])
    whole = gw.predict(case, limit_um=10, cycles=1e5, samples=40)
    for key in ("remaining_life_cycles", "at_horizon", "source", "samples"):
        assert merged.summary[key] == whole.summary[key], key


def test_bad_inputs_name_the_python_argument(observations):
    case = gw.Case.paper()
    with pytest.raises(gw.CaseError, match="`samples`"):
        gw.calibrate(case, observations, samples=0)
    with pytest.raises(gw.CaseError, match="`limit_um`") as e:
        gw.predict(case, limit_um=-1, cycles=1e5)
    assert "--" not in str(e.value)
    bad = dict(observations, cycles=observations["cycles"][::-1].copy())
    with pytest.raises(gw.CaseError, match="non-decreasing"):
        gw.calibrate(case, bad, **SAMPLER)
    with pytest.raises(TypeError, match="observations"):
        gw.calibrate(case, 42)


def test_predict_with_a_future_spectrum_equals_cli(cli, tmp_path):
    """A future duty given as TOML text from Python and as a file to the CLI: the same
    resolved spectrum in the identity, the same summary to the last bit."""
    bins = (
        "bins = [{torque_nm = 40, input_speed_hz = 20, share = 0.5}, "
        "{torque_nm = 60, input_speed_hz = 30, share = 0.5}]\n"
    )
    text = (
        "[numerics]\nsteps_per_mesh_period = 60\nevaluated_mesh_periods = 2\n"
        "[wear]\npoints_per_profile = 31\n[load_spectrum]\n" + bins
    )
    case = gw.Case.from_toml(text)
    # The case file as written (Case.to_toml does not write a spectrum's bins).
    (tmp_path / "case.toml").write_text(text)
    k0 = case["wear.coefficient_m2_per_n"]
    post = tmp_path / "post.csv"
    post.write_text(f"sample,wear_coefficient_m2_per_n\n0,{2 * k0!r}\n1,{2.5 * k0!r}\n")
    future = "[load_spectrum]\n" + bins + "torque_scale = 1.3\n"
    (tmp_path / "future.toml").write_text(future)
    common = {"limit_um": 4, "cycles": 3e4, "check_runs": 1, "grid_points": 11}
    py = gw.predict(case, post, future_spectrum=future, future_from_cycles=1e4, **common)
    out = tmp_path / "cli"
    subprocess.run(
        [str(cli), "-q", "predict", "--config", str(tmp_path / "case.toml"), "--out", str(out),
        "--posterior",
        str(post),
        "--limit-um=4",
        "--cycles=3e4",
        "--check-runs=1",
        "--grid-points=11",
        "--future-spectrum",
        str(tmp_path / "future.toml"),
        "--future-from-cycles=1e4"],
        check=True,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        timeout=120,
    )
    assert py.summary == cli_json(out)
    assert py.summary["future_duty"]["from_cycles"] == 1e4
    assert py.summary["future_duty"]["load_spectrum"]["torque_scale"] == 1.3
    # A path gives the same; bad values name the Python argument.
    by_path = gw.predict(
        case, post, future_spectrum=tmp_path / "future.toml", future_from_cycles=1e4, **common
    )
    assert by_path.summary["remaining_life_cycles"] == py.summary["remaining_life_cycles"]
    with pytest.raises(gw.CaseError, match="`future_from_cycles`"):
        gw.predict(case, post, future_spectrum=future, **common)
    with pytest.raises(gw.CaseError, match="`future_spectrum`") as e:
        gw.predict(case, post, future_spectrum="[load_spectrum]\nbins = []\n", future_from_cycles=1e4, **common)
    assert "--" not in str(e.value)
