#!/usr/bin/env bash
# Fuzzes Reparam's STL reading path and patch layout with libFuzzer
# (tests/fuzz/stlLayoutFuzz.cpp): clang from Debian (`apt-get install
# clang`), Reparam's Mesh/ and Numeric/ sources and the reading ones of
# Geo/ compiled into the fuzzer with AddressSanitizer and UBSan, Gmsh's
# library from the main build (scripts/build.sh first).
#
#   scripts/fuzz.sh [SECONDS]        # default 600; the corpus grows in
#                                    # build/fuzz/corpus
#   REPARAM_FUZZ_RUNS=N scripts/fuzz.sh   # N inputs instead (the CTest)
#
# Exit code 0: no crash, hang (10 s per input) or sanitizer report; 77:
# clang with libFuzzer is missing (nothing run).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${REPARAM_BUILD_DIR:-$here/build}
out=$build/fuzz
seconds=${1:-600}
command -v clang++ > /dev/null || { echo "clang++ missing: not fuzzed"; exit 77; }
mkdir -p "$out/obj"
echo 'extern "C" int LLVMFuzzerTestOneInput(const char *, unsigned long) { return 0; }' \
  > "$out/probe.cpp"
clang++ -fsanitize=fuzzer "$out/probe.cpp" -o "$out/probe" 2> /dev/null ||
  { echo "clang++ has no libFuzzer: not fuzzed"; exit 77; }
src=$(sed -n 's/^GMSH_SOURCE_DIR:[A-Z]*=//p' "$build/CMakeCache.txt")
[ -n "$src" ] && [ -f "$build/gmsh/libgmsh.so" ] ||
  { echo "Build first: scripts/build.sh" >&2; exit 1; }

flags=(-std=gnu++17 -O1 -g -fno-omit-frame-pointer
  -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
  -DEIGEN_MALLOC_ALREADY_ALIGNED=1 -I"$build/gmsh/Common" -I/usr/include/eigen3
  -I/usr/include/suitesparse)
for d in $(find "$here/Geo" "$here/Mesh" "$here/Numeric" -name '*.h' -printf '%h\n' | sort -u); do
  flags+=(-I"$d")
done
for d in Common Geo Mesh Numeric Solver Post contrib/MathEx; do flags+=(-I"$src/$d"); done
sources=($(find "$here/Mesh" "$here/Numeric" -name '*.cpp' | sort)
  "$here"/Geo/input/reparamStlInput.cpp "$here"/tests/fuzz/stlLayoutFuzz.cpp)
# each source once, with ccache, both cores
export CCACHE_BASEDIR=$here CCACHE_NOHASHDIR=1
cc="clang++"
command -v ccache > /dev/null && cc="ccache clang++"
objects=()
for s in "${sources[@]}"; do objects+=("$out/obj/$(basename "${s%.cpp}").o"); done
printf '%s\n' "${sources[@]}" | xargs -P "${REPARAM_JOBS:-$(nproc)}" -I{} \
  sh -c "$cc ${flags[*]} -c {} -o \"$out/obj/\$(basename {} .cpp).o\""
clang++ -fsanitize=fuzzer,address,undefined "${objects[@]}" \
  -L"$build/gmsh" -lgmsh -Wl,-rpath,"$build/gmsh" -lklu -lumfpack \
  -o "$out/stlLayoutFuzz"

mkdir -p "$out/corpus" "$out/seeds" "$out/crashes"
python3 "$here/tests/fuzz/make-seeds.py" "$out/seeds"
limits=(-max_len=10084 -timeout=10 -rss_limit_mb=2048
  -artifact_prefix="$out/crashes/")
if [ -n "${REPARAM_FUZZ_RUNS:-}" ]; then
  limits+=(-runs="$REPARAM_FUZZ_RUNS" -seed=1)
else
  limits+=(-max_total_time="$seconds")
fi
export ASAN_OPTIONS=detect_leaks=0
"$out/stlLayoutFuzz" "${limits[@]}" "$out/corpus" "$out/seeds"
