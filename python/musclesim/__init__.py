"""musclesim: muscle-like actuator tension, networks and control from Python.

SI units throughout (m, m/s, N, s); activations and excitations in [0, 1]; a shortening
velocity is positive when the actuator shortens. See help() on each function and class.
"""
from ._musclesim import *  # noqa: F401,F403
from ._musclesim import __doc__ as _extension_doc  # noqa: F401
from .scenario import scenario_from_dict  # noqa: F401,E402
from .stepping import sweep  # noqa: F401,E402
