"""Two Python threads calling into musclesim at once run in parallel: the GIL is released.

Run alone (ctest RUN_SERIAL, test python.parallel): the comparison needs the machine's cores
to itself, which the rest of the suite, run concurrently, would take."""
import os
import threading
import time


import musclesim

SOURCE = os.environ.get("MUSCLESIM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
# 60 runs of a few ms each: about 0.4 s of integration per thread
JOBS = [(os.path.join(SOURCE, "scenarios", "force_regulation.yaml"), {"output.interval": 0.5})] * 60


def work():
    musclesim.run_many(JOBS, threads=1)


def serial_and_parallel_seconds():
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


def test_two_threads_take_less_time_than_one_after_the_other():
    assert (os.cpu_count() or 1) >= 2, "two threads in parallel need two cores"
    work()  # warm caches and the allocator before timing
    # held, the GIL would make two threads take as long as the serial calls (ratio >= 1);
    # released, about 0.5 on two idle cores. Below 0.8 in the best of 5 tries tells the two
    # apart with room for a busy moment; a machine busy throughout with other work (another
    # build) leaves no core free and fails it: ctest runs it alone (RUN_SERIAL) for that
    # reason, and test_sweep's ticker shows the GIL released whatever the load.
    ratios = []
    for _ in range(5):
        serial, parallel = serial_and_parallel_seconds()
        ratios.append(parallel / serial)
        if ratios[-1] < 0.8:
            break
    assert min(ratios) < 0.8, ratios
