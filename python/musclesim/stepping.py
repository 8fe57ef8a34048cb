"""Sweep files from Python: musclesim.sweep runs one and returns its summary as a table."""
import csv
import os
import tempfile

import numpy as np

from ._musclesim import _run_sweep
from .tables import structured

# summary columns that are counts rather than measurements
_INTEGER_COLUMNS = ("index", "steps", "rhs_evals")
# summary columns that are text
_TEXT_COLUMNS = ("status", "message")


def _column_array(name, texts):
    if name in _TEXT_COLUMNS:
        return np.array(texts, dtype=object)
    if name in _INTEGER_COLUMNS:
        return np.array([int(t) for t in texts], dtype=np.int64)
    try:
        # an empty field (a metric of a failed or invalid point) is NaN
        return np.array([float(t) if t != "" else np.nan for t in texts], dtype=np.float64)
    except ValueError:  # an axis whose values are not numbers
        return np.array(texts, dtype=object)


def sweep(path, threads=0):
    """Runs the sweep file `path` (as `musclesim sweep PATH --jobs threads`; threads 0: every
    core) with the GIL released, and returns its summary as one NumPy structured array, a
    record per point, with the summary CSV's columns as fields in its order: index, one per
    swept path, status, the metrics (SI units as in the CSV; NaN where a point has none),
    steps, rhs_evals, wall_seconds [s], message. Counts are int64, status and message str,
    the rest float64 (an axis of non-numeric values: str). `summary["status"]` is a column,
    `summary.dtype.names` the columns, `pandas.DataFrame(summary)` a DataFrame. The sweep
    file's own `output` is not written."""
    with tempfile.TemporaryDirectory(prefix="musclesim_sweep_") as directory:
        output = os.path.join(directory, "summary.csv")
        _run_sweep(os.fspath(path), output, threads)
        with open(output, newline="") as file:
            rows = list(csv.reader(file))
    header, body = rows[0], rows[1:]
    return structured(header, [_column_array(name, [row[c] for row in body])
                               for c, name in enumerate(header)])
