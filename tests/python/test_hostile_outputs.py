"""Every hostile-output case of the CLI's output tests (tests/cli/outputs.sh and the
side_outputs, fifo_side_output, folder_kind, second_writer and resume_in_use cases of
tests/cli/hardening_outputs.sh) through the package too: the engine owns the output checks, so
`wpg.run(...).save`, `wpg.batch` and `wpg.compare` refuse what `wpg run`, `wpg batch` and `wpg
compare` refuse, with the same one-line message, before any work and with every file left as it
was. Cases of commands the package does not have (plot, bench, merge, push-sweep) stay in the
CLI's tests."""
import hashlib
import os
import stat
import subprocess
import time

import pytest

import wpg
from conftest import SOURCE

CLI_STUDIES = os.path.join(SOURCE, "tests", "cli", "studies")
SCENARIO = os.path.join(SOURCE, "datasets", "scenarios", "walk_forward.yaml")


def _copy(source, target):
    with open(source, "rb") as f:
        data = f.read()
    with open(target, "wb") as f:
        f.write(data)


def _prepare(folder):
    """The CLI tests' work folder: the scenario and the two small studies."""
    _copy(SCENARIO, os.path.join(folder, "in.yaml"))
    _copy(os.path.join(CLI_STUDIES, "tiny_batch.yaml"), os.path.join(folder, "study.yaml"))
    _copy(os.path.join(CLI_STUDIES, "tiny_compare.yaml"), os.path.join(folder, "compare.yaml"))


def _snapshot(folder):
    """Every entry below `folder`: its type and, for a regular file, its contents' digest."""
    entries = {}
    for root, dirs, names in os.walk(folder):
        for name in dirs + names:
            path = os.path.join(root, name)
            mode = os.lstat(path).st_mode
            if stat.S_ISLNK(mode):
                entries[os.path.relpath(path, folder)] = "link to " + os.readlink(path)
            elif stat.S_ISREG(mode):
                with open(path, "rb") as f:
                    entries[os.path.relpath(path, folder)] = hashlib.md5(f.read()).hexdigest()
            else:
                entries[os.path.relpath(path, folder)] = stat.S_IFMT(mode)
    return entries


def _hdf5_file(path):
    """A small HDF5 file (any HDF5 file: the signature is what the output checks read)."""
    import h5py
    with h5py.File(path, "w") as f:
        f["x"] = [1.0]


# Each case: (name, setup(folder), CLI arguments, the package's call, what the message says).
# The setup makes the hostile files in the work folder (the current folder of both front ends,
# so that the paths in the messages are the same); the package's call takes the folder too.
def _nothing(_folder):
    pass


def _mkdir(*names):
    def setup(folder):
        for name in names:
            os.makedirs(os.path.join(folder, name))
    return setup


def _symlink(target, name):
    def setup(folder):
        with open(os.path.join(folder, "victim.txt"), "w") as f:
            f.write("victim\n")
        os.symlink(target, os.path.join(folder, name))
    return setup


def _hardlink(folder):
    os.link(os.path.join(folder, "in.yaml"), os.path.join(folder, "hardlink.h5"))


def _copy_of(source, name):
    def setup(folder):
        _copy(os.path.join(folder, source), os.path.join(folder, name))
    return setup


def _fifo(name):
    def setup(folder):
        os.makedirs(os.path.dirname(os.path.join(folder, name)), exist_ok=True)
        os.mkfifo(os.path.join(folder, name))
    return setup


def _binary(name):
    def setup(folder):
        os.makedirs(os.path.dirname(os.path.join(folder, name)), exist_ok=True)
        with open(os.path.join(folder, name), "wb") as f:
            f.write(b"\x00\x01binary, not a table\x00" * 16)
    return setup


def _text(name):
    def setup(folder):
        os.makedirs(os.path.dirname(os.path.join(folder, name)), exist_ok=True)
        with open(os.path.join(folder, name), "w") as f:
            f.write("notes that are not HDF5\n")
    return setup


