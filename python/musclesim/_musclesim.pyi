"""
musclesim: muscle-like actuator tension, networks and control, on SUNDIALS CVODES. SI units throughout: lengths in m, speeds in m/s, forces in N, times in s; activations and excitations in [0, 1]. A shortening velocity v is positive when the actuator shortens.
"""
from __future__ import annotations
from musclesim import InputError
from musclesim import ParameterError
import numpy
import numpy.typing
import typing
__all__ = ['InputError', 'Model', 'Parameter', 'ParameterError', 'Result', 'RunStats', 'Scenario', 'SeriesIdentification', 'SeriesParameterEstimate', 'SolverOptions', 'Stepper', 'fit_gaussians', 'force_length_preset', 'load_model', 'load_scenario']
class Model:
    """
    The tension model of one actuator (docs/model.md):
    T(x, v, u) = T_p(x) + u f_iso f_L(x) g(v), x the length [m], v the shortening velocity [m/s]
    (positive when the actuator shortens, v = -dx/dt), u the activation in [0, 1], T in [N].
    
    Every curve method takes numbers or NumPy arrays (converted to float64) and broadcasts its
    arguments against each other as NumPy does; it returns float64 arrays of the broadcast shape,
    or a numpy.float64 (a subclass of float) when every argument is a scalar or 0-d. Immutable.
    """
    def __init__(self, params: dict[str, typing.Any]) -> None:
        """
        A model from a dict with the keys of a scenario's `model:` block (docs/guide/model.md,
        docs/model.md): f_iso [N]; passive {k_p [N], alpha [1/m], slack_length [m]}; active_length
        {optimal_range [l1, l2] [m], sigma (optional), and gaussians [{amplitude, width, center}] or
        fit {count, target, ...}}; velocity {v_max [m/s], n, epsilon [m/s], eccentric {v_max, n,
        limit} (optional)}. The dict is read by the same reader as a file, as a document in memory
        (no text in between; NumPy numbers and arrays as Python numbers and lists): the same rules,
        and an InputError for a value that breaks one, naming the key path and "<model dict>" in
        place of the file (a dict has no lines: location None), e.g. "model.passive.k_p = abc
        (<model dict>): must be a number". A value of a type no file holds (not a number, bool, str,
        None, list or dict) is a TypeError naming its key path.
        """
    def __repr__(self) -> str:
        ...
    def f_L(self, x: typing.Any) -> typing.Any:
        """
        Active tension-length factor f_L [-] at length x [m]: the sum of Gaussians divided by its maximum over optimal_range, so its peak there is 1.
        """
    def f_L_slope(self, x: typing.Any) -> typing.Any:
        """
        df_L/dx [1/m] at length x [m].
        """
    def g(self, v: typing.Any) -> typing.Any:
        """
        Tension-velocity factor g [-] at shortening velocity v [m/s] (> 0 shortening): 1 at v = 0, 0 at v = v_max, epsilon-regularised so it is smooth at 0.
        """
    def g_slope(self, v: typing.Any) -> typing.Any:
        """
        dg/dv [s/m] at shortening velocity v [m/s].
        """
    def passive(self, x: typing.Any) -> typing.Any:
        """
        Passive tension T_p [N] at length x [m]: k_p (exp(alpha (x - slack_length)) - 1) above the slack length, 0 at or below it.
        """
    def tension(self, x: typing.Any, v: typing.Any, u: typing.Any) -> typing.Any:
        """
        Total tension T [N] at length x [m], shortening velocity v [m/s] (> 0 shortening) and activation u [-] in [0, 1] (ParameterError outside, NaN included).
        """
    def tension_parts(self, x: typing.Any, v: typing.Any, u: typing.Any) -> dict[str, typing.Any]:
        """
        The tension and its parts at (x [m], v [m/s], u [-]), as a dict of arrays:
        total T [N], passive T_p [N], active T_a = u f_iso f_L g [N], d_length dT/dx [N/m],
        d_velocity dT/dv [N s/m] (v the shortening velocity), d_activation dT/du [N]. The
        derivatives are the analytic ones the simulator's Jacobian uses; at x = slack_length the
        passive slope is the left one (0).
        """
    @property
    def fit_result(self) -> dict[str, typing.Any] | None:
        """
        The fit the block asked for (a dict as fit_gaussians returns), or None when the block gave its Gaussians.
        """
    @property
    def optimal_length(self) -> float:
        """
        Where f_L peaks on optimal_range [m] (f_L = 1 there).
        """
    @property
    def params(self) -> dict[str, typing.Any]:
        """
        The parameters as a dict with the `model:` block's keys (units as there), the Gaussians always explicit (a fit's result in its place): Model(model.params) is the same model.
        """
