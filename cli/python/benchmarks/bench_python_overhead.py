#!/usr/bin/python3
"""What driving wpg from Python costs (docs/python.md, "Speed"): a measurement, not a test.

  PYTHONPATH=build/python /usr/bin/python3 cli/python/benchmarks/bench_python_overhead.py \\
      --wpg build/cli/wpg [--study STUDY.yaml] [--pairs 5] [-j 2] [--skip-batch]

1. Study throughput: `wpg.batch(study, jobs=J)` against `wpg batch STUDY -j J --no-plot`
   (default: datasets/studies/speeds_weights_heights.yaml), in interleaved pairs (which goes
   first alternates), medians of the wall times.
2. Online step: the wall time per control period of `gen.step(command=...)` in a Python loop
   against the same walk stepped by a C++ loop inside the extension (OnlineCore.run_steps: the
   same generator, the same command each period); the difference is what Python adds per step
   (the call, the command's conversion, the state object, the GIL released around the step).
   Medians over repeated walks, each walk started afresh.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import wpg


def batch_pairs(cli, study, jobs, pairs, folder):
    times = {"cli": [], "python": []}
    for pair in range(pairs):
        for which in (("cli", "python") if pair % 2 == 0 else ("python", "cli")):
            out = os.path.join(folder, "%s%d.h5" % (which, pair))
            start = time.perf_counter()
            if which == "cli":
                subprocess.run([cli, "batch", study, "-o", out, "-j", str(jobs), "--no-plot"],
                               check=True, stdout=subprocess.DEVNULL)
            else:
                wpg.batch(study, output=out, jobs=jobs)
            times[which].append(time.perf_counter() - start)
            os.unlink(out)
    return times


def step_times(steps, repeats):
    command = (0.2, 0.0, 0.05)
    python, cxx = [], []
    for _ in range(repeats):
        gen = wpg.OnlineGenerator("walk_forward")
        start = time.perf_counter()
        for _ in range(steps):
            gen.step(command=command)
        python.append((time.perf_counter() - start) / steps)
        cxx.append(wpg.OnlineGenerator("walk_forward")._core.run_steps(list(command), steps) / steps)
    return statistics.median(python), statistics.median(cxx)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--wpg", help="the built wpg executable (for the batch comparison)")
    parser.add_argument("--study", default=os.path.join(wpg.data_directory(), "datasets",
                                                         "studies", "speeds_weights_heights.yaml"))
    parser.add_argument("--pairs", type=int, default=5)
    parser.add_argument("-j", "--jobs", type=int, default=2)
    parser.add_argument("--steps", type=int, default=4000, help="control periods per walk")
    parser.add_argument("--repeats", type=int, default=9, help="walks per step measurement")
    parser.add_argument("--skip-batch", action="store_true")
    args = parser.parse_args()

    if not args.skip_batch:
        if not args.wpg:
            parser.error("--wpg is needed for the batch comparison (or --skip-batch)")
        with tempfile.TemporaryDirectory(prefix="wpg-bench-") as folder:
            times = batch_pairs(args.wpg, args.study, args.jobs, args.pairs, folder)
        cli, python = statistics.median(times["cli"]), statistics.median(times["python"])
        print("batch %s -j %d, %d interleaved pairs: median CLI %.2f s, Python %.2f s, "
              "Python throughput / CLI throughput %.3f" % (os.path.basename(args.study),
                                                           args.jobs, args.pairs, cli, python,
                                                           cli / python))
        print("  CLI    " + " ".join("%.2f" % t for t in times["cli"]))
        print("  Python " + " ".join("%.2f" % t for t in times["python"]))

    python, cxx = step_times(args.steps, args.repeats)
    print("step, median of %d walks of %d control periods: Python gen.step(command=...) "
          "%.2f us, C++ step %.2f us, Python adds %.2f us per step"
          % (args.repeats, args.steps, 1e6 * python, 1e6 * cxx, 1e6 * (python - cxx)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
