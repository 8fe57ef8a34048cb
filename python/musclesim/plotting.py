"""Figures drawn by gnuplot, as `musclesim plot` draws them, from results in memory.

plot() picks the figure from the data's type and hands its columns to the library's script
builders as the table the CLI would read from their CSV: numbers as float64 (the CLI's CSV
prints 17 significant digits, which read back to the same double), text columns as text.
"""
from __future__ import annotations

import operator as _operator
import os as _os
from typing import Any, Iterable, List, Union

import numpy as _np
import numpy.typing as _npt

from . import _musclesim
from ._errors import InputError as _InputError
from ._types import PathLike as _PathLike

# A column as _plot_columns takes it.
_Column = Union[_npt.NDArray[_np.float64], List[str]]

__all__ = ["plot"]


def _column(name: str, values: _npt.ArrayLike) -> _Column:
    """One column as _plot_columns takes it: a 1-D float64 array, or a list of str."""
    array = _np.asarray(values)
    if array.ndim != 1:
        raise _InputError("data: column %s must be a 1-D array, not one of shape %s"
                          % (name, tuple(array.shape)))
    kind = array.dtype.kind
    if kind in "fb":
        return _np.ascontiguousarray(array, dtype=_np.float64)
    if kind in "iu":  # counts (index, steps, series) exactly as the CLI prints them
        return [str(v) for v in array.tolist()]
    if kind == "U":
        texts: list[str] = array.tolist()
        return texts
    if kind == "S":
        return [v.decode("utf-8") for v in array.tolist()]
    if kind == "O":  # pandas' text columns, or Python numbers
        items: list[Any] = array.tolist()
        if all(isinstance(v, str) for v in items):
            return items
        try:
            return _np.asarray(items, dtype=_np.float64)
        except (TypeError, ValueError):
            return [str(v) for v in items]
    raise _InputError("data: column %s has dtype %s: a column must hold numbers or text"
                      % (name, array.dtype))


def _columns(data: object) -> tuple[list[str], list[_Column]] | None:
    """(names, columns) of a table-like `data`, or None for another type."""
    pairs: Iterable[tuple[Any, Any]]
    if isinstance(data, _musclesim.Result):
        pairs = data.columns.items()
    elif isinstance(data, _musclesim.SeriesIdentification):
        pairs = data.residuals.items()
    elif isinstance(data, _np.ndarray) and data.dtype.names:
        pairs = ((name, data[name]) for name in data.dtype.names)
    elif hasattr(data, "keys") and hasattr(data, "__getitem__"):  # dict, DataFrame, mapping
        table: Any = data
        pairs = ((key, table[key]) for key in table.keys())
    else:
        return None
    names: list[str] = []
    columns: list[_Column] = []
    for key, values in pairs:
        names.append(str(key))
        columns.append(_column(str(key), values))
    return names, columns


def _pixels(size: tuple[int, int]) -> tuple[int, int]:
    try:
        width, height = size
        width, height = _operator.index(width), _operator.index(height)
    except (TypeError, ValueError):
        raise TypeError("size must be (width, height) in pixels, two integers, not %r"
                        % (size,)) from None
    if not all(-2**31 < v < 2**31 for v in (width, height)):  # the library's int
        raise _InputError("size %dx%d: width and height must be 100 to 10000 px"
                          % (width, height))
    return width, height