class Parameter:
    """
    A handle on one number of a Scenario (Scenario.parameter(path)), named by its key path in the scenario's file form ('model.f_iso', 'load[0].value', 'nodes[1].mass', ...): `value` reads it and, assigned, sets it as Scenario.set does (checked at once; a refused value leaves the scenario unchanged). In the key's unit.
    """
    def __repr__(self) -> str:
        ...
    @property
    def path(self) -> str:
        """
        The key path, written one way.
        """
    @property
    def value(self) -> float:
        """
        The value in the scenario [the key's unit]; assigning sets it.
        """
    @value.setter
    def value(self, arg1: typing.Any) -> None:
        ...
class Result:
    """
    One run's trajectory and solver counters, as `musclesim run` writes them (its CSV and its --stats JSON), recorded straight into NumPy arrays. Rows are the output grid's times (output.interval) or every internal step (interval: steps). SI units: t in s, lengths and positions in m, velocities in m/s (shortening_velocity positive when the actuator shortens), tensions and loads in N, activations and excitations in [0, 1].
    """
    def __getitem__(self, column: str) -> numpy.typing.NDArray[typing.Any]:
        """
        result['column'] is result.columns['column'].
        """
    def __getstate__(self) -> tuple[typing.Any, ...]:
        ...
    def __len__(self) -> int:
        """
        The number of rows.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple[typing.Any, ...]) -> None:
        ...
    def to_dataframe(self) -> typing.Any:
        """
        The columns as a pandas.DataFrame (pandas imported only here; ImportError naming python3-pandas if it is missing).
        """
    @property
    def columns(self) -> dict[str, numpy.typing.NDArray[typing.Any]]:
        """
        dict {name: 1-D NumPy array of len(result)}, exactly the CLI CSV's columns in its order: float64, except the text columns `phase` and `<actuator>.phase` ('concentric', 'eccentric', 'isometric'), which are NumPy str arrays. With sensitivities, d_<column>/d_<path> after them.
        """
    @property
    def run_stats(self) -> RunStats:
        """
        The counters as a RunStats.
        """
    @property
    def stats(self) -> dict[str, typing.Any]:
        """
        dict of the run's counters, as `musclesim run --stats` writes them: steps, rhs_evals, jac_evals, linear_setups, newton_iters, newton_conv_fails, error_test_fails, wall_seconds [s], final_time [s], linear_solver, status, message (and with sensitivities their counters and `sensitivities`, one {path, derivative} each).
        """
    @property
    def status(self) -> str:
        """
        'completed', 'limit' (stopped at a length limit) or 'failed' (the solver failed; the rows up to the failure are kept).
        """
    @property
    def times(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        columns['t']: the rows' times [s], float64, shape (len(result),).
        """
class RunStats:
    """
    A run's solver counters (Result.run_stats; the same as the dict Result.stats): steps, rhs_evals, jac_evals, linear_setups, newton_iters, newton_conv_fails, error_test_fails, wall_seconds [s], final_time [s], linear_solver, status, message.
    """
    def __getstate__(self) -> tuple[typing.Any, ...]:
        ...
    def __setstate__(self, arg0: tuple[typing.Any, ...]) -> None:
        ...
    @property
    def error_test_fails(self) -> int:
        """
        Steps the local error test rejected [-].
        """
    @property
    def final_time(self) -> float:
        """
        Where the run ended [s].
        """
    @property
    def jac_evals(self) -> int:
        """
        Jacobian evaluations [-].
        """
    @property
    def linear_setups(self) -> int:
        """
        Newton matrix factorisations [-].
        """
    @property
    def linear_solver(self) -> str:
        """
        The linear solver used (never 'auto').
        """
    @property
    def message(self) -> str:
        """
        Why the run ended early (a limit or a failure); '' when it completed.
        """
    @property
    def newton_conv_fails(self) -> int:
        """
        Newton convergence failures [-].
        """
    @property
    def newton_iters(self) -> int:
        """
        Newton iterations [-].
        """
    @property
    def rhs_evals(self) -> int:
        """
        Right-hand side evaluations, a difference-quotient Jacobian's included [-].
        """
    @property
    def status(self) -> str:
        """
        'completed', 'limit' (a length limit reached) or 'failed'.
        """
    @property
    def steps(self) -> int:
        """
        Internal steps taken [-].
        """
    @property
    def wall_seconds(self) -> float:
        """
        Wall-clock time of the run [s].
        """
