#!/usr/bin/python3
"""check_push_sweep.py WPG SWEEP.h5 SWEEP.json K SITUATION...: the files of `wpg push-sweep`
agree with each other and with the documented format, and the JSON's pushes replay: for one
sagittal and one coronal entry (the largest recovered force of the first non-zero phase),
`wpg run <scenario> --set 'pushes[0]={t: .., force: [..], duration: 0.1}'` exits 0 and the same
push 15 % stronger exits 1 (the walk fails: a fall or a relaxed constraint).
"""
import json
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

KEYS = ["situation", "direction", "phase", "scenario", "t", "duration", "force"]
DIRECTIONS = ["sagittal+", "sagittal-", "coronal+", "coronal-"]


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def replay(wpg, entry, factor, workdir):
    fx, fy = (factor * f for f in entry["force"])
    push = f"pushes[0]={{t: {entry['t']!r}, force: [{fx!r}, {fy!r}], duration: {entry['duration']!r}}}"
    out = os.path.join(workdir, "replay.h5")
    run = subprocess.run([wpg, "run", entry["scenario"], "--no-plot", "-o", out, "--set", push],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    return run.returncode, push, run.stderr.strip()


def main():
    wpg, h5_path, json_path, phases = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    situations = sys.argv[5:]
    with open(json_path) as f:
        entries = json.load(f)
    expected_rows = len(situations) * len(DIRECTIONS) * phases
    if len(entries) != expected_rows:
        fail(f"{len(entries)} JSON entries, expected {expected_rows}")
    for i, entry in enumerate(entries):
        if list(entry) != KEYS:
            fail(f"entry {i} has keys {list(entry)}, expected {KEYS}")
        s, d = situations[i // (4 * phases)], DIRECTIONS[(i // phases) % 4]
        if (entry["situation"], entry["direction"]) != (s, d):
            fail(f"entry {i}: {entry['situation']} {entry['direction']}, expected {s} {d}")
        if abs(entry["phase"] - (i % phases) / phases) > 1e-12 or entry["duration"] != 0.1:
            fail(f"entry {i}: phase {entry['phase']} duration {entry['duration']}")
        fx, fy = entry["force"]
        along = {"sagittal+": fx, "sagittal-": -fx, "coronal+": fy, "coronal-": -fy}[d]
        across = fy if d.startswith("sagittal") else fx
        if along < 0 or across != 0:
            fail(f"entry {i}: force {entry['force']} is not along {d}")
    with h5py.File(h5_path, "r") as f:
        table = f["push_sweep"]
        columns = [text(c) for c in table.attrs["columns"]]
        for name in ["situation", "direction", "phase", "t", "force", "impulse"]:
            if name not in columns:
                fail(f"/push_sweep lacks column {name}")
        if table["t"].shape != (expected_rows,):
            fail(f"/push_sweep/t has shape {table['t'].shape}")
        for i, entry in enumerate(entries):
            if (text(table["situation"][i]) != entry["situation"] or
                    text(table["direction"][i]) != entry["direction"] or
                    table["t"][i] != entry["t"] or table["fx"][i] != entry["force"][0] or
                    table["fy"][i] != entry["force"][1]):
                fail(f"row {i} of /push_sweep differs from JSON entry {i}")
            if not np.isclose(table["impulse"][i], 0.1 * table["force"][i]):
                fail(f"row {i}: impulse {table['impulse'][i]} is not force x 0.1 s")
    workdir = tempfile.mkdtemp()
    checked = 0
    for plane in ["sagittal+", "coronal+"]:
        candidates = [e for e in entries if e["direction"] == plane and any(e["force"])]
        if not candidates:
            fail(f"no {plane} entry with a recovered force")
        entry = candidates[0]
        status, push, _ = replay(wpg, entry, 1.0, workdir)
        if status != 0:
            fail(f"wpg run {entry['scenario']} --set '{push}': exit {status}, expected 0 (recovered)")
        status, push, _ = replay(wpg, entry, 1.15, workdir)
        if status != 1:
            fail(f"wpg run {entry['scenario']} --set '{push}': exit {status}, expected 1 (15 % stronger fails)")
        checked += 1
    print(f"ok: {len(entries)} entries; {checked} pushes replayed (recovered, 15 % stronger fails)")


if __name__ == "__main__":
    main()
