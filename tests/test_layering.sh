#!/bin/sh
# test_layering.sh - the folders of lib/ include one another only
# downward (bench/layering.sh; README, "Layering").  The check runs on
# the tree, then on a copy of lib/ with one upward include planted in
# lib/core (which may include nothing above it), which it must refuse,
# naming the file and line: a check that could never fail proves
# nothing.
#
# Environment: ZR_SRCDIR (the source tree).
set -u
top=${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}
check=$top/bench/layering.sh
[ -f "$check" ] || { echo "test_layering.sh: no $check" >&2; exit 99; }

if ! sh "$check" "$top"; then
  echo "test_layering.sh: an include goes back up the layers (above)" >&2
  exit 1
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/zr_test_layering.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
cp -R "$top/lib" "$work/lib" || exit 99
printf '#include "trace/render.h"\n' >>"$work/lib/core/vec.h"
out=$(sh "$check" "$work" 2>&1)
status=$?
if [ $status -ne 1 ]; then
  echo "test_layering.sh: a planted upward include passed (status" \
       "$status): $out" >&2
  exit 1
fi
case $out in
*"lib/core/vec.h:"*"lib/core includes trace/render.h"*) ;;
*)
  echo "test_layering.sh: the planted include was not named: $out" >&2
  exit 1 ;;
esac
# A folder outside the order is refused too.
mkdir "$work/lib/extra"
out=$(sh "$check" "$work" 2>&1)
case $out in
*"lib/extra: error: folder not in the layer order"*) ;;
*)
  echo "test_layering.sh: a folder outside the order passed: $out" >&2
  exit 1 ;;
esac
echo "test_layering.sh: lib/ includes only downward"
