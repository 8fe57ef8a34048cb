"""musclesim.identify_curves against independent computations: the `musclesim identify`
program run on the shipped data files (their CSVs read here with NumPy), curves generated
here from known parameters by the closed forms of docs/model.md (eqs. 1, 3-4 and 12), and the
program's own messages for the same bad data."""
import math
import os
import pathlib
import re
import subprocess

import numpy as np
import pytest

import musclesim as ms
from conftest import CLI, SOURCE

SOURCE_DIR = SOURCE

X_COLUMN = {"passive": "length", "active": "length", "velocity": "shortening_velocity"}


def read_curve_csv(path):
    """A CSV of `musclesim identify` as {column: float64 array}: '#' lines are comments."""
    lines = [line for line in pathlib.Path(path).read_text().splitlines()
             if line.strip() and not line.startswith("#")]
    names = lines[0].split(",")
    values = np.loadtxt(lines[1:], delimiter=",", ndmin=2)
    return {name: values[:, k] for k, name in enumerate(names)}


def read_data_file(path):
    """The shipped data files' one-line flow maps, `part: {csv: F, count: 3, ...}`, as dicts."""
    parts = {}
    for line in pathlib.Path(path).read_text().splitlines():
        match = re.match(r"^(passive|active|velocity):\s*\{(.*)\}\s*$", line)
        if match:
            entries = dict(item.split(":", 1) for item in match.group(2).split(","))
            parts[match.group(1)] = {k.strip(): v.strip() for k, v in entries.items()}
    assert parts, f"no curve read from {path}"
    for entry in parts.values():
        assert set(entry) <= {"csv", "count", "nonnegative", "f_iso"}, entry
    return parts


def arguments_of(name, as_dicts):
    """identify_curves' arguments for data/NAME.yaml: each curve as (x, tension) arrays, or
    as the dict of the CSV's columns."""
    arguments = {}
    for part, entry in read_data_file(SOURCE_DIR / "data" / f"{name}.yaml").items():
        columns = read_curve_csv(SOURCE_DIR / "data" / entry["csv"])
        arguments[part] = columns if as_dicts else (columns[X_COLUMN[part]], columns["tension"])
        if "count" in entry:
            arguments["active_count"] = int(entry["count"])
        if "nonnegative" in entry:
            arguments["nonnegative"] = entry["nonnegative"] == "true"
        if "f_iso" in entry:
            arguments["f_iso"] = float(entry["f_iso"])
    return arguments


def run_cli(*args, check=True):
    return subprocess.run([CLI, "identify", *args], cwd=SOURCE_DIR, capture_output=True,
                          text=True, check=check)


# --- (a) the program's model block, for each data set docs/guide/identification.md fits ---

@pytest.mark.parametrize("name,as_dicts", [("synthetic", True), ("ghj1966", False),
                                           ("hill", False), ("eccentric", False)])
def test_model_block_is_the_programs(name, as_dicts):
    result = ms.identify_curves(**arguments_of(name, as_dicts))
    ours = result.model_yaml.splitlines(keepends=True)
    theirs = run_cli(f"data/{name}.yaml").stdout.splitlines(keepends=True)
    # only the header's first line names the source
    assert theirs[0] == f"# identified by musclesim identify from data/{name}.yaml\n"
    assert ours[0] == "# identified by musclesim identify from Python arrays\n"
    assert ours[1:] == theirs[1:]


def test_source_names_the_header_and_nothing_else():
    result = ms.identify_curves(**arguments_of("hill", False), source="data/hill.yaml")
    assert result.model_yaml == run_cli("data/hill.yaml").stdout


def without_timings(report):
    """The report without its ns/eval column, the one thing measured rather than computed."""
    return [re.sub(r"\| [^|]* \|$", "|", line) if line.startswith("|") else line
            for line in report.splitlines()]


def test_report_is_the_programs_and_mentions_each_curve(tmp_path):
    result = ms.identify_curves(**arguments_of("synthetic", False), report=True)
    run_cli("data/synthetic.yaml", "--report", str(tmp_path / "report.md"))
    expected = (tmp_path / "report.md").read_text()
    assert without_timings(result.report) == without_timings(expected)
    for heading in ("## passive tension-length", "## active tension-length",
                    "## tension-velocity"):
        assert heading in result.report
    for model in ("exponential (eq. 1)", "3 Gaussians (eqs. 3-4)", "power law (eq. 12)"):
        assert f"| {model} |" in result.report
    assert ms.identify_curves(**arguments_of("hill", False)).report is None


