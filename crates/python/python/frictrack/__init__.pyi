"""Type stubs of the frictrack package (SI units: m, s, N, J; speeds in m/s)."""

import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

__version__: str

#: Each table's columns and their units: "histories", "snapshots", "wheels".
COLUMNS: Dict[str, Dict[str, str]]

ScenarioLike = Union[None, str, "os.PathLike[str]", Mapping[str, Any]]

class InputError(ValueError):
    """Bad input: the message names the field (its dotted path in the scenario, or the keyword), its value and what
    is allowed."""

class Table:
    """A table: `data` a NumPy structured array (float64 fields), `units` each column's unit."""

    data: np.ndarray
    units: Dict[str, str]
    def __init__(self, data: np.ndarray, units: Mapping[str, str]) -> None: ...
    @classmethod
    def from_records(cls, records: Sequence[Mapping[str, Any]], units: Mapping[str, str]) -> "Table": ...
    @property
    def columns(self) -> List[str]: ...
    def __getitem__(self, column: str) -> np.ndarray: ...
    def __len__(self) -> int: ...
    def to_pandas(self) -> Any:
        """A pandas DataFrame with the units in `attrs["units"]` (pandas must be installed)."""

class Run:
    """One run: `summary` (dict, the keys of `frictrack run --format json`), `histories` (histories.csv: section m,
    time s, load_position m, deflection m, velocity m/s, acceleration m/s², moment N·m, friction_force N),
    `snapshots` (snapshots.csv), `wheels` (wheels.csv, None without vehicles), `losses` (losses of wheel–rail
    contact), `warnings`."""

    summary: Dict[str, Any]
    histories: Table
    snapshots: Table
    wheels: Optional[Table]
    warnings: List[str]
    @property
    def losses(self) -> Optional[Table]: ...

class Sweep(Table):
    """`frictrack sweep`'s CSV as a table (one row per speed) and the failed runs (speed m/s, error)."""

    failures: List[Tuple[float, str]]

def run(
    scenario: ScenarioLike = None,
    *,
    speed: float = ...,
    train: str = ...,
    devices: int = ...,
    device_force: float = ...,
    distributed_friction: float = ...,
    damping_ratio: float = ...,
    theta: float = ...,
    elements: int = ...,
    load_advance: float = ...,
    solver: str = ...,
    tolerance: float = ...,
    steady_start: float = ...,
    static_start: float = ...,
    absorbing_zones: float = ...,
    extremes_window: Sequence[float] = ...,
) -> Run:
    """One run of `scenario` (a TOML path, a TOML string, a dict, or None for the reference case) with overrides named
    as the command line's flags; releases the GIL, stops on Ctrl-C, raises InputError naming bad input."""

def sweep(
    scenario: ScenarioLike = None,
    speeds: Sequence[float] = ...,
    jobs: Optional[int] = None,
    **overrides: Any,
) -> Sweep:
    """One run per speed (m/s) on `jobs` threads (None: all cores), as `frictrack sweep`."""

def trains() -> List[str]:
    """The train catalogue's names."""

def override_names() -> List[str]:
    """The keyword overrides `run` and `sweep` take."""
