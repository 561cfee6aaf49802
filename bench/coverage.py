#!/usr/bin/env python3
"""Whether the STL recipe gives a whole mesh (bench/coverage.sh runs this).

Per mesh and map, runs the README's recipe in its own gmsh process and
compares the output surface mesh with the input: every discrete surface
meshed, no error, and as many boundary loops out as in (a surface left
unmeshed or a torn seam opens a new loop). Prints one Markdown row per run.
Python 3 standard library only.
"""

import argparse
import collections
import datetime
import json
import math
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshmeasures  # noqa: E402
import stlfile  # noqa: E402

# About this many output triangles: the input's own count, capped so the
# large meshes stay quick to remesh
MAX_TRIANGLES = 25000

MAP_LABELS = {6: "automatic (6)", 0: "Gmsh (0)", "cgal": "CGAL isotropic"}


def mesh_name(stl):
    return os.path.splitext(os.path.basename(stl))[0]


# --- Input -----------------------------------------------------------------


def read_stl(path):
    """Triangles of a binary or ASCII STL as triples of vertex ids, and the
    total area. STL repeats each corner in every triangle: corners with
    identical coordinates are welded into one vertex to get the edges."""
    corners = stlfile.stl_corners(path)
    ids = {}
    triangles = []
    area = 0.0
    for i in range(0, len(corners) - 2, 3):
        a, b, c = corners[i : i + 3]
        area += triangle_area(a, b, c)
        triangles.append(tuple(ids.setdefault(p, len(ids)) for p in (a, b, c)))
    return triangles, area


def triangle_area(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = (
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    )
    return 0.5 * math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)


def mesh_size(area, triangles):
    """Edge length of equilateral triangles that tile `area` with
    min(triangles, MAX_TRIANGLES) of them."""
    n = min(triangles, MAX_TRIANGLES)
    return math.sqrt(4.0 * area / (math.sqrt(3.0) * n))


# --- Topology --------------------------------------------------------------


def edge_uses(elements):
    """How many elements (triangles or quadrangles, as tuples of node ids)
    use each undirected edge."""
    uses = collections.Counter()
    for e in elements:
        if len(set(e)) < len(e):
            continue  # degenerate: its edges bound nothing
        for i in range(len(e)):
            a, b = e[i], e[(i + 1) % len(e)]
            uses[(a, b) if a < b else (b, a)] += 1
    return uses


def count_loops(edges):
    """Boundary loops formed by `edges` (pairs of node ids). Each walk is cut
    into a loop whenever it comes back to a node already on it, so two holes
    pinched at a node count as two loops; an open chain (left by
    non-manifold edges) counts as one, whatever the edges' order."""
    at = collections.defaultdict(list)
    for i, (a, b) in enumerate(edges):
        at[a].append(i)
        at[b].append(i)
    used = [False] * len(edges)
    loops = 0
    # Walks start at the ends of open chains first: a walk started inside a
    # chain would stop at one end and leave the rest as a second "loop"
    # (gmsh2x_car_body counted 22 to 25 loops for the same 13 boundary
    # components, depending on the edges' order)
    ends = [n for n, incident in at.items() if len(incident) % 2]
    starts = [(i, n) for n in ends for i in at[n]]
    starts += [(i, edges[i][0]) for i in range(len(edges))]
    for first, node in starts:
        if used[first]:
            continue
        path, position = [node], {node: 0}
        edge = first
        while edge is not None:
            used[edge] = True
            a, b = edges[edge]
            node = b if a == node else a
            if node in position:  # closed a loop: drop it from the path
                loops += 1
                for n in path[position[node] + 1 :]:
                    del position[n]
                del path[position[node] + 1 :]
            else:
                position[node] = len(path)
                path.append(node)
            edge = next((e for e in at[node] if not used[e]), None)
        if len(path) > 1:
            loops += 1
    return loops


def topology(elements):
    """(boundary loops, non-manifold edges) of a surface mesh."""
    uses = edge_uses(elements)
    boundary = [e for e, n in uses.items() if n == 1]
    return count_loops(boundary), sum(1 for n in uses.values() if n > 2)