# --- (b) parameters recovered from curves made here by the closed forms ------------------

K_P, ALPHA, SLACK = 2.0, 60.0, 0.1            # N, 1/m, m
F_ISO, WIDTH, CENTER = 80.0, 2500.0, 0.1      # N, 1/m^2, m: one Gaussian
V_F_ISO, V_MAX, N = 90.0, 1.5, 2              # N, m/s, -


def passive_closed_form(x, k_p, alpha, slack):
    """Eq. 1: k_p (exp(alpha (x - slack)) - 1) above the slack length, 0 below."""
    return np.where(x > slack, k_p * np.expm1(alpha * (x - slack)), 0.0)


def velocity_closed_form(v, f_iso, v_max, n):
    """Eq. 12 unregularised, v >= 0: f_iso (1 - (v / v_max)^(1/n))."""
    return f_iso * (1.0 - (v / v_max) ** (1.0 / n))


X_PASSIVE = np.linspace(0.08, 0.16, 33)       # m: 8 points at or below the slack length
X_ACTIVE = np.linspace(0.06, 0.14, 25)        # m: the Gaussian's center in the middle
V = np.linspace(0.0, 1.2, 13)                 # m/s: concentric only


@pytest.fixture(scope="module")
def closed_form_fit():
    # noise-free: the fits should meet the truth up to their solvers' tolerances
    return ms.identify_curves(
        passive=(X_PASSIVE, passive_closed_form(X_PASSIVE, K_P, ALPHA, SLACK)),
        active={"length": X_ACTIVE,
                "tension": F_ISO * np.exp(-WIDTH * (X_ACTIVE - CENTER) ** 2 / 2)},
        velocity=(V, velocity_closed_form(V, V_F_ISO, V_MAX, N)),
        active_count=1)


def test_noise_free_curves_give_back_their_parameters(closed_form_fit):
    p, a, v = closed_form_fit.passive, closed_form_fit.active, closed_form_fit.velocity
    # Levenberg-Marquardt from the profile's start converges to roundoff on exact data; 1e-9
    # leaves room for its stopping rule (relative steps of 1e-10 and below)
    assert p["k_p"][0] == pytest.approx(K_P, rel=1e-9)
    assert p["alpha"][0] == pytest.approx(ALPHA, rel=1e-9)
    assert p["slack_length"][0] == pytest.approx(SLACK, rel=1e-9)
    interval = p["slack_length_interval"]
    # the profile's interval holds the truth (to the same 1e-9 on its bisected ends)
    assert interval["low"] - 1e-9 <= SLACK <= interval["high"] + 1e-9
    assert p["points"] == X_PASSIVE.size

    # the closed-form Gaussian fit's multi-start minimisation stops at relative changes near
    # 1e-10 in the cost, which moves the width by about 1e-8 relatively: hence 1e-7
    assert a["f_iso"][0] == pytest.approx(F_ISO, rel=1e-7)
    assert len(a["widths"]) == len(a["centers"]) == len(a["amplitudes"]) == 1
    assert a["widths"][0][0] == pytest.approx(WIDTH, rel=1e-7)
    assert a["centers"][0][0] == pytest.approx(CENTER, rel=1e-7)
    # amplitudes are scaled so that max f_L = 1: a / sqrt(2 pi) = 1 for one Gaussian
    assert a["amplitudes"][0][0] == pytest.approx(math.sqrt(2 * math.pi), rel=1e-7)
    # optimal_range: where exp(-b (x - d)^2 / 2) >= 0.98, walked in steps of span / 4000 [m]
    half = math.sqrt(-2.0 * math.log(0.98) / WIDTH)
    step = (X_ACTIVE[-1] - X_ACTIVE[0]) / 4000
    assert a["optimal_range"][0] == pytest.approx(CENTER - half, abs=step)
    assert a["optimal_range"][1] == pytest.approx(CENTER + half, abs=step)

    # linear least squares in (f_iso, f_iso / v_max^(1/n)) at the right n: exact to roundoff
    assert v["n"] == N
    assert v["f_iso"][0] == pytest.approx(V_F_ISO, rel=1e-10)
    assert v["v_max"][0] == pytest.approx(V_MAX, rel=1e-10)
    assert v["eccentric"] is None
    assert [c["n"] for c in v["candidates"]] == list(range(1, 11))


