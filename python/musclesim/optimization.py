"""Optimal control from Python: musclesim.optimize finds the activations, piecewise linear on
a grid, that take a Scenario's network to final values with the least effort
(docs/guide/optimize.md), as `musclesim optimize` does from a problem file."""
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


def optimize(scenario: Scenario, controls: Sequence[Mapping[str, Any]],
             final_values: Sequence[Mapping[str, Any]] = (), intervals: int = 20,
             tolerance: float = 1e-8, max_iterations: int = 500) -> dict[str, Any]:
    """The activations of `controls` that reach `final_values` with the least effort.

    controls: [{"actuator": NAME, "bounds": [lo, hi] (default [0, 1]),
    "effort": {"weight": w (1), "power": 2 or 3 (2)}}, ...]; final_values: [{"column":
    "load.position", "value": x} or {"column": ..., "bounds": [lo, hi]}, ...]. The grid has
    `intervals` even intervals over the scenario's time span. Returns a dict: status (IPOPT's),
    solved, objective, constraint_violation, iterations, times (the grid), controls (name ->
    values on the grid) and scenario (the given one with the optimal activations as tables,
    which .run() re-simulates). A problem the scenario does not fit raises InputError.
    """
    control_tuples = []
    for i, control in enumerate(controls):
        where = f"controls[{i}]"
        _check_keys(control, _CONTROL_KEYS, where)
        if "actuator" not in control:
            raise ValueError(f"{where}: missing 'actuator', the name of an actuator")
        lower, upper = _pair(control.get("bounds", (0.0, 1.0)), where + ".bounds")
        effort = control.get("effort", {})
        control_tuples.append((str(control["actuator"]), lower, upper,
                               float(effort.get("weight", 1.0)), int(effort.get("power", 2))))
    final_tuples = []
    for k, final in enumerate(final_values):
        where = f"final_values[{k}]"
        _check_keys(final, _FINAL_KEYS, where)
        if "column" not in final or ("value" in final) == ("bounds" in final):
            raise ValueError(f"{where}: give 'column' and either 'value' or 'bounds'")
        if "value" in final:
            lower = upper = float(final["value"])
        else:
            lower, upper = _pair(final["bounds"], where + ".bounds")
        final_tuples.append((str(final["column"]), lower, upper))
    return _optimize(scenario, control_tuples, final_tuples, int(intervals), float(tolerance),
                     int(max_iterations))
