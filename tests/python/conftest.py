"""Shared fixtures of the Python package's tests (run by ctest: tests/CMakeLists.txt sets
PYTHONPATH to <build>/python, WPG_CLI to the built `wpg` and WPG_DATA_DIR to the source tree)."""
import os
import subprocess
import sys

import pytest

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
STUDIES = os.path.join(os.path.dirname(__file__), "studies")
COMPARE_BATCH_FILES = os.path.join(SOURCE, "tests", "cli", "compare_batch_files.py")


@pytest.fixture(scope="session")
def cli():
    """The built `wpg` executable: a function running it, returning the CompletedProcess."""
    path = os.environ.get("WPG_CLI")
    if not path:
        pytest.skip("WPG_CLI (the built wpg) is not set: run through ctest")

    def run(*arguments, check=True):
        done = subprocess.run([path] + [str(a) for a in arguments], capture_output=True,
                              text=True)
        if check and done.returncode not in (0, 1):
            raise AssertionError("wpg %s: exit %d\n%s" % (" ".join(map(str, arguments)),
                                                          done.returncode, done.stderr))
        return done
    return run


def same_batch_files(a, b):
    """compare_batch_files.py: the same contents bit for bit but the wall-time fields."""
    done = subprocess.run([sys.executable, COMPARE_BATCH_FILES, str(a), str(b)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def files_under(folder):
    return sorted(os.path.relpath(os.path.join(root, name), folder)
                  for root, _dirs, names in os.walk(folder) for name in names)
