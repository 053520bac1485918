"""The package's arguments checked before they reach the library: each wrong one an :class:`InputError` naming the
argument, its value and what it takes (never a bare ``TypeError``)."""

from __future__ import annotations

import os
from typing import Any, Optional, Sequence, Union

from . import _native

InputError = _native.InputError


def _numbers(name: str, values: Any, what: str, example: str) -> "list[float]":
    """``values`` as a list of floats: one number or any iterable of numbers; anything else (text, None, a bool) is an
    InputError naming the argument ``name``, what it takes (``what``) and an ``example``."""
    if isinstance(values, (int, float)) and not isinstance(values, bool):
        return [float(values)]
    try:
        if values is None or isinstance(values, (str, bytes, bool)):
            raise TypeError
        return [float(v) for v in values]
    except (TypeError, ValueError):
        raise InputError(f"invalid {name} = {values!r}: must be {what} or a sequence of them, e.g. {example}") from None


def _speeds(speeds: "Union[float, str, Sequence[Union[float, str]]]") -> "list[float]":
    """Speeds (m/s) as a list: one speed or any iterable of them, each a number (m/s) or text with its unit
    (``"144km/h"``, ``"40m/s"``) as ``run(speed=...)`` takes it; anything else is an InputError naming it."""
    if isinstance(speeds, str):
        speeds = [speeds]
    if isinstance(speeds, (list, tuple)) and any(isinstance(v, str) for v in speeds):
        return [_native.parse_speed("speeds", v) if isinstance(v, str)
                else _numbers("speeds", v, "a speed in m/s", "200.0")[0] for v in speeds]
    return _numbers("speeds", speeds, "a speed in m/s or text with its unit", '200.0, "144km/h" or [100.0, 200.0]')


def _place(name: str, value: Any) -> Optional[float]:
    """A position along the track (m) or None; anything else is an InputError naming the argument."""
    if value is None:
        return None
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value)
    raise InputError(f"invalid {name} = {value!r}: must be a position along the track in m (a number), or None")


def _jobs(jobs: Optional[int]) -> int:
    """Worker threads: None or 0 for every core, else a whole number ≥ 1; anything else is an InputError."""
    if jobs is None:
        return 0
    if isinstance(jobs, int) and not isinstance(jobs, bool) and jobs >= 0:
        return jobs
    raise InputError(f"invalid jobs = {jobs!r}: must be a whole number ≥ 1 of threads, or 0 or None for every core")


def _path(name: str, value: Any, what: str = "a path") -> Optional[str]:
    """A file or folder path (str or os.PathLike) as text, or None; anything else an InputError naming ``name``."""
    if value is None:
        return None
    if isinstance(value, (str, os.PathLike)) and not isinstance(value, bytes):
        return os.fspath(value)
    raise InputError(f"invalid {name} = {value!r}: must be {what} (a str or os.PathLike)")


def _domain(domain: Any) -> "tuple[Optional[float], Optional[float]]":
    """The moving window (behind, ahead) m, or (None, None) for the default: two numbers ≥ 0; anything else an
    InputError naming ``domain``."""
    if domain is None:
        return None, None
    bad = InputError(f"invalid domain = {domain!r}: must be two numbers (behind, ahead) in m, e.g. (60.0, 60.0)")
    if isinstance(domain, (str, bytes)):
        raise bad
    try:
        values = [float(x) for x in domain]
    except (TypeError, ValueError):
        raise bad from None
    if len(values) != 2 or any(isinstance(x, bool) for x in domain):
        raise bad
    return values[0], values[1]
