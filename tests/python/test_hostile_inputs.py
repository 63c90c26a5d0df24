"""Hostile input files through the package's readers: each refused at once with
wpg.InputError naming the file, as `wpg` refuses it, never a wait. A FIFO (or an external link
to one) would block an open(2) for reading until a writer comes: each call runs in a child
process with a time limit, so that a hang fails the test instead of stalling the suite."""
import os
import subprocess
import sys
import textwrap

import pytest

import wpg
from conftest import STUDIES

READERS = {
    "load_run": "wpg.io.load_run(path)",
    "load_run_named": "wpg.io.load_run(path, name='tiny_0')",
    "run_names": "wpg.io.run_names(path)",
    "load_summary": "wpg.io.load_summary(path)",
    "load_compare_summary": "wpg.io.load_compare_summary(path)",
}


def outcome(call, path):
    """What `call` does with `path` in a child process: its one line, or 'hang'."""
    code = textwrap.dedent("""
        import sys, wpg
        path = sys.argv[1]
        try:
            %s
        except wpg.InputError as error:
            print("InputError: " + str(error))
        else:
            print("accepted")
    """) % call
    try:
        done = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True,
                              text=True, timeout=20)
    except subprocess.TimeoutExpired:
        return "hang"
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


@pytest.mark.parametrize("reader", sorted(READERS))
def test_a_fifo_is_refused_by_every_reader(tmp_path, reader):
    pipe = tmp_path / "pipe.h5"
    os.mkfifo(pipe)
    assert outcome(READERS[reader], pipe) == (
        "InputError: %s: cannot read: expected a regular file, got a FIFO (pipe)" % pipe)


@pytest.fixture(scope="module")
def batch_file(tmp_path_factory):
    folder = tmp_path_factory.mktemp("batch")
    wpg.batch(os.path.join(STUDIES, "tiny.yaml"), output=folder / "tiny.h5", jobs=2)
    return folder / "tiny.h5"


@pytest.mark.parametrize("linked", ["/batch", "/batch/summary/done"])
def test_load_summary_checks_external_links_as_the_cli_does(tmp_path, batch_file, cli, linked):
    """A batch file whose summary table (or one column) is an external link to a FIFO: the
    reader refuses the link, naming it, as `wpg view`'s dashboard (which reads the table) does,
    instead of blocking in it."""
    import h5py
    linking = tmp_path / "linking.h5"
    linking.write_bytes(batch_file.read_bytes())
    os.mkfifo(tmp_path / "pipe.h5")
    with h5py.File(linking, "r+") as handle:
        del handle[linked]
        handle[linked] = h5py.ExternalLink("pipe.h5", linked)
    expected = "%s: external link to 'pipe.h5': expected a regular file, got a FIFO (pipe)" % linked
    got = outcome(READERS["load_summary"], linking)
    assert got.startswith("InputError: %s: " % linking) and got.endswith(expected), got
    done = cli("view", linking, "-o", tmp_path / "page.html", check=False)
    assert done.returncode == 2 and expected in done.stderr, done.stderr
    assert not (tmp_path / "page.html").exists()
