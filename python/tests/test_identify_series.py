"""identify_series: time-series identification from Python values, checked against
`musclesim identify` on the same data file (run here as a separate program), against known
parameters behind noise-free data made in the test, against finite-difference
sensitivities computed in the test, and for the input rules and their messages."""
import copy
import os
import pathlib
import re
import subprocess
import warnings
from decimal import Decimal

import numpy as np
import pytest

import musclesim
from conftest import CLI, SOURCE

DATA = SOURCE / "data" / "quick_release.yaml"

# A quick release as scenarios/quick_release.yaml, on a coarser grid (51 rows) and at a tight
# tolerance, so that noise-free data and finite differences are accurate: the actuator,
# activated at 0.05 s, lifts 60 N, and at 0.15 s half the load is taken off.
RELEASE = {
    "name": "release",
    "model": {
        "f_iso": 100.0,
        "passive": {"k_p": 1.0, "alpha": 100.0, "slack_length": 0.105},
        "active_length": {"optimal_range": [0.095, 0.105],
                          "gaussians": [{"amplitude": 1.0, "width": 3000.0, "center": 0.1}]},
        "velocity": {"v_max": 1.0, "n": 3, "epsilon": 1e-3},
    },
    "actuator": {"mass": 0.1},
    "initial": {"length": 0.1},
    "activation": {"type": "step", "time": 0.05, "before": 0.0, "after": 1.0},
    "load": [{"type": "step", "time": 0.05, "before": 0.0, "after": 60.0},
             {"type": "step", "time": 0.15, "before": 0.0, "after": -30.0}],
    "time": {"start": 0.0, "end": 0.25},
    "solver": {"method": "bdf", "rtol": 1e-10, "atol": 1e-13},
    "output": {"interval": 0.005},
}
TRUTH = {"f_iso": 90.0, "v_max": 1.2}  # what the noise-free data are made with [N, m/s]


def release(f_iso=100.0, v_max=1.0, name="release.yaml"):
    d = copy.deepcopy(RELEASE)
    d["model"]["f_iso"] = f_iso
    d["model"]["velocity"]["v_max"] = v_max
    return musclesim.scenario_from_dict(d, name=name)


def read_csv(path):
    """A CSV with # comment lines as {column: float64 array}."""
    lines = [line for line in open(path) if not line.startswith("#")]
    header = lines[0].strip().split(",")
    table = np.loadtxt(lines[1:], delimiter=",", ndmin=2)
    return {name: table[:, i] for i, name in enumerate(header)}


def quick_release_data_file():
    """What data/quick_release.yaml gives: its scenario, its series' CSV and noise, and its
    parameters, read from its text (flow mappings, one a line)."""
    text = DATA.read_text()
    scenario = re.search(r"^scenario: (\S+)", text, re.M).group(1)
    csv = re.search(r"- csv: (\S+)", text).group(1)
    noise = {k: float(v) for k, v in re.findall(r"noise: \{(\w+): ([-+.\deE]+)\}", text)}
    parameters = [{"path": p, "start": float(s), "bounds": [float(lo), float(hi)]}
                  for p, s, lo, hi in re.findall(
                      r"- \{path: ([\w.]+), start: ([-+.\deE]+), "
                      r"bounds: \[([-+.\deE]+), ([-+.\deE]+)\]\}", text)]
    assert len(parameters) == 3 and noise, "data/quick_release.yaml changed form"
    series = dict(read_csv(DATA.parent / csv))
    series["noise"] = noise
    return musclesim.load_scenario(str((DATA.parent / scenario).resolve())), series, parameters


def cli(*args):
    return subprocess.run([CLI, "identify", str(DATA), *args], capture_output=True, text=True)


def printed_tolerance(text):
    """Half a unit in the last digit `text` prints: how far a number printed so may be."""
    return 0.5 * 10.0 ** Decimal(text).as_tuple().exponent


# --- (a) the data file's example against the CLI -------------------------------------------

