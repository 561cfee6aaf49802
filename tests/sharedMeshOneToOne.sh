#!/usr/bin/env bash
# CTest: the automatic chain (Mesh.CompoundParametrization = 6) gives a
# one-to-one (u, v) on every patch of a shared mesh that ClassifySurfaces
# splits into disks: 0 flipped triangles and 0 folds (exact checks), and as
# many patches parametrized as Gmsh's own map manages.
#
#   sharedMeshOneToOne.sh BENCH_BINARY MESH.stl [TIMEOUT]
#
# Exit 77 (skipped) when the mesh is absent or ClassifySurfaces does not end
# within TIMEOUT seconds (pelvis_tlem2: Gmsh's METIS split loop).
set -uo pipefail
bench=$1
mesh=$2
limit=${3:-120}
[ -f "$mesh" ] || { echo "skipped: $mesh not present"; exit 77; }
out=$(REPARAM_BENCH_RUNS=1 timeout -k 5 "$limit" "$bench" "$mesh" 6 0 2>/dev/null)
echo "$out"
if ! echo "$out" | grep -q '^triangles'; then
  echo "skipped: ClassifySurfaces did not end within $limit s"
  exit 77
fi
patches=$(echo "$out" | awk '/^triangles/ { print $4 }')
read -r ok flipped folds bad < <(echo "$out" | awk '/^map 6 / { print $6, $8, $10, $12 }')
stockOk=$(echo "$out" | awk '/^map 0 / { print $6 }')
echo "patches $patches: automatic ok $ok (Gmsh's map ok ${stockOk:-?}), flipped $flipped, folds $folds, not one-to-one $bad"
[ -n "${ok:-}" ] || { echo "FAILED: no result for map 6"; exit 1; }
[ "$flipped" -eq 0 ] && [ "$folds" -eq 0 ] && [ "$bad" -eq 0 ] \
  || { echo "FAILED: flipped or folded patches"; exit 1; }
# the patches Gmsh's own map parametrizes, ours does too
if [ -n "${stockOk:-}" ] && [ "$ok" -lt "$stockOk" ]; then
  echo "FAILED: fewer patches parametrized than Gmsh's own map"
  exit 1
fi
echo "passed"
