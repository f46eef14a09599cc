# SPDX-License-Identifier: BSD-3-Clause
"""Long calls give up the GIL and stop on Ctrl-C (issue 40, item 7): the analysis runs on a
worker thread while the caller checks for signals every 50 ms."""

import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np

import kinestat

# A square grid of bars with its bottom row fixed: a mechanism with many modes (one per row of
# cells, at least), so the dense analysis and its second-order classification take seconds.
CHILD = r"""
import sys, time
import numpy as np
import kinestat

def grid(n):
    nodes = np.array([(i, j) for j in range(n) for i in range(n)], dtype=float)
    bars = [(j * n + i, j * n + i + 1) for j in range(n) for i in range(n - 1)]
    bars += [(j * n + i, (j + 1) * n + i) for j in range(n - 1) for i in range(n)]
    return kinestat.Framework(nodes, bars=bars, supports={i: "fixed" for i in range(n)})

model = grid(int(sys.argv[1]))
text = model.to_json()
print("start", flush=True)
started = time.monotonic()
try:
    kinestat.analyze(model)
    print("finished", time.monotonic() - started, flush=True)
except KeyboardInterrupt:
    print("interrupted", time.monotonic() - started, flush=True)
# The module still works after an interrupted call: a triangle, rigid by hand (3 bars, 6 - 3 = 3
# coordinates after fixing one node and one direction of another).
triangle = kinestat.Framework([[0, 0], [1, 0], [0, 1]], bars=[[0, 1], [1, 2], [2, 0]], supports={0: "fixed", 1: ["y"]})
result = kinestat.analyze(triangle)
print("after", result.mechanisms, result.self_stresses, flush=True)
"""

GRID = 26  # 676 nodes, 1,300 bars: D(c) 1,300 x 1,300, dense path


def grid(n):
    nodes = np.array([(i, j) for j in range(n) for i in range(n)], dtype=float)
    bars = [(j * n + i, j * n + i + 1) for j in range(n) for i in range(n - 1)]
    bars += [(j * n + i, (j + 1) * n + i) for j in range(n - 1) for i in range(n)]
    return kinestat.Framework(nodes, bars=bars, supports={i: "fixed" for i in range(n)})


def test_ctrl_c_stops_a_long_analysis_within_a_second():
    child = subprocess.Popen([sys.executable, "-c", CHILD, str(GRID)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=os.environ.copy())
    try:
        assert child.stdout.readline().strip() == "start"
        time.sleep(1.0)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        line = child.stdout.readline().split()
        returned = time.monotonic() - sent
        # "finished" would mean the analysis ended before the signal: the model is too small.
        assert line and line[0] == "interrupted", (line, child.stderr.read() if child.poll() is not None else "")
        assert returned < 2.0, f"KeyboardInterrupt {returned:.2f} s after SIGINT"
        assert child.stdout.readline().split() == ["after", "0", "0"]
        assert child.wait(timeout=300) == 0
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()


def test_other_threads_run_while_an_analysis_is_in_progress():
    model = grid(GRID)
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.005)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        started = time.monotonic()
        result = kinestat.analyze(model)
        ended = time.monotonic()
    finally:
        done.set()
        ticker.join()
    # By hand: (n - 1)^2 open square cells over a fixed row; 2 n (n - 1) free coordinates,
    # 2 n (n - 1) bars, and the grid of squares moves: every horizontal row of bars shears.
    assert result.mechanisms >= GRID - 1
    assert ended - started > 0.5, "the analysis must be long enough to show anything"
    during = [t for t in ticks if started < t < ended]
    gaps = np.diff([started, *during, ended])
    # Holding the GIL, the analysis would leave one gap as long as itself.
    assert gaps.max() < 0.25, f"the ticker stopped for {gaps.max():.2f} s of a {ended - started:.2f} s analysis"


def test_analyses_from_several_threads_give_the_results_of_one_thread():
    # Calls from other threads wait for their turn in the library (its orderings share state):
    # every thread gets the JSON report a lone call gives, byte for byte.
    models = [grid(12), grid(13), kinestat.Framework(np.c_[np.arange(40.0), np.zeros(40)], bars=np.c_[np.arange(39), np.arange(1, 40)])]
    alone = [kinestat.analyze(model).to_json() for model in models]
    together = [None] * (2 * len(models))

    def run(slot):
        together[slot] = kinestat.analyze(models[slot % len(models)]).to_json()

    threads = [threading.Thread(target=run, args=(slot,)) for slot in range(len(together))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert together == alone + alone
