#!/usr/bin/python3
"""check_push_sweep.py WPG SWEEP.h5 SWEEP.json K SITUATION...: the files of `wpg push-sweep`
agree with each other and with the documented format, and the JSON's pushes replay: for one
sagittal and one coronal entry (the largest recovered force of the first non-zero phase),
`wpg run <scenario> --set 'pushes[0]={t: .., force: [..], duration: 0.1}'` exits 0 with the swing
foot within the sweep's limits (the run's checks/swing_foot_speed_max and _acceleration_max, equal
to the entry's swing_speed_max and swing_acceleration_max), and the same push 15 % stronger is not
recovered: it exits 1 (a fall or a relaxed constraint) or its swing foot breaks a limit.
"""
import json
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

KEYS = ["situation", "direction", "phase", "scenario", "t", "duration", "force",
        "swing_speed_max", "swing_acceleration_max"]
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
    if os.path.exists(out):
        os.remove(out)
    run = subprocess.run([wpg, "run", entry["scenario"], "--no-plot", "-o", out, "--set", push],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    peaks = None
    if os.path.exists(out):
        with h5py.File(out, "r") as f:
            checks = next(iter(f["runs"].values()))["checks"].attrs
            peaks = (float(checks["swing_foot_speed_max"]), float(checks["swing_foot_acceleration_max"]))
    return run.returncode, push, peaks


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
        limits = (float(f.attrs["max_swing_speed"]), float(f.attrs["max_swing_acceleration"]))
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
            if (table["swing_speed_max"][i] != entry["swing_speed_max"] or
                    table["swing_acceleration_max"][i] != entry["swing_acceleration_max"]):
                fail(f"row {i}: swing peaks differ from JSON entry {i}")
            if any(entry["force"]) and any(
                    limit > 0 and peak > limit for peak, limit in
                    zip((entry["swing_speed_max"], entry["swing_acceleration_max"]), limits)):
                fail(f"entry {i}: recovered with the swing foot beyond the limits {limits}")
            if not np.isclose(table["impulse"][i], 0.1 * table["force"][i]):
                fail(f"row {i}: impulse {table['impulse'][i]} is not force x 0.1 s")
    workdir = tempfile.mkdtemp()
    checked = 0
    for plane in ["sagittal+", "coronal+"]:
        candidates = [e for e in entries if e["direction"] == plane and any(e["force"])]
        if not candidates:
            fail(f"no {plane} entry with a recovered force")
        entry = candidates[0]
        status, push, peaks = replay(wpg, entry, 1.0, workdir)
        if status != 0:
            fail(f"wpg run {entry['scenario']} --set '{push}': exit {status}, expected 0 (recovered)")
        if peaks != (entry["swing_speed_max"], entry["swing_acceleration_max"]):
            fail(f"wpg run {entry['scenario']} --set '{push}': swing peaks {peaks}, the entry's "
                 f"{entry['swing_speed_max']}, {entry['swing_acceleration_max']}")
        status, push, peaks = replay(wpg, entry, 1.15, workdir)
        beyond = peaks is not None and any(
            limit > 0 and peak > limit for peak, limit in zip(peaks, limits))
        if not (status == 1 or (status == 0 and beyond)):
            fail(f"wpg run {entry['scenario']} --set '{push}': exit {status}, swing peaks {peaks}: "
                 f"expected 1 or a swing foot beyond {limits} (15 % stronger fails)")
        checked += 1
    print(f"ok: {len(entries)} entries; {checked} pushes replayed (recovered, 15 % stronger fails)")


if __name__ == "__main__":
    main()
