"""Two Python threads calling musclesim.run_many at once against the same calls one after the
other: the speed-up the released GIL gives on this machine's cores (about 2 on two idle cores;
1 if the GIL were held). python/tests/test_sweep.py checks that the GIL is released; this
measures what it buys. Prints a table. Run with the build tree on the path:
  PYTHONPATH=build/python /usr/bin/python3 bench/python_threads.py
"""
import os
import platform
import threading
import time

import musclesim

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
# 60 runs of a few ms each: about 0.4 s of integration per call
JOBS = [(os.path.join(ROOT, "scenarios", "force_regulation.yaml"), {"output.interval": 0.5})] * 60
TRIES = 5


def work() -> None:
    musclesim.run_many(JOBS, threads=1)


def serial_and_parallel_seconds() -> tuple[float, float]:
    start = time.perf_counter()
    work()
    work()
    serial = time.perf_counter() - start
    threads = [threading.Thread(target=work) for _ in range(2)]
    start = time.perf_counter()
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return serial, time.perf_counter() - start


def main() -> None:
    work()  # warm caches and the allocator before timing
    times = [serial_and_parallel_seconds() for _ in range(TRIES)]
    serial, parallel = min(times, key=lambda t: t[1] / t[0])
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores; "
          f"best of {TRIES}")
    print("| two calls of run_many (60 runs each) | seconds |")
    print("|---|---|")
    print(f"| one after the other | {serial:.3f} |")
    print(f"| on two Python threads at once | {parallel:.3f} |")
    print(f"| speed-up | {serial / parallel:.2f} |")


if __name__ == "__main__":
    main()