# --- Output ----------------------------------------------------------------

# MSH element types of the surface elements: 3-node triangle, 4-node quad
SURFACE_ELEMENTS = {2: 3, 3: 4}


def read_msh_surface(path):
    """The triangles and quadrangles of the dimension-2 entities of an ASCII
    MSH 4.1 file, as tuples of node tags (Gmsh shares the nodes of a curve
    between the surfaces on either side, so tags weld the surfaces)."""
    with open(path) as f:
        lines = iter(f.read().splitlines())
    elements = None
    for line in lines:
        if line.strip() == "$MeshFormat":
            version = next(lines).split()
            if not version[0].startswith("4") or version[1] != "0":
                raise ValueError("not an ASCII MSH 4 file: %s" % " ".join(version))
        if line.strip() != "$Elements":
            continue
        blocks = int(next(lines).split()[0])
        elements = []
        for _ in range(blocks):
            dim, _tag, kind, count = (int(w) for w in next(lines).split())
            rows = [next(lines) for _ in range(count)]
            if dim == 2 and kind in SURFACE_ELEMENTS:
                corners = SURFACE_ELEMENTS[kind]
                elements += [
                    tuple(int(w) for w in r.split()[1 : 1 + corners]) for r in rows
                ]
    if elements is None:
        raise ValueError("no $Elements in %s" % path)
    return elements


def read_msh_nodes(path, dimensions=None):
    """Coordinates of the nodes of an ASCII MSH 4.1 file by tag; with a
    dict `dimensions`, also the dimension of the entity each is on."""
    with open(path) as f:
        lines = iter(f.read().splitlines())
    nodes = {}
    for line in lines:
        if line.strip() != "$Nodes":
            continue
        blocks = int(next(lines).split()[0])
        for _ in range(blocks):
            block = next(lines).split()
            count = int(block[3])
            tags = [int(next(lines)) for _ in range(count)]
            for tag in tags:
                nodes[tag] = tuple(float(w) for w in next(lines).split()[:3])
                if dimensions is not None:
                    dimensions[tag] = int(block[0])
    return nodes


def as_triangles(elements):
    """Quadrangles cut in two triangles along their first diagonal."""
    out = []
    for e in elements:
        out += [e] if len(e) == 3 else [(e[0], e[1], e[2]), (e[0], e[2], e[3])]
    return out


# The summary block Gmsh prints after meshing repeats the counts under the
# "Error" or "Warning" prefix (Msg::PrintErrorCounter): not messages
SUMMARY = re.compile(
    r"^(Error|Warning) *: *(-+|Mesh generation error summary"
    r"|\d+ (errors?|warnings?)|Check the full log for details)\s*$"
)

# "Reparam: layout of 86482 triangles: 1203 feature patches, 1110 noise
# patches merged (size 0.5), 12 splits, 98 patches (clean 0.1 s, split and
# verify 2.1 s, total 2.3 s)": one pattern per field, so a reworded line
# still gives the fields it keeps
LAYOUT_FIELDS = {
    "feature": (r"(\d+) feature patch", int),
    "merged": (r"(\d+) noise patch", int),
    "splits": (r"(\d+) splits?\b", int),
    "patches": (r"(\d+) patch(?:es)? *\(", int),
    "seconds": (r"total ([0-9.eE+-]+) *s", float),
}


def read_log(path):
    """Errors, warnings and the last Reparam layout line's fields (None for
    stock Gmsh, which has no layout) of a gmsh log."""
    errors = warnings = 0
    layout = None
    with open(path, errors="replace") as f:
        for line in f:
            if SUMMARY.match(line.strip()):
                continue
            errors += "Error" in line
            warnings += "Warning" in line
            if "Reparam: layout of" in line:
                layout = {}
                for name, (pattern, kind) in LAYOUT_FIELDS.items():
                    m = re.search(pattern, line)
                    layout[name] = kind(m.group(1)) if m else None
    return errors, warnings, layout


