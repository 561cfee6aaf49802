#!/usr/bin/env bash
# Whether the STL recipe gives a whole mesh: the README's recipe (Merge,
# ClassifySurfaces{40, 1, 1, 180}, CreateGeometry, Mesh 2 with
# Frontal-Delaunay, sized for about min(input triangles, 25000) triangles,
# default options) in the built gmsh executable, one process per mesh and
# map, with the automatic chain (Mesh.CompoundParametrization = 6) and Gmsh's
# own map (0), on the tutorials' STL and every mesh of ../shared/data/meshes
# (when present):
#
#   bench/coverage.sh [file.stl ...] > bench/RESULTS-coverage.md
#       REPARAM_BENCH_TIMEOUT   seconds per run, default 120
#       REPARAM_COVERAGE_MAPS   maps to run, default "6 0"
#       REPARAM_COVERAGE_LOGS   folder to keep each run's gmsh log in (unset:
#                               logs are dropped with the run's temp folder)
#       REPARAM_COVERAGE_SIZES  factors on that size, default "1"; e.g.
#                               "0.7 1 1.4" runs each mesh and map at each
#       REPARAM_COVERAGE_CGAL   1: also CGAL's isotropic remeshing at the same
#                               size (bench/cgalRemesh.cpp, built as
#                               bench/speed.sh does; REPARAM_CGAL_REMESH: an
#                               executable already built)
#
# Per mesh and map (bench/coverage.py): whole or not (no error, every
# discrete surface meshed, as many boundary loops out as in), surfaces
# meshed and kept as their input triangles (the safety net), boundary loops
# and non-manifold edges in and out, errors and warnings in the log,
# Hausdorff distance (% of the diagonal), inverted elements, kappa min (and
# before Mesh.CompoundOptimize, with its time)
# from Mesh.CompoundReportFile, triangles, Reparam's layout (feature
# patches, after cleaning, final patches, splits, seconds) and CPU time;
# then per map the meshes whole and the total CPU time. With a size sweep
# or CGAL's rows, also the size factor, kappa mean, tau, the Hausdorff
# distance's two sides and the triangles against the count the size asks
# (bench/README.md, "What each script prints").
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
build=${REPARAM_BUILD_DIR:-$here/build}
gmsh=$build/gmsh/gmsh
[ -x "$gmsh" ] || gmsh=$(find "$build" -maxdepth 2 -name gmsh -type f -executable | head -n 1)
[ -n "$gmsh" ] || { echo "Build first: scripts/build.sh" >&2; exit 1; }

cgal=
if [ "${REPARAM_COVERAGE_CGAL:-0}" = 1 ]; then
  cgal=${REPARAM_CGAL_REMESH:-$build/bench/cgalRemesh}
  if [ ! -x "$cgal" ]; then
    [ -f /usr/include/CGAL/Polygon_mesh_processing/remesh.h ] || {
      echo "CGAL headers missing (apt-get install libcgal-dev)" >&2; exit 1; }
    mkdir -p "$(dirname "$cgal")"
    g++ -O2 -std=c++17 -DNDEBUG "$here/bench/cgalRemesh.cpp" -o "$cgal" \
      -lgmp -lmpfr || exit 1
  fi
fi

benchMeshes "$@"

logs=()
[ -n "${REPARAM_COVERAGE_LOGS:-}" ] && logs=(--logs "$REPARAM_COVERAGE_LOGS")
exec python3 "$here/bench/coverage.py" --gmsh "$gmsh" --repo "$here" \
  --timeout "${REPARAM_BENCH_TIMEOUT:-120}" \
  --maps "${REPARAM_COVERAGE_MAPS:-6 0}" \
  --sizes "${REPARAM_COVERAGE_SIZES:-1}" --cgal "$cgal" \
  ${logs[@]+"${logs[@]}"} "${meshes[@]}"