def test_quick_release_fit_is_the_clis(tmp_path):
    scenario, series, parameters = quick_release_data_file()
    result = musclesim.identify_series(scenario, [series], parameters)
    out = cli("-o", str(tmp_path / "est.yaml"), "--report", str(tmp_path / "report.md"),
              "--residuals", str(tmp_path / "res.csv"))
    assert out.returncode == 0, out.stderr
    assert result.converged and result.warnings == []
    header = re.findall(r"^#   (\S+) = (\S+) \+- (not determined|\S+)",
                        (tmp_path / "est.yaml").read_text(), re.M)
    assert [h[0] for h in header] == [p["path"] for p in parameters]
    for (path, estimate, error), p in zip(header, result.parameters):
        # the same computation: the estimate's shortest exact text reads back to the same
        # double; the standard error is printed to 2 significant digits
        assert p.estimate == float(estimate) == result.estimates[path]
        if error == "not determined":
            assert p.standard_error == np.inf
        else:
            assert abs(p.standard_error - float(error)) <= printed_tolerance(error)
    # the whole report after its title (which names the data file) is the CLI's, and each
    # residual is the same double (17 significant digits read back)
    cli_report = (tmp_path / "report.md").read_text()
    assert result.report.split("\n", 1)[1] == cli_report.split("\n", 1)[1]
    lines = (tmp_path / "res.csv").read_text().splitlines()
    columns = lines[0].split(",")
    rows = [line.split(",") for line in lines[1:]]
    for i, name in enumerate(columns):
        got = result.residuals[name]
        if name == "output":
            assert list(got) == [r[i] for r in rows]
        else:
            np.testing.assert_array_equal(got, np.array([float(r[i]) for r in rows]), err_msg=name)
    # the estimated scenario: the given one with the estimates set
    assert result.scenario.overrides == ["%s=%s" % h[:2] for h in header]


def test_quick_release_design_is_the_clis(tmp_path):
    scenario, series, parameters = quick_release_data_file()
    design = musclesim.identify_series(scenario, [series], parameters, design=True)
    out = cli("--design")
    assert out.returncode == 0, out.stderr
    assert design.report.split("\n", 1)[1] == out.stdout.split("\n", 1)[1]
    assert design.design and design.scenario is None
    assert design.estimates == {p["path"]: p["start"] for p in parameters}


# --- (b) independent checks: known parameters, finite differences ---------------------------

@pytest.mark.parametrize("noise", [{"length": 2e-5}, None])
def test_noise_free_data_give_back_the_parameters(noise):
    truth = release(**TRUTH).run()
    series = {"t": truth["t"], "length": truth["length"]}
    if noise:
        series["noise"] = noise
    result = musclesim.identify_series(
        release(), [series],
        [{"path": "model.f_iso", "start": 70.0, "bounds": [1.0, 1000.0]},
         {"path": "model.velocity.v_max", "start": 0.7}])
    assert result.converged and result.noise_given == bool(noise)
    # the data are exact to the integration tolerance (rtol 1e-10); the estimates' error is
    # that, amplified by the near-collinear columns (correlation about -0.98), about 1e-8
    # relative: 1e-6 leaves margin and still fails a fit stopped 30% off at its start
    assert result.estimates["model.f_iso"] == pytest.approx(TRUTH["f_iso"], rel=1e-6)
    assert result.estimates["model.velocity.v_max"] == pytest.approx(TRUTH["v_max"], rel=1e-6)
    assert [p.verdict for p in result.parameters] == ["identifiable", "identifiable"]


def finite_difference_jacobian(columns, steps):
    """d(columns)/d(f_iso, v_max) on the output grid by central differences, from runs of
    the scenario at p +- h (the first-order error O(h^2) cancels)."""
    base = {"f_iso": 100.0, "v_max": 1.0}
    jacobian = []
    for name, h in steps.items():
        up = release(**{**base, name: base[name] + h}).run()
        down = release(**{**base, name: base[name] - h}).run()
        jacobian.append(np.concatenate([(up[c] - down[c]) / (2 * h) for c in columns]))
    return np.array(jacobian).T


def test_design_standard_errors_match_finite_differences():
    noise = {"length": 2e-5, "shortening_velocity": 1e-3}  # m, m/s
    paths = ["model.f_iso", "model.velocity.v_max"]
    grid = musclesim.identify_series(release(), [{"noise": noise}], paths, design=True)
    # the same, measured at every other time of the grid, and twice (two series)
    times = release().run()["t"][::2]
    sparse = musclesim.identify_series(
        release(), [{"t": times, "noise": {"length": noise["length"]}},
                    {"t": times, "noise": {"shortening_velocity": noise["shortening_velocity"]}}],
        paths, design=True)

    jacobian = finite_difference_jacobian(list(noise), {"f_iso": 1e-2, "v_max": 1e-4})
    rows = len(jacobian) // 2
    weights = np.repeat([1 / noise["length"], 1 / noise["shortening_velocity"]], rows)
    every_other = np.concatenate([np.arange(0, rows, 2), rows + np.arange(0, rows, 2)])
    for result, keep in ((grid, slice(None)), (sparse, every_other)):
        weighted = weights[keep, None] * jacobian[keep]
        covariance = np.linalg.inv(weighted.T @ weighted)  # (J^T W J)^-1
        errors = np.sqrt(np.diag(covariance))
        # central differences at h = 1e-4 p: truncation ~h^2 ~ 1e-8 relative, integration
        # noise ~rtol / h ~ 1e-6; 1e-4 has margin and fails a wrong weight or column
        np.testing.assert_allclose([p.standard_error for p in result.parameters], errors,
                                   rtol=1e-4)
        np.testing.assert_allclose(result.correlation[0, 1],
                                   covariance[0, 1] / (errors[0] * errors[1]), atol=1e-4)
        assert result.values == len(weighted)