def test_f_iso_held_by_the_argument_is_kept():
    v_fixed = ms.identify_curves(velocity=(V, velocity_closed_form(V, V_F_ISO, V_MAX, N)),
                                 f_iso=V_F_ISO).velocity
    assert v_fixed["f_iso"] == (V_F_ISO, 0.0)  # held, so no error of its own
    assert v_fixed["v_max"][0] == pytest.approx(V_MAX, rel=1e-10)  # roundoff, as above


def test_estimates_are_the_ones_the_block_comments_give(closed_form_fit):
    # the block writes each number in its shortest exact form, as Python's repr does
    text = closed_form_fit.model_yaml
    p, a, v = closed_form_fit.passive, closed_form_fit.active, closed_form_fit.velocity
    assert (f"k_p = {p['k_p'][0]!r} +- {p['k_p'][1]!r} N, alpha = {p['alpha'][0]!r} +- "
            f"{p['alpha'][1]!r} 1/m, slack_length = {p['slack_length'][0]!r} +- "
            f"{p['slack_length'][1]!r} m; RMSE {p['rmse']!r} N") in text
    assert (f"amplitude {a['amplitudes'][0][0]!r} +- {a['amplitudes'][0][1]!r}, width "
            f"{a['widths'][0][0]!r} +- {a['widths'][0][1]!r}, center {a['centers'][0][0]!r} "
            f"+- {a['centers'][0][1]!r}") in text
    assert f"f_iso: {a['f_iso'][0]:.17g}" in text
    assert f"v_max = {v['v_max'][0]!r} +- {v['v_max'][1]!r} m/s, RMSE {v['rmse']!r} N" in text


def test_eccentric_estimates_are_the_data_files_branch():
    # data/eccentric.yaml: v_max_e 0.5 m/s, n_e 2, limit 1.8 with 1 N noise (its comments)
    e = ms.identify_curves(**arguments_of("eccentric", False)).velocity["eccentric"]
    assert e["identified"] and e["limit_identified"] and e["in_model"]
    assert e["why_not"] is None and e["why_no_limit"] is None
    assert e["n"] == 2
    # the truth within three standard errors, as 1 N of noise on 20 points allows
    for key, truth in (("v_max", 0.5), ("limit", 1.8)):
        value, error = e[key]
        assert abs(value - truth) <= 3 * error, (key, value, error)


# --- (d) the returned model is the identified curves ---------------------------------------

def test_model_evaluates_the_identified_curves(closed_form_fit):
    model = closed_form_fit.model
    p, a, v = closed_form_fit.passive, closed_form_fit.active, closed_form_fit.velocity
    x = np.linspace(0.05, 0.17, 61)
    # the same formula in double precision: differences are roundoff in exp
    np.testing.assert_allclose(
        model.passive(x),
        passive_closed_form(x, p["k_p"][0], p["alpha"][0], p["slack_length"][0]),
        rtol=1e-13, atol=1e-13)

    f_iso = a["f_iso"][0]
    gaussians = sum(amp / math.sqrt(2 * math.pi) * np.exp(-b * (x - d) ** 2 / 2)
                    for (amp, _), (b, _), (d, _) in zip(a["amplitudes"], a["widths"],
                                                        a["centers"]))
    # the model divides by its own maximum over optimal_range, which the fit already made
    # 1 up to the maximiser's tolerance (a relative 1e-10 or better on a smooth peak)
    np.testing.assert_allclose(model.f_L(x), gaussians, rtol=1e-9, atol=1e-12)
    assert model.params["f_iso"] == f_iso  # the active fit's f_iso, read back exactly

    # eq. 12 with the epsilon regularisation (MODEL.md section 4), eps = 1e-3 v_max
    v_max, n = v["v_max"][0], v["n"]
    eps = 1e-3 * v_max
    speeds = np.linspace(-0.3, 1.4, 35)
    g_eps = 1 - speeds * (speeds ** 2 + eps ** 2) ** ((1 / n - 1) / 2) / v_max ** (1 / n)
    np.testing.assert_allclose(model.g(speeds), g_eps, rtol=1e-12, atol=1e-12)  # roundoff

    # T = T_p + u f_iso f_L g, u = 0.6
    tension = model.tension(x, 0.4, 0.6)
    g_at = 1 - 0.4 * (0.16 + eps ** 2) ** ((1 / n - 1) / 2) / v_max ** (1 / n)
    expected = (passive_closed_form(x, p["k_p"][0], p["alpha"][0], p["slack_length"][0])
                + 0.6 * f_iso * gaussians * g_at)
    np.testing.assert_allclose(tension, expected, rtol=1e-9, atol=1e-9)  # f_L's 1e-9, above