def _dataset_as(name):
    def setup(folder):
        _hdf5_file(os.path.join(folder, name))
    return setup


def _save(output):
    return lambda: wpg.run("in.yaml", overrides={"duration": 1}).save(output)


def _batch(study, output, plot=False):
    return lambda: wpg.batch(study, output=output, jobs=1, plot=plot)


def _compare(output, plot=False):
    return lambda: wpg.compare("compare.yaml", output=output, jobs=1, plot=plot)


RUN = ["run", "in.yaml", "--set", "duration=1", "--no-plot", "-o"]
CASES = [
    # outputs.sh, 1: not a regular file.
    ("device", _nothing, RUN + ["/dev/null"], _save("/dev/null"), "expected a regular file"),
    ("new_folder", _nothing, RUN + ["newdir/"], _save("newdir/"), "expected a regular file"),
    ("existing_folder", _mkdir("existing"), RUN + ["existing"], _save("existing"),
     "expected a regular file"),
    # outputs.sh, 2: an input (a second name for it too), a file of another kind.
    ("the_scenario", _nothing, RUN + ["in.yaml"], _save("in.yaml"), "an input of the command"),
    ("hard_link", _hardlink, RUN + ["hardlink.h5"], _save("hardlink.h5"),
     "an input of the command"),
    ("another_kind", _copy_of("in.yaml", "other.yaml"), RUN + ["other.yaml"],
     _save("other.yaml"), "another kind"),
    # outputs.sh, 3: a symbolic link, never followed.
    ("symlink", _symlink("in.yaml", "link.h5"), RUN + ["link.h5"], _save("link.h5"),
     "symbolic link"),
    # hardening side_outputs: a batch's summary files, a comparison's.
    ("batch_summary_symlink", _symlink("victim.txt", "out.summary.csv"),
     ["batch", "study.yaml", "-o", "out.h5", "--no-plot"], _batch("study.yaml", "out.h5"),
     "symbolic link"),
    ("batch_summary_is_the_study", _copy_of("study.yaml", "s.summary.md"),
     ["batch", "s.summary.md", "-o", "s.h5", "--no-plot"], _batch("s.summary.md", "s.h5"),
     "an input of the command"),
    ("batch_figure_over_a_dataset", _dataset_as("fig.summary.png"),
     ["batch", "study.yaml", "-o", "fig.h5"], _batch("study.yaml", "fig.h5", plot=True),
     "another kind"),
    ("compare_summary_symlink", lambda f: (_mkdir("cmp")(f), _symlink("../victim.txt",
                                                                      "cmp/summary.md")(f)),
     ["compare", "compare.yaml", "-o", "cmp", "--no-plot"], _compare("cmp"), "symbolic link"),
    # hardening fifo_side_output: never opened (it would block).
    ("batch_summary_fifo", _fifo("out.summary.csv"),
     ["batch", "study.yaml", "-o", "out.h5", "--no-plot"], _batch("study.yaml", "out.h5"), "FIFO"),
    ("compare_summary_fifo", _fifo("cmp/summary.md"),
     ["compare", "compare.yaml", "-o", "cmp", "--no-plot"], _compare("cmp"), "FIFO"),
    # hardening folder_kind: a folder where a file goes, a file where a folder goes.
    ("batch_summary_folder", _mkdir("out.summary.csv"),
     ["batch", "study.yaml", "-o", "out.h5", "--no-plot"], _batch("study.yaml", "out.h5"),
     "a folder"),
    ("compare_study_folder", _mkdir("cmp/study.h5"),
     ["compare", "compare.yaml", "-o", "cmp", "--no-plot"], _compare("cmp"), "a folder"),
    ("compare_into_a_file", _text("file_dir"),
     ["compare", "compare.yaml", "-o", "file_dir", "--no-plot"], _compare("file_dir"),
     "not a directory"),
    ("batch_under_a_file", _text("file_dir"),
     ["batch", "study.yaml", "-o", "file_dir/out.h5", "--no-plot"],
     _batch("study.yaml", "file_dir/out.h5"), "irectory"),
    # Side outputs of another kind: a binary OUT.summary.csv, a DIR/study.h5 that is not HDF5,
    # a comparison's figure over a dataset.
    ("batch_summary_binary", _binary("out.summary.csv"),
     ["batch", "study.yaml", "-o", "out.h5", "--no-plot"], _batch("study.yaml", "out.h5"),
     "another kind"),
    ("compare_study_not_hdf5", _text("cmp/study.h5"),
     ["compare", "compare.yaml", "-o", "cmp", "--no-plot"], _compare("cmp"), "another kind"),
    ("compare_table_binary", _binary("cmp/summary.csv"),
     ["compare", "compare.yaml", "-o", "cmp", "--no-plot"], _compare("cmp"), "another kind"),
    ("compare_figure_over_a_dataset", lambda f: (_mkdir("cmp")(f), _dataset_as(
        "cmp/top_trap.png")(f)),
     ["compare", "compare.yaml", "-o", "cmp"], _compare("cmp", plot=True), "another kind"),
]