def read_report(path):
    """Meshed and all discrete surfaces, Hausdorff distance (% of the input's
    diagonal) and inverted elements from Mesh.CompoundReportFile, or None
    when gmsh did not write it (crash, timeout, no discrete surface).

    `surfaces` has one entry per discrete surface meshed (with or without
    elements); `unmeshedSurfaces` lists those without a parametrization,
    which the mesher skipped, and `inputKeptSurfaces` those meshed with
    their input triangles, by the safety net or after their planar mesh
    (Geo/report/reparamReportFormat.cpp)."""
    try:
        with open(path) as f:
            report = json.load(f)
        surfaces = report["surfaces"]
        keptTags = set(report.get("inputKeptSurfaces", []))
        kept = len(keptTags)
        # the kappa mean off the surfaces narrower than a quarter of the
        # size, which the report names (Geo/report/reparamReport.cpp): issue
        # 37's CAD goal holds there when the input forbids it on them
        narrow = set(report.get("narrowSurfaces", []))
        off = [s for s in surfaces if s["surface"] not in narrow
               and s["triangles"] and s.get("kappaMean") is not None]
        offNarrow = None
        if narrow and off:
            offNarrow = sum(s["kappaMean"] * s["triangles"] for s in off) / sum(
                s["triangles"] for s in off)
        # the safety net's surfaces have no line of their own; a surface
        # whose planar mesh gave way to its input after meshing has one
        keptOnly = len(keptTags - set(s["surface"] for s in surfaces))
        return {
            "meshed": keptOnly
            + sum(1 for s in surfaces if s["triangles"] + s["quadrangles"] > 0),
            "surfaces": len(surfaces) + len(report["unmeshedSurfaces"])
            + keptOnly,
            "kept": kept,
            "hausdorff": report["total"]["hausdorffPercent"],
            "inverted": report["total"]["inverted"],
            "kappa min": report["total"]["kappaMin"],
            "kappa mean": report["total"].get("kappaMean"),
            "kappa mean off narrow": offNarrow,
            "tau": report["total"].get("tau"),
            "eta min": report["total"].get("etaMin"),
            "eta mean": report["total"].get("etaMean"),
            # Mesh.CompoundOptimize: the worst kappa before it, its time
            "optimization": report["total"].get("optimization"),
        }
    except (OSError, ValueError, KeyError, TypeError):
        return None


# --- One run -----------------------------------------------------------------


def recipe(stl, map_value, size, folder, mesher="Mesh.Algorithm = 6;"):
    """The README's STL recipe with its default options (`mesher`: the
    planar mesher's options, Frontal-Delaunay by default)."""
    return "\n".join(
        [
            # the map first: Reparam repairs the STL facets' orientation at
            # Merge, Gmsh's own map (0) keeps the file as it is
            "Mesh.CompoundParametrization = %d;" % map_value,
            'Merge "%s";' % os.path.abspath(stl),
            "ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};",
            "CreateGeometry;",
            "Mesh.MeshSizeMin = %.9g;" % size,
            "Mesh.MeshSizeMax = %.9g;" % size,
            mesher,
            'Mesh.CompoundReportFile = "%s";' % os.path.join(folder, "report.json"),
            "Mesh.MshFileVersion = 4.1;",
            "Mesh.Binary = 0;",
            "Mesh 2;",
            'Save "%s";' % os.path.join(folder, "out.msh"),
            "",
        ]
    )


