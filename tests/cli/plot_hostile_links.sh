#!/usr/bin/env bash
# plot_hostile_links.sh WPG: the Python plot scripts check an HDF5 link before h5py follows it,
# as wpg's C++ readers do (analysis/wpg_file_reading.py): an external link to a FIFO (h5py's
# open(2) would block forever) or to a device is one line and exit 2 within the bound, naming the
# link; a soft link cycle too; a link to a regular file still draws (a merged index).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
scripts="$HERE/../../analysis"
make_workdir
cd "$WORKDIR"
"$wpg" run walk_forward --set duration=2 --no-plot -o run.h5 >/dev/null || fail "run: exit $?"
mkfifo fifo

# to_<target>.h5: /runs/walk_forward an external link to the FIFO, a device, run.h5;
# soft_cycle.h5: a soft link to itself; batch_fifo.h5: /batch an external link to the FIFO.
"$PYTHON" - <<'PY'
import h5py
for name, target in (("to_fifo", "fifo"), ("to_device", "/dev/zero"), ("to_run", "run.h5")):
    with h5py.File(name + ".h5", "w") as f:
        f.create_group("runs")["walk_forward"] = h5py.ExternalLink(target, "/runs/walk_forward")
        with h5py.File("run.h5", "r") as run:  # the stored scenario, as an index has it
            for key, value in run.attrs.items():
                f.attrs[key] = value
with h5py.File("soft_cycle.h5", "w") as f:
    f.create_group("runs")["walk_forward"] = h5py.SoftLink("/runs/walk_forward")
with h5py.File("batch_fifo.h5", "w") as f:
    f["batch"] = h5py.ExternalLink("fifo", "/batch")
PY

# refused SCRIPT FILE PATTERN: exit 2 within 20 s, one line matching PATTERN, no traceback.
refused() {
  local status=0
  timeout 20 "$PYTHON" "$scripts/$1" "$2" -o figure.png >stdout 2>stderr || status=$?
  [[ $status == 2 ]] || fail "$1 $2: exit $status, expected 2 (124: it hung) ($(cat stderr))"
  [[ "$(wc -l <stderr)" == 1 ]] || fail "$1 $2: not one line on stderr: $(cat stderr)"
  grep -q -- "$3" stderr || fail "$1 $2: expected '$3': $(cat stderr)"
  [[ ! -e figure.png ]] || fail "$1 $2: a figure was written"
}
refused plot_run.py to_fifo.h5 "/runs/walk_forward: external link to 'fifo': expected a regular file, got a FIFO"
refused plot_run.py to_device.h5 "external link to '/dev/zero': expected a regular file, got a character device"
refused plot_run.py soft_cycle.h5 "/runs/walk_forward: more than 8 links"
refused plot_batch.py batch_fifo.h5 "/batch: external link to 'fifo': expected a regular file, got a FIFO"

# A link to a regular HDF5 file (what `wpg merge` writes) is followed: the run is drawn.
timeout 60 "$PYTHON" "$scripts/plot_run.py" to_run.h5 -o figure.png >/dev/null 2>stderr ||
  fail "plot_run.py through a link to run.h5: exit $? ($(cat stderr))"
check_png figure.png
