"""Result objects of the studies: the summary (a dict, the keys and numbers of the
command line's summary.json), the tables (the CSV files the command line writes, as
numpy columns with their units in the names) and named views of their columns.

Nothing here computes: every number comes from the Rust library; the views only pick
and stack columns.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple

import numpy as np

from . import _gearwear

__all__ = [
    "Table",
    "StiffnessResult",
    "DynamicsResult",
    "MeshResponse",
    "PlanetaryDynamicsResult",
    "PlanetarySignalsResult",
    "WearRunResult",
    "WearResult",
    "RunResult",
    "SweepResult",
    "CalibrationResult",
    "PredictionResult",
    "LoadSpectrumResult",
    "DutyResult",
]

#: The 8 generalised coordinates of the dynamic model, in the column order of
#: ``displacement``, ``velocity``, ``acceleration`` and ``mode_shapes``, and their SI units.
COORDINATES: Tuple[str, ...] = tuple(_gearwear.COORDINATES)
COORDINATE_UNITS: Tuple[str, ...] = tuple(_gearwear.COORDINATE_UNITS)


def _pandas():
    try:
        import pandas
    except ImportError as e:  # pandas is optional
        raise ImportError(
            "to_pandas() needs pandas, which gearwear does not install: "
            "pip install pandas (or pip install './python[data]', with pyarrow)"
        ) from e
    return pandas


#: Columns that count or number things (a bin, a rank, a tooth, an update, a sample):
#: returned as int64 when every value is whole, as the CSV writes them.
INTEGER_COLUMNS = frozenset({"rank", "bin", "tooth", "update", "sample", "case_id"})


def _as_integers(column: str, a: np.ndarray) -> np.ndarray:
    """``a`` as int64 when ``column`` counts things and every value is whole, else ``a``."""
    if column in INTEGER_COLUMNS and np.all(np.isfinite(a)) and np.all(a == np.round(a)):
        out = a.astype(np.int64)
        out.flags.writeable = False
        return out
    return a


class Table(Mapping[str, np.ndarray]):
    """A table of named float64 columns, units in the names (``time_s``,
    ``mesh_force_n``): the CSV file of the same name that the command line writes.
    Columns that count things (``rank``, ``bin``, ``tooth``, ``update``, ``sample``,
    ``case_id``) are int64.

    A read-only mapping ``{column: 1-D array}``; ``to_numpy()`` stacks the columns,
    ``to_pandas()`` makes a DataFrame (pandas optional).
    """

    def __init__(self, name: str, columns: Sequence[str], data: np.ndarray, lengths: Sequence[int]):
        #: The table's name (its CSV file name without ``.csv``).
        self.name = name
        # Column i is data[i, :lengths[i]] (the rest NaN padding).
        self._index = {c: i for i, c in enumerate(columns)}
        self._data = data
        self._lengths = list(lengths)
        data.flags.writeable = False

    @classmethod
    def from_columns(cls, name: str, columns: Mapping[str, np.ndarray]) -> "Table":
        """A table of the given 1-D columns (copied)."""
        cols = {c: np.asarray(a, dtype=np.float64) for c, a in columns.items()}
        n = max((len(a) for a in cols.values()), default=0)
        data = np.full((len(cols), n), np.nan)
        for i, a in enumerate(cols.values()):
            data[i, : len(a)] = a
        return cls(name, list(cols), data, [len(a) for a in cols.values()])

    @property
    def columns(self) -> List[str]:
        """Column names, in file order."""
        return list(self._index)

    @property
    def n_rows(self) -> int:
        """Number of rows (the longest column; the CSV leaves shorter ones empty)."""
        return self._data.shape[1]

    def __getitem__(self, column: str) -> np.ndarray:
        try:
            i = self._index[column]
        except KeyError:
            raise KeyError(
                f"table {self.name!r} has no column {column!r}; columns: {', '.join(self._index)}"
            ) from None
        return _as_integers(column, self._data[i, : self._lengths[i]])

    def __iter__(self) -> Iterator[str]:
        return iter(self._index)

    def __len__(self) -> int:
        return len(self._index)

    def to_numpy(self) -> np.ndarray:
        """The columns side by side: shape (n_rows, n_columns), NaN where a column is
        shorter."""
        return self._data.T.copy()

    def to_pandas(self) -> Any:
        """A ``pandas.DataFrame`` of the table (needs pandas); counting columns int64."""
        pd = _pandas()
        n = self.n_rows
        return pd.DataFrame(
            {
                c: (self[c] if len(self[c]) == n else self._data[i].copy())
                for c, i in self._index.items()
            },
            columns=self.columns,
        )

    def __repr__(self) -> str:
        return f"<gearwear.Table {self.name!r}: {self.n_rows} rows x {len(self)} columns>"


class _Result:
    """What every study returns: ``summary``, ``tables``, ``headline``, and where the
    output set went (``out``)."""

    def __init__(
        self,
        summary: Dict[str, Any],
        tables: Dict[str, Tuple[List[str], np.ndarray, List[int]]],
        headline: str,
        documents: Optional[Dict[str, bytes]] = None,
        warnings: Sequence[str] = (),
        out: Optional[str] = None,
        incomplete: Optional[str] = None,
    ):
        #: The summary: the keys and numbers of the command's summary.json (display units
        #: in the key names), with ``metadata`` (program, version, command, the resolved
        #: case and its SHA-256, and ``resolved``: the values the model used for the
        #: ``"derived"`` keys and the operating point).
        self.summary: Dict[str, Any] = summary
        #: The tables by name (the CSV file names without ``.csv``).
        self.tables: Dict[str, Table] = {n: Table(n, *t) for n, t in tables.items()}
        #: The lines the command line prints as its result.
        self.headline: str = headline
        #: The output folder written, or None.
        self.out: Optional[Path] = None if out is None else Path(out)
        #: Why the result is incomplete (a wear run the solver gave up on, failed sweep
        #: cases), or None; the command line exits 1 for these.
        self.incomplete: Optional[str] = incomplete
        self._documents: Dict[str, bytes] = dict(documents or {})
        self._warnings: List[str] = list(warnings)

    def to_pandas(self, table: Optional[str] = None) -> Any:
        """One table as a ``pandas.DataFrame``, or with no name, a dict of all of them
        (needs pandas)."""
        if table is None:
            return {n: t.to_pandas() for n, t in self.tables.items()}
        if table not in self.tables:
            raise KeyError(f"no table {table!r}; tables: {', '.join(self.tables)}")
        return self.tables[table].to_pandas()

    @property
    def warnings(self) -> List[str]:
        """The study's warnings (undercut, formulas used outside their fitted range, a
        wear run that stopped early), also issued as ``GearwearWarning``."""
        return list(self._warnings)

    @property
    def figures_png(self) -> Dict[str, bytes]:
        """PNG bytes of each figure rendered for the report, by file name."""
        return {n: b for n, b in self._documents.items() if n.endswith(".png")}

    @property
    def figures_svg(self) -> Dict[str, str]:
        """SVG text of each figure rendered for the report (``figures="svg"`` or
        ``"png,svg"``), by file name."""
        return {n: b.decode("utf-8") for n, b in self._documents.items() if n.endswith(".svg")}

    @property
    def report_html(self) -> Optional[str]:
        """The self-contained HTML report, for the studies that write one."""
        html = self._documents.get("report.html")
        return None if html is None else html.decode("utf-8")

    def __repr__(self) -> str:
        return f"<gearwear.{type(self).__name__}: {self.headline}>"


def _stack(table: Table, names: Sequence[str]) -> np.ndarray:
    return np.column_stack([table[n] for n in names])


class StiffnessResult(_Result):
    """Mesh stiffness over one mesh period (potential energy method), load sharing, the
    quasi-static transmission error, the ISO 6336-1 cross-check and the pair's geometry:
    what ``gearwear stiffness`` writes. Table: ``mesh_stiffness`` (720 samples over one
    mesh period)."""

    @property
    def table(self) -> Table:
        """The ``mesh_stiffness`` table."""
        return self.tables["mesh_stiffness"]

    @property
    def pinion_angle_deg(self) -> np.ndarray:
        """Pinion rotation within one mesh period (0 .. 360/z1), deg; shape (n,)."""
        return self.table["pinion_angle_deg"]

    @property
    def stiffness_total_n_per_m(self) -> np.ndarray:
        """Total mesh stiffness k_m, N/m; shape (n,)."""
        return self.table["stiffness_total_n_per_m"]

    @property
    def stiffness_pair_n_per_m(self) -> np.ndarray:
        """Stiffness of each of the (up to) two pairs in contact, N/m, NaN where a pair is
        out of contact; shape (n, 2)."""
        return _stack(self.table, ["stiffness_pair0_n_per_m", "stiffness_pair1_n_per_m"])

    @property
    def quasi_static_te_um(self) -> np.ndarray:
        """Quasi-static transmission error under the case's load, µm; shape (n,)."""
        return self.table["quasi_static_te_um"]


