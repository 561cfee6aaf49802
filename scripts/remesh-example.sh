#!/usr/bin/env bash
# Remeshes tutorials/dome.stl (tutorial t1) with Gmsh's own parametrization
# and with Reparam's, and prints the stage times and the quality of each.
#   scripts/remesh-example.sh [tutorial.geo]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
gmsh=${REPARAM_BUILD_DIR:-$here/build}/gmsh/gmsh
geo=${1:-$here/tutorials/t1_remesh_stl.geo}
[ -x "$gmsh" ] || { echo "Build first: scripts/build.sh" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "Remeshing $(basename "$geo") with Gmsh's parametrization (0) and Reparam's mean value map (3):"
printf '\n%-24s %12s %10s %9s %10s %9s %9s %9s\n' map "geometry(s)" "mesh2D(s)" "total(s)" triangles kappa_min kappa_avg "<0.3(%)"
for map in 0 3; do
  log=$out/log$map.txt
  start=$(date +%s%N)
  if ! "$gmsh" "$geo" -2 -setnumber Parametrization $map -o "$out/remesh$map.msh" > "$log" 2>&1 \
     || grep -q "^Error" "$log"; then
    cat "$log"; echo "gmsh failed with Mesh.CompoundParametrization = $map" >&2; exit 1
  fi
  end=$(date +%s%N)
  awk -v map=$map -v ns=$((end - start)) '
    function wall(line) { sub(/.*\(Wall /, "", line); sub(/s,.*/, "", line); return line + 0 }
    /Done creating geometry of discrete surfaces/ { geometry = wall($0) }
    /Done meshing 2D/ { mesh = wall($0) }
    /Reparam: surface/ {
      for(i = 1; i <= NF; i++) {
        if($i == "triangles,") n = $(i - 1)
        if($i == "min") k = $(i + 1)
        if($i == "mean") m = $(i + 1)
        if($i == "below") { b = $(i - 1); sub(/%/, "", b) }
      }
      tri += n; wsum += m * n; bsum += b * n
      if(kmin == "" || k < kmin) kmin = k
    }
    END {
      name = (map == 0) ? "0 Gmsh (stock)" : "3 Reparam mean value"
      printf "%-24s %12.4f %10.3f %9.2f %10d %9.3f %9.3f %9.2f\n", name, geometry, mesh, ns / 1e9, tri, kmin, wsum / tri, bsum / tri
    }' "$log"
done
echo
echo "geometry: CreateGeometry (parametrization of every discrete surface + Gmsh's search structures)"
echo "Reparam's own stage times (tutorial run with map 3):"
grep "Reparam: .* map of" "$out/log3.txt" | sed 's/^Info *: */  /'
