"""Scenarios from files and dicts against `musclesim run`'s CSV (run here as a separate
program, its CSV parsed with NumPy): the same columns in the same order, the same numbers."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import musclesim
from conftest import CLI, SOURCE



def scenario_path(name):
    return os.path.join(SOURCE, "scenarios", name)


def cli_run(tmp_path, scenario, sets=(), sensitivities=()):
    """The CLI's CSV as (header, {numeric column: float64}, {text column: str})."""
    out = tmp_path / "cli.csv"
    command = [CLI, "run", scenario, "-o", str(out), "--quiet"]
    for s in sets:
        command += ["--set", s]
    for p in sensitivities:
        command += ["--sensitivity", p]
    subprocess.run(command, check=True, capture_output=True, text=True)
    with open(out) as f:
        header = f.readline().strip().split(",")
    table = np.loadtxt(out, delimiter=",", skiprows=1, dtype=str, ndmin=2)
    numbers, texts = {}, {}
    for i, name in enumerate(header):
        if name == "phase" or name.endswith(".phase"):
            texts[name] = table[:, i]
        else:
            numbers[name] = table[:, i].astype(np.float64)
    return header, numbers, texts


def assert_same_as_cli(result, cli):
    header, numbers, texts = cli
    assert list(result.columns) == header
    assert len(result) == len(numbers["t"])
    for name, expected in numbers.items():
        # exact: both are the same 17-significant-digit text read back, which round-trips
        # a double exactly, of the same deterministic computation
        np.testing.assert_array_equal(result.columns[name], expected, err_msg=name)
    for name, expected in texts.items():
        assert list(result.columns[name]) == list(expected), name


def test_concentric_file_matches_cli(tmp_path):
    result = musclesim.load_scenario(scenario_path("concentric.yaml")).run()
    assert result.status == "completed"
    assert_same_as_cli(result, cli_run(tmp_path, scenario_path("concentric.yaml")))


def test_network_matches_cli_with_overrides_as_list_or_dict(tmp_path):
    path = scenario_path("antagonist_pair.yaml")
    cli = cli_run(tmp_path, path, sets=["time.end=0.2"])
    listed = musclesim.load_scenario(path, set=["time.end=0.2"])
    assert listed.is_network
    assert_same_as_cli(listed.run(), cli)
    assert_same_as_cli(musclesim.load_scenario(path, set={"time.end": 0.2}).run(), cli)


def test_controllers_match_cli(tmp_path):
    path = scenario_path("force_regulation.yaml")
    scenario = musclesim.load_scenario(path).set("time.end", 0.2)
    assert scenario.is_network and scenario.name == "force_regulation"
    assert_same_as_cli(scenario.run(), cli_run(tmp_path, path, sets=["time.end=0.2"]))


# scenarios/concentric.yaml written out by hand as a dict (its `time.end` 0.2 s)
CONCENTRIC = {
    "name": "concentric_isotonic",
    "model": {
        "f_iso": 100.0,
        "passive": {"k_p": 1.0, "alpha": 100.0, "slack_length": 0.105},
        "active_length": {
            "optimal_range": [0.095, 0.105],
            "gaussians": [
                {"amplitude": 0.35188944617853268, "width": 20635.199147929347,
                 "center": 0.073556703926583866},
                {"amplitude": 2.2575025981825489, "width": 4125.1402656159307,
                 "center": 0.097194271247335401},
                {"amplitude": 1.3136662819543681, "width": 3009.3607405177986,
                 "center": 0.1301541244400391},
            ],
        },
        "velocity": {"v_max": 1.0, "n": 3, "epsilon": 1.0e-3},
    },
    "actuator": {"mass": 0.1, "damping": 0.0, "stiffness": 0.0, "rest_length": 0.1},
    "initial": {"length": 0.1, "lengthening_rate": 0.0},
    "activation": {"type": "step", "time": 0.05, "before": 0.0, "after": 1.0},
    "load": [{"type": "step", "time": 0.05, "before": 0.0, "after": 40.0}],
    "time": {"start": 0.0, "end": 0.2},
    "solver": {"method": "bdf", "rtol": 1.0e-6, "atol": 1.0e-9, "jacobian": "analytic",
               "max_step": 0.0},
    "output": {"file": "concentric.csv", "interval": 0.001},
    "limits": {"min_length": 0.06, "max_length": 0.2},
}


def test_dict_gives_the_file_result(tmp_path):
    scenario = musclesim.scenario_from_dict(CONCENTRIC)
    assert not scenario.is_network and scenario.name == "concentric_isotonic"
    cli = cli_run(tmp_path, scenario_path("concentric.yaml"), sets=["time.end=0.2"])
    assert_same_as_cli(scenario.run(), cli)
    # and the dict's own JSON text as a file (JSON is YAML) through the CLI
    text_file = tmp_path / "dict.yaml"
    text_file.write_text(json.dumps(CONCENTRIC))
    assert_same_as_cli(scenario.run(), cli_run(tmp_path, str(text_file)))


