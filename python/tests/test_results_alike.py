"""Results without holes (what a user met): the duty tables of a run and of a wear study
under the same spectrum carry the same names and the same rankings, columns that count
things come back as integers, and the package's `data` extra brings pandas and pyarrow."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

import gearwear as gw
from test_duty import square_wave

CHEAP = {
    "wear.total_cycles": 1e4,
    "numerics.steps_per_mesh_period": 60,
    "numerics.evaluated_mesh_periods": 2,
    "stiffness.table_points_per_mesh_period": 60,
}


@pytest.fixture(scope="module")
def studies():
    spectrum = gw.load_spectrum(square_wave(), interpolation="hold")
    case = spectrum.apply(gw.Case.paper().set(CHEAP)).set("load_spectrum.life_wear_limit_um", 1.0)
    return gw.run(case), gw.wear(case)


def test_run_and_wear_name_the_duty_tables_alike(studies):
    run, wear = studies
    for result in (run, wear):
        for mode in ("dynamic", "quasi_static", "quasi-static"):
            ranking = result.duty.ranking(mode)
            assert ranking.n_rows == 2
            assert f"duty_bins_{mode.replace('-', '_')}" in result.tables
            assert result.duty.wear_by_bin(mode).n_rows > 0
    # The same spectrum runs in both studies: the same bins ranked in the same order,
    # with the same shares of the wear.
    for mode in ("dynamic", "quasi_static"):
        a, b = run.duty.ranking(mode), wear.duty.ranking(mode)
        assert np.array_equal(a["bin"], b["bin"])
        assert np.array_equal(a["share_of_pinion_wear"], b["share_of_pinion_wear"])
    with pytest.raises(KeyError, match="no 'sideways' run"):
        run.duty.ranking("sideways")


def test_columns_that_count_are_integers(studies):
    _, wear = studies
    ranking = wear.duty.ranking("dynamic")
    for column in ("rank", "bin"):
        assert ranking[column].dtype == np.int64, column
    # Ranks 1..n and each bin once.
    assert sorted(ranking["rank"].tolist()) == [1, 2]
    assert sorted(ranking["bin"].tolist()) == [1, 2]
    # Measured quantities stay floats.
    assert ranking["share_of_pinion_wear"].dtype == np.float64
    assert wear.tables["updates_dynamic"]["update"].dtype == np.int64
    pd = pytest.importorskip("pandas")
    frame = ranking.to_pandas()
    assert isinstance(frame, pd.DataFrame)
    assert frame["rank"].dtype == np.int64 and frame["share_of_cycles"].dtype == np.float64


def test_run_and_wear_under_a_spectrum_give_the_same_life(studies):
    run, wear = studies
    for result in (run, wear):
        assert result.duty.life is not None and result.duty.life.n_rows > 0
    # The same life runs: the same cycles and hours to the limit.
    assert run.duty.summary["life"] == wear.duty.summary["life"]
    assert wear.duty.summary["life"]["spectrum_hours"] > 0


def test_the_data_extra_brings_pandas_and_pyarrow():
    pyproject = Path(__file__).resolve().parents[1] / "pyproject.toml"
    text = pyproject.read_text()
    m = re.search(r"^data\s*=\s*\[([^\]]*)\]", text, re.MULTILINE)
    assert m, "no data extra in pyproject.toml"
    names = {re.split(r"[<>=!~ ]", s.strip().strip('"'))[0] for s in m.group(1).split(",")}
    assert {"pandas", "pyarrow"} <= names, names
