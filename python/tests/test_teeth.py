"""Per-tooth inputs (docs/MODEL.md section 9) set from Python reach the studies as the
command line's case file does: the same summaries (compared exactly) and the per-tooth
tables with each tooth's inputs."""

import numpy as np
import pytest

import gearwear as gw
from conftest import cli_summary

#: Pinion tooth 3 stands 5 um proud: the excitation repeats every pinion revolution (19
#: mesh periods). Coarse grids keep the tooth-resolved wear study short.
PITCH = [0.0] * 19
PITCH[3] = 5.0
CASE = gw.Case.paper().set(
    {
        "teeth.pitch_error_pinion_um": PITCH,
        "numerics.steps_per_mesh_period": 60,
        "stiffness.table_points_per_mesh_period": 60,
        "wear.total_cycles": 1e4,
    }
)


@pytest.mark.parametrize("study", ["dynamics", "wear"])
def test_per_tooth_keys_give_the_command_lines_summary(cli, tmp_path, study):
    extra = ("--mode", "dynamic") if study == "wear" else ()
    kwargs = {"mode": "dynamic"} if study == "wear" else {}
    r = getattr(gw, study)(CASE, **kwargs)
    assert r.summary == cli_summary(cli, tmp_path, study, CASE, *extra)
    teeth = r.summary["teeth"]
    assert teeth["excitation_mesh_periods"] == 19
    assert teeth["hunting_mesh_periods"] == 589
    # The inputs, and the single pitch deviations as differences of neighbouring positions.
    t = r.tables["teeth_pinion"]
    assert t["position_error_um"].tolist() == PITCH
    want = np.array(PITCH) - np.roll(PITCH, 1)
    assert t["single_pitch_deviation_um"].tolist() == want.tolist()


def test_a_per_tooth_array_of_the_wrong_length_names_both_lengths():
    # Refused when the case is made (or at the latest when a study starts).
    with pytest.raises(gw.CaseError) as e:
        gw.dynamics(gw.Case.paper().set("teeth.pitch_error_gear_um", [1.0, 2.0, 3.0]))
    text = str(e.value)
    assert "teeth.pitch_error_gear_um" in text and "3 values" in text and "31" in text
