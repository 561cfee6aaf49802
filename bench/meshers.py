#!/usr/bin/env python3
"""Every planar mesher of the STL recipe through Reparam's automatic map:
the coverage bench's run (bench/coverage.py: whole, errors, elements
against the input) for MeshAdapt, Delaunay, Frontal-Delaunay, BAMG and the
two quadrangle recipes, with the quality of each mesh."""

import argparse
import collections
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import coverage as cv  # noqa: E402

MESHERS = [
    ("MeshAdapt", "Mesh.Algorithm = 1;"),
    ("Delaunay", "Mesh.Algorithm = 5;"),
    ("Frontal-Delaunay", "Mesh.Algorithm = 6;"),
    ("BAMG", "Mesh.Algorithm = 7;"),
    ("Frontal-Delaunay + Blossom", "Mesh.Algorithm = 6; Mesh.RecombineAll = 1;"),
    ("Frontal-Delaunay for quads + Blossom",
     "Mesh.Algorithm = 8; Mesh.RecombineAll = 1;"),
]

COLUMNS = [
    "mesh", "mesher", "whole", "errors", "warnings", "against the input",
    "triangles", "quadrangles", "kappa min", "kappa mean", "eta min",
    "eta mean", "tau (%)", "Hausdorff (%)", "CPU (s)",
]


def row_text(name, mesher, row):
    report, out = row["report"] or {}, row["out"] or {}
    whole = "yes" if row["whole"] else "NO" + (
        " (%s)" % row["status"] if row["status"] else "")
    return "| " + " | ".join([
        name, mesher, whole, str(row["errors"]), str(row["warnings"]),
        cv.text(report.get("inverted")),
        cv.text(out.get("triangles")), cv.text(out.get("quadrangles")),
        cv.text(report.get("kappa min"), "%.3g"),
        cv.text(report.get("kappa mean"), "%.3f"),
        cv.text(report.get("eta min"), "%.3g"),
        cv.text(report.get("eta mean"), "%.3f"),
        cv.text(report.get("tau"), "%.1f"),
        cv.text(report.get("hausdorff"), "%.3g"),
        "%.1f" % row["cpu"],
    ]) + " |"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--gmsh", required=True)
    parser.add_argument("--timeout", type=float, default=600)
    parser.add_argument("--repo", default=os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    print(cv.header(args.repo, args.gmsh, args.timeout, [6]).replace(
        "Coverage of the STL recipe (bench/coverage.sh)",
        "The STL recipe's planar meshers (bench/meshers.sh)").replace(
        "Mesh 2 (Frontal-Delaunay,", "Mesh 2 (each mesher,"))
    print()
    print("| " + " | ".join(COLUMNS) + " |")
    print("|---|---|---|" + "---:|" * (len(COLUMNS) - 3))
    whole, against, errors = (collections.Counter() for _ in range(3))
    for stl in map(os.path.abspath, args.meshes):
        name = cv.mesh_name(stl)
        triangles, area = cv.read_stl(stl)
        input_mesh = (len(triangles), area) + cv.input_topology(args.gmsh, stl)
        for label, options in MESHERS:
            row = cv.measure(args.gmsh, stl, 6, input_mesh, args.timeout, None,
                             options)
            whole[label] += row["whole"]
            against[label] += bool((row["report"] or {}).get("inverted"))
            errors[label] += bool(row["errors"])
            print(row_text(name, label, row), flush=True)
    print()
    for label, _ in MESHERS:
        print("- %s: %d of %d meshes whole, %d with an error, %d with elements "
              "against the input" % (label, whole[label], len(args.meshes),
                                     errors[label], against[label]))


if __name__ == "__main__":
    sys.exit(main())
