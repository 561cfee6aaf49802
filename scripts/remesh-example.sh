#!/usr/bin/env bash
# Remeshes tutorials/dome.stl (tutorial t1) with Gmsh's own parametrization,
# Reparam's mean value map and Reparam's automatic chain, and prints the
# stage times and the quality of each (from Reparam's JSON report,
# Mesh.CompoundReportFile).
#   scripts/remesh-example.sh [tutorial.geo]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
gmsh=${REPARAM_BUILD_DIR:-$here/build}/gmsh/gmsh
geo=${1:-$here/tutorials/t1_remesh_stl.geo}
[ -x "$gmsh" ] || { echo "Build first: scripts/build.sh" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "Remeshing $(basename "$geo") with Gmsh's parametrization (0), Reparam's mean value map (3) and its automatic chain (6):"
printf '\n%-24s %11s %9s %8s %9s %9s %9s %7s %6s %10s %8s\n' map "geometry(s)" "mesh2D(s)" "total(s)" triangles kappa_min kappa_avg "<0.3(%)" "tau(%)" "Hausd.(%)" inverted
for map in 0 3 6; do
  log=$out/log$map.txt
  json=$out/report$map.json
  start=$(date +%s%N)
  if ! "$gmsh" "$geo" -2 -setnumber Mesh.CompoundParametrization $map \
       -string "Mesh.CompoundReportFile = \"$json\";" \
       -o "$out/remesh$map.msh" > "$log" 2>&1 || grep -q "^Error" "$log"; then
    cat "$log"; echo "gmsh failed with Mesh.CompoundParametrization = $map" >&2; exit 1
  fi
  end=$(date +%s%N)
  python3 - "$map" "$((end - start))" "$log" "$json" <<'PY'
import json, re, sys
map, ns, log, report = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], sys.argv[4]
def wall(what):
    for line in open(log):
        if what in line:
            return float(re.search(r"\(Wall ([0-9.e+-]+)s", line).group(1))
    return 0.
t = json.load(open(report))["total"]
name = {0: "0 Gmsh (stock)", 3: "3 Reparam mean value", 6: "6 Reparam automatic"}[map]
print("%-24s %11.4f %9.3f %8.2f %9d %9.3f %9.3f %7.2f %6.1f %10.3g %8d" % (
    name, wall("Done creating geometry of discrete surfaces"),
    wall("Done meshing 2D"), ns / 1e9, t["triangles"], t["kappaMin"],
    t["kappaMean"], 100 * t["kappaShareBelow03"], t["tau"],
    t["hausdorffPercent"], t["inverted"]))
PY
done
echo
echo "geometry: CreateGeometry (parametrization of every discrete surface + Gmsh's search structures)"
echo "Reparam's report (tutorial run with map 6):"
grep -E "Reparam: (.* map of|surface  |[0-9]+ |total )" "$out/log6.txt" | sed 's/^Info *: */  /'
