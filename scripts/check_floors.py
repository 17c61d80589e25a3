#!/usr/bin/env python3
"""The library's floors (issue 39): each folder of source/ and
include/fgimpact/ includes only the headers of its own folder and of the
floors below it.  Prints every include that runs back up, with its file and
line, and exits 1 if there is one; with --graph, the folder-level include
counts.  Run from anywhere: scripts/check_floors.py [--graph]."""
import os
import re
import sys

# Lowest first.  base: what every floor uses (exceptions, stop signals,
# atomic files and manifests, checkpoints, selections and patterns).
FLOORS = ["base", "material", "plate", "contact", "time", "output", "problem",
          "analysis", "study", "app"]

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
INCLUDE = re.compile(r'\s*#\s*include\s*[<"]fgimpact/(\w+)/([\w.]+)[>"]')


def folder_files():
    for top in ("source", os.path.join("include", "fgimpact")):
        for folder in sorted(os.listdir(os.path.join(ROOT, top))):
            path = os.path.join(ROOT, top, folder)
            if not os.path.isdir(path):
                continue
            for name in sorted(os.listdir(path)):
                yield folder, os.path.join(top, folder, name)


def main():
    upward, counts = [], {}
    for folder, relative in folder_files():
        if folder not in FLOORS:
            upward.append(f"{relative}: folder '{folder}' is not a floor "
                          f"(scripts/check_floors.py lists them)")
            continue
        with open(os.path.join(ROOT, relative), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                match = INCLUDE.match(line)
                if not match or match.group(1) == folder:
                    continue
                target = match.group(1)
                counts[(folder, target)] = counts.get((folder, target), 0) + 1
                if (target not in FLOORS or
                        FLOORS.index(target) > FLOORS.index(folder)):
                    upward.append(f"{relative}:{number}: {folder} includes "
                                  f"{target}/{match.group(2)}, a floor above")
    if "--graph" in sys.argv:
        for (a, b), n in sorted(counts.items(),
                                key=lambda e: (FLOORS.index(e[0][0]),
                                               e[0][1])):
            print(f"{a} -> {b}: {n}")
    for line in upward:
        print(line)
    print(f"check_floors: {len(upward)} include(s) running back up "
          f"(floors, lowest first: {' < '.join(FLOORS)})")
    return 1 if upward else 0


if __name__ == "__main__":
    sys.exit(main())
