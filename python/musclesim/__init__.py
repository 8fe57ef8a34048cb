"""musclesim: muscle-like actuator tension, networks and control from Python.

SI units throughout (m, m/s, N, s); activations and excitations in [0, 1]; a shortening
velocity is positive when the actuator shortens. See help() on each function and class.
"""
from ._musclesim import *  # noqa: F401,F403
from ._musclesim import __doc__ as _extension_doc  # noqa: F401
from ._musclesim import __version__  # noqa: F401
from .scenario import scenario_from_dict  # noqa: F401,E402
from .sweeps import sweep  # noqa: F401,E402
from .tables import table  # noqa: F401,E402


def run_many(jobs, threads=0, sensitivities=None):
    """Runs many scenarios on `threads` C++ threads (0: every core) with the GIL released.

    Each job is a Scenario (from load_scenario or scenario_from_dict, with its set() values)
    or a (path, overrides) pair, overrides a list of 'key=value' strings or a dict. Returns
    one Result per job, in order, as Scenario.run() gives it: .columns (the CSV's columns as
    NumPy arrays, SI units: s, m, m/s, N), .stats, .status. musclesim.table(results) stacks
    them into one structured array (a DataFrame with pandas.DataFrame(...)).
    `sensitivities`: dotted paths of numeric parameters whose forward sensitivities every run
    adds as the columns d_<column>/d_<path>, as Scenario.run(sensitivities=...) does.
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
    return _extension.run_many(jobs, threads, list(sensitivities or []))


from .curves_identification import *  # noqa: F401,F403,E402
from .series_identification import *  # noqa: F401,F403,E402
from .plotting import *  # noqa: F401,F403,E402
