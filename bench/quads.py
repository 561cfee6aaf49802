#!/usr/bin/env python3
"""The paper's quadrangle table (Sec. 6.2) on the smooth meshes: per mesh and
map, the STL recipe with Frontal-Delaunay for quads and Blossom
(Mesh.Algorithm = 8, Mesh.RecombineAll = 1), default options otherwise, at
the coverage bench's size; eta min and mean, tau, triangles left (% of the
elements), Hausdorff distance, inverted elements from Reparam's JSON report,
and the gmsh process's CPU time. Map 0 is stock Gmsh (its own map, no
Reparam step runs on it). See bench/quads.sh."""

import argparse
import datetime
import json
import os
import resource
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import coverage  # noqa: E402

MAP_NAMES = {0: "Gmsh (0)", 4: "FE conformal (4)", 5: "spectral (5)",
             6: "automatic (6)"}


def recipe(stl, map_value, size_min, size_max, options, folder):
    """The STL recipe with these mesh sizes and extra .geo lines."""
    return "\n".join([
        "Mesh.CompoundParametrization = %d;" % map_value,
        'Merge "%s";' % os.path.abspath(stl),
        "ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};",
        "CreateGeometry;",
        "Mesh.MeshSizeMin = %.9g;" % size_min,
        "Mesh.MeshSizeMax = %.9g;" % size_max]
        + options
        + ['Mesh.CompoundReportFile = "%s";' % os.path.join(folder, "report.json"),
           "Mesh 2;", ""])


def run(gmsh, stl, map_value, size_min, size_max, options, timeout):
    """The report's total line, with the process's CPU time and its count
    of Error lines; None if gmsh wrote no report (crash, timeout)."""
    with tempfile.TemporaryDirectory() as folder:
        geo = os.path.join(folder, "recipe.geo")
        with open(geo, "w") as f:
            f.write(recipe(stl, map_value, size_min, size_max, options, folder))
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        try:
            out = subprocess.run([gmsh, geo, "-parse_and_exit"], cwd=folder,
                                 capture_output=True, text=True,
                                 timeout=timeout).stdout
        except subprocess.TimeoutExpired:
            return None
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        try:
            with open(os.path.join(folder, "report.json")) as f:
                total = json.load(f)["total"]
        except (OSError, ValueError, KeyError):
            return None
        total["cpu"] = cpu
        total["errors"] = sum(1 for l in out.splitlines() if l.startswith("Error"))
        return total


def coverage_size(stl):
    """The coverage bench's size for this STL."""
    triangles, area = coverage.read_stl(stl)
    return coverage.mesh_size(area, len(triangles))


def cell(value, form):
    return "-" if value is None else form % value


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--gmsh", required=True)
    p.add_argument("--repo", required=True)
    p.add_argument("--maps", default="0 4 5 6")
    p.add_argument("--timeout", type=float, default=300)
    p.add_argument("meshes", nargs="+")
    a = p.parse_args()
    maps = [int(m) for m in a.maps.split()]
    commit = coverage.command_output(["git", "-C", a.repo, "rev-parse", "--short", "HEAD"])
    print("Quadrangles (bench/quads.sh), %s, commit %s, %s: the STL recipe with "
          "Mesh.Algorithm = 8 and Mesh.RecombineAll = 1 (Blossom), defaults "
          "otherwise, size for about min(input triangles, %d) triangles. eta: "
          "Eq. 4 of the paper over the quadrangles; tri.: triangles left, %% of "
          "the elements; H: Hausdorff distance, %% of the diagonal.\n"
          % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), commit,
             coverage.cpu_model(), coverage.MAX_TRIANGLES))
    print("| mesh | map | quads | tri. (%) | eta min | eta mean | tau (%) | H (%) | inverted | errors | CPU (s) |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for stl in a.meshes:
        size = coverage_size(stl)
        for m in maps:
            t = run(a.gmsh, stl, m, size, size,
                    ["Mesh.Algorithm = 8;", "Mesh.RecombineAll = 1;"], a.timeout)
            name = os.path.basename(stl)[:-4]
            if t is None:
                print("| %s | %s | failed |||||||||" % (name, MAP_NAMES.get(m, m)))
                continue
            q, tr = t.get("quadrangles", 0), t.get("triangles", 0)
            print("| %s | %s | %d | %s | %s | %s | %s | %s | %s | %d | %.1f |" % (
                name, MAP_NAMES.get(m, str(m)), q,
                cell(100. * tr / max(q + tr, 1), "%.1f"),
                cell(t.get("etaMin"), "%.3f"), cell(t.get("etaMean"), "%.3f"),
                cell(t.get("tau"), "%.1f"), cell(t.get("hausdorffPercent"), "%.3g"),
                cell(t.get("inverted"), "%d"), t["errors"], t["cpu"]), flush=True)


if __name__ == "__main__":
    main()
