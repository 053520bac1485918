"""frictrack from Python: railway track dynamics under moving trains with Coulomb friction.

A thin layer over frictrack's Rust library (the same that the ``frictrack`` command runs): a scenario is read by the
library's parser and run by the library; this package only turns what the library returns into Python objects —
the run summary into a dict with the keys of ``frictrack run --format json``, the tables into NumPy structured
arrays. Units are SI throughout (m, s, N, J; speeds in m/s); each table's units are in its ``units`` mapping and in
the ``attrs`` of its pandas frame.

>>> import frictrack
>>> run = frictrack.run(speed=150.0, distributed_friction=2000.0)
>>> run.summary["max_downward_deflection"]["value"]   # m; also "position" (m) and "time" (s)  # doctest: +SKIP
"""

from __future__ import annotations

import json
import os
import sys
import warnings as _warnings
from pathlib import Path
from typing import Any, Callable, Dict, Mapping, Optional, Sequence, Union

from . import _native
from ._args import _domain, _jobs, _numbers, _path, _place, _speeds
from ._progress import ProgressLike, _Reporter
from ._report import report
from ._tables import Table, parse_csv

__all__ = [
    "COLUMNS", "Ground", "InputError", "Receptance", "Run", "Stationary", "Study", "Sweep", "Table", "analytic",
    "ground", "override_names", "override_table", "receptance", "report", "run", "stationary", "study", "sweep", "track_profile", "train",
    "trains", "__version__",
]

InputError = _native.InputError
__version__: str = _native.__version__

#: Each table's columns and units, as the library writes them (``histories.csv``, ``snapshots.csv``, ``wheels.csv``).
COLUMNS: Dict[str, Dict[str, str]] = {name: dict(columns) for name, columns in _native.columns()}

ScenarioLike = Union[None, str, "os.PathLike[str]", Mapping[str, Any]]


def _source(scenario: ScenarioLike) -> "tuple[str, Optional[str]]":
    """(kind, text) of a scenario: none (the reference case), a file, a TOML string, or a dict."""
    if scenario is None:
        return "reference", None
    if isinstance(scenario, Mapping):
        return "json", json.dumps(scenario)
    if isinstance(scenario, os.PathLike):
        return "path", os.fspath(scenario)
    if isinstance(scenario, str):
        # A TOML string has a newline or a '='; a file name has neither.
        if "\n" in scenario or "=" in scenario:
            return "toml", scenario
        return "path", scenario
    raise TypeError(f"scenario must be None, a path, a TOML string or a dict, not {type(scenario).__name__}")


# The overrides a receptance uses: the track's damping, mesh and absorbing zones; a load's (speed, train, friction,
# the time step and solver) do nothing for it and are refused rather than ignored.
_RECEPTANCE_OVERRIDES = ("damping_ratio", "elements", "absorbing_zones")


class Run:
    """One run's results.

    ``summary``: the run summary, a dict with the keys and values of ``frictrack run --format json`` (m, s, N, J).
    ``histories``: the recorded sections over time (``histories.csv``), a :class:`Table`.
    ``snapshots``: the beam's deflection and moment at the requested instants (``snapshots.csv``).
    ``wheels``: each wheel over time (``wheels.csv``), or ``None`` without vehicles.
    ``sleepers``: the sleepers under the recorded sections over time (``sleepers.csv``: deflection m, acceleration
    m/s², pad and ballast forces N, a ballast body's acceleration m/s² or NaN without one), or ``None`` where no
    recorded section is over a sleeper.
    ``losses``: each loss of wheel–rail contact (from ``summary["vehicles"]["losses"]``), or ``None``.
    ``warnings``: what the command line would print as warnings.
    ``report``: the text report ``frictrack run`` prints (also ``str(run)``).
    ``folder``: the run folder, when the run was given ``out`` (else ``None``); :meth:`report_html` reports it.
    """

    def __init__(self, summary: Dict[str, Any], histories: Table, snapshots: Table,
                 wheels: Optional[Table], warnings: "list[str]", report: str = "",
                 folder: "Optional[os.PathLike[str]]" = None, sleepers: Optional[Table] = None) -> None:
        self.summary = summary
        self.folder = folder
        self.report = report
        self.histories = histories
        self.snapshots = snapshots
        self.wheels = wheels
        self.sleepers = sleepers
        self.warnings = warnings

    @property
    def losses(self) -> Optional[Table]:
        vehicles = self.summary.get("vehicles")
        if vehicles is None:
            return None
        return Table.from_records(
            vehicles["losses"],
            {"wheel": "1", "lift_off_position": "m", "lift_off_time": "s", "landing_position": "m",
             "duration": "s", "impact_force": "N"},
        )

    def report_html(self, out: "str | os.PathLike[str] | None" = None) -> str:
        """This run's report as one self-contained HTML page (as ``frictrack report`` writes it: figures inline,
        tables, warnings, scenario, command, version, commit, date), also written to ``out`` when given. Needs the
        run folder: run with ``out=DIR``."""
        if self.folder is None:
            raise InputError("invalid out = None: a run's report is made from its folder; run it with out=DIR "
                             "(frictrack.run(..., out='results')), then call report_html()")
        target = _path("out", out, "a file path for the HTML report")
        if target is not None:
            _native.write_report(os.fspath(self.folder), target)
        return _native.report_html(os.fspath(self.folder))

    def __str__(self) -> str:
        return self.report

    def __repr__(self) -> str:
        down = (self.summary.get("max_downward_deflection") or {}).get("value")
        return f"<frictrack.Run v = {self.summary.get('speed')} m/s, max downward deflection {down} m>"


