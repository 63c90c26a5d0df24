#!/usr/bin/env python3
"""Fails when a module includes or links a module above it (docs/architecture.md, "Modules").

  scripts/check-layers.py [--root DIR]

Each C++ module is a folder; its level is where it stands in the order below. A module may
include the headers of (and link) the modules of lower levels and its own, never a module of
its own level or above: libwpg < {datasets/input, planning, robots, analysis} <
datasets/study_design < datasets/storage < {cli/engine, cli/viewer} < {cli/commands,
cli/python}. The levels are those the code had when the rule was written: every include and
every target_link_libraries of a wpg target between the modules went down them. Tests sit
above everything and are not checked.

Checked: every #include of a wpg header ("wpg/<module>/..." or "wpg/<libwpg header>") and every
quoted include of a file beside it (which must not climb out of its module with ".."), in the
.hpp/.cpp files of each module; and the wpg targets each module's CMakeLists.txt links. Prints
one line per violation ("FILE:LINE: MODULE includes HEADER of MODULE (level ...)") and exits 1;
exits 0 silently otherwise. scripts/test.sh runs it before the test suite (so .ci/run does too).
"""
import argparse
import os
import re
import sys

# (module folder, level). The folder's files belong to the deepest folder listed that holds them.
MODULES = [
    ("libwpg", 0),
    ("datasets/input", 1), ("planning", 1), ("robots", 1), ("analysis", 1),
    ("datasets/study_design", 2),
    ("datasets/storage", 3),
    ("cli/engine", 4), ("cli/viewer", 4),
    ("cli/commands", 5), ("cli/python", 5), ("cli", 5),  # cli/main.cpp: the executable
]
LEVEL = dict(MODULES)

# The public header prefixes of each module (wpg/<prefix>...); any other wpg/ header is libwpg's.
HEADER_PREFIXES = [
    ("wpg/datasets/input/", "datasets/input"),
    ("wpg/datasets/study_design/", "datasets/study_design"),
    ("wpg/datasets/storage/", "datasets/storage"),
    ("wpg/planning/", "planning"),
    ("wpg/robots/", "robots"),
    ("wpg/analysis/", "analysis"),
    ("wpg/engine/", "cli/engine"),
    ("wpg/viewer/", "cli/viewer"),
]

# The CMake targets of each module.
TARGETS = {
    "wpg_core": "libwpg",
    "wpg_datasets_input": "datasets/input",
    "wpg_datasets_study_design": "datasets/study_design",
    "wpg_datasets_storage": "datasets/storage",
    "wpg_datasets": "datasets/storage",  # the interface target of the three
    "wpg_planning": "planning",
    "wpg_robots": "robots",
    "wpg_analysis": "analysis",
    "wpg_engine": "cli/engine",
    "wpg_viewer": "cli/viewer",
    "wpg_python": "cli/python",
    "wpg": "cli",
}

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
LINK = re.compile(r"target_link_libraries\s*\(([^)]*)\)", re.S)


def module_of(relative_path):
    """The module a file of the tree belongs to (the deepest module folder holding it)."""
    best = None
    for folder, _level in MODULES:
        if relative_path == folder or relative_path.startswith(folder + "/"):
            if best is None or len(folder) > len(best):
                best = folder
    return best


def header_module(header):
    for prefix, module in HEADER_PREFIXES:
        if header.startswith(prefix):
            return module
    return "libwpg" if header.startswith("wpg/") else None


def allowed(source, target):
    return source == target or LEVEL[target] < LEVEL[source]


def check_file(root, relative, module, problems):
    with open(os.path.join(root, relative), encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            quote, header = match.groups()
            if header.startswith("wpg/"):
                target = header_module(header)
            elif quote == '"':
                # A file beside this one: it must stay in this module.
                beside = os.path.normpath(os.path.join(os.path.dirname(relative), header))
                if not os.path.exists(os.path.join(root, beside)):
                    continue  # a header of a library found through its include path
                target = module_of(beside)
                if target is None:
                    problems.append("%s:%d: %s includes %s, outside every module"
                                    % (relative, number, module, header))
                    continue
            else:
                continue  # a system or third-party header
            if not allowed(module, target):
                problems.append("%s:%d: %s (level %d) includes %s of %s (level %d)"
                                % (relative, number, module, LEVEL[module], header, target,
                                   LEVEL[target]))


def check_links(root, relative, module, problems):
    with open(os.path.join(root, relative), encoding="utf-8") as f:
        text = f.read()
    for match in LINK.finditer(text):
        words = match.group(1).split()
        for word in words[1:]:
            target = TARGETS.get(word)
            if target and not allowed(module, target):
                number = text.count("\n", 0, match.start()) + 1
                problems.append("%s:%d: %s (level %d) links %s of %s (level %d)"
                                % (relative, number, module, LEVEL[module], word, target,
                                   LEVEL[target]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."),
                        help="the source tree (default: this script's)")
    root = os.path.abspath(parser.parse_args().root)
    problems = []
    for folder, _level in MODULES:
        top = os.path.join(root, folder)
        for directory, subfolders, names in os.walk(top):
            subfolders[:] = sorted(s for s in subfolders if s not in ("node_modules", "dist"))
            for name in sorted(names):
                relative = os.path.relpath(os.path.join(directory, name), root)
                module = module_of(relative)
                if module != folder:
                    continue  # a file of a deeper module, checked as that module's
                if name.endswith((".hpp", ".cpp", ".h")):
                    check_file(root, relative, module, problems)
                elif name == "CMakeLists.txt":
                    check_links(root, relative, module, problems)
    for problem in problems:
        print("check-layers: " + problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
