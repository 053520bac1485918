"""A run's tables as NumPy structured arrays, read from the CSV text the library writes (so a table holds exactly
the numbers of ``histories.csv``, ``snapshots.csv`` or ``wheels.csv``), with each column's unit."""

from __future__ import annotations

import csv
from typing import Any, Dict, Iterable, Mapping, Optional

import numpy as np


class Table:
    """A table: ``data`` a NumPy structured array (one field per column, float64), ``units`` the unit of each column
    (SI). ``table["deflection"]`` is a column; ``to_pandas()`` a DataFrame with the units in ``attrs["units"]``."""

    def __init__(self, data: np.ndarray, units: Mapping[str, str]) -> None:
        self.data = data
        self.units = dict(units)

    @classmethod
    def from_records(cls, records: Iterable[Mapping[str, Any]], units: Mapping[str, str]) -> "Table":
        """A table of `records` (dicts) with the columns of `units` (a missing value is NaN)."""
        names = list(units)
        rows = [tuple(np.nan if r.get(n) is None else float(r[n]) for n in names) for r in records]
        data = np.array(rows, dtype=[(n, "f8") for n in names])
        return cls(data, units)

    @property
    def columns(self) -> "list[str]":
        return list(self.data.dtype.names or ())

    def __getitem__(self, column: str) -> np.ndarray:
        return self.data[column]

    def __len__(self) -> int:
        return len(self.data)

    def to_pandas(self) -> Any:
        """The table as a pandas DataFrame (pandas must be installed), units in ``attrs["units"]``."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_pandas() needs pandas: pip install pandas") from e
        frame = pd.DataFrame({name: self.data[name] for name in self.columns})
        frame.attrs["units"] = dict(self.units)
        return frame

    def __repr__(self) -> str:
        parts = ", ".join(f"{c} ({self.units.get(c, '')})" for c in self.columns)
        return f"<frictrack.Table {len(self)} rows: {parts}>"


def _number(cell: str) -> float:
    return float(cell) if cell.strip() else np.nan


def parse_csv(text: str, units: Optional[Mapping[str, str]]) -> Table:
    """A table from CSV text with a header line: a column of numbers as float64 (an empty cell, a failed run's, is
    NaN), any other column as text (a study's `model`, `status`…); `#` lines are comments. Numbers read back to the
    very floats the library wrote."""
    lines = [line for line in text.splitlines() if line and not line.startswith("#")]
    if not lines:
        return Table(np.empty(0, dtype=[]), {})
    names = lines[0].split(",")
    rows = list(csv.reader(lines[1:]))
    columns = []
    for k, name in enumerate(names):
        cells = [row[k] if k < len(row) else "" for row in rows]
        try:
            columns.append((name, np.array([_number(c) for c in cells], dtype=np.float64)))
        except ValueError:
            columns.append((name, np.array(cells, dtype=str)))
    dtype = [(name, values.dtype if values.dtype.kind == "U" else "f8") for name, values in columns]
    data = np.empty(len(rows), dtype=dtype)
    for name, values in columns:
        data[name] = values
    column_units: Dict[str, str] = {n: (units or {}).get(n, "") for n in names}
    return Table(data, column_units)