class DynamicsResult(_Result):
    """One steady-state evaluation of the 8-DOF tribo-dynamic model (new teeth): what
    ``gearwear dynamics`` writes. Tables: ``timeseries`` (the recorded mesh periods),
    ``path`` (contacts along the path of contact over one mesh period), ``modes`` (poles
    of the damped linearised model: frequencies, damping ratios, mesh energy shares,
    complex shapes), ``modes_undamped`` (natural frequencies and mass-normalised shapes)
    and ``spectrum`` (of dy_p/dt)."""

    def _ts(self, column: str) -> np.ndarray:
        return self.tables["timeseries"][column]

    @property
    def time_s(self) -> np.ndarray:
        """Time, s; shape (n,)."""
        return self._ts("time_s")

    @property
    def mesh_phase_rad(self) -> np.ndarray:
        """Mesh phase (pinion rotation reduced to one mesh period), rad; shape (n,)."""
        return self._ts("mesh_phase_rad")

    @property
    def dte_um(self) -> np.ndarray:
        """Dynamic transmission error (relative displacement along the line of action),
        µm; shape (n,). Its maximum is ``summary["dte"]["max_um"]``."""
        return self._ts("dte_um")

    @property
    def mesh_force_n(self) -> np.ndarray:
        """Mesh force, N; shape (n,)."""
        return self._ts("mesh_force_n")

    @property
    def mesh_stiffness_n_per_m(self) -> np.ndarray:
        """Mesh stiffness along the response, N/m; shape (n,)."""
        return self._ts("mesh_stiffness_n_per_m")

    @property
    def coordinates(self) -> List[str]:
        """The model's generalised coordinates in the column order of ``displacement``,
        ``velocity``, ``acceleration`` and ``mode_shapes``: ``COORDINATES`` for a single
        pair (8); for a gear train of k stages the lateral coordinates of every stage's
        pinion and gear (``x_pinion1`` ... ``y_gear{k}``), then the rotations from the
        motor through every shaft to the brake (``phi_motor`` ... ``phi_brake``), as the
        ``modes_undamped`` table names them."""
        t = self.tables.get("modes_undamped")
        if t is None:
            return list(COORDINATES)
        return [c[len("shape_") :] for c in t.columns if c.startswith("shape_")]

    @property
    def coordinate_units(self) -> List[str]:
        """The SI unit of each of ``coordinates``: ``m`` (lateral) or ``rad``."""
        return ["rad" if c.startswith("phi_") else "m" for c in self.coordinates]

    def _coords(self, prefix: str, suffix: str) -> np.ndarray:
        names = [
            f"{prefix}{c}_{u}{suffix}" for c, u in zip(self.coordinates, self.coordinate_units)
        ]
        return _stack(self.tables["timeseries"], names)

    @property
    def displacement(self) -> np.ndarray:
        """Generalised displacements q, shape (n, d), SI units, columns as
        ``coordinates`` (single pair, d = 8: x, y of pinion and gear in m, then the
        rotations of motor, pinion, gear and brake in rad, ``COORDINATES``)."""
        return self._coords("", "")

    @property
    def velocity(self) -> np.ndarray:
        """Generalised velocities dq/dt, shape (n, d): m/s and rad/s (order as
        ``displacement``)."""
        return self._coords("d", "_per_s")

    @property
    def acceleration(self) -> np.ndarray:
        """Generalised accelerations, shape (n, d): m/s^2 and rad/s^2."""
        return self._coords("dd", "_per_s2")

    @property
    def n_meshes(self) -> int:
        """Number of meshes: 1 for a single pair, k for a gear train of k stages."""
        return len(self.summary.get("meshes", [])) or 1

    def mesh(self, stage: int) -> "MeshResponse":
        """The response of stage ``stage``'s mesh (1 .. ``n_meshes``): its DTE, force,
        stiffness and phase over the recorded time. Stage 1 is what ``dte_um``,
        ``mesh_force_n``, ``mesh_stiffness_n_per_m`` and ``mesh_phase_rad`` give."""
        if isinstance(stage, bool) or not isinstance(stage, int):
            raise TypeError(f"stage: expected an int, got {type(stage).__name__}")
        if not 1 <= stage <= self.n_meshes:
            raise ValueError(f"stage = {stage}: this model has meshes 1 .. {self.n_meshes}")
        prefix = "" if stage == 1 else f"mesh{stage}_"
        meshes = self.summary.get("meshes")
        return MeshResponse(
            stage,
            self.tables["timeseries"],
            prefix,
            meshes[stage - 1] if meshes else {},
        )

    @property
    def friction_coefficient(self) -> np.ndarray:
        """Friction coefficient of pair 0 (the one that entered contact last) and pair 1,
        0 out of contact; shape (n, 2)."""
        return _stack(
            self.tables["timeseries"], ["friction_coefficient_pair0", "friction_coefficient_pair1"]
        )

    @property
    def friction_force_n(self) -> np.ndarray:
        """Signed friction force of pairs 0 and 1, N; shape (n, 2)."""
        return _stack(self.tables["timeseries"], ["friction_force_pair0_n", "friction_force_pair1_n"])

    @property
    def pair_load_n(self) -> np.ndarray:
        """Normal load of pairs 0 and 1, N; shape (n, 2)."""
        return _stack(self.tables["timeseries"], ["load_pair0_n", "load_pair1_n"])

    @property
    def spectrum_frequency_hz(self) -> Optional[np.ndarray]:
        """Frequencies of the dy_p/dt spectrum, Hz; shape (m,) (None without a y
        velocity)."""
        t = self.tables.get("spectrum")
        return None if t is None else t["frequency_hz"]

    @property
    def spectrum_velocity_y_pinion_mm_per_s(self) -> Optional[np.ndarray]:
        """Amplitude spectrum of dy_p/dt, mm/s; shape (m,)."""
        t = self.tables.get("spectrum")
        return None if t is None else t["velocity_y_pinion_amplitude_mm_per_s"]

    @property
    def natural_frequencies_hz(self) -> np.ndarray:
        """Undamped natural frequencies of the model linearised at the mean mesh
        stiffness, ascending, Hz; shape (k,) (k = 8 less the coordinates an imposed speed
        removes). With the case's damping most of these modes are overdamped: see
        ``damped_frequency_hz`` and ``mesh_pole``."""
        return self.tables["modes_undamped"]["undamped_frequency_hz"]

    @property
    def mode_shapes(self) -> np.ndarray:
        """Mass-normalised undamped mode shapes, one row per natural frequency, columns
        as ``coordinates`` (0 on an imposed coordinate); shape (k, d)."""
        return _stack(self.tables["modes_undamped"], [f"shape_{c}" for c in self.coordinates])

    @property
    def damped_frequency_hz(self) -> np.ndarray:
        """Damped frequency |Im lambda| / 2 pi of each pole of the damped linearised
        model (one per conjugate pair; 0 for a real, overdamped pole), Hz; shape (p,)."""
        return self.tables["modes"]["damped_frequency_hz"]

    @property
    def damping_ratio(self) -> np.ndarray:
        """Damping ratio -Re lambda / |lambda| of each pole, dimensionless; shape (p,)."""
        return self.tables["modes"]["damping_ratio"]

    @property
    def mesh_pole(self) -> np.ndarray:
        """Whether each pole is a mesh pole (oscillatory, with most of its strain energy
        in the mesh: where the response peaks when a mesh harmonic meets it); booleans as
        1.0 / 0.0, shape (p,)."""
        return self.tables["modes"]["mesh_pole"]


