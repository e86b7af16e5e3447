"""The native module of gearwear (Rust, PyO3). Use it through the package ``gearwear``,
which wraps these tuples in result objects."""

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

def keys() -> List[Dict[str, Any]]:
    """Every key of a case: ``{key, unit, valid, doc, default}`` each."""

def stiffness(
    case: Case, budget_scale: Optional[float] = None, no_budget: bool = False
) -> Tuple[Dict[str, Any], _Tables, str]:
    """(summary, tables, headline) of ``gearwear stiffness``."""

def dynamics(
    case: Case,
    transmission_error: Optional[npt.NDArray[np.float64]] = None,
    budget_scale: Optional[float] = None,
    no_budget: bool = False,
) -> Tuple[Dict[str, Any], _Tables, str]:
    """(summary, tables, headline) of ``gearwear dynamics``; ``transmission_error`` of
    shape (n, 2): pinion angle deg, error um."""

def wear(
    case: Case,
    mode: str = "both",
    progress: Optional[_Progress] = None,
    budget_scale: Optional[float] = None,
    no_budget: bool = False,
) -> Tuple[Dict[str, Any], _Tables, str]:
    """(summary, tables, headline) of ``gearwear wear --mode MODE``."""

def run(
    case: Case,
    out: Optional[PathLike[str]] = None,
    progress: Optional[_Progress] = None,
    budget_scale: Optional[float] = None,
    no_budget: bool = False,
) -> Tuple[Dict[str, Any], _Tables, str, Dict[str, bytes]]:
    """(summary, tables, headline, documents) of ``gearwear run``."""

def sweep(
    case: Case,
    vary: Sequence[Tuple[str, str]],
    run: str = "dynamics",
    progress: Optional[_Progress] = None,
    budget_scale: Optional[float] = None,
    no_budget: bool = False,
) -> Tuple[
    Dict[str, Any],
    List[str],
    List[str],
    npt.NDArray[np.float64],
    List[List[str]],
    npt.NDArray[np.float64],
]:
    """(summary, keys, columns, case_ids, values, results) of ``gearwear sweep``."""

def _time_rust_dynamics(case: Case, repeats: int) -> List[float]:
    """Seconds of each of ``repeats`` Rust-only runs of what ``dynamics(case)`` runs."""