@pytest.mark.parametrize("name, setup, arguments, call, expected", CASES,
                         ids=[case[0] for case in CASES])
def test_refused_as_the_cli_refuses_it(name, setup, arguments, call, expected, tmp_path, cli,
                                       monkeypatch):
    cli_folder, python_folder = tmp_path / "cli", tmp_path / "python"
    for folder in (cli_folder, python_folder):
        folder.mkdir()
        _prepare(str(folder))
        setup(str(folder))

    before = _snapshot(str(cli_folder))
    done = subprocess.run([os.environ["WPG_CLI"]] + arguments, cwd=cli_folder,
                          stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60)
    assert done.returncode == 2, (name, done.returncode, done.stderr)
    lines = done.stderr.splitlines()
    assert len(lines) == 1 and expected in lines[0], (name, done.stderr)
    assert _snapshot(str(cli_folder)) == before, name

    before = _snapshot(str(python_folder))
    monkeypatch.chdir(python_folder)
    with pytest.raises(wpg.InputError) as error:
        call()
    assert "wpg: error: " + str(error.value) == lines[0], name
    assert _snapshot(str(python_folder)) == before, name


def _long_study(folder):
    """The second_writer case's study: 12 walks of 30 s, a few seconds on one thread."""
    with open(os.path.join(folder, "study.yaml")) as f:
        text = f.read()
    text = (text.replace("duration: 2.0", "duration: 30.0")
            .replace("[300.0, 3000.0]", "[300, 600, 1000, 1500, 2000, 3000]")
            .replace("name: tiny", "name: longer"))
    with open(os.path.join(folder, "long.yaml"), "w") as f:
        f.write(text + "    walking.step_height: [0.04, 0.06]\n")


@pytest.mark.parametrize("resume", [False, True], ids=["second_writer", "resume_in_use"])
def test_a_batch_file_in_use_is_refused(resume, tmp_path, monkeypatch):
    """hardening second_writer and resume_in_use: a batch file another wpg is writing."""
    _prepare(str(tmp_path))
    _long_study(str(tmp_path))
    monkeypatch.chdir(tmp_path)
    first = subprocess.Popen([os.environ["WPG_CLI"], "batch", "long.yaml", "-o", "out.h5",
                              "-j", "1", "--no-plot"], stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE)
    try:
        for _ in range(400):  # until its file has its layout
            if os.path.exists("out.h5") and os.path.getsize("out.h5") > 4096:
                break
            time.sleep(0.02)
        assert first.poll() is None, "the first batch ended before the second started"
        inode = os.stat("out.h5").st_ino
        with pytest.raises(wpg.InputError, match="in use by another wpg"):
            wpg.batch("long.yaml", output="out.h5", jobs=1, resume=resume)
        assert os.stat("out.h5").st_ino == inode, "the file in use was replaced"
        assert not os.path.exists("out.h5.damaged"), "a file in use was moved aside"
    finally:
        _out, err = first.communicate(timeout=300)
    assert first.returncode == 0, err