class Scenario:
    """
    A validated scenario in memory (a single actuator, docs/guide/scenarios.md, or a network on a line, docs/guide/networks.md), read from a file or a dict, with the values set() since. SI units as in the files.
    """
    def __copy__(self) -> Scenario:
        ...
    def __deepcopy__(self, memo: typing.Any) -> Scenario:
        ...
    def __getstate__(self) -> tuple[typing.Any, ...]:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple[typing.Any, ...]) -> None:
        ...
    def copy(self) -> Scenario:
        """
        An independent copy: set() on one leaves the other as it is (copy.copy and copy.deepcopy give the same).
        """
    def parameter(self, path: str) -> Parameter:
        """
        The handle on the number at key path `path` (ParameterError when it names no number of this scenario): handle.value reads it, handle.value = v sets it.
        """
    def run(self, sensitivities: typing.Any = None) -> Result:
        """
        Integrates the scenario (GIL released) as `musclesim run` does and returns a Result, its columns filled in memory. `sensitivities`: dotted paths of numeric parameters ('model.f_iso', 'load[0].value', 'models.muscle.f_iso', ...) whose forward sensitivities add the columns d_<column>/d_<path>, as `musclesim run --sensitivity PATH` writes them; a scenario's own `sensitivities:` list adds its own. A solver failure is a result (status 'failed'), not an exception.
        """
    def set(self, key: str, value: typing.Any) -> Scenario:
        """
        Sets one value by its dotted key path as `musclesim run --set KEY=VALUE` does (e.g. 'load[0].after', 'model.velocity.n', 'elements[1].activation.after', in the file's units) and validates the scenario at once: a number goes in place through the key's parameter handle, a word (a method, a waveform's type) reads the scenario again. InputError (with .key) for a key that is not there or a value that breaks a rule, leaving the scenario unchanged. Returns the scenario.
        """
    def to_yaml(self) -> str:
        """
        The scenario as a YAML file's text, its set() values written in: what `musclesim run` runs alike (the original's comments are not kept).
        """
    @property
    def _display(self) -> str:
        """
        The scenario's name in messages: the path as given, or the dict's name.
        """
    @property
    def _path(self) -> str:
        """
        The file read (absolute), or '' for a dict.
        """
    @property
    def is_network(self) -> bool:
        """
        True for a network (a top-level `nodes:` key), False for a single actuator.
        """
    @property
    def name(self) -> str:
        """
        The scenario's `name:` ('' if none).
        """
    @property
    def overrides(self) -> list[str]:
        """
        The 'key=value' values set since the file or dict was read: one per key, its last value, in the order the keys were first set.
        """
    @property
    def solver(self) -> SolverOptions:
        """
        A copy of the solver's options (SolverOptions).
        """
