#!/usr/bin/env bash
# CTest: the STL recipe (the automatic map) on a mesh, at a given size,
# with a planar mesher (6, Frontal-Delaunay, by default), Mesh.RecombineAll
# (0 by default) and Mesh.CompoundOptimize (its default if not given);
# prints Gmsh's log.
#
#   remeshStl.sh GMSH_EXECUTABLE MESH.stl SIZE [ALGORITHM [RECOMBINE_ALL
#                [OPTIMIZE [OPTIONS]]]]
#
# OPTIONS: one more .geo statement before Mesh 2, without its semicolon
# (CMake splits arguments at semicolons)
set -euo pipefail
gmsh=$1
mesh=$2
size=$3
algorithm=${4:-6}
recombine=${5:-0}
optimize=${6:+Mesh.CompoundOptimize = $6;}
options=${7:+$7;}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/remesh.geo" <<GEO
Merge "$mesh";
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;
Mesh.MeshSizeMin = $size;
Mesh.MeshSizeMax = $size;
Mesh.Algorithm = $algorithm;
Mesh.RecombineAll = $recombine;
$optimize
$options
Mesh 2;
GEO
"$gmsh" "$work/remesh.geo" -parse_and_exit 2>&1
