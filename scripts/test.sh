#!/usr/bin/env bash
# Installs what is missing, builds Gmsh with Reparam and runs every test
# (GoogleTest through CTest). This is the README's test command; .ci/run
# calls it.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${REPARAM_BUILD_DIR:-$here/build}
bash "$here/scripts/build.sh"
cd "$build"
ctest --output-on-failure --parallel "${REPARAM_JOBS:-$(nproc)}"
