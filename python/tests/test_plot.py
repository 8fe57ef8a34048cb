"""musclesim.plot: the figures of `musclesim plot`, from results in memory.

Each figure's gnuplot script (written with script=...) is compared with the one the CLI writes
with --script for the CSV the CLI itself writes of the same data: equal scripts draw equal
figures, and the CLI's CSV goes through its own writer and reader, independent of the
columns' conversion here.
"""
import json
import os
import subprocess

import numpy as np
import pytest

import musclesim
from conftest import CLI, SOURCE

SCENARIOS = os.path.join(SOURCE, "scenarios")
DATA = os.path.join(SOURCE, "data")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
TITLE = "same title"  # given to both, so that no line names a file


def cli(*args):
    out = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return out


def clis_script(tmp_path, *plot_args, title=TITLE):
    """The script of `musclesim plot ... --script`."""
    title_args = ["--title", title] if title is not None else []
    cli("plot", *plot_args, "-o", tmp_path / "cli.png", "--script", tmp_path / "cli.gp",
        *title_args)
    return (tmp_path / "cli.gp").read_text()


def our_script(tmp_path, data, title=TITLE, **options):
    """The script of musclesim.plot, whose PNG must be there too."""
    figure = tmp_path / "ours.png"
    assert musclesim.plot(data, figure, title=title, script=tmp_path / "ours.gp",
                          **options) == str(figure)
    assert figure.read_bytes()[:8] == PNG_SIGNATURE
    return (tmp_path / "ours.gp").read_text()


def data_block_rows(script, name):
    """The rows of the inline data block `$name << EOD` as a float array."""
    block = script.split("$%s << EOD\n" % name, 1)[1].split("EOD\n", 1)[0]
    return np.array([[float(v) for v in line.split()] for line in block.splitlines()])


# --- (a) trajectories, sweeps and residuals: the CLI's scripts ---------------------------------

def test_trajectory_is_the_clis(tmp_path):
    path = os.path.join(SCENARIOS, "concentric.yaml")
    cli("run", path, "--set", "time.end=0.1", "-o", tmp_path / "run.csv")
    result = musclesim.load_scenario(path, {"time.end": 0.1}).run()
    ours = our_script(tmp_path, result)
    assert ours == clis_script(tmp_path, tmp_path / "run.csv")
    # the data drawn are the run's columns (t, length, ... in the builder's order)
    rows = data_block_rows(ours, "trajectory")
    np.testing.assert_array_equal(rows[:, 0], result.columns["t"])
    np.testing.assert_array_equal(rows[:, 1], result.columns["length"])
    # with no title, only the title line differs: the CLI names its CSV, plot the kind
    default = our_script(tmp_path, result, title=None).splitlines()
    cli_default = clis_script(tmp_path, tmp_path / "run.csv", title=None).splitlines()
    differing = [(a, b) for a, b in zip(default, cli_default) if a != b]
    assert len(default) == len(cli_default) and len(differing) == 1
    assert differing[0][0] == "set multiplot layout 4,1 title 'trajectory'"
    assert str(tmp_path / "run.csv") in differing[0][1]


def test_network_trajectory_is_the_clis(tmp_path):
    path = os.path.join(SCENARIOS, "force_regulation.yaml")
    cli("run", path, "-o", tmp_path / "run.csv")
    ours = our_script(tmp_path, musclesim.load_scenario(path).run())
    assert ours == clis_script(tmp_path, tmp_path / "run.csv")
    assert "set multiplot" in ours and "measured" in ours  # the network's figure, a controller


@pytest.mark.parametrize("name", ["planar_pendulum", "suspended_mass"])
def test_a_spatial_networks_paths_are_the_clis(tmp_path, name):
    # a network in the plane: its nodes' paths beside the elements' panels, as the CLI draws
    path = os.path.join(SCENARIOS, name + ".yaml")
    cli("run", path, "--set", "time.end=0.2", "-o", tmp_path / "run.csv")
    ours = our_script(tmp_path, musclesim.load_scenario(path, {"time.end": 0.2}).run())
    assert ours == clis_script(tmp_path, tmp_path / "run.csv")


@pytest.mark.parametrize("frames", [{"frame_count": 3}, {"frames": [0.0, 0.05, 0.1]}])
def test_a_spatial_networks_frames_are_the_clis(tmp_path, frames):
    path = os.path.join(SCENARIOS, "planar_pendulum.yaml")
    cli("run", path, "--set", "time.end=0.1", "-o", tmp_path / "run.csv")
    scenario = musclesim.load_scenario(path, {"time.end": 0.1})
    ours = our_script(tmp_path, scenario.run(), scenario=scenario, **frames)
    flag = (["--frame-count", "3"] if "frame_count" in frames else ["--frames", "0,0.05,0.1"])
    assert ours == clis_script(tmp_path, tmp_path / "run.csv", *flag, "--scenario", path)