def run(
    scenario: ScenarioLike = None, *, progress: ProgressLike = None, out: "str | os.PathLike[str] | None" = None,
    check_resolution: bool = False, accuracy: Optional[float] = None, **overrides: Any,
) -> Run:
    """Run ``scenario`` (a TOML file path, a TOML string, a dict with the file's keys, or ``None`` for the reference
    case) with keyword ``overrides`` named as the command line's flags: ``speed`` (m/s, or text with its unit such as
    ``"360km/h"``), ``acceleration`` (m/s², negative brakes; ``speed`` is then the speed at x = 0), ``train`` (a
    catalogue name or a CSV file), ``devices``, ``device_force`` (N),
    ``distributed_friction`` (N/m), ``damping_ratio``, ``theta``, ``spectral_radius``, ``elements``, ``load_advance`` (m), ``max_step``
    (s), ``solver``, ``tolerance``, ``steady_start`` (m), ``static_start`` (m), ``absorbing_zones`` (m), ``extremes_window``
    ([A, B] m). :func:`override_table` says what each sets.

    The run is ``frictrack run SCENARIO --format json --out DIR``: mid-span is recorded when the scenario names no
    section. With ``out`` (a folder, created if missing) the run folder is written there as that command writes it:
    ``summary.json``, ``histories.csv``, ``snapshots.csv``, ``wheels.csv`` with vehicles, ``sleepers.csv`` with
    sleepers under recorded sections, and the figures (PNG, SVG). It releases the GIL (other threads run meanwhile) and stops within a step on Ctrl-C
    (KeyboardInterrupt). Bad input raises :class:`InputError` naming the field. ``progress``: a callable of the
    fraction done, ``True`` for a tqdm bar, ``False`` for none; by default a tqdm bar where tqdm is installed and
    standard error is a terminal.

    ``check_resolution=True`` is ``frictrack run --check-resolution``: the run's twins at other resolutions (one
    coarser and one finer, or two finer) run after it, about 4–20 times its cost, and ``summary["resolution_check"]``
    holds each outcome's values at the three resolutions, how they converge and the run's estimated error (``None``
    where they do not converge).

    ``accuracy=TOL`` is ``frictrack run --accuracy TOL``: the run refined (elements and load advance halved together)
    until every outcome's estimated error is within TOL of its value (0.01: 1 %); the result is the finest run's,
    its ``summary["resolution_check"]`` the last three resolutions and ``summary["accuracy"]`` the tolerance, whether
    it was reached (``status``: ``reached`` or ``not_reached`` with ``why`` and the ``outcomes`` above TOL), every
    resolution run, the outcomes that diverge and, with ballast friction, the ``law`` it ran (one section a node where
    the friction is light and the law the default). A scenario's ``[integration] accuracy`` asks the same;
    ``accuracy=`` overrides it.
    """
    if not isinstance(check_resolution, bool):
        raise InputError(f"invalid check_resolution = {check_resolution!r}: True or False")
    if accuracy is not None and (isinstance(accuracy, bool) or not isinstance(accuracy, (int, float))):
        raise InputError(f"invalid accuracy = {accuracy!r}: a relative error in (0, 1): 0.01 asks for every outcome "
                         "within 1 %")
    if accuracy is not None and check_resolution:
        raise InputError("invalid check_resolution = True beside accuracy: accuracy checks every resolution it runs")
    kind, text = _source(scenario)
    folder = _path("out", out, "a folder path")
    given = [] if scenario is None else ["{…}" if isinstance(scenario, Mapping) else repr(scenario)]
    given += [f"{k}={v!r}" for k, v in overrides.items()] + ([] if folder is None else [f"out={folder!r}"])
    given += ["check_resolution=True"] if check_resolution else []
    given += [] if accuracy is None else [f"accuracy={accuracy!r}"]
    with _Reporter(progress, "run") as report:
        summary, lines, histories, snapshots, wheels, sleepers, warnings = _native.run(
            kind, text, list(overrides.items()), report, folder,
            f"frictrack.run({', '.join(given)}) (Python)", check_resolution,
            None if accuracy is None else float(accuracy),
        )
    return Run(
        json.loads(summary),
        parse_csv(histories, COLUMNS["histories"]),
        parse_csv(snapshots, COLUMNS["snapshots"]),
        None if wheels is None else parse_csv(wheels, COLUMNS["wheels"]),
        list(warnings),
        lines,
        None if out is None else Path(out),
        None if sleepers is None else parse_csv(sleepers, COLUMNS["sleepers"]),
    )


