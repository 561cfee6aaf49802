# Sourced by the bench scripts. benchMeshes FILE... sets `meshes` to the
# given files, or by default to the tutorials' STL files and every mesh of
# ../shared/data/meshes (when present), smallest first; BENCH_EXTRA_MESHES
# (an array, if set) goes first in the default list.
benchMeshes() {
  if [ $# -gt 0 ]; then
    meshes=("$@")
    return
  fi
  local here data
  here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  meshes=(${BENCH_EXTRA_MESHES[@]+"${BENCH_EXTRA_MESHES[@]}"} "$here"/tutorials/*.stl)
  data=$here/../shared/data/meshes
  [ -d "$data" ] && meshes+=($(ls -S -r "$data"/*.stl))
}

# benchProgram NAME sets `build` (REPARAM_BUILD_DIR, default build/) and
# `bench` to the benchmark program NAME in it, and stops if it is not built.
benchProgram() {
  build=${REPARAM_BUILD_DIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build}
  bench=$build/bench/$1
  [ -x "$bench" ] || { echo "Build first: scripts/build.sh" >&2; exit 1; }
}

# benchGmsh sets `gmsh` to the built gmsh executable (REPARAM_BUILD_DIR,
# default build/), and stops if it is not built.
benchGmsh() {
  local build=${REPARAM_BUILD_DIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build}
  gmsh=$build/gmsh/gmsh
  [ -x "$gmsh" ] || { echo "Build first: scripts/build.sh" >&2; exit 1; }
}

# smoothMeshes "NAME..." [FILE...] sets `meshes` to the files given, or by
# default to the tutorials' dome.stl and the shared meshes named (those
# present)
smoothMeshes() {
  local here data m names=$1
  shift
  if [ $# -gt 0 ]; then
    meshes=("$@")
    return
  fi
  here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  meshes=("$here/tutorials/dome.stl")
  data=$here/../shared/data/meshes
  for m in $names; do
    [ -f "$data/$m.stl" ] && meshes+=("$data/$m.stl")
  done
}
