#!/usr/bin/env bash
# Bijectivity of the automatic chain (Mesh.CompoundParametrization = 6) on
# the tutorials' STL files and every mesh of ../shared/data/meshes (when
# present), against Gmsh's own map (0) in the same process:
#
#   bench/bijectivity.sh [file.stl ...]   (REPARAM_BENCH_TIMEOUT, default 300 s)
#
# Per mesh: patches after ClassifySurfaces{40, 1, 1, 180}; where the chain
# ended (spectral / FE conformal re-pinned / mean value / failed); flipped
# triangles and folds found by the checks over all steps, flips left after
# the repairs; the whole parametrization time (every patch, one run), the
# time of the maps alone and of the checks and repairs (share: of the whole
# parametrization); patches whose final (u, v) still flip or fold, for ours and for
# Gmsh's own map (checked with the same exact predicates).
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
benchProgram reparamBenchParametrize
timeout=${REPARAM_BENCH_TIMEOUT:-300}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

benchMeshes "$@"

printf '| mesh | patches | ended on spectral / LSCM re-pinned / mean value / failed | flips found | folds found | flips left after repair | parametrization (s) | maps (s) | checks + repairs (s) | checks share | not one-to-one: ours / Gmsh |\n'
printf '|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n'
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh" .stl)
  REPARAM_BENCH_VERBOSITY=5 REPARAM_BENCH_RUNS=1 \
    timeout -k 5 "$timeout" "$bench" "$mesh" 6 0 > "$tmp/out.txt" 2> /dev/null
  if ! grep -q '^triangles' "$tmp/out.txt"; then
    printf '| %s | ClassifySurfaces did not end within %s s |||||||||\n' "$name" "$timeout"
    continue
  fi
  python3 - "$name" "$tmp/out.txt" <<'PY'
import re, sys
name, path = sys.argv[1], sys.argv[2]
started = False
patches = 0
ended = {"spectral": 0, "lscm": 0, "mv": 0}
flips = folds = left = 0
maptime = checktime = 0.
last_left = 0
ours = stock = "-"
total = 0.
for line in open(path, errors="replace"):
    if line.startswith("triangles"):
        started, patches = True, int(line.split()[3])
        continue
    if not started:
        continue
    m = re.search(r"map: (\d+) flipped, (\d+) folds, .*\((\d+) flipped, "
                  r"\d+ folds\), map ([\d.e+-]+) s, checks ([\d.e+-]+) s", line)
    if m:
        flips += int(m.group(1)); folds += int(m.group(2))
        last_left = int(m.group(3))
        maptime += float(m.group(4)); checktime += float(m.group(5))
        continue
    m = re.search(r"Reparam: (.*) map of \d+ nodes", line)
    if m:
        key = ("spectral" if m.group(1).startswith("spectral") else
               "lscm" if "LSCM" in m.group(1) else "mv")
        ended[key] += 1
        left += last_left
        continue
    f = line.split()
    if line.startswith("map 6 "):
        ours, total = f[11], float(f[3])
    elif line.startswith("map 0 "):
        stock = f[11]
failed = patches - sum(ended.values())
share = "%.1f %%" % (100 * checktime / total) if total > 0 else "-"
print("| %s | %d | %d / %d / %d / %d | %d | %d | %d | %.4f | %.4f | %.4f | %s | %s / %s |"
      % (name, patches, ended["spectral"], ended["lscm"], ended["mv"], failed,
         flips, folds, left, total, maptime, checktime, share, ours, stock))
PY
done
