"""Reading wpg's HDF5 files (datasets/SCHEMA.md) in the plot scripts, trusting nothing.

A file given to a plot script may be anyone's: truncated, bit-flipped, or made to declare
2e8 rows in a few kB. Every read here checks what it gets (group or dataset, rank, columns,
number type, finite values) and the size a dataset declares BEFORE h5py allocates it (the
limits of wpg/datasets/storage/read_limits.hpp, datasets/SCHEMA.md "Reading"). Any problem is a
BadFile whose message is one line, "FILE: /path: expected ...", and `run_script` turns it
(and any other error while reading or drawing) into that one line on stderr and exit status 2:
no traceback. The stored scenario is parsed with PyYAML (a setup dependency), never with
regular expressions.
"""
import math
import os
import stat
import sys

# As wpg/datasets/storage/read_limits.hpp.
MAX_STORED_SAMPLES = 720001  # rows of a run's per-sample datasets (3600 s at 5 ms, + 1)
MAX_READ_ELEMENTS = 1 << 26  # elements of any one dataset or attribute
MAX_LINK_DEPTH = 8  # links followed inside links, as kMaxExternalLinkDepth of wpg's readers


class BadFile(Exception):
    """A problem with an input file: `str(error)` is one line naming the file and the object."""


def one_line(text):
    return " ".join(str(text).split())


def report(script, message):
    """One line on stderr: `wpg: error: SCRIPT: ...` under `wpg`, else `SCRIPT: ...`."""
    prefix = "wpg: error: " if os.environ.get("WPG_PLOT_PROG") == "wpg" else ""
    sys.stderr.write("%s%s: %s\n" % (prefix, script, one_line(message)))


def run_script(script, main):
    """Runs main(); a BadFile or any other error becomes one line and exit status 2."""
    try:
        status = main()
    except BadFile as error:
        report(script, error)
        sys.exit(2)
    except KeyboardInterrupt:
        sys.exit(130)
    except MemoryError:
        report(script, "out of memory")
        sys.exit(2)
    except Exception as error:  # noqa: BLE001 - no traceback for anything a file can cause
        # A content no check above foresaw: named by the input file (the first argument).
        inputs = [argument for argument in sys.argv[1:] if not argument.startswith("-")]
        report(script, "%s: cannot read or draw it (%s: %s)"
               % (inputs[0] if inputs else "?", type(error).__name__, one_line(error)[:200]))
        sys.exit(2)
    sys.exit(status or 0)


def png_metadata(source):
    """The PNG text of a figure: who drew it (wpg's version, commit, machine and date, given by
    `wpg` in WPG_PROVENANCE) and from which file."""
    return {"Software": os.environ.get("WPG_PROVENANCE") or "wpg analysis scripts",
            "Source": os.path.basename(str(source))}


def save_figure(fig, output, **savefig_options):
    """fig as a PNG at `output`, atomically: an exclusive temporary file beside it, renamed over
    it (a symlink, a FIFO or a half-written figure is never left at `output`)."""
    _write_atomically(output, lambda stream: fig.savefig(stream, format="png", **savefig_options))


def save_figure_cropped(fig, output, dpi, metadata, pad_inches=0.1):
    """fig as a PNG at `output` (atomically, as save_figure), cropped to its drawing with
    `pad_inches` of the background round it: what savefig(bbox_inches="tight") writes, from one
    draw instead of two (tight draws the whole figure once to measure it, then again to write
    it: a run's figure took 1.15 s of CPU with it, 0.98 s without, medians of 8 interleaved
    runs). The figure is drawn at `dpi`, and the pixels that are not the background bound the
    crop. A drawing that reaches the canvas's border may go on past it, where only the tight
    bounding box sees it: then the figure is written with that."""
    import numpy as np
    from matplotlib.image import imsave

    def write(stream):
        fig.set_dpi(dpi)
        fig.canvas.draw()
        rgba = np.asarray(fig.canvas.buffer_rgba())
        drawn = np.any(rgba != rgba[0, 0], axis=2)  # the corner: the background (nothing there)
        rows, columns = np.flatnonzero(drawn.any(axis=1)), np.flatnonzero(drawn.any(axis=0))
        pad = int(round(pad_inches * dpi))
        height, width = drawn.shape
        if (not len(rows) or rows[0] < pad or columns[0] < pad or rows[-1] >= height - pad
                or columns[-1] >= width - pad):
            fig.savefig(stream, format="png", dpi=dpi, bbox_inches="tight",
                        pad_inches=pad_inches, metadata=metadata)
            return
        crop = rgba[rows[0] - pad:rows[-1] + pad + 1, columns[0] - pad:columns[-1] + pad + 1]
        imsave(stream, np.ascontiguousarray(crop), format="png", dpi=dpi, metadata=metadata)

    _write_atomically(output, write)