def test_model_of_a_part_without_data_is_the_stand_in():
    result = ms.identify_curves(passive=(X_PASSIVE, passive_closed_form(X_PASSIVE, K_P, ALPHA,
                                                                        SLACK)))
    assert result.active is None and result.velocity is None
    # no active data: f_iso 1 N and f_L flat (one Gaussian a kilometre wide); g close to 1
    assert result.params["f_iso"] == 1.0
    assert result.model.f_L(np.array([0.0, 0.1, 0.2])) == pytest.approx(1.0, abs=1e-6)
    assert result.model.g(0.5) == pytest.approx(1.0, abs=1e-5)  # (0.5 / 1e6 m/s): 5e-7


def test_result_is_read_only_and_says_what_it_holds(closed_form_fit):
    with pytest.raises(AttributeError):
        closed_form_fit.model = None
    assert repr(closed_form_fit) == "<musclesim.CurvesIdentification of passive, active, velocity>"


# --- (c) bad data: the argument and the row named, the program's words -------------------

def rising(n):
    return np.linspace(0.1, 0.2, n), np.linspace(1.0, 2.0, n)


def test_unsorted_duplicate_and_non_finite_rows_are_named():
    with pytest.raises(ms.InputError, match=re.escape(
            "passive: row 4: length = 0.12 is not greater than the row before (0.14): rows "
            "must be sorted by length, without duplicates")) as error:
        ms.identify_curves(passive=([0.1, 0.13, 0.14, 0.12, 0.15], [1.0, 2.0, 3.0, 4.0, 5.0]))
    # the argument is the key path; arrays have no file position
    assert error.value.key == "passive" and error.value.location is None
    with pytest.raises(ms.InputError, match=re.escape(
            "velocity: row 2: shortening_velocity = 0 is not greater than the row before (0)")):
        ms.identify_curves(velocity=([0.0, 0.0, 0.5], [100.0, 100.0, 40.0]))
    x, t = rising(10)
    t[4] = np.nan
    with pytest.raises(ms.InputError, match=re.escape(
            "active: row 5: length = 0.14444444444444446, tension = nan: values must be "
            "finite")):
        ms.identify_curves(active=(x, t))


def test_too_few_points_and_zero_tension_are_refused():
    with pytest.raises(ms.InputError, match="active: too few points: 9, need at least 10"):
        ms.identify_curves(active=rising(9))  # 3 Gaussians: 9 parameters
    with pytest.raises(ms.InputError, match="active: too few points: 6, need at least 7"):
        ms.identify_curves(active=rising(6), active_count=2)
    with pytest.raises(ms.InputError, match="passive: too few points: 3, need at least 4"):
        ms.identify_curves(passive=rising(3))
    with pytest.raises(ms.InputError, match="velocity: too few points: 2, need at least 3"):
        ms.identify_curves(velocity=([0.0, 0.5], [100.0, 40.0]))
    with pytest.raises(ms.InputError, match="passive: every tension is zero: nothing to fit"):
        ms.identify_curves(passive=(rising(5)[0], np.zeros(5)))


@pytest.mark.parametrize("kwargs,message", [
    ({"active_count": 0}, "active_count = 0: must be an integer from 1 to 12"),
    ({"active_count": 13}, "active_count = 13: must be an integer from 1 to 12"),
    ({"f_iso": -1.0}, "f_iso = -1: must be > 0 and <= 1e+09 [N]"),
    ({"f_iso": 2e9}, "f_iso = 2e+09: must be > 0 and <= 1e+09 [N]"),
    ({"f_iso": float("nan")}, "f_iso = nan: must be > 0"),
])
def test_options_outside_their_ranges_are_refused(kwargs, message):
    with pytest.raises(ms.InputError, match=re.escape(message)):
        ms.identify_curves(velocity=([0.0, 0.5, 1.0], [100.0, 40.0, 10.0]), **kwargs)


