"""The native module of gearwear (Rust, PyO3). Use it through the package ``gearwear``,
which wraps these dicts in result objects. Each study function runs the job of the
library's application layer that the command of the same name runs, and returns a dict
``{summary, tables, headline, documents, warnings, out, incomplete}`` (sweeps add
``keys, columns, case_ids, values, branches, results``)."""

from os import PathLike
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
#: The dynamic model's 8 coordinates and their SI units.
COORDINATES: List[str]
COORDINATE_UNITS: List[str]

# {name: (columns, data of shape (n_columns, n_rows), each column's length)}
_Tables = Dict[str, Tuple[List[str], npt.NDArray[np.float64], List[int]]]
_Progress = Callable[[str, float, float], Any]

class Case:
    """A validated gear-pair case, immutable. See ``gearwear.keys()`` for every key with
    its unit, default and valid range."""

    def __init__(self) -> None:
        """The paper's case (as ``Case.paper()``)."""
    @staticmethod
    def paper() -> Case:
        """The paper's case (Coatings 2022, 12, 1250), the defaults of every key."""
    @staticmethod
    def from_toml(source: Union[str, PathLike[str]]) -> Case:
        """A case from a TOML case file (a path, or a str file name) or TOML text (a str
        with a line break, ``=`` or ``[``). Raises CaseError, OSError."""
    @overload
    def set(self, key: str, value: Any, /) -> Case: ...
    @overload
    def set(self, values: Mapping[str, Any], /) -> Case: ...
    def set(self, *args: Any) -> Case:
        """A new case with ``key`` (``section.key``) set to ``value``, as ``--set``; or
        several keys at once from a mapping. None removes a key (its default applies).
        Raises CaseError listing every problem."""
    def to_toml(self) -> str:
        """The case as commented TOML (as ``gearwear config``)."""
    def __getitem__(self, key: str) -> Any:
        """A key's value (None for an unset optional key); KeyError for an unknown key."""
    def __contains__(self, key: str) -> bool: ...
    def keys(self) -> List[str]:
        """Every key, in case-file order."""
    def to_dict(self) -> Dict[str, Any]:
        """``{key: value}`` for every key."""
    @property
    def sha256(self) -> str:
        """SHA-256 of the resolved case (``metadata.case_sha256`` of every summary)."""
    def __eq__(self, other: object) -> bool: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str]]: ...

class Problem:
    """One problem of an invalid case."""

    @property
    def key(self) -> Optional[str]:
        """Dotted key (``section.key``, or an unknown section's name), None if none."""
    @property
    def value(self) -> Any:
        """The value given (None if the message names none)."""
    @property
    def valid(self) -> Optional[str]:
        """What would be valid: range, choices, valid keys or a condition."""
    @property
    def message(self) -> str:
        """The whole message, as the command line prints it."""
    def to_dict(self) -> Dict[str, Any]: ...

class CaseError(ValueError):
    """An invalid case; ``problems`` lists every problem."""

    problems: List[Problem]

class StudyError(RuntimeError):
    """A study failed on a valid case (e.g. no periodic steady state)."""

def _cli_main(argv: List[str]) -> int: ...
def keys() -> List[Dict[str, Any]]:
    """Every key of a case: ``{key, unit, valid, doc, default}`` each."""

_Result = Dict[str, Any]
_Path = Optional[Union[str, PathLike[str]]]
# A CSV path, or (column names, one float64 array per column; NaN: not measured).
_TableIn = Union[str, PathLike[str], Tuple[List[str], List[npt.NDArray[np.float64]]]]

def stiffness(
    case: Case,
    *,
    out: _Path = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear stiffness``; ``figures``: "png" (default), "svg" or "png,svg";
    ``figure_size``: (width, height) px of a one-panel figure."""

def dynamics(
    case: Case,
    transmission_error: Optional[npt.NDArray[np.float64]] = None,
    *,
    out: _Path = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear dynamics``; ``transmission_error`` of shape (n, 2): pinion angle deg,
    error µm."""

def wear(
    case: Case,
    mode: str = "both",
    progress: Optional[_Progress] = None,
    *,
    out: _Path = None,
    resume: bool = False,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear wear --mode MODE``."""

def run(
    case: Case,
    out: _Path = None,
    progress: Optional[_Progress] = None,
    *,
    resume: bool = False,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear run``."""

def sweep(
    case: Case,
    vary: Sequence[Tuple[str, Union[str, Sequence[Any]]]],
    run: str = "dynamics",
    progress: Optional[_Progress] = None,
    *,
    out: _Path = None,
    shard: Optional[Union[str, Tuple[int, int]]] = None,
    continuation: Optional[str] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear sweep``."""

def sweep_merge(
    inputs: Sequence[Union[str, PathLike[str]]],
    out: _Path = None,
    *,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear sweep-merge``."""

def calibrate(
    case: Case,
    observations: _TableIn,
    *,
    seed: int = 1,
    samples: int = 2000,
    walkers: int = 32,
    steps: int = 2000,
    check_runs: int = 3,
    out: _Path = None,
    progress: Optional[_Progress] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear calibrate``."""

def predict(
    case: Case,
    posterior: Optional[_TableIn] = None,
    *,
    limit_um: float,
    cycles: float,
    seed: int = 1,
    samples: Optional[int] = None,
    grid_points: int = 101,
    forward: str = "surrogate",
    shard: Optional[Union[str, Tuple[int, int]]] = None,
    check_runs: int = 3,
    out: _Path = None,
    progress: Optional[_Progress] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    future_spectrum: Optional[Union[str, PathLike[str]]] = None,
    future_from_cycles: Optional[float] = None,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear predict``."""

def predict_merge(
    inputs: Sequence[Union[str, PathLike[str]]],
    out: _Path = None,
    *,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear predict-merge``."""

def signals(
    case: Case,
    *,
    transfer_path: _Path = None,
    out: _Path = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear signals``."""

def dataset(
    design: Union[str, PathLike[str], Mapping[str, Any]],
    out: Union[str, PathLike[str]],
    *,
    shard: Optional[Tuple[int, int]] = None,
    progress: Optional[Callable[[str, float, float], Any]] = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear dataset``."""

def dataset_merge(
    inputs: Sequence[Union[str, PathLike[str]]],
    out: Union[str, PathLike[str]],
    *,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
    transfer_path: Optional[Union[str, PathLike[str]]] = None,
    budget_scale: float = 1.0,
) -> _Result:
    """``gearwear dataset-merge``."""

def _time_rust_dynamics(case: Case, repeats: int) -> List[float]:
    """Seconds of each of ``repeats`` Rust-only runs of what ``dynamics(case)`` runs."""

def _running_jobs() -> int:
    """Jobs still running on the pool, including an interrupted evaluation finishing in
    the background (for tests)."""

def load_spectrum(
    history: _TableIn,
    *,
    torque_classes: int = 10,
    speed_classes: int = 5,
    interpolation: str = "linear",
    level: str = "mean",
    torque_shaft: str = "pinion",
    gap_factor: float = 10.0,
    merge_below_share: float = 1e-3,
    out: _Path = None,
    budget_scale: float = 1.0,
    replace: bool = False,
    figures: Optional[str] = None,
    figure_size: Optional[Tuple[int, int]] = None,
) -> _Result:
    """``gearwear load-spectrum``."""

def _case_with_spectrum(case: Case, section: str) -> Case: ...
