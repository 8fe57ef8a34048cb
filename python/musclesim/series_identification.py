"""Identification of a scenario's parameters from measured time series, in memory.

What `musclesim identify DATA.yaml` does for a data file with a `scenario:` key
(docs/guide/identification.md, "From time series"), with the data file's parts given as Python
values: the arguments are read by the data file's own reader as a document in memory, so the
same rules and messages apply (key paths such as "parameters[0].bounds", the place
"identify_series").
"""
from __future__ import annotations

import warnings as _warnings
from typing import Any, Iterable, Mapping

from . import _musclesim
from ._types import ColumnTable as _ColumnTable

__all__ = ["identify_series"]

# What messages call the data file the arguments are written as.
_SPEC_NAME = "identify_series"


def _series_entry(index: int,
                  given: _ColumnTable) -> tuple[dict[str, Any], list[tuple[str, Any]]]:
    """The data file's entry of one series (its noise levels) and its (column, values) pairs."""
    if not hasattr(given, "keys") or isinstance(given, (str, bytes)):
        raise TypeError("series[%d] must be a dict (or a pandas DataFrame) of 1-D arrays keyed "
                        "by column name, with 't' among them, not %s"
                        % (index, type(given).__name__))
    entry: dict[str, Any] = {}
    columns: list[tuple[str, Any]] = []
    for key in given.keys():
        if key == "noise":
            entry["noise"] = given[key]
        else:
            columns.append((str(key), given[key]))
    return entry, columns


def identify_series(scenario: _musclesim.Scenario, series: Iterable[_ColumnTable],
                    parameters: Iterable[str | Mapping[str, Any]], design: bool = False,
                    max_evaluations: int = 200) -> _musclesim.SeriesIdentification:
    """Estimates scenario parameters from measured time series, or checks the experiment.

    As `musclesim identify DATA.yaml [--design]` for a data file with a `scenario:` key, with
    no data file, CSV file or subprocess:

    scenario: a musclesim.Scenario (load_scenario or scenario_from_dict) holding the
        experiment's known inputs; its set() overrides act as the CLI's --set.
    series: a list of measured series, each a dict of 1-D arrays keyed by the trajectory
        CSV's column names ('t' [s], strictly increasing, required; 'length' [m],
        'tension_total' [N], 'NODE.position' [m], ...; a pandas DataFrame too, and
        {**frame, "noise": {...}} with noise levels), plus optionally "noise": {column: SD},
        each column's noise standard deviation in its unit. Give noise levels for every
        column or for none (then every series must measure one and the same column, and the
        standard errors come from s^2 = RSS / (N - P)). With design=True a series may be just
        {"noise": {column: SD}} (its times the scenario's output grid) or {"t": times,
        "noise": {...}}; every column needs a noise level, and measured values are not used.
    parameters: a list of dotted key paths ('model.f_iso'), or of dicts {"path": P,
        "start": V, "bounds": [lower, upper]} as the data file's entries (start: optional,
        the scenario's value; bounds: optional), in the parameters' units.
    design: False, fit (bounded Levenberg-Marquardt on the exact Jacobian of forward
        sensitivities); True, no fit: Cramer-Rao standard errors at the start values with the
        stated noise (`identify --design`).
    max_evaluations: the runs with sensitivities the fit may take.

    Returns a SeriesIdentification: estimates, parameters (one SeriesParameterEstimate each:
    estimate, standard_error, verdict, ...), correlation, singular_values, residuals, report
    (Markdown), and for a fit `scenario`, the estimated Scenario, ready to run(). The runs
    take place with the GIL released.

    Raises musclesim.InputError (naming the key path, e.g. "parameters[0].bounds",
    "series[1] (row 4)", "series[0].noise.force") for input that breaks a rule, as the CLI
    exits 2. A fit that does not converge, or whose weighted residuals lie far above the
    stated noise, still returns its result, with a RuntimeWarning (the CLI's exit 1 and
    warning); result.warnings holds the texts.
    """
    if not isinstance(scenario, _musclesim.Scenario):
        raise TypeError("scenario must be a musclesim.Scenario (load_scenario or "
                        "scenario_from_dict), not %s" % type(scenario).__name__)
    if hasattr(series, "keys") or isinstance(series, (str, bytes)):
        raise TypeError("series must be a list of series (dicts of arrays), not one; "
                        "write [series] for a single one")
    if isinstance(parameters, (str, bytes)) or hasattr(parameters, "keys"):
        raise TypeError("parameters must be a list of paths or {path, start, bounds} dicts, "
                        "not one; write [parameter] for a single one")
    entries: list[dict[str, Any]] = []
    columns: list[list[tuple[str, Any]]] = []
    for index, given in enumerate(series):
        entry, pairs = _series_entry(index, given)
        entries.append(entry)
        columns.append(pairs)
    spec = {
        "scenario": scenario._display,
        "series": entries,
        "parameters": [{"path": p} if isinstance(p, str) else p for p in parameters],
    }
    result = _musclesim._identify_series(scenario, spec, _SPEC_NAME, columns, bool(design),
                                         int(max_evaluations))
    for message in result.warnings:
        _warnings.warn("identify_series: " + message, RuntimeWarning, stacklevel=2)
    return result
