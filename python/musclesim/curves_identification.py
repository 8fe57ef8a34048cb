"""Identification from measured curves: `musclesim identify DATA.yaml` on arrays.

The same checks, fits, `model:` block and report as the command
(docs/guide/identification.md), with the curves given as arrays rather than as CSV files. SI
units: lengths in m, shortening velocities in m/s (> 0 when the actuator shortens), tensions
in N.
"""
from __future__ import annotations

import numbers as _numbers
from typing import Any, Mapping, NoReturn, Tuple, Union

import numpy as _np
import numpy.typing as _npt

from ._errors import InputError
from ._musclesim import Model
from ._musclesim import _identify_curves
from ._types import ColumnTable as _ColumnTable

__all__ = ["identify_curves", "CurvesIdentification"]

# The arguments an error on them is keyed by.
_ARGUMENTS = ("passive", "active", "velocity", "active_count", "f_iso")

# A measured curve: a pair (x, tension) of 1-d array-likes, or a dict or DataFrame of columns.
_Curve = Union[Tuple[_npt.ArrayLike, _npt.ArrayLike], _ColumnTable]
# A curve as _identify_curves takes it.
_Columns = Tuple[_npt.NDArray[_np.float64], _npt.NDArray[_np.float64]]

# The columns a curve's CSV holds, which a dict or DataFrame names alike.
_COLUMNS = {
    "passive": ("length", "tension"),
    "active": ("length", "tension"),
    "velocity": ("shortening_velocity", "tension"),
}


def _columns(argument: str, curve: _Curve | None) -> _Columns | None:
    """(x, tension) of one curve as float64 arrays, from a pair or a dict / DataFrame."""
    if curve is None:
        return None
    x_name, y_name = _COLUMNS[argument]
    given: Any = curve  # whatever it is, checked here
    if hasattr(given, "keys"):  # a dict or a pandas DataFrame: the CSV's column names
        missing = [name for name in (x_name, y_name) if name not in given.keys()]
        if missing:
            raise InputError(f"{argument}: no column {', '.join(missing)}: a dict or DataFrame "
                             f"needs columns {x_name},{y_name}")
        x, tension = given[x_name], given[y_name]
    else:
        try:
            x, tension = given
        except (TypeError, ValueError):
            raise InputError(f"{argument}: give a pair ({x_name}, tension) of 1-d arrays, or a "
                             f"dict or DataFrame with columns {x_name},{y_name}") from None
    return (_as_column(argument, x_name, x), _as_column(argument, y_name, tension))


def _as_column(argument: str, name: str,
               values: _npt.ArrayLike) -> _npt.NDArray[_np.float64]:
    try:
        array = _np.asarray(values, dtype=_np.float64)
    except (TypeError, ValueError) as error:
        raise InputError(
            f"{argument}: {name} must be a 1-d sequence of numbers ({error})") from None
    if array.ndim != 1:
        raise InputError(f"{argument}: {name} must be a 1-d sequence of numbers; "
                         f"got shape {array.shape}")
    return array


