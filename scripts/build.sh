#!/usr/bin/env bash
# Configures and builds Gmsh with Reparam inside, into build/ (or $REPARAM_BUILD_DIR).
# Compiler output is cached by ccache under the user's cache directory, with
# paths made relative to this checkout so that another clone hits the cache.
#   scripts/build.sh [extra cmake -D options]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${REPARAM_BUILD_DIR:-$here/build}
src=$(bash "$here/scripts/install-deps.sh" | tail -n 1)

export CCACHE_BASEDIR=$here
export CCACHE_DIR=${CCACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/ccache}
export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-4G}
export CCACHE_NOHASHDIR=1

mkdir -p "$build"
cmake -S "$here" -B "$build" -DGMSH_SOURCE_DIR="$src" \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache \
  -DREPARAM_GUI="${REPARAM_GUI:-OFF}" "$@" > "$build/reparam-configure.log" 2>&1 \
  || { cat "$build/reparam-configure.log"; exit 1; }
start=$(date +%s)
cmake --build "$build" --parallel "${REPARAM_JOBS:-$(nproc)}"
echo "-- Build took $(( $(date +%s) - start )) s; $(ccache -s | grep -iE 'hits|misses' | tr -s ' ' | paste -sd ';')"
