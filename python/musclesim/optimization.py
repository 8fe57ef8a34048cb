"""Optimal control from Python: musclesim.optimize finds the activations, piecewise linear on
a grid, with free parameters and a free final time, that meet final values and path bounds
at the least weighted effort, tracking, terminal and final-time cost (docs/guide/optimize.md),
as `musclesim optimize` does from a problem file."""
from __future__ import annotations

from typing import Any, Mapping, Sequence

from ._musclesim import Scenario, _optimize
from ._errors import InputError


def _reference(term: Mapping[str, Any], where: str) -> Any:
    """A tracking reference as the problem file gives it: (times, values) become its points."""
    reference = term.get("reference")
    if isinstance(reference, Mapping) or reference is None:
        return reference
    try:
        times, values = reference
        times, values = list(times), list(values)
        if len(times) != len(values):
            raise ValueError
    except (TypeError, ValueError):
        raise InputError(f"{where}.reference (optimize(...)): must be (times, values) of one "
                         "length, or "
                         "{'points': [[t, value], ...]} or {'csv': FILE, 'column': NAME}"
                         ) from None
    return {"points": [[t, v] for t, v in zip(times, values)]}


def optimize(scenario: Scenario, controls: Sequence[Mapping[str, Any]],
             final_values: Sequence[Mapping[str, Any]] = (), intervals: int = 20,
             tolerance: float = 1e-8, max_iterations: int = 500, *,
             path_bounds: Sequence[Mapping[str, Any]] = (),
             tracking: Sequence[Mapping[str, Any]] = (),
             terminal: Sequence[Mapping[str, Any]] = (),
             parameters: Sequence[Mapping[str, Any]] = (),
             final_time: Mapping[str, Any] | None = None,
             max_seconds: float | None = None) -> dict[str, Any]:
    """The controls (and free parameters, and final time) that meet the constraints at the
    least weighted sum of effort, tracking, terminal and final-time terms, as `musclesim
    optimize` finds them from a problem file (docs/guide/optimize.md), with the same keys,
    read by the same reader: every argument is checked by the problem file's rules and a
    broken one raises InputError naming its key, value and rule.

    controls: [{"actuator": NAME, "bounds": [lo, hi] (default [0, 1]),
    "effort": {"weight": w (1), "power": 2 or 3 (2)}}, ...]: an actuator's activation, or its
    excitation when it has activation dynamics. final_values: [{"column": "load.position",
    "value": x} or {"column": ..., "bounds": [lo, hi]}, ...]. path_bounds: [{"column": ...,
    "bounds": [lo, hi]}] at every grid point. tracking: [{"column": ..., "reference":
    (times, values) or {"points": [[t, r], ...]} or {"csv": FILE, "column": NAME},
    "weight": w}]. terminal: [{"column": ..., "target": x, "weight": w}].
    parameters: [{"path": "models.muscle.f_iso", "bounds": [lo, hi]}]. final_time:
    {"bounds": [lo, hi], "weight": w} for a free final time. Columns are a run's
    differentiated columns. The grid has `intervals` even intervals over the span (an
    integer from 1 to 100000). tolerance, max_iterations and max_seconds are the problem
    file's optimizer block (max_seconds: the solve's wall time, None for no limit).

    Returns a dict: status (IPOPT's, or infeasibility_stalled, maximum_seconds_exceeded),
    solved, objective, terms (effort, tracking, terminal, final_time), constraint_violation,
    largest_violation (the constraint violated most, named), infeasible,
    dual_infeasibility, iterations, gradient_check, resimulation_deviation, final_time,
    times (the grid), controls (name -> values on the grid), parameters (path -> value),
    states (the shooting states, a row per grid point) and scenario (the given one with the
    optimal controls as tables, the parameters and the final time set, which .run()
    re-simulates). A problem the scenario does not fit raises InputError.
    """
    problem: dict[str, Any] = {"intervals": intervals, "controls": list(controls)}
    for key, entries in (("final_values", final_values), ("path_bounds", path_bounds),
                         ("terminal", terminal), ("parameters", parameters)):
        if entries:
            problem[key] = list(entries)
    if tracking:
        terms = []
        for i, term in enumerate(tracking):
            given = dict(term) if isinstance(term, Mapping) else term
            if isinstance(given, dict) and "reference" in given:
                given["reference"] = _reference(given, f"tracking[{i}]")
            terms.append(given)
        problem["tracking"] = terms
    if final_time is not None:
        problem["final_time"] = final_time
    optimizer: dict[str, Any] = {"tolerance": tolerance, "max_iterations": max_iterations}
    if max_seconds is not None:
        optimizer["max_seconds"] = max_seconds
    problem["optimizer"] = optimizer
    return _optimize(scenario, problem)