def test_set_changes_the_run(tmp_path):
    path = scenario_path("concentric.yaml")
    light = musclesim.load_scenario(path, set=["time.end=0.2"]).run()
    scenario = musclesim.load_scenario(path, set=["time.end=0.2"])
    assert scenario.set("load[0].after", 60.0) is scenario
    heavy = scenario.run()
    # a larger load (still below f_iso = 100 N) shortens the actuator less
    assert heavy["length"].min() > light["length"].min()
    assert_same_as_cli(heavy, cli_run(tmp_path, path, sets=["time.end=0.2", "load[0].after=60"]))


def test_a_network_run_follows_each_set_after_runs_before_it(tmp_path):
    # a scenario keeps the system its reading built for its runs; a set() must not leave a run
    # on the system of the values before it
    path = scenario_path("antagonist_pair.yaml")
    scenario = musclesim.load_scenario(path, set={"time.end": 0.2})
    assert_same_as_cli(scenario.run(), cli_run(tmp_path, path, sets=["time.end=0.2"]))
    scenario.set("nodes[1].mass", 2.5)  # a number, set in place through its handle
    assert_same_as_cli(scenario.run(),
                       cli_run(tmp_path, path, sets=["time.end=0.2", "nodes[1].mass=2.5"]))
    scenario.set("nodes[1].position", "0.065")  # text: the file read again with it
    assert_same_as_cli(scenario.run(), cli_run(
        tmp_path, path, sets=["time.end=0.2", "nodes[1].mass=2.5", "nodes[1].position=0.065"]))


def test_bad_set_raises_and_leaves_the_scenario():
    scenario = musclesim.load_scenario(scenario_path("concentric.yaml"))
    with pytest.raises(musclesim.InputError) as bad_key:
        scenario.set("load[0].aftr", 60.0)
    assert bad_key.value.key == "load[0].aftr"
    assert bad_key.value.location is None  # a value given by set() has no place in a file
    assert "unknown key" in str(bad_key.value)
    with pytest.raises(musclesim.InputError) as bad_value:
        scenario.set("model.velocity.n", 0)
    assert bad_value.value.key == "model.velocity.n"
    assert bad_value.value.location is None
    assert scenario.overrides == []


def test_broken_file_names_file_line_column(tmp_path):
    broken = tmp_path / "broken.yaml"
    text = open(scenario_path("concentric.yaml")).read()
    assert "  f_iso: 100.0" in text
    lines = text.splitlines()
    line = next(i for i, s in enumerate(lines) if s.startswith("  f_iso: 100.0")) + 1
    broken.write_text(text.replace("  f_iso: 100.0", "  f_iso: -100.0"))
    with pytest.raises(musclesim.InputError) as error:
        musclesim.load_scenario(str(broken))
    assert error.value.key == "model.f_iso"
    assert error.value.location == "%s:%d:10" % (broken, line)  # the value after "  f_iso: "
    # the CLI's message is the same text
    cli = subprocess.run([CLI, "run", str(broken), "-o", str(tmp_path / "x.csv")],
                         capture_output=True, text=True)
    assert cli.returncode == 2
    assert str(error.value) in cli.stderr


def test_dict_error_names_key_path_and_dict():
    bad = json.loads(json.dumps(CONCENTRIC))
    bad["load"][0]["type"] = "stepp"
    with pytest.raises(musclesim.InputError) as error:
        musclesim.scenario_from_dict(bad)
    assert error.value.key == "load[0].type"
    # read as a document, without text: the dict is named, and has no lines to give
    assert error.value.location is None
    assert "tmp" not in str(error.value) and "(<dict>)" in str(error.value)


def test_sensitivity_columns_match_cli(tmp_path):
    path = scenario_path("concentric.yaml")
    scenario = musclesim.load_scenario(path, set=["time.end=0.2"])
    result = scenario.run(sensitivities=["model.f_iso", "load[0].after"])
    assert "d_length/d_model.f_iso" in result.columns
    assert "d_tension_total/d_load[0].after" in result.columns
    assert [s["path"] for s in result.stats["sensitivities"]] == ["model.f_iso", "load[0].after"]
    assert_same_as_cli(result, cli_run(tmp_path, path, sets=["time.end=0.2"],
                                       sensitivities=["model.f_iso", "load[0].after"]))


def test_network_sensitivity_columns_match_cli(tmp_path):
    path = scenario_path("antagonist_pair.yaml")
    result = musclesim.load_scenario(path, set=["time.end=0.1"]).run(
        sensitivities=["models.muscle.f_iso"])
    assert "d_flexor.tension/d_models.muscle.f_iso" in result.columns
    assert_same_as_cli(result, cli_run(tmp_path, path, sets=["time.end=0.1"],
                                       sensitivities=["models.muscle.f_iso"]))


