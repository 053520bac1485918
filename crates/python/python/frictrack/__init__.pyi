"""Type stubs of the frictrack package (SI units: m, s, N, J; speeds in m/s)."""

import os
from pathlib import Path
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

__version__: str

#: Each table's columns and their units: "histories", "snapshots", "wheels".
COLUMNS: Dict[str, Dict[str, str]]

ScenarioLike = Union[None, str, "os.PathLike[str]", Mapping[str, Any]]
#: `progress=`: a callable of the fraction done (0–1), True for a tqdm bar, False for none (default: a tqdm bar where
#: tqdm is installed and standard error is a terminal).
ProgressLike = Union[None, bool, Callable[[float], Any]]

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
    `snapshots` (snapshots.csv), `wheels` (wheels.csv, None without vehicles), `sleepers` (sleepers.csv: the
    sleepers under recorded sections, None where none is), `losses` (losses of wheel–rail contact), `warnings`, `report` (the text `frictrack run` prints; also `str(run)`), `folder` (the run folder
    when run with `out`, else None)."""

    summary: Dict[str, Any]
    report: str
    histories: Table
    snapshots: Table
    wheels: Optional[Table]
    sleepers: Optional[Table]
    warnings: List[str]
    folder: Optional[Path]
    @property
    def losses(self) -> Optional[Table]: ...
    def report_html(self, out: Union[str, os.PathLike[str], None] = None) -> str:
        """The run's report as one self-contained HTML page (also written to `out`); needs a run with `out`."""

class Sweep(Table):
    """`frictrack sweep`'s CSV as a table (one row per speed), the failed runs (speed m/s, error) and the warnings
    for the swept speeds; with check_resolution, the check at the sweep's peak."""

    failures: List[Tuple[float, str]]
    warnings: List[str]
    resolution_check: Optional[Dict[str, Any]]

def run(
    scenario: ScenarioLike = None,
    *,
    speed: Union[float, str] = ...,
    acceleration: float = ...,
    train: str = ...,
    devices: int = ...,
    device_force: float = ...,
    distributed_friction: float = ...,
    damping_ratio: float = ...,
    theta: float = ...,
    spectral_radius: float = ...,
    elements: int = ...,
    load_advance: float = ...,
    max_step: float = ...,
    solver: str = ...,
    tolerance: float = ...,
    steady_start: float = ...,
    static_start: float = ...,
    absorbing_zones: float = ...,
    extremes_window: Sequence[float] = ...,
    progress: ProgressLike = None,
    out: Union[str, os.PathLike, None] = None,
    check_resolution: bool = False,
    accuracy: Optional[float] = None,
) -> Run:
    """One run of `scenario` (a TOML path, a TOML string, a dict, or None for the reference case) with overrides named
    as the command line's flags; with `out`, the run folder `frictrack run --out` writes (summary.json, CSVs,
    figures); with `check_resolution`, each outcome's error estimated from twins at other resolutions
    (summary["resolution_check"]); with `accuracy`, refined until every outcome is within it (summary["accuracy"]);
    releases the GIL, stops on Ctrl-C, raises InputError naming bad input."""

def sweep(
    scenario: ScenarioLike = None,
    speeds: Union[float, str, Sequence[Union[float, str]]] = ...,
    jobs: Optional[int] = None,
    progress: ProgressLike = None,
    check_resolution: bool = False,
    **overrides: Any,
) -> Sweep:
    """One run per speed (m/s) on `jobs` threads (None: all cores), as `frictrack sweep`; with `check_resolution`,
    the run at the sweep's peak checked against its twins (Sweep.resolution_check)."""

def analytic(
    scenario: ScenarioLike = None,
    speeds: Union[float, str, Sequence[Union[float, str]]] = ...,
    damping_ratio: Optional[float] = None,
    train: Optional[str] = None,
) -> List[Dict[str, Any]]:
    """`frictrack analytic --format json`'s points: the closed-form steady state per speed (m/s)."""

class Stationary:
    """The stationary wave per speed: `points` (dicts, as `frictrack stationary --format json`), `waves` (speed m/s →
    the wave's shape: s, deflection, slope, moment, soil_reaction, friction_force, with their units; on a `[ground]`
    s and deflection along the train),
    `warnings` (peaks resolved to worse than 1 %), `report` (the table `frictrack stationary` prints; also
    `str(result)`)."""

    points: List[Dict[str, Any]]
    report: str
    waves: Dict[float, Table]
    warnings: List[str]
    measured: Optional[Dict[str, Any]]

