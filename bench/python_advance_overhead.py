"""The cost of stepping a network from Python: scenarios/force_regulation.yaml (no input
changes) advanced 1 ms at a time for 0.5 s, once by advance() called from a Python loop and
once by advance_each(), the same calls looped in C++. The difference per call is what Python
adds. Run with the build tree on the path:
  PYTHONPATH=build/python /usr/bin/python3 bench/python_advance_overhead.py
"""
import os
import platform
import time

import numpy as np

import musclesim

SCENARIO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenarios",
                        "force_regulation.yaml")
TIMES = np.arange(1, 501) * 1e-3  # s: 500 pieces of 1 ms
REPEATS = 30


def python_loop():
    stepper = musclesim.Stepper(SCENARIO)
    advance = stepper.advance
    start = time.perf_counter()
    for t in TIMES.tolist():
        advance(t)
    return time.perf_counter() - start


def cpp_loop():
    stepper = musclesim.Stepper(SCENARIO)
    start = time.perf_counter()
    stepper.advance_each(TIMES)
    return time.perf_counter() - start


def main():
    python_loop(), cpp_loop()  # warm up
    # interleaved, the minimum of each: the least disturbed by other work on the machine
    python_times, cpp_times = [], []
    for _ in range(REPEATS):
        python_times.append(python_loop())
        cpp_times.append(cpp_loop())
    calls = len(TIMES)
    py_us, cpp_us = min(python_times) / calls * 1e6, min(cpp_times) / calls * 1e6
    py_med, cpp_med = np.median(python_times) / calls * 1e6, np.median(cpp_times) / calls * 1e6
    print(f"machine: {platform.platform()}, {os.cpu_count()} cores, Python {platform.python_version()}")
    print(f"scenario: force_regulation.yaml, {calls} advances of 1 ms, {REPEATS} repeats")
    print(f"{'loop':<28}{'min us/call':>14}{'median us/call':>17}")
    print(f"{'Python: advance(t)':<28}{py_us:>14.2f}{py_med:>17.2f}")
    print(f"{'C++: advance_each(times)':<28}{cpp_us:>14.2f}{cpp_med:>17.2f}")
    print(f"{'Python overhead':<28}{py_us - cpp_us:>14.2f}{py_med - cpp_med:>17.2f}")


if __name__ == "__main__":
    main()
