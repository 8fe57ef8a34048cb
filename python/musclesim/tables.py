"""Results as one NumPy structured array (pandas.DataFrame(array) makes a DataFrame of it)."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Iterable, Sequence

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from ._musclesim import Result

__all__ = ["table"]


def structured(names: Sequence[str],
               columns: Sequence[npt.NDArray[Any]]) -> npt.NDArray[np.void]:
    """A structured array of len(columns[0]) records from 1-D arrays named `names`; a str
    column gets the width of its longest value."""
    fields: list[tuple[str, Any]] = []
    for name, values in zip(names, columns):
        values = np.asarray(values)
        if values.dtype.kind in "OU":
            width = max([len(str(v)) for v in values], default=1)
            fields.append((name, "U%d" % max(width, 1)))
        else:
            fields.append((name, values.dtype))
    rows = len(columns[0]) if columns else 0
    array = np.empty(rows, dtype=fields)
    for name, values in zip(names, columns):
        array[name] = values
    return array


def table(results: Iterable[Result]) -> npt.NDArray[np.void]:
    """The trajectories of run_many's (or Scenario.run's) Results stacked into one NumPy
    structured array, one record per row of each run: the field `job` (int64, the result's
    index in `results`), then every column of the runs (the first run's order, then any new
    ones), float64 or str like Result.columns. A run without a column has NaN there (float64)
    or '' (str). `pandas.DataFrame(musclesim.table(results))` is the same as a DataFrame, and
    `array[array["job"] == k]` one run's rows. SI units as in the CSV (s, m, m/s, N)."""
    from . import Result  # the extension's type, imported late: this module loads first
    if isinstance(results, (str, bytes, dict)) or not hasattr(results, "__iter__"):
        raise TypeError("table(results): results must be an iterable of musclesim.Result, "
                        "not %s" % type(results).__name__)
    results = list(results)
    names: list[str] = []
    text: dict[str, bool] = {}
    for k, result in enumerate(results):
        if not isinstance(result, Result):
            raise TypeError("table(results): results[%d] is %s, not a musclesim.Result "
                            "(from Scenario.run or run_many)" % (k, type(result).__name__))
        for name, values in result.columns.items():
            if name not in text:
                names.append(name)
                text[name] = np.asarray(values).dtype.kind in "OU"
    job = np.concatenate([np.full(len(r), k, dtype=np.int64) for k, r in enumerate(results)]
                         or [np.empty(0, dtype=np.int64)])
    columns: list[npt.NDArray[Any]] = []
    for name in names:
        parts: list[npt.NDArray[Any]] = []
        for result in results:
            if name in result.columns:
                parts.append(np.asarray(result.columns[name]))
            elif text[name]:
                parts.append(np.full(len(result), "", dtype="U1"))
            else:
                parts.append(np.full(len(result), np.nan))
        columns.append(np.concatenate(parts))
    return structured(["job"] + names, [job] + columns)
