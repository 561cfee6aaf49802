#!/usr/bin/env bash
# The paper's Table 1 on real data: for each mesh, each map (mean value 3,
# finite element conformal 4, spectral conformal 5, Gmsh's own 0) and each
# planar mesher (Delaunay 5, Frontal-Delaunay 6, MeshAdapt 1), the STL recipe
# end to end in its own process (reparamBenchRemesh) at one uniform size per
# mesh, the input's mean edge length (which keeps about the input's triangle
# count):
#
#   bench/table1.sh [file.stl ...]   (REPARAM_BENCH_TIMEOUT, default 300 s;
#                                     REPARAM_TABLE1_MAPS, default "3 4 5 0";
#                                     REPARAM_TABLE1_MESHERS, default "5 6 1")
#
# Prints a Markdown table (kappa min, and before Mesh.CompoundOptimize with
# its time, kappa mean, tau, elements, times,
# faces meshed, inverted elements, faces where the map was not one-to-one
# and the mean value map took over) and, per mesh, the best map x mesher:
# every face meshed, fewest inverted elements, then the highest kappa min
# (to 0.01), then the highest kappa mean. A mesh whose ClassifySurfaces does
# not end within the time limit is reported once and skipped.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
benchProgram reparamBenchRemesh
timeout=${REPARAM_BENCH_TIMEOUT:-300}
maps=(${REPARAM_TABLE1_MAPS:-3 4 5 0})
meshers=(${REPARAM_TABLE1_MESHERS:-5 6 1})
benchMeshes "$@"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
results=$tmp/results

echo "# bench/table1.sh — $(date +%F), $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores"
echo
echo "Commit $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown); timeout ${timeout} s per run."
echo
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh" .stl)
  for map in "${maps[@]}"; do
    for mesher in "${meshers[@]}"; do
      out=$(timeout -k 5 "$timeout" "$bench" "$mesh" "$map" "$mesher" 2>/dev/null)
      line=$(echo "$out" | grep '^remesh')
      if [ -n "$line" ]; then
        echo "$name $line" >> "$results"
      elif echo "$out" | grep -q '^classify'; then
        echo "$name timeout map $map algorithm $mesher" >> "$results"
      else
        echo "$name unclassified map $map algorithm $mesher" >> "$results"
        continue 3
      fi
    done
  done
done

python3 - "$results" "$timeout" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1])]
timeout = sys.argv[2]
mapNames = {"0": "Gmsh (0)", "1": "harmonic (1)", "2": "barycentric (2)",
            "3": "mean value (3)", "4": "FE conformal (4)",
            "5": "spectral (5)", "6": "automatic (6)"}
mesherNames = {"1": "MeshAdapt", "5": "Delaunay", "6": "Frontal-Delaunay"}
print("| mesh | map | mesher | faces meshed | CreateGeometry (s) | Mesh 2 (s) "
      "| elements | kappa min | kappa min before optimization "
      "| optimization (s) | kappa mean | tau (%) | inverted | MV fallbacks |")
print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
best = {}
order = []
for r in rows:
    name, kind = r[0], r[1]
    if name not in order:
        order.append(name)
    if kind == "unclassified":
        print("| %s | | | ClassifySurfaces did not end within %s s ||||||||"
              % (name, timeout))
        continue
    f = dict(zip(r[2::2], r[3::2]))
    label, mesher = mapNames[f["map"]], mesherNames[f["algorithm"]]
    if kind == "timeout":
        print("| %s | %s | %s | did not end within %s s ||||||||||"
              % (name, label, mesher, timeout))
        continue
    elements = int(f["triangles"]) + int(f["quadrangles"])
    # Mesh.CompoundOptimize (Reparam's maps only): the worst triangle before
    # it, and its time (within Mesh 2)
    optimized = int(f.get("optimizedFaces", "0")) > 0
    before = "%.3f" % float(f["kappaMinBeforeOptimization"]) if optimized else ""
    seconds = "%.3f" % float(f["optimization"]) if optimized else ""
    print("| %s | %s | %s | %s / %s | %.3f | %.3f | %d | %.3f | %s | %s | %.3f "
          "| %.1f | %s | %s |" % (name, label, mesher, f["meshed"], f["faces"],
                                  float(f["geometry"]), float(f["mesh"]),
                                  elements, float(f["kappaMin"]), before,
                                  seconds, float(f["kappaMean"]),
                                  float(f["tau"]), f["inverted"],
                                  f["fallbacks"] if f["map"] != "0" else ""))
    key = (f["meshed"] == f["faces"], -int(f["inverted"]),
           round(float(f["kappaMin"]), 2), float(f["kappaMean"]))
    if name not in best or key > best[name][0]:
        best[name] = (key, "%s + %s" % (label, mesher), f)
print()
print("Best map x mesher per mesh (every face meshed, fewest inverted, then "
      "kappa min to 0.01, then kappa mean):")
print()
print("| mesh | best | kappa min | kappa mean | tau (%) | inverted |")
print("|---|---|---:|---:|---:|---:|")
for name in order:
    if name in best:
        key, label, f = best[name]
        print("| %s | %s | %.3f | %.3f | %.1f | %s |" % (
            name, label, float(f["kappaMin"]), float(f["kappaMean"]),
            float(f["tau"]), f["inverted"]))
PY
