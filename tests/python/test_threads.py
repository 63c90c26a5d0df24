"""Walks release the GIL: Python threads run them in parallel, with the results of one at a time."""
import threading

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
    # With the GIL held for the whole walk this loop would not get to run until it ended.
    done = threading.Event()
    thread = threading.Thread(target=lambda: (wpg.run("walk_forward",
                                                      overrides={"duration": 30}), done.set()))
    thread.start()
    turns = 0
    while not done.is_set() and thread.is_alive():
        turns += 1
    thread.join()
    assert turns > 1000