def stationary(
    scenario: ScenarioLike = None,
    speeds: Union[float, str, Sequence[Union[float, str]]] = ...,
    domain: Optional[Sequence[float]] = None,
    element_length: Optional[float] = None,
    progress: ProgressLike = None,
    measured: Union[str, "os.PathLike[str]", None] = None,
    **overrides: Any,
) -> Stationary:
    """The stationary wave on the infinite track at `speeds` (m/s) on the moving domain (behind, ahead) m (None: the
    command line's default domain); on a `[ground]` the train's steady wave (domain behind its last axle and ahead of
    its first; no element length; `measured` a record set beside the wave at one speed)."""

class Study:
    """A study preset's results: `summary`, `table` (its CSV with units), `headline`, `lines`."""

    name: str
    summary: Dict[str, Any]
    table: Table
    headline: List[str]
    lines: List[str]

def study(
    name: str,
    scenario: ScenarioLike = None,
    resolution: str = "coarse",
    jobs: Optional[int] = None,
    deck_track: Optional[str] = None,
    **overrides: Any,
) -> Study:
    """Run the study preset `name` as `frictrack study` does; `deck_track` ("ballasted" or "direct-fastening") sets
    the EN 1990 deck-acceleration limit of the `hslm` study's verdicts."""

def report(folder: Union[str, os.PathLike[str]], out: Union[str, os.PathLike[str], None] = None) -> Path:
    """Write the report of a run, study or reproduce folder as one self-contained HTML file (default
    `folder/report.html`): figures inline as SVG, tables, verdicts, warnings, scenario, command, version, commit,
    date. Returns the path written."""

def train(name: str) -> Dict[str, Any]:
    """A train's summary (name, axles, patches, length m, total_force N) and `axles_table` (offset m, force N)."""

def track_profile(
    spectrum: str = "german-low",
    length: float = 1000.0,
    spacing: float = 0.25,
    seed: int = 1,
    band: Optional[Sequence[float]] = None,
) -> Tuple[Table, Table, Dict[str, Any]]:
    """A random rail's sample (x m, r m), periodogram and summary, as `frictrack track-profile`."""

def trains() -> List[str]:
    """The train catalogue's names."""

def override_table() -> List[Tuple[str, str, str, str]]:
    """(keyword, type, unit or "", what it sets) per keyword override of :func:`run`."""

def override_names() -> List[str]:
    """The keyword overrides `run` and `sweep` take."""

class Receptance:
    """The track's receptance over frequency: `table` (frequency Hz, real/imaginary/magnitude of α m/N, phase deg,
    mobility m/(s·N)), `resonances` (refined peaks of |α|), `summary` (the JSON), `warnings`, `report` (the text of
    `frictrack receptance`; also `str()`)."""

    summary: Dict[str, Any]
    table: Table
    resonances: List[Dict[str, Any]]
    report: str
    warnings: List[str]

def receptance(
    scenario: ScenarioLike = None,
    frequencies: Sequence[float] = ...,
    at: Optional[float] = None,
    excite: Optional[float] = None,
    jobs: Optional[int] = None,
    out: Union[str, os.PathLike[str], None] = None,
    **overrides: Any,
) -> Receptance:
    """`frictrack receptance`: α = w(at)/F (m/N) at each frequency (Hz) for a force at `excite` (default `at`, the
    point receptance; `at` defaults to mid-track), from the scenario's own model; warnings as UserWarning."""

class Ground:
    """`frictrack ground`: `dispersion` (frequency Hz, phase_velocity m/s), `speeds` (speed m/s, max_downward_deflection
    and max_upward_deflection m), `stiffness` (k_eq along the load's line, N/m²), the critical speeds (m/s; None where
    undefined), `summary` (the JSON, units in `summary["units"]`), `warnings`, `report` (also `str()`)."""

    summary: Dict[str, Any]
    dispersion: Table
    speeds: Table
    stiffness: Table
    critical_speed: Optional[float]
    winkler_critical_speed: float
    minimum_phase_velocity: Optional[float]
    report: str
    warnings: List[str]

def ground(
    scenario: ScenarioLike,
    frequencies: Optional[Sequence[float]] = None,
    jobs: Optional[int] = None,
    out: Union[str, os.PathLike[str], None] = None,
) -> Ground:
    """`frictrack ground`: the composite beam on the scenario's `[ground]` — Rayleigh modes, the Winkler control, the
    critical speed on the ground; warnings as UserWarning."""