def run_gmsh(gmsh, geo, log, timeout):
    """Runs `gmsh geo -parse_and_exit` with its output in `log`. Returns
    (status, CPU seconds of the process): status is None when it ended, else
    why it did not ("timeout", "signal 11")."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    status = None
    with open(log, "w") as out:
        process = subprocess.Popen(
            [gmsh, geo, "-parse_and_exit"],
            stdout=out,
            stderr=subprocess.STDOUT,
            cwd=os.path.dirname(geo),
            start_new_session=True,  # its own group, to end all of it
        )
        try:
            code = process.wait(timeout=timeout)
            if code < 0:
                status = "signal %d" % -code
        except subprocess.TimeoutExpired:
            # as `timeout -k 5`: a chance to end cleanly, then killed
            status = "timeout"
            os.killpg(process.pid, signal.SIGTERM)
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return status, cpu


def measure(gmsh, stl, map_value, input_mesh, timeout, logs,
            mesher="Mesh.Algorithm = 6;", factor=1.0, reference=None):
    """One row's numbers for `stl` remeshed with `map_value` (and the planar
    mesher's options `mesher`) at `factor` times the bench's size; with
    `reference` (reference_surface()), the Hausdorff distance's two sides."""
    triangles, area, loops_in, nonmanifold_in = input_mesh
    with tempfile.TemporaryDirectory(prefix="reparam-coverage-") as folder:
        geo = os.path.join(folder, "recipe.geo")
        with open(geo, "w") as f:
            f.write(recipe(stl, map_value, factor * mesh_size(area, triangles),
                           folder, mesher))
        log = os.path.join(folder, "gmsh.log")
        status, cpu = run_gmsh(gmsh, geo, log, timeout)
        row = {
            "status": status,
            "cpu": cpu,
            "loops in": loops_in,
            "nonmanifold in": nonmanifold_in,
        }
        row["errors"], row["warnings"], row["layout"] = read_log(log)
        row["report"] = read_report(os.path.join(folder, "report.json"))
        row["out"] = None
        try:
            elements = read_msh_surface(os.path.join(folder, "out.msh"))
        except (OSError, ValueError, StopIteration):  # none, or cut short
            elements = None
        row["distances"] = None
        if elements is not None and reference:
            nodes = read_msh_nodes(os.path.join(folder, "out.msh"))
            row["distances"] = two_sided(
                *indexed(nodes, as_triangles(elements)), reference)
        if elements is not None:
            loops, nonmanifold = topology(elements)
            row["out"] = {
                "loops": loops,
                "nonmanifold": nonmanifold,
                "triangles": sum(1 for e in elements if len(e) == 3),
                "quadrangles": sum(1 for e in elements if len(e) == 4),
            }
        if logs:  # kept to look into a run that is not whole
            name = "%s-map%d%s.log" % (mesh_name(stl), map_value,
                                       "" if factor == 1.0 else "-x%g" % factor)
            shutil.copy(log, os.path.join(logs, name))
            shutil.copy(geo, os.path.join(logs, name[:-4] + ".geo"))
            if os.path.exists(os.path.join(folder, "out.msh")):
                shutil.copy(os.path.join(folder, "out.msh"),
                            os.path.join(logs, name[:-4] + ".msh"))
    row["whole"] = is_whole(row)
    return row


def indexed(nodes, elements):
    """(points, triangles by index into points) of elements by node tag."""
    index = {}
    points = []
    for e in elements:
        for n in e:
            if n not in index:
                index[n] = len(points)
                points.append(nodes[n])
    return points, [tuple(index[n] for n in e) for e in elements]


def reference_surface(stl):
    """The input as the Python measures need it: welded points, triangles,
    their bucket grid, bounding box diagonal."""
    points, triangles = meshmeasures.welded_surface(stl)
    return {
        "points": points,
        "triangles": triangles,
        "grid": meshmeasures.TriangleGrid(points, triangles),
        "diagonal": meshmeasures.diagonal(points),
    }


def two_sided(points, triangles, reference):
    """Hausdorff distance mesh -> input and input -> mesh, % of the input's
    diagonal, sampled on nodes and centroids (as Reparam's report)."""
    if not triangles:
        return None
    grid = meshmeasures.TriangleGrid(points, triangles)
    percent = 100.0 / reference["diagonal"]
    return {
        "mesh to input": percent * meshmeasures.one_sided_hausdorff(
            points, triangles, reference["grid"]),
        "input to mesh": percent * meshmeasures.one_sided_hausdorff(
            reference["points"], reference["triangles"], grid),
    }


