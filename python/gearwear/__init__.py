"""gearwear: dynamic wear prediction of spur gears, from Python.

The Rust library of the ``gearwear`` command line (mesh stiffness by the potential
energy method, the 8-DOF tribo-dynamic model, Archard wear and their two-way coupling;
Coatings 2022, 12(9), 1250, with the corrections of docs/MODEL.md), called directly:

>>> import gearwear as gw
>>> case = gw.Case.paper().set("operating.input_speed_hz", 45)
>>> d = gw.dynamics(case)
>>> d.summary["dte"]["max_um"] == d.dte_um.max()
True

Every study runs the same job of the library as the command of the same name (the
application layer, ``src/app``) and returns a named result: its summary (a dict with the
keys and numbers of that command's summary.json), its tables (the CSV files it writes, as
numpy columns with units in their names) and named views of them:

====================================  ========================  ======================
function                              command                   returns
====================================  ========================  ======================
``stiffness(case)``                   gearwear stiffness        ``StiffnessResult``
``dynamics(case, te)``                gearwear dynamics         ``DynamicsResult`` [#]_
``wear(case, mode)``                  gearwear wear             ``WearResult``
``run(case, out)``                    gearwear run              ``RunResult``
``sweep(case, vary, run)``            gearwear sweep            ``SweepResult``
``sweep_merge(inputs)``               gearwear sweep-merge      ``SweepResult``
``calibrate(case, observations)``     gearwear calibrate        ``CalibrationResult``
``predict(case, posterior, ...)``     gearwear predict          ``PredictionResult``
``predict_merge(inputs)``             gearwear predict-merge    ``PredictionResult``
``load_spectrum(history)``            gearwear load-spectrum    ``LoadSpectrumResult``
``signals(case)``                     gearwear signals          ``SignalsResult`` [#]_
====================================  ========================  ======================

.. [#] ``PlanetaryDynamicsResult`` for a case with ``[planetary]``. A gear train's
   (``[[stage]]``) ``DynamicsResult`` has every stage's coordinates and ``mesh(k)``; its
   ``WearResult`` has its runs per mesh in ``stages`` and the train's ``history(mode)``;
   its ``sweep`` (of dynamics; ``vary`` may name ``stage.N.KEY``) has one column set per
   mesh (``stageK_mesh_frequency_hz``, ``stageK_dte_max_um``, ``stageK_mesh_force_mean_n``,
   ``stageK_mesh_force_max_n``, ``stageK_dynamic_factor``).
.. [#] ``PlanetarySignalsResult`` for a case with ``[planetary]`` (the ring sensor).

A case with a ``[load_spectrum]`` runs ``wear``, ``run``, ``calibrate``, ``predict`` and
wear sweeps under its spectrum; ``WearResult.duty`` then views what each bin did.

``out=FOLDER`` writes the command's output set there (checkpoints and ``resume=True``
for wear studies, finished cases skipped on a rerun of a sweep); without it nothing is
written; a folder that holds another command's results is refused unless
``replace=True``. ``budget_scale`` raises the run budget (docs/RELIABILITY.md) knowingly;
``math.inf`` drops the check.

The computation runs in Rust with the GIL released (other Python threads go on), sweeps
and the two wear runs in parallel (rayon; ``RAYON_NUM_THREADS`` sets the threads).
Ctrl-C (KeyboardInterrupt) stops a study: a wear study at its next update (milliseconds);
control returns within about half a second in any case. ``progress=callable`` is called
on the calling thread as ``progress(task, done, total)``.

Invalid input raises ``CaseError`` (a ``ValueError``) listing every problem with its key,
value and valid range; a solver failure raises ``StudyError`` (a ``RuntimeError``); the
model's findings (undercut, formulas outside their fitted range) are ``GearwearWarning``s.
"""

from __future__ import annotations

import os as _os
import warnings as _warnings
from typing import Any as _Any
from typing import Callable as _Callable
from typing import Mapping as _Mapping
from typing import Optional as _Optional
from typing import Sequence as _Sequence
from typing import Tuple as _Tuple
from typing import Union as _Union

import numpy as _np