def plot(data: object, output: _PathLike, title: str | None = None,
         size: tuple[int, int] = (1000, 750), x: str | None = None, y: str | None = None,
         color: str | None = None, script: _PathLike | None = None, *,
         frames: Iterable[float] | None = None, frame_count: int | None = None,
         scenario: Any = None) -> str:
    """Draws the figure `musclesim plot` draws of `data`, with gnuplot, to `output`.

    No CSV file and no subprocess of the CLI: the data's columns go to the library's script
    builders as the table the CLI reads from its CSV, so the figure (and its script) is the
    CLI's for the same data. `data` is one of:

      a Result (Scenario.run(), run_many): its trajectory, as `musclesim plot RUN.csv` draws
          it: length [m], shortening velocity [m/s] (> 0 when shortening), activation [-]
          (excitation dashed) and tensions with the load [N] against time [s], concentric,
          eccentric and isometric intervals shaded; a network's: node positions, element
          lengths, tensions, activations and, per controller, measured against reference and
          the errors.
      a musclesim.Model: its curves, as `musclesim plot --curves`: passive, active (u = 1,
          v = 0) and total tension [N] against length [m], L_opt shaded and each Gaussian
          thin, and g(v) against shortening velocity [m/s].
      a sweep summary (musclesim.sweep's structured array), with x: the metric y (default
          the first) against the swept path x, a line per value of the swept path `color`;
          without color and with two swept paths, a heat map. Failed points and NaN metrics
          are left out. As `musclesim plot SWEEP.csv --x X --y Y --color C`.
      a SeriesIdentification (identify_series): its residuals, as `musclesim plot` draws
          `identify --residuals`: a panel per measured series and output, measured as points
          and the model as a line, over the standardised residuals against time [s].
      a dict of 1-D arrays keyed by the CSV's column names, a pandas DataFrame, or a NumPy
          structured array: told apart as the CLI tells CSV files apart: with x a sweep
          summary; else a residual table (columns measured, model, standardised), a
          network's trajectory (a <node>.position column) or a trajectory.

    output: the figure's path, .png (pngcairo) or .svg; replaced only when gnuplot succeeds.
    title: the figure's title (None or '': the CLI's default from the input: 'trajectory',
        'residuals', 'model curves', 'Y against X'). UTF-8 text without control characters,
        drawn as written (no gnuplot markup).
    size: (width, height) in pixels, each 100..10000.
    x, y, color: a sweep summary's swept path, metric and second swept path (y and color
        only with x), as the CLI's --x, --y, --color.
    script: a path where the gnuplot script is also written (the CLI's --script), to restyle
        the figure by hand.
    frames, frame_count: a run in the plane or in space drawn as its shape at these times
        [s] (or at this many evenly spaced ones, 1..36), as the CLI's --frames and
        --frame-count; scenario: the Scenario it ran, whose elements are then drawn along
        their paths over their via points (the CLI's --scenario). Without them such a run is
        drawn as its nodes' paths beside the elements' lengths, tensions and activations.

    Returns `output` as a str. The script is built and gnuplot run with the GIL released.
    Raises musclesim.InputError as the CLI exits 2, naming what is wrong: an extension other
    than .png/.svg, a size out of range, a title with a control character, y or color
    without x, a missing column, columns of unequal length, an x that is not a swept path, or
    a plotted cell that is not a finite number, named as SOURCE:ROW (e.g. "trajectory:12:
    column length = 'nan'", ROW the 0-based row index where the CLI names its CSV's line).
    TypeError for a `data` of another type. RuntimeError, the library's, when gnuplot (Debian:
    gnuplot-nox) is missing or fails.
    """
    output = _os.fspath(output)
    script = _os.fspath(script) if script is not None else None
    width, height = _pixels(size)
    title = "" if title is None else str(title)
    if isinstance(data, _musclesim.Model):
        if x is not None or y is not None or color is not None:
            raise _InputError("x, y and color go with a sweep summary, not with a Model's "
                              "curves")
        _musclesim._plot_model(data.params, output, title, width, height, script)
        return output
    table = _columns(data)
    if table is None:
        raise TypeError("plot: data must be a Result, a Model, a SeriesIdentification, a sweep "
                        "summary (a NumPy structured array) or a dict or DataFrame of 1-D "
                        "arrays keyed by column name, not %s" % type(data).__name__)
    names, columns = table
    if frames is not None or frame_count is not None or scenario is not None:
        if x is not None or y is not None or color is not None:
            raise _InputError("frames, frame_count and scenario go with a run, not with a "
                              "sweep summary's x, y and color")
        if (frames is None) == (frame_count is None):
            raise _InputError("give frames (the times) or frame_count (how many), one of them, "
                              "as the CLI's --frames or --frame-count")
        times = [] if frames is None else [float(t) for t in frames]
        if frames is not None and not times:
            raise _InputError("frames: give at least one time [s]")
        count = 0 if frame_count is None else _operator.index(frame_count)
        if not -2**31 < count < 2**31:
            raise _InputError("frame_count %d: must be 1 to 36" % count)
        _musclesim._plot_frames(names, columns, output, title, width, height, times, count,
                                scenario, script)
        return output
    _musclesim._plot_columns(names, columns, output, title, width, height, x, y, color, script)
    return output
