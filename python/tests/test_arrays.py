"""The arrays have the documented shapes and units; checked against the case that made
them (time step, mesh period, profile points) and against the summary."""

import numpy as np
import pytest

import gearwear as gw


def test_dynamics_signals(case):
    d = gw.dynamics(case)
    # The error control adds steps to the grid nodes, which are all recorded.
    n = len(d.time_s)
    assert n >= case["numerics.evaluated_mesh_periods"] * case["numerics.steps_per_mesh_period"]
    for a in (d.time_s, d.mesh_phase_rad, d.dte_um, d.mesh_force_n, d.mesh_stiffness_n_per_m):
        assert a.shape == (n,) and a.dtype == np.float64
    for a in (d.displacement, d.velocity, d.acceleration):
        assert a.shape == (n, 8)
    for a in (d.friction_coefficient, d.friction_force_n, d.pair_load_n):
        assert a.shape == (n, 2)
    # Units: time in s. The samples cover the recorded mesh periods of 1 / (z1 f_in) s
    # each (the last sample is one step before the window's end), and no step is longer
    # than the grid's node spacing, at most twice the mean (its nodes sit on the mesh
    # events); 1e-9 relative allows for the rounding of accumulated time.
    steps = case["numerics.steps_per_mesh_period"]
    periods = case["numerics.evaluated_mesh_periods"]
    mesh_period_s = 1.0 / (case["gear.teeth_pinion"] * case["operating.input_speed_hz"])
    assert d.summary["steady_state"]["mesh_period_s"] == pytest.approx(mesh_period_s, rel=1e-12)
    span = d.time_s[-1] - d.time_s[0]
    assert (periods - 1) * mesh_period_s < span < periods * mesh_period_s * (1 + 1e-9)
    h = np.diff(d.time_s)
    assert h.min() > 0 and h.max() < 2 * mesh_period_s / steps
    # The mesh phase is pinion rotation (rad) within one mesh period of 2 pi / z1.
    assert d.mesh_phase_rad.min() >= 0.0
    assert d.mesh_phase_rad.max() < 2 * np.pi / case["gear.teeth_pinion"]
    # The DTE array's maximum is the summary's, exactly (x 1e6 is monotone).
    assert d.dte_um.max() == d.summary["dte"]["max_um"]
    assert d.dte_um.min() == d.summary["dte"]["min_um"]
    assert d.mesh_force_n.max() == d.summary["mesh_force"]["max_n"]
    # DTE (um) against the line-of-action displacement it is made of: the DTE is some um,
    # not m (a unit slip would be 1e6 off).
    assert 1.0 < d.summary["dte"]["max_um"] < 1e3
    # Modes: as the summary's natural frequencies and mesh poles; shapes one row per mode.
    assert d.natural_frequencies_hz.tolist() == d.summary["undamped_natural_frequencies_hz"]
    assert d.mode_shapes.shape == (len(d.natural_frequencies_hz), 8)
    poles = d.damped_frequency_hz[d.mesh_pole == 1].tolist()
    assert poles == [p["damped_frequency_hz"] for p in d.summary["mesh_poles"]]
    assert np.all((d.damping_ratio >= 0) & (d.damping_ratio <= 1))
    # Spectrum of dy_p/dt: frequencies in Hz, spaced by 1 / (recorded window, s).
    f = d.spectrum_frequency_hz
    assert f.shape == d.spectrum_velocity_y_pinion_mm_per_s.shape
    window_s = case["numerics.evaluated_mesh_periods"] * mesh_period_s
    np.testing.assert_allclose(np.diff(f), 1.0 / window_s, rtol=1e-9)
    # Arrays are read-only views of the result.
    with pytest.raises(ValueError):
        d.dte_um[0] = 0.0


def test_stiffness_arrays(case):
    s = gw.stiffness(case)
    n = len(s.pinion_angle_deg)
    assert n == 720
    assert s.stiffness_pair_n_per_m.shape == (n, 2)
    assert s.pinion_angle_deg[0] == 0.0
    assert s.pinion_angle_deg[-1] < 360.0 / case["gear.teeth_pinion"]
    m = s.summary["mesh_stiffness"]
    # The sampled total lies within the table's extremes (sampling cannot exceed them;
    # 1e-9 relative for the interpolation's rounding).
    assert s.stiffness_total_n_per_m.max() <= m["max_n_per_m"] * (1 + 1e-9)
    assert s.stiffness_total_n_per_m.min() >= m["min_n_per_m"] * (1 - 1e-9)
    assert s.quasi_static_te_um.max() == s.summary["quasi_static_te"]["max_um"]


def test_wear_arrays():
    case = gw.Case.paper()
    w = gw.wear(case)
    assert set(w.runs) == {"dynamic", "quasi_static"}
    p = case["wear.points_per_profile"]
    for mode, r in w.runs.items():
        u = w.summary["updates"][mode] + 1
        assert r.cycles.shape == (u,)
        assert r.cycles[0] == 0.0 and r.cycles[-1] == case["wear.total_cycles"]
        assert r.wear_pinion_um.shape == (u, p) == r.wear_gear_um.shape
        assert r.wear_rate_pinion_um_per_kcycle.shape == (u, p)
        assert r.rho1_mm.shape == (p,)
        # The updates' maximum is the maximum of the profile.
        np.testing.assert_array_equal(r.wear_pinion_um.max(axis=1), r.max_wear_pinion_um)
        # Wear only grows.
        assert np.all(np.diff(r.wear_pinion_um, axis=0) >= 0.0)
    d = w.dynamic
    assert d.max_wear_pinion_um[-1] == pytest.approx(
        w.summary["max_wear_pinion_um"]["dynamic"][-1], rel=0, abs=0
    )


def test_transmission_error_input_is_checked():
    case = gw.Case.paper()
    with pytest.raises(ValueError, match="shape"):
        gw.dynamics(case, transmission_error=np.zeros((5, 3)))
    # Half a mesh period: refused, naming the input and the period.
    half = np.column_stack([np.linspace(0, 180 / 19, 10), np.zeros(10)])
    with pytest.raises(ValueError, match="transmission_error.*less than one mesh period"):
        gw.dynamics(case, transmission_error=half)
    # A zero error is no error: the same response as none (adding 0.0 changes no bit).
    zero = np.column_stack([np.linspace(0, 360 / 19, 10), np.zeros(10)])
    assert gw.dynamics(case, zero).summary["dte"] == gw.dynamics(case).summary["dte"]
