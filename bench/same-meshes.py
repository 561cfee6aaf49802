#!/usr/bin/env python3
"""Whether two runs of bench/coverage.sh made the same meshes: compares the
.msh files two REPARAM_COVERAGE_LOGS folders kept, byte for byte (the
recipe's ASCII MSH 4.1 holds no time or path), and prints a table.

    python3 bench/same-meshes.py BEFORE_LOGS AFTER_LOGS

Exits 1 when a mesh differs or is missing on one side. Python 3 standard
library only.
"""

import hashlib
import os
import sys


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    before, after = sys.argv[1], sys.argv[2]
    names = sorted(
        {n for folder in (before, after) for n in os.listdir(folder)
         if n.endswith(".msh")}
    )
    print("| mesh and map | before | after | same |")
    print("|---|---|---|---|")
    counts = {"same": 0, "different": 0, "missing": 0}
    for name in names:
        sides = [os.path.join(folder, name) for folder in (before, after)]
        present = [os.path.exists(p) for p in sides]
        if not all(present):
            verdict = "missing"
        elif digest(sides[0]) == digest(sides[1]):
            verdict = "same"
        else:
            verdict = "different"
        counts[verdict] += 1
        sizes = ["%d B" % os.path.getsize(p) if ok else "-"
                 for p, ok in zip(sides, present)]
        print("| %s | %s | %s | %s |" % (name[:-4], sizes[0], sizes[1], verdict))
    print()
    print("- %(same)d the same, %(different)d different, %(missing)d missing"
          % counts)
    return 0 if counts["same"] == len(names) else 1


if __name__ == "__main__":
    sys.exit(main())