class SeriesIdentification:
    """
    The result of identify_series: a weighted least-squares fit of scenario parameters to measured time series (or, with design=True, the experiment's check at the start values), with what the Jacobian of forward sensitivities says about the parameters: standard errors, correlations, the singular values of the scaled sensitivity matrix and a verdict. As `musclesim identify DATA.yaml` (docs/guide/identification.md, "From time series"). Values in the units of the scenario's parameters and of the measured columns (SI: m, m/s, N, s).
    """
    def __repr__(self) -> str:
        ...
    @property
    def converged(self) -> bool:
        """
        Whether the fit converged (True for the design). A fit that did not is returned with its last point and a RuntimeWarning.
        """
    @property
    def correlation(self) -> numpy.ndarray[typing.Any, numpy.dtype[numpy.float64]]:
        """
        P x P float64 array of the estimates' correlations [-]; NaN in the row and column of a parameter the experiment does not determine.
        """
    @property
    def degrees_of_freedom(self) -> int:
        """
        values - parameters not at a bound.
        """
    @property
    def design(self) -> bool:
        """
        True for the design check (no fit: the start values, Cramer-Rao standard errors).
        """
    @property
    def estimates(self) -> dict[str, float]:
        """
        dict {path: estimate} in the parameters' order and units (the design: the starts).
        """
    @property
    def evaluations(self) -> int:
        """
        Runs with sensitivities the fit took (0 for the design).
        """
    @property
    def iterations(self) -> int:
        """
        Accepted Levenberg-Marquardt steps (0 for the design).
        """
    @property
    def noise_given(self) -> bool:
        """
        True: weighted by 1/noise, covariance (J^T W J)^-1; False: unweighted, s^2 (J^T J)^-1 with s^2 = RSS / degrees_of_freedom.
        """
    @property
    def parameters(self) -> list[SeriesParameterEstimate]:
        """
        One SeriesParameterEstimate per parameter, in the order given.
        """
    @property
    def report(self) -> str:
        """
        Markdown, as `musclesim identify --report` (a fit) or `--design` writes it.
        """
    @property
    def residuals(self) -> dict[str, numpy.typing.NDArray[typing.Any]]:
        """
        dict of 1-D arrays, one entry per measured value (the columns of `musclesim identify --residuals`): series (int64, the index in `series`), output (str, the column), t [s], measured, model, residual (measured - model) [the column's unit], standardised (residual / noise, or / s without noise levels) [-]. Empty for the design.
        """
    @property
    def scenario(self) -> typing.Any:
        """
        The estimated Scenario (the given one with 'path=estimate' overrides after its own), ready to run(); None for the design.
        """
    @property
    def singular_values(self) -> numpy.ndarray[typing.Any, numpy.dtype[numpy.float64]]:
        """
        The singular values of the scaled sensitivity matrix (each column the outputs' change, in noise standard deviations, for a relative change of its parameter), descending, float64 [-].
        """
    @property
    def stop_reason(self) -> str:
        """
        Why the fit stopped ('' for the design).
        """
    @property
    def values(self) -> int:
        """
        The number of measured values in the fit.
        """
    @property
    def variance_factor(self) -> float:
        """
        1 with noise levels; else s^2 = RSS / degrees_of_freedom [the values' unit squared].
        """
    @property
    def verdict(self) -> str:
        """
        The verdict in plain sentences: which parameters this experiment determines.
        """
    @property
    def warnings(self) -> list[str]:
        """
        The warnings identify_series issued (a fit that did not converge, weighted residuals far above the stated noise), as texts; [] when none.
        """
    @property
    def weak_directions(self) -> list[dict[str, typing.Any]]:
        """
        The combinations the experiment does not determine: a list of dicts {ratio: its singular value over the largest [-], components: float64 array, one per parameter, unit length, relative changes d p_j / |p_j| that leave the outputs unchanged}.
        """
    @property
    def weighted_rss(self) -> float:
        """
        The fit's sum of squared weighted residuals ((measured - model) / noise)^2 [-] (or of plain residuals without noise levels, in the values' unit squared); 0 for the design.
        """
class SeriesParameterEstimate:
    """
    One parameter of identify_series: its values, its standard error and the verdict on whether the experiment determines it. Values are in the parameter's own unit (the scenario file's: N, m, m/s, s, ...).
    """
    def __repr__(self) -> str:
        ...
    @property
    def column_ratio(self) -> float:
        """
        Its column of the scaled sensitivity matrix over the largest column [-]: near 0, the outputs do not depend on it.
        """
    @property
    def estimate(self) -> float:
        """
        The fit's estimate; for the design, the start.
        """
    @property
    def lower(self) -> typing.Any:
        """
        The lower bound, or None.
        """
    @property
    def path(self) -> str:
        """
        The dotted key path, as Scenario.set takes it ('model.f_iso').
        """
    @property
    def relative_standard_error(self) -> float:
        """
        standard_error / |estimate| (/ 1 at an estimate of 0) [-].
        """
    @property
    def scenario_value(self) -> float:
        """
        Its value in the scenario (with the scenario's set() overrides).
        """
    @property
    def standard_error(self) -> float:
        """
        Its standard error (the design's: the Cramer-Rao bound); inf when the experiment does not determine it (negligible column, dependent, at a bound).
        """
    @property
    def start(self) -> float:
        """
        Where the fit started: the entry's start, or the scenario's value.
        """
    @property
    def upper(self) -> typing.Any:
        """
        The upper bound, or None.
        """
    @property
    def verdict(self) -> str:
        """
        'identifiable' (relative standard error <= 0.25), 'poorly_determined' (above it), 'negligible_column' (the outputs do not depend on it), 'dependent' (in a combination the outputs do not see: weak_directions), 'at_bound' (the estimate sits on a bound: not estimated).
        """