class Sweep(Table):
    """A sweep's table (``frictrack sweep``'s CSV: one row per speed, SI units in ``units``), its ``failures``,
    (speed m/s, error) for each run that failed (its row is NaN), and its ``warnings``, what the command line warns
    for the runs at the lowest and highest speed (e.g. a load advance too coarse there); with ``check_resolution``,
    ``resolution_check``: the run at the sweep's peak checked against its twins (``speed``, ``point``, ``check`` as
    in a run's summary), else ``None``."""

    def __init__(self, table: Table, failures: "list[tuple[float, str]]", warnings: "list[str]",
                 resolution_check: Optional[Dict[str, Any]] = None) -> None:
        super().__init__(table.data, table.units)
        self.failures = failures
        self.warnings = warnings
        self.resolution_check = resolution_check


def sweep(scenario: ScenarioLike = None, speeds: Sequence[float] = (), jobs: Optional[int] = None,
          progress: ProgressLike = None, check_resolution: bool = False, **overrides: Any) -> Sweep:
    """One run per speed of ``speeds`` (m/s), on ``jobs`` worker threads (``None``: all cores), as ``frictrack
    sweep``: the same CSV as a table (``speed``, ``max_downward_deflection``, … with their units). A failed run
    leaves a NaN row and is listed in ``failures``; the others are kept. The scenario, overrides and ``progress``
    (the fraction of runs done) are as for :func:`run`. ``check_resolution=True`` is ``frictrack sweep
    --check-resolution``: the run at the speed of the largest max downward deflection checked against its twins
    (``resolution_check``)."""
    if not isinstance(check_resolution, bool):
        raise InputError(f"invalid check_resolution = {check_resolution!r}: True or False")
    kind, text = _source(scenario)
    with _Reporter(progress, "sweep") as report:
        csv, failures, warnings, checked = _native.sweep(
            kind, text, _speeds(speeds), _jobs(jobs), list(overrides.items()), report, check_resolution
        )
    return Sweep(parse_csv(csv, dict(_native.sweep_columns())), [(float(v), str(e)) for v, e in failures],
                 list(warnings), None if checked is None else json.loads(checked))


def analytic(scenario: ScenarioLike = None, speeds: Sequence[float] = (), damping_ratio: Optional[float] = None,
             train: Optional[str] = None) -> "list[Dict[str, Any]]":
    """The closed-form steady state of the scenario's beam on an infinite foundation (``frictrack analytic``) at each
    speed (m/s), optionally at another damping ratio and under a train: one dict per speed, the keys of ``frictrack
    analytic --format json`` (deflections m, moments N·m, as magnitudes). Undamped within 1 % of the critical speed
    a ``UserWarning`` says the number is the undamped resonance, which grows without bound there."""
    kind, text = _source(scenario)
    points, warnings = _native.analytic(kind, text, _speeds(speeds), damping_ratio, train)
    for warning in warnings:
        _warnings.warn(warning, stacklevel=2)
    return json.loads(points)


