#!/usr/bin/env bash
# CTest: the STL recipe on a harder copy of a mesh (bench/make-hard-inputs.py:
# VARIANT noisy or messy, the bench's seed), through remeshStl.sh; prints
# Gmsh's log.
#
#   remeshHardInput.sh GMSH_EXECUTABLE MESH.stl VARIANT SIZE [ARGS...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
gmsh=$1
mesh=$2
variant=$3
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/../bench/make-hard-inputs.py" "$mesh" "$work" > /dev/null
name=$(basename "$mesh" .stl)
bash "$here/remeshStl.sh" "$gmsh" "$work/${name}_$variant.stl" "$@"
