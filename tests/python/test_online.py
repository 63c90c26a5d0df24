"""wpg.OnlineGenerator: the online API, one control period per step()."""
import os
import pathlib
import re

import numpy as np
import pytest

import wpg


def test_steps_follow_the_offline_walk_of_the_same_command():
    # generateWalk is a loop over the same online generator: a constant command from t = 0
    # gives, step by step, the samples of the offline walk with that reference.
    command = (0.2, 0.0, 0.05)
    offline = wpg.run("walk_forward", overrides={
        "duration": 3, "reference": [{"t": 0.0, "v": list(command)}]})
    gen = wpg.OnlineGenerator("walk_forward")
    assert gen.time == 0.0 and gen.control_period == 0.005
    n = len(offline.time) - 1  # the last sample of a walk is its closing sample
    states = [gen.step(command=command) for _ in range(n)]
    assert np.array_equal(np.array([s.time for s in states]), offline.time[:n])
    assert np.array_equal(np.array([s.com for s in states]), offline.com[:n])
    assert np.array_equal(np.array([s.cop for s in states]), offline.cop[:n])
    assert np.array_equal(np.array([s.left_foot for s in states]), offline.left_foot[:n])
    assert np.array_equal(np.array([s.right_foot for s in states]), offline.right_foot[:n])
    codes = {"double": 0, "left": 1, "right": 2}
    assert np.array_equal(np.array([codes[s.support] for s in states]), offline.support[:n])
    assert {s.status for s in states} == {"solved"}
    assert sum(s.nmpc_sample for s in states) == len(offline.mpc)
    np.testing.assert_array_equal(gen.command, command)


def test_the_online_example_of_the_docs_recovers_its_push():
    # docs/python.md's online example, run as written: walking towards a circle and pushed
    # forward (30 N for 0.1 s at 3 s) while it slides along the circle's border. The step that
    # catches the push must land beyond that border (the landing's own half-plane).
    docs = pathlib.Path(os.environ["WPG_DATA_DIR"]) / "docs" / "python.md"
    blocks = re.findall(r"```python\n(.*?)```", docs.read_text(), re.S)
    example = next(b for b in blocks if "gen.push(" in b)
    assert "force=(30, 0)" in example and "set_obstacles" in example
    names = {"wpg": wpg}
    exec(example, names)
    assert names["s"].status == "solved"
    assert names["gen"].time == pytest.approx(10.0)


def test_a_push_is_the_scenario_push_of_the_offline_walk():
    # 60 N forward at 3 s while walking at 0.2 m/s: the robot falls at 4.2 s, online as offline.
    offline = wpg.run("walk_forward", overrides={
        "duration": 5, "reference": [{"t": 0.0, "v": [0.2, 0, 0]}],
        "pushes": [{"t": 3.0, "force": [60, 0], "duration": 0.1}]})
    assert offline.success is False and offline.mpc.status.iloc[-1] == "fallen"
    gen = wpg.OnlineGenerator("walk_forward")
    states = []
    for k in range(len(offline.time) - 1):
        if k == 600:
            gen.push(force=(60, 0), duration=0.1)
        states.append(gen.step(command=(0.2, 0.0, 0.0)))
    assert np.array_equal(np.array([s.com for s in states]), offline.com[:len(states)])
    assert not any(s.fallen for s in states)
    # The offline walk ends at the fall (its closing sample): the next step falls, and stays.
    assert offline.time[-1] == pytest.approx(4.2)
    for _ in range(3):
        s = gen.step(command=(0.2, 0.0, 0.0))
        assert s.fallen and s.status == "fallen" and s.time == offline.time[-1]


def test_a_push_moves_the_com_by_its_impulse():
    still, pushed = wpg.OnlineGenerator("walk_forward"), wpg.OnlineGenerator("walk_forward")
    for _ in range(20):
        still.step()
        pushed.step()
    pushed.push(force=(60, 0), duration=0.1)
    a = [still.step() for _ in range(21)]
    b = [pushed.step() for _ in range(21)]
    # 60 N on 56.037 kg (the scenario's robot_mass) during the 20 periods of 0.1 s, then
    # nothing: the CoM velocity gains the impulse over the mass, 6 N s / m (the NMPC's own
    # reaction starts at the sampling instant after the push).
    accelerations = np.array([s.com_acc[0] - r.com_acc[0] for s, r in zip(b, a)])
    assert accelerations[:20] == pytest.approx(60 / 56.037, rel=1e-12)
    assert b[19].com_vel[0] - a[19].com_vel[0] == pytest.approx(60 / 56.037 * 0.095, rel=1e-9)
    assert b[-1].com_vel[0] - a[-1].com_vel[0] == pytest.approx(6 / 56.037, rel=1e-9)
    assert b[-1].com[0] > a[-1].com[0]


