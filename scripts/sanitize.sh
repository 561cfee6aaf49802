#!/usr/bin/env bash
# The test suite with AddressSanitizer and UndefinedBehaviorSanitizer on
# Reparam's sources and tests (Gmsh's own files compile as stock), in its
# own build folder (build-sanitize/, or $REPARAM_SANITIZE_DIR):
#
#   scripts/sanitize.sh [ctest arguments]     e.g. -R optimizeOnInput
#
# Any memory error or undefined behaviour in our code ends its test with a
# report. Leaks are not checked (Gmsh keeps its model in globals until
# exit). The Python tutorial is left out: Python's own interpreter would
# have to load the sanitizers' runtime first.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
# REPARAM_SANITIZER=thread: ThreadSanitizer instead (build-tsan/), for the
# layout's threads, e.g. REPARAM_SANITIZER=thread scripts/sanitize.sh -R Threads
if [ "${REPARAM_SANITIZER:-address}" = thread ]; then
  export REPARAM_BUILD_DIR=${REPARAM_SANITIZE_DIR:-$here/build-tsan}
  bash "$here/scripts/build.sh" -DREPARAM_SANITIZE=thread
else
  export REPARAM_BUILD_DIR=${REPARAM_SANITIZE_DIR:-$here/build-sanitize}
  bash "$here/scripts/build.sh" -DREPARAM_SANITIZE=ON
fi
# The reports also go to files: a test that checks its log for a line may
# pass with a report after that line, the files still tell
reports=$REPARAM_BUILD_DIR/sanitizer-reports
rm -rf "$reports"
mkdir -p "$reports"
export ASAN_OPTIONS=detect_leaks=0:halt_on_error=1:log_path=$reports/asan
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:log_path=$reports/ubsan
export TSAN_OPTIONS=halt_on_error=1:log_path=$reports/tsan
cd "$REPARAM_BUILD_DIR"
status=0
ctest --output-on-failure --parallel "${REPARAM_JOBS:-$(nproc)}" \
  -E 'python' "$@" || status=$?
if [ -n "$(ls -A "$reports")" ]; then
  echo "Sanitizer reports in $reports:" >&2
  head -n 40 "$reports"/* >&2
  exit 1
fi
echo "No sanitizer report"
exit $status
