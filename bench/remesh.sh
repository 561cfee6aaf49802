#!/usr/bin/env bash
# The STL recipe end to end (Merge, ClassifySurfaces{40, 1, 1, 180},
# CreateGeometry, Mesh 2 with Frontal-Delaunay at the input's mean edge
# length) with the automatic chain (Mesh.CompoundParametrization = 6)
# against Gmsh's own map (0), each in its own process, on the tutorials' STL
# and every mesh of ../shared/data/meshes (when present):
#
#   bench/remesh.sh [file.stl ...]   (REPARAM_BENCH_TIMEOUT, default 120 s;
#                                     REPARAM_BENCH_ALGORITHM, default 6)
#
# Per mesh and map: faces meshed / parametrized, CreateGeometry and Mesh 2
# times, triangles, kappa min and mean, elements pointing against the input
# normals (input triangles closest to their centroid and to the points
# halfway to their corners, after Gmsh orients the mesh), two-sided Hausdorff and mean distance to the input in % of its
# bounding-box diagonal.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
benchProgram reparamBenchRemesh
timeout=${REPARAM_BENCH_TIMEOUT:-120}
algorithm=${REPARAM_BENCH_ALGORITHM:-6}

benchMeshes "$@"

printf '| mesh | map | faces meshed | CreateGeometry (s) | Mesh 2 (s) | triangles | kappa min | kappa mean | inverted | Hausdorff (%%) | mean distance (%%) |\n'
printf '|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n'
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh" .stl)
  for map in 6 0; do
    label=$([ "$map" = 0 ] && echo "Gmsh (0)" || echo "automatic (6)")
    line=$(timeout -k 5 "$timeout" "$bench" "$mesh" "$map" "$algorithm" 2>/dev/null | grep '^remesh')
    if [ -z "$line" ]; then
      printf '| %s | %s | did not end within %s s |||||||||\n' "$name" "$label" "$timeout"
      continue
    fi
    echo "$line" | python3 -c '
import sys
name, label = sys.argv[1], sys.argv[2]
f = sys.stdin.read().split()[1:]
v = dict(zip(f[0::2], f[1::2]))
print("| %s | %s | %s / %s | %.3f | %.3f | %s | %.3f | %.3f | %s | %.3g | %.3g |" % (
    name, label, v["meshed"], v["faces"], float(v["geometry"]),
    float(v["mesh"]), v["triangles"], float(v["kappaMin"]),
    float(v["kappaMean"]), v["inverted"], float(v["hausdorff"]),
    float(v["mean"])))' "$name" "$label"
  done
done