class SolverOptions:
    """
    How CVODES integrates a scenario (its `solver:` block): method 'bdf' or 'adams', rtol [-], atol [m and m/s], jacobian 'analytic' or 'difference_quotient', max_step [s] (0: no limit), max_steps, linear_solver 'auto', 'small', 'dense', 'band' or 'sparse'. Scenario.solver gives a copy; Scenario.set('solver.rtol', ...) changes a scenario's.
    """
    def __init__(self) -> None:
        """
        The defaults: bdf, rtol 1e-6, atol 1e-9, analytic Jacobian, auto.
        """
    def __repr__(self) -> str:
        ...
    @property
    def atol(self) -> float:
        """
        The absolute tolerance on positions and velocities [m and m/s]; > 0 and < 1.
        """
    @property
    def jacobian(self) -> str:
        """
        The Newton iteration's Jacobian: the analytic one, or a difference quotient: one of 'analytic', 'difference_quotient'.
        """
    @property
    def linear_solver(self) -> str:
        """
        How the Newton systems are solved: auto picks small, band or sparse by the system's size and structure (docs/solver.md): one of 'dense', 'band', 'sparse', 'auto', 'small'.
        """
    @property
    def max_step(self) -> float:
        """
        The largest internal step (0: no limit) [s]; >= 0 and finite.
        """
    @property
    def max_steps(self) -> int:
        """
        The internal steps one run may take before it fails (CV_TOO_MUCH_WORK) [-]; an integer from 1 to 1e+12.
        """
    @property
    def method(self) -> str:
        """
        The integration method: bdf (stiff problems: the default) or adams (nonstiff): one of 'bdf', 'adams'.
        """
    @property
    def rtol(self) -> float:
        """
        The relative tolerance of the local error test [-]; >= 1e-14 and < 1.
        """
class Stepper:
    """
    A scenario integrated piece by piece from Python (the C++ Stepper): advance to the next sample time, read the state, set the activation of actuators no controller drives, advance again. A single-actuator scenario steps as its network (docs/model.md 7.4): node `ground` fixed at 0, node `tip` (its position is the length), element `actuator`, `damper` and `spring` (the last two of coefficient 0 when the scenario gives none). Times in s, lengths in m, tensions in N, activations in [0, 1].
    """
    def __init__(self, scenario: typing.Any, set: typing.Any = None, rtol: float | None = None, atol: float | None = None) -> None:
        """
        A stepper of `scenario`: a Scenario (load_scenario or scenario_from_dict, with the values set() on it) or a scenario file's path (str or pathlib.Path), `set` applied after them: a list of "key=value" strings as --set takes them, or a dict {key: value}. `rtol` and `atol` (m, m/s) replace the scenario's solver tolerances. Starts at the scenario's time.start with its limits; its time.end and output are not used.
        """
    def advance(self, t: float) -> str:
        """
        Integrates from `time` to `t` [s] (GIL released) and returns "completed" (time is then t), "limit" (a length limit was reached; no further advance) or "failed" (see `message`). Raises ValueError unless t is finite and after time.
        """
    def advance_each(self, times: numpy.ndarray[typing.Any, numpy.dtype[numpy.float64]]) -> str:
        """
        advance(t) for every t of the 1-D array `times` [s], looped in C++ with the GIL released; stops at the first that does not complete and returns its status.
        """
    def sample(self) -> dict[str, float]:
        """
        What the network CSV would record at `time`: a dict {column: float} with the CSV's column names (t, <node>.position, <node>.velocity, <element>.length, <element>.tension, <actuator>.shortening_velocity, .activation, .excitation, .tension_passive, .tension_active, <node>.load, <controller>.reference, .measured, .error, .output), without the text column <actuator>.phase.
        """
    def set_activation(self, actuator: str, u: float) -> None:
        """
        Holds the activation of `actuator` (with activation dynamics, its excitation) at `u` in [0, 1] from `time` on (zero-order hold); the next advance restarts the integrator. Raises ValueError for an unknown name, a non-actuator, an actuator a controller drives, or u outside [0, 1].
        """
    @property
    def columns(self) -> list[str]:
        """
        The keys of sample() after "t", in the CSV's order.
        """
    @property
    def message(self) -> str:
        """
        Why the last advance ended early (empty if it completed).
        """
    @property
    def state(self) -> numpy.ndarray[typing.Any, numpy.dtype[numpy.float64]]:
        """
        A copy of the state y(time) as a 1-D float64 array, in the network's state order (positions [m] and velocities [m/s] of the free nodes, then activations of actuators with dynamics).
        """
    @property
    def stats(self) -> dict[str, typing.Any]:
        """
        Solver counters summed over every advance (steps, rhs_evals, ...), wall_seconds [s], final_time [s], status and message.
        """
    @property
    def time(self) -> float:
        """
        Where the integration stands [s].
        """
