"""musclesim.Model, load_model and fit_gaussians against independent computations: the CLI's
`curves` tables, a NumPy re-implementation of docs/model.md's equations, central finite
differences, and the fit's cost recomputed by quadrature."""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import musclesim as ms
from conftest import CLI, SOURCE

# the trapezoidal rule: numpy.trapezoid from NumPy 2 (numpy.trapz before, removed in 2.0)
trapezoid = getattr(np, "trapezoid", None) or np.trapz

SOURCE_DIR = SOURCE

# Without the errors binding, InputError is a RuntimeError and ParameterError a ValueError.
INPUT_ERROR = getattr(ms, "InputError", RuntimeError)
PARAMETER_ERROR = getattr(ms, "ParameterError", ValueError)

MODEL = {
    "f_iso": 50.0,
    "passive": {"k_p": 2.0, "alpha": 80.0, "slack_length": 0.1},
    "active_length": {
        "optimal_range": [0.09, 0.11],
        "gaussians": [
            {"amplitude": 1.5, "width": 3000.0, "center": 0.1},
            {"amplitude": 0.4, "width": 12000.0, "center": 0.075},
        ],
    },
    "velocity": {"v_max": 0.8, "n": 3, "epsilon": 1e-3},
}

ECCENTRIC = json.loads(json.dumps(MODEL))
ECCENTRIC["velocity"]["eccentric"] = {"v_max": 0.5, "n": 2, "limit": 1.6}


# --- NumPy re-implementation of docs/model.md (sections 2-5, 9) -----------------------------

def ref_passive(p, x):
    q = p["passive"]
    return np.where(x > q["slack_length"],
                    q["k_p"] * (np.exp(q["alpha"] * (x - q["slack_length"])) - 1.0), 0.0)


def ref_sum(p, x):
    a = p["active_length"]
    sigma = a.get("sigma", 1.0)
    return sum(g["amplitude"] / np.sqrt(2 * np.pi * sigma)
               * np.exp(-g["width"] * (x - g["center"]) ** 2 / (2 * sigma))
               for g in a["gaussians"])


def ref_f_L(p, x):
    l1, l2 = p["active_length"]["optimal_range"]
    # the peak on L_opt from a grid of 2e5 cells: the grid misses the true maximum by at most
    # f'' h^2 / 8, a relative 1e-12 here (b = 12000 / m^2, h = 1e-7 m)
    peak = ref_sum(p, np.linspace(l1, l2, 200001)).max()
    return ref_sum(p, x) / peak


def ref_g(p, v):
    vel = p["velocity"]
    eps = vel["epsilon"]

    def phi(v, n):
        return v * (v * v + eps * eps) ** ((1.0 / n - 1.0) / 2.0)

    g = 1.0 - phi(v, vel["n"]) / vel["v_max"] ** (1.0 / vel["n"])
    ecc = vel.get("eccentric")
    if ecc:
        n_e, v_e = ecc.get("n", vel["n"]), ecc.get("v_max", vel["v_max"])
        psi = -phi(v, n_e) / v_e ** (1.0 / n_e)
        if "limit" in ecc:
            head = ecc["limit"] - 1.0
            lengthening = 1.0 + head * np.tanh(psi / head)
        else:
            lengthening = 1.0 + psi
        g = np.where(v < 0, lengthening, g)
    return g


def ref_tension(p, x, v, u):
    return ref_passive(p, x) + u * p["f_iso"] * ref_f_L(p, x) * ref_g(p, v)


# --- curves ----------------------------------------------------------------------------------