class CurvesIdentification:
    """What identify_curves found. Read-only attributes:

    model_yaml: str, the complete `model:` block as `musclesim identify` prints it (header
        comments, each parameter with its standard error and each curve's RMSE in comments);
        write it to a file to use it in a scenario.
    model: musclesim.Model, that block read back (parts without data are the neutral
        stand-ins the block says), so result.model.tension(x, v, u) works at once.
    params: dict, model.params: the block's keys and values.
    passive, active, velocity: dict of plain Python values per curve fitted, or None when the
        curve was not given. An estimate is a tuple (value, standard_error) in the
        parameter's unit; the standard error comes from the Jacobian at the optimum and is
        nan when it cannot be estimated. Keys as the YAML's:
      passive: k_p [N], alpha [1/m], slack_length [m]; rmse [N]; points [-];
        slack_length_interval {low, high [m], low_bounded, high_bounded (False: the data do
        not bound that side; the end is then how far the search went), level [-] (0.95),
        wide (True: the data place the slack length only coarsely)}, the 95% profile-
        likelihood interval; k_p_over_interval [N] and alpha_over_interval [1/m], (low,
        high) of the best k_p and alpha across that interval.
      active: f_iso [N] (the fitted curve's maximum); optimal_range (l1, l2) [m] (where the
        curve is within 2% of its maximum); amplitudes [-], widths [1/m^2] (the Gaussians'
        precisions b_k) and centers [m], lists of estimates, one per Gaussian of f_L;
        rmse [N]; points [-].
      velocity: f_iso [N] (standard error 0 when held by f_iso=), v_max [m/s], n [-] (the
        exponent 1/n of the best fit), rmse [N], points [-]; candidates: one dict per n in
        1..10 {n, f_iso, v_max, rmse, valid}; eccentric: None without points v < 0, else
        {points, identified, limit_identified, in_model (the branch is in `model`: it is
        left out when its estimates break the model's rules), why_not, why_no_limit (the
        reason, or None), v_max [m/s], n [-], limit [-] (the bounded branch's limit L on
        T / f_iso), rmse [N] (None where not identified)}.
    report: str, the Markdown of `musclesim identify --report` (each fit against a natural
        cubic spline and polynomials of degree 3 and 4), or None unless report=True.
    """

    __slots__ = ("model_yaml", "model", "params", "passive", "active", "velocity", "report")
    model_yaml: str
    model: Model
    params: dict[str, Any]
    passive: dict[str, Any] | None
    active: dict[str, Any] | None
    velocity: dict[str, Any] | None
    report: str | None

    def __init__(self, found: Mapping[str, Any]) -> None:
        values = dict(found)
        object.__setattr__(self, "model", Model(values.pop("params")))
        object.__setattr__(self, "params", self.model.params)
        for name in ("model_yaml", "passive", "active", "velocity", "report"):
            object.__setattr__(self, name, values[name])

    def __setattr__(self, name: str, value: object) -> NoReturn:
        raise AttributeError("CurvesIdentification is read-only")

    def __repr__(self) -> str:
        fitted = [name for name in ("passive", "active", "velocity") if getattr(self, name)]
        return f"<musclesim.CurvesIdentification of {', '.join(fitted)}>"


def identify_curves(passive: _Curve | None = None, active: _Curve | None = None,
                    velocity: _Curve | None = None, active_count: int = 3,
                    nonnegative: bool = False, f_iso: float | None = None, report: bool = False,
                    *, source: str = "Python arrays") -> CurvesIdentification:
    """The model's parameters fitted to measured curves, as `musclesim identify DATA.yaml`.

    Each curve is a pair (x, tension) of 1-d array-likes of equal length, or a dict or pandas
    DataFrame with the columns of the command's CSV:
      passive:  length [m], tension [N] -> slack_length, k_p, alpha (eq. 1)
      active:   length [m], tension [N] -> active_count Gaussians of f_L, f_iso its maximum
      velocity: shortening_velocity [m/s] (> 0 shortening), tension [N] -> f_iso, v_max, n;
                with points v < 0 also the eccentric branch's v_max, n and limit
    At least one curve is required. active_count: Gaussians to fit, 1 to 12; nonnegative:
    keep every amplitude >= 0; f_iso [N] (> 0 and <= 1e9): held fixed in the velocity fit.
    report=True also makes the Markdown report of --report. source: the header comment's
    "identified by musclesim identify from <source>" (one line).

    The data rules are the command's: at least 4 passive points, 3 active_count + 1 active
    ones, 3 velocity ones (2 with f_iso), finite values, x strictly increasing (no
    duplicates), tension not zero everywhere. A curve that breaks one raises InputError
    naming the argument and the row (1-based), e.g. "active: row 4: length = 0.2 is not
    greater than the row before (0.3): rows must be sorted by length, without duplicates";
    data a fit cannot use raise InputError too ("velocity data: ..."). The fits run with
    the GIL released.

    Returns a CurvesIdentification: model_yaml (the command's `model:` block), model (a
    musclesim.Model of it), passive / active / velocity (estimates with standard errors,
    keys as the YAML's) and report.
    """
    if isinstance(active_count, bool) or not isinstance(active_count, _numbers.Integral):
        raise TypeError("active_count must be an int (Gaussians to fit, 1 to 12), not %r"
                        % (active_count,))
    if f_iso is not None and (isinstance(f_iso, bool) or not isinstance(f_iso, _numbers.Real)):
        raise TypeError("f_iso must be a number [N] or None, not %r" % (f_iso,))
    try:
        found = _identify_curves(_columns("passive", passive), _columns("active", active),
                                 _columns("velocity", velocity), int(active_count),
                                 bool(nonnegative), None if f_iso is None else float(f_iso),
                                 bool(report), str(source))
    except InputError as error:
        # messages on the data start with the argument ("active: too few points ..."), on
        # the settings with it as "active_count = 13: ...": the argument is the key
        if getattr(error, "key", None) is None:
            head = str(error).split(":", 1)[0].split(" = ", 1)[0]
            if head in _ARGUMENTS:
                error.key = head
        raise
    return CurvesIdentification(found)
