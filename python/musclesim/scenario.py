"""Scenarios from Python dicts (the YAML file's keys and values)."""
from __future__ import annotations

from typing import Any

from . import _musclesim


def scenario_from_dict(d: dict[str, Any], name: str = "<dict>") -> _musclesim.Scenario:
    """A validated Scenario from a dict with a scenario file's keys (a single actuator's:
    docs/guide/scenarios.md; a network's: docs/guide/networks.md).

    The dict is read by the same reader as a file, as a document in memory (no text in
    between), so the same rules apply; an InputError names the key path (e.g.
    "load[0].after") and `name` in place of the file (a dict has no lines). SI units as in
    the files (m, m/s, N, s; activations in [0, 1]). NumPy numbers and arrays are taken as
    Python numbers and lists.
    """
    if not isinstance(d, dict):
        raise TypeError("scenario_from_dict expects a dict, not %s" % type(d).__name__)
    return _musclesim._scenario_from_dict(d, name)