def _cpp_run_seconds(scenario: Scenario, repeats: int) -> list[float]:
    """
    The reference for Scenario.run()'s overhead (bench/python_run_overhead.py): the same run, recorded in memory by C++ alone `repeats` times; each one's wall time [s].
    """
def _identify_curves(passive: typing.Any, active: typing.Any, velocity: typing.Any, active_count: int, nonnegative: bool, f_iso: float | None, report: bool, source: str) -> dict[str, typing.Any]:
    """
    The engine of musclesim.identify_curves (use that): each curve None or a pair of 1-d
    arrays (x, tension), x a length [m] (passive, active) or a shortening velocity [m/s]
    (velocity, > 0 shortening), tension [N]. Checks the data by the rules of the CLI's CSV
    reader, fits them with the GIL released, and returns a dict: model_yaml (the `model:` block
    of `musclesim identify`, its header naming `source`), params (that block read back, for
    musclesim.Model), passive, active, velocity (the estimates, or None) and report (the
    Markdown of --report, or None). Raises InputError naming the argument and row for bad data.
    """
def _identify_series(scenario: typing.Any, spec: typing.Any, spec_name: str, series: list[typing.Any], design: bool, max_evaluations: int) -> SeriesIdentification:
    """
    identify_series's C++ half: `spec` a data file's keys as a dict without csv keys (messages name it `spec_name`), `series` one list of (column, array) pairs per entry of its series. identify_series is the public way.
    """
def _plot_columns(names: list[str], columns: list[typing.Any], output: str, title: str, width: int, height: int, x: str | None, y: str | None, color: str | None, script: str | None) -> None:
    """
    The figure `musclesim plot` draws of a CSV with these columns (each a 1-D float64 array or a list of str), with the GIL released: with x a sweep summary's, else a residual table's, a network trajectory's or a trajectory's. musclesim.plot is the public way.
    """
def _plot_frames(names: list[str], columns: list[typing.Any], output: str, title: str, width: int, height: int, times: list[float], count: int, scenario: typing.Any, script: str | None) -> None:
    """
    The frames figure (`musclesim plot --frames/--frame-count`) of a run in the plane or in space given as its columns, at `times` (or `count` evenly spaced ones when empty), the elements drawn along their paths with `scenario`, with the GIL released. musclesim.plot is the public way.
    """
def _plot_model(params: dict[str, typing.Any], output: str, title: str, width: int, height: int, script: str | None) -> None:
    """
    The curves figure (`musclesim plot --curves`) of the model block given as a dict, with the GIL released. musclesim.plot is the public way.
    """
def _optimize(scenario: typing.Any, problem: dict) -> dict[str, typing.Any]:
    """
    optimize's C++ half: `problem` a dict of a problem file's keys but base and output (intervals, controls, final_values, path_bounds, tracking, terminal, parameters, final_time, optimizer), read by the problem file's reader; returns a dict of the result with the optimum as a Scenario. musclesim.optimize is the public way.
    """
def _require(condition: bool, path: str, value: float, rule: str) -> None:
    """
    The library's Require: raises ParameterError(path, value, rule) unless `condition`.
    """
def _run_many(jobs: list[typing.Any], threads: int, sensitivities: list[str]) -> list[Result]:
    """
    run_many's C++ half: every job, a Scenario or a (path, overrides) pair (overrides: None, a list of "key=value" strings as --set takes them, or a dict), run on `threads` C++ threads (0: every core) with the GIL released, each recorded in memory; one Result per job, in order. A bad job raises (the first in the list's order) after every job has run. musclesim.run_many is the public way.
    """
