"""gearwear.Case: building, reading, changing; CaseError for every class of problem,
each naming the key (and value and valid range where there is one)."""

import pickle
from pathlib import Path

import pytest

import gearwear as gw
from conftest import REPO


def test_paper_case_and_keys():
    c = gw.Case.paper()
    assert c == gw.Case()
    assert c["gear.module_mm"] == 2.0 and c["gear.teeth_pinion"] == 19
    assert c["gear.centre_distance_mm"] is None  # optional, unset
    assert c["friction.model"] == "xu2007"
    assert len(c.keys()) == len(gw.keys())
    assert {k["key"] for k in gw.keys()} == set(c.keys())
    assert c.to_dict()["operating.input_speed_hz"] == 30.0
    with pytest.raises(KeyError, match="gear.modul"):
        c["gear.modul"]


def test_set_returns_a_new_case():
    c = gw.Case.paper()
    c2 = c.set("operating.input_speed_hz", 45)
    assert c["operating.input_speed_hz"] == 30.0
    assert c2["operating.input_speed_hz"] == 45.0  # integers widen to floats, as --set
    assert c2 != c and c2.sha256 != c.sha256
    c3 = c.set({"gear.centre_distance_mm": 50.5, "friction.model": "constant"})
    assert c3["gear.centre_distance_mm"] == 50.5
    assert c3.set("gear.centre_distance_mm", None) == c.set("friction.model", "constant")
    import numpy as np

    assert c.set("gear.teeth_pinion", np.int64(20))["gear.teeth_pinion"] == 20
    assert c.set("wear.total_cycles", np.float64(1e5))["wear.total_cycles"] == 1e5


def test_toml_round_trips(tmp_path):
    c = gw.Case.paper().set({"operating.load_torque_nm": 80, "surface.roughness_table_rms_um": [0.3, 0.2, 0.1]})
    text = c.to_toml()
    assert gw.Case.from_toml(text) == c
    f = tmp_path / "case.toml"
    f.write_text(text)
    assert gw.Case.from_toml(f) == c and gw.Case.from_toml(str(f)) == c
    assert gw.Case.from_toml("[operating]\ninput_speed_hz = 45\n") == gw.Case.paper().set(
        "operating.input_speed_hz", 45
    )
    assert gw.Case.from_toml("") == gw.Case.paper()
    with pytest.raises(OSError, match="nope.toml"):
        gw.Case.from_toml(tmp_path / "nope.toml")
    assert pickle.loads(pickle.dumps(c)) == c
    assert eval(repr(c), {"gearwear": gw}) == c


def problems(exc_info):
    return exc_info.value.problems


def test_unknown_key_names_it_and_the_valid_ones():
    with pytest.raises(gw.CaseError) as e:
        gw.Case.paper().set("operating.speed_hz", 3)
    (p,) = problems(e)
    assert p.key == "operating.speed_hz"
    assert "operating.input_speed_hz" in p.valid
    with pytest.raises(gw.CaseError) as e:
        gw.Case.from_toml("[gears]\nmodule_mm = 2\n")
    assert problems(e)[0].key == "gears"


def test_wrong_type_names_key_value_and_range():
    with pytest.raises(gw.CaseError) as e:
        gw.Case.paper().set("operating.input_speed_hz", "fast")
    (p,) = problems(e)
    assert (p.key, p.value, p.valid) == ("operating.input_speed_hz", "fast", "a number in [1e-6, 1000]")
    with pytest.raises(gw.CaseError) as e:
        gw.Case.paper().set("gear.teeth_pinion", 19.5)
    assert problems(e)[0].key == "gear.teeth_pinion"
    assert isinstance(e.value, ValueError)