from . import _gearwear as _native
from ._gearwear import Case, CaseError, Problem, StudyError, __version__, keys
from ._results import (
    COORDINATE_UNITS,
    COORDINATES,
    CalibrationResult,
    DutyResult,
    DatasetResult,
    DynamicsResult,
    LoadSpectrumResult,
    MeshResponse,
    PlanetaryDynamicsResult,
    PlanetarySignalsResult,
    PredictionResult,
    RunResult,
    SignalsResult,
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
    "sweep_merge",
    "calibrate",
    "predict",
    "predict_merge",
    "load_spectrum",
    "signals",
    "dataset",
    "dataset_merge",
    "Table",
    "StiffnessResult",
    "DynamicsResult",
    "MeshResponse",
    "PlanetaryDynamicsResult",
    "PlanetarySignalsResult",
    "WearResult",
    "WearRunResult",
    "RunResult",
    "SweepResult",
    "CalibrationResult",
    "PredictionResult",
    "LoadSpectrumResult",
    "DutyResult",
    "SignalsResult",
    "DatasetResult",
    "COORDINATES",
    "COORDINATE_UNITS",
    "__version__",
]

#: ``progress(task, done, total)``: ``task`` is ``"dynamic"`` or ``"quasi_static"`` (wear
#: runs; done and total in load cycles), ``"sweep"`` (cases), ``"reference_runs"``,
#: ``"posterior"`` or ``"samples"`` (prognostics), ``"records"`` (a dataset).
Progress = _Callable[[str, float, float], _Any]
PathLike = _Union[str, "_os.PathLike[str]"]


class GearwearWarning(UserWarning):
    """A finding of the model that does not stop it (undercut, thin tips, formulas used
    outside their fitted range, a wear run that stopped early); the command line prints
    these as ``warning:``."""


def __dir__() -> list:
    """The public API only."""
    return sorted(__all__)


def _check_case(case: _Any) -> Case:
    if not isinstance(case, Case):
        raise TypeError(
            f"expected a gearwear.Case, got {type(case).__name__}: "
            "use Case.paper(), Case.from_toml(...) or case.set(...)"
        )
    return case


def _path(out: _Optional[PathLike]) -> _Optional[str]:
    return None if out is None else _os.fspath(out)


def _whole(name: str, v: _Any) -> int:
    """``v`` as a whole number, refusing what Python would silently turn into one (a bool,
    a float such as 1.5, a string)."""
    if isinstance(v, bool) or not isinstance(v, (int, _np.integer)):
        raise TypeError(f"`{name}` = {v!r}: expected a whole number (int), got {type(v).__name__}")
    return int(v)


def _real(name: str, v: _Any) -> float:
    """``v`` as a real number, refusing a bool, a string (``'2e4'``) or a complex."""
    if isinstance(v, bool) or not isinstance(v, (int, float, _np.integer, _np.floating)):
        raise TypeError(f"`{name}` = {v!r}: expected a real number, got {type(v).__name__}")
    return float(v)


def _shard(v: _Any, text: bool) -> _Any:
    """A shard as ``(i, n)`` of whole numbers (or, where ``text``, ``"I/N"``)."""
    if v is None or (text and isinstance(v, str)):
        return v
    if not (isinstance(v, (tuple, list)) and len(v) == 2):
        form = '"I/N" or (i, n)' if text else "(i, n)"
        raise TypeError(f"`shard` = {v!r}: expected {form}, shard i of n")
    return (_whole("shard[0]", v[0]), _whole("shard[1]", v[1]))


def _done(result: _Any, native: _Mapping[str, _Any]) -> _Any:
    """Warn about the study's findings and return its result."""
    for w in native["warnings"]:
        _warnings.warn(w, GearwearWarning, stacklevel=3)
    if native["incomplete"]:
        _warnings.warn(native["incomplete"], GearwearWarning, stacklevel=3)
    return result