class Stationary:
    """The stationary wave on the infinite track at each speed (``frictrack stationary``): ``points`` one dict per
    speed (its ``status``: "converged", "not converged", "domain too short", "no stationary wave"; peaks m, moments
    N·m, powers W; ``discretisation_error`` of the peaks from one halving of the elements), ``waves`` each found
    wave's shape by speed (m/s) as a :class:`Table` (s, deflection, slope, moment, soil_reaction, friction_force, with
    their units; on a ``[ground]`` s and deflection along the train, s = 0 at its first axle), ``warnings`` what the
    command line warns
    (peaks resolved to worse than 1 %), ``report`` the table ``frictrack stationary`` prints (also ``str()``),
    ``measured`` the comparison with a measured record where one was given (on a ``[ground]``: ``direction``,
    ``shift`` m, ``rms_misfit`` and ``rms_measured`` m, the peaks of both in m), else None."""

    def __init__(self, points: "list[Dict[str, Any]]", waves: Dict[float, Table], warnings: "list[str]",
                 report: str = "", measured: Optional[Dict[str, Any]] = None) -> None:
        self.points = points
        self.waves = waves
        self.warnings = warnings
        self.report = report
        self.measured = measured

    def __str__(self) -> str:
        return self.report


def stationary(scenario: ScenarioLike = None, speeds: Sequence[float] = (),
               domain: Optional[Sequence[float]] = None, element_length: Optional[float] = None,
               progress: ProgressLike = None, measured: "str | os.PathLike[str] | None" = None,
               **overrides: Any) -> Stationary:
    """The stationary wave of the scenario's load on the infinite track at ``speeds`` (m/s, by continuation in
    order) on a moving domain ``domain`` = (behind, ahead) m of ``element_length`` m elements (grown where needed;
    by default those of ``frictrack stationary``: 60 m each way, 0.25 m elements);
    linear, tensionless and bilinear soils, ballast friction. On a ``[ground]`` the track's steady wave under
    the scenario's train (or load), a Fourier integral with no mesh: ``domain`` = (behind the last axle, ahead of the
    first) m, 60 m each way by default, ``element_length`` refused, ballast friction (``distributed_friction``, N/m)
    under the composite beam or between the two-beam track's sleepers and embankment, solved with the ground as a
    non-local operator; ``measured`` (a CSV of ``x_m,displacement_mm``,
    upward positive) sets a record beside the wave at one speed, as ``--measured`` does. Overrides and ``progress``
    (the fraction of speeds done) as for :func:`run`; Ctrl-C stops it before its next speed."""
    kind, text = _source(scenario)
    behind, ahead = _domain(domain)
    length = None if element_length is None else _numbers("element_length", element_length, "a length in m", "0.25")[0]
    record = _path("measured", measured, "a CSV file of x_m,displacement_mm")
    with _Reporter(progress, "stationary") as report:
        points, lines, waves, warnings, columns, compared = _native.stationary(
            kind, text, _speeds(speeds), (behind, ahead, length), list(overrides.items()), report, record
        )
    return Stationary(json.loads(points), {float(v): parse_csv(csv, COLUMNS[columns]) for v, csv in waves},
                      list(warnings), lines, None if compared is None else json.loads(compared))


class Study:
    """A study preset's results (``frictrack study NAME``): ``summary`` (its JSON summary), ``table`` (its CSV with
    units), ``headline`` (the two sentences of its report section), ``lines`` (one per curve)."""

    def __init__(self, name: str, summary: Dict[str, Any], table: Table, headline: "list[str]",
                 lines: "list[str]") -> None:
        self.name = name
        self.summary = summary
        self.table = table
        self.headline = headline
        self.lines = lines

    def __repr__(self) -> str:
        return f"<frictrack.Study {self.name}: {' '.join(self.headline)}>"