# --- (d) the estimated scenario runs to the fitted model ------------------------------------

def test_estimated_scenario_runs_to_the_fitted_model():
    # the data with a 50 N afterload; the scenario says 40 N and set() corrects it, as --set
    data = release(**TRUTH)
    data.set("load[0].after", 50.0)
    truth = data.run()
    scenario = copy.deepcopy(RELEASE)
    scenario["load"][0]["after"] = 40.0
    scenario = musclesim.scenario_from_dict(scenario, name="release.yaml")
    scenario.set("load[0].after", 50.0)
    result = musclesim.identify_series(
        scenario, [{"t": truth["t"], "length": truth["length"]}],
        [{"path": "model.f_iso", "start": 70.0}, "model.velocity.v_max"])
    assert result.converged
    assert result.estimates["model.f_iso"] == pytest.approx(TRUTH["f_iso"], rel=1e-6)  # as above
    assert result.scenario.overrides[0] == "load[0].after=50.0"
    run = result.scenario.run()
    at = np.searchsorted(run["t"], result.residuals["t"])
    np.testing.assert_array_equal(run["t"][at], result.residuals["t"])
    # two integrations at rtol 1e-10 of a 0.1 m length (one with sensitivities in its error
    # control): 1e-9 m is 100 times rtol * length, far below any noise worth fitting
    np.testing.assert_allclose(run["length"][at], result.residuals["model"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(result.residuals["residual"],
                               result.residuals["measured"] - result.residuals["model"],
                               rtol=0, atol=0)


def test_an_estimated_scenario_as_read_runs_to_the_fitted_model_not_the_one_read():
    # no set() before the fit: the scenario as read, whose runs use the system its reading
    # built; its estimate's runs must use the fitted values, as a scenario read with them does
    truth = release(**TRUTH).run()
    result = musclesim.identify_series(
        release(), [{"t": truth["t"], "length": truth["length"]}],
        [{"path": "model.f_iso", "start": 70.0}, "model.velocity.v_max"])
    fitted = release(f_iso=result.estimates["model.f_iso"],
                     v_max=result.estimates["model.velocity.v_max"])
    np.testing.assert_array_equal(result.scenario.run()["length"], fitted.run()["length"])
    assert np.abs(result.scenario.run()["length"] - release().run()["length"]).max() > 1e-4


# --- warnings: results kept, as the CLI writes them ------------------------------------------

def test_a_fit_out_of_evaluations_warns_and_returns():
    scenario, series, parameters = quick_release_data_file()
    with pytest.warns(RuntimeWarning, match="did not converge"):
        result = musclesim.identify_series(scenario, [series], parameters, max_evaluations=2)
    assert not result.converged and result.evaluations <= 2
    assert result.scenario is not None and len(result.residuals["t"]) == result.values


def test_noise_levels_far_too_small_warn():
    scenario, series, parameters = quick_release_data_file()
    series["noise"] = {"length": series["noise"]["length"] / 10}
    with pytest.warns(RuntimeWarning, match="far above the 1 the stated noise predicts"):
        result = musclesim.identify_series(scenario, [series], parameters)
    # a tenth of the noise the data carry: the mean square near 100, above the threshold 4
    assert result.weighted_rss / result.degrees_of_freedom > 4
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the stated noise: no warning
        series["noise"] = {"length": series["noise"]["length"] * 10}
        musclesim.identify_series(scenario, [series], parameters)


# --- inputs --------------------------------------------------------------------------------

class Columns:
    """A mapping that is not a dict, as a pandas DataFrame is: keys() and [column]."""

    def __init__(self, d):
        self.d = d

    def keys(self):
        return self.d.keys()

    def __getitem__(self, key):
        return list(self.d[key])  # a list, not an array


def test_series_as_any_mapping_of_sequences():
    truth = release(**TRUTH).run()
    paths = ["model.f_iso", "model.velocity.v_max"]
    plain = musclesim.identify_series(release(), [{"t": truth["t"], "length": truth["length"]}],
                                      paths)
    mapped = musclesim.identify_series(
        release(), [Columns({"t": truth["t"], "length": truth["length"]})], paths)
    assert mapped.estimates == plain.estimates  # the same values, the same computation


T = np.linspace(0.0, 0.2, 21)
GOOD = {"t": T, "length": 0.1 + 0.0 * T, "noise": {"length": 2e-5}}


def rejection(series=None, parameters=("model.f_iso",), design=False, scenario=None):
    with pytest.raises(musclesim.InputError) as error:
        musclesim.identify_series(scenario or release(), [GOOD] if series is None else series,
                                  list(parameters), design=design)
    return error.value


def test_bad_parameters_name_their_entry():
    e = rejection(parameters=["model.nope"])
    assert "parameters[0].path = model.nope in scenario release.yaml" in str(e)
    # the arguments are a document in memory, without lines: named, not located
    assert str(e).startswith("identify_series: parameters[0].path") and e.location is None
    e = rejection(parameters=[{"path": "model.f_iso", "bounds": [1000, 1]}])
    assert e.key == "parameters[0].bounds" and "lower < upper" in str(e)
    e = rejection(parameters=[{"path": "model.f_iso", "start": 2000, "bounds": [1, 1000]}])
    assert e.key == "parameters[0].start" and "must lie within bounds [1, 1000]" in str(e)
    e = rejection(parameters=[{"path": "model.f_iso", "bounds": [1, float("nan")]}])
    assert e.key == "parameters[0].bounds[1]" and "= .nan" in str(e)
    e = rejection(parameters=[{"path": "model.f_iso", "strat": 3}])
    assert e.key == "parameters[0].strat" and "unknown key" in str(e)
    e = rejection(parameters=["model.f_iso", "model.f_iso"])
    assert e.key == "parameters[1].path" and "listed twice" in str(e)


def test_bad_series_name_the_series_row_and_column():
    e = rejection([{"t": T[::-1], "length": GOOD["length"]}])
    assert e.key == "series[0]" and str(e).startswith("series[0] (row 2): t = 0.19 is not greater")
    e = rejection([GOOD, {"t": T, "length": np.where(T > 0.1, np.nan, 0.1)}])
    assert str(e) == "series[1] (row 12): length = nan: must be finite"
    e = rejection([{**GOOD, "noise": {"tension_total": 1.0}}])
    assert e.key == "series[0].noise.tension_total" and "has no column tension_total" in str(e)
    e = rejection([{"length": GOOD["length"]}])
    assert e.key == "series[0]" and "no column t" in str(e)
    e = rejection([{"t": T, "length": GOOD["length"][:-1]}])
    assert e.key == "series[0].length" and "has 20 values where t has 21" in str(e)
    e = rejection([{"t": T, "length": np.ones((21, 2))}])
    assert e.key == "series[0].length" and "1-D array" in str(e)
    e = rejection([{**GOOD, "noise": {"length": -1.0}}])
    assert e.key == "series[0].noise.length" and "must be > 0" in str(e)
    e = rejection([{"t": T + 1.0, "length": GOOD["length"]}])
    assert "series[0] (row 1): t = 1 lies outside the scenario's run, from 0 to 0.25 s" in str(e)
    e = rejection([{"t": T, "lengthh": GOOD["length"]}])
    assert "column lengthh is not an output the scenario's run differentiates" in str(e)
    e = rejection([{"t": T}], design=True)  # the design takes the columns from noise
    assert e.key == "series[0]" and "neither output columns nor noise levels" in str(e)
    e = rejection([{"t": T, "length": GOOD["length"]}], design=True)
    assert e.key == "series[0]" and "needs a noise level for column length" in str(e)
    e = rejection([{"noise": {"length": 1e-5}}])  # only the design does without values
    assert e.key == "series[0]" and "no column t" in str(e)
    e = rejection([])
    assert e.key == "series" and "one or more series" in str(e)


def test_wrong_types_raise_type_errors():
    with pytest.raises(TypeError, match="Scenario"):
        musclesim.identify_series(str(DATA), [GOOD], ["model.f_iso"])
    with pytest.raises(TypeError, match="list of series"):
        musclesim.identify_series(release(), GOOD, ["model.f_iso"])
    with pytest.raises(TypeError, match=r"series\[0\] must be a dict"):
        musclesim.identify_series(release(), [T], ["model.f_iso"])
    with pytest.raises(ValueError, match="max_evaluations"):
        musclesim.identify_series(release(), [GOOD], ["model.f_iso"], max_evaluations=0)