def test_obstacles_are_checked_as_a_scenario_list():
    gen = wpg.OnlineGenerator("walk_forward")
    gen.set_obstacles([{"type": "circle", "center": np.array([1.5, 0.0]), "radius": 0.3,
                        "margin": 0.2}])
    with pytest.raises(wpg.InputError, match=r"obstacles\[0\]\.radius"):
        gen.set_obstacles([{"type": "circle", "center": [1.5, 0.0], "radius": -0.3}])
    gen.set_obstacles([])
    with pytest.raises(wpg.InputError, match="command"):
        gen.step(command=(0.1, 0.0))
    with pytest.raises(wpg.InputError, match="duration"):
        gen.push(force=(10, 0), duration=0)


def test_walking_into_an_obstacle_keeps_the_steps_outside_it():
    gen = wpg.OnlineGenerator("walk_forward")
    gen.set_obstacles([{"type": "circle", "center": [1.0, 0.0], "radius": 0.2, "margin": 0.1}])
    feet = []
    for _ in range(int(12 / gen.control_period)):
        s = gen.step(command=(0.25, 0.0, 0.0))
        feet.append(s.left_foot[:2])
        feet.append(s.right_foot[:2])
    distance = np.linalg.norm(np.array(feet) - [1.0, 0.0], axis=1)
    assert distance.min() > 0.2  # no ankle ever inside the obstacle


def test_reset():
    gen = wpg.OnlineGenerator("walk_forward")
    for _ in range(100):
        gen.step(command=(0.2, 0, 0))
    gen.reset((1.0, 2.0, 0.0))
    s = gen.step()
    assert gen.time == pytest.approx(0.005)
    assert s.com[:2] == pytest.approx([1.0, 2.0])


@pytest.mark.parametrize("call, message", [
    (lambda g: g.push((50.0, 0.0), duration=1e17),
     "push: duration: expected a positive number of seconds, at most 3600 (the longest walk), "
     "got 1e+17"),
    (lambda g: g.push((50.0, 0.0), duration=0.0),
     "push: duration: expected a positive number of seconds, at most 3600 (the longest walk), "
     "got 0"),
    (lambda g: g.push((1e30, 0.0)),
     "push: force: expected 2 finite numbers of at most 100000 N in magnitude, got (1e+30, 0)"),
    (lambda g: g.reset(pose=(1e300, 0.0, 0.0)),
     "reset: pose: expected (x, y, yaw) with x and y of at most 10000 m and yaw of at most "
     "10000 rad in magnitude, got (1e+300, 0, 0)"),
    (lambda g: g.reset(pose=(0.0, 0.0, float("nan"))),
     "reset: pose: expected (x, y, yaw) with x and y of at most 10000 m and yaw of at most "
     "10000 rad in magnitude, got (0, 0, nan)"),
])
def test_bad_online_arguments_are_one_clear_error(call, message):
    """Bad input: one line naming the argument and what was expected, the generator unchanged."""
    gen = wpg.OnlineGenerator("walk_forward")
    for _ in range(10):
        gen.step(command=(0.2, 0, 0))
    with pytest.raises(wpg.InputError) as error:
        call(gen)
    assert str(error.value) == message
    assert gen.time == pytest.approx(0.05)


def test_a_long_push_acts_until_it_ends():
    """A push of the longest walk's duration is not dropped: it still pushes after 1 s."""
    pushed, free = wpg.OnlineGenerator("walk_forward"), wpg.OnlineGenerator("walk_forward")
    pushed.push((30.0, 0.0), duration=3600.0)
    for _ in range(200):
        a, b = pushed.step(), free.step()
    assert a.com[0] - b.com[0] > 1e-3


def test_each_nmpc_step_carries_its_plan():
    offline = wpg.run("walk_forward", overrides={
        "duration": 2, "reference": [{"t": 0.0, "v": [0.2, 0.0, 0.0]}]})
    gen = wpg.OnlineGenerator("walk_forward")
    states = [gen.step(command=(0.2, 0.0, 0.0)) for _ in range(len(offline.time) - 1)]
    plans = [s.plan for s in states if s.nmpc_sample]
    assert all(s.plan is None for s in states if not s.nmpc_sample)
    assert len(plans) == len(offline.plans)
    for i, plan in enumerate(plans):
        n = plan["sample_count"]
        np.testing.assert_array_equal(plan["com"][:n], offline.plans.com[i][:n])
        np.testing.assert_array_equal(plan["steps"], offline.plans.steps[i])
        assert plan["time"] == offline.mpc["time"][i]