def run_cgal(cgal, stl, size, out_stl, timeout):
    """CGAL's isotropic remeshing as bench/speed.py runs it (3 iterations,
    borders protected, the same target edge length): (status, CPU)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    status = None
    try:
        done = subprocess.run([cgal, stl, "%.9g" % size, "3", out_stl],
                              capture_output=True, timeout=timeout)
        if done.returncode:
            status = ("signal %d" % -done.returncode if done.returncode < 0
                      else "exit %d" % done.returncode)
    except subprocess.TimeoutExpired:
        status = "timeout"
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return status, cpu


def cgal_quality(points, triangles, reference, size):
    """The report's columns for a mesh without a report."""
    kmin, kmean = meshmeasures.kappa_min_mean(points, triangles)
    distances = two_sided(points, triangles, reference)
    return {
        "meshed": None, "surfaces": None, "kept": None,
        "hausdorff": distances and max(distances.values()),
        "inverted": meshmeasures.against_input(
            points, triangles, reference["points"], reference["triangles"],
            reference["grid"]),
        "kappa min": kmin, "kappa mean": kmean, "kappa mean off narrow": None,
        "tau": meshmeasures.tau(points, triangles, size),
        "optimization": None,
    }, distances


def measure_cgal(cgal, stl, input_mesh, timeout, factor, reference):
    """One row's numbers for `stl` remeshed by CGAL at the same size."""
    triangles, area, loops_in, nonmanifold_in = input_mesh
    size = factor * mesh_size(area, triangles)
    row = {"cpu": 0.0, "loops in": loops_in, "nonmanifold in": nonmanifold_in,
           "errors": None, "warnings": None, "layout": None, "report": None,
           "out": None, "distances": None}
    with tempfile.TemporaryDirectory(prefix="reparam-coverage-") as folder:
        out_stl = os.path.join(folder, "cgal.stl")
        row["status"], row["cpu"] = run_cgal(cgal, stl, size, out_stl, timeout)
        if row["status"] is None and os.path.exists(out_stl):
            points, elements = meshmeasures.welded_surface(out_stl)
            row["report"], row["distances"] = cgal_quality(
                points, elements, reference, size)
            loops, nonmanifold = topology(elements)
            row["out"] = {"loops": loops, "nonmanifold": nonmanifold,
                          "triangles": len(elements), "quadrangles": 0}
    row["whole"] = (row["status"] is None and row["out"] is not None
                    and row["out"]["loops"] == loops_in)
    return row


def input_topology(gmsh, stl):
    """Boundary loops and non-manifold edges of the input as Gmsh reads it:
    Gmsh merges STL corners within its geometry tolerance, so an STL whose
    facets leave cracks of 1e-12 is closed for Gmsh (featuretype: 16 loops
    by exact coordinates, none in Gmsh)."""
    with tempfile.TemporaryDirectory(prefix="reparam-coverage-") as folder:
        geo = os.path.join(folder, "input.geo")
        msh = os.path.join(folder, "input.msh")
        with open(geo, "w") as f:
            f.write('Merge "%s";\nMesh.Binary = 0;\nSave "%s";\n' % (stl, msh))
        subprocess.run([gmsh, geo, "-parse_and_exit"], stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=False)
        return topology(read_msh_surface(msh))


def is_whole(row):
    report, out = row["report"], row["out"]
    return (
        row["status"] is None
        and row["errors"] == 0
        and report is not None
        and report["meshed"] == report["surfaces"]
        and out is not None
        and out["loops"] == row["loops in"]
    )


# --- Table -------------------------------------------------------------------

COLUMNS = [
    "mesh", "map", "whole", "surfaces meshed / all", "kept as input",
    "loops in / out", "non-manifold edges in / out", "errors", "warnings",
    "Hausdorff (%)", "inverted", "kappa min", "kappa min before optimization",
    "optimization (s)", "triangles", "feature patches",
    "after cleaning",
    "final patches", "splits", "layout (s)", "CPU (s)",
]


