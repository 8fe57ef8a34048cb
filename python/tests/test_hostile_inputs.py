"""Hostile use of the module: objects made without their constructor, set() called
thousands of times, unlike results stacked, absurd times, and a deterministic fuzz of the
public functions' arguments (wrong types and shapes, NaN, infinities, huge numbers). Each
must end in a Python exception that says what is wrong: never a crash, a hang, garbage or a
silently wrong answer."""
import math
import random

import numpy as np
import pytest

import musclesim
from musclesim import _musclesim
from conftest import CONCENTRIC, SCENARIOS

UNINITIALISED = "made without its constructor"


def bound_types():
    return [value for value in vars(_musclesim).values()
            if isinstance(value, type) and type(value).__name__ == "pybind11_type"]


@pytest.mark.parametrize("cls", bound_types(), ids=lambda cls: cls.__name__)
def test_every_bound_type_refuses_use_without_its_constructor(cls):
    made = cls.__new__(cls)
    properties = [name for name, value in vars(cls).items() if isinstance(value, property)]
    for name in properties:
        with pytest.raises(TypeError, match=UNINITIALISED):
            getattr(made, name)
    if "__repr__" in vars(cls):
        with pytest.raises(TypeError, match=UNINITIALISED):
            repr(made)


@pytest.mark.parametrize("use", [
    lambda: musclesim.Model.__new__(musclesim.Model).tension(0.1, 0.0, 1.0),
    lambda: musclesim.Scenario.__new__(musclesim.Scenario).to_yaml(),
    lambda: musclesim.Scenario.__new__(musclesim.Scenario).run(),
    lambda: musclesim.Result.__new__(musclesim.Result).columns,
    lambda: musclesim.Stepper.__new__(musclesim.Stepper).advance(0.1),
    lambda: musclesim.Stepper.__new__(musclesim.Stepper).set_activation("flexor", 0.5),
    lambda: musclesim.run_many([musclesim.Scenario.__new__(musclesim.Scenario)]),
], ids=["tension", "to_yaml", "run", "columns", "advance", "set_activation", "run_many"])
def test_the_probes_uses_of_uninitialised_objects_raise_type_error(use):
    with pytest.raises(TypeError, match=UNINITIALISED):
        use()


def test_a_subclass_that_forgets_the_base_constructor_is_refused():
    class Forgetful(musclesim.Stepper):
        def __init__(self):  # no super().__init__()
            pass

    with pytest.raises(TypeError, match="__init__"):
        Forgetful()


def test_set_keeps_one_value_per_key_and_makes_the_same_scenario():
    looped = musclesim.load_scenario(CONCENTRIC)
    for k in range(3000):
        looped.set("model.f_iso", 100.0 + k)
        looped.set("solver.method", "adams" if k % 2 else "bdf")
    assert looped.overrides == ["model.f_iso=3099.0", "solver.method=adams"]
    once = musclesim.load_scenario(CONCENTRIC, set=["model.f_iso=3099.0", "solver.method=adams"])
    assert looped.to_yaml() == once.to_yaml()
    np.testing.assert_array_equal(looped.run().columns["length"], once.run().columns["length"])


def test_table_of_what_is_not_results_names_the_argument():
    single = musclesim.load_scenario(CONCENTRIC, set={"time.end": 0.01}).run()
    with pytest.raises(TypeError, match=r"results\[1\] is int, not a musclesim.Result"):
        musclesim.table([single, 3])
    with pytest.raises(TypeError, match=r"results\[0\] is dict, not a musclesim.Result"):
        musclesim.table([single.columns])
    with pytest.raises(TypeError, match="results must be an iterable of musclesim.Result, not "
                                        "dict"):
        musclesim.table(single.columns)


@pytest.mark.parametrize("t_next", [1e300, -1e300, 1e10, math.nan, math.inf])
def test_advance_to_an_absurd_time_is_refused_and_the_stepper_goes_on(t_next):
    stepper = musclesim.Stepper(SCENARIOS / "antagonist_pair.yaml")
    with pytest.raises(musclesim.ParameterError, match="t_next"):
        stepper.advance(t_next)
    assert stepper.advance(0.001) == "completed" and stepper.time == 0.001


