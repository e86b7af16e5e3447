"""gearwear: dynamic wear prediction of spur gears, from Python.

The Rust library of the ``gearwear`` command line (mesh stiffness by the potential
energy method, the 8-DOF tribo-dynamic model, Archard wear and their two-way coupling;
Coatings 2022, 12(9), 1250, with the corrections of docs/MODEL.md), called directly:

>>> import gearwear as gw
>>> case = gw.Case.paper().set("operating.input_speed_hz", 45)
>>> d = gw.dynamics(case)
>>> d.summary["dte"]["max_um"] == d.dte_um.max()
True

Every study mirrors a command and returns its summary (a dict with the keys and numbers
of that command's summary.json), its tables (the CSV files it writes, as numpy columns
with units in their names) and named views of them:

==========================  ====================  ===================
function                    command               returns
==========================  ====================  ===================
``stiffness(case)``         gearwear stiffness    ``StiffnessResult``
``dynamics(case, te)``      gearwear dynamics     ``DynamicsResult``
``wear(case, mode)``        gearwear wear         ``WearResult``
``run(case, out)``          gearwear run          ``RunResult``
``sweep(case, vary, run)``  gearwear sweep        ``SweepResult``
==========================  ====================  ===================

The computation runs in Rust with the GIL released (other Python threads go on), sweeps
and the two wear runs in parallel (rayon; ``RAYON_NUM_THREADS`` sets the threads).
Ctrl-C (KeyboardInterrupt) stops a study: a wear study at its next update (milliseconds);
control returns within about half a second in any case. ``progress=callable`` is called
on the calling thread as ``progress(what, done, total)``.

Invalid input raises ``CaseError`` (a ``ValueError``) listing every problem with its key,
value and valid range; a solver failure raises ``StudyError`` (a ``RuntimeError``).

Every study is checked against the run budget before it starts, as on the command line
(2 GiB and 10 minutes on one core of the reference machine; docs/RELIABILITY.md): one
over it raises ``CaseError`` naming the keys that drive its cost. ``budget_scale=X``
multiplies the budget knowingly, ``no_budget=True`` drops it.
"""

from __future__ import annotations

import os
import warnings as _warnings
from numbers import Integral, Real
from pathlib import Path
from typing import Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _gearwear as _native
from ._gearwear import Case, CaseError, Problem, StudyError, __version__, keys
from ._results import (
    COORDINATE_UNITS,
    COORDINATES,
    DynamicsResult,
    RunResult,
    StiffnessResult,
    SweepResult,
    Table,
    WearResult,
    WearRunResult,
)

__all__ = [
    "Case",
    "CaseError",
    "Problem",
    "StudyError",
    "GearwearWarning",
    "keys",
    "stiffness",
    "dynamics",
    "wear",
    "run",
    "sweep",
    "Table",
    "StiffnessResult",
    "DynamicsResult",
    "WearResult",
    "WearRunResult",
    "RunResult",
    "SweepResult",
    "COORDINATES",
    "COORDINATE_UNITS",
    "__version__",
]

#: ``progress(what, done, total)``: ``what`` is ``"dynamic"`` or ``"quasi_static"``
#: (wear runs; done and total in load cycles) or ``"sweep"`` (cases).
Progress = Callable[[str, float, float], Any]


class GearwearWarning(UserWarning):
    """A finding of the model that does not stop it (undercut, thin tips, formulas used
    outside their fitted range); the command line prints these as ``warning:``."""


def _check_case(case: Any) -> Case:
    if not isinstance(case, Case):
        raise TypeError(
            f"expected a gearwear.Case, got {type(case).__name__}: "
            "use Case.paper(), Case.from_toml(...) or case.set(...)"
        )
    return case


def _warn(summary: Mapping[str, Any]) -> None:
    for w in summary.get("warnings") or []:
        _warnings.warn(w, GearwearWarning, stacklevel=3)


def stiffness(case: Case, *, budget_scale: Optional[float] = None, no_budget: bool = False) -> StiffnessResult:
    """Mesh stiffness over one mesh period, as ``gearwear stiffness``.

    Potential energy method (bending, shear, axial compression, Hertz, Sainsot fillet
    foundation), load sharing, the quasi-static transmission error under the case's load,
    the ISO 6336-1 Method B cross-check and the pair's geometry. Table
    ``mesh_stiffness``: 720 samples over one mesh period (360/z1 deg of pinion rotation).
    """
    r = StiffnessResult(*_native.stiffness(_check_case(case), budget_scale, no_budget))
    _warn(r.summary)
    return r


