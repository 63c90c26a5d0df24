"""The NMPC's registered extensions from Python: wpg.families() and wpg.costs() list them with
their parameters and units; their names work in wpg.run(overrides=...) and OnlineGenerator."""
import numpy as np
import pytest

import wpg


def test_families_and_costs_list_wpgs_own_with_units():
    families = {f["name"]: f for f in wpg.families()}
    costs = {c["name"]: c for c in wpg.costs()}
    corridor = {p["name"]: p for p in families["corridor"]["parameters"]}
    assert set(corridor) == {"left", "right", "cop_margin"}
    assert corridor["left"]["unit"] == "m" and corridor["left"]["required"]
    assert corridor["cop_margin"]["default"] == 0.005 and not corridor["cop_margin"]["required"]
    look_at = {p["name"]: p for p in costs["look_at"]["parameters"]}
    assert look_at["x"]["unit"] == "m"
    assert look_at["weight"]["unit"] == "1/rad^2" and look_at["weight"]["default"] == 100.0


def test_a_corridor_by_override_holds_the_walk():
    # The walk drifts to the left at 0.05 m/s; the override's left wall stops the feet there.
    command = {"duration": 8, "reference": [{"t": 0.0, "v": [0.2, 0.05, 0.0]}]}
    free = wpg.run("walk_forward", overrides=command)
    walled = wpg.run("walk_forward", overrides=dict(command, **{
        "constraints.corridor.left": 0.15, "constraints.corridor.right": -0.3}))
    assert free.footsteps["y"].max() > 0.2
    assert walled.success
    assert walled.footsteps["y"].max() <= 0.15 + 1e-9
    # the CoP at the NMPC samples (every 0.1 s, 20 control periods; between them the LIPM's
    # CoP may pass by a millimetre, as it may leave the margin-reduced support polygon)
    assert walled.cop[::20, 1].max() <= 0.15 + 1e-9


def test_the_online_generator_takes_the_look_at_cost():
    # Facing a point to the left while walking straight on: the feet turn towards it.
    gen = wpg.OnlineGenerator("walk_forward", overrides={"costs.look_at.x": 1.0,
                                                         "costs.look_at.y": 3.0,
                                                         "costs.look_at.weight": 400.0})
    plain = wpg.OnlineGenerator("walk_forward")
    for _ in range(600):
        s = gen.step(command=(0.1, 0.0, 0.0))
        p = plain.step(command=(0.1, 0.0, 0.0))
    assert s.status == "solved"
    assert abs(p.left_foot[3]) < 0.01
    assert s.left_foot[3] > 0.1  # turned left, towards the point


def test_a_bad_parameter_names_its_key():
    with pytest.raises(wpg.InputError, match=r"key 'constraints.corridor.right': missing"):
        wpg.run("walk_forward", overrides={"constraints.corridor.left": 0.2})
    with pytest.raises(wpg.InputError, match=r"did you mean 'look_at'"):
        wpg.OnlineGenerator("walk_forward", overrides={"costs.lookat.x": 2.0})
