#!/usr/bin/env bash
# Every planar mesher of the STL recipe (MeshAdapt, Delaunay,
# Frontal-Delaunay, BAMG, and the two quadrangle recipes) through Reparam's
# automatic map, on the given STL files or the tutorials' and the shared
# meshes (bench/meshers.py): whole, errors, elements against the input,
# quality, CPU.
#
#   bench/meshers.sh [file.stl ...] > bench/RESULTS-meshers.md
#       REPARAM_BENCH_TIMEOUT   seconds per run, default 600
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
benchGmsh
benchMeshes "$@"
exec python3 "$here/bench/meshers.py" --gmsh "$gmsh" --repo "$here" \
  --timeout "${REPARAM_BENCH_TIMEOUT:-600}" "${meshes[@]}"
