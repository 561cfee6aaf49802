#!/usr/bin/env bash
# The STL recipe's CPU time and kappa now against an earlier commit, in the
# same run (one machine's load for both): builds REV in a git worktree
# (scripts/build.sh, so ccache makes it quick), then runs both gmsh
# executables alternately on each mesh (bench/against-commit.py):
#
#   bench/against-commit.sh REV [file.stl ...] > table.md
#       REPARAM_BASE_DIR       where the worktree goes (default
#                              ${TMPDIR:-/tmp}/reparam-base-REV)
#       REPARAM_BENCH_ROUNDS   runs per executable and mesh, default 2
#       REPARAM_BENCH_TIMEOUT  seconds per run, default 300
#
# Meshes: as bench/coverage.sh (the tutorials' STL and the shared meshes).
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/bench/common.sh"
[ $# -ge 1 ] || { sed -n 2,13p "$0" >&2; exit 2; }
rev=$(git -C "$here" rev-parse --short "$1") || exit 2
shift
gmsh=$here/build/gmsh/gmsh
[ -x "$gmsh" ] || { echo "Build first: scripts/build.sh" >&2; exit 1; }
base=${REPARAM_BASE_DIR:-${TMPDIR:-/tmp}/reparam-base-$rev}
if [ ! -d "$base" ]; then
  git -C "$here" worktree add -q --detach "$base" "$rev" || exit 1
fi
if [ ! -x "$base/build/gmsh/gmsh" ]; then
  echo "Building $rev in $base" >&2
  (cd "$base" && bash scripts/build.sh) >&2 || exit 1
fi

benchMeshes "$@"
exec python3 "$here/bench/against-commit.py" --base "$base/build/gmsh/gmsh" \
  --base-name "$rev" --gmsh "$gmsh" --rounds "${REPARAM_BENCH_ROUNDS:-2}" \
  --timeout "${REPARAM_BENCH_TIMEOUT:-300}" "${meshes[@]}"