def text(value, form="%s"):
    return "-" if value is None else form % value


# With a size sweep or CGAL's rows: the size factor and the measures that
# compare remeshers (older tables, without them, stay comparable)
SWEEP_COLUMNS = {
    "map": ["size factor"],
    "kappa min": ["kappa mean", "kappa mean off narrow surfaces", "tau (%)",
                  "Hausdorff mesh -> input (%)", "Hausdorff input -> mesh (%)"],
    "triangles": ["triangles / asked"],
}


def sweep_columns():
    columns = []
    for c in COLUMNS:
        columns += [c] + SWEEP_COLUMNS.get(c, [])
    return columns


def table_cells(name, map_value, row):
    """The row's cells by column name (COLUMNS and SWEEP_COLUMNS)."""
    report, out, layout = row["report"], row["out"], row["layout"] or {}
    optimization = report and report["optimization"]
    whole = "yes" if row["whole"] else "NO"
    if row["status"]:
        whole += " (%s)" % row["status"]
    after_cleaning = None
    if layout.get("feature") is not None and layout.get("merged") is not None:
        after_cleaning = layout["feature"] - layout["merged"]
    elements = None
    if out:
        elements = str(out["triangles"])
        if out["quadrangles"]:
            elements += " + %d quads" % out["quadrangles"]
    meshed = "no report"
    if report and report["meshed"] is not None:
        meshed = "%d / %d" % (report["meshed"], report["surfaces"])
    elif report:
        meshed = "-"
    cells = dict(zip(COLUMNS, [
        name,
        MAP_LABELS.get(map_value, "map %s" % map_value),
        whole,
        meshed,
        text(report and report["kept"]),
        "%d / %s" % (row["loops in"], text(out and out["loops"])),
        "%d / %s" % (row["nonmanifold in"], text(out and out["nonmanifold"])),
        text(row["errors"]),
        text(row["warnings"]),
        text(report and report["hausdorff"], "%.3g"),
        text(report and report["inverted"]),
        text(report and report["kappa min"], "%.3g"),
        text(optimization and optimization["kappaMinBefore"], "%.3g"),
        text(optimization and optimization["seconds"], "%.2f"),
        text(elements),
        text(layout.get("feature")),
        text(after_cleaning),
        text(layout.get("patches")),
        text(layout.get("splits")),
        text(layout.get("seconds"), "%.3g"),
        "%.1f" % row["cpu"],
    ]))
    cells.update(sweep_cells(row))
    return cells


def sweep_cells(row):
    report, distances, out = row["report"], row.get("distances"), row["out"]
    return {
        "size factor": "%g" % row.get("factor", 1.0),
        "kappa mean": text(report and report["kappa mean"], "%.3f"),
        "kappa mean off narrow surfaces":
            text(report and report["kappa mean off narrow"], "%.3f"),
        "tau (%)": text(report and report["tau"], "%.1f"),
        "Hausdorff mesh -> input (%)":
            text(distances and distances["mesh to input"], "%.3g"),
        "Hausdorff input -> mesh (%)":
            text(distances and distances["input to mesh"], "%.3g"),
        "triangles / asked": text(
            out and row.get("asked") and out["triangles"] / row["asked"],
            "%.2f"),
    }


def table_row(name, map_value, row, columns=COLUMNS):
    cells = table_cells(name, map_value, row)
    return "| " + " | ".join(cells[c] for c in columns) + " |"


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def command_output(command):
    result = subprocess.run(command, capture_output=True, text=True)
    return (result.stdout + result.stderr).strip() or "unknown"


