"""Files whose global heaps (where HDF5 keeps variable-length strings) are damaged, given to
the package's readers: each raises wpg.InputError naming the file, as `wpg` refuses it
(tests/cli/hardening_heaps.sh). HDF5 itself loops forever on a zeroed heap and aborts or
segfaults on 0xff bytes: each call runs in a child process with a time limit and a 2 GB
address space, so that a hang or a crash fails the test instead of the suite."""
import os
import resource
import subprocess
import sys
import textwrap

import pytest

import wpg
from conftest import SOURCE, STUDIES

DAMAGE = os.path.join(SOURCE, "tests", "cli", "damage_heaps.py")
READERS = {
    "load_run": "wpg.io.load_run(path, name='tiny_0')",
    "load_summary": "wpg.io.load_summary(path)",
    "run_names": "wpg.io.run_names(path)",
}


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))


def outcome(call, path):
    """What `call` does with `path` in a child process: its one line, 'hang' or 'crash'."""
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
                              text=True, timeout=30, preexec_fn=limit_memory)
    except subprocess.TimeoutExpired:
        return "hang"
    if done.returncode != 0:
        return "crash (exit %d): %s" % (done.returncode, done.stderr.strip()[-300:])
    return done.stdout.strip()


@pytest.fixture(scope="module")
def batch_file(tmp_path_factory):
    folder = tmp_path_factory.mktemp("batch")
    wpg.batch(os.path.join(STUDIES, "tiny.yaml"), output=folder / "tiny.h5", jobs=2)
    return folder / "tiny.h5"


@pytest.mark.parametrize("mode", ["zero", "ff", "length"])
@pytest.mark.parametrize("reader", sorted(READERS))
def test_a_damaged_heap_is_refused_by_every_reader(tmp_path, batch_file, mode, reader):
    damaged = tmp_path / ("%s.h5" % mode)
    damaged.write_bytes(batch_file.read_bytes())
    subprocess.run(["/usr/bin/python3", DAMAGE, mode, str(damaged)], check=True,
                   capture_output=True)
    got = outcome(READERS[reader], damaged)
    # Run names are in the object headers, and a run's strings in other collections than
    # the summary's names (length): those readers need not refuse, only never hang or crash.
    if (reader == "run_names" or mode == "length") and got == "accepted":
        return
    assert got.startswith("InputError: %s: " % damaged), got
