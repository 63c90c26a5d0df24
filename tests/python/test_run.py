"""wpg.run and wpg.Run: the contract, against the files and numbers of the `wpg` CLI."""
import json

import numpy as np
import pandas as pd
import pytest

import wpg

OVERRIDES = {"duration": 6, "reference[1].v": [0.3, 0, 0]}
CLI_SET = ["--set", "duration=6", "--set", "reference[1].v=[0.3, 0, 0]"]


@pytest.fixture(scope="module")
def walk():
    return wpg.run("walk_forward", overrides=OVERRIDES)


def owner_of(array):
    while isinstance(array.base, np.ndarray):
        array = array.base
    return array.base


def test_arrays_have_the_contract_shapes_and_view_the_run(walk):
    assert walk.success is True and walk.exit_code == 0 and walk.outcome == "succeeded"
    n = len(walk.time)
    assert n == 6 / 0.005 + 1
    assert walk.com.shape == (n, 3) and walk.cop.shape == (n, 2)
    assert walk.left_foot.shape == (n, 4) and walk.right_foot.shape == (n, 4)
    assert walk.com.dtype == np.float64 and walk.support.dtype == np.uint8
    # Views of the C++ result, not copies: owned by the run's core, read-only.
    for array in (walk.time, walk.com, walk.cop, walk.left_foot, walk.support):
        assert owner_of(array) is walk._core
        assert not array.flags.writeable
    with pytest.raises(ValueError):
        walk.com[0, 0] = 1.0
    # Physical sense: the CoM height is the walking parameter, time runs at 5 ms.
    assert np.allclose(np.diff(walk.time), 0.005)
    assert np.all(walk.com[:, 2] == walk.com[0, 2]) and 0.7 < walk.com[0, 2] < 0.9
    assert walk.com[-1, 0] > 0.8  # walked forward at 0.3 m/s for ~4 s


def test_the_views_outlive_the_run_object():
    com = wpg.run("walk_forward", overrides={"duration": 2}).com
    import gc
    gc.collect()
    assert com.shape[1] == 3 and np.all(np.isfinite(com))


def test_tables(walk):
    steps = walk.footsteps
    assert list(steps.columns) == ["landing_time", "x", "y", "yaw", "side"]
    assert set(steps.side) == {"left", "right"}
    assert (steps.landing_time.iloc[:2] == 0).all() and steps.landing_time.is_monotonic_increasing
    mpc = walk.mpc
    assert len(mpc) == walk.metrics["nmpc_iterations"]
    assert mpc.status.dtype == object and set(mpc.status) <= {"solved", "relaxed_obstacle"}
    for column in ("solve_time", "qp_iterations", "sqp_iterations", "cost", "slack_cop",
                   "slack_obstacle"):
        assert column in mpc.columns
    assert mpc.attrs["units"]["slack_yaw_bound"] == "rad"
    assert mpc.qp_iterations.sum() == walk.metrics["qp_iterations_total"]


def test_save_writes_the_cli_dataset_and_metrics_match_analyze(walk, cli, tmp_path):
    mine, theirs = tmp_path / "python.h5", tmp_path / "cli.h5"
    walk.save(mine)
    cli("run", "walk_forward", *CLI_SET, "-o", theirs, "--no-plot")
    done = cli("diff", "--rtol", "0", "--atol", "0", theirs, mine)
    assert done.returncode == 0, done.stdout + done.stderr
    analyzed = json.loads(cli("analyze", "--format", "json", theirs).stdout)["walk_forward"]
    metrics = walk.metrics
    assert list(metrics) == list(analyzed)
    wall = {name for name, *_rest in wpg._wpg.metric_table() if _rest[-1]}
    assert wall == {"nmpc_time_mean", "nmpc_time_std", "nmpc_time_min", "nmpc_time_max",
                    "nmpc_time_p99"}
    for name, value in analyzed.items():
        if name in wall:
            continue
        if value is None:
            assert np.isnan(metrics[name]), name
        else:
            assert metrics[name] == value, name


def test_a_failed_walk_is_a_result(cli, tmp_path):
    # A 600 N push for 0.3 s knocks the standing robot over: the NMPC reports the fall.
    over = {"duration": 4, "pushes": [{"t": 1.0, "force": [600, 0], "duration": 0.3}]}
    run = wpg.run("push_standing", overrides=over)
    assert run.success is False and run.exit_code == 1 and run.outcome == "walk_failed"
    assert run.message and (run.mpc.status != "solved").any()
    run.save(tmp_path / "failed.h5")
    done = cli("run", "push_standing", "--set", "duration=4", "--set",
               "pushes=[{t: 1.0, force: [600, 0], duration: 0.3}]", "-o", tmp_path / "cli.h5",
               "--no-plot")
    assert done.returncode == 1  # the CLI's exit status for the same walk
    assert cli("diff", tmp_path / "cli.h5", tmp_path / "failed.h5").returncode == 0


