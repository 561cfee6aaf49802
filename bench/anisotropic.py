#!/usr/bin/env python3
"""Anisotropic meshes from the curvature (the paper's Sec. 6.3): per mesh,
the STL recipe with sizes in [h/4, 4h] (h: the coverage bench's size) and N
elements per circle of curvature, isotropic (Frontal-Delaunay with Gmsh's
Mesh.MeshSizeFromCurvature = N) against anisotropic (BAMG with Reparam's
Mesh.CompoundCurvatureMetric = N): triangles, Hausdorff and mean distance
to the input, kappa mean, inverted elements, errors, CPU time, and the
ratios. See bench/anisotropic.sh."""

import argparse
import datetime
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import coverage  # noqa: E402
import quads  # noqa: E402

MODES = [
    ("isotropic, Frontal-Delaunay", ["Mesh.Algorithm = 6;",
                                      "Mesh.MeshSizeFromCurvature = %g;"]),
    ("anisotropic, BAMG", ["Mesh.Algorithm = 7;",
                           "Mesh.CompoundCurvatureMetric = %g;"]),
]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--gmsh", required=True)
    p.add_argument("--repo", required=True)
    p.add_argument("--n", type=float, default=20)
    p.add_argument("--timeout", type=float, default=300)
    # BAMG's result changes from run to run (meshGFaceBamg orders the nodes
    # by their addresses): the median run by Hausdorff distance
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("meshes", nargs="+")
    a = p.parse_args()
    commit = coverage.command_output(["git", "-C", a.repo, "rev-parse", "--short", "HEAD"])
    print("Anisotropic meshes (bench/anisotropic.sh), %s, commit %s, %s: the "
          "STL recipe with the automatic map, sizes in [h/4, 4h] (h for about "
          "min(input triangles, %d) triangles), %g elements per circle of "
          "curvature; each the median of %d runs by Hausdorff distance (BAMG's "
          "mesh changes from run to run). H: Hausdorff distance, mean d.: mean "
          "distance, %% of the diagonal; ratios: anisotropic over isotropic.\n"
          % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), commit,
             coverage.cpu_model(), coverage.MAX_TRIANGLES, a.n, a.runs))
    print("| mesh | mesh type | triangles | H (%) | mean d. (%) | kappa mean | inverted | errors | CPU (s) | triangles ratio | H ratio |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for stl in a.meshes:
        h = quads.coverage_size(stl)
        name = os.path.basename(stl)[:-4]
        rows = []
        for label, options in MODES:
            runs = [quads.run(a.gmsh, stl, 6, h / 4, 4 * h,
                              [o % a.n if "%" in o else o for o in options],
                              a.timeout) for _ in range(a.runs)]
            runs = sorted((r for r in runs if r is not None),
                          key=lambda r: r["hausdorffPercent"])
            t = runs[len(runs) // 2] if runs else None
            rows.append(t)
            if t is None:
                print("| %s | %s | failed |||||||||" % (name, label))
                continue
            ratio = ["", ""]
            if rows[0] is not None and t is not rows[0]:
                ratio = ["%.2f" % (t["triangles"] / max(rows[0]["triangles"], 1)),
                         "%.2f" % (t["hausdorffPercent"] / max(rows[0]["hausdorffPercent"], 1e-300))]
            print("| %s | %s | %d | %.3g | %.3g | %.3f | %d | %d | %.1f | %s | %s |" % (
                name, label, t["triangles"], t["hausdorffPercent"],
                t.get("meanDistancePercent", float("nan")), t["kappaMean"],
                t["inverted"], t["errors"], t["cpu"], ratio[0], ratio[1]), flush=True)


if __name__ == "__main__":
    main()