def study(name: str, scenario: ScenarioLike = None, resolution: str = "coarse", jobs: Optional[int] = None,
          deck_track: Optional[str] = None, **overrides: Any) -> Study:
    """Run the study preset ``name`` (``discrete-speed``, ``hslm``, ``stationary-wave``, ``voided-sleepers``,
    ``receptance``, ``ledsgard`` — its own built-in site —, …) on ``scenario`` (the reference case by default) at
    ``resolution`` ("coarse" or "paper") on ``jobs`` threads.

    ``deck_track`` ("ballasted", 3.5 m/s², or "direct-fastening", 5 m/s²; default the scenario's ``[output]
    deck_track``) sets the EN 1990 deck-acceleration limit the ``hslm`` study checks a span against: each curve of
    ``summary["curves"]`` then has its ``deck_verdict`` ("within", "over", "within the range only") from the refined
    peak ``peak_max_acceleration`` (m/s²) at ``peak_acceleration_speed`` (m/s), and ``acceleration_over_limit``."""
    kind, text = _source(scenario)
    summary, table, headline, lines, columns = _native.study(
        name, kind, text, resolution, _jobs(jobs), deck_track, list(overrides.items())
    )
    return Study(name, json.loads(summary), parse_csv(table, dict(columns)), list(headline), list(lines))


class Receptance:
    """The track's receptance over frequency (``frictrack receptance``): ``table`` one row per frequency
    (frequency Hz, real, imaginary and magnitude of α in m/N, phase in degrees, mobility in m/(s·N)),
    ``resonances`` the peaks of |α| (frequency refined between the grid's, magnitude, prominence), ``summary`` the
    whole JSON (place, kind, rail, loss factors), ``warnings`` (a mesh too coarse, waves back from the ends) and
    ``report`` the text the command line prints (also ``str()``)."""

    def __init__(self, summary: Dict[str, Any], table: Table, report: str, warnings: "list[str]") -> None:
        self.summary = summary
        self.table = table
        self.resonances: "list[Dict[str, Any]]" = summary["resonances"]
        self.report = report
        self.warnings = warnings

    def __str__(self) -> str:
        return self.report


def receptance(scenario: ScenarioLike = None, frequencies: Sequence[float] = (), at: Optional[float] = None,
               excite: Optional[float] = None, jobs: Optional[int] = None,
               out: "str | os.PathLike[str] | None" = None, **overrides: Any) -> Receptance:
    """The receptance α = w(at)/F (m/N) of the scenario's track for a harmonic force at ``excite`` (m; default
    ``at``, the point receptance; ``at`` defaults to mid-track) at each of ``frequencies`` (Hz, > 0, increasing),
    from the same model as a run — Euler–Bernoulli or Timoshenko rail, viscous damping and the loss factors of
    ``[beam]`` and ``[foundation]`` — one complex banded solve per frequency on ``jobs`` threads. A linear
    foundation only. ``out`` (a folder) receives receptance.csv, receptance.json and the figure. ``frequencies`` may
    be one frequency. Overrides of the track only: ``damping_ratio``, ``elements``, ``absorbing_zones`` (as for
    :func:`run`); a load's are refused."""
    frequencies = _numbers("frequencies", frequencies, "a frequency in Hz", "50.0 or range(10, 1001, 5)")
    for name in overrides:
        if name not in _RECEPTANCE_OVERRIDES:
            raise InputError(
                f"invalid {name} = {overrides[name]!r}: does nothing for a receptance, a property of the track alone; "
                f"it takes {', '.join(_RECEPTANCE_OVERRIDES)}"
            )
    kind, text = _source(scenario)
    summary, table, report, warnings = _native.receptance(
        kind, text, frequencies, _place("at", at), _place("excite", excite), _jobs(jobs), list(overrides.items()),
        _path("out", out, "a folder path"),
    )
    for warning in warnings:
        _warnings.warn(warning, stacklevel=2)
    return Receptance(json.loads(summary), parse_csv(table, COLUMNS["receptance"]), report, list(warnings))