class MeshResponse:
    """One mesh's response in a dynamics result (``DynamicsResult.mesh(k)``): columns of
    the ``timeseries`` table and the mesh's block of the summary."""

    def __init__(self, stage: int, timeseries: Table, prefix: str, summary: Mapping[str, Any]):
        #: The stage (1-based) of the mesh.
        self.stage = stage
        #: The summary's block of this mesh (``meshes[stage - 1]`` of summary.json; empty
        #: for a single pair, whose numbers are the summary's own).
        self.summary: Mapping[str, Any] = summary
        self._t = timeseries
        self._p = prefix

    def _col(self, name: str) -> np.ndarray:
        if self._p and name == "mesh_phase_rad":
            return self._t[f"{self._p}phase_rad"]
        if self._p and name.startswith("mesh_"):
            return self._t[f"{self._p}{name[len('mesh_'):]}"]
        return self._t[f"{self._p}{name}"]

    @property
    def time_s(self) -> np.ndarray:
        """Time, s; shape (n,)."""
        return self._t["time_s"]

    @property
    def mesh_phase_rad(self) -> np.ndarray:
        """The mesh's phase (its pinion's rotation reduced to one mesh period), rad."""
        return self._col("mesh_phase_rad")

    @property
    def dte_um(self) -> np.ndarray:
        """The mesh's dynamic transmission error, µm; shape (n,)."""
        return self._col("dte_um")

    @property
    def mesh_force_n(self) -> np.ndarray:
        """The mesh's force, N; shape (n,)."""
        return self._col("mesh_force_n")

    @property
    def mesh_stiffness_n_per_m(self) -> np.ndarray:
        """The mesh's stiffness along the response, N/m; shape (n,)."""
        return self._col("mesh_stiffness_n_per_m")

    def __repr__(self) -> str:
        return f"<gearwear.MeshResponse stage {self.stage}>"


