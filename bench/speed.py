#!/usr/bin/env python3
"""The speed bench's runs and table (bench/speed.sh)."""

import argparse
import datetime
import math
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import coverage  # noqa: E402

# Reparam's stages, from Gmsh's "Done ... (Wall ..s, CPU ..s)" lines
STAGES = [
    ("classify", "Done classifying surfaces"),
    ("geometry", "Done creating geometry of discrete surfaces"),
    ("1D", "Done meshing 1D"),
    ("2D", "Done meshing 2D"),
]


def stage_seconds(log):
    """CPU seconds of each stage in a gmsh log (None where missing)."""
    text = open(log, errors="replace").read()
    out = {}
    for name, line in STAGES:
        m = re.search(re.escape(line) + r".*?CPU ([0-9.eE+-]+)s", text)
        out[name] = float(m.group(1)) if m else None
    m = re.search(r"split and verify ([0-9.eE+-]+) s", text)
    out["layout"] = float(m.group(1)) if m else None
    m = re.search(r"Reparam: total +\d+ surf\.\s+(.*)", text)
    out["triangles"] = int(m.group(1).split()[7]) if m else None
    return out


QUALITY = [
    ("kmin", r"kappa min ([0-9.eE+-]+)"),
    ("kmean", r"kappa min [0-9.eE+-]+ mean ([0-9.eE+-]+)"),
    ("tau", r"tau ([0-9.eE+-]+)%"),
    ("hausdorff", r"against '.*' \(\d+ elements\): Hausdorff ([0-9.eE+-]+)%"),
    ("against", r"of its diagonal, (\d+) elements pointing"),
]


def measure(gmsh, mesh, stl, size, timeout):
    """Plugin(SurfaceMeshQuality) on the mesh file `mesh`, against the STL it
    was made from (Reference): the same measures for every remesher's
    output. A dict of QUALITY's names (None where missing)."""
    with tempfile.TemporaryDirectory(prefix="reparam-quality-") as folder:
        geo = os.path.join(folder, "quality.geo")
        with open(geo, "w") as f:
            f.write("\n".join([
                'Merge "%s";' % os.path.abspath(mesh),
                "Mesh.MeshSizeMin = %.9g;" % size,
                "Mesh.MeshSizeMax = %.9g;" % size,
                "Plugin(SurfaceMeshQuality).CreateViews = 0;",
                'Plugin(SurfaceMeshQuality).Reference = "%s";'
                % os.path.abspath(stl),
                "Plugin(SurfaceMeshQuality).Run;", ""]))
        log = os.path.join(folder, "quality.log")
        status, _ = coverage.run_gmsh(gmsh, geo, log, timeout)
        text_ = open(log, errors="replace").read()
        out = {}
        for name, pattern in QUALITY:
            m = re.search(pattern, text_)
            out[name] = float(m.group(1)) if m and not status else None
        return out


def run_gmsh(gmsh, stl, map_value, size, timeout, threads=1, quality=None):
    """(status, CPU, stages); stages["wall"]: the process's wall seconds;
    with quality (the gmsh executable to measure with), stages["quality"]:
    measure()'s of the mesh written."""
    with tempfile.TemporaryDirectory(prefix="reparam-speed-") as folder:
        geo = os.path.join(folder, "recipe.geo")
        with open(geo, "w") as f:
            f.write("General.NumThreads = %d;\n" % threads)
            f.write(coverage.recipe(stl, map_value, size, folder))
        log = os.path.join(folder, "gmsh.log")
        start = time.time()
        status, cpu = coverage.run_gmsh(gmsh, geo, log, timeout)
        wall = time.time() - start
        stages = stage_seconds(log)
        stages["wall"] = wall
        out_msh = os.path.join(folder, "out.msh")
        if quality and os.path.exists(out_msh):
            stages["quality"] = measure(quality, out_msh, stl, size, timeout)
        if stages["triangles"] is None:
            try:
                out = coverage.read_msh_surface(os.path.join(folder, "out.msh"))
                stages["triangles"] = sum(1 for e in out if len(e) == 3)
            except (OSError, ValueError, StopIteration):
                pass
        return status, cpu, stages


def floor_geos(stl, triangles, folder):
    """The two runs of Gmsh's own floor: its reading and classification of
    the STL without reparametrization (no split loop, no map), and
    Frontal-Delaunay on a unit square (the simplest parametrization there
    is, the identity) at the size that gives `triangles` triangles, written
    as the recipe writes its mesh."""
    classify = "\n".join([
        "Mesh.CompoundParametrization = 0;",
        'Merge "%s";' % os.path.abspath(stl),
        "ClassifySurfaces{40 * Pi / 180, 1, 0, 180 * Pi / 180};", ""])
    h = math.sqrt(4.0 / math.sqrt(3.0) / max(triangles, 1))
    square = "\n".join(
        ["Point(%d) = {%d, %d, 0, %.9g};" % (i + 1, x, y, h)
         for i, (x, y) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)])] +
        ["Line(%d) = {%d, %d};" % (i + 1, i + 1, (i + 1) % 4 + 1)
         for i in range(4)] +
        ["Curve Loop(1) = {1, 2, 3, 4};", "Plane Surface(1) = {1};",
         "Mesh.Algorithm = 6;", "Mesh.MshFileVersion = 4.1;",
         "Mesh.Binary = 0;", "Mesh 2;",
         'Save "%s";' % os.path.join(folder, "square.msh"), ""])
    return classify, square


