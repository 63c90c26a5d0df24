#!/usr/bin/env python3
"""Fails when a source file or the documentation outgrows its limit.

  scripts/check-sizes.py [--root DIR]

The limits, which keep each file one concept a reader can hold and the documentation short
enough to be read whole:
- every source file (.cpp, .hpp, .h, .py, .js, .mjs, .sh, .cmake) at most 600 lines: split a
  larger one by concern;
- README.md at most 200 lines, docs/performance.md at most 250 (the current figures and how to
  measure them; their history is CHANGELOG.md's);
- README.md and docs/*.md together at most 50 000 words (`cat docs/*.md README.md | wc -w`).
Build trees (build*/ and out/ at the top), node_modules/, dist/ and __pycache__/ are not
looked at. Prints one line per file over its limit ("FILE: N lines (limit L)") and exits 1;
exits 0 silently otherwise. scripts/test.sh runs it before the test suite (so .ci/run does too).
"""
import argparse
import glob
import os
import sys

SOURCE_EXTENSIONS = (".cpp", ".hpp", ".h", ".py", ".js", ".mjs", ".sh", ".cmake")
SOURCE_LINES = 600
PAGE_LINES = {"README.md": 200, "docs/performance.md": 250}
DOC_WORDS = 50000
SKIPPED_FOLDERS = {"node_modules", "dist", "__pycache__", ".git"}


def line_count(path):
    with open(path, "rb") as f:
        return f.read().count(b"\n")


def source_files(root):
    for folder, subfolders, files in os.walk(root):
        relative = os.path.relpath(folder, root)
        subfolders[:] = sorted(
            name for name in subfolders if name not in SKIPPED_FOLDERS and not (
                relative == "." and (name.startswith("build") or name == "out")))
        for name in sorted(files):
            if name.endswith(SOURCE_EXTENSIONS):
                yield os.path.join(folder, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."))
    root = os.path.abspath(parser.parse_args().root)
    problems = []
    for path in source_files(root):
        lines = line_count(path)
        if lines > SOURCE_LINES:
            problems.append(f"{os.path.relpath(path, root)}: {lines} lines (limit {SOURCE_LINES})")
    for page, limit in PAGE_LINES.items():
        path = os.path.join(root, page)
        if os.path.exists(path) and line_count(path) > limit:
            problems.append(f"{page}: {line_count(path)} lines (limit {limit})")
    pages = sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    pages += [p for p in [os.path.join(root, "README.md")] if os.path.exists(p)]
    words = 0
    for path in pages:
        with open(path, encoding="utf-8", errors="replace") as f:
            words += len(f.read().split())
    if words > DOC_WORDS:
        problems.append(f"README.md and docs/*.md: {words} words (limit {DOC_WORDS})")
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