class Ground:
    """The scenario's composite beam (or two-beam track) on its ``[ground]`` (``frictrack ground``): ``dispersion`` the soil's fundamental
    Rayleigh mode (frequency Hz, phase_velocity m/s), ``speeds`` the steady deflection over speed (speed m/s,
    max_downward_deflection and max_upward_deflection m), ``stiffness`` k_eq along the load's line (speed m/s,
    wavenumber rad/m, frequency Hz, stiffness_real and stiffness_imaginary N/m²), ``critical_speed``,
    ``winkler_critical_speed`` and ``minimum_phase_velocity`` (m/s; None where undefined, with a warning),
    ``summary`` the whole JSON (every number's unit in ``summary["units"]``), ``warnings`` and ``report`` (the text
    of the command line; also ``str()``)."""

    def __init__(self, summary: Dict[str, Any], report: str, warnings: "list[str]") -> None:
        self.summary = summary
        units = {u["name"]: u["unit"] for u in summary["units"]}

        def pick(rows: "list[Dict[str, Any]]", names: "tuple[str, ...]") -> Table:
            return Table.from_records(rows, {n: units[n] for n in names})

        self.dispersion = pick(summary["dispersion"], ("frequency", "phase_velocity"))
        self.speeds = pick(summary["speeds"], ("speed", "max_downward_deflection", "max_upward_deflection"))
        self.stiffness = pick(
            summary["equivalent_stiffness"],
            ("speed", "wavenumber", "frequency", "stiffness_real", "stiffness_imaginary"),
        )
        self.critical_speed: Optional[float] = summary["critical_speed"]
        self.winkler_critical_speed: float = summary["winkler_critical_speed"]
        self.minimum_phase_velocity: Optional[float] = summary["minimum_phase_velocity"]
        self.report = report
        self.warnings = warnings

    def __str__(self) -> str:
        return self.report


def ground(scenario: ScenarioLike, frequencies: Optional[Sequence[float]] = None, jobs: Optional[int] = None,
           out: "str | os.PathLike[str] | None" = None) -> Ground:
    """The scenario's composite beam (``[beam]``), or its rail on ``[sleepers]`` over an ``[embankment]``, on its
    layered ``[ground]``: the soil's Rayleigh modes at
    ``frequencies`` (Hz, > 0, increasing; default 1 to 50 by 1) and the fundamental's least phase velocity, the static
    strip stiffness and the Winkler control, where the beam's dispersion meets the soil's, and the critical speed on
    the ground (the speed of the largest steady deflection under ``[load] force``), on ``jobs`` threads. ``out`` (a
    folder) receives ground.json, the tables (CSV) and the figures. Warnings as UserWarning."""
    if frequencies is not None:
        frequencies = _numbers("frequencies", frequencies, "a frequency in Hz", "range(1, 51)")
    kind, text = _source(scenario)
    summary, _table, report, warnings = _native.ground(
        kind, text, frequencies, _jobs(jobs), _path("out", out, "a folder path")
    )
    for warning in warnings:
        _warnings.warn(warning, stacklevel=2)
    return Ground(json.loads(summary), report, list(warnings))


def train(name: str) -> Dict[str, Any]:
    """The train ``name`` (a catalogue name or a CSV file of offset,force lines): its summary (name, axles, patches,
    length m, total_force N) and ``axles``, a :class:`Table` of offset (m behind the first axle) and force (N)."""
    summary, axles = _native.train(name)
    result = json.loads(summary)
    result["axles_table"] = Table.from_records(
        [{"offset": o, "force": f} for o, f in axles], {"offset": "m", "force": "N"}
    )
    return result


def track_profile(spectrum: str = "german-low", length: float = 1000.0, spacing: float = 0.25, seed: int = 1,
                  band: Optional[Sequence[float]] = None) -> "tuple[Table, Table, Dict[str, Any]]":
    """A random rail (``frictrack track-profile``): its sample r(x) every ``spacing`` m over ``length`` m, its
    periodogram against the target spectrum, and the summary (standard deviations in m) — for the spectrum, band
    (shortest, longest wavelength in m) and seed given."""
    profile, psd, summary = _native.track_profile(
        spectrum, float(length), float(spacing), int(seed), None if band is None else tuple(float(b) for b in band)
    )
    return parse_csv(profile, None), parse_csv(psd, None), json.loads(summary)


def trains() -> "list[str]":
    """The train catalogue's names (``frictrack trains``): ``single`` and HSLM-A1 … A10."""
    return list(_native.trains())


def override_names() -> "list[str]":
    """The keyword overrides :func:`run` takes."""
    return list(_native.override_names())


def override_table() -> "list[tuple[str, str, str, str]]":
    """The keyword overrides with what they take and do: (keyword, type, unit or "", what it sets) each — the
    command line's table of flags (``frictrack run --help`` prints the same sentences)."""
    return [tuple(row) for row in _native.override_table()]
