#!/bin/sh
# test_includes.sh - every standard include file of POV-Ray 3.7
# (povray-includes, /usr/share/povray-3.7/include) parses without error
# when included alone, one line per file.  A few of them use colours or
# shapes they do not include themselves, so POV-Ray 3.7 cannot parse
# them alone either (measured with povray on an 8x6 render: shapes2,
# shapesq, skies, stdcam, stoneold, stones, stones1, stones2); those are
# included after colors.inc and shapes.inc, as their headers ask.
# Skipped (77) when POV-Ray's include files are not installed.
#
# Environment: ZR_BUILDDIR (where bin/zrcube is), POVRAY_INCLUDE.

set -u
ZRCUBE="${ZR_BUILDDIR:-$(pwd)}/bin/zrcube"
INC="${POVRAY_INCLUDE:-/usr/share/povray-3.7/include}"
if [ ! -x "$ZRCUBE" ]; then
  echo "test_includes.sh: no zrcube at $ZRCUBE" >&2
  exit 99
fi
if [ ! -f "$INC/colors.inc" ]; then
  echo "test_includes.sh: $INC has no POV-Ray include files" \
       "(apt-get install povray-includes): skipped"
  exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_test_includes.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT

needs_others=" shapes2.inc shapesq.inc skies.inc stdcam.inc stoneold.inc \
stones.inc stones1.inc stones2.inc "
failures=0
total=0
for f in "$INC"/*.inc; do
  name=$(basename "$f")
  total=$((total + 1))
  {
    echo '#version 3.7;'
    case $needs_others in
      *" $name "*) echo '#include "colors.inc"'; echo '#include "shapes.inc"' ;;
    esac
    echo "#include \"$name\""
  } >"$work/t.pov"
  if "$ZRCUBE" --parse-only -q "$work/t.pov" >/dev/null 2>"$work/err" &&
     ! grep -q -e 'Sanitizer' -e 'runtime error:' "$work/err"; then
    echo "ok $name"
  else
    echo "FAIL $name: $(grep -m1 -e error -e Sanitizer "$work/err")"
    failures=$((failures + 1))
  fi
done
echo "$((total - failures)) of $total include files parse"
[ "$failures" -eq 0 ]