def test_a_blocked_walk_says_so_and_reads_back_the_same(cli, tmp_path):
    # The wall with no way round (3.6 m aside, beyond generator.max_detour): the robot steps in
    # place in front of its margin, every NMPC iteration solved; the walk ends blocked (exit 1),
    # since the start of the first window without progress.
    run = wpg.run("obstacle_wall")
    assert run.outcome == "blocked" and run.blocked is True
    assert run.success is False and run.exit_code == 1
    assert set(run.mpc.status) == {"solved"}
    assert run.blocked_since == pytest.approx(8.9, abs=1e-9)
    i = int(np.argmin(abs(run.time - run.blocked_since)))
    assert run.blocked_position == tuple(run.com[i, :2])
    assert run.message.startswith("the robot is blocked: ") and "since t = 8.9 s" in run.message
    metrics = run.metrics
    assert metrics["blocked"] == 1 and metrics["blocked_since"] == run.blocked_since
    assert 0.2 < metrics["progress_ratio"] < 0.3
    # The commanded velocity the progress is measured along: 0.2 m/s along x from 1 s on.
    mpc = run.mpc
    assert (mpc.commanded_vx[mpc.time >= 1.0] == 0.2).all() and (mpc.commanded_vy == 0).all()
    run.save(tmp_path / "wall.h5")
    back = wpg.io.load_run(tmp_path / "wall.h5")
    assert back.outcome == "blocked" and back.blocked_since == run.blocked_since
    assert back.blocked_position == run.blocked_position
    assert back.metrics["progress_ratio"] == metrics["progress_ratio"]
    # A walk that makes progress: not blocked, nothing to say where.
    walk = wpg.run("walk_forward", overrides={"duration": 6})
    assert walk.outcome == "succeeded" and walk.blocked is False
    assert walk.blocked_since is None and walk.blocked_position is None
    assert walk.metrics["blocked"] == 0 and np.isnan(walk.metrics["blocked_since"])
    assert 0.7 < walk.metrics["progress_ratio"] < 0.8  # 0.76: the start from rest lags the command


def test_replay_and_filter_add_the_multibody_arrays(cli, tmp_path):
    run = wpg.run("walk_forward", overrides={"duration": 3}, replay=True, filter=True)
    n = len(run.time)
    assert run.success
    assert run.q.shape == (n, 37) and run.zmp_multibody.shape == (n, 2)
    assert run.com_filtered.shape == (n, 3) and run.zmp_multibody_filtered.shape == (n, 2)
    assert owner_of(run.q) is run._core
    assert len(run.replay["configuration_names"]) == 37
    # The filter brings the multibody ZMP closer to the reference CoP (paper Fig. 6).
    before = np.sqrt(np.mean(np.sum((run.zmp_multibody - run.cop) ** 2, axis=1)))
    after = np.sqrt(np.mean(np.sum((run.zmp_multibody_filtered - run.cop) ** 2, axis=1)))
    assert np.isclose(before, run.metrics["zmp_error_rms_before"], rtol=1e-12)
    assert after < before
    plain = wpg.run("walk_forward", overrides={"duration": 3})
    assert plain.q is None and plain.replay == {}
    run.save(tmp_path / "filtered.h5")
    cli("run", "walk_forward", "--set", "duration=3", "--filter", "-o", tmp_path / "cli.h5",
        "--no-plot")
    done = cli("diff", tmp_path / "cli.h5", tmp_path / "filtered.h5")
    assert done.returncode == 0, done.stdout


def test_a_scenario_file_and_overrides_of_every_kind(tmp_path):
    path = tmp_path / "mine.yaml"
    path.write_text("name: mine\nrobot: hrp2\nduration: 2.0\n"
                    "reference:\n  - {t: 0.0, v: [0.0, 0.0, 0.0]}\n")
    run = wpg.run(path, overrides={"walking.com_height": np.float64(0.8), "replay": False,
                                   "reference": [{"t": 0.0, "v": np.array([0.1, 0.0, 0.0])}]})
    assert run.name == "mine" and run.com[0, 2] == 0.8
    assert "com_height: 0.8" in run.scenario


def test_the_figure_is_the_cli_figure(walk):
    import matplotlib.figure
    figure = walk.figure()
    assert isinstance(figure, matplotlib.figure.Figure)
    titles = [text.get_text() for ax in figure.axes for text in ax.texts]
    assert any("run walk_forward" in title for title in titles)


def test_the_plan_figure_is_the_cli_one(walk):
    import matplotlib.figure
    figure = walk.figure(plan=True, at=[3.0])
    assert isinstance(figure, matplotlib.figure.Figure)
    legends = [t.get_text() for ax in figure.axes if ax.get_legend()
               for t in ax.get_legend().get_texts()]
    assert "preview at t = 3.0 s (16 samples, 2 steps)" in legends, legends
    titles = [ax.get_title() for ax in figure.axes]
    assert any(t.startswith("prediction error over %d iterations" % len(walk.mpc))
               for t in titles), titles