# --- a deterministic fuzz of the public functions' arguments ---------------------------------

HOSTILE = [None, True, 0, -1, 2**70, math.nan, math.inf, -math.inf, 1e308, -1e308, 5e-324, "",
           "x", "model.f_iso", "../../etc/passwd", [], [1.0], [[1.0, 2.0]], (1, 2), {},
           {"a": 1}, object(), np.zeros((2, 2)), np.array([math.nan]), np.array(["a"]),
           np.arange(3.0), b"\x00\xff"]
# what a refusal may be: the module's own errors, and Python's for a wrong type or value
REFUSALS = (TypeError, ValueError, OverflowError, musclesim.InputError)



def calls(folder):
    scenario = musclesim.load_scenario(CONCENTRIC, set={"time.end": 0.01})
    move = musclesim.load_scenario(SCENARIOS / "antagonist_move.yaml")
    short = scenario.run()
    figure = folder / "hostile.png"
    stepper = musclesim.Stepper(SCENARIOS / "antagonist_pair.yaml")
    tension_model = musclesim.load_model(CONCENTRIC)
    return {
        "Model.tension": (tension_model.tension, 3),
        "Model.f_L": (tension_model.f_L, 1),
        "Model.g": (tension_model.g, 1),
        "Scenario.set": (scenario.set, 2),
        "Scenario.parameter": (scenario.parameter, 1),
        "Scenario.run": (lambda s: scenario.run(sensitivities=s), 1),
        "Stepper.advance": (stepper.advance, 1),
        "Stepper.set_activation": (stepper.set_activation, 2),
        "load_scenario": (musclesim.load_scenario, 2),
        "scenario_from_dict": (musclesim.scenario_from_dict, 1),
        "fit_gaussians": (musclesim.fit_gaussians, 3),
        "force_length_preset": (musclesim.force_length_preset, 3),
        "run_many": (musclesim.run_many, 2),
        "table": (musclesim.table, 1),
        # an optimisation's every argument, and a figure's data and options
        "optimize": (lambda c, f, i: musclesim.optimize(move, controls=c, final_values=f,
                                                         intervals=i, max_seconds=5.0), 3),
        "optimize.options": (lambda t, m, s: musclesim.optimize(
            move, controls=[{"actuator": "flexor"}], intervals=2, tolerance=t,
            max_iterations=m, max_seconds=s), 3),
        "optimize.terms": (lambda p, tr, te: musclesim.optimize(
            move, controls=[{"actuator": "flexor"}], intervals=2, path_bounds=p, tracking=tr,
            terminal=te, max_seconds=5.0), 3),
        "plot": (lambda d, t: musclesim.plot(d, figure, title=t), 2),
        "plot.options": (lambda x, n: musclesim.plot(short, figure, x=x, frame_count=n), 2),
    }


def test_hostile_arguments_raise_a_clear_python_exception(tmp_path):
    rng = random.Random(20261127)
    for name, (function, arity) in calls(tmp_path).items():
        for _ in range(60):
            arguments = [rng.choice(HOSTILE) for _ in range(arity)]
            try:
                function(*arguments)
            except REFUSALS as error:
                assert str(error), (name, arguments)  # a refusal says why
            except Exception as error:  # noqa: BLE001 - anything else is the failure
                pytest.fail("%s%r raised %s: %s" % (name, tuple(arguments),
                                                    type(error).__name__, error))


def test_values_nested_past_the_limit_or_holding_themselves_raise_value_error():
    deep = "x"
    for _ in range(5000):
        deep = {"a": deep}
    cyclic = {}
    cyclic["x"] = cyclic
    loop = []
    loop.append(loop)
    for value in (deep, cyclic, {"name": "n", "nodes": loop}):
        with pytest.raises(ValueError, match="nested deeper than 100 levels"):
            musclesim.scenario_from_dict(value)