def run_floor(gmsh, stl, triangles, timeout):
    """Gmsh's own floor under the recipe (reading and classifying the STL,
    meshing as many triangles on a plane): CPU and wall of the two runs
    less one process start (an empty run), and the wall of the first (the
    classification runs on one thread)."""
    with tempfile.TemporaryDirectory(prefix="reparam-floor-") as folder:
        classify, square = floor_geos(stl, triangles, folder)
        runs = []
        for name, text_ in (("classify", classify), ("square", square),
                            ("empty", "")):
            geo = os.path.join(folder, name + ".geo")
            with open(geo, "w") as f:
                f.write(text_)
            start = time.time()
            status, cpu = coverage.run_gmsh(
                gmsh, geo, os.path.join(folder, name + ".log"), timeout)
            if status:
                return None
            runs.append((cpu, time.time() - start))
        (c1, w1), (c2, w2), (c0, w0) = runs
        return {"cpu": c1 + c2 - c0, "wall": w1 + w2 - w0,
                "classifyCpu": c1 - c0, "squareCpu": c2 - c0,
                "classifyWall": w1 - w0, "squareWall": w2 - w0}


def run_cgal(cgal, stl, size, timeout, out_stl=None):
    """(status, CPU, triangles, wall); with out_stl, CGAL's mesh written
    there (after its timing, in the same process)"""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    command = [cgal, stl, "%.9g" % size] + (["3", out_stl] if out_stl else [])
    try:
        out = subprocess.run(command, capture_output=True, text=True,
                             timeout=timeout).stdout
    except subprocess.TimeoutExpired:
        return "timeout", None, None, None
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    m = re.search(r"cgal triangles (\d+)", out)
    return None, cpu, int(m.group(1)) if m else None, wall


def text(value, form="%.2f"):
    return "-" if value is None else form % value


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gmsh", required=True)
    parser.add_argument("--cgal", default="")
    parser.add_argument("--repo", required=True)
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("meshes", nargs="+")
    a = parser.parse_args()
    print("Speed of the STL recipe (bench/speed.sh), %s, commit %s, %d CPUs "
          "(%s), Gmsh %s, timeout %g s." % (
              datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
              coverage.command_output(
                  ["git", "-C", a.repo, "rev-parse", "--short", "HEAD"]),
              len(os.sched_getaffinity(0)), coverage.cpu_model(),
              coverage.command_output([a.gmsh, "-version"]), a.timeout))
    print("\nCPU seconds of each process (Reparam: the README's recipe with "
          "the defaults; stock: Gmsh's own map and split loop; CGAL: "
          "isotropic remeshing, 3 iterations, borders protected, after "
          "reading and orienting the STL), at the same target edge length. "
          "Reparam's stages are the CPU its log gives for each.\n")
    print("| mesh | input triangles | size | Reparam CPU (s) | classify | "
          "CreateGeometry | 1D | 2D | stock CPU (s) | CGAL CPU (s) | "
          "Reparam / CGAL | Reparam / stock | triangles Reparam | stock | "
          "CGAL |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
          "---:|---:|")
    total = {"reparam": 0.0, "stock": 0.0, "cgal": 0.0}
    walls = []
    floors = []
    qualities = []
    for stl in a.meshes:
        triangles, area = coverage.read_stl(stl)
        size = coverage.mesh_size(area, len(triangles))
        rs, rcpu, rst = run_gmsh(a.gmsh, stl, 6, size, a.timeout,
                                 quality=a.gmsh)
        ss, scpu, sst = run_gmsh(a.gmsh, stl, 0, size, a.timeout,
                                 quality=a.gmsh)
        cquality = None
        if a.cgal:
            with tempfile.TemporaryDirectory(prefix="reparam-cgal-") as d:
                out_stl = os.path.join(d, "cgal.stl")
                cs, ccpu, ctri, cwall = run_cgal(a.cgal, stl, size, a.timeout,
                                                 out_stl)
                if not cs and os.path.exists(out_stl):
                    cquality = measure(a.gmsh, out_stl, stl, size, a.timeout)
        else:
            cs, ccpu, ctri, cwall = None, None, None, None
        qualities.append((coverage.mesh_name(stl), rst.get("quality"),
                          sst.get("quality"), cquality))
        ts, tcpu, tst = run_gmsh(a.gmsh, stl, 6, size, a.timeout, threads=2)
        tst["cpu"] = tcpu
        walls.append((coverage.mesh_name(stl), rst, tst, cwall))
        if len(triangles) >= 10000 and rst["triangles"] and ccpu:
            floors.append((coverage.mesh_name(stl), rcpu, ccpu, cwall,
                           rst["triangles"],
                           run_floor(a.gmsh, stl, rst["triangles"],
                                     a.timeout)))
        total["reparam"] += rcpu
        total["stock"] += scpu
        total["cgal"] += ccpu or 0.0
        stock = text(scpu, "%.2f") + (" (%s)" % ss if ss else "")
        print("| %s | %d | %.4g | %s | %s | %s | %s | %s | %s | %s | %s | %s "
              "| %s | %s | %s |" % (
                  coverage.mesh_name(stl), len(triangles), size,
                  text(rcpu) + (" (%s)" % rs if rs else ""),
                  text(rst["classify"]), text(rst["geometry"]),
                  text(rst["1D"]), text(rst["2D"]), stock,
                  text(ccpu) + (" (%s)" % cs if cs else ""),
                  text(rcpu / ccpu if ccpu else None, "%.1f"),
                  text(rcpu / scpu if scpu else None, "%.2f"),
                  text(rst["triangles"], "%d"), text(sst["triangles"], "%d"),
                  text(ctri, "%d")))
    print("\nTotal CPU: Reparam %.1f s, stock %.1f s, CGAL %.1f s."
          % (total["reparam"], total["stock"], total["cgal"]))
    print("\nWall seconds, Reparam with General.NumThreads = 1 and 2 (Gmsh "
          "built with OpenMP: the layout verifies its parts and Mesh2D "
          "meshes the surfaces on both threads; Reparam's curves are "
          "meshed on one), CGAL (one "
          "thread), and Reparam's CPU with 2 threads:\n")
    print("| mesh | Reparam wall, 1 thread | 2 threads | 1 / 2 | layout "
          "(split and verify), 1 thread | 2 threads | CPU, 2 threads | CGAL "
          "wall | Reparam 2 threads / CGAL (wall) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, one, two, cgal_wall in walls:
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, text(one["wall"]), text(two["wall"]),
            text(one["wall"] / two["wall"] if two["wall"] else None),
            text(one["layout"], "%.3g"), text(two["layout"], "%.3g"),
            text(two["cpu"]), text(cgal_wall),
            text(two["wall"] / cgal_wall if cgal_wall else None, "%.1f")))
    print_floors(floors)
    print_qualities(qualities)



