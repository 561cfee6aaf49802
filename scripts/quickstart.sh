#!/usr/bin/env bash
# The README's quick start: installs what is missing (Debian packages and
# Gmsh 4.8.4's source), builds Gmsh with Reparam, then remeshes the bundled
# example and prints its quality table.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/build.sh"
bash "$here/scripts/remesh-example.sh"
