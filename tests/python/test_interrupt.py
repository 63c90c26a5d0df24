"""Ctrl-C (SIGINT) stops a study from Python as it stops `wpg batch`: within about one run's
time, leaving a batch file that `resume=True` finishes."""
import os
import subprocess
import sys
import textwrap

STUDY = """\
name: long
base: walk_forward
sweep:
  grid:
    walking.weight_cop: [%s]
  zip:
    duration: [60.0]
""" % ", ".join(str(300.0 + 10 * i) for i in range(120))

INTERRUPTED = textwrap.dedent("""
    import os, signal, sys, threading, time, wpg
    study, output, jobs = sys.argv[1], sys.argv[2], int(sys.argv[3])
    threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT)).start()
    start = time.monotonic()
    try:
        wpg.batch(study, output=output, jobs=jobs)
    except KeyboardInterrupt:
        print("interrupted after %.2f s" % (time.monotonic() - start))
    else:
        print("finished after %.2f s" % (time.monotonic() - start))
""")


def interrupted_batch(tmp_path, jobs):
    study = tmp_path / "long.yaml"
    study.write_text(STUDY)
    output = tmp_path / "long.h5"
    done = subprocess.run([sys.executable, "-c", INTERRUPTED, str(study), str(output), str(jobs)],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return study, output, done.stdout.strip()


def test_ctrl_c_stops_a_batch_within_a_run_and_leaves_it_resumable(tmp_path):
    import wpg
    for jobs in (1, 2):
        folder = tmp_path / str(jobs)
        folder.mkdir()
        study, output, said = interrupted_batch(folder, jobs)
        # 120 walks of 60 s take ~4 s on one core, ~32 ms each: stopped well within 1 s of the
        # signal (at 1 s), not after the whole study.
        assert said.startswith("interrupted after "), said
        assert float(said.split()[2]) < 2.0, said
        done = wpg.io.load_summary(output)["done"]
        assert 0 < done.sum() < len(done), done.sum()
        table = wpg.batch(study, output=output, jobs=2, resume=True)
        assert table["done"].all() and len(table) == 120