def test_frames_of_a_run_on_a_line_are_refused_as_the_cli_refuses_them(tmp_path):
    result = musclesim.load_scenario(os.path.join(SCENARIOS, "antagonist_pair.yaml"),
                                     {"time.end": 0.05}).run()
    with pytest.raises(musclesim.InputError, match="not the run of a network in the plane"):
        musclesim.plot(result, tmp_path / "f.png", frame_count=2)
    with pytest.raises(musclesim.InputError, match="frames .*or frame_count"):
        musclesim.plot(result, tmp_path / "f.png", frames=[0.0], frame_count=2)


SWEEP = {
    "mode": "grid",
    "parameters": {"load[0].after": {"from": 20.0, "to": 60.0, "count": 3},  # N
                   "model.f_iso": {"from": 80.0, "to": 100.0, "count": 2}},   # N
    "metrics": ["mean_shortening_velocity", "final_length"],
    "metric_options": {"window": [0.06, 0.07]},                              # s
    "trajectories": "none",
}


@pytest.fixture(scope="module")
def sweeps(tmp_path_factory):
    """The same sweep of concentric.yaml by the CLI (its summary CSV) and by musclesim.sweep
    (its structured array)."""
    folder = tmp_path_factory.mktemp("sweep")
    spec = dict(SWEEP, base=os.path.join(SCENARIOS, "concentric.yaml"))
    (folder / "sweep.yaml").write_text(json.dumps(spec))
    cli("sweep", folder / "sweep.yaml", "-o", folder / "summary.csv", "--quiet")
    return folder / "summary.csv", musclesim.sweep(spec, threads=2)


def test_sweep_heat_map_and_lines_are_the_clis(tmp_path, sweeps):
    csv, summary = sweeps
    heat = our_script(tmp_path, summary, x="load[0].after")
    assert heat == clis_script(tmp_path, csv, "--x", "load[0].after")
    assert "with boxxyerror" in heat and len(data_block_rows(heat, "cells")) == 6  # 3 x 2 points

    options = dict(x="load[0].after", y="final_length", color="model.f_iso")
    lines = our_script(tmp_path, summary, **options)
    assert lines == clis_script(tmp_path, csv, "--x", "load[0].after", "--y", "final_length",
                                "--color", "model.f_iso")
    assert "title 'model.f_iso = 80'" in lines and "title 'model.f_iso = 100'" in lines
    # a pandas DataFrame of the summary, and a dict of its columns, draw the same
    import pandas  # a test dependency (scripts/install-deps.sh), not the module's
    assert our_script(tmp_path, pandas.DataFrame(summary), **options) == lines
    assert our_script(tmp_path, {n: summary[n] for n in summary.dtype.names}, **options) == lines


def test_a_failed_points_nan_metric_is_left_out_as_the_clis_empty_field(tmp_path, sweeps):
    _, summary = sweeps
    damaged = summary.copy()
    damaged["final_length"][0] = np.nan  # what musclesim.sweep reads from an empty field
    script = our_script(tmp_path, damaged, x="load[0].after", y="final_length")
    # the heat map's cells: one point fewer, and not the one whose metric is missing
    cells = data_block_rows(script, "cells")
    assert len(cells) == len(summary) - 1
    assert summary["final_length"][0] not in cells[:, 6]


def test_residuals_are_the_clis(tmp_path):
    scenario_path = os.path.join(SCENARIOS, "quick_release.yaml")
    length_csv = os.path.join(DATA, "quick_release_length.csv")
    parameters = [{"path": "model.f_iso", "start": 80.0},           # N
                  {"path": "model.velocity.v_max", "start": 0.6}]   # m/s
    noise = {"length": 2e-5}  # m, the data's noise level
    spec = {"scenario": scenario_path, "series": [{"csv": length_csv, "noise": noise}],
            "parameters": parameters}
    (tmp_path / "data.yaml").write_text(json.dumps(spec))
    cli("identify", tmp_path / "data.yaml", "-o", tmp_path / "est.yaml", "--residuals",
        tmp_path / "res.csv")

    lines = [line for line in open(length_csv) if not line.startswith("#")]
    table = np.loadtxt(lines[1:], delimiter=",")
    series = {"t": table[:, 0], "length": table[:, 1], "noise": noise}
    fit = musclesim.identify_series(musclesim.load_scenario(scenario_path), [series], parameters)
    ours = our_script(tmp_path, fit)
    assert ours == clis_script(tmp_path, tmp_path / "res.csv")
    assert "series 0: length" in ours
    # the residuals dict itself is a residual table too
    assert our_script(tmp_path, dict(fit.residuals)) == ours


# --- (b) a model's curves -------------------------------------------------------------------

@pytest.mark.parametrize("name", ["concentric.yaml", "fit_indicator.yaml"])
def test_curves_are_the_clis(tmp_path, name):
    # fit_indicator's Gaussians come from a fit: Model.params must carry them exactly
    path = os.path.join(SCENARIOS, name)
    ours = our_script(tmp_path, musclesim.load_model(path))
    assert ours == clis_script(tmp_path, "--curves", path)
    # a Model made from the params dict draws the same
    assert our_script(tmp_path, musclesim.Model(musclesim.load_model(path).params)) == ours