class PlanetaryDynamicsResult(_Result):
    """The periodic steady state of a planetary set (``gearwear dynamics`` on a case with
    ``[planetary]``). Tables: ``mesh_forces`` (``time_s``, ``sun_planet_{i}_force_n``,
    ``ring_planet_{i}_force_n``) and ``motions`` (every member's coordinates, m; the
    rotations as ``u`` = base radius x angle). ``summary["planetary_dynamics"]`` holds
    the load sharing and dynamic factors."""

    @property
    def planets(self) -> int:
        """Number of planets N."""
        return sum(1 for c in self.tables["mesh_forces"].columns if c.startswith("sun_planet_"))

    @property
    def time_s(self) -> np.ndarray:
        """Time, s; shape (n,)."""
        return self.tables["mesh_forces"]["time_s"]

    def _forces(self, mesh: str) -> np.ndarray:
        names = [f"{mesh}_planet_{i}_force_n" for i in range(1, self.planets + 1)]
        return _stack(self.tables["mesh_forces"], names)

    @property
    def sun_planet_force_n(self) -> np.ndarray:
        """Force of each sun-planet mesh, N; shape (n, N), planet 1 first."""
        return self._forces("sun")

    @property
    def ring_planet_force_n(self) -> np.ndarray:
        """Force of each ring-planet mesh, N; shape (n, N)."""
        return self._forces("ring")

    @property
    def motions(self) -> Table:
        """Every member's displacements over the recorded time (the ``motions`` table)."""
        return self.tables["motions"]

    @property
    def load_sharing_factor(self) -> np.ndarray:
        """Each planet's load sharing factor, N x its mean sun-mesh force over the sum of
        them (1 for an even share); shape (N,)."""
        return np.asarray(self.summary["planetary_dynamics"]["load_sharing_factor"], dtype=float)

    @property
    def mesh_frequency_hz(self) -> float:
        """Mesh frequency z_r (f_carrier - f_ring), Hz."""
        return float(self.summary["planetary_dynamics"]["mesh_frequency_hz"])


