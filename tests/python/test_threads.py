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


SHARED_GENERATOR = """
import threading, wpg
gen = wpg.OnlineGenerator("walk_forward")
period = gen.control_period
errors = []

def stepping(steps):
    try:
        for _ in range(steps):
            gen.step(command=(0.2, 0.0, 0.0))
    except Exception as error:
        errors.append(error)

threads = [threading.Thread(target=stepping, args=(150,)) for _ in range(4)]
for thread in threads: thread.start()
for thread in threads: thread.join()
# Each step one whole control period: 600 of them, whatever the threads' interleaving.
assert not errors, errors
assert abs(gen.time - 600 * period) < 1e-9, gen.time

def resetting():
    for i in range(100):
        gen.reset(pose=(0.01 * i, 0.0, 0.0))
        gen.push((50.0, 0.0), duration=0.05)
        gen.set_obstacles([])

threads = [threading.Thread(target=stepping, args=(150,)) for _ in range(3)]
threads.append(threading.Thread(target=resetting))
for thread in threads: thread.start()
for thread in threads: thread.join()
assert not errors, errors
state = gen.step()
assert all(abs(v) < 1e3 for v in state.com), state.com
print("ok")
"""


def test_one_generator_shared_by_threads_steps_one_period_at_a_time():
    """Threads stepping, resetting and pushing one OnlineGenerator: each call whole (a lock per
    generator), never a crash or a step lost. Run in a child process: a double free kills it."""
    import subprocess
    done = subprocess.run([sys.executable, "-c", SHARED_GENERATOR], capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0 and done.stdout.strip() == "ok", (done.returncode, done.stderr)