def _write_atomically(output, write):
    """write(stream) into an exclusive temporary file beside `output`, renamed over it."""
    import tempfile
    folder = os.path.dirname(os.path.abspath(output))
    fd, temporary = tempfile.mkstemp(prefix="." + os.path.basename(output) + ".",
                                     suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as stream:
            write(stream)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, output)
    except BaseException:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        raise


def import_h5py(script):
    """h5py and numpy, or one line and exit 2 naming the Debian packages."""
    try:
        import h5py  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as error:
        report(script, "needs h5py and numpy for %s (%s): install the Debian packages "
               "python3-h5py python3-numpy" % (sys.executable, error))
        sys.exit(2)
    return h5py


def open_file(path):
    """The HDF5 file `path`, open for reading: checked first to be a regular file, as wpg's
    checkInputFile (input_file.hpp) does (h5py would wait forever in a FIFO)."""
    import h5py
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        raise BadFile("%s: cannot read: no such file" % path)
    if stat.S_ISDIR(mode):
        raise BadFile("%s: cannot read: it is a directory" % path)
    if not stat.S_ISREG(mode):
        raise BadFile("%s: cannot read: expected a regular file, got %s"
                      % (path, _file_type_name(mode)))
    if not os.access(path, os.R_OK):
        raise BadFile("%s: cannot read: permission denied" % path)
    try:
        return h5py.File(path, "r")
    except (OSError, ValueError) as error:
        try:
            hdf5 = h5py.is_hdf5(path)
        except (OSError, ValueError):
            hdf5 = False
        if not hdf5:
            raise BadFile("%s: not an HDF5 file" % path)
        raise BadFile("%s: cannot read the HDF5 file (%s)" % (path, one_line(error)[:200]))