class _Recorded(_Result):
    """A study that writes a record at a sampling rate (the summary's ``record``)."""

    @property
    def record(self) -> Table:
        """The record: ``time_s`` and the channels (a pair's adds ``tachometer_v``)."""
        return self.tables["record"]

    @property
    def sampling_rate_hz(self) -> float:
        """The record's sampling rate, Hz."""
        return float(self.summary["record"]["sampling_rate_hz"])

    @property
    def channel_unit(self) -> str:
        """Unit of the channels: ``m/s^2``, ``g`` or ``mV`` for accelerometers, ``N`` for
        the ring sensor of a planetary set (the force it hears)."""
        return str(self.summary["record"]["channel_unit"])


class PlanetarySignalsResult(_Recorded):
    """What a sensor on the ring of a planetary set hears (``gearwear signals`` on a case
    with ``[planetary]``): the ``record`` (``time_s``, ``ring_sensor_n``) at the case's
    sampling rate and ``orders`` (each carrier order's amplitude over one carrier
    revolution). ``summary["planetary_signals"]`` gives the carrier, mesh and
    planet-pass frequencies and each mesh harmonic's sidebands (docs/SIGNALS.md)."""

    @property
    def orders(self) -> Table:
        """``carrier_order``, ``frequency_hz``, ``amplitude_n`` (single-sided)."""
        return self.tables["orders"]

    @property
    def planet_pass_hz(self) -> float:
        """Planet-pass frequency N f_carrier, Hz."""
        return float(self.summary["planetary_signals"]["planet_pass_hz"])

    @property
    def mesh_frequency_hz(self) -> float:
        """Mesh frequency z_r f_carrier, Hz (the ring fixed)."""
        return float(self.summary["planetary_signals"]["mesh_frequency_hz"])


class WearRunResult:
    """One wear run (dynamic or quasi-static): a row per update in ``updates``, the
    profiles of every update in ``profiles``, and views of them."""

    def __init__(self, mode: str, updates: Table, profiles: Table):
        #: ``"dynamic"`` or ``"quasi_static"``.
        self.mode = mode
        #: One row per update: cycles, maximum wear depths (µm), wear rate (µm per 1000
        #: cycles), roughness (µm), mesh force (N), DTE (µm), dy_p/dt RMS and harmonics
        #: (mm/s), friction coefficient.
        self.updates = updates
        #: Per profile point: rho1 and radii (mm), then per update i the pinion and gear
        #: wear depth (``wear_pinion_um_u{i}``, µm) and pinion wear rate (µm/kcycle).
        self.profiles = profiles

    @property
    def cycles(self) -> np.ndarray:
        """Pinion load cycles at each update (0 first); shape (u,)."""
        return self.updates["cycles"]

    @property
    def max_wear_pinion_um(self) -> np.ndarray:
        """Largest pinion wear depth at each update, µm; shape (u,) (the paper's
        Fig. 13)."""
        return self.updates["max_wear_pinion_um"]

    @property
    def max_wear_gear_um(self) -> np.ndarray:
        """Largest gear wear depth at each update, µm; shape (u,)."""
        return self.updates["max_wear_gear_um"]

    @property
    def rho1_mm(self) -> np.ndarray:
        """Profile points as pinion roll distance along the line of action, mm; shape
        (p,)."""
        return self.profiles["rho1_mm"]

    def _per_update(self, stem: str) -> np.ndarray:
        n = len(self.cycles)
        return np.vstack([self.profiles[f"{stem}_u{i}"] for i in range(n)])

    @property
    def wear_pinion_um(self) -> np.ndarray:
        """Pinion wear depth profile at each update, µm; shape (u, p)."""
        return self._per_update("wear_pinion_um")

    @property
    def wear_gear_um(self) -> np.ndarray:
        """Gear wear depth at the same profile points (the gear point meeting each pinion
        point), µm; shape (u, p)."""
        return self._per_update("wear_gear_um")

    @property
    def wear_rate_pinion_um_per_kcycle(self) -> np.ndarray:
        """Pinion wear per 1000 cycles of the state at each update, µm; shape (u, p)."""
        return self._per_update("rate_pinion_um_per_kcycle")

    def __repr__(self) -> str:
        return f"<gearwear.WearRunResult {self.mode}: {len(self.cycles)} records>"