def stiffness(
    case: Case,
    *,
    out: _Optional[PathLike] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> StiffnessResult:
    """Mesh stiffness over one mesh period, as ``gearwear stiffness``.

    Potential energy method (bending, shear, axial compression, Hertz, Sainsot fillet
    foundation), load sharing, the quasi-static transmission error under the case's load,
    the ISO 6336-1 Method B cross-check and the pair's geometry. Table
    ``mesh_stiffness``: 720 samples over one mesh period (360/z1 deg of pinion rotation).

    ``figures``: the formats of the figures written to ``out``: ``"png"`` (default),
    ``"svg"`` or ``"png,svg"``; ``figure_size``: (width, height) px of a one-panel figure
    (width 400-8192, height 200-4096; figures of several panels keep their height ratio).
    """
    n = _native.stiffness(
        _check_case(case),
        out=_path(out),
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(StiffnessResult(**n), n)


def dynamics(
    case: Case,
    transmission_error: _Optional[_Any] = None,
    *,
    out: _Optional[PathLike] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> _Union[DynamicsResult, PlanetaryDynamicsResult]:
    """One steady-state evaluation of the 8-DOF tribo-dynamic model (new teeth), as
    ``gearwear dynamics [--transmission-error FILE]``.

    ``transmission_error``: None, or an external transmission error over exactly one mesh
    period as an array-like of shape (n, 2): column 0 the pinion angle in deg (strictly
    increasing, spanning one mesh period of 360/z1 deg, with or without its end point),
    column 1 the error in µm; interpolated linearly and periodically (the columns of the
    CLI's ``pinion_angle_deg,error_um`` file).

    Signals over ``numerics.evaluated_mesh_periods`` mesh periods of
    ``numerics.steps_per_mesh_period`` samples each: ``time_s``, ``dte_um``,
    ``mesh_force_n``, ``displacement``/``velocity``/``acceleration`` (n, 8) in SI, the
    per-pair friction and loads, the dy_p/dt spectrum, natural frequencies and mode
    shapes. ``summary`` is that of summary.json.

    ``figures``, ``figure_size``: as for :func:`stiffness`.
    """
    te = None
    if transmission_error is not None:
        te = _np.ascontiguousarray(transmission_error, dtype=_np.float64)
        if te.ndim != 2 or te.shape[1] != 2:
            raise ValueError(
                "transmission_error: expected shape (n, 2) (pinion angle deg, error µm), "
                f"got {te.shape}"
            )
    n = _native.dynamics(
        _check_case(case),
        te,
        out=_path(out),
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    if "planetary_dynamics" in n["summary"]:
        return _done(PlanetaryDynamicsResult(**n), n)
    return _done(DynamicsResult(**n), n)


def wear(
    case: Case,
    mode: str = "both",
    progress: _Optional[Progress] = None,
    *,
    out: _Optional[PathLike] = None,
    resume: bool = False,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> WearResult:
    """The coupled dynamics-wear study and/or its quasi-static twin, as ``gearwear wear
    --mode MODE``, to ``wear.total_cycles`` load cycles.

    ``mode``: ``"both"`` (default; the two runs in parallel), ``"dynamic"`` or
    ``"quasi_static"`` (``"quasi-static"`` also accepted). ``progress(mode, cycles,
    total_cycles)`` after every update of each run, e.g. to move a tqdm bar. ``out``: a
    folder for the command's output set, with a checkpoint after every update;
    ``resume=True`` continues from the checkpoints there.

    ``figures``, ``figure_size``: as for :func:`stiffness`.
    """
    n = _native.wear(
        _check_case(case),
        mode,
        progress,
        out=_path(out),
        resume=resume,
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(WearResult(**n), n)


def run(
    case: Case,
    out: _Optional[PathLike] = None,
    progress: _Optional[Progress] = None,
    *,
    resume: bool = False,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> RunResult:
    """The paper's whole section 4, as ``gearwear run``: mesh stiffness, the dynamic and
    quasi-static wear studies, the dynamic response at 0.1, 0.5 and 1 µm of wear, the
    comparison with the paper's numbers, figures 2 and 4-13 and the HTML report.

    ``out``: a folder to write the same output set as ``gearwear run --out DIR`` (summary,
    figures, CSVs, report, checkpoints, manifest), published as one set; None writes
    nothing (the figures and report are still in the result). ``resume=True`` continues
    the wear studies from the checkpoints in ``out``.

    ``figures``, ``figure_size``: as for :func:`stiffness`.
    """
    n = _native.run(
        _check_case(case),
        _path(out),
        progress,
        resume=resume,
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(RunResult(**n), n)


def _axis(spec: _Any) -> _Any:
    """A sweep axis as the native module takes it: range/list text, or a list of values."""
    if isinstance(spec, str):
        return spec
    if isinstance(spec, _np.ndarray):
        return spec.tolist()
    if isinstance(spec, (_Sequence, range)):
        return [v.tolist() if isinstance(v, (_np.ndarray, _np.generic)) else v for v in spec]
    return [spec]


def sweep(
    case: Case,
    vary: _Mapping[str, _Union[str, _Sequence[_Any], _np.ndarray]],
    run: str = "dynamics",
    progress: _Optional[Progress] = None,
    *,
    out: _Optional[PathLike] = None,
    shard: _Optional[_Union[str, tuple]] = None,
    continuation: _Optional[str] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> SweepResult:
    """A parameter study, as ``gearwear sweep --vary KEY=... [--run RUN]``: the cross
    product of ``vary`` on ``case``, run in parallel.

    ``vary``: ``{key: values}``; values a ``"START:STOP:STEP"`` range (STOP included when
    the range lands on it), a ``"v1,v2,..."`` list, or a sequence/array of numbers or
    strings. The first key varies slowest. Every case is checked before any runs: a bad
    value raises ``CaseError`` naming the case, the key and the value.
    ``run``: ``"dynamics"`` (one steady-state evaluation per case) or ``"wear"`` (the wear
    study in both modes). ``progress("sweep", cases_done, cases_total)``.
    ``out``: a folder for the sweep's files (a case record per finished case: a rerun
    skips them); ``shard``: ``"I/N"`` or ``(I, N)``, the cases with id mod N = I - 1;
    ``continuation``: ``"up"``, ``"down"`` or ``"both"``, one axis followed along its
    solution branches. Rows of cases whose solver failed are missing;
    ``summary["failed"]`` says why. ``figures``, ``figure_size``: the sweep figure's
    formats and size, as for :func:`stiffness`.
    """
    axes = [(str(k), _axis(v)) for k, v in vary.items()]
    n = _native.sweep(
        _check_case(case),
        axes,
        run,
        progress,
        out=_path(out),
        shard=_shard(shard, text=True),
        continuation=continuation,
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(SweepResult(**n), n)


def sweep_merge(
    inputs: _Sequence[PathLike],
    out: _Optional[PathLike] = None,
    *,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> SweepResult:
    """The tables of sweep shards (or of earlier merges) joined into one sorted by case
    id, as ``gearwear sweep-merge``; ``inputs``: sweep folders or CSV files. Inputs of
    different sweeps are refused. ``figures``, ``figure_size``: as for :func:`stiffness`."""
    n = _native.sweep_merge(
        [_os.fspath(p) for p in inputs],
        _path(out),
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(SweepResult(**n), n)


def _table(data: _Any, what: str, columns: _Optional[_Sequence[str]] = None) -> _Any:
    """An input table as the native module takes it: a path, or (names, float64 arrays).

    Accepted: a path (str or os.PathLike) to a CSV file; a pandas DataFrame; a mapping of
    column name to 1-D array; a numpy structured array; a 2-D array with ``columns``; a
    result whose ``tables`` hold it (``CalibrationResult``: its posterior samples)."""
    if isinstance(data, (str, _os.PathLike)):
        return _os.fspath(data)
    if isinstance(data, CalibrationResult):
        data = data.tables["posterior_samples"]
    if hasattr(data, "columns") and hasattr(data, "to_numpy") and not isinstance(data, _np.ndarray):
        if isinstance(data, Table):
            names = list(data.columns)
            arrays = [data[c] for c in names]
        else:  # a pandas DataFrame
            names = [str(c) for c in data.columns]
            for c in data.columns:
                if _np.iscomplexobj(data[c].to_numpy()):
                    raise TypeError(f"{what}: column {str(c)!r} holds complex numbers: give real ones")
            arrays = [data[c].to_numpy(dtype=_np.float64, na_value=_np.nan) for c in data.columns]
    elif isinstance(data, _Mapping):
        names = [str(k) for k in data]
        arrays = [data[k] for k in data]
    elif isinstance(data, _np.ndarray) and data.dtype.names:
        names = list(data.dtype.names)
        arrays = [data[n] for n in names]
    elif isinstance(data, _np.ndarray) and data.ndim == 2:
        if columns is None or len(columns) != data.shape[1]:
            raise ValueError(
                f"{what}: a 2-D array needs `columns`, one name per column ({data.shape[1]})"
            )
        names = [str(c) for c in columns]
        arrays = [data[:, j] for j in range(data.shape[1])]
    else:
        raise TypeError(
            f"{what}: expected a CSV path, a pandas DataFrame, a mapping of columns, a "
            f"structured array or a 2-D array with `columns`, got {type(data).__name__}"
        )
    cols = []
    for name, a in zip(names, arrays):
        if _np.iscomplexobj(a):
            raise TypeError(f"{what}: column {name!r} holds complex numbers: give real ones")
        a = _np.ascontiguousarray(a, dtype=_np.float64)
        if a.ndim != 1:
            raise ValueError(f"{what}: column {name!r} is not one-dimensional")
        cols.append(a)
    return (names, cols)


def calibrate(
    case: Case,
    observations: _Any,
    *,
    columns: _Optional[_Sequence[str]] = None,
    seed: int = 1,
    samples: int = 2000,
    walkers: int = 32,
    steps: int = 2000,
    check_runs: int = 3,
    out: _Optional[PathLike] = None,
    progress: _Optional[Progress] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> CalibrationResult:
    """The posterior of the wear coefficient (and, where the case's ``[calibration]``
    leaves them free, the roughness factor and load torque) given observations of a
    running gearbox, as ``gearwear calibrate --observations FILE``.

    ``observations``: a pandas DataFrame, a mapping of columns, a structured array, a 2-D
    array with ``columns=[...]``, or a CSV path: a ``cycles`` column (pinion load
    cycles), one column per observed quantity (named as the wear study's ``updates``
    table: ``max_wear_pinion_um``, ``velocity_y_pinion_rms_mm_per_s``, ...), optional
    ``sigma_<name>`` columns (the measurement noise, same unit); NaN where a quantity was
    not measured (docs/PROGNOSTICS.md). ``seed`` (a whole number in [0, 2**53]) seeds
    every random draw; ``samples`` posterior samples; ``walkers`` and ``steps`` of the
    ensemble sampler (the first half burn-in); ``check_runs`` true wear runs checked
    against the surrogate.
    ``figures``, ``figure_size``: as for :func:`stiffness` (the report embeds the SVG
    when only SVG is asked for).
    """
    obs = _table(observations, "observations", columns)
    n = _native.calibrate(
        _check_case(case),
        obs,
        seed=seed,
        samples=samples,
        walkers=walkers,
        steps=steps,
        check_runs=check_runs,
        out=_path(out),
        progress=progress,
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(CalibrationResult(**n), n)


def predict(
    case: Case,
    posterior: _Any = None,
    *,
    limit_um: float,
    cycles: float,
    seed: int = 1,
    samples: _Optional[int] = None,
    grid_points: int = 101,
    forward: str = "surrogate",
    shard: _Optional[_Union[str, tuple]] = None,
    check_runs: int = 3,
    out: _Optional[PathLike] = None,
    progress: _Optional[Progress] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    future_spectrum: _Optional[PathLike] = None,
    future_from_cycles: _Optional[float] = None,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> PredictionResult:
    """Monte Carlo prediction of wear, vibration indicators and remaining life, as
    ``gearwear predict --limit-um L --cycles N [--posterior FILE]``.

    ``posterior``: None (samples of the case's prior), a ``CalibrationResult``, or its
    samples as a DataFrame, mapping, structured array or CSV path (columns
    ``wear_coefficient_m2_per_n`` and optionally ``roughness_scale``,
    ``load_torque_nm``). ``limit_um``: the wear limit on the maximum pinion wear depth,
    µm; ``cycles``: the horizon, pinion load cycles. ``samples``: ensemble size (default:
    every posterior row, or 2000 prior draws); ``grid_points`` cycle counts of the fan
    charts; ``forward``: ``"surrogate"`` (fast) or ``"exact"`` (one wear study per
    sample); ``shard``: ``"I/N"`` or ``(I, N)`` (join the shards' ``out`` folders with
    ``predict_merge``).

    ``future_spectrum``: a future duty, as ``--future-spectrum``: a ``[load_spectrum]``
    section (TOML text, or a path to a TOML file holding only that section, spelled as in
    a case file) that replaces the case's duty from ``future_from_cycles`` on (pinion
    cycles from new teeth, required with it, in [0, ``cycles``)).

    ``figures``, ``figure_size``: as for :func:`stiffness` (the report embeds the SVG
    when only SVG is asked for; a shard draws no figure).
    """
    post = None if posterior is None else _table(posterior, "posterior")
    n = _native.predict(
        _check_case(case),
        post,
        limit_um=_real("limit_um", limit_um),
        cycles=_real("cycles", cycles),
        seed=seed,
        samples=samples,
        grid_points=grid_points,
        forward=forward,
        shard=_shard(shard, text=True),
        check_runs=check_runs,
        out=_path(out),
        progress=progress,
        budget_scale=budget_scale,
        replace=replace,
        future_spectrum=None if future_spectrum is None else (
            future_spectrum if isinstance(future_spectrum, str) else _os.fspath(future_spectrum)
        ),
        future_from_cycles=None if future_from_cycles is None else _real("future_from_cycles", future_from_cycles),
        figures=figures,
        figure_size=figure_size,
    )
    return _done(PredictionResult(**n), n)


def predict_merge(
    inputs: _Sequence[PathLike],
    out: _Optional[PathLike] = None,
    *,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> PredictionResult:
    """The shards of a sharded ``predict`` joined, as ``gearwear predict-merge``;
    ``inputs``: shard files (``predict_shard_I_of_N.json``) or folders holding them.
    ``figures``, ``figure_size``: as for :func:`stiffness`."""
    n = _native.predict_merge(
        [_os.fspath(p) for p in inputs],
        _path(out),
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(PredictionResult(**n), n)


def load_spectrum(
    history: _Any,
    *,
    columns: _Optional[_Sequence[str]] = None,
    torque_classes: int = 10,
    speed_classes: int = 5,
    interpolation: str = "linear",
    level: str = "mean",
    torque_shaft: str = "pinion",
    gap_factor: float = 10.0,
    merge_below_share: float = 1e-3,
    out: _Optional[PathLike] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> LoadSpectrumResult:
    """The load spectrum of a measured torque / speed history, as ``gearwear
    load-spectrum --history FILE``: its load duration distribution (time at level on a
    torque x speed grid, ISO 6336-6) and the spectrum for a case (``result.apply(case)``,
    ``result.toml``, or with ``out`` the files ``spectrum.csv`` and
    ``load_spectrum.toml``), with the time-at-level histogram.

    ``history``: a CSV path, a pandas DataFrame, a mapping of columns, a structured array
    or a 2-D array with ``columns=[...]``: ``time_s`` (s, strictly increasing),
    ``torque_nm`` (N m on ``torque_shaft``) and ``input_speed_hz`` (Hz) or
    ``input_speed_rpm``; other columns are ignored; NaN is a gap in the record (an
    error). ``torque_classes`` and ``speed_classes`` equal classes from 0 to the largest
    value; ``interpolation``: ``"linear"`` between samples (a ramp counts exactly) or
    ``"hold"`` (sample and hold); ``level``: each bin's torque the cell's
    revolution-weighted ``"mean"`` (keeps its wear) or the class's ``"upper"`` edge;
    ``gap_factor``: the longest interval accepted, in median intervals.
    ``merge_below_share``: bins with less than this share of the revolutions (default
    0.1 %) join their nearest bin, keeping the revolutions, the time and the quasi-static
    wear; 0 keeps every bin.
    ``figures``, ``figure_size``: as for :func:`stiffness`.
    """
    h = _table(history, "history", columns)
    n = _native.load_spectrum(
        h,
        torque_classes=_whole("torque_classes", torque_classes),
        speed_classes=_whole("speed_classes", speed_classes),
        interpolation=interpolation,
        level=level,
        torque_shaft=torque_shaft,
        gap_factor=gap_factor,
        merge_below_share=merge_below_share,
        out=_path(out),
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(LoadSpectrumResult(**n), n)


def signals(
    case: Case,
    *,
    transfer_path: _Optional[PathLike] = None,
    out: _Optional[PathLike] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> _Union[SignalsResult, PlanetarySignalsResult]:
    """One record of what a sensor sees, as ``gearwear signals [--transfer-path FILE]``.

    The case's ``[signals]`` section sets the acquisition (sampling rate, anti-alias
    filter, unit, sensitivity, measurement noise, tachometer, record length) and the
    operating variation (``ramp_end_speed_hz`` for a run-up or coast-down,
    ``torque_fluctuation_rms_nm`` for a fluctuating load). ``transfer_path``: an FRF table
    (.csv) or modal description (.toml); default: the built-in generic housing.
    ``figures``, ``figure_size``: as for :func:`stiffness`.
    """
    n = _native.signals(
        _check_case(case),
        transfer_path=_path(transfer_path),
        out=_path(out),
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    if "planetary_signals" in n["summary"]:
        return _done(PlanetarySignalsResult(**n), n)
    return _done(SignalsResult(**n), n)


def dataset(
    design: _Union[PathLike, _Mapping[str, _Any]],
    out: PathLike,
    *,
    shard: _Optional[_Sequence[int]] = None,
    progress: _Optional[Progress] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
) -> DatasetResult:
    """A labelled dataset from a study design, as ``gearwear dataset``: written to ``out``
    record by record (resumable: a rerun keeps finished records).
    ``design``: a design file (a path), the design's TOML text, or a dict of its keys,
    e.g. ``{"case": gw.Case.paper().set(...), "run_to_failure": {"states": 3},
    "condition": [{"name": "healthy"}]}`` (``case`` may be a :class:`Case` or a case
    file's name). A text or dict design resolves relative file names against the
    current folder; the records equal those of the same design read from a file.
    ``shard=(i, n)`` runs shard i of n; join shards with ``dataset_merge``.
    ``figures``, ``figure_size``: the formats and size of ``indicator_trends`` (the
    records are the same whatever they are), as for :func:`stiffness`."""
    sh = _shard(shard, text=False)
    if isinstance(design, _os.PathLike):
        design = _os.fspath(design)
    n = _native.dataset(
        design,
        _os.fspath(out),
        shard=sh,
        progress=progress,
        budget_scale=budget_scale,
        replace=replace,
        figures=figures,
        figure_size=figure_size,
    )
    return _done(DatasetResult(**n), n)


def dataset_merge(
    inputs: _Sequence[PathLike],
    out: PathLike,
    *,
    replace: bool = False,
    figures: _Optional[str] = None,
    figure_size: _Optional[_Tuple[int, int]] = None,
    transfer_path: _Optional[PathLike] = None,
    budget_scale: float = 1.0,
) -> DatasetResult:
    """The shards of a dataset joined into ``out`` with its index and metadata, as
    ``gearwear dataset-merge``: byte for byte the dataset an unsharded run writes (with the
    same ``figures``, ``figure_size``: as for :func:`stiffness`). Each shard's records
    are verified by recomputing a sample of them first (a forged shard is refused,
    nothing written); ``transfer_path``: the transfer-path file the shards' design
    names, needed to recompute them (``--transfer-path``). The verification reads and
    analyses every record: its cost is checked against the run budget first
    (``budget_scale``, as for :func:`dataset`)."""
    n = _native.dataset_merge(
        [_os.fspath(p) for p in inputs],
        _os.fspath(out),
        replace=replace,
        figures=figures,
        figure_size=figure_size,
        transfer_path=None if transfer_path is None else _os.fspath(transfer_path),
        budget_scale=budget_scale,
    )
    return _done(DatasetResult(**n), n)