def test_an_svg_of_the_size_asked_for(tmp_path):
    figure = tmp_path / "curves.svg"
    musclesim.plot(musclesim.load_model(os.path.join(SCENARIOS, "concentric.yaml")), figure,
                   size=(640, 480))
    head = figure.read_text()[:2000]
    assert "<svg" in head and 'width="640"' in head and 'height="480"' in head


# --- (c) bad input --------------------------------------------------------------------------

@pytest.fixture(scope="module")
def short_run():
    return musclesim.load_scenario(os.path.join(SCENARIOS, "concentric.yaml"),
                                   {"time.end": 0.01}).run()


@pytest.mark.parametrize("options, message", [
    ({"output": "fig.jpg"}, "fig.jpg: the figure's file must end in .png or .svg"),
    ({"size": (5, 5)}, "size 5x5: width and height must be 100 to 10000 px"),
    ({"size": (10 ** 12, 500)}, "width and height must be 100 to 10000 px"),
    ({"title": "two\nlines"}, "title 'two\\x0alines': must not contain control characters"),
    ({"y": "final_length"}, "y = final_length: given without x"),
    ({"color": "model.f_iso"}, "color = model.f_iso: given without x"),
    ({"x": "load[0].after"}, "sweep: missing columns: index, status, steps"),
])
def test_bad_options_raise_input_errors_naming_them(tmp_path, short_run, options, message):
    options = dict(options)
    output = tmp_path / options.pop("output", "fig.png")
    with pytest.raises(musclesim.InputError) as error:
        musclesim.plot(short_run, output, **options)
    assert message in str(error.value)
    assert str(error.value).split(" ")[0] in ("output", "size", "title", "y", "color", "sweep:")
    assert not output.exists()


def test_a_sweep_x_that_is_not_a_swept_path(tmp_path, sweeps):
    _, summary = sweeps
    with pytest.raises(musclesim.InputError) as error:
        musclesim.plot(summary, tmp_path / "fig.png", x="load")
    assert str(error.value) == ("x load: not a swept path of sweep (it sweeps load[0].after, "
                                "model.f_iso)")
    with pytest.raises(musclesim.InputError, match="y nope: not a metric of sweep"):
        musclesim.plot(summary, tmp_path / "fig.png", x="load[0].after", y="nope")


@pytest.mark.parametrize("data", [[1.0, 2.0], "run.csv", 3.0, None])
def test_unsupported_data_types_raise_type_error(tmp_path, data):
    with pytest.raises(TypeError, match="data must be a Result, a Model"):
        musclesim.plot(data, tmp_path / "fig.png")


def test_a_model_takes_no_sweep_options(tmp_path):
    model = musclesim.load_model(os.path.join(SCENARIOS, "concentric.yaml"))
    with pytest.raises(musclesim.InputError, match="x, y and color go with a sweep summary"):
        musclesim.plot(model, tmp_path / "fig.png", x="load[0].after")


def test_bad_columns_name_the_column_and_row(tmp_path, short_run):
    columns = dict(short_run.columns)
    bad = columns["length"].copy()
    bad[3] = np.nan
    with pytest.raises(musclesim.InputError) as error:
        musclesim.plot(dict(columns, length=bad), tmp_path / "fig.png")
    # the row is named by its 0-based index, where the CLI names its CSV's line
    assert str(error.value) == "trajectory:3: column length = 'nan': must be a finite number"
    with pytest.raises(musclesim.InputError, match="column length has 2 values, but column t has"):
        musclesim.plot(dict(columns, length=bad[:2]), tmp_path / "fig.png")
    with pytest.raises(musclesim.InputError, match=r"column length must be a 1-D array, not one "
                                                   r"of shape \(2, 2\)"):
        musclesim.plot(dict(columns, length=np.zeros((2, 2))), tmp_path / "fig.png")
    with pytest.raises(TypeError, match="size must be \\(width, height\\)"):
        musclesim.plot(short_run, tmp_path / "fig.png", size=1000)


def test_missing_gnuplot_is_the_librarys_error(tmp_path, short_run, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))  # no gnuplot there
    with pytest.raises(RuntimeError, match="gnuplot is not installed .*gnuplot-nox"):
        musclesim.plot(short_run, tmp_path / "fig.png", script=tmp_path / "fig.gp")
    # the script is written first, as the CLI's --script is
    assert (tmp_path / "fig.gp").exists() and not (tmp_path / "fig.png").exists()


def test_script_over_the_figure_is_refused_before_anything_is_written(tmp_path, short_run):
    figure = tmp_path / "fig.png"
    with pytest.raises(musclesim.InputError,
                       match=r"script .*fig.png: output .*fig.png names the same file"):
        musclesim.plot(short_run, figure, script=figure)
    assert list(tmp_path.iterdir()) == []
