#!/usr/bin/env bash
# Per-map parametrization benchmark: every map of Mesh.CompoundParametrization
# (1 FE harmonic, 2 Tutte, 3 mean value, 4 LSCM, 5 spectral) and Gmsh's own
# (0), on the same patches in the same process, on a generated bumpy square
# of about 100k triangles (the size of the speed targets), the tutorials' STL
# files and every mesh of ../shared/data/meshes (when present).
#
#   bench/maps.sh [file.stl ...]        (REPARAM_BENCH_TIMEOUT, default 300 s)
#
# Per mesh: triangles in, patches after ClassifySurfaces{40, 1, 1, 180} (the
# largest), seconds of computeParametrization over all patches for each map
# (best of 3), and stock / map ratios. Parametrizations that fail count in
# the "failed" column (as for stock: the patches the split leaves pinched).
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
benchProgram reparamBenchParametrize
timeout=${REPARAM_BENCH_TIMEOUT:-300}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if [ $# -eq 0 ]; then
  python3 "$here/bench/make-large-patch.py" "$tmp/bumpy_square_100k.stl" 100000
  BENCH_EXTRA_MESHES=("$tmp/bumpy_square_100k.stl")
fi
benchMeshes "$@"

printf '| mesh | tri in | patches (largest) | stock (s) | harmonic (s) | Tutte (s) | mean value (s) | LSCM (s) | spectral (s) | stock / harmonic | stock / Tutte | stock / mean value | stock / LSCM | stock / spectral | failed stock / ours |\n'
printf '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n'
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh" .stl)
  timeout -k 5 "$timeout" "$bench" "$mesh" 1 2 3 4 5 0 > "$tmp/param.txt" 2> /dev/null
  read -r _ tri _ patches _ largest _ < <(grep '^triangles' "$tmp/param.txt")
  if [ -z "${tri:-}" ]; then
    printf '| %s | - | ClassifySurfaces did not end within %s s |||||||||||||\n' "$name" "$timeout"
    continue
  fi
  awk -v name="$name" -v tri="$tri" -v patches="$patches" -v largest="$largest" -v limit="$timeout" '
    $1 == "map" { s[$2] = $4; ok[$2] = $6 }
    END {
      line = sprintf("| %s | %s | %s (%s) |", name, tri, patches, largest)
      for(m = 0; m <= 5; m++) line = line sprintf(" %s |", (m in s) ? s[m] : ">" limit)
      for(m = 1; m <= 5; m++)
        line = line sprintf(" %s |", (m in s && 0 in s && s[m] > 0) ? sprintf("%.1fx", s[0] / s[m]) : "-")
      worst = patches
      for(m = 1; m <= 5; m++) if(m in ok && ok[m] < worst) worst = ok[m]
      line = line sprintf(" %s / %s |", (0 in ok) ? patches - ok[0] : "-", patches - worst)
      print line
    }' "$tmp/param.txt"
  unset tri patches largest
done
