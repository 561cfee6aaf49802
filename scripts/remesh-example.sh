#!/usr/bin/env bash
# Remeshes tutorials/dome.stl (tutorial t1) with Gmsh's own parametrization
# and with Reparam's, and prints the stage times and the quality of each.
#   scripts/remesh-example.sh [tutorial.geo]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
gmsh=${REPARAM_BUILD_DIR:-$here/build}/gmsh/gmsh
geo=${1:-$here/tutorials/t1_remesh_stl.geo}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

printf '%-26s %9s %9s %9s %10s %9s %9s\n' map "param(s)" "mesh(s)" "total(s)" triangles "kappa_min" "kappa_avg"
for map in 0 3; do
  log=$out/log$map.txt
  start=$(date +%s.%N)
  "$gmsh" "$geo" -2 -setnumber Parametrization $map -o "$out/remesh$map.msh" > "$log" 2>&1 || {
    cat "$log"; echo "gmsh failed with Mesh.CompoundParametrization = $map"; exit 1; }
  total=$(echo "$(date +%s.%N) - $start" | bc)
  [ $map = 3 ] && { echo; grep "Reparam:" "$log" | sed 's/^/  /'; echo; } >&2
  awk -v map=$map -v total=$total '
    /Reparam: .* map of/ { for(i=1;i<=NF;i++) if($i=="solve" || $i=="assemble" || $i=="patch") param += $(i+1) }
    /Done creating geometry of discrete surfaces/ { if(map==0) { match($0, /Wall ([0-9.e-]+)s/, m); param = m[1] } }
    /Reparam: surface/ {
      for(i=1;i<=NF;i++) {
        if($i=="mesh") mesh += $(i+1)
        if($i=="triangles,") tri += $(i-1)
        if($i=="min") { kmin = (kmin=="" || $(i+1) < kmin) ? $(i+1) : kmin }
        if($i=="mean") { s += $(i+1) * cur }
      }
    }
    /Reparam: surface/ { for(i=1;i<=NF;i++) if($i=="triangles,") { n=$(i-1) } ; for(i=1;i<=NF;i++) if($i=="mean") ksum += $(i+1)*n }
    END {
      name = (map==0) ? "0 Gmsh built-in (stock)" : "3 Reparam mean value"
      printf "%-26s %9.3f %9.3f %9.2f %10d %9.3f %9.3f\n", name, param, mesh, total, tri, kmin, ksum/tri
    }' "$log"
done
echo "(param: the parametrization stage; for stock Gmsh, its whole CreateGeometry step)"
