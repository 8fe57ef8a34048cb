"""musclesim: muscle-like actuator tension, networks and control from Python.

SI units throughout (m, m/s, N, s); activations and excitations in [0, 1]; a shortening
velocity is positive when the actuator shortens. See help() on each function and class.
"""
from __future__ import annotations

import typing as _typing

from ._errors import InputError as InputError  # noqa: F401
from ._errors import ParameterError as ParameterError  # noqa: F401
from ._musclesim import *  # noqa: F401,F403
from ._musclesim import __doc__ as _extension_doc  # noqa: F401
from ._musclesim import __version__ as __version__  # noqa: F401
from ._musclesim import Result, Scenario
from ._types import Overrides as _Overrides
from ._types import PathLike as _PathLike
from .scenario import scenario_from_dict as scenario_from_dict  # noqa: F401,E402
from .sweeps import sweep as sweep  # noqa: F401,E402
from .optimization import optimize as optimize  # noqa: F401,E402
from .tables import table as table  # noqa: F401,E402

# A job of run_many: a Scenario, or a scenario file's path with the values to set first.
_Job = _typing.Union[Scenario, _typing.Tuple[_PathLike, _Overrides]]


def run_many(jobs: _typing.Iterable[_Job], threads: int = 0,
             sensitivities: _typing.Iterable[str] | None = None) -> list[Result]:
    """Runs many scenarios on `threads` C++ threads (0: every core) with the GIL released.

    Each job is a Scenario (from load_scenario or scenario_from_dict, with its set() values)
    or a (path, overrides) pair, overrides None, a list of 'key=value' strings as --set takes
    them, or a dict. Returns one Result per job, in order, as Scenario.run() gives it:
    .columns (the CSV's columns as NumPy arrays, SI units: s, m, m/s, N), .stats, .status. A
    bad job raises (the first in the list's order) after every job has run.
    musclesim.table(results) stacks them into one structured array (a DataFrame with
    pandas.DataFrame(...)). `sensitivities`: dotted paths of numeric parameters whose forward
    sensitivities every run adds as the columns d_<column>/d_<path>, as
    Scenario.run(sensitivities=...) does.
    """
    from . import _musclesim as _extension
    if isinstance(threads, bool) or not isinstance(threads, int):
        raise TypeError("threads must be an int (0: every core), not %r" % (threads,))
    jobs = list(jobs)
    for k, job in enumerate(jobs):
        if not isinstance(job, (Scenario, tuple, list)) or (
                not isinstance(job, Scenario) and len(job) != 2):
            raise TypeError("jobs[%d] must be a Scenario or a (path, overrides) pair, not %r"
                            % (k, job))
    if isinstance(sensitivities, str):
        raise TypeError("sensitivities must be a list of dotted paths, not one str")
    return _extension._run_many(jobs, threads, list(sensitivities or []))


from .curves_identification import *  # noqa: F401,F403,E402
from .series_identification import *  # noqa: F401,F403,E402
from .plotting import *  # noqa: F401,F403,E402