def test_out_of_range_lists_every_problem():
    with pytest.raises(gw.CaseError) as e:
        gw.Case.from_toml("[gear]\nmodule_mm = -2\npressure_angle_deg = 40\n[wear]\ncoefficient_m2_per_n = -1e-16\n")
    ps = {p.key: p for p in problems(e)}
    assert set(ps) == {"gear.module_mm", "gear.pressure_angle_deg", "wear.coefficient_m2_per_n"}
    assert ps["gear.module_mm"].value == -2.0
    assert ps["gear.pressure_angle_deg"].valid == "a number in [10, 35]"
    assert "3 problems" in str(e.value)
    assert ps["gear.module_mm"].to_dict()["key"] == "gear.module_mm"


def test_bad_choice_and_relation():
    with pytest.raises(gw.CaseError) as e:
        gw.Case.paper().set("friction.model", "coulomb")
    p = problems(e)[0]
    assert p.key == "friction.model" and p.value == "coulomb" and '"xu2007"' in p.valid
    with pytest.raises(gw.CaseError) as e:
        gw.Case.paper().set("lubricant.viscosity_cp", 0.8)
    assert problems(e)[0].key == "lubricant.viscosity_cp"


def test_inconsistent_geometry_is_found_by_the_study():
    """A centre distance below the sum of the base radii is valid key by key; the model
    refuses it (as the CLI does, exit 2), naming the key and the value."""
    c = gw.Case.paper().set("gear.centre_distance_mm", 40)
    for study in (gw.stiffness, gw.dynamics, gw.wear):
        with pytest.raises(gw.CaseError) as e:
            study(c)
        (p,) = problems(e)
        assert p.key == "gear.centre_distance_mm" and p.value == 40.0
        assert "base radii" in p.valid
    # Load sharing by paper eq. 7 needs a contact ratio below 2: asked for explicitly on a
    # deeper pair it is refused; the default ("auto") shares by stiffness there.
    deep = gw.Case.paper().set({"gear.addendum_coefficient": 1.5, "gear.dedendum_coefficient": 1.9,
                                "gear.pressure_angle_deg": 14.5, "gear.teeth_pinion": 40,
                                "gear.teeth_gear": 80})
    with pytest.raises(gw.CaseError) as e:
        gw.dynamics(deep.set("contact.load_sharing", "pedrero"))
    assert problems(e)[0].key == "contact.load_sharing"


def test_sweep_values_are_checked_before_running():
    with pytest.raises(gw.CaseError) as e:
        gw.sweep(gw.Case.paper(), {"operating.input_speed_hz": [-5, 30]})
    (p,) = problems(e)
    assert p.key == "operating.input_speed_hz" and p.value == -5.0
    with pytest.raises(gw.CaseError) as e:
        gw.sweep(gw.Case.paper(), {"operating.input_speed_hz": "30:20:5"})
    assert "operating.input_speed_hz" in str(e.value)
    with pytest.raises(ValueError, match="run"):
        gw.sweep(gw.Case.paper(), {"operating.input_speed_hz": [30]}, run="fast")


def test_not_a_case():
    with pytest.raises(TypeError, match="gearwear.Case"):
        gw.dynamics({"gear.module_mm": 2})
    with pytest.raises(ValueError, match="mode"):
        gw.wear(gw.Case.paper(), mode="static")


def test_repr_never_shows_a_case_as_another():
    # A two-stage train and a tooth fault live in arrays of tables that the flat keys do
    # not reach: their repr must not read as the paper's case (it did: "Case.paper()").
    train = gw.Case.from_toml(REPO / "examples" / "two_stage_reducer.toml")
    r = repr(train)
    assert r.startswith("<gearwear.Case:") and "[[stage]] x 2" in r, r
    assert train != gw.Case.paper()
    fault = gw.Case.from_toml('[[fault]]\nkind = "crack"\ngear = "pinion"\ntooth = 0\ncrack_depth_mm = 1\n')
    assert "[[fault]] x 1" in repr(fault), repr(fault)
    with_key = fault.set("operating.load_torque_nm", 80)
    assert '"operating.load_torque_nm": 80' in repr(with_key) and "[[fault]]" in repr(with_key)
    # What the flat keys do spell stays an expression that rebuilds the case.
    c = gw.Case.paper().set("operating.load_torque_nm", 80)
    assert eval(repr(c), {"gearwear": gw}) == c
