"""A result folder as one self-contained HTML file: ``frictrack report DIR [--out FILE]`` from Python."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Optional, Union

from . import _native
from ._args import _path

PathLike = Union[str, "os.PathLike[str]"]


def report(folder: PathLike, out: Optional[PathLike] = None) -> Path:
    """Write the report of ``folder`` — written by ``frictrack run --out``, ``frictrack study --out``, ``frictrack
    reproduce --out`` or ``frictrack.run(out=...)`` — as one self-contained HTML file: the figures inline as SVG, the
    tables and verdicts, every warning, the scenario as it ran, the command, frictrack's version and commit, the
    date, a table of contents and a print stylesheet. ``out`` defaults to ``folder/report.html``; returns the path
    written. A folder of neither kind raises :class:`InputError` naming it."""
    written = _native.write_report(_result_folder(folder), _path("out", out, "a file path for the HTML report"))
    return Path(written)


def report_html(folder: PathLike) -> str:
    """The report of ``folder`` (as :func:`report` writes it) as HTML text."""
    return _native.report_html(_result_folder(folder))


def _result_folder(folder: PathLike) -> str:
    """The result folder a report is made of, as text; None or anything but a path is an InputError naming it."""
    source = _path("folder", folder, "a result folder")
    if source is None:
        raise _native.InputError("invalid folder = None: must be a result folder (written by run --out, study --out, "
                                 "reproduce --out or frictrack.run(out=...))")
    return source