def test_malformed_curves_are_refused_naming_the_argument():
    with pytest.raises(ms.InputError, match="give at least one of passive, active, velocity"):
        ms.identify_curves()
    with pytest.raises(ms.InputError, match=re.escape(
            "active: 5 length values and 4 tension values: give one tension per length")):
        ms.identify_curves(active=(np.arange(5.0), np.ones(4)))
    with pytest.raises(ms.InputError, match="passive: length must be a 1-d sequence"):
        ms.identify_curves(passive=(np.ones((2, 3)), np.ones(6)))
    with pytest.raises(ms.InputError, match="velocity: no column shortening_velocity"):
        ms.identify_curves(velocity={"length": [0.0, 1.0, 2.0], "tension": [3.0, 2.0, 1.0]})
    with pytest.raises(ms.InputError, match=r"passive: give a pair \(length, tension\)"):
        ms.identify_curves(passive=(np.arange(4.0),))
    with pytest.raises(ms.InputError, match="active: tension must be a 1-d sequence of numbers"):
        ms.identify_curves(active=(np.arange(4.0), ["a", "b", "c", "d"]))


@pytest.mark.parametrize("rows,at_line,at_row", [
    ("0.1,1\n0.3,2\n0.2,3\n0.4,4\n0.5,5\n", 4, 3),        # unsorted
    ("0.1,1\n0.2,2\n0.3,nan\n0.4,4\n", 4, 3),             # not finite
])
def test_a_bad_row_is_refused_in_the_programs_words(tmp_path, rows, at_line, at_row):
    (tmp_path / "p.csv").write_text("length,tension\n" + rows)
    (tmp_path / "d.yaml").write_text("passive: {csv: p.csv}\n")
    program = run_cli(str(tmp_path / "d.yaml"), check=False)
    assert program.returncode == 2  # an input error
    columns = read_curve_csv(tmp_path / "p.csv")
    with pytest.raises(ms.InputError) as raised:
        ms.identify_curves(passive=(columns["length"], columns["tension"]))
    ours = str(raised.value)
    prefix = f"passive: row {at_row}: "
    assert ours.startswith(prefix)
    # the program names file:line where we name the argument and row; the rule is the same
    assert f"p.csv:{at_line}: {ours[len(prefix):]}" in program.stderr


# --- the forms a curve may take -------------------------------------------------------------

class FrameLike:
    """What identify_curves uses of a pandas DataFrame: keys() and columns by name."""

    def __init__(self, columns):
        self._columns = columns

    def keys(self):
        return list(self._columns)

    def __getitem__(self, name):
        return self._columns[name]


def test_pairs_dicts_and_frames_give_the_same_fit():
    x, t = X_PASSIVE, passive_closed_form(X_PASSIVE, K_P, ALPHA, SLACK)
    forms = [(x, t), [list(x), list(t)], np.vstack([x, t]), {"length": x, "tension": t},
             FrameLike({"length": x, "tension": t, "other": t})]
    texts = {ms.identify_curves(passive=form).model_yaml for form in forms}
    assert len(texts) == 1


def test_a_pandas_data_frame_is_read_by_its_columns():
    import pandas as pd  # a test dependency (scripts/install-deps.sh), not the module's
    x, t = X_PASSIVE, passive_closed_form(X_PASSIVE, K_P, ALPHA, SLACK)
    frame = pd.DataFrame({"length": x, "tension": t})
    assert (ms.identify_curves(passive=frame).model_yaml
            == ms.identify_curves(passive=(x, t)).model_yaml)


def test_a_column_of_a_two_dimensional_array_is_read_in_order():
    # columns of a C-ordered table are strided views: their values, not the memory beside
    table = np.column_stack([X_PASSIVE, passive_closed_form(X_PASSIVE, K_P, ALPHA, SLACK)])
    assert (ms.identify_curves(passive=(table[:, 0], table[:, 1])).model_yaml
            == ms.identify_curves(passive=(table[:, 0].copy(), table[:, 1].copy())).model_yaml)


def test_the_report_at_the_fewest_points_notes_the_reference_it_cannot_fit():
    # 4 passive points: the exponential (3 parameters) fits, a quartic (5 coefficients)
    # cannot; the report leaves that row out and says so, where it used to fail
    x = np.array([0.11, 0.12, 0.13, 0.14])
    found = ms.identify_curves(passive=(x, np.expm1(100.0 * (x - 0.105))), report=True)
    assert "| exponential (eq. 1) |" in found.report
    assert "| polynomial, degree 4 |" not in found.report
    assert "polynomial, degree 4: not fitted (a polynomial of degree 4 needs more than 4 points)" \
        in found.report
