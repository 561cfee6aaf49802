#!/usr/bin/env python3
"""Two bench/coverage.sh runs of Reparam's automatic map side by side, over
the (mesh, size factor) runs both have: per measure, the geometric mean of
after / before and on how many runs it went up and down.

    python3 bench/sweep-compare.py BEFORE.md AFTER.md

A change that moves most runs one way shows in the counts; the single
worst triangle (kappa min) of a mesh changes with any change of its nodes,
and its geometric mean says whether it does so one way. Python 3 standard
library only.
"""

import math
import sys

MEASURES = ["kappa min", "kappa mean", "tau (%)", "triangles / asked",
            "Hausdorff (%)", "inverted", "final patches", "layout (s)",
            "CPU (s)"]


def rows(path):
    table, header = {}, None
    for line in open(path):
        if not line.startswith("| "):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[0] == "mesh":
            header = cells
            continue
        if header and len(cells) == len(header) and cells[1].startswith("automatic"):
            row = dict(zip(header, cells))
            table[(cells[0], row.get("size factor", "1"))] = row
    return table


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    before, after = rows(sys.argv[1]), rows(sys.argv[2])
    common = [k for k in before if k in after]
    print("%d runs in both\n" % len(common))
    print("| measure | after / before (geometric mean) | up | down |")
    print("|---|---:|---:|---:|")
    for m in MEASURES:
        logs, up, down = [], 0, 0
        for k in common:
            a, b = number(before[k].get(m, "")), number(after[k].get(m, ""))
            if a is None or b is None:
                continue
            up += b > a
            down += b < a
            if a > 0 and b > 0:
                logs.append(math.log(b / a))
        mean = "%.4f" % math.exp(sum(logs) / len(logs)) if logs else "-"
        print("| %s | %s | %d | %d |" % (m, mean, up, down))


if __name__ == "__main__":
    main()