def test_scenarios_are_the_shipped_files():
    import os
    names = wpg.scenarios()
    shipped = sorted(f[:-5] for f in os.listdir(os.path.join(wpg.data_directory(), "datasets",
                                                             "scenarios")) if f.endswith(".yaml"))
    assert names == shipped and "walk_forward" in names


def test_docstrings():
    for function in (wpg.run, wpg.batch, wpg.compare, wpg.scenarios, wpg.io.load_run,
                     wpg.io.load_summary, wpg.OnlineGenerator.step, wpg.Run.save,
                     wpg.Run.figure, wpg.OnlineGenerator.push, wpg.OnlineGenerator.set_obstacles):
        assert function.__doc__ and len(function.__doc__) > 40, function
    assert issubclass(wpg.InputError, ValueError) and isinstance(pd.DataFrame(), pd.DataFrame)


def test_a_clamped_command_warns_and_walks_as_the_clamp(tmp_path):
    # 2.0 m/s is beyond HRP-2's 0.4 m/s clamp: one UserWarning naming the key, kept in
    # run.warnings and in the saved dataset; the walk is that of 0.4 m/s.
    with pytest.warns(UserWarning, match=r"key 'reference\[1\]\.v\[0\]': 2\.0 m/s is beyond"):
        fast = wpg.run("walk_forward", overrides={"duration": 2, "reference[1].v": [2.0, 0, 0]})
    assert len(fast.warnings) == 1 and "clamped to 0.4 m/s" in fast.warnings[0]
    clamped = wpg.run("walk_forward", overrides={"duration": 2, "reference[1].v": [0.4, 0, 0]})
    assert clamped.warnings == []
    assert np.array_equal(fast.com, clamped.com) and np.array_equal(fast.cop, clamped.cop)
    fast.save(tmp_path / "fast.h5")
    import h5py
    with h5py.File(tmp_path / "fast.h5", "r") as f:
        text = f["runs/walk_forward"].attrs["warnings"]
        text = text.decode() if isinstance(text, bytes) else text
    assert text == fast.warnings[0] + "\n"


def test_plans_predict_the_executed_com_and_read_back_the_same(walk, tmp_path):
    plans = walk.plans
    assert len(plans) == len(walk.mpc)
    k, n = plans.com.shape[:2]
    assert plans.com.shape == (k, n, 2) and plans.steps.shape[2] == 4
    assert plans.active_rows.shape == (k, len(plans.families))
    per = (len(walk.time) - 1) // k  # control periods per NMPC iteration
    executed = walk.com[per::per, :2][:k]
    np.testing.assert_allclose(plans.com[:len(executed), 0], executed, rtol=0, atol=1e-12)
    frame = plans.frame()
    assert len(frame) == plans.sample_count.sum()
    np.testing.assert_allclose(frame.sample_time, frame.time + frame["sample"] * 0.1)
    walk.save(tmp_path / "run.h5")
    back = wpg.io.load_run(tmp_path / "run.h5")
    for name in ("sample_count", "com", "com_vel", "com_acc", "jerk", "cop", "steps",
                 "step_side", "active_rows"):
        np.testing.assert_array_equal(getattr(back.plans, name), getattr(plans, name))
    off = wpg.run("walk_forward", overrides=dict(OVERRIDES, **{"generator.record_plan": False}))
    assert off.plans is None
    np.testing.assert_array_equal(off.com, walk.com)


def test_route_plans_of_a_walk_to_a_goal(walk, tmp_path):
    run = wpg.run("goal_with_yaw")
    plans = run.route_plans
    assert len(plans) >= 1 and plans["trigger"][0] == "start", plans
    assert plans["status"][0] == "exact_solution"
    route = plans["route"][0]
    assert route.ndim == 2 and route.shape[1] == 3 and len(route) >= 2
    # The route starts where the robot stood and ends at the goal (3, 1.5), within its tolerance.
    assert np.hypot(*(route[-1, :2] - [3.0, 1.5])) < 0.1, route[-1]
    assert plans.attrs["units"]["route"] == "m, m, rad"
    # Read back: the file's plans/ group, the same numbers (wall times included: stored).
    run.save(tmp_path / "goal.h5")
    back = wpg.io.load_run(tmp_path / "goal.h5").route_plans
    assert list(back.columns) == list(plans.columns) and len(back) == len(plans)
    for column in plans.columns:
        for a, b in zip(plans[column], back[column]):
            assert np.array_equal(np.asarray(a), np.asarray(b), equal_nan=not isinstance(a, str)), column
    assert len(walk.route_plans) == 0  # a walk on a velocity command plans nothing
