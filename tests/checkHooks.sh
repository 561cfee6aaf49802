#!/usr/bin/env bash
# CTest rooms.hooksDeclaredOnce: every function Gmsh calls into Reparam is
# declared once, in Geo/reparamHooks.h. The patch series declares none of
# them itself (an added top-level line `type reparamX(...)` or
# `type opt_mesh_compound_x(...)` without a body), every patched Gmsh file
# that calls one includes reparamHooks.h, and every function the patches
# call is declared there.
#
#   checkHooks.sh REPARAM_SOURCE_DIR
set -uo pipefail
here=$1
hooks=$here/Geo/reparamHooks.h
status=0

# declarations added by the patches (a '+' line at column 0 naming a hook,
# ending in ';' and not a call inside a statement)
declared=$(grep -nE '^\+[A-Za-z_][A-Za-z0-9_:<>,*& ]* \**(reparam[A-Z][A-Za-z]*|opt_mesh_compound_[a-z_]+)\(' \
  "$here"/patches/*.patch | grep -vE '^\S+:\+\s*(return|if|else)\b')
if [ -n "$declared" ]; then
  echo "Hooks declared by the patches instead of Geo/reparamHooks.h:"
  echo "$declared"
  status=1
fi

# every hook the patches call is declared in reparamHooks.h
for name in $(grep -hE '^\+' "$here"/patches/*.patch | grep -v '^+++' |
  sed 's#//.*##' | grep -oE '\b(reparam[A-Z][A-Za-z]*|opt_mesh_compound_[a-z_]+)\b *[(,]' |
  grep -oE '^[A-Za-z_]+' | sort -u); do
  grep -qE "\b$name\(" "$hooks" || {
    echo "$name is called by the patches but not declared in Geo/reparamHooks.h"
    status=1
  }
done

# every patched file that calls a hook includes reparamHooks.h (in the
# patch that first calls it, or an earlier one)
for file in $(grep -h '^+++ b/' "$here"/patches/*.patch | sed 's#^+++ b/##' | sort -u); do
  calls=0
  includes=0
  for patch in "$here"/patches/*.patch; do
    body=$(awk -v f="b/$file" '/^\+\+\+ /{on = ($2 == f)} on && /^\+[^+]/' "$patch")
    echo "$body" | sed 's#//.*##' |
      grep -qE '\b(reparam[A-Z][A-Za-z]*|opt_mesh_compound_[a-z_]+) *[(,]' && calls=1
    echo "$body" | grep -q '#include "reparamHooks.h"' && includes=1
  done
  if [ $calls = 1 ] && [ $includes = 0 ]; then
    echo "$file calls Reparam's hooks without including reparamHooks.h"
    status=1
  fi
done

[ $status = 0 ] && echo "hooks ok: $(grep -cE '^[a-zA-Z].*\b(reparam[A-Z][A-Za-z]*|opt_mesh_compound_[a-z_]+)\(' "$hooks") declarations in Geo/reparamHooks.h"
exit $status
