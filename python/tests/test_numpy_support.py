"""Results are right under the NumPy that runs the tests (the suite runs under Debian's NumPy 1
and, as python.pytest_numpy2, under NumPy 2 in build-deps/venv): a run's last row is the
CLI's last row, and every column has the stride of a float64. A module built on a pybind11
that cannot serve NumPy 2 (before 2.12) refuses to import there rather than return arrays of
stride 0, whose every row reads as the first."""
import csv
import os
import subprocess

import numpy as np

import musclesim
from musclesim import _musclesim
from conftest import CLI, SOURCE


def test_every_result_column_is_a_contiguous_float64_array():
    result = musclesim.load_scenario(str(SOURCE / "scenarios/concentric.yaml")).run()
    for name in result.columns:
        column = result[name]
        if column.dtype.kind == "f":
            assert column.strides == (8,), name
    # the last row is not the first: the load was lifted
    assert result["length"][-1] < result["length"][0] - 0.01


def test_a_run_ends_where_the_command_line_run_ends(tmp_path):
    out = tmp_path / "run.csv"
    subprocess.run([CLI, "run", str(SOURCE / "scenarios/concentric.yaml"), "-o", str(out)],
                   check=True, capture_output=True)
    with out.open() as f:
        rows = [row for row in csv.DictReader(line for line in f if not line.startswith("#"))]
    result = musclesim.load_scenario(str(SOURCE / "scenarios/concentric.yaml")).run()
    assert len(rows) == len(result["t"])
    for name in ("t", "length", "shortening_velocity", "tension_total"):
        expected = np.array([float(row[name]) for row in rows])
        # the CSV writes every number to round-trip: the same doubles
        np.testing.assert_array_equal(result[name], expected, err_msg=name)


def test_input_arrays_of_every_layout_are_read_by_their_strides():
    model = musclesim.Model({
        "f_iso": 50.0,
        "passive": {"k_p": 2.0, "alpha": 80.0, "slack_length": 0.1},
        "active_length": {"optimal_range": [0.09, 0.11],
                          "gaussians": [{"amplitude": 1.0, "width": 3000.0, "center": 0.1}]},
        "velocity": {"v_max": 0.8, "n": 3, "epsilon": 1e-3},
    })
    x = np.linspace(0.06, 0.14, 9)
    every_other = np.linspace(0.06, 0.14, 17)[::2]
    np.testing.assert_array_equal(model.f_L(every_other), model.f_L(x))
    assert model.f_L(x).strides == (8,)


def test_the_refusal_rule_refuses_only_numpy_2_with_an_old_pybind11():
    old, new = 0x020A0300, 0x020D0600  # pybind11 2.10.3 (Debian 12), 2.13.6 (PyPI)
    message = _musclesim._numpy_refusal(old, "2.4.6")
    assert "pybind11 2.10" in message and "NumPy 2.4.6" in message and ">= 2.12" in message
    assert _musclesim._numpy_refusal(old, "1.24.2") == ""
    assert _musclesim._numpy_refusal(new, "2.4.6") == ""
    assert _musclesim._numpy_refusal(new, "1.24.2") == ""
    assert _musclesim._numpy_refusal(old, "10.0.0") != ""


def test_this_module_was_built_on_a_pybind11_that_serves_the_numpy_it_runs_under():
    assert _musclesim._numpy_refusal(_musclesim._pybind11_version_hex, np.__version__) == ""


def test_the_numpy_major_this_run_was_asked_for():
    # python.pytest_numpy2 sets it: a venv that silently fell back to NumPy 1 fails here
    expected = os.environ.get("MUSCLESIM_EXPECT_NUMPY_MAJOR")
    if expected is not None:
        assert np.__version__.split(".")[0] == expected