class Reader:
    """Checked reads from one open file; `path` names it in every message."""

    def __init__(self, path, handle):
        self.path = path
        self.file = handle

    def fail(self, where, expected):
        raise BadFile("%s: %s: %s" % (self.path, where, expected))

    def _get(self, parent, name):
        where = _join(parent.name, name)
        try:
            return self._follow(parent, name, 0), where
        except BadFile:
            raise
        except (OSError, KeyError, ValueError, RuntimeError) as error:
            self.fail(where, "cannot read it (%s)" % one_line(error)[:160])

    def _follow(self, parent, name, depth):
        """The object `name` (a path) below `parent`, or None: every link on the way checked
        BEFORE h5py follows it. h5py (HDF5) would open an external link's target with open(2),
        which blocks forever on a FIFO and reads any file: as wpg's C++ readers
        (external_link_guard.cpp), the target must be a regular file, and links inside links
        are followed at most MAX_LINK_DEPTH deep (a cycle)."""
        import h5py
        current = parent.file["/"] if name.startswith("/") else parent
        for part in [part for part in name.split("/") if part and part != "."]:
            where = _join(current.name, part)
            if not isinstance(current, h5py.Group):
                self.fail(current.name, "expected a group")
            link = current.get(part, getlink=True)
            if link is None:
                return None
            if isinstance(link, (h5py.SoftLink, h5py.ExternalLink)) and depth >= MAX_LINK_DEPTH:
                self.fail(where, "more than %d links followed one inside another (a cycle?)"
                          % MAX_LINK_DEPTH)
            if isinstance(link, h5py.SoftLink):
                current = self._follow(current, link.path, depth + 1)
            elif isinstance(link, h5py.ExternalLink):
                current = self._follow_external(current.file.filename, where, link, depth)
            else:
                current = current[part]
            if current is None:
                return None
        return current

    def _follow_external(self, holder, where, link, depth):
        """The object an external link of the file `holder` names, its file checked first."""
        import h5py
        described = "external link to '%s'" % link.filename
        # Where HDF5 looks (without HDF5_EXT_PREFIX): an absolute name as it is; a relative one
        # beside the file holding the link, then from the working folder.
        candidates = [link.filename] if os.path.isabs(link.filename) else [
            os.path.join(os.path.dirname(os.path.abspath(holder)), link.filename), link.filename]
        for candidate in candidates:
            try:
                mode = os.stat(candidate).st_mode
            except (OSError, ValueError):
                continue
            if not stat.S_ISREG(mode):
                self.fail(where, "%s: expected a regular file, got %s"
                          % (described, _file_type_name(mode)))
            try:
                target = h5py.File(candidate, "r")
            except (OSError, ValueError) as error:
                self.fail(where, "%s: cannot open it as an HDF5 file (%s)"
                          % (described, one_line(error)[:120]))
            found = self._follow(target["/"], link.path, depth + 1)
            if found is None:
                self.fail(where, "%s: no object '%s' in it" % (described, link.path))
            return found
        self.fail(where, "%s: no such file" % described)

    def group(self, parent, name, optional=False):
        """The group `name` below `parent` (None when optional and absent)."""
        import h5py
        item, where = self._get(parent, name)
        if item is None and optional:
            return None
        if not isinstance(item, h5py.Group):
            self.fail(where, "expected a group" + (", missing" if item is None else ""))
        return item

    def has(self, parent, name):
        """Whether `name` exists below `parent` (its links checked: BadFile on a hostile one)."""
        try:
            return self._follow(parent, name, 0) is not None
        except BadFile:
            raise
        except (OSError, KeyError, ValueError, RuntimeError):
            return False

    def dataset(self, parent, name, columns=None, kind="number", rows=None,
                max_rows=MAX_STORED_SAMPLES, finite=True, optional=False):
        """The dataset `name` below `parent` as a numpy array, checked.

        columns: None for 1-D (n,), an int k for (n, k), "any" for (n, k) with any k.
        kind: "number" (float or integer), "integer", "text" (strings, returned as str),
        "auto" (numbers or text, as stored).
        rows: the number of rows it must have (None: any up to max_rows).
        finite: floating-point values must be finite (not for kind "text").
        """
        import h5py
        import numpy as np
        item, where = self._get(parent, name)
        if item is None and optional:
            return None
        if not isinstance(item, h5py.Dataset):
            self.fail(where, "expected a dataset" + (", missing" if item is None else ""))
        shape = item.shape
        if shape is None:
            shape = (0,)
        expected_shape = ("(n,)" if columns is None else
                          "(n, k)" if columns == "any" else "(n, %d)" % columns)
        if len(shape) != (1 if columns is None else 2) or (
                isinstance(columns, int) and shape[1] != columns):
            self.fail(where, "expected shape %s, got %s" % (expected_shape, shape))
        elements = 1
        for extent in shape:
            elements *= int(extent)
        if shape[0] > max_rows or elements > MAX_READ_ELEMENTS:
            self.fail(where, "declares shape %s: expected at most %d rows and %d elements "
                      "(the readers' limits, datasets/SCHEMA.md)"
                      % (shape, max_rows, MAX_READ_ELEMENTS))
        if rows is not None and shape[0] != rows:
            self.fail(where, "expected %d rows, got %d" % (rows, shape[0]))
        dtype_kind = item.dtype.kind
        if kind == "auto":
            kind = "text" if dtype_kind in "SOU" else "number"
        if kind == "text":
            if dtype_kind not in "SOU":
                self.fail(where, "expected strings, got %s" % item.dtype)
        elif kind == "integer":
            if dtype_kind not in "iu":
                self.fail(where, "expected integers, got %s" % item.dtype)
        elif dtype_kind not in "fiu":
            self.fail(where, "expected numbers, got %s" % item.dtype)
        try:
            if kind == "text":
                values = item.asstr()[()] if dtype_kind in "SO" else item[()]
                return np.asarray([str(v) for v in np.asarray(values).reshape(-1)])
            values = np.asarray(item[()])
        except (OSError, ValueError, TypeError, UnicodeDecodeError, RuntimeError) as error:
            self.fail(where, "cannot read it (%s)" % one_line(error)[:160])
        if finite and values.dtype.kind == "f" and values.size and \
                not np.all(np.isfinite(values)):
            row = int(np.argwhere(~np.isfinite(values.reshape(shape[0], -1)))[0][0])
            self.fail(where, "row %d: expected finite numbers" % row)
        return values

    def attribute(self, obj, name, kind="number", default=None, optional=False):
        """The attribute `name` of `obj`: one number ("number") or one string ("text");
        a list of strings ("texts"). `default` when absent and optional."""
        import numpy as np
        where = obj.name + ":" + name
        try:
            present = name in obj.attrs
        except (OSError, KeyError, ValueError, RuntimeError) as error:
            self.fail(where, "cannot read it (%s)" % one_line(error)[:160])
        if not present:
            if optional:
                return default
            self.fail(where, "expected an attribute, missing")
        try:
            shape = obj.attrs.get_id(name).shape
            elements = 1
            for extent in shape or ():
                elements *= int(extent)
            if elements > MAX_READ_ELEMENTS:
                self.fail(where, "declares shape %s: expected at most %d elements"
                          % (shape, MAX_READ_ELEMENTS))
            value = obj.attrs[name]
        except BadFile:
            raise
        except (OSError, KeyError, ValueError, TypeError, RuntimeError) as error:
            self.fail(where, "cannot read it (%s)" % one_line(error)[:160])
        if kind == "texts":
            items = np.asarray(value, dtype=object).reshape(-1)
            if not all(isinstance(v, (str, bytes)) for v in items):
                self.fail(where, "expected a list of strings")
            return [_text(v) for v in items]
        array = np.asarray(value, dtype=object).reshape(-1) if not isinstance(
            value, (str, bytes)) else [value]
        if len(array) != 1:
            self.fail(where, "expected one value, got %d" % len(array))
        value = array[0]
        if kind == "text":
            if not isinstance(value, (str, bytes)):
                self.fail(where, "expected a string")
            return _text(value)
        if isinstance(value, (str, bytes)) or not isinstance(value, (int, float, np.number)):
            self.fail(where, "expected a number")
        return float(value)