def dynamics(
    case: Case,
    transmission_error: Optional[Any] = None,
    *,
    budget_scale: Optional[float] = None,
    no_budget: bool = False,
) -> DynamicsResult:
    """One steady-state evaluation of the 8-DOF tribo-dynamic model (new teeth), as
    ``gearwear dynamics [--transmission-error FILE]``.

    ``transmission_error``: None, or an external transmission error over exactly one mesh
    period as an array-like of shape (n, 2): column 0 the pinion angle in deg (strictly
    increasing, spanning one mesh period of 360/z1 deg, with or without its end point),
    column 1 the error in um; interpolated linearly and periodically (the columns of the
    CLI's ``pinion_angle_deg,error_um`` file).

    Signals over ``numerics.evaluated_mesh_periods`` mesh periods of
    ``numerics.steps_per_mesh_period`` samples each: ``time_s``, ``dte_um``,
    ``mesh_force_n``, ``displacement``/``velocity``/``acceleration`` (n, 8) in SI, the
    per-pair friction and loads, the dy_p/dt spectrum, natural frequencies and mode
    shapes. ``summary`` is that of summary.json.
    """
    te = None
    if transmission_error is not None:
        te = np.ascontiguousarray(transmission_error, dtype=np.float64)
        if te.ndim != 2 or te.shape[1] != 2:
            raise ValueError(
                "transmission_error: expected shape (n, 2) (pinion angle deg, error um), "
                f"got {te.shape}"
            )
    r = DynamicsResult(*_native.dynamics(_check_case(case), te, budget_scale, no_budget))
    _warn(r.summary)
    return r


def wear(
    case: Case,
    mode: str = "both",
    progress: Optional[Progress] = None,
    *,
    budget_scale: Optional[float] = None,
    no_budget: bool = False,
) -> WearResult:
    """The coupled dynamics-wear study and/or its quasi-static twin, as ``gearwear wear
    --mode MODE``, to ``wear.total_cycles`` load cycles (no checkpoints).

    ``mode``: ``"both"`` (default; the two runs in parallel), ``"dynamic"`` or
    ``"quasi_static"`` (``"quasi-static"`` also accepted). ``progress(mode, cycles,
    total_cycles)`` after every update of each run, e.g. to move a tqdm bar.
    """
    r = WearResult(*_native.wear(_check_case(case), mode, progress, budget_scale, no_budget))
    _warn(r.summary)
    return r


def run(
    case: Case,
    out: Optional[Union[str, "os.PathLike[str]"]] = None,
    progress: Optional[Progress] = None,
    *,
    budget_scale: Optional[float] = None,
    no_budget: bool = False,
) -> RunResult:
    """The paper's whole section 4, as ``gearwear run``: mesh stiffness, the dynamic and
    quasi-static wear studies, the dynamic response at 0.1, 0.5 and 1 um of wear, the
    comparison with the paper's numbers, figures 2 and 4-13 and the HTML report.

    ``out``: a folder to write the same output set as ``gearwear run --out DIR`` (summary,
    figures, CSVs, report, checkpoints, manifest), published as one set; None writes
    nothing (the figures and report are still in the result).
    """
    out_path = None if out is None else Path(os.fspath(out))
    r = RunResult(
        *_native.run(_check_case(case), out_path, progress, budget_scale, no_budget), out=out_path
    )
    _warn(r.summary)
    return r


def _value_text(v: Any) -> str:
    """A value as ``--vary`` list text (numbers in their shortest exact form)."""
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, Integral):
        return str(int(v))
    if isinstance(v, Real):
        return repr(float(v))
    if isinstance(v, str):
        return v
    raise TypeError(f"sweep: cannot vary over a {type(v).__name__} value ({v!r})")


def _axis_text(key: str, spec: Any) -> str:
    if isinstance(spec, str):
        return spec
    if isinstance(spec, (Sequence, np.ndarray, range)):
        values = [_value_text(v) for v in np.asarray(spec, dtype=object).ravel()]
        if not values:
            raise ValueError(f"sweep: no values given for {key}")
        return ",".join(values)
    return _value_text(spec)


def sweep(
    case: Case,
    vary: Mapping[str, Union[str, Sequence[Any], np.ndarray]],
    run: str = "dynamics",
    progress: Optional[Progress] = None,
    *,
    budget_scale: Optional[float] = None,
    no_budget: bool = False,
) -> SweepResult:
    """A parameter study, as ``gearwear sweep --vary KEY=... [--run RUN]`` (without
    files, resumption or shards): the cross product of ``vary`` on ``case``, run in
    parallel.

    ``vary``: ``{key: values}``; values a ``"START:STOP:STEP"`` range (STOP included when
    the range lands on it), a ``"v1,v2,..."`` list, or a sequence/array of numbers or
    strings. The first key varies slowest. Every case is checked before any runs: a bad
    value raises ``CaseError`` naming the case, the key and the value.
    ``run``: ``"dynamics"`` (one steady-state evaluation per case) or ``"wear"`` (the wear
    study in both modes). ``progress("sweep", cases_done, cases_total)``.
    Rows of cases whose solver failed are missing; ``summary["failed"]`` says why.
    """
    axes = [(str(k), _axis_text(str(k), v)) for k, v in vary.items()]
    r = SweepResult(*_native.sweep(_check_case(case), axes, run, progress, budget_scale, no_budget))
    _warn(r.summary)
    return r
