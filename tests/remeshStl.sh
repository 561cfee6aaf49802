#!/usr/bin/env bash
# CTest: the STL recipe (Frontal-Delaunay, the automatic map) on a mesh, at
# a given size; prints Gmsh's log.
#
#   remeshStl.sh GMSH_EXECUTABLE MESH.stl SIZE
set -euo pipefail
gmsh=$1
mesh=$2
size=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/remesh.geo" <<GEO
Merge "$mesh";
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;
Mesh.MeshSizeMin = $size;
Mesh.MeshSizeMax = $size;
Mesh.Algorithm = 6;
Mesh 2;
GEO
"$gmsh" "$work/remesh.geo" -parse_and_exit 2>&1
