#!/usr/bin/env bash
# Installs the Debian packages Reparam builds against and fetches Gmsh 4.8.4's
# source (Debian's gmsh source package) unless GMSH_SOURCE_DIR points at one.
# Idempotent: a second run installs nothing and downloads nothing.
#
#   scripts/install-deps.sh            # no GUI
#   REPARAM_GUI=ON scripts/install-deps.sh
#
# Prints the Gmsh source directory on its last line.
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
cache=${REPARAM_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/reparam}
mkdir -p "$cache"

packages=(build-essential cmake ccache pkg-config dpkg-dev
  libeigen3-dev libmetis-dev libgmm++-dev libann-dev
  libspectra-dev libgtest-dev libsuitesparse-dev
  # the system BLAS (Debian alternative) under UMFPACK/CHOLMOD: UMFPACK's
  # LU of the mean-value map is 1.5x faster with it on 50k unknowns
  libopenblas0-serial
  # the gmsh executable's allocator: Gmsh's stages on large inputs spent a
  # fifth of their time in glibc's malloc (bench/README.md#the-allocator)
  libjemalloc-dev
  zlib1g-dev libpng-dev libjpeg-dev python3
  # Debian's gmsh source links these even without the GUI (its patch
  # 30_delete_gl2ps_from_source)
  libgl2ps-dev libgl-dev freeglut3-dev
  # libFuzzer for scripts/fuzz.sh and its CTest (skipped without it): clang
  # only recommends its runtimes (libFuzzer, the sanitizers), which
  # --no-install-recommends below would leave out
  clang libclang-rt-dev)
if [ "${REPARAM_GUI:-OFF}" = "ON" ]; then
  packages+=(libfltk1.3-dev libgl2ps-dev libglu1-mesa-dev libxft-dev
    libxinerama-dev libxcursor-dev libxfixes-dev
    # the GUI's CTest (label gui) runs Gmsh's window on a virtual display
    xvfb xauth)
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$p")
done

need_source=0
if [ -z "${GMSH_SOURCE_DIR:-}" ] && [ ! -f "$cache/gmsh-4.8.4/CMakeLists.txt" ]; then
  need_source=1
fi

if [ ${#missing[@]} -gt 0 ] || [ $need_source -eq 1 ]; then
  # apt-get source needs a deb-src entry for the same suites as the binaries.
  if ! grep -rqs "^Types:.*deb-src\|^deb-src" /etc/apt/sources.list /etc/apt/sources.list.d/; then
    $sudo tee /etc/apt/sources.list.d/reparam-deb-src.sources >/dev/null <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  fi
  $sudo apt-get update -qq
fi

if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}" >&2
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

if [ -n "${GMSH_SOURCE_DIR:-}" ]; then
  src=$GMSH_SOURCE_DIR
else
  src=$cache/gmsh-4.8.4
  if [ ! -f "$src/CMakeLists.txt" ]; then
    tmp=$(mktemp -d "$cache/fetch.XXXXXX")
    (cd "$tmp" && apt-get source -qq gmsh >&2)
    dir=$(find "$tmp" -maxdepth 1 -type d -name 'gmsh-4.8.4*' | head -n 1)
    [ -n "$dir" ] || { echo "apt-get source gmsh did not give 4.8.4" >&2; exit 1; }
    rm -rf "$src"
    mv "$dir" "$src"
    rm -rf "$tmp"
  fi
fi
grep -q 'GMSH_MINOR_VERSION 8' "$src/CMakeLists.txt" && grep -q 'GMSH_PATCH_VERSION 4' "$src/CMakeLists.txt" \
  || { echo "$src is not Gmsh 4.8.4" >&2; exit 1; }
echo "$src"