class DutyResult:
    """What a wear study under a load spectrum (a case with ``[load_spectrum]``) adds:
    the spectrum, what each bin did per run, and (``run`` only) the lives to the wear
    limit. The runs themselves (``WearResult.runs``) hold the shared wear state and the
    response at the monitoring bin."""

    def __init__(self, tables: Mapping[str, Table], summary: Mapping[str, Any]):
        self._tables = tables
        #: The summary's ``load_spectrum``: the bins as used, the monitoring bin, per run
        #: the ranking and wear per bin, and with ``run`` the life table.
        self.summary: Mapping[str, Any] = summary

    @property
    def spectrum(self) -> Table:
        """One row per bin: ``bin``, ``torque_nm``, ``input_speed_hz`` (scales applied),
        and the shares of cycles, time and (of the first run) pinion wear, percent."""
        return self._tables["duty_spectrum"]

    def _of_mode(self, kind: str, mode: str) -> Table:
        """Table ``duty_KIND_MODE`` (``run`` and ``wear`` both name it so)."""
        mode = mode.replace("-", "_")
        name = f"duty_{kind}_{mode}"
        if name not in self._tables:
            ran = sorted(
                n[len(f"duty_{kind}_") :] for n in self._tables if n.startswith(f"duty_{kind}_")
            )
            raise KeyError(f"no {mode!r} run under the spectrum; runs: {', '.join(ran) or 'none'}")
        return self._tables[name]

    def ranking(self, mode: str = "dynamic") -> Table:
        """The bins of run ``mode`` ranked by their share of the pinion's wear (largest
        first): ``rank``, ``bin``, torque, speed, the shares of cycles, pinion wear, gear
        wear and wear at the deepest point, the largest depth the bin added (µm) and the
        wear intensity (share of wear / share of cycles). Table ``duty_bins_MODE``."""
        return self._of_mode("bins", mode)

    def wear_by_bin(self, mode: str = "dynamic") -> Table:
        """Wear depth along the profile at the end of run ``mode``: ``rho1_mm``, the
        totals and what each bin added (``wear_pinion_bin{i}_um``, ``wear_gear_bin{i}_um``)."""
        return self._of_mode("wear_by_bin", mode)

    def dynamic_factor(self, mode: str = "dynamic") -> Table:
        """The dynamic factor (max / mean mesh force) of each bin at every update of run
        ``mode``: ``cycles``, ``dynamic_factor_bin{i}``."""
        return self._of_mode("dynamic_factor", mode)

    @property
    def life(self) -> Optional[Table]:
        """Cycles to the wear limit at each bin alone, under the spectrum and by the
        linear mix (``run`` and ``wear``; the summary's ``life`` adds the hours)."""
        return self._tables.get("duty_life")

    def __repr__(self) -> str:
        return f"<gearwear.DutyResult: {self.spectrum.n_rows} bins>"


class WearResult(_Result):
    """The wear study (dynamic and/or quasi-static): what ``gearwear wear`` writes.
    Tables ``updates_MODE`` and ``wear_profiles_MODE`` per mode; ``runs`` views them;
    under a load spectrum ``duty`` views what each bin did."""

    def __init__(self, *args: Any, **kwargs: Any):
        super().__init__(*args, **kwargs)
        # `wear` writes each run's ranking as duty/bins_MODE.csv, `run` as
        # csv/duty_bins_MODE.csv: both results name the table duty_bins_MODE.
        for n in [n for n in self.tables if n.startswith("bins_")]:
            t = self.tables[n]
            self.tables.setdefault(f"duty_{n}", Table(f"duty_{n}", t.columns, t._data, t._lengths))

    @property
    def duty(self) -> Optional[DutyResult]:
        """The duty-cycle results of a case with a load spectrum, else None."""
        if "duty_spectrum" not in self.tables:
            return None
        return DutyResult(self.tables, self.summary.get("load_spectrum", {}))

    def _runs_of(self, suffix: str) -> Dict[str, WearRunResult]:
        out = {}
        for mode in ("dynamic", "quasi_static"):
            u = self.tables.get(f"updates_{mode}{suffix}")
            p = self.tables.get(f"wear_profiles_{mode}{suffix}")
            if u is not None and p is not None:
                out[mode] = WearRunResult(mode, u, p)
        return out

    @property
    def is_train(self) -> bool:
        """Whether the study ran on a gear train (its runs are per stage: ``stages``)."""
        return any(n.startswith("wear_history_") for n in self.tables)

    @property
    def runs(self) -> Dict[str, WearRunResult]:
        """The runs present by mode (``"dynamic"``, ``"quasi_static"``). A gear train's
        runs are per mesh: ``stages``."""
        if self.is_train:
            raise ValueError(
                f"a gear train of {len(self.stages)} stages wears mesh by mesh: "
                "take result.stages[k][mode] (k = 0 for stage 1) and result.history(mode)"
            )
        return self._runs_of("")

    @property
    def stages(self) -> List[Dict[str, WearRunResult]]:
        """A gear train's runs, one dict per mesh (stage 1 first) of its runs by mode,
        each counting that stage's pinion cycles; empty for a single pair."""
        out = []
        while True:
            runs = self._runs_of(f"_stage{len(out) + 1}")
            if not runs:
                return out
            out.append(runs)

    def history(self, mode: str = "dynamic") -> Table:
        """A gear train's wear history of run ``mode``: one row per update and stage with
        the input cycles, the stage's pinion and gear cycles, its maximum wear depths and
        the stage whose wear cut the block (``block_limited_by_stage``)."""
        name = f"wear_history_{mode.replace('-', '_')}"
        if name not in self.tables:
            raise KeyError(f"no {name!r} table: a gear train's {mode!r} run was not made")
        return self.tables[name]

    @property
    def dynamic(self) -> Optional[WearRunResult]:
        """The dynamic run (None if not run; a gear train's: ``stages``)."""
        return self.runs.get("dynamic")

    @property
    def quasi_static(self) -> Optional[WearRunResult]:
        """The quasi-static run (None if not run)."""
        return self.runs.get("quasi_static")