@pytest.mark.parametrize("params", [MODEL, ECCENTRIC], ids=["symmetric", "eccentric"])
def test_tension_matches_numpy_reimplementation(params):
    model = ms.Model(params)
    rng = np.random.default_rng(1)
    x = rng.uniform(0.05, 0.14, 500)
    v = rng.uniform(-1.0, 1.0, 500)
    u = rng.uniform(0.0, 1.0, 500)
    parts = model.tension_parts(x, v, u)
    # same formulas in another order (pow vs **, the peak found differently): a few ulps of
    # the largest term, plus the 1e-12 of the grid peak
    np.testing.assert_allclose(parts["total"], ref_tension(params, x, v, u), rtol=1e-10,
                               atol=1e-10)
    np.testing.assert_allclose(parts["passive"], ref_passive(params, x), rtol=1e-12, atol=0)
    np.testing.assert_allclose(model.passive(x), ref_passive(params, x), rtol=1e-12, atol=0)
    np.testing.assert_allclose(model.f_L(x), ref_f_L(params, x), rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(model.g(v), ref_g(params, v), rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(parts["active"], parts["total"] - parts["passive"], rtol=1e-12,
                               atol=1e-12)


def test_curves_match_the_cli(tmp_path):
    # a model file as the CLI reads it (JSON is YAML)
    path = tmp_path / "model.yaml"
    path.write_text(json.dumps({"name": "t", "model": ECCENTRIC}))
    model = ms.load_model(str(path))
    length = subprocess.run([CLI, "curves", str(path), "--length", "0.05:0.15:101"],
                            check=True, capture_output=True, text=True).stdout
    table = np.genfromtxt(length.splitlines(), delimiter=",", names=True)
    # the CLI prints 17 significant digits of the same double: equal to a roundoff
    np.testing.assert_allclose(model.f_L(table["length"]), table["f_L"], rtol=1e-15, atol=0)
    np.testing.assert_allclose(model.passive(table["length"]), table["tension_passive"],
                               rtol=1e-15, atol=0)
    velocity = subprocess.run([CLI, "curves", str(path), "--velocity", "-2:1:61"],
                              check=True, capture_output=True, text=True).stdout
    table = np.genfromtxt(velocity.splitlines(), delimiter=",", names=True)
    np.testing.assert_allclose(model.g(table["shortening_velocity"]), table["g"], rtol=1e-15,
                               atol=1e-16)


@pytest.mark.parametrize("params", [MODEL, ECCENTRIC], ids=["symmetric", "eccentric"])
def test_derivatives_match_central_differences(params):
    model = ms.Model(params)
    rng = np.random.default_rng(2)
    # away from the passive kink at slack_length (0.1) and the eccentric kink at v = 0
    x = np.concatenate([rng.uniform(0.06, 0.099, 50), rng.uniform(0.101, 0.13, 50)])
    v = np.concatenate([rng.uniform(-1.0, -0.01, 50), rng.uniform(0.01, 1.0, 50)])
    u = rng.uniform(0.1, 1.0, 100)
    parts = model.tension_parts(x, v, u)
    # central differences: truncation h^2 f'''/6 against roundoff eps |T| / h; h = 1e-6 m
    # (m/s) gives both near 1e-7 relative for curves varying on millimetres
    h = 1e-6
    fd_x = (model.tension(x + h, v, u) - model.tension(x - h, v, u)) / (2 * h)
    fd_v = (model.tension(x, v + h, u) - model.tension(x, v - h, u)) / (2 * h)
    fd_u = (model.tension(x, v, u + h) - model.tension(x, v, u - h)) / (2 * h)
    np.testing.assert_allclose(parts["d_length"], fd_x, rtol=1e-6, atol=1e-5)
    np.testing.assert_allclose(parts["d_velocity"], fd_v, rtol=1e-6, atol=1e-5)
    # T is linear in u: only roundoff, eps |T| / h ~ 1e-8 N
    np.testing.assert_allclose(parts["d_activation"], fd_u, rtol=1e-7, atol=1e-7)
    np.testing.assert_allclose(model.f_L_slope(x),
                               (model.f_L(x + h) - model.f_L(x - h)) / (2 * h), rtol=1e-6,
                               atol=1e-6)
    np.testing.assert_allclose(model.g_slope(v), (model.g(v + h) - model.g(v - h)) / (2 * h),
                               rtol=1e-6, atol=1e-6)


def test_broadcasting_shapes_and_dtypes():
    model = ms.Model(MODEL)
    x = np.linspace(0.08, 0.12, 4).reshape(4, 1)
    v = np.array([0.0, 0.1, -0.1])
    parts = model.tension_parts(x, v, 0.5)
    for key in ("total", "passive", "active", "d_length", "d_velocity", "d_activation"):
        assert parts[key].shape == (4, 3) and parts[key].dtype == np.float64
    # each element is the scalar evaluation at its broadcast coordinates
    assert parts["total"][2, 1] == model.tension(x[2, 0], v[1], 0.5)
    # integer and list inputs are converted to float64
    assert model.tension([1, 0], 0, 1).dtype == np.float64
    assert model.f_L(np.zeros((2, 0))).shape == (2, 0)
    with pytest.raises(ValueError):
        model.tension(np.zeros(3), np.zeros(2), 1.0)  # shapes that do not broadcast


def test_scalars_give_numpy_float64():
    model = ms.Model(MODEL)
    t = model.tension(0.1, 0.0, 1.0)
    # documented: scalar (or 0-d) arguments give a numpy.float64, a subclass of float
    assert type(t) is np.float64 and isinstance(t, float)
    # at optimal length-ish and rest: the isometric tension times f_L there
    assert t == pytest.approx(MODEL["f_iso"] * ref_f_L(MODEL, 0.1), rel=1e-10)
    assert type(model.tension_parts(np.array(0.1), 0.0, 1.0)["d_length"]) is np.float64
    assert type(model.g(0.2)) is np.float64


def test_large_arrays_agree_with_small_ones():
    model = ms.Model(MODEL)
    x = np.linspace(0.05, 0.15, 100000)
    big = model.tension(x, 0.05, 0.7)
    # above the GIL-release threshold the same loop runs: equal to a small evaluation
    assert big[12345] == model.tension(x[12345], 0.05, 0.7)


def test_params_round_trip():
    model = ms.Model(ECCENTRIC)
    params = model.params
    assert params["velocity"]["eccentric"] == ECCENTRIC["velocity"]["eccentric"]
    assert params["active_length"]["gaussians"] == ECCENTRIC["active_length"]["gaussians"]
    again = ms.Model(params)
    x = np.linspace(0.05, 0.15, 50)
    v = np.linspace(-1, 1, 50)
    assert np.array_equal(again.tension(x, v, 0.6), model.tension(x, v, 0.6))
    assert again.params == params
    # NumPy scalars and arrays in the dict are accepted
    params["f_iso"] = np.float64(50.0)
    params["active_length"]["optimal_range"] = np.array([0.09, 0.11])
    assert np.array_equal(ms.Model(params).tension(x, v, 0.6), model.tension(x, v, 0.6))


def test_load_model_reads_a_scenario():
    model = ms.load_model(str(SOURCE_DIR / "scenarios" / "isometric.yaml"))
    # isometric.yaml: f_iso 100 N, optimal_range [0.095, 0.105]; f_L peaks at 1 on it
    assert model.params["f_iso"] == 100.0
    assert model.f_L(model.optimal_length) == 1.0
    assert 0.095 <= model.optimal_length <= 0.105
    assert model.fit_result is None


def test_a_block_asking_for_a_fit_runs_it():
    params = json.loads(json.dumps(MODEL))
    params["active_length"] = {"optimal_range": [0.09, 0.11],
                               "fit": {"count": 2, "target": "indicator"}}
    model = ms.Model(params)
    fit = ms.fit_gaussians(n=2, target="indicator", optimal_range=(0.09, 0.11))
    # the same deterministic fit, bit for bit
    assert np.array_equal(model.fit_result["amplitudes"], fit["amplitudes"])
    assert model.params["active_length"]["gaussians"] == fit["gaussians"]


@pytest.mark.parametrize("change, error, message", [
    (lambda p: p.update(f_iso=-1.0), INPUT_ERROR, "f_iso"),
    (lambda p: p["velocity"].update(n=2.5), INPUT_ERROR, "model.velocity.n"),
    (lambda p: p["passive"].pop("alpha"), INPUT_ERROR, "model.passive.alpha"),
    (lambda p: p["velocity"].update(typo=1), INPUT_ERROR, "typo"),
    (lambda p: p["active_length"]["gaussians"][0].update(width=-3), INPUT_ERROR,
     r"gaussians\[0\]\.width"),
])
def test_bad_model_dicts_raise_the_readers_errors(change, error, message):
    params = json.loads(json.dumps(MODEL))
    change(params)
    with pytest.raises(error, match=message) as info:
        ms.Model(params)
    assert "(<model dict>)" in str(info.value)  # named like a file, without lines


def test_bad_model_files_name_the_file(tmp_path):
    path = tmp_path / "bad.yaml"
    params = json.loads(json.dumps(MODEL))
    params["velocity"]["v_max"] = 0.0
    path.write_text(json.dumps({"name": "t", "model": params}))
    with pytest.raises(INPUT_ERROR, match=r"model\.velocity\.v_max = 0\.0 \(.*bad\.yaml:1:"):
        ms.load_model(str(path))


# --- fit -------------------------------------------------------------------------------------

def gaussians(x, a, b, d, sigma=1.0):
    return sum(ak / np.sqrt(2 * np.pi * sigma) * np.exp(-bk * (x - dk) ** 2 / (2 * sigma))
               for ak, bk, dk in zip(a, b, d))


def test_fit_recovers_known_gaussians_from_samples():
    a, b, d = [1.2, 0.5], [4000.0, 9000.0], [0.1, 0.13]
    x = np.linspace(0.05, 0.18, 200)
    fit = ms.fit_gaussians(x, gaussians(x, a, b, d), n=2)
    order = np.argsort(fit["centers"])
    # noise-free data the model can fit exactly: the minimiser stops at a gradient tolerance,
    # so the parameters agree to about the square root of the cost's roundoff
    np.testing.assert_allclose(fit["amplitudes"][order], a, rtol=1e-5)
    np.testing.assert_allclose(fit["widths"][order], b, rtol=1e-5)
    np.testing.assert_allclose(fit["centers"][order], d, rtol=1e-6)
    assert fit["cost"] < 1e-12  # against sum y^2 ~ 100
    # the cost as the samples target defines it: the sum of squared differences
    recomputed = np.sum((gaussians(x, fit["amplitudes"], fit["widths"], fit["centers"])
                         - gaussians(x, a, b, d)) ** 2)
    assert fit["cost"] == pytest.approx(recomputed, rel=1e-3, abs=1e-20)


def test_fit_with_fixed_shapes_solves_the_amplitudes_exactly():
    a, b, d = [0.8, -0.3, 0.6], [5000.0, 5000.0, 5000.0], [0.08, 0.1, 0.12]
    x = np.linspace(0.05, 0.15, 40)
    fit = ms.fit_gaussians(x, gaussians(x, a, b, d), n=3, widths=b, centers=d)
    # a linear least-squares solve of an exactly representable target: roundoff of the
    # normal equations, condition number ~1e3
    np.testing.assert_allclose(fit["amplitudes"], a, rtol=1e-9)
    assert fit["iterations"] == 0


def test_polygon_fit_cost_equals_the_integral_of_the_squared_difference():
    xp = np.array([0.06, 0.09, 0.11, 0.16])
    yp = np.array([0.0, 1.0, 1.0, 0.0])
    fit = ms.fit_gaussians(xp, yp, n=3, target="polygon", nonnegative=True)
    assert np.all(fit["amplitudes"] >= 0)
    # trapezoid over a range where the Gaussians have decayed (1e-7 m steps; the integrand is
    # smooth between the polygon's vertices, which lie on the grid): error ~ h^2 -> 1e-9 rel
    x = np.linspace(0.0, 0.25, 2500001)
    diff = gaussians(x, fit["amplitudes"], fit["widths"], fit["centers"]) - np.interp(
        x, xp, yp, left=0.0, right=0.0)
    recomputed = trapezoid(diff ** 2, x)
    assert fit["cost"] == pytest.approx(recomputed, rel=1e-6)
    norm = trapezoid(np.interp(x, xp, yp, left=0.0, right=0.0) ** 2, x)
    assert fit["relative_residual"] == pytest.approx(recomputed / norm, rel=1e-6)


def test_preset_fit_cost_equals_the_integral_against_the_cli_curve(tmp_path):
    fit = ms.fit_gaussians(n=3, preset="gordon1966", optimal_length=0.1)
    # the preset tabulated by the CLI on a fine grid: gordon1966 is piecewise linear with
    # its kinks on this grid's 1e-5 m steps (normalised 1e-4), so the trapezoid of the
    # squared difference is accurate to ~h^2 f'' -> 1e-6 relative
    out = subprocess.run([CLI, "curves", "--preset", "gordon1966", "--optimal-length", "0.1",
                          "--length", "0:0.3:30001"], check=True, capture_output=True,
                         text=True).stdout
    table = np.genfromtxt(out.splitlines(), delimiter=",", names=True)
    x = table["length"]
    diff = gaussians(x, fit["amplitudes"], fit["widths"], fit["centers"]) - table["f_L"]
    assert fit["cost"] == pytest.approx(trapezoid(diff ** 2, x), rel=1e-5)


def test_bad_fit_arguments_raise():
    x = np.linspace(0.0, 1.0, 5)
    with pytest.raises(PARAMETER_ERROR, match="count"):
        ms.fit_gaussians(x, x, n=13)
    with pytest.raises(PARAMETER_ERROR, match="samples need at least 9"):
        ms.fit_gaussians(x, x, n=3)
    with pytest.raises(PARAMETER_ERROR, match="must be one of"):
        ms.fit_gaussians(preset="nope")
    with pytest.raises(PARAMETER_ERROR, match=r"points\[1\]\[0\]"):
        ms.fit_gaussians([0.0, 2e3], [0.0, 1.0], n=1, target="polygon")
    with pytest.raises(ValueError, match="optimal_range"):
        ms.fit_gaussians(n=2, target="indicator")
    with pytest.raises(ValueError, match="same length"):
        ms.fit_gaussians(x, x[:3], n=1)


def test_an_activation_outside_0_1_is_refused():
    model = ms.Model(MODEL)
    for u in (1.5, -0.1, float("nan")):
        with pytest.raises(ms.ParameterError) as error:
            model.tension(0.1, 0.0, np.array([0.5, u]))
        assert error.value.path == "u" and "[0, 1]" in error.value.rule
    # the ends are activations: u = 0 leaves the passive tension alone
    assert model.tension(0.12, 0.0, 0.0) == model.passive(0.12)


@pytest.mark.parametrize("preset", ["degroote2016", "thelen2003", "gordon1966", "mujoco"])
def test_force_length_presets_equal_the_programs_table(preset, tmp_path):
    csv = tmp_path / "preset.csv"
    subprocess.run([CLI, "curves", "--preset", preset, "--optimal-length",
                    "0.1", "--length", "0:0.2:41", "-o", str(csv)], check=True)
    table = np.loadtxt(csv, delimiter=",", skiprows=1)
    # the same evaluation, printed with 17 significant digits: equal to the last bit
    np.testing.assert_array_equal(ms.force_length_preset(preset, table[:, 0], 0.1), table[:, 2])
    with pytest.raises(ms.ParameterError, match="preset = nope"):
        ms.force_length_preset("nope", 0.1)


# OpenSim's DeGrooteFregly2016Muscle written out again in NumPy from bench/peers/README.md
# (its constants as OpenSim 4.6 has them); velocity positive lengthening there
DEGROOTE_TERMS = [
    (0.8150671134243542, 1.055033428970575, 0.162384573599574, 0.063303448465465),
    (0.433004984392647, 0.716775413397760, -0.029947116970696, 0.200356847296188),
    (0.1, 1.0, 0.353553390593274, 0.0),
]


def degroote_tension(x, v, u, f_iso, l_opt, v_max, damping):
    lm = x / l_opt
    vm = -v / (v_max * l_opt)
    active = sum(b1 * np.exp(-0.5 * (lm - b2) ** 2 / (b3 + b4 * lm) ** 2)
                 for b1, b2, b3, b4 in DEGROOTE_TERMS)
    offset = np.exp(4.0 * (0.2 - 1.0) / 0.6)
    passive = (np.exp(4.0 * (lm - 1.0) / 0.6) - offset) / (np.exp(4.0) - offset)
    f_v = -0.3211346127989808 * np.arcsinh(-8.149 * vm - 0.374) + 0.8825327733249912
    return f_iso * (u * active * f_v + passive + damping * vm)


def test_params_hold_every_key_of_the_block_with_its_default_and_only_given_optional_ones():
    # the dict is the block as the reader completes it: defaults filled in, integers as ints,
    # an eccentric key only where the block gives one
    params = ms.Model(MODEL).params
    assert params["pennation_angle"] == 0.0
    assert params["active_length"]["sigma"] == 1.0
    assert type(params["velocity"]["n"]) is int and params["velocity"]["n"] == MODEL["velocity"]["n"]
    assert "eccentric" not in params["velocity"]
    partial = json.loads(json.dumps(MODEL))
    partial["velocity"]["eccentric"] = {"n": 2}
    assert ms.Model(partial).params["velocity"]["eccentric"] == {"n": 2}
    degroote = ms.Model({"family": "degroote2016", "f_iso": 400.0,
                         "optimal_fiber_length": 0.1}).params
    # OpenSim's defaults, as the reader fills them in
    assert degroote == {"family": "degroote2016", "f_iso": 400.0, "pennation_angle": 0.0,
                        "optimal_fiber_length": 0.1, "max_contraction_velocity": 10.0,
                        "active_force_width_scale": 1.0,
                        "passive_fiber_strain_at_one_norm_force": 0.6, "fiber_damping": 0.0}


def test_a_family_model_round_trips_and_evaluates_its_tools_curves():
    block = {"family": "degroote2016", "f_iso": 400.0, "optimal_fiber_length": 0.1,
             "max_contraction_velocity": 10.0, "fiber_damping": 0.02}
    model = ms.Model(block)
    x = np.linspace(0.06, 0.14, 17)
    v = np.linspace(-0.8, 0.8, 17)
    expected = degroote_tension(x, v, 0.7, 400.0, 0.1, 10.0, 0.02)
    assert np.allclose(model.tension(x, v, 0.7), expected, rtol=1e-13, atol=1e-11)
    assert model.optimal_length == 0.1
    again = ms.Model(model.params)
    assert again.params == model.params
    assert np.array_equal(again.tension(x, v, 0.7), model.tension(x, v, 0.7))
    mujoco = ms.Model({"family": "mujoco", "f_iso": 200.0, "lengthrange": [0.05, 0.25]})
    # the optimal length is where MuJoCo's normalised length is 1: 0.05 + 0.25 L0
    assert mujoco.optimal_length == pytest.approx(0.05 + 0.25 * 0.2 / 0.3, rel=1e-15)
    assert mujoco.f_L(mujoco.optimal_length) == pytest.approx(1.0, rel=1e-15)


def test_a_family_refuses_another_familys_keys():
    with pytest.raises(INPUT_ERROR, match="model.v_max.*unknown key"):
        ms.Model({"family": "degroote2016", "f_iso": 1.0, "optimal_fiber_length": 0.1,
                  "v_max": 2.0})
    with pytest.raises(INPUT_ERROR, match="must be paper, degroote2016 or mujoco"):
        ms.Model({"family": "thelen2003", "f_iso": 1.0})