def test_shapes_dtypes_and_stats():
    result = musclesim.load_scenario(scenario_path("concentric.yaml")).run()
    n = len(result)
    # output.interval 0.001 s over [0, 0.5] s: 501 rows
    assert n == 501
    np.testing.assert_array_equal(result.times, result.columns["t"])
    for name, column in result.columns.items():
        assert column.shape == (n,), name
        if name == "phase":
            assert column.dtype.kind == "U"
            assert set(column) <= {"concentric", "eccentric", "isometric"}
        else:
            assert column.dtype == np.float64, name
    assert result.times[0] == 0.0 and result.times[-1] == pytest.approx(0.5, abs=1e-12)
    for key in ("steps", "rhs_evals", "jac_evals", "status", "message", "final_time",
                "wall_seconds", "linear_solver"):
        assert key in result.stats
    assert result.stats["steps"] > 0 and result.status == "completed"
    with pytest.raises(KeyError):
        result["no_such_column"]


def test_network_phase_columns_are_text():
    result = musclesim.load_scenario(scenario_path("antagonist_pair.yaml"),
                                     set={"time.end": 0.05}).run()
    assert result.columns["flexor.phase"].dtype.kind == "U"
    assert result.columns["flexor.length"].dtype == np.float64


def test_to_dataframe_without_pandas(monkeypatch):
    result = musclesim.load_scenario(scenario_path("isometric.yaml"), set=["time.end=0.01"]).run()
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now raises ImportError
    with pytest.raises(ImportError, match="python3-pandas"):
        result.to_dataframe()


def test_to_dataframe_with_pandas():
    import pandas  # a test dependency (scripts/install-deps.sh), not the module's
    result = musclesim.load_scenario(scenario_path("isometric.yaml"), set=["time.end=0.01"]).run()
    frame = result.to_dataframe()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == list(result.columns)
    np.testing.assert_array_equal(frame["t"].to_numpy(), result.times)


def test_solver_failure_is_a_result_with_the_rows_so_far(tmp_path):
    path = scenario_path("concentric.yaml")
    result = musclesim.load_scenario(path, set={"solver.max_steps": 5}).run()
    assert result.status == "failed" and "max_steps" in result.stats["message"]
    # the CLI exits 3 and leaves the rows computed so far in PATH.partial
    out = tmp_path / "failed.csv"
    cli = subprocess.run(
        [CLI, "run", path, "-o", str(out), "--quiet", "--set", "solver.max_steps=5"],
        capture_output=True, text=True)
    assert cli.returncode == 3
    partial = np.loadtxt(str(out) + ".partial", delimiter=",", skiprows=1, dtype=str, ndmin=2)
    assert 0 < len(result) == partial.shape[0]
    # exact, as in assert_same_as_cli
    np.testing.assert_array_equal(result["length"], partial[:, 1].astype(np.float64))


def test_a_scenario_shared_by_threads_runs_while_another_sets():
    # run() and set() take the scenario's state with the GIL; a set() seen half done (an
    # override list growing under a run) would crash or run a mixture
    import threading
    scenario = musclesim.load_scenario(scenario_path("concentric.yaml"), set={"time.end": 0.02})
    finals, errors = [], []

    def runner():
        for _ in range(30):
            result = scenario.run()
            finals.append(result.stats["final_time"])

    def setter():
        try:
            for k in range(300):
                scenario.set("load[0].after", 20.0 + k % 5)
        except Exception as error:  # noqa: BLE001 - any is the failure
            errors.append(error)

    threads = [threading.Thread(target=runner), threading.Thread(target=setter)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert errors == [] and finals == [0.02] * 30
    # one value per key, its last
    assert scenario.overrides == ["time.end=0.02", "load[0].after=24.0"]


def test_solver_options_hold_each_key_of_the_solver_block_as_the_file_gave_it():
    # every key `musclesim reference solver` lists is an attribute, with the file's value
    # (set here through --set, as a file would give it) or the table's default
    table = subprocess.run([CLI, "reference", "solver"], check=True, capture_output=True,
                           text=True).stdout
    rows = [line.split("|") for line in table.splitlines()[2:]]
    defaults = {row[3].strip().strip("`"): row[5].strip() for row in rows}
    assert set(defaults) == {"rtol", "atol", "max_step", "max_steps", "method", "jacobian",
                             "linear_solver"}
    given = {"solver.rtol": 1e-8, "solver.max_steps": 500, "solver.linear_solver": "dense",
             "solver.method": "adams"}
    solver = musclesim.load_scenario(scenario_path("concentric.yaml"), set=given).solver
    for key, default in defaults.items():
        value = getattr(solver, key)
        if "solver." + key in given:
            assert value == given["solver." + key], key
        elif isinstance(value, str):
            assert value == default, key
    assert isinstance(solver.max_steps, int)
    assert "an integer from 1 to 1e+12" in type(solver).max_steps.__doc__
