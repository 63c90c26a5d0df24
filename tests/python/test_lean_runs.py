"""wpg.batch(fields=...): lean runs through the engine's request, as `wpg batch --fields`, and
what wpg.io.load_run says of a lean run (datasets/SCHEMA.md, "Lean runs")."""
import os

import h5py
import numpy as np
import pytest

import wpg
from conftest import STUDIES

TINY = os.path.join(STUDIES, "tiny.yaml")


def test_lean_batch_stores_its_fields_and_the_same_summary(tmp_path):
    full = wpg.batch(TINY, output=tmp_path / "full.h5", jobs=2)
    lean = wpg.batch(TINY, output=tmp_path / "lean.h5", jobs=2, fields="summary, footsteps")
    wall = [c for c in full.columns if c.startswith("nmpc_time")]
    assert full.drop(columns=wall).equals(lean.drop(columns=wall))
    with h5py.File(tmp_path / "lean.h5", "r") as f, h5py.File(tmp_path / "full.h5", "r") as g:
        assert list(f.attrs["fields"]) == ["summary", "footsteps"]
        run = f["runs/tiny_1"]
        assert sorted(run) == ["checks", "footstep_lift_off", "footstep_side", "footsteps"]
        assert np.array_equal(run["footsteps"][()], g["runs/tiny_1/footsteps"][()])


def test_load_run_of_a_lean_run_says_what_it_lacks(tmp_path):
    wpg.batch(TINY, output=tmp_path / "lean.h5", fields=["summary", "com", "footsteps"])
    with pytest.raises(wpg.InputError) as error:
        wpg.io.load_run(tmp_path / "lean.h5", "tiny_2")
    message = str(error.value)
    assert "is a lean run (fields summary, com, footsteps): it lacks cop, feet, mpc" in message
    assert "\n" not in message


@pytest.mark.parametrize("fields, expected", [
    (["summary", "coms"], "fields: 'coms' is not a field; did you mean 'com'?"),
    (["com"], "fields: expected 'summary' among the fields (got com)"),
    ([], "fields: expected a list of fields"),
])
def test_bad_fields_are_refused_before_anything_is_written(tmp_path, fields, expected):
    with pytest.raises(wpg.InputError) as error:
        wpg.batch(TINY, output=tmp_path / "out.h5", fields=fields)
    assert str(error.value).startswith(expected), str(error.value)
    assert list(tmp_path.iterdir()) == []
