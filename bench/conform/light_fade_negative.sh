#!/bin/sh
# light_fade_negative.sh [ZRCUBE] - what povray 3.7 does with a light's
# fade_distance below 0 (tests/light_fade.pov, cases 1-9: powers 1, 2,
# 3, 0.5 and 1001, distances 2 and 10, alone and beside an unfaded light
# of 0.5).  Prints each case's flat colour (8-bit, sRGB file) from povray
# and, given ZRCUBE, from zrcube.  What povray 3.7.0.10 printed
# (2026-12-03): 235 0 0 175 188 89 193 187/188 161 - the manual's formula
# taken as it is, the negative ratio's power included (a negative light
# takes light away from the other; a NaN power adds nothing), which
# tests/test_light_fade.sh checks zrcube against.
# Usage: bench/conform/light_fade_negative.sh [build/bin/zrcube] (needs
# povray and /usr/bin/python3 with PIL).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/../../tests/light_fade.pov
zr=${1:-}
[ -n "$zr" ] && zr=$(cd "$(dirname "$zr")" && pwd)/$(basename "$zr")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
colours() { # PNG -> the distinct colours, sorted
  /usr/bin/python3 -c "from PIL import Image; import sys; print(' '.join(sorted({'%d,%d,%d' % p for p in Image.open(sys.argv[1]).convert('RGB').getdata()})))" "$1"
}
for c in 1 2 3 4 5 6 7 8 9; do
  povray +I"$scene" +Op.png +W16 +H12 -D -A +WT1 -GA Declare=Case=$c \
    >/dev/null 2>&1
  line="case $c povray $(colours p.png)"
  if [ -n "$zr" ]; then
    "$zr" +I"$scene" +Oz.png +W16 +H12 -D +WT1 Declare=Case=$c \
      >/dev/null 2>&1
    line="$line zrcube $(colours z.png)"
  fi
  echo "$line"
done
