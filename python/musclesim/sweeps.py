"""Sweeps from Python: musclesim.sweep runs a sweep file or dict, its summary as a table."""
from __future__ import annotations

import csv
import os
from typing import Any

import numpy as np
import numpy.typing as npt

from ._musclesim import _sweep
from ._types import PathLike
from .tables import structured

# summary columns that are counts rather than measurements
_INTEGER_COLUMNS = ("index", "steps", "rhs_evals")
# summary columns that are text
_TEXT_COLUMNS = ("status", "message")


def _column_array(name: str, texts: list[str]) -> npt.NDArray[Any]:
    if name in _TEXT_COLUMNS:
        return np.array(texts, dtype=object)
    if name in _INTEGER_COLUMNS:
        return np.array([int(t) for t in texts], dtype=np.int64)
    try:
        # an empty field (a metric of a failed or invalid point) is NaN
        return np.array([float(t) if t != "" else np.nan for t in texts], dtype=np.float64)
    except ValueError:  # an axis whose values are not numbers
        return np.array(texts, dtype=object)


def _read_summary(path: str) -> tuple[list[str], list[npt.NDArray[Any]]]:
    """The summary CSV the sweep wrote where it was asked to, as columns."""
    with open(path, newline="") as file:
        rows = list(csv.reader(file))
    header, body = rows[0], rows[1:]
    return header, [_column_array(column, [row[c] for row in body])
                    for c, column in enumerate(header)]


def sweep(spec: PathLike | dict[str, Any], threads: int = 0, output: PathLike | None = None,
          resume: bool = False, name: str = "<dict>") -> npt.NDArray[np.void]:
    """Runs a sweep (docs/guide/sweeps.md) with the GIL released and returns its summary.

    `spec` is a sweep file's path, or a dict with a sweep file's keys (base, mode, parameters,
    metrics, metric_options, trajectories, ...) read by the same reader as a document in
    memory, so the same rules and messages apply (InputError naming `name` for the file); its
    `base` is a scenario file's path (relative to the working directory) or a Scenario, whose
    numbers the axes set through parameter handles (no file is written). `threads`: as
    `--jobs` (0: every core). `output`: where the summary CSV (and any per-run trajectories
    beside it) is written, as `-o`; None: the summary is kept in memory, no file written (the
    sweep file's own `output` is not used). `resume`: as `--resume`, keep the rows of an
    interrupted sweep's output.partial and run the rest (it needs `output`). Ctrl-C stops the
    sweep (KeyboardInterrupt) after the running points, their rows kept in output.partial when
    `output` is given. A sweep keeping trajectories (`trajectories: all` or `failed`) needs
    `output`: they are written beside it.

    Returns one NumPy structured array, a record per point, with the summary CSV's columns as
    fields in its order: index, one per swept path, status, the metrics (SI units as in the
    CSV; NaN where a point has none), steps, rhs_evals, wall_seconds [s], message. Counts are
    int64, status and message str, the rest float64 (an axis of non-numeric values: str).
    `summary["status"]` is a column, `summary.dtype.names` the columns,
    `pandas.DataFrame(summary)` a DataFrame."""
    if isinstance(threads, bool) or not isinstance(threads, int):
        raise TypeError("threads must be an int (0: every core), not %r" % (threads,))
    if resume and output is None:
        raise ValueError("resume=True continues the summary at output: give output=PATH, "
                         "the one the interrupted sweep wrote to")
    if not isinstance(spec, (str, os.PathLike, dict)):
        raise TypeError("sweep expects a path or a dict, not %s" % type(spec).__name__)
    display = os.fspath(spec) if isinstance(spec, (str, os.PathLike)) else name
    in_memory = _sweep(spec, threads, output, bool(resume), display)
    header, columns = in_memory if output is None else _read_summary(os.fspath(output))
    return structured(list(header), list(columns))