def _text(value):
    return value.decode("utf-8", "replace") if isinstance(value, bytes) else str(value)


def _file_type_name(mode):
    for test, name in ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO (pipe)"),
                       (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISSOCK, "a socket"), (stat.S_ISLNK, "a symbolic link")):
        if test(mode):
            return name
    return "a special file"


def _join(parent, name):
    return (parent.rstrip("/") + "/" + name) if not name.startswith("/") else name


def parse_scenario(path, where, text):
    """The stored scenario (YAML text) as a dict; BadFile when it is not a YAML mapping."""
    import yaml  # python3-yaml, a setup dependency
    if not text:
        raise BadFile("%s: %s: expected the scenario's YAML text, got nothing" % (path, where))
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        raise BadFile("%s: %s: expected the scenario's YAML text, got a YAML error%s"
                      % (path, where, " at line %d" % (mark.line + 1) if mark else ""))
    if not isinstance(data, dict):
        raise BadFile("%s: %s: expected the scenario's YAML text (a mapping)" % (path, where))
    return data


def walking_number(scenario, key, default):
    """walking.<key> of a parsed scenario when it is a finite positive number, else default."""
    walking = scenario.get("walking")
    value = walking.get(key) if isinstance(walking, dict) else None
    if isinstance(value, (int, float)) and not isinstance(value, bool) and \
            math.isfinite(value) and value > 0:
        return float(value)
    return default