class RunResult(WearResult):
    """The paper's whole section 4 (``gearwear run``): the summary with the paper
    comparison, every figure's table (``fig02_mesh_stiffness`` ... ``fig13_...``), the
    wear runs (as ``WearResult``), the figures as PNG (``figures_png``) and the HTML
    report (``report_html``). On a gear train: the summary's ``meshes`` (one entry per
    stage) and ``limiting_mesh`` (per mode, the stage that wore deepest), the wear runs
    per mesh as ``stages`` and ``history(mode)``."""


class CalibrationResult(_Result):
    """The posterior of a calibration (``gearwear calibrate``): the summary (each
    parameter's median, 90 % interval, ESS and R-hat, the noise of each observed
    quantity, the surrogate check), the tables ``posterior_samples`` (one row per sample)
    and ``posterior_band`` (the model's band against the observations), figures and
    report. Pass it to ``predict`` as the posterior."""

    @property
    def samples(self) -> Table:
        """The posterior samples: ``wear_coefficient_m2_per_n`` (m^2/N) and, when
        calibrated, ``roughness_scale`` and ``load_torque_nm``."""
        return self.tables["posterior_samples"]

    @property
    def parameters(self) -> Dict[str, Dict[str, Any]]:
        """Each calibrated parameter's summary by column name: median, ci90, ess, rhat."""
        return {p["parameter"]: p for p in self.summary["parameters"]}


class PredictionResult(_Result):
    """A prediction (``gearwear predict`` / ``predict-merge``): the summary (remaining
    life percentiles, the bands at the horizon, failed samples, the surrogate check), the
    tables ``life_samples`` (per sample: parameters, cycles to the limit, status),
    ``fan_wear`` and ``fan_vibration`` (percentile bands over the cycle grid), figures and
    report."""

    @property
    def life(self) -> Dict[str, Any]:
        """Cycles to the wear limit: p05, median, p95, probability beyond the horizon."""
        return self.summary["remaining_life_cycles"]


class LoadSpectrumResult(_Result):
    """The load spectrum of a measured history (``gearwear load-spectrum``): the summary
    (time under load and idle, revolutions, the counting method and classes, the bins),
    the tables ``spectrum`` (one row per bin: ``torque_nm``, ``input_speed_hz``,
    ``share``; the CSV a case's ``load_spectrum.file`` reads), ``ldd`` (every torque x
    speed cell: class edges, ``time_s``, ``cycles``, ``mean_torque_nm``) and
    ``ldd_time_at_level`` (the histogram's data, in hours)."""

    @property
    def bins(self) -> Table:
        """The spectrum's bins: ``torque_nm``, ``input_speed_hz``, ``share`` (of the
        pinion revolutions)."""
        return self.tables["spectrum"]

    @property
    def ldd(self) -> Table:
        """The load duration distribution: one row per torque x speed cell (torque class
        slowest), with its time (s), revolutions and mean torque (N m)."""
        return self.tables["ldd"]

    @property
    def toml(self) -> str:
        """The spectrum as a ``[load_spectrum]`` section of a case file, bins inline."""
        return self._documents["load_spectrum.toml"].decode("utf-8")

    def apply(self, case: Any) -> Any:
        """``case`` with this spectrum as its ``[load_spectrum]`` (any spectrum it had is
        replaced); a new, validated ``Case``."""
        return _gearwear._case_with_spectrum(case, self.toml)


def _as_numbers(values: Sequence[str]) -> np.ndarray:
    try:
        return np.array([float(v) for v in values], dtype=np.float64)
    except ValueError:
        return np.array(values, dtype=object)


