#!/usr/bin/env bash
# CTest: Mesh.CompoundReportFile writes valid JSON whose numbers agree with
# each other and with the log's table, on tutorial 1 (spectral map) and on
# tutorial 2 as a compound (quadrangles: Mesh.RecombineAll).
#
#   reportJson.sh GMSH_EXECUTABLE SOURCE_DIR WORK_DIR
set -euo pipefail
gmsh=$1
src=$2
work=$3
mkdir -p "$work"
check() {
  if [ ! -f "$1" ]; then
    # say why rather than a Python traceback: the log's end
    echo "no report written to $1; the end of $2:"
    tail -n 40 "$2"
    return 1
  fi
  python3 - "$1" "$2" "$3" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
log = open(sys.argv[2]).read()
map_name = sys.argv[3]
surfaces, total = report["surfaces"], report["total"]
assert surfaces, "no surface"
assert total["surfaces"] == len(surfaces)
for s in surfaces:
    assert s["map"] == map_name, s["map"]
    assert s["mapsTried"] and s["mapsTried"][-1] == map_name, s["mapsTried"]
    assert s["oneToOne"] is True
    assert s["inverted"] == 0, s["inverted"]
    assert 0 < s["kappaMin"] <= s["kappaMean"] <= 1
    assert s["seconds"]["planarMesh"] > 0
    # the log's table line of this surface: triangles and quadrangles
    line = [l for l in log.splitlines()
            if l.startswith("Info    : Reparam: %-9d " % s["surface"])]
    assert len(line) == 1, line
    fields = line[0].split()
    assert str(s["triangles"]) in fields and str(s["quadrangles"]) in fields
elements = sum(s["triangles"] for s in surfaces)
assert total["triangles"] == elements
assert total["quadrangles"] == sum(s["quadrangles"] for s in surfaces)
assert total["kappaMin"] == min(s["kappaMin"] for s in surfaces)
mean = sum(s["kappaMean"] * s["triangles"] for s in surfaces) / elements
assert abs(total["kappaMean"] - mean) < 1e-5, (total["kappaMean"], mean)
if total["quadrangles"]:
    assert 0 <= total["etaMin"] <= total["etaMean"] <= 1
else:
    assert total["etaMin"] is None
print("report ok: %d surfaces, %d triangles, %d quadrangles, kappa min %.3f"
      % (len(surfaces), total["triangles"], total["quadrangles"],
         total["kappaMin"]))
PY
}
"$gmsh" "$src/tutorials/t1_remesh_stl.geo" -2 \
  -setnumber Mesh.CompoundParametrization 5 \
  -string "Mesh.CompoundReportFile = \"$work/t1.json\";" \
  -o "$work/t1.msh" > "$work/t1.log" 2>&1
check "$work/t1.json" "$work/t1.log" "spectral conformal"
"$gmsh" "$src/tutorials/t2_compound.geo" -2 \
  -setnumber Mesh.CompoundParametrization 3 -string "Mesh.RecombineAll = 1; Mesh.CompoundReportFile = \"$work/t2.json\";" \
  -o "$work/t2.msh" > "$work/t2.log" 2>&1
check "$work/t2.json" "$work/t2.log" "mean value"
