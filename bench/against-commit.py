#!/usr/bin/env python3
"""The STL recipe's CPU time and quality now against an earlier commit's
build, in the same run (bench/against-commit.sh runs this).

Per mesh, the README's recipe (bench/coverage.py's, automatic map) runs in
both gmsh executables, alternating, `--rounds` times each: the median CPU
time of each, their ratio, and kappa min / kappa mean from the report.
Alternating runs share the machine's load, so the ratio holds where the
absolute times drift (10-30 % between runs on this machine).
Python 3 standard library only.
"""

import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import coverage  # noqa: E402


def quality(row):
    report = row["report"]
    if not report or not row["whole"]:
        return None
    return report["kappa min"], report["kappa mean"]


def text(value, form):
    return "-" if value is None else form % value


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--base", required=True, help="the earlier gmsh")
    parser.add_argument("--gmsh", required=True, help="this build's gmsh")
    parser.add_argument("--base-name", default="base")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=300)
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()

    print("CPU seconds of the whole gmsh process (README recipe, automatic "
          "map, default options), median of %d alternating runs each; %s: "
          "the earlier commit's build, now: this one's; %s\n"
          % (args.rounds, args.base_name, coverage.cpu_model()))
    print("| mesh | CPU %s (s) | CPU now (s) | now / %s | kappa min %s | now "
          "| kappa mean %s | now |" % ((args.base_name,) * 4))
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    totals = [0.0, 0.0]
    worst = None
    for stl in map(os.path.abspath, args.meshes):
        triangles, area = coverage.read_stl(stl)
        input_mesh = (len(triangles), area) + coverage.input_topology(
            args.gmsh, stl)
        cpu = [[], []]
        rows = [None, None]
        for _ in range(args.rounds):
            for i, gmsh in enumerate((args.base, args.gmsh)):
                rows[i] = coverage.measure(gmsh, stl, 6, input_mesh,
                                           args.timeout, None)
                cpu[i].append(rows[i]["cpu"])
        median = [statistics.median(c) for c in cpu]
        totals = [t + m for t, m in zip(totals, median)]
        ratio = median[1] / median[0] if median[0] > 0 else None
        # the small ones are timer noise
        if ratio is not None and median[0] >= 1.0:
            name = coverage.mesh_name(stl)
            worst = max(worst or (ratio, name), (ratio, name))
        q = [quality(r) for r in rows]
        print("| %s | %.2f | %.2f | %s | %s | %s | %s | %s |" % (
            coverage.mesh_name(stl), median[0], median[1],
            text(ratio, "%.2f"),
            text(q[0] and q[0][0], "%.3g"), text(q[1] and q[1][0], "%.3g"),
            text(q[0] and q[0][1], "%.3f"), text(q[1] and q[1][1], "%.3f")),
            flush=True)
    print("\n- total CPU: %s %.1f s, now %.1f s (%.2f)"
          % (args.base_name, totals[0], totals[1],
             totals[1] / totals[0] if totals[0] > 0 else float("nan")))
    if worst:
        print("- largest ratio among the meshes of 1 s or more: %.2f (%s)"
              % worst)


if __name__ == "__main__":
    sys.exit(main())
