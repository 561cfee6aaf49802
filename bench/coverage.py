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
import stlfile  # noqa: E402

# About this many output triangles: the input's own count, capped so the
# large meshes stay quick to remesh
MAX_TRIANGLES = 25000

MAP_LABELS = {6: "automatic (6)", 0: "Gmsh (0)"}


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
            mesher="Mesh.Algorithm = 6;"):
    """One row's numbers for `stl` remeshed with `map_value` (and the planar
    mesher's options `mesher`)."""
    triangles, area, loops_in, nonmanifold_in = input_mesh
    with tempfile.TemporaryDirectory(prefix="reparam-coverage-") as folder:
        geo = os.path.join(folder, "recipe.geo")
        with open(geo, "w") as f:
            f.write(recipe(stl, map_value, mesh_size(area, triangles), folder,
                           mesher))
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
        if elements is not None:
            loops, nonmanifold = topology(elements)
            row["out"] = {
                "loops": loops,
                "nonmanifold": nonmanifold,
                "triangles": sum(1 for e in elements if len(e) == 3),
                "quadrangles": sum(1 for e in elements if len(e) == 4),
            }
        if logs:  # kept to look into a run that is not whole
            name = "%s-map%d.log" % (mesh_name(stl), map_value)
            shutil.copy(log, os.path.join(logs, name))
            shutil.copy(geo, os.path.join(logs, name[:-4] + ".geo"))
            if os.path.exists(os.path.join(folder, "out.msh")):
                shutil.copy(os.path.join(folder, "out.msh"),
                            os.path.join(logs, name[:-4] + ".msh"))
    row["whole"] = is_whole(row)
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


def table_row(name, map_value, row):
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
    cells = [
        name,
        MAP_LABELS.get(map_value, "map %d" % map_value),
        whole,
        "%d / %d" % (report["meshed"], report["surfaces"]) if report else "no report",
        text(report and report["kept"]),
        "%d / %s" % (row["loops in"], text(out and out["loops"])),
        "%d / %s" % (row["nonmanifold in"], text(out and out["nonmanifold"])),
        str(row["errors"]),
        str(row["warnings"]),
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
    ]
    return "| " + " | ".join(cells) + " |"


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


def header(repo, gmsh, timeout, maps):
    commit = command_output(["git", "-C", repo, "rev-parse", "--short", "HEAD"])
    # the version names the commit the executable was built from
    version = command_output([gmsh, "-version"])
    return (
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


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--gmsh", required=True)
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--maps", default="6 0")
    parser.add_argument("--repo", default=os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--logs", help="folder to copy each run's gmsh log to")
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    maps = [int(m) for m in args.maps.split()]
    if args.logs:
        os.makedirs(args.logs, exist_ok=True)

    print(header(args.repo, args.gmsh, args.timeout, maps))
    print()
    print("| " + " | ".join(COLUMNS) + " |")
    print("|---|---|---|" + "---:|" * (len(COLUMNS) - 3))
    whole = collections.Counter()
    cpu = collections.Counter()
    for stl in args.meshes:
        name = mesh_name(stl)
        triangles, area = read_stl(stl)
        input_mesh = (len(triangles), area) + input_topology(args.gmsh, stl)
        for map_value in maps:
            row = measure(
                args.gmsh, stl, map_value, input_mesh, args.timeout, args.logs
            )
            whole[map_value] += row["whole"]
            cpu[map_value] += row["cpu"]
            print(table_row(name, map_value, row), flush=True)
    print()
    for map_value in maps:
        print(
            "- %s: %d of %d meshes whole, CPU %.1f s"
            % (MAP_LABELS.get(map_value, "map %d" % map_value), whole[map_value],
               len(args.meshes), cpu[map_value])
        )


if __name__ == "__main__":
    sys.exit(main())