class SweepResult:
    """A parameter sweep (``gearwear sweep``, ``sweep-merge``): one row per case."""

    def __init__(
        self,
        summary: Dict[str, Any],
        keys: Sequence[str],
        columns: Sequence[str],
        case_ids: np.ndarray,
        values: Sequence[Sequence[str]],
        branches: Sequence[Optional[str]],
        results: np.ndarray,
        tables: Optional[Dict[str, Any]] = None,
        headline: str = "",
        documents: Optional[Dict[str, bytes]] = None,
        warnings: Sequence[str] = (),
        out: Optional[str] = None,
        incomplete: Optional[str] = None,
    ):
        #: What was run (sweep.json): ``vary`` (keys and values), ``run``,
        #: ``total_cases``, ``failed`` (case id, values, error of each case without a
        #: row), ``base`` (metadata of the base case), modes and resonance crossings.
        self.summary: Dict[str, Any] = summary
        #: The varied keys, in the order given.
        self.keys: List[str] = list(keys)
        #: The result columns (display units in the names, e.g. ``dte_max_um``).
        self.columns: List[str] = list(columns)
        #: Case ids (first key varying slowest), shape (n,).
        self.case_ids: np.ndarray = case_ids.astype(np.int64)
        #: The varied values by key: float64 arrays for numbers, else object arrays of
        #: the text given; shape (n,).
        self.values: Dict[str, np.ndarray] = {
            k: _as_numbers([v[i] for v in values]) for i, k in enumerate(self.keys)
        }
        #: The branch of each row of a continuation sweep (``"up"``/``"down"``), else None.
        self.branches: List[Optional[str]] = list(branches)
        #: The results, shape (n, len(columns)); NaN where not finite.
        self.results: np.ndarray = results
        self.results.flags.writeable = False
        #: The line the command line prints as its result.
        self.headline: str = headline
        #: The output folder written, or None.
        self.out: Optional[Path] = None if out is None else Path(out)
        #: Why the sweep is incomplete (failed cases), or None.
        self.incomplete: Optional[str] = incomplete
        self.warnings: List[str] = list(warnings)

    def __getitem__(self, name: str) -> np.ndarray:
        """A varied key's values or a result column, e.g. ``s["dte_max_um"]``."""
        if name in self.values:
            return self.values[name]
        if name in self.columns:
            return self.results[:, self.columns.index(name)]
        raise KeyError(f"no column {name!r}; keys: {self.keys}; columns: {self.columns}")

    @property
    def table(self) -> Table:
        """The numeric columns as a ``Table``: the varied keys (numeric ones), ``case_id``,
        the results (the layout of sweep.csv)."""
        cols: Dict[str, np.ndarray] = {
            k: v for k, v in self.values.items() if v.dtype == np.float64
        }
        cols["case_id"] = self.case_ids.astype(np.float64)
        for j, c in enumerate(self.columns):
            cols[c] = np.ascontiguousarray(self.results[:, j])
        return Table.from_columns("sweep", cols)

    def to_pandas(self) -> Any:
        """The sweep table as a ``pandas.DataFrame`` (every varied key, ``case_id``,
        the results; needs pandas)."""
        pd = _pandas()
        data: Dict[str, Any] = dict(self.values)
        data["case_id"] = self.case_ids
        for j, c in enumerate(self.columns):
            data[c] = self.results[:, j]
        return pd.DataFrame(data)

    def __len__(self) -> int:
        return len(self.case_ids)

    def __repr__(self) -> str:
        return f"<gearwear.SweepResult: {len(self)} cases x {len(self.columns)} results, varied {self.keys}>"



class SignalsResult(_Recorded):
    """One record of what a sensor sees (``gearwear signals``): the accelerometer channels
    and the tachometer at the sampling rate, their spectrum, the time-synchronous average
    of each shaft, and the condition indicators. Tables: ``record`` (``time_s``, one
    column per sensor with its unit in the name, ``tachometer_v``), ``spectrum``,
    ``tsa_pinion``, ``tsa_gear``. See docs/SIGNALS.md."""

    @property
    def indicators(self) -> List[Dict[str, Any]]:
        """Per channel: ``rms``, ``crest_factor``, ``kurtosis``, and ``pinion`` / ``gear``
        dicts of the TSA indicators (``fm0``, ``fm4``, ``m6a``, ``m8a``, ``na4``,
        ``nb4``, ``energy_ratio``, ``sideband_level_factor``, ``sideband_index``, ...)."""
        return list(self.summary["indicators"])


class DatasetResult(_Result):
    """A labelled dataset written to a folder (``gearwear dataset`` / ``dataset-merge``):
    the summary counts the records (computed, reused, failed, missing from the index).
    The dataset itself is in the folder ``out``: ``index.parquet`` (or ``index.csv``),
    ``signals/<id>.parquet``, ``metadata.json`` (docs/SIGNALS.md, "Datasets")."""

    @property
    def index_path(self) -> Optional[Path]:
        """The index table (Parquet), when the run wrote one (not for a shard)."""
        if self.out is None:
            return None
        p = self.out / "index.parquet"
        return p if p.exists() else None
