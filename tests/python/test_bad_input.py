"""Bad input: wpg.InputError (a ValueError) with the CLI's one-line message naming the key, and
nothing written."""
import os

import pytest

import wpg
from conftest import STUDIES, files_under


@pytest.mark.parametrize("value", [-1, 22000])
def test_a_bad_value_names_the_key_as_the_cli_does(cli, tmp_path, value):
    """The CLI's line, the override named as Python's (`overrides`, not `--set`): for a value
    its reader refuses (-1) and one a check over several keys refuses (22000 s, over 3600)."""
    with pytest.raises(wpg.InputError) as error:
        wpg.run("walk_forward", overrides={"duration": value})
    message = str(error.value)
    assert "walk_forward.yaml" in message and "'duration'" in message and "\n" not in message
    assert message.endswith("(set by overrides 'duration=%d')" % value), message
    assert "--set" not in message
    done = cli("run", "walk_forward", "--set", "duration=%d" % value, "-o", tmp_path / "x.h5",
               check=False)
    assert done.returncode == 2
    assert message.replace("overrides 'duration", "--set 'duration") in done.stderr
    assert isinstance(error.value, ValueError)
    with pytest.raises(wpg.InputError) as online:
        wpg.OnlineGenerator("walk_forward", overrides={"duration": value})
    assert str(online.value) == message


@pytest.mark.parametrize("overrides, key", [
    ({"walking.no_such_key": 1}, "walking.no_such_key"),
    ({"reference[1].v": [0.3, 0]}, "reference[1].v"),
    ({"generator.algorithm": "quantum"}, "generator.algorithm"),
    ({"duration": float("nan")}, "duration"),
    ({"duration": object()}, "duration"),
    ({"": 1}, "''"),
])
def test_bad_overrides(overrides, key):
    with pytest.raises(wpg.InputError, match=r".*" + __import__("re").escape(key)):
        wpg.run("walk_forward", overrides=overrides)


def test_bad_scenarios(tmp_path):
    with pytest.raises(wpg.InputError, match="no shipped scenario of that name"):
        wpg.run("no_such_scenario")
    with pytest.raises(wpg.InputError, match="it is a directory"):
        wpg.run(tmp_path)
    with pytest.raises(wpg.InputError, match="overrides: expected a dict"):
        wpg.run("walk_forward", overrides=["duration=3"])


def test_save_refuses_bad_paths_and_writes_nothing(tmp_path):
    run = wpg.run("walk_forward", overrides={"duration": 1})
    text = tmp_path / "notes.txt"
    text.write_text("mine")
    with pytest.raises(wpg.InputError, match="notes.txt"):
        run.save(text)  # exists and is not HDF5: never replaced
    assert text.read_text() == "mine"
    with pytest.raises(wpg.InputError):
        run.save(tmp_path)  # a folder
    with pytest.raises(wpg.InputError):
        run.save("/dev/null")
    with pytest.raises(wpg.InputError):
        run.save(wpg._wpg.resolve_scenario("walk_forward"))  # an input
    assert files_under(tmp_path) == ["notes.txt"]


def test_a_bad_study_writes_nothing(tmp_path):
    study = tmp_path / "bad.yaml"
    study.write_text("name: bad\nbase: walk_forward\nsweep:\n  grid:\n    duration: [2.0, -1.0]\n")
    out = tmp_path / "out"
    with pytest.raises(wpg.InputError, match="duration"):
        wpg.batch(study, output=out / "b.h5", jobs=2)
    with pytest.raises(wpg.InputError, match="no such file"):
        wpg.batch(tmp_path / "missing.yaml", output=out / "b.h5")
    with pytest.raises(wpg.InputError, match="jobs"):
        wpg.batch(os.path.join(STUDIES, "tiny.yaml"), output=out / "b.h5", jobs=0)
    with pytest.raises(wpg.InputError, match="unknown key"):
        wpg.compare(os.path.join(STUDIES, "tiny.yaml"), output=out)
    assert files_under(tmp_path) == ["bad.yaml"]


def test_bad_files_to_read(tmp_path):
    with pytest.raises(wpg.InputError, match="missing.h5"):
        wpg.io.load_run(tmp_path / "missing.h5")
    junk = tmp_path / "junk.h5"
    junk.write_bytes(b"not hdf5 at all")
    with pytest.raises(wpg.InputError, match="junk.h5"):
        wpg.io.load_run(junk)
    with pytest.raises(wpg.InputError, match="junk.h5"):
        wpg.io.load_summary(junk)