def print_floors(floors):
    """Gmsh's own floor against CGAL, for issue 15's target (CPU within 2x
    CGAL's on every mesh of 10k input triangles or more)"""
    if not floors:
        return
    print("\nGmsh's own floor, same run, meshes of 10k input triangles or "
          "more: the CPU of the steps of the recipe that are Gmsh's and "
          "stay (reading the STL and Gmsh's classification without "
          "reparametrization, one process; Frontal-Delaunay meshing as many "
          "triangles as Reparam's mesh on a unit square, the identity map, "
          "and writing them, another; less an empty process's start). No "
          "map, no discrete surface, no optimization, no report: any "
          "recipe that uses Gmsh's planar mesher unchanged costs more. "
          "Wall, 2 threads: the classification's wall (one thread) plus "
          "half the square's (the surfaces meshed on both).\n")
    print("| mesh | triangles | Reparam CPU (s) | floor CPU (s) | reading "
          "and classification | square | CGAL CPU (s) | floor / CGAL | "
          "square / CGAL | Reparam / floor | floor wall, 2 threads (s) | "
          "CGAL wall (s) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, rcpu, ccpu, cwall, triangles, f in floors:
        if f is None:
            print("| %s | %d | %s | - | - | - | %s | - | - | - | - | %s |" % (
                name, triangles, text(rcpu), text(ccpu), text(cwall)))
            continue
        print("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |"
              % (name, triangles, text(rcpu), text(f["cpu"]),
                 text(f["classifyCpu"]), text(f["squareCpu"]), text(ccpu),
                 text(f["cpu"] / ccpu, "%.2f"),
                 text(f["squareCpu"] / ccpu, "%.2f"),
                 text(rcpu / f["cpu"], "%.1f"),
            text(f["classifyWall"] + 0.5 * f["squareWall"]), text(cwall)))


def print_qualities(qualities):
    """The three meshes side by side, measured alike"""
    print("\nQuality side by side, the same meshes: each output merged in "
          "gmsh and measured by Plugin(SurfaceMeshQuality) with the input "
          "STL as `Reference` (kappa min / mean, tau in % against the size "
          "asked, Hausdorff distance in % of the input's diagonal).\n")
    print("| mesh | Reparam | stock | CGAL |")
    print("|---|---|---|---|")

    def cell(q):
        if not q or q.get("kmin") is None:
            return "-"
        return "%s / %s / %s / %s" % (
            text(q["kmin"], "%.3f"), text(q["kmean"], "%.3f"),
            text(q["tau"], "%.1f"), text(q["hausdorff"], "%.3f"))

    for name, reparam, stock, cgal in qualities:
        print("| %s | %s | %s | %s |" % (name, cell(reparam), cell(stock),
                                         cell(cgal)))


if __name__ == "__main__":
    main()
