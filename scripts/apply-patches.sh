#!/usr/bin/env bash
# Applies patches/*.patch to a Gmsh source tree, idempotently.
#   scripts/apply-patches.sh GMSH_SOURCE_DIR PATCH_DIR
# The series last applied is kept in GMSH_SOURCE_DIR/.reparam-applied; when
# patches/ changes, that series is reverted first, then the new one applied,
# so only the files the patches touch change (and need recompiling).
set -euo pipefail
src=$1
dir=$2
stamp=$src/.reparam-applied
new=$(mktemp)
trap 'rm -f "$new"' EXIT
cat /dev/null "$dir"/*.patch > "$new" 2>/dev/null || true

if [ -f "$stamp" ] && cmp -s "$stamp" "$new"; then
  exit 0
fi
# Each applied patch is also kept in $applied, to be reverted last first:
# two patches may change the same file, the later one on top of the other
applied=$src/.reparam-applied.d
if [ -d "$applied" ] || { [ -f "$stamp" ] && [ -s "$stamp" ]; }; then
  # (a copy without a stamp: a series that failed half-way, reverted too)
  echo "-- Reverting the previous Reparam patch series in $src"
  if [ -d "$applied" ]; then
    for p in $(ls -r "$applied"/*.patch 2>/dev/null); do
      patch -d "$src" -p1 -R -s -N --no-backup-if-mismatch < "$p"
    done
  else
    # a tree patched before the copies were kept: its patches changed
    # different files, so their concatenation reverts in one go
    patch -d "$src" -p1 -R -s -N --no-backup-if-mismatch < "$stamp"
  fi
fi
rm -f "$stamp"
rm -rf "$applied"
mkdir -p "$applied"
for p in "$dir"/*.patch; do
  [ -e "$p" ] || continue
  echo "-- Applying $(basename "$p")"
  # all or nothing: a patch that does not apply leaves no hunk behind
  patch -d "$src" -p1 -s -N --dry-run < "$p" > /dev/null ||
    { echo "-- $(basename "$p") does not apply to $src" >&2; exit 1; }
  patch -d "$src" -p1 -s -N --no-backup-if-mismatch < "$p"
  cp "$p" "$applied/"
done
cp "$new" "$stamp"
