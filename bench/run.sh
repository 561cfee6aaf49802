#!/usr/bin/env bash
# Parametrization benchmark: Gmsh's own map (Mesh.CompoundParametrization 0)
# against Reparam's mean value map (3), in the same run, on every mesh of
# ../shared/data/meshes (when present) and on the tutorials' STL files.
#
#   bench/run.sh [file.stl ...]        (REPARAM_BENCH_TIMEOUT, default 300 s)
#
# Per mesh: triangles in; patches after ClassifySurfaces{40, 1, 1, 180} and the
# largest; the parametrization stage (computeParametrization on every patch,
# same patches for both maps) and its ratio; the whole STL recipe (Merge,
# ClassifySurfaces, CreateGeometry, Mesh 2 at the input's mean edge length)
# as a gmsh process for each map: wall time, triangles out, errors.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
benchProgram reparamBenchParametrize
gmsh=$build/gmsh/gmsh
[ -x "$gmsh" ] || { echo "Build first: scripts/build.sh" >&2; exit 1; }
timeout=${REPARAM_BENCH_TIMEOUT:-300}
benchMeshes "$@"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }

# Runs the STL recipe with map $2 on $1 at size $3; prints "seconds triangles errors"
remesh() {
  local geo=$tmp/recipe.geo log=$tmp/remesh.log
  cat > "$geo" <<GEO
Merge "$1";
Mesh.CompoundParametrization = $2;
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;
Mesh.MeshSizeMin = $3;
Mesh.MeshSizeMax = $3;
GEO
  local start=$(now)
  timeout -k 5 "$timeout" "$gmsh" "$geo" -2 -o "$tmp/out.msh" > "$log" 2>&1
  local status=$?
  local seconds=$(elapsed "$start" "$(now)")
  local triangles=$(awk '/Reparam: surface/ { for(i = 2; i <= NF; i++) if($i == "triangles,") n += $(i - 1) } END { print n + 0 }' "$log")
  local errors=$(grep -c "Error" "$log")
  if [ $status -eq 124 ] || [ $status -eq 137 ]; then seconds=">$timeout"; triangles="-"; fi
  echo "$seconds $triangles $errors"
}

printf '| mesh | tri in | patches (largest) | param stock (s) | param Reparam (s) | param ratio | remesh stock (s) | remesh Reparam (s) | tri out stock | tri out Reparam | errors stock / Reparam |\n'
printf '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n'
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh" .stl)
  timeout -k 5 "$timeout" "$bench" "$mesh" 3 0 > "$tmp/param.txt" 2> /dev/null
  read -r _ tri _ patches _ largest _ _ _ size < <(grep '^triangles' "$tmp/param.txt")
  if [ -z "${tri:-}" ]; then
    # the split (Gmsh's ClassifySurfaces, the same for both maps) never ended
    printf '| %s | - | ClassifySurfaces did not end within %s s | - | - | - | - | - | - | - | - |\n' "$name" "$timeout"
    continue
  fi
  ours=$(awk '$1 == "map" && $2 == 3 { print $4 }' "$tmp/param.txt")
  stock=$(awk '$1 == "map" && $2 == 0 { print $4 }' "$tmp/param.txt")
  [ -n "$ours" ] || ours=">$timeout"
  [ -n "$stock" ] || stock=">$timeout"
  ratio=$(awk -v s="$stock" -v o="$ours" 'BEGIN { if(s + 0 > 0 && o + 0 > 0) printf "%.1fx", s / o; else print "-" }')
  read -r t0 n0 e0 < <(remesh "$mesh" 0 "$size")
  read -r t3 n3 e3 < <(remesh "$mesh" 3 "$size")
  printf '| %s | %s | %s (%s) | %s | %s | %s | %s | %s | %s | %s | %s / %s |\n' \
    "$name" "${tri:--}" "${patches:--}" "${largest:--}" "$stock" "$ours" "$ratio" "$t0" "$t3" "$n0" "$n3" "$e0" "$e3"
  unset tri patches largest size
done
