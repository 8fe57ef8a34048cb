"""Optimal control from Python: musclesim.optimize finds the activations, piecewise linear on
a grid, with free parameters and a free final time, that meet final values and path bounds
at the least weighted effort, tracking, terminal and final-time cost (docs/guide/optimize.md),
as `musclesim optimize` does from a problem file."""
from __future__ import annotations

from typing import Any, Mapping, Sequence

from ._musclesim import Scenario, _optimize

_CONTROL_KEYS = {"actuator", "bounds", "effort"}
_FINAL_KEYS = {"column", "value", "bounds"}


def _pair(value: Any, where: str) -> tuple[float, float]:
    try:
        lower, upper = value
        return float(lower), float(upper)
    except (TypeError, ValueError):
        raise ValueError(f"{where} = {value!r}: must be [lower, upper]") from None


def _check_keys(entry: Mapping[str, Any], known: set[str], where: str) -> None:
    unknown = set(entry) - known
    if unknown:
        raise ValueError(f"{where}: unknown keys {sorted(unknown)}; known: {sorted(known)}")


def _entries(entries: Sequence[Mapping[str, Any]], name: str, known: set[str],
             required: Sequence[str]) -> list[tuple[int, str, Mapping[str, Any]]]:
    out = []
    for i, entry in enumerate(entries):
        where = f"{name}[{i}]"
        _check_keys(entry, known, where)
        for key in required:
            if key not in entry:
                raise ValueError(f"{where}: missing '{key}'")
        out.append((i, where, entry))
    return out


def optimize(scenario: Scenario, controls: Sequence[Mapping[str, Any]],
             final_values: Sequence[Mapping[str, Any]] = (), intervals: int = 20,
             tolerance: float = 1e-8, max_iterations: int = 500, *,
             path_bounds: Sequence[Mapping[str, Any]] = (),
             tracking: Sequence[Mapping[str, Any]] = (),
             terminal: Sequence[Mapping[str, Any]] = (),
             parameters: Sequence[Mapping[str, Any]] = (),
             final_time: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """The controls (and free parameters, and final time) that meet the constraints at the
    least weighted sum of effort, tracking, terminal and final-time terms, as `musclesim
    optimize` finds them from a problem file (docs/guide/optimize.md), with the same keys.

    controls: [{"actuator": NAME, "bounds": [lo, hi] (default [0, 1]),
    "effort": {"weight": w (1), "power": 2 or 3 (2)}}, ...]: an actuator's activation, or its
    excitation when it has activation dynamics. final_values: [{"column": "load.position",
    "value": x} or {"column": ..., "bounds": [lo, hi]}, ...]. path_bounds: [{"column": ...,
    "bounds": [lo, hi]}] at every grid point. tracking: [{"column": ..., "reference":
    (times, values), "weight": w}]. terminal: [{"column": ..., "target": x, "weight": w}].
    parameters: [{"path": "models.muscle.f_iso", "bounds": [lo, hi]}]. final_time:
    {"bounds": [lo, hi], "weight": w} for a free final time. Columns are a run's
    differentiated columns. The grid has `intervals` even intervals over the span.

    Returns a dict: status (IPOPT's), solved, objective, terms (effort, tracking, terminal,
    final_time), constraint_violation, dual_infeasibility, iterations, gradient_check,
    resimulation_deviation, final_time, times (the grid), controls (name -> values on the
    grid), parameters (path -> value), states (the shooting states, a row per grid point) and
    scenario (the given one with the optimal controls as tables, the parameters and the final
    time set, which .run() re-simulates). A problem the scenario does not fit raises
    InputError.
    """
    control_tuples = []
    for _, where, control in _entries(controls, "controls", _CONTROL_KEYS, ["actuator"]):
        lower, upper = _pair(control.get("bounds", (0.0, 1.0)), where + ".bounds")
        effort = control.get("effort", {})
        control_tuples.append((str(control["actuator"]), lower, upper,
                               float(effort.get("weight", 1.0)), int(effort.get("power", 2))))
    final_tuples = []
    for _, where, final in _entries(final_values, "final_values", _FINAL_KEYS, ["column"]):
        if ("value" in final) == ("bounds" in final):
            raise ValueError(f"{where}: give 'column' and either 'value' or 'bounds'")
        if "value" in final:
            lower = upper = float(final["value"])
        else:
            lower, upper = _pair(final["bounds"], where + ".bounds")
        final_tuples.append((str(final["column"]), lower, upper))
    path_tuples = [(str(b["column"]), *_pair(b["bounds"], where + ".bounds"))
                   for _, where, b in _entries(path_bounds, "path_bounds", {"column", "bounds"},
                                               ["column", "bounds"])]
    tracking_tuples = []
    for _, where, term in _entries(tracking, "tracking", {"column", "reference", "weight"},
                                   ["column", "reference"]):
        times, values = term["reference"]
        tracking_tuples.append((str(term["column"]), [float(t) for t in times],
                                [float(v) for v in values], float(term.get("weight", 1.0))))
    terminal_tuples = [(str(term["column"]), float(term["target"]), float(term.get("weight", 1.0)))
                       for _, _, term in _entries(terminal, "terminal",
                                                  {"column", "target", "weight"},
                                                  ["column", "target"])]
    parameter_tuples = [(str(p["path"]), *_pair(p["bounds"], where + ".bounds"))
                        for _, where, p in _entries(parameters, "parameters", {"path", "bounds"},
                                                    ["path", "bounds"])]
    time_tuple = None
    if final_time is not None:
        _check_keys(final_time, {"bounds", "weight"}, "final_time")
        if "bounds" not in final_time:
            raise ValueError("final_time: missing 'bounds'")
        time_tuple = (*_pair(final_time["bounds"], "final_time.bounds"),
                      float(final_time.get("weight", 0.0)))
    return _optimize(scenario, control_tuples, final_tuples, int(intervals), float(tolerance),
                     int(max_iterations), path_tuples, tracking_tuples, terminal_tuples,
                     parameter_tuples, time_tuple)
