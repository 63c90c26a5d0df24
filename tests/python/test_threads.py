"""Walks release the GIL: Python threads run them in parallel, with the results of one at a time."""
import sys
import threading
import time

import numpy as np

import wpg

SPEEDS = ([0.2, 0, 0], [0.3, 0.05, 0.1])


def walk(speed):
    return wpg.run("walk_forward", overrides={"duration": 5, "reference[1].v": speed})


def same_walk(a, b):
    for name in ("time", "com", "com_vel", "cop", "left_foot", "right_foot", "support"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert a.footsteps.equals(b.footsteps)
    assert a.mpc.drop(columns="solve_time").equals(b.mpc.drop(columns="solve_time"))


def test_two_threads_give_the_results_of_one_at_a_time():
    alone = [walk(speed) for speed in SPEEDS]
    results = [None, None]

    def work(i):
        results[i] = walk(SPEEDS[i])
    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for a, b in zip(alone, results):
        same_walk(a, b)
    assert not np.array_equal(results[0].com, results[1].com)


def test_python_runs_while_a_walk_runs():
    # A second thread counts, handing the GIL back at every turn (sleep(0)). With a switch
    # interval of 100 s this thread is never asked to drop the GIL between its own statements, so
    # the count can move between `before` and `after` only if the walk releases the GIL (checked:
    # a regular expression that holds it gives 0, a sleep thousands). No timing is asserted.
    count = [0]
    stop = [False]

    def spin():
        while not stop[0]:
            count[0] += 1
            time.sleep(0)
    interval = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    try:
        thread = threading.Thread(target=spin)
        thread.start()
        while count[0] == 0:
            time.sleep(0.001)
        before = count[0]
        wpg.run("walk_forward", overrides={"duration": 60})
        after = count[0]
        stop[0] = True
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    assert after > before, "no Python turn while the walk ran"
