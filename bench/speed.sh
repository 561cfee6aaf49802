#!/usr/bin/env bash
# Whole-remesh CPU time of the STL recipe against a local-operations
# remesher, in the same run: Reparam (the README's recipe, defaults), stock
# Gmsh's own map (Mesh.CompoundParametrization = 0) and CGAL's isotropic
# remeshing (3 iterations, borders protected) at the same target edge
# length (bench/coverage.py's size: about min(input triangles, 25000)
# triangles), one process each, on the tutorials' STL and every mesh of
# ../shared/data/meshes (when present):
#
#   bench/speed.sh [file.stl ...] > bench/RESULTS-speed.md
#       REPARAM_BENCH_TIMEOUT   seconds per run, default 120
#
# CGAL (Debian's libcgal-dev) is built here for the bench only
# (bench/cgalRemesh.cpp, into the build folder); without its headers the
# CGAL column is left out. Prints a Markdown table: CPU seconds of each
# process, Reparam's stages (from its log: ClassifySurfaces, CreateGeometry,
# 1D, 2D with the optimization), triangles, and the ratios.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
build=${REPARAM_BUILD_DIR:-$here/build}
gmsh=$build/gmsh/gmsh
[ -x "$gmsh" ] || { echo "Build first: scripts/build.sh" >&2; exit 1; }
cgal=$build/bench/cgalRemesh
if [ ! -x "$cgal" ] || [ "$here/bench/cgalRemesh.cpp" -nt "$cgal" ]; then
  if [ -f /usr/include/CGAL/Polygon_mesh_processing/remesh.h ]; then
    mkdir -p "$build/bench"
    g++ -O2 -std=c++17 -DNDEBUG "$here/bench/cgalRemesh.cpp" -o "$cgal" \
      -lgmp -lmpfr
  else
    echo "CGAL headers missing (apt-get install libcgal-dev): no CGAL column" >&2
    cgal=
  fi
fi
benchMeshes "$@"
exec python3 "$here/bench/speed.py" --gmsh "$gmsh" --cgal "$cgal" \
  --repo "$here" --timeout "${REPARAM_BENCH_TIMEOUT:-120}" "${meshes[@]}"
