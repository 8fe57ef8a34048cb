#!/usr/bin/python3
"""The SciPy side of the work-precision comparison: the same scenario integrated with
scipy.integrate.solve_ivp (Radau, BDF, LSODA), as a careful SciPy user would write it:
the model from docs/model.md in scalar `math` (no numpy on two numbers), the analytic Jacobian
given to every method, and the run split at the inputs' breakpoints so that no step
straddles a jump. Errors against the reference musclesim wrote (work_precision).

    scipy_peer.py SCENARIO.yaml REFERENCE.csv > rows.csv

Prints CSV rows: scenario,tool,method,rtol,error,error_length,error_tension,wall_seconds,rhs_evals
Handles the waveforms of the canonical scenarios: constant and step activations and loads,
springs and hanging masses.
"""
import csv
import math
import os
import sys
import time

import yaml
from scipy.integrate import solve_ivp


def num(value):
    """A YAML number: PyYAML reads 1.0e5 (no sign in the exponent) as text."""
    return float(value)


def waveform(spec):
    """(value(t), breakpoints) of a constant or step waveform."""
    if spec["type"] == "constant":
        return (lambda t, v=num(spec["value"]): v), []
    if spec["type"] == "step":
        time_, before, after = num(spec["time"]), num(spec["before"]), num(spec["after"])
        return (lambda t: before if t < time_ else after), [time_]
    raise ValueError("waveform type %s is not handled by this peer" % spec["type"])


class Model:
    """Tension of docs/model.md sections 2-5, with derivatives."""

    def __init__(self, m):
        self.f_iso = num(m["f_iso"])
        p = m["passive"]
        self.k_p, self.alpha_p, self.slack = num(p["k_p"]), num(p["alpha"]), num(p["slack_length"])
        a = m["active_length"]
        self.sigma = num(a.get("sigma", 1.0))
        self.gaussians = [(num(g["amplitude"]), num(g["width"]), num(g["center"]))
                          for g in a["gaussians"]]
        l1, l2 = (num(v) for v in a["optimal_range"])
        # max of f over L_opt: a fine grid, then golden section around the best point
        xs = [l1 + (l2 - l1) * i / 4000 for i in range(4001)]
        best = max(range(len(xs)), key=lambda i: self.f(xs[i])[0])
        lo, hi = xs[max(best - 1, 0)], xs[min(best + 1, len(xs) - 1)]
        r = (math.sqrt(5) - 1) / 2
        for _ in range(100):
            c, d = hi - r * (hi - lo), lo + r * (hi - lo)
            if self.f(c)[0] > self.f(d)[0]:
                hi = d
            else:
                lo = c
        self.peak = max(self.f(0.5 * (lo + hi))[0], self.f(xs[best])[0])
        v = m["velocity"]
        self.n, self.eps = int(v["n"]), num(v["epsilon"])
        self.a_exp = 1.0 / self.n
        self.inv_scale = num(v["v_max"]) ** (-self.a_exp)

    def f(self, x):
        value = slope = 0.0
        norm = 1.0 / math.sqrt(2 * math.pi * self.sigma)
        for a, b, d in self.gaussians:
            psi = a * norm * math.exp(-b * (x - d) ** 2 / (2 * self.sigma))
            value += psi
            slope -= psi * b * (x - d) / self.sigma
        return value, slope

    def tension(self, x, v, u):
        """T, dT/dx, dT/dv with v the shortening velocity."""
        if x > self.slack:
            e = math.exp(self.alpha_p * (x - self.slack))
            tp, dtp = self.k_p * (e - 1), self.k_p * self.alpha_p * e
        else:
            tp, dtp = 0.0, 0.0
        fl, dfl = self.f(x)
        fl, dfl = fl / self.peak, dfl / self.peak
        w = v * v + self.eps * self.eps
        p = w ** ((self.a_exp - 1) / 2)
        g = 1 - v * p * self.inv_scale
        dg = -p * (self.a_exp * v * v + self.eps * self.eps) / w * self.inv_scale
        return (tp + u * self.f_iso * fl * g, dtp + u * self.f_iso * dfl * g,
                u * self.f_iso * fl * dg)


