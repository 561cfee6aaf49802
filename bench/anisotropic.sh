#!/usr/bin/env bash
# Anisotropic meshes from the curvature against isotropic ones
# (bench/anisotropic.py), on dome.stl and the shared vessels:
#
#   bench/anisotropic.sh [file.stl ...] > bench/RESULTS-anisotropic.md
#       REPARAM_ANISOTROPIC_N   elements per circle of curvature, default 20
#       REPARAM_BENCH_TIMEOUT   seconds per run, default 300
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
benchGmsh
smoothMeshes "gmsh2x_bifurcation aneurysm aorta_gmsh" "$@"
exec python3 "$here/bench/anisotropic.py" --gmsh "$gmsh" --repo "$here" \
  --n "${REPARAM_ANISOTROPIC_N:-20}" --timeout "${REPARAM_BENCH_TIMEOUT:-300}" \
  "${meshes[@]}"
