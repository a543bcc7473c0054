#!/usr/bin/env python3
"""Fails when an #include runs back up the project's layers.

The source tree is a stack of layers; a file may include headers of its own
layer and of the layers below it, never of one above it, and never of another
group of its own layer (tools/ and python/ know nothing of each other). From
the bottom up:

  src/core          the per-pixel math, header-only, shared with the device
  src/base          threads, log, progress, stop requests, image containers
  options           option structs, parsing and checks
  src/prior         the segmentation prior
  src/engine        the per-pixel state, the pass schedule, the back-ends' step interface
  src/deformable    the deformable step (APD-MVS and MSP-MVS's parts)
  src/patch_match   conventional sweeps, segment planes, open sky, the pass runner
  src/backend       the back-end choice and entry; backend/cpu, backend/cuda
  io                every reader and writer
  app               the commands: mains, dispatcher, locks, shards
  python | tools    the Python module; the evaluator, scene generator, RGB-D importer
  tests             unit and integration tests and their support
  bench | fuzz      benchmarks; fuzz targets

Includes are resolved as the build resolves them: from the repository root,
then from src/, then from the including file's folder.

  tools/check_layers.py [--root DIR]    exit 1 and list every upward include
  tools/check_layers.py --list          print the layers

ctest runs it (check_layers_test).
"""

import argparse
import os
import re
import subprocess
import sys

# Bottom to top; a layer is one or more groups (path prefixes) side by side.
LAYERS = [
    ["src/core"],
    ["src/base"],
    ["options"],
    ["src/prior"],
    ["src/engine"],
    ["src/deformable"],
    ["src/patch_match"],
    ["src/backend"],
    ["io"],
    ["app"],
    ["python", "tools"],
    ["tests"],
    ["bench", "fuzz"],
]
SOURCE_SUFFIXES = (".h", ".cc", ".cu", ".cuh")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def group_of(path):
    """(layer index, group prefix) of a repository path, or None outside the layers."""
    best = None
    for index, groups in enumerate(LAYERS):
        for prefix in groups:
            if path == prefix or path.startswith(prefix + "/"):
                if best is None or len(prefix) > len(best[1]):
                    best = (index, prefix)
    return best


def resolve(root, including, name):
    """The repository path an include names, or None (a system or generated header)."""
    for base in ("", "src", os.path.dirname(including)):
        candidate = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def source_files(root):
    try:
        listed = subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True,
                                check=True).stdout.split("\n")
    except (OSError, subprocess.CalledProcessError):
        listed = [os.path.relpath(os.path.join(d, f), root)
                  for d, _, files in os.walk(root) for f in files]
    return sorted(f for f in listed if f.endswith(SOURCE_SUFFIXES))


def upward_includes(root):
    """Every include that crosses a layer upwards or into another group of its layer."""
    problems = []
    for path in source_files(root):
        own = group_of(path)
        if own is None:
            continue
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = resolve(root, path, match.group(1))
                theirs = group_of(target) if target else None
                if theirs is None:
                    continue
                if theirs[0] > own[0] or (theirs[0] == own[0] and theirs[1] != own[1]):
                    problems.append(f"{path}:{number}: includes {target} ({theirs[1]}) "
                                    f"from {own[1]}, which is {'above' if theirs[0] > own[0] else 'beside'} it")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    parser.add_argument("--list", action="store_true", help="print the layers, bottom first")
    args = parser.parse_args()
    if args.list:
        for index, groups in enumerate(LAYERS):
            print(index, " | ".join(groups))
        return 0
    problems = upward_includes(args.root)
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} include(s) run up a layer (tools/check_layers.py lists the layers)")
        return 1
    print(f"check_layers: {len(source_files(args.root))} files, no include runs up a layer")
    return 0


if __name__ == "__main__":
    sys.exit(main())
