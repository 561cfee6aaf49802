#!/usr/bin/env bash
# Reparam - optimal discrete parametrizations for Gmsh compound surfaces
#
# The two rules of the documentation (issue 36): the README is for users
# and stays short, the measurements live next to the scripts that make them
# (bench/README.md, bench/RESULTS-*.md), and the code's comments say why in
# a line and point there instead of quoting a bench mesh.
#
#   tests/docsCheck.sh readmeLength SOURCE_DIR [MAX_LINES]
#       README.md has at most MAX_LINES lines (default 400)
#   tests/docsCheck.sh noBenchMeshNamesInCode SOURCE_DIR [DATA_DIR]
#       no bench mesh name in a // comment of Geo/, Mesh/, Numeric/, Plugin/
#
# The bench mesh names: the STL stems of tutorials/ and of DATA_DIR (the
# shared meshes, when present), the segmentation-like inputs of
# bench/make-segmentations.py (vessel_*, bone_binary) and Gmsh's own STL
# files the tests remesh (gmshSourceMesh.* in tests/CMakeLists.txt) but
# those named by a common word (sphere, object, surface1, surface2). A name
# matches as a word, in any case, with a suffix such as _noisy or _messy
# (the copies of bench/make-hard-inputs.py). Prints each offending line as
# file:line: text.
set -euo pipefail

mode=${1:?usage: docsCheck.sh readmeLength|noBenchMeshNamesInCode SOURCE_DIR [...]}
src=${2:?usage: docsCheck.sh MODE SOURCE_DIR [...]}
cd "$src"

case $mode in
  readmeLength)
    max=${3:-400}
    lines=$(wc -l < README.md)
    if [ "$lines" -gt "$max" ]; then
      echo "README.md has $lines lines, more than $max: move the measurements" \
        "and their stories to bench/README.md"
      exit 1
    fi
    echo "README.md: $lines lines (at most $max)"
    ;;
  noBenchMeshNamesInCode)
    data=${3:-}
    names=(dome lever terrain terrain_stl_data aorta2 aneurysm_data
           sphere-surf t13_data bone_binary 'vessel_[a-z0-9]+')
    for stl in tutorials/*.stl ${data:+"$data"/*.stl}; do
      [ -f "$stl" ] && names+=("$(basename "$stl" .stl)")
    done
    alternatives=$(printf '%s\n' "${names[@]}" | sort -u | paste -sd '|')
    # the text after // holds a name between non-word characters
    pattern="//.*(^|[^[:alnum:]_])($alternatives)(_[[:alnum:]]+)*([^[:alnum:]_]|$)"
    hits=$(grep -rnIiE --include='*.h' --include='*.cpp' --include='*.hpp' \
             "$pattern" Geo Mesh Numeric Plugin || true)
    if [ -n "$hits" ]; then
      echo "$hits"
      echo "$(echo "$hits" | wc -l) comment lines name a bench mesh: say why" \
        "in a line and point to the section of bench/README.md that" \
        "measured it"
      exit 1
    fi
    echo "no bench mesh named in the comments of Geo/ Mesh/ Numeric/" \
      "Plugin/ (${#names[@]} names)"
    ;;
  *)
    echo "unknown mode $mode" >&2
    exit 2
    ;;
esac
