"""wpg.batch, wpg.compare and reading studies back: the files `wpg batch` / `wpg compare` write."""
import os

import numpy as np
import pytest

import wpg
from conftest import SOURCE, STUDIES, files_under, same_batch_files

TINY = os.path.join(STUDIES, "tiny.yaml")


@pytest.fixture(scope="module")
def batch_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("batch")


@pytest.fixture(scope="module")
def table(batch_dir):
    return wpg.batch(TINY, output=batch_dir / "py2.h5", jobs=2)


def test_batch_equals_the_cli_batch_for_any_jobs(table, batch_dir, cli):
    cli("batch", TINY, "-o", batch_dir / "cli.h5", "-j", "1", "--no-plot")
    same_batch_files(batch_dir / "cli.h5", batch_dir / "py2.h5")
    wpg.batch(TINY, output=batch_dir / "py1.h5", jobs=1)
    same_batch_files(batch_dir / "cli.h5", batch_dir / "py1.h5")
    for suffix in (".summary.csv", ".summary.md"):
        assert (batch_dir / ("py2" + suffix)).is_file()
    assert (batch_dir / "cli.summary.csv").read_text().count("\n") == \
        (batch_dir / "py2.summary.csv").read_text().count("\n")


def test_the_summary_has_typed_swept_columns(table):
    assert len(table) == 4 and list(table["index"]) == [0, 1, 2, 3]
    assert table.attrs["swept_keys"] == ["reference[1].v", "walking.weight_cop", "duration"]
    assert table["sweep.walking.weight_cop"].dtype == np.float64
    assert list(table["sweep.reference[1].v"]) == [(0.1, 0.0, 0.0)] * 2 + [(0.25, 0.05, 0.0)] * 2
    assert list(table["sweep.reference[1].v[1]"]) == [0.0, 0.0, 0.05, 0.05]
    assert table["sweep.reference[1].v[0]"].dtype == np.float64
    assert table["done"].dtype == bool and table["done"].all()
    assert (table["exit_status"] == 0).all() and table.attrs["failed_runs"] == 0
    units = table.attrs["units"]
    assert units["distance"] == "m" and units["sweep.reference[1].v[0]"] == units["sweep.reference[1].v"]
    assert list(table["name"]) == ["tiny_%d" % i for i in range(4)]
    # A faster command walks further.
    assert table["distance"][2] > table["distance"][0]


def test_a_run_read_back_is_the_run(table, batch_dir):
    stored = wpg.io.load_run(batch_dir / "py2.h5", name="tiny_3")
    fresh = wpg.run("walk_forward", overrides={"reference[1].v": [0.25, 0.05, 0],
                                               "walking.weight_cop": 3000.0, "duration": 4.0,
                                               "name": "tiny_3"})
    assert stored.name == "tiny_3" and stored.success
    for name in ("time", "com", "cop", "left_foot", "right_foot", "support"):
        assert np.array_equal(getattr(stored, name), getattr(fresh, name)), name
    assert stored.footsteps.equals(fresh.footsteps)
    assert stored.metrics["distance"] == table["distance"][3]
    assert wpg.io.run_names(batch_dir / "py2.h5") == ["tiny_%d" % i for i in range(4)]
    with pytest.raises(wpg.InputError, match="tiny_9"):
        wpg.io.load_run(batch_dir / "py2.h5", name="tiny_9")
    with pytest.raises(wpg.InputError):
        stored.save(batch_dir / "again.h5")  # already in its file


def test_shards_merged_into_an_index_read_back(table, batch_dir, cli):
    for k in (0, 1):
        cli("batch", TINY, "-o", batch_dir / ("shard%d.h5" % k), "--shard", "%d/2" % k,
            "--no-plot")
    cli("merge", batch_dir / "index.h5", batch_dir / "shard0.h5", batch_dir / "shard1.h5",
        "--no-plot")
    merged = wpg.io.load_summary(batch_dir / "index.h5")
    assert merged.drop(columns=[c for c in merged if c.startswith("nmpc_time")]).equals(
        table.drop(columns=[c for c in table if c.startswith("nmpc_time")]))
    a = wpg.io.load_run(batch_dir / "index.h5", name="tiny_1")  # an external link to shard 1
    b = wpg.io.load_run(batch_dir / "py2.h5", name="tiny_1")
    assert np.array_equal(a.com, b.com)


def test_a_replayed_run_read_back_has_its_multibody_arrays(tmp_path):
    run = wpg.run("walk_forward", overrides={"duration": 2}, replay=True)
    run.save(tmp_path / "r.h5")
    back = wpg.io.load_run(tmp_path / "r.h5")
    assert np.array_equal(back.q, run.q) and np.array_equal(back.zmp_multibody, run.zmp_multibody)
    assert back.com_filtered is None
    assert back.metrics["zmp_error_rms_before"] == run.metrics["zmp_error_rms_before"]


def test_compare_equals_the_cli(tmp_path, cli):
    study = os.path.join(SOURCE, "tests", "cli", "studies", "compare_small.yaml")
    small = tmp_path / "small.yaml"
    # Two seeds of one world and one variant, 20 s: the shape of the CLI's study, faster.
    small.write_text(open(study).read().replace("duration: 40.0", "duration: 20.0")
                     .replace("seeds: 2", "seeds: 1")
                     .replace("  - {name: trap, u_trap: {}}\n", "")
                     .replace("  nmpc_only: {planner.algorithm: none}\n", ""))
    frame = wpg.compare(small, output=tmp_path / "py", jobs=2)
    cli("compare", small, "-o", tmp_path / "cli", "--no-plot")
    same_batch_files(tmp_path / "cli" / "study.h5", tmp_path / "py" / "study.h5")
    assert files_under(tmp_path / "py") == ["study.h5", "summary.csv", "summary.md"]
    assert list(frame["world"]) == ["field"] and list(frame["variant"]) == ["rrtconnect_nmpc"]
    assert frame.attrs["units"]["time_to_goal_median"] == "s"
    assert 0.0 <= frame["success_rate"][0] <= 1.0


def test_a_run_is_found_by_its_unpadded_index(tmp_path):
    study = tmp_path / "ten.yaml"
    study.write_text("name: ten\nbase: walk_forward\nsweep:\n  grid:\n"
                     "    duration: [1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2.0]\n")
    table = wpg.batch(study, output=tmp_path / "ten.h5", jobs=2)
    assert table["name"][3] == "ten_03"
    run = wpg.io.load_run(tmp_path / "ten.h5", name="ten_3")
    assert run.name == "ten_03" and run.time[-1] == pytest.approx(1.3)
    assert wpg.io.load_run(tmp_path / "ten.h5", name="ten_03").name == "ten_03"
    with pytest.raises(wpg.InputError, match="ten_11"):
        wpg.io.load_run(tmp_path / "ten.h5", name="ten_11")
