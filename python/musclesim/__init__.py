"""musclesim: muscle-like actuator tension, networks and control from Python.

SI units throughout (m, m/s, N, s); activations and excitations in [0, 1]; a shortening
velocity is positive when the actuator shortens. See help() on each function and class.
"""
from ._musclesim import *  # noqa: F401,F403
from ._musclesim import __doc__ as _extension_doc  # noqa: F401
from .scenario import scenario_from_dict  # noqa: F401,E402
from .sweeps import sweep  # noqa: F401,E402
from .tables import table  # noqa: F401,E402


def run_many(jobs, threads=0):
    """Runs many scenarios on `threads` C++ threads (0: every core) with the GIL released.

    Each job is a Scenario (from load_scenario or scenario_from_dict, with its set() values)
    or a (path, overrides) pair, overrides a list of 'key=value' strings or a dict. Returns
    one Result per job, in order, as Scenario.run() gives it: .columns (the CSV's columns as
    NumPy arrays, SI units: s, m, m/s, N), .stats, .status. musclesim.table(results) stacks
    them into one structured array (a DataFrame with pandas.DataFrame(...)).
    """
    from . import _musclesim as _extension
    jobs = list(jobs)  # the Scenarios (and a dict's temporary file) live until the runs end
    converted = [(job._path, job.overrides) if isinstance(job, Scenario) else job for job in jobs]
    return _extension.run_many(converted, threads)


from .curves_identification import *  # noqa: F401,F403,E402
from .series_identification import *  # noqa: F401,F403,E402
from .plotting import *  # noqa: F401,F403,E402
