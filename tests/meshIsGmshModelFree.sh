#!/usr/bin/env bash
# CTest rooms.meshIsGmshModelFree: Mesh/ and Numeric/ work on plain arrays
# and Gmsh's small value types (SPoint2/3, SVector3, STensor3,
# SBoundingBox3d, the robust predicates) only. A file there that includes a
# header of Gmsh's model or elements (GModel, GFace, MVertex, MTriangle,
# background meshes, OS.h, Context.h...) or any header of our Geo/ is
# printed as file:line, and the test fails.
#
#   meshIsGmshModelFree.sh REPARAM_SOURCE_DIR
set -uo pipefail
here=$1
cd "$here" || exit 1

# Gmsh's model, entity and element classes, and what reaches into its state
gmshModel='G(Model|Face|Edge|Vertex|Region|Entity)[A-Za-z_]*|discrete(Face|Edge|Vertex|Region)'
gmshModel+='|M(Vertex|Element|Triangle|Quadrangle|Line|Point|Edge|Face|Tetrahedron|Hexahedron|Prism|Pyramid|Trihedron)[A-Za-z_]*'
gmshModel+='|BackgroundMesh[A-Za-z_]*|meshG(Face|Edge|Region)[A-Za-z_]*|Field|OS|Context|Options|GmshMessage|PView[A-Za-z_]*'
# our Geo/ headers, by name (headers are included by name, every room is
# on the include path)
ours=$(find Geo -name '*.h' -printf '%f\n' | sed 's/\.h$//' | paste -sd '|')

files=$(find Mesh Numeric -name '*.h' -o -name '*.cpp' | sort)
# file:line: the include, for every forbidden one
found=$(grep -nHE "^\s*#\s*include\s*[<\"]([^\">]*/)?($gmshModel${ours:+|$ours})\.h[\">]" $files)
status=0
if [ -n "$found" ]; then
  echo "$found"
  status=1
fi

if [ $status = 0 ]; then
  echo "Gmsh-model-free: $(echo "$files" | wc -l) files of Mesh/ and Numeric/ include no model or element header of Gmsh and no header of Geo/"
else
  echo "Mesh/ and Numeric/ must not include Gmsh's model or element headers nor Geo/'s: move the code that needs them to Geo/ (Geo/core/ for shared adapters)"
fi
exit $status