def header(repo, gmsh, timeout, maps, factors=(1.0,), cgal=""):
    commit = command_output(["git", "-C", repo, "rev-parse", "--short", "HEAD"])
    # the version names the commit the executable was built from
    version = command_output([gmsh, "-version"])
    text_ = (
        "Coverage of the STL recipe (bench/coverage.sh), %s, commit %s, "
        "%d CPUs (%s), Gmsh %s, timeout %g s, maps %s. Per mesh and map, one gmsh "
        "process runs Merge, ClassifySurfaces{40, 1, 1, 180}, CreateGeometry "
        "and Mesh 2 (Frontal-Delaunay, size for about min(input triangles, "
        "%d) triangles). Whole: no error, every discrete surface meshed and "
        "as many boundary loops out as in."
        % (
            datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), commit,
            len(os.sched_getaffinity(0)), cpu_model(), version, timeout,
            ", ".join(map(str, maps)), MAX_TRIANGLES,
        )
    )
    if list(factors) != [1.0] or cgal:
        text_ += (
            " Size factors %s (times that size; triangles / asked: against "
            "the input's area / (sqrt(3)/4 h^2)).%s Kappa mean and tau from "
            "the report (CGAL: the same definitions in bench/meshmeasures.py, "
            "tau for the constant size, inverted: against the closest input "
            "facet's normal at the centroid, '-' when the input's facets "
            "disagree); Hausdorff mesh -> input and input -> mesh sampled "
            "in Python on nodes and centroids."
            % (" ".join("%g" % f for f in factors),
               " CGAL: isotropic remeshing, 3 iterations, borders "
               "protected, the same h." if cgal else ""))
    return text_


def arguments():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--gmsh", required=True)
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--maps", default="6 0")
    parser.add_argument("--sizes", default="1",
                        help="factors applied to the bench's size")
    parser.add_argument("--cgal", default="",
                        help="cgalRemesh executable: a CGAL row per mesh and size")
    parser.add_argument("--repo", default=os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--logs", help="folder to copy each run's gmsh log to")
    parser.add_argument("meshes", nargs="+")
    return parser.parse_args()


def mesh_rows(args, stl, maps, factors, sweep):
    """(map, factor, row) of every run on one mesh, in the table's order."""
    triangles, area = read_stl(stl)
    input_mesh = (len(triangles), area) + input_topology(args.gmsh, stl)
    reference = reference_surface(stl) if sweep else None
    for factor in factors:
        runs = [(m, lambda m=m: measure(
            args.gmsh, stl, m, input_mesh, args.timeout, args.logs,
            factor=factor, reference=reference)) for m in maps]
        if args.cgal:
            runs.append(("cgal", lambda: measure_cgal(
                args.cgal, stl, input_mesh, args.timeout, factor, reference)))
        for map_value, run in runs:
            row = run()
            row["factor"] = factor
            row["asked"] = min(len(triangles), MAX_TRIANGLES) / factor ** 2
            yield map_value, factor, row


def summary_label(map_value, factor, sweep):
    label = MAP_LABELS.get(map_value, "map %s" % map_value)
    return label + (" at size x%g" % factor if sweep else "")


def main():
    args = arguments()
    maps = [int(m) for m in args.maps.split()]
    factors = [float(f) for f in args.sizes.split()]
    sweep = factors != [1.0] or bool(args.cgal)
    columns = sweep_columns() if sweep else COLUMNS
    if args.logs:
        os.makedirs(args.logs, exist_ok=True)

    print(header(args.repo, args.gmsh, args.timeout, maps, factors, args.cgal))
    print()
    print("| " + " | ".join(columns) + " |")
    print("|---|---|" + "---|" * sweep + "---|" + "---:|" * (len(columns) - 3 - sweep))
    whole = collections.Counter()
    cpu = collections.Counter()
    order = []
    for stl in args.meshes:
        for map_value, factor, row in mesh_rows(args, stl, maps, factors, sweep):
            key = (map_value, factor)
            if key not in order:
                order.append(key)
            whole[key] += row["whole"]
            cpu[key] += row["cpu"]
            print(table_row(mesh_name(stl), map_value, row, columns), flush=True)
    print()
    for key in order:
        print("- %s: %d of %d meshes whole, CPU %.1f s"
              % (summary_label(key[0], key[1], sweep), whole[key],
                 len(args.meshes), cpu[key]))


if __name__ == "__main__":
    sys.exit(main())
