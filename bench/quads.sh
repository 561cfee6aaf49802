#!/usr/bin/env bash
# The paper's quadrangle table: Frontal-Delaunay for quads + Blossom through
# each map, on dome.stl and the smooth shared meshes (bench/quads.py):
#
#   bench/quads.sh [file.stl ...] > bench/RESULTS-quads.md
#       REPARAM_QUADS_MAPS      maps, default "0 4 5 6" (0: stock Gmsh)
#       REPARAM_BENCH_TIMEOUT   seconds per run, default 300
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
benchGmsh
smoothMeshes "aorta_gmsh gmsh2x_bifurcation aneurysm tooth fertility camelhead armadillo gmsh2x_skull" "$@"
exec python3 "$here/bench/quads.py" --gmsh "$gmsh" --repo "$here" \
  --timeout "${REPARAM_BENCH_TIMEOUT:-300}" \
  --maps "${REPARAM_QUADS_MAPS:-0 4 5 6}" "${meshes[@]}"