def _scenario_from_dict(dict: typing.Any, name: str) -> Scenario:
    """
    A scenario from a dict read as a file's document (no text in between); messages name it `name`. scenario_from_dict is the public way.
    """
def _sweep(spec: typing.Any, threads: int, output: typing.Any, resume: bool, name: str) -> typing.Any:
    """
    Runs the sweep `spec` (a sweep file's path, or a dict of its keys whose base may be a Scenario) as `musclesim sweep` does (threads 0: every core), GIL released, Ctrl-C stopping it. With `output`, the summary is that file (and `resume` continues an interrupted one) and None is returned; without, it is kept in memory and returned as (header, columns). musclesim.sweep() makes the structured array.
    """
def fit_gaussians(x: typing.Any = None, f: typing.Any = None, n: int = 3, *, target: str | None = None, preset: str | None = None, optimal_length: float = 1.0, optimal_range: tuple[float, float] | None = None, sigma: float = 1.0, nonnegative: bool = False, widths: typing.Any = None, centers: typing.Any = None) -> dict[str, typing.Any]:
    """
    Least-squares fit of n Gaussians (1..12) to a force-length target (docs/model.md
    section 3.2; the `fit:` block of a model). Each component is
    psi_k(x) = a_k / sqrt(2 pi sigma) exp(-b_k (x - d_k)^2 / (2 sigma)), the sum unnormalised.
    
    Targets:
      fit_gaussians(x, f, n)                       samples (default with points): the cost is
          the sum over i of (sum_k psi_k(x_i) - f_i)^2 [-]; x in m, f on the f_L scale [-].
      fit_gaussians(x, f, n, target="polygon")     the piecewise-linear curve through (x, f),
          x strictly increasing, zero outside: the cost is the integral over the real line of
          the squared difference [m].
      fit_gaussians(n=..., target="indicator", optimal_range=(l1, l2))   1 on [l1, l2] [m],
          0 elsewhere; cost as for a polygon.
      fit_gaussians(n=..., preset=NAME, optimal_length=L)   a standard curve (degroote2016,
          thelen2003, gordon1966, mujoco) scaled to peak at L [m]; cost as for a polygon.
    Amplitudes come from the linear solve (>= 0 with nonnegative=True); widths b_k (the YAML
    key `width`, an inverse variance [1/m^2 when sigma = 1]) and centers d_k [m] from a
    deterministic multi-start minimisation, unless both widths and centers are given (n values
    each): then the shapes are fixed and only the amplitudes are solved.
    
    Returns a dict: amplitudes, widths, centers (float64 arrays of n), gaussians (the list of
    {amplitude, width, center} for a model block), cost (see above), relative_residual (cost
    over the integral of target^2, or the sum of f_i^2 for samples), iterations (cost evaluations
    of the best start; 0 with shapes fixed), starts (starting points tried). A bad argument
    raises the library's ParameterError (a ValueError) naming it.
    """
def force_length_preset(preset: str, x: typing.Any, optimal_length: float = 1.0) -> typing.Any:
    """
    A standard active force-length curve f_L [-] at lengths x [m], scaled so that its peak
    is 1 at `optimal_length` [m] (default 1: x is then the normalised length l / L), as `musclesim
    curves --preset NAME` tabulates it: preset degroote2016, thelen2003, gordon1966 or mujoco
    (docs/guide/model.md, "Standard curves"). fit_gaussians(preset=...) fits Gaussians to it.
    """
def load_model(path: typing.Any) -> Model:
    """
    The model of a YAML file: a model file (`name` and `model` only, as the CLI writes) or a
    scenario, which is then checked whole (as `musclesim curves FILE` reads it). Raises the
    reader's error (file:line:column, key, value, rule) for bad input.
    """
def load_scenario(path: typing.Any, set: typing.Any = None) -> Scenario:
    """
    Reads and validates the scenario file `path` (single actuator or network), applying `set` first: a list of 'key=value' texts as `musclesim run --set` takes them, or a dict {key: value}. InputError (with .key and .location 'file:line:column') for bad input.
    """
__version__: str = '0.2.0'