def main():
    scenario_path, reference_path = sys.argv[1], sys.argv[2]
    with open(scenario_path) as f:
        s = yaml.safe_load(f)
    name = os.path.splitext(os.path.basename(scenario_path))[0]
    model = Model(s["model"])
    act = s["actuator"]
    mass, c = num(act["mass"]), num(act.get("damping", 0.0))
    k, l0 = num(act.get("stiffness", 0.0)), num(act.get("rest_length", 0.0))
    activation, breaks = waveform(s["activation"])
    loads = s.get("load", [])
    loads = [loads] if isinstance(loads, dict) else loads
    forces, spring_k, spring_pull = [], 0.0, 0.0
    for load in loads:
        if load["type"] == "spring":
            spring_k += num(load["stiffness"])
            spring_pull += num(load["stiffness"]) * num(load["anchor"])
        elif load["type"] == "mass":
            mass += num(load["mass"])
            forces.append(lambda t, w=num(load["mass"]) * num(load.get("gravity", 9.81)): w)
        else:
            value, more = waveform(load)
            forces.append(value)
            breaks += more

    def rhs(t, y):
        x, xdot = y
        tension = model.tension(x, -xdot, activation(t))[0]
        load = spring_pull - spring_k * x + sum(fn(t) for fn in forces)
        return [xdot, (load - tension - c * xdot - k * (x - l0)) / mass]

    def jac(t, y):
        x, xdot = y
        _, dtdx, dtdv = model.tension(x, -xdot, activation(t))
        return [[0.0, 1.0], [(-spring_k - dtdx - k) / mass, (dtdv - c) / mass]]

    with open(reference_path) as f:
        reference = [(float(r["t"]), float(r["length"]), float(r["tension"])) for r in csv.DictReader(f)]
    times = [r[0] for r in reference]
    t0, t1 = num(s["time"]["start"]), num(s["time"]["end"])
    stops = sorted(b for b in set(breaks) if t0 < b < t1) + [t1]
    y0 = [num(s["initial"]["length"]), num(s["initial"].get("lengthening_rate", 0.0))]
    scale = max(abs(r[2]) for r in reference)

    def solve(method, rtol, atol):
        """The output grid's states and the RHS evaluations, one solve per segment."""
        out, y, start, evaluations, i = [], list(y0), t0, 0, 0
        for stop in stops:
            grid = []
            while i < len(times) and times[i] <= stop:
                grid.append(times[i])
                i += 1
            is_output = bool(grid) and grid[-1] == stop
            sol = solve_ivp(rhs, (start, stop), y, method=method, rtol=rtol, atol=atol, jac=jac,
                            t_eval=grid if is_output else grid + [stop])
            if sol.status != 0:
                raise RuntimeError(sol.message)
            evaluations += sol.nfev
            kept = len(sol.t) if is_output else len(sol.t) - 1
            out += [(sol.t[j], sol.y[0][j], sol.y[1][j]) for j in range(kept)]
            y, start = [sol.y[0][-1], sol.y[1][-1]], stop
        return out, evaluations

    print("scenario,tool,method,rtol,error,error_length,error_tension,wall_seconds,rhs_evals")
    for method in ("Radau", "BDF", "LSODA"):
        for e in range(3, 11):
            rtol = 10.0 ** -e
            atol = rtol * 1e-3
            walls = []
            for _ in range(3):
                start = time.perf_counter()
                out, nfev = solve(method, rtol, atol)
                walls.append(time.perf_counter() - start)
            walls.sort()
            err_x = err_t = 0.0
            for (t, x, xdot), (_, x_ref, t_ref) in zip(out, reference):
                tension = model.tension(x, -xdot, activation(t))[0]
                err_x = max(err_x, abs(x - x_ref) / abs(x_ref))
                err_t = max(err_t, abs(tension - t_ref) / scale)
            if len(out) != len(reference):
                err_x = err_t = float("inf")
            print("%s,scipy,%s,%.0e,%.6g,%.6g,%.6g,%.6g,%d" % (
                name, method.lower(), rtol, max(err_x, err_t), err_x, err_t, walls[1], nfev))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
